"""Interpreted motion against LinuxCNC's own canon logs (corpus README, section A).

Each LinuxCNC interpreter test directory in ``corpus/linuxcnc/tests`` holds a
program and the ``rs274`` canon call log it must produce.  The log prints
``STRAIGHT_TRAVERSE``/``STRAIGHT_FEED``/``ARC_FEED`` end points in *program*
coordinates and current units; the offsets it excludes are printed as
separate calls (``SET_G5X_OFFSET``, ``SET_G92_OFFSET``,
``USE_TOOL_LENGTH_OFFSET``) in the units current when they are printed.  The
harness applies them (machine = program + G92 + G5x + tool offset, all in mm)
and compares with our machine coordinates to 4 decimals of the log's unit
(each printed number is rounded to 0.0001, so the tolerance is 0.0001 of the
log unit).  Arc centres and the helix end are compared the same way, the
rotation sign and turn count exactly.

Directories are taken from ``INTERP_TESTS.tsv`` when their command is a single
``rs274 ... -g X.ngc`` run without INI or parameter file and with exit status
0.  The ones that cannot be compared are listed in :data:`SKIPPED` with the
reason; a directory whose program we report as ``unknown`` (an unsupported
code, e.g. cutter compensation) is compared up to that point, which is what
"motion before it is still emitted" promises.
"""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

import pytest

from nczones.errors import GcodeError
from nczones.exact import format_decimal
from nczones.gcode import interpret
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from tests.corpus import CORPUS
from tests.oracles.rs274 import AXES6, canon_motion

TESTS = CORPUS / "linuxcnc" / "tests"
TSV = CORPUS / "linuxcnc" / "INTERP_TESTS.tsv"

pytestmark = pytest.mark.skipif(not TSV.is_file(), reason="corpus not available")

#: Directories not compared, with the reason.
SKIPPED = {
    "tests/interp/g76": "G76 threading cycle (unsupported, unknown before any motion that matters)",
    "tests/interp/machine-coord-params": "compares MESSAGE lines only (no motion in the log)",
    "tests/interp/rotation/abs-pts": "compares MESSAGE lines only, with rotation",
    "tests/interp/g71-endless-loop": "the test only checks termination; no expected motion",
    "tests/interp/g71-endless-loop2": "the test only checks termination; no expected motion",
    "tests/interp/g71-endless-loop_2": "the test only checks termination; no expected motion",
    "tests/interp/g71-with-g70": "the test only checks termination; no expected motion",
    "tests/interp/g72-facing": "the test only checks termination; no expected motion",
    "tests/interp/g72-missing-iteration": "the test only checks termination; no expected motion",
}



def _cases():
    if not TSV.is_file():
        return []
    out = []
    for row in TSV.read_text().splitlines()[1:]:
        cols = row.split("\t")
        if len(cols) < 3:
            continue
        d, cmd, status = cols[0], cols[1], cols[2]
        if not (TESTS.parent.parent / d / "expected").is_file() and not (CORPUS / "linuxcnc" / d / "expected").is_file():
            continue
        out.append((d, cmd, status))
    return out


def _parse_cmd(cmd: str):
    """(program, tool table) for a plain single rs274 run, else None."""
    if "||" in cmd or " -i " in cmd or " -v " in cmd or " -n " in cmd or "2>&1" in cmd or not cmd.startswith("rs274"):
        return None
    first = cmd.split("|")[0].split()
    prog = next((a for a in first if a.endswith(".ngc")), None)
    tbl = first[first.index("-t") + 1] if "-t" in first else None
    return prog, tbl


def _machine(tooltable: Path | None):
    tools = ""
    if tooltable is not None and tooltable.is_file():
        lines = []
        diameters = []
        for line in tooltable.read_text().splitlines():
            m = re.match(r"\s*T(\d+)\b.*?\bZ([-+]?[\d.]+)", line.split(";")[0], re.I)
            if m:
                lines.append(f'H{int(m.group(1))} = "{m.group(2)}"')
            m = re.match(r"\s*T(\d+)\b.*?\bD([-+]?[\d.]+)", line.split(";")[0], re.I)
            if m:  # rs274's tool table diameters are inches (the standalone interpreter's user units)
                diameters.append(f'T{int(m.group(1))} = "{format_decimal(Fraction(m.group(2)) * Fraction(254, 10))}"')
        tools = "[tool_lengths]\n" + "\n".join(lines) + "\n" + "[tool_diameters]\n" + "\n".join(diameters) + "\n"
    axes = ["X", "Y", "Z", "A", "B", "C", "U", "V", "W"]
    rapid = "\n".join(f'{a} = "1000"' for a in axes)
    ref = "\n".join(f'{a} = "0"' for a in axes)
    text = (
        f"[machine]\naxes = {axes!r}\npulse = \"0.0001\"\ncutter_compensation = \"linuxcnc\"\n".replace("'", '"')
        + f"[machine.rapid]\n{rapid}\n[machine.reference]\n{ref}\n"
        + tools
    )
    return parse_machine(text)


