"""Every LinuxCNC program of the corpus through LinuxCNC's ``rs274 -g`` and nczones, classified.

    python -m tests.tools.rs274_corpus [--only SUBSTR] [--timeout S] [--max-bytes N] [--tool-length IN]

The programs are the MANIFEST rows with role ``program`` and a ``LinuxCNC*`` dialect
(:func:`tests.corpus.corpus_programs`).  Each runs through ``rs274`` (with the tool table and parameter file of
``tests/tools/rs274_diff.py``'s :func:`run_rs274`, in a scratch directory, so external subroutine files are not
found: LinuxCNC without them refuses those programs too) and through nczones (LinuxCNC's arc acceptance rule,
cutter compensation modelled as LinuxCNC does it) on a machine with axes X Y Z A B C at machine zero, the same
tools (T1-T98 and T210; 2.54 mm diameter as the table's ``D0.1``), no zones.  :func:`tests.oracles.rs274.compare`
holds nczones's motion to rs274's within the rounding of its 4-decimal log.

Classes (``compare``'s outcome, with both refusals split by whether rs274 ran to the end):

* ``match``: both run, every motion agrees;
* ``both refuse (same line)`` / ``both refuse (other line)``;
* ``unknown (rs274 runs)`` / ``unknown (rs274 refuses)``: nczones stops with ``unknown`` (the motion before it
  agreed); not a wrong answer, a false rejection when rs274 runs it;
* ``false rejection``: nczones refuses what rs274 runs to the end (a parity bug);
* ``too lenient``: rs274 refuses, nczones runs past (potentially a wrong ``safe``);
* ``motion differs``: both run but a motion differs (potentially a wrong ``safe``, the most important);
* ``... : 2.10 feature``: rs274 (2.9) refuses a code of LinuxCNC 2.10 that nczones follows (G6.2, G5.2 in
  G18/G19), after the motion before it agreed or not (the class before the colon);
* ``oracle gap`` / ``crash`` / ``rs274 timeout`` / ``nczones timeout`` / ``skipped (size)``.

rs274's "File ended with no percent sign or program end" (a program without M2/M30/%) and "Bad character '%'
used" on a ``%`` line (a file that does not start with ``%``; nczones ends the program there) come after all
the motion before them, which LinuxCNC has run by then; they are counted (``[no end]``) and otherwise ignored.

Tool lengths are 0 unless ``--tool-length`` gives tool n the length n x IN inches: the standalone rs274 re-reads
a position without the tool length after M6/M61 and the length unconverted after G20/G21 (``saicanon.cc``),
which real LinuxCNC does not do, so with lengths real programs show differences of the oracle, not of nczones.
"""

from __future__ import annotations

import argparse
import signal
import sys
import tempfile
import time
from collections import Counter
from fractions import Fraction
from pathlib import Path

from nczones.machine import parse_machine
from tests.corpus import CORPUS, corpus_programs
from tests.oracles.rs274 import AXES6, Outcome, compare, machine_text
from tests.tools.rs274_diff import RS274, run_rs274

#: Tool numbers the corpus names (T0-T15, T210), with room to spare; T99 is the table's empty spindle.
TOOLS = [*range(1, 99), 210]
NO_END = "File ended with no percent sign or program end"
BAD_PERCENT = "Bad character '%' used"  # a '%' line in a file that does not start with one
CLASSES = {
    "match": "match",
    "error-line": "both refuse (other line)",
    "unknown": "unknown",
    "false-error": "false rejection",
    "missed-error": "too lenient",
    "path": "motion differs",
    "oracle-gap": "oracle gap",
    "crash": "crash",
}
#: Classes that could let nczones say ``safe`` of what LinuxCNC moves otherwise.
SOUNDNESS = ("motion differs", "too lenient")


class _Timeout(Exception):
    pass


def machine_for(tools_inch: dict[int, Fraction]):
    """X Y Z A B C at machine zero, the tool lengths of the table, cutter compensation as LinuxCNC."""
    text = machine_text(AXES6, tools_inch)
    text = text.replace('pulse = "0.0001"\n', 'pulse = "0.0001"\ncutter_compensation = "linuxcnc"\n', 1)
    # the table's D0.1 (inches); the spindle is empty at start (diameter 0, nczones's tool 0 without an entry)
    diameters = "\n".join(f'T{n} = "2.54"' for n in sorted(tools_inch))
    return parse_machine(text + f"[tool_diameters]\n{diameters}\n")


