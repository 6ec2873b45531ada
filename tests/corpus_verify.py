"""``nczones verify`` over whole corpora: every program ends with exit 0, 1, 2 or 3, never 4 (an internal
error), and within a bounded time (issue 33, class 6 and 7).

Used by ``tests/gcode/test_corpus_verify.py`` (the LinuxCNC corpus) and ``tests/gcode/fanuc/test_corpus.py`` (the
Fanuc corpus); ``python -m tests.corpus_verify`` runs both whole and prints the counts for specs/.
"""

from __future__ import annotations

import contextlib
import io
import os
import signal
import sys
import time
from collections import Counter
from pathlib import Path

from nczones.cli import main
from tests.corpus import CORPUS, FANUC, corpus_programs

#: Seconds of solver work and of repetitions a program may use (``--budget``).
BUDGET = "10"
#: Wall seconds after which a program counts as a hang: its budget plus the straight-line interpretation and
#: proof of the largest corpus program (0.65 MB) on a loaded machine.
HANG_S = 300

_AXES = ["X", "Y", "Z", "A", "B", "C", "U", "V", "W"]
#: A machine for the LinuxCNC corpus: every axis, LinuxCNC's cutter compensation (a 1 mm tool for every tool
#: number), a travel box and a forbidden block inside it, so that the prover has work to do.
LINUXCNC_MACHINE = (
    '[machine]\nname = "corpus mill"\naxes = ' + str(_AXES).replace("'", '"')
    + '\npulse = "0.0001"\ncutter_compensation = "linuxcnc"\n'
    + "[machine.rapid]\n" + "\n".join(f'{a} = "1000"' for a in _AXES) + "\n"
    + "[machine.reference]\n" + "\n".join(f'{a} = "0"' for a in _AXES) + "\n"
    + "[tool_lengths]\n" + "\n".join(f'H{i} = "0"' for i in range(1, 100)) + "\n"
    + "[tool_diameters]\n" + "\n".join(f'T{i} = "1"' for i in range(0, 100)) + "\n"
    + '[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-2000", Y = "-2000", Z = "-2000" }\n'
    + 'max = { X = "2000", Y = "2000", Z = "2000" }\n'
    + '[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\nmin = { X = "500", Y = "500", Z = "-2000" }\n'
    + 'max = { X = "600", Y = "600", Z = "-500" }\n')


class Hang(BaseException):
    """A program ran past :data:`HANG_S` (not an Exception: the CLI's handlers must not turn it into exit 4)."""


def _alarm(_signum, _frame):
    raise Hang


def verify_exit(program: Path, machine: Path, *extra: str) -> tuple[int | str, float, str]:
    """(exit status or "hang", seconds, the first error or unknown line of standard error) of ``nczones verify`` run in process."""
    err = io.StringIO()
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(HANG_S)
    t0 = time.perf_counter()
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            code: int | str = main(["verify", str(program), "--machine", str(machine), "--budget", BUDGET,
                                    "--format", "json", "--output", os.devnull, *extra])
    except Hang:
        code = "hang"
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    lines = err.getvalue().strip().splitlines()
    first = next((x for x in lines if "error" in x or "unknown[" in x), lines[0] if lines else "")
    return code, time.perf_counter() - t0, first


def linuxcnc_programs() -> list[str]:
    """Every MANIFEST program written for LinuxCNC (dialects naming it: LinuxCNC, CAMotics, Vectric .tap)."""
    return [rel for rel, dialect in corpus_programs() if "LinuxCNC" in dialect]


def fanuc_programs() -> list[tuple[str, str]]:
    """(path relative to the corpus, family) of every program of ``corpus/fanuc`` and every Fanuc-dialect row of
    the main MANIFEST (Haas/Fanuc macro samples)."""
    rows = [("fanuc/" + r.split("\t")[0], r.split("\t")[4])
            for r in (FANUC / "MANIFEST.tsv").read_text(encoding="utf-8").splitlines()[1:] if r.strip()]
    return rows + [(rel, dialect) for rel, dialect in corpus_programs() if dialect.startswith("Fanuc")]


def sample(items: list, n: int) -> list:
    """A fixed, deterministic sample of ``n`` items spread over the list (every k-th)."""
    if len(items) <= n:
        return list(items)
    step = len(items) / n
    return [items[int(i * step)] for i in range(n)]


def run(programs, machine_for, out=None) -> tuple[Counter, list, float]:
    """Exit counts, the failures (exit 4 or hang) and the slowest time over ``programs``."""
    counts: Counter = Counter()
    bad, slowest = [], 0.0
    for item in programs:
        rel = item if isinstance(item, str) else item[0]
        machine = machine_for(item)
        code, seconds, last = verify_exit(CORPUS / rel, machine)
        counts[code] += 1
        slowest = max(slowest, seconds)
        if code in (4, "hang"):
            bad.append((rel, code, last))
        if out is not None:
            print(f"{code}\t{seconds:.1f}\t{rel}\t{last[:150]}", file=out, flush=True)
    return counts, bad, slowest


if __name__ == "__main__":  # the full run: python -m tests.corpus_verify DIR (DIR for the machine files)
    import tempfile

    folder = Path(sys.argv[1] if len(sys.argv) > 1 else tempfile.mkdtemp())
    from tests.gcode.fanuc.test_corpus import fanuc_machine_file

    lcnc = folder / "linuxcnc.toml"
    lcnc.write_text(LINUXCNC_MACHINE)
    which = sys.argv[2] if len(sys.argv) > 2 else "both"
    for name, progs, pick in (("fanuc", fanuc_programs(), lambda item: fanuc_machine_file(item[0], folder)),
                              ("linuxcnc", linuxcnc_programs(), lambda _item: lcnc)):
        if which not in ("both", name):
            continue
        t0, c0 = time.perf_counter(), time.process_time()
        counts, bad, slowest = run(progs, pick, out=sys.stdout)
        print(f"# {name}: {len(progs)} programs, exits {dict(counts)}, exit 4/hang {bad}, slowest {slowest:.1f} s, "
              f"{time.perf_counter() - t0:.0f} s wall, {time.process_time() - c0:.0f} s CPU", flush=True)