def _log_motion(expected: Path):
    """Expected motions as (kind, machine-mm tuple of 6, arc info) from the canon log
    (:func:`tests.oracles.rs274.canon_motion`, dwells left out)."""
    out = []
    for m in canon_motion(expected.read_text(errors="replace")):
        if m.kind == "DWELL":
            continue
        info = (m.direction, m.centre, m.unit, m.plane, m.rotation) if m.kind == "ARC" else (m.unit, m.rotation)
        out.append((m.kind, m.end, info))
    return out


def _compare(d: str, prog: Path, tbl: Path | None):
    moves = _log_motion(prog.parent / "expected")
    machine = _machine(tbl)
    run = interpret(prog, machine, arc_tolerance=Fraction(1, 10))
    mine = []
    try:
        for s in run.segments():
            if s.kind is not SegmentKind.DWELL:
                mine.append(s)
    except GcodeError as exc:
        return "error", exc.render()
    if run.unsupported:
        moves = moves[: len(mine)]
    if len(mine) != len(moves):
        return "mismatch", f"{len(mine)} motions, the log has {len(moves)}"
    names = machine.axis_names
    for k, (s, (kind, pt, info)) in enumerate(zip(mine, moves)):
        unit, rotation = (info[0], info[1]) if kind != "ARC" else (info[2], info[4])
        # rotated: the log's 4-decimal program values and offsets, rotated, carry up to ~1.5x their rounding
        tol = Fraction(1, 10000) * unit * (2 if rotation else 1)
        if s.kind.name != kind:
            return "mismatch", f"motion {k} (line {s.line}): {s.kind.name} vs log {kind}"
        end = [s.end[names.index(a)] for a in AXES6]
        for a, e, x in zip(AXES6, end, pt):
            t = tol if a in "XYZ" else Fraction(1, 10000)
            if abs(e - x) > t:
                return "mismatch", f"motion {k} (line {s.line}) axis {a}: {float(e):.5f} vs log {float(x):.5f} mm"
        if kind == "ARC":
            rot, centre, _, plane, _ = info
            turns = abs(rot) - 1
            if (rot < 0) != s.clockwise or turns != s.turns or s.plane.name != plane:
                return "mismatch", f"motion {k} (line {s.line}): arc direction/turns/plane differ"
            if s.centre is not None:
                for c, x in zip(s.centre, centre):
                    if abs(c - x) > tol:
                        return "mismatch", f"motion {k} (line {s.line}): centre {float(c):.5f} vs log {float(x):.5f}"
    status = "unknown-prefix" if run.unsupported else "match"
    return status, run.unsupported[0].render() if run.unsupported else ""


def _all_results():
    results = {}
    for d, cmd, status in _cases():
        if d in SKIPPED:
            results[d] = ("skip", SKIPPED[d])
            continue
        parsed = _parse_cmd(cmd)
        if parsed is None or status.strip() != "0":
            results[d] = ("skip", f"not a plain rs274 run: {cmd}")
            continue
        prog_name, tbl_name = parsed
        base = CORPUS / "linuxcnc" / d
        prog = base / prog_name
        if not prog.is_file():
            results[d] = ("skip", f"program {prog_name} missing")
            continue
        results[d] = _compare(d, prog, base / tbl_name if tbl_name else None)
    return results


@pytest.fixture(scope="module")
def results():
    return _all_results()


def test_canon_logs_match(results, capsys):
    counts: dict[str, int] = {}
    for d, (status, why) in sorted(results.items()):
        counts[status] = counts.get(status, 0) + 1
        with capsys.disabled():
            print(f"  {status:15s} {d}  {why[:150]}")
    with capsys.disabled():
        print("canon comparison:", counts)
    matched = [d for d, (s, _) in results.items() if s == "match"]
    assert len(matched) >= 25, counts
    bad = {d: r for d, r in results.items() if r[0] in ("mismatch",) and d not in KNOWN_MISMATCH}
    assert not bad, bad


#: Directories where our motion deliberately differs from LinuxCNC's log.
KNOWN_MISMATCH: dict[str, str] = {}
