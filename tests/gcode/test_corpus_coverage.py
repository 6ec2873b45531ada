"""Corpus coverage: every program interpreted, rejected with a diagnostic, or unknown.

Issue 3, "Done when": every G-code program of ``../shared/corpus`` ends in
one of three outcomes and never in a traceback:

* ``complete``: every block executed, all motion emitted;
* ``unknown``: an :class:`~nczones.gcode.Unsupported` with a code, a reason
  and a line (a code nczones cannot model exactly, never skipped);
* ``rejected``: a :class:`~nczones.errors.GcodeError` with ``file:line:column``.

and at least 90% of the programs *LinuxCNC itself accepts* are ``complete``.

Which programs LinuxCNC accepts
-------------------------------
Candidates are the MANIFEST rows with role ``program`` and a ``LinuxCNC*``
dialect.  Not accepted, each with the reason in :data:`NOT_ACCEPTED`:

* LinuxCNC rejects them: ``tests/interp/bad/``, test directories whose
  expected result is an error, and programs with an error LinuxCNC reports
  as well (two motion codes in one block other than G80, which LinuxCNC drops, ``G1`` without any ``F``, an
  unclosed comment, a codes LinuxCNC does not have, a subroutine-local
  parameter read after the return);
* they need files or settings outside the program, which a program-only run
  cannot have and LinuxCNC run without them rejects: external subroutine
  files (``o<name> call`` of a sub not in the file; our ``GC393``), user
  M codes M100-M199 (executables in the PROGRAM_PREFIX directory), codes
  remapped in an INI file (M11-M13 laser raster, M428/M429 and G68.2/G69
  5-axis kinematics), HAL pins and INI values read as parameters
  (``#<_hal[...]>``, ``#<_ini[...]>``).

The long tests (``-m long``) run all programs, with both arc rules (about a minute each on a loaded
2-core machine); :func:`test_corpus_outcomes_sample` and its LinuxCNC-arc-rule twin run a deterministic
sample (every third small program) in the default run.
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest

from nczones.errors import GcodeError
from nczones.gcode import interpret
from nczones.machine import parse_machine
from tests.corpus import CORPUS, corpus_programs

MANIFEST = CORPUS / "MANIFEST.tsv"
pytestmark = [pytest.mark.corpus, pytest.mark.skipif(not MANIFEST.is_file(), reason="corpus not available")]

_AXES = ["X", "Y", "Z", "A", "B", "C", "U", "V", "W"]
MACHINE = parse_machine(
    "[machine]\naxes = " + str(_AXES).replace("'", '"') + '\npulse = "0.0001"\n'
    + "[machine.rapid]\n" + "\n".join(f'{a} = "1000"' for a in _AXES) + "\n"
    + "[machine.reference]\n" + "\n".join(f'{a} = "0"' for a in _AXES) + "\n"
    + "[tool_lengths]\n" + "\n".join(f'H{i} = "0"' for i in range(1, 100)) + "\n"
)
#: LinuxCNC programs run on a machine that models LinuxCNC's cutter compensation (a 1 mm tool for every
#: tool number: the corpus has no tool tables for most programs; LinuxCNC's own test directories with
#: tables are compared in test_canon_linuxcnc).
LINUXCNC_MACHINE = parse_machine(
    "[machine]\naxes = " + str(_AXES).replace("'", '"') + '\npulse = "0.0001"\ncutter_compensation = "linuxcnc"\n'
    + "[machine.rapid]\n" + "\n".join(f'{a} = "1000"' for a in _AXES) + "\n"
    + "[machine.reference]\n" + "\n".join(f'{a} = "0"' for a in _AXES) + "\n"
    + "[tool_lengths]\n" + "\n".join(f'H{i} = "0"' for i in range(1, 100)) + "\n"
    + "[tool_diameters]\n" + "\n".join(f'T{i} = "1"' for i in range(0, 100)) + "\n"
)

#: Path fragment -> why LinuxCNC does not accept the program as it stands in the corpus.
NOT_ACCEPTED: dict[str, str] = {
    "/tests/interp/bad/": "LinuxCNC's own must-fail tests",
    "m98m99/03-": "expected result is an error", "m98m99/04-": "expected result is an error",
    "m98m99/06-": "expected result is an error", "nested-sub-error": "expected result is an error",
    "nested-sub-in-file-error": "expected result is an error", "iniparam-failassign": "expected result is an error",
    "illegal": "expected result is an error", "-error": "expected result is an error",
    "camotics/examples/compass/": "G1 before any F word: LinuxCNC 'cannot do G1 with zero feed rate'",
    "varRefTests/LocalNamedTest": "reads #<x>, local to the subroutine, after it returned: 'named parameter not defined'",
    "varRefTests/GlobalNamedTest": "assigns #<_x>: 'Cannot assign to read-only parameter #<_x>' (rs274 2.9)",
    "gcode-rs/tests/data/_samples.ngc": "unclosed comment '( brocken comment'",
    "gcode-rs/tests/data/_gcodeLexer_samples.ngc": "unclosed comment '( brocken comment'",
    "nurbs/G5/Curva_Stella #1=1_G5.ngc": "G2.2 is not a LinuxCNC G code",
    "tests/interp/abort-hot-comment/": "(abort, ...) stops the program with an error (its expected output)",
    # needs files or configuration outside the program
    "nc_files/nestedcall.ngc": "calls o<g20sub>, an external subroutine file not in the corpus",
    "nc_files/plasmac/": "reads HAL pins (#<_hal[plasmac...]>) / uses plasmac user M codes of the QtPlasmaC config",
    "tests/interp/iniparam/": "reads INI values (#<_ini[...]>) of test.ini",
    "configs/sim/axis/laser/raster_test.ngc": "M11-M13 are remapped in the laser config INI",
    "configs/sim/axis/vismach/": "M428/M429, G68.2/G69 are remapped in the vismach configs' INI files",
    "configs/sim/axis/geometry/xyzc.ngc": "M110 is a user M code (external file M110)",
    "wz-tests/130207L.ngc": "M111 is a user M code (external file M111)",
}
#: Outcome codes that mean "needs a file outside the program" whatever the path.
NEEDS_OUTSIDE_CODES = {"GC393": "calls a subroutine that is not in the file (LinuxCNC searches SUBROUTINE_PATH)"}


programs = corpus_programs


def not_accepted_reason(rel: str, dialect: str, code: str = "") -> str | None:
    """Why LinuxCNC does not accept this program as it stands, or None if it does."""
    if not dialect.startswith("LinuxCNC"):
        return f"dialect {dialect}"
    for frag, why in NOT_ACCEPTED.items():
        if frag in rel:
            return why
    return NEEDS_OUTSIDE_CODES.get(code)


def outcome(path: Path, fast: bool = True, arc_tolerance="0.002", machine=None) -> tuple[str, str, str]:
    """(status, code, detail) of one program; status complete/unknown/rejected."""
    run = interpret(path, MACHINE if machine is None else machine, fast=fast, arc_tolerance=arc_tolerance)
    try:
        n = sum(len(c) for c in run)
    except GcodeError as exc:
        d = exc.diagnostics[0]
        assert d.code.startswith("GC") and d.span is not None and d.span.line >= 1, exc.render()
        return "rejected", d.code, d.message
    if run.unsupported:
        u = run.unsupported[0]
        assert u.reason and u.span is not None and u.span.line >= 1, u
        return "unknown", u.code, u.reason
    return "complete", "", f"{n} segments"


def _run(selection, arc_tolerance="0.002") -> dict:
    counts: dict[str, int] = {}
    reasons: dict[str, int] = {}
    accepted = complete = 0
    excluded: dict[str, int] = {}
    missing = []
    for rel, dialect in selection:
        status, code, detail = outcome(CORPUS / rel, arc_tolerance=arc_tolerance,
                                       machine=LINUXCNC_MACHINE if dialect.startswith("LinuxCNC") else MACHINE)
        counts[status] = counts.get(status, 0) + 1
        why = not_accepted_reason(rel, dialect, code)
        if why is not None:
            excluded[why] = excluded.get(why, 0) + 1
            continue
        accepted += 1
        if status == "complete":
            complete += 1
        else:
            key = f"{status} {code}"
            reasons[key] = reasons.get(key, 0) + 1
            missing.append(f"{key:16s} {rel}  ({detail[:70]})")
    return {"counts": counts, "reasons": reasons, "accepted": accepted, "complete": complete,
            "excluded": excluded, "missing": missing}


def _print(r: dict, dt: float, title: str) -> None:
    print(f"\n{title}: outcomes {r['counts']} in {dt:.1f}s")
    print(f"LinuxCNC-accepted programs interpreted completely: {r['complete']}/{r['accepted']} "
          f"= {r['complete'] / max(r['accepted'], 1):.1%} (target 90%)")
    print("accepted but not complete, by first reason:", dict(sorted(r["reasons"].items(), key=lambda kv: -kv[1])))
    print("not counted as accepted:", r["excluded"])
    for line in r["missing"]:
        print("   ", line)


#: Measured share of accepted programs interpreted completely with the default arc
#: tolerance of 0.002 mm (91.8 %, see specs/gcode-support.md, "Corpus coverage"); the
#: tests guard against regressions below it.
COVERAGE_FLOOR = 0.91
#: the sample's share with LinuxCNC's arc rule (measured 2026-12-07, suite37)
SAMPLE_FLOOR_LINUXCNC = 0.93  # 142/152 = 93.4 %


@pytest.mark.long
def test_corpus_outcomes(capsys):
    """Issue 3's target (>= 90 % of the programs LinuxCNC accepts are interpreted fully), met with
    the issue's default arc tolerance of 0.002 mm; all 746 programs, about 15 s (``-m long``: the default run
    takes the sample below)."""
    t0 = time.perf_counter()
    r = _run(programs())
    with capsys.disabled():
        _print(r, time.perf_counter() - t0, "corpus, default arc tolerance 0.002 mm")
    assert r["accepted"] > 400
    assert r["complete"] / r["accepted"] >= COVERAGE_FLOOR


@pytest.mark.long
def test_corpus_outcomes_with_linuxcncs_arc_rule(capsys):
    """The same with LinuxCNC's own arc acceptance rule (arc_tolerance="linuxcnc"): the programs
    LinuxCNC accepts, accepted as it does (``-m long``; the default run takes the sample below)."""
    t0 = time.perf_counter()
    r = _run(programs(), arc_tolerance="linuxcnc")
    with capsys.disabled():
        _print(r, time.perf_counter() - t0, "corpus, LinuxCNC's arc acceptance rule")
    assert r["accepted"] > 400
    assert r["complete"] / r["accepted"] >= 0.94  # measured 95.0 %


def _sample() -> list[tuple[str, str]]:
    out = []
    for k, (rel, dialect) in enumerate(programs()):
        try:
            size = (CORPUS / rel).stat().st_size
        except OSError:
            continue
        if size < 20_000 and k % 3 == 0:
            out.append((rel, dialect))
    return out


def test_corpus_outcomes_sample(capsys):
    """Every third small program: a defined outcome each, and the coverage floor on the sample."""
    t0 = time.perf_counter()
    sample = _sample()
    r = _run(sample)
    with capsys.disabled():
        _print({**r, "missing": []}, time.perf_counter() - t0, f"corpus sample ({len(sample)} programs)")
    assert sum(r["counts"].values()) == len(sample)
    # the sample's share is 138/152 = 90.8 % since two of its lathe cycles are unknown by design (G71 of
    # lathe_g7x_quadrants.ngc, G72 of g72-iterations-missing.ngc: LinuxCNC 2.9.0~pre1 and the later 2.9 versions
    # cut them differently, specs/turning.md "Version"); the whole corpus keeps COVERAGE_FLOOR
    assert r["accepted"] > 100 and r["complete"] / r["accepted"] >= COVERAGE_FLOOR - 0.005


def test_corpus_outcomes_sample_with_linuxcncs_arc_rule(capsys):
    """The sample with LinuxCNC's arc acceptance rule: a defined outcome each, and its measured share."""
    t0 = time.perf_counter()
    sample = _sample()
    r = _run(sample, arc_tolerance="linuxcnc")
    with capsys.disabled():
        _print({**r, "missing": []}, time.perf_counter() - t0, f"corpus sample, LinuxCNC's arc rule ({len(sample)})")
    assert sum(r["counts"].values()) == len(sample)
    assert r["accepted"] > 100 and r["complete"] / r["accepted"] >= SAMPLE_FLOOR_LINUXCNC


def test_nurbs_programs_are_interpreted_as_splines():
    """G6.2 and G5.2 corpus programs end complete, with SPLINE segments whose curves are valid clamped NURBS."""
    from nczones.geometry.nurbs import spline_curve
    from nczones.motion import SegmentKind

    rels = [r for r, _ in programs() if re.search(r"nurbs/G6/homer #1=1\.ngc$|nurbs/G5/nurbs-zx\.ngc$", r)]
    if len(rels) < 2:
        pytest.skip("NURBS samples not in the corpus")
    for rel in rels:
        status, code, detail = outcome(CORPUS / rel)
        assert status == "complete", (rel, code, detail)
        segs = [s for c in interpret(CORPUS / rel, MACHINE) for s in c.segments()]
        splines = [s for s in segs if s.kind is SegmentKind.SPLINE]
        assert splines
        for s in splines:
            c = spline_curve(s)
            assert c.points[0] == s.start and c.points[-1] == s.end