def classify(rel: str, work: Path, tools: dict[int, Fraction], machine, timeout: float) -> tuple[str, str]:
    """(class, detail) of one corpus program."""
    program = (CORPUS / rel).read_text()
    moves, error, _ = run_rs274(program, ((), tools, {}), work, timeout=timeout)
    if error is not None and error[0] == "rs274 timed out":
        return "rs274 timeout", f"{timeout:.0f} s"
    no_end = error is not None and (error[0] == NO_END or (error[0] == BAD_PERCENT and error[1].strip() == "%"))
    if no_end:
        error = None

    def alarm(_sig, _frame):
        raise _Timeout

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(int(timeout))
    try:
        o = compare(program, machine, moves, error, arc_tolerance="linuxcnc")
    except _Timeout:
        return "nczones timeout", f"{timeout:.0f} s"
    except Exception as exc:  # noqa: BLE001 - an internal error of nczones is a finding too
        o = Outcome("crash", f"{type(exc).__name__}: {exc}")
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    cls = CLASSES.get(o.status, o.status)
    detail = o.detail
    if error is not None and _newer(error):
        return f"{cls}: 2.10 feature", detail if error[0] in detail else detail + f" / rs274: {error[0]} at {error[1]!r}"
    if o.status == "false-error" and "ambiguous in a block with both G64 and M19" in detail:
        return f"{cls}: 2.10 feature", detail  # LinuxCNC 2.10 refuses it (tests/interp/bad/g64-m19-r-ambiguous.ngc)
    if o.status == "match" and error is not None:
        cls = "both refuse (same line)"
    elif o.status == "unknown":
        cls = "unknown (rs274 refuses)" if error is not None else "unknown (rs274 runs)"
        if error is not None:
            detail += f" / rs274: {error[0]}"
    elif o.status == "path" and error is not None:
        detail += f" / rs274 then refuses: {error[0]} at {error[1]!r}"
    if o.status in ("path", "missed-error", "false-error", "error-line", "crash"):
        detail += _source_line(program, detail)
    return cls + (" [no end]" if no_end and cls == "match" else ""), detail


def _newer(error: tuple[str, str]) -> bool:
    """rs274 2.9 refuses what LinuxCNC 2.10 has and nczones follows: G6.2 and NURBS (G5.2) in G18/G19
    (``interp_convert.cc``, commit dbb08bfdbd "add nurbs in xy, yz and zx plane", not on the 2.9 branch), and
    G64's R word (the planner dial, d45804b2b4)."""
    message, text = error
    code = text.upper().replace(" ", "")
    return (message == "Unknown g code used" and "G6.2" in code) or \
        message == "You must specify both X and Y coordinates for Control Points" or \
        (message == "R word with no g code that uses it" and "G64" in code)


def _source_line(program: str, detail: str) -> str:
    """The text of the line a detail names (``(line N)`` or ``prog.ngc:N:``), for the report."""
    import re

    m = re.search(r"\(line (\d+)\)|prog\.ngc:(\d+):", detail)
    if not m:
        return ""
    n = int(m.group(1) or m.group(2))
    lines = program.splitlines()
    return f"\n        line {n}: {lines[n - 1].strip()[:100]!r}" if 0 < n <= len(lines) else ""


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default="", help="programs whose corpus path contains this")
    ap.add_argument("--timeout", type=float, default=60, help="seconds per program, for rs274 and for nczones")
    ap.add_argument("--max-bytes", type=int, default=1_000_000, help="skip larger programs (0: none)")
    ap.add_argument("--tool-length", type=Fraction, default=Fraction(0), help="tool n is n x this many inches")
    args = ap.parse_args(argv)
    if not Path(RS274).exists():
        print(f"{RS274} not found (LinuxCNC's standalone interpreter, package linuxcnc-uspace)", file=sys.stderr)
        return 2
    rels = [rel for rel, dialect in corpus_programs() if dialect.startswith("LinuxCNC") and args.only in rel]
    if not rels:
        print(f"no LinuxCNC programs in {CORPUS} (MANIFEST.tsv) match {args.only!r}", file=sys.stderr)
        return 2
    tools = {n: n * args.tool_length for n in TOOLS}
    machine = machine_for(tools)
    counts: Counter = Counter()
    found: dict[str, list[tuple[str, str]]] = {}
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for k, rel in enumerate(rels, 1):
            size = (CORPUS / rel).stat().st_size
            if args.max_bytes and size > args.max_bytes:
                cls, detail = "skipped (size)", f"{size:,} bytes"
            else:
                t = time.perf_counter()
                cls, detail = classify(rel, work, tools, machine, args.timeout)
                detail += f"  [{time.perf_counter() - t:.1f} s]" if time.perf_counter() - t > 10 else ""
            counts[cls] += 1
            found.setdefault(cls, []).append((rel, detail))
            print(f"[{k}/{len(rels)}] {cls}: {rel}", file=sys.stderr, flush=True)
    print(f"\n{len(rels)} LinuxCNC programs in {time.perf_counter() - t0:.0f} s (rs274 {RS274}, timeout "
          f"{args.timeout:.0f} s, tool length n x {args.tool_length} in)\n")
    width = max(len(c) for c in counts)
    for cls, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        mark = "  <- soundness" if cls in SOUNDNESS else ""
        print(f"  {cls:{width}s} {n:4d}{mark}")
    for cls in sorted(found, key=lambda c: (c not in SOUNDNESS, c)):
        if cls.startswith("match") or cls.startswith("both refuse (same"):
            continue
        print(f"\n== {cls} ({len(found[cls])})")
        for rel, detail in found[cls]:
            print(f"  {rel}\n      {detail}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
