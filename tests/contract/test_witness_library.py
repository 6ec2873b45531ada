"""A ranged witness in a ``--library`` subprogram replays by its file and line (:mod:`nczones.pipeline.witnesses`).

LinuxCNC ``o<hit> call`` reads ``hit.ngc`` from the library folder; Fanuc ``M98 P1234`` and ``G65 P1234`` read
``O1234.nc``.  The subprogram's line 2 is a rapid into the clamp, violating once ``G54.Y`` is 0.5 or more.

1. The call reached at every value: the witness names the library file and line, and the verdict stays
   ``unsafe`` with it; written into the machine file, its values give ``unsafe`` on that file and line.
2. The main program's line 5 is an arc the control refuses away from ``G54.Y = 0`` (LinuxCNC: the end is off
   the circle; Fanuc: R too short for the chord): at the witness's values the call is never made, the witness
   is dropped, and the verdict is ``unknown`` (VF232).
3. The match is by file and line: a replay that moves on the main file's line 2 (G53 rapids, lines 2-4) and
   then ends before the call does not reach the library's line 2.  (An end-to-end program cannot show this
   through a refusal: a refused block ends the replay before it hands out the motion ahead of it, and every
   witness is dropped then.)
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from unittest import mock

import pytest

from nczones.pipeline import witnesses
from nczones.prover import verify_text
from tests.contract.test_range_seams import Setup, machine_for

_Z = (Fraction(-80), Fraction(-80), Fraction(-30)), (Fraction(80), Fraction(80), Fraction(260))
_CLAMP = ("clamp", (Fraction(25), Fraction(1, 2), Fraction(-30)), (Fraction(40), Fraction(5), Fraction(260)), True,
          False)
_SUB = {"linuxcnc": ("hit.ngc", "o<hit> sub\nG0 X30. Y0.\nG0 X0. Y0.\no<hit> endsub\nM2\n"),
        "fanuc": ("O1234.nc", "O1234 (HIT)\nG0 X30. Y0.\nG0 X0. Y0.\nM99\n")}
_CALL = {"linuxcnc": "o<hit> call\n", "fanuc": "M98 P1234\nG65 P1234\n"}
_ARC = {"linuxcnc": "G2 X-10. Y0. I-5. J0.\n", "fanuc": "G2 X-10. Y0. R5.\n"}
_START = "G21 G90 G17 G54 F600.\nG53 G0 X0. Y0. Z140.\nG53 G0 Z130.\nG53 G0 Z140.\n"
DIALECTS = ["linuxcnc", "fanuc"]


def _library(tmp_path: Path, dialect: str) -> tuple[str, Path]:
    name, text = _SUB[dialect]
    (tmp_path / name).write_text(text)
    return str(tmp_path), tmp_path / name


def _machine(dialect: str, values: dict[str, Fraction] | None = None):
    return machine_for(Setup(dialect, "G61", "linear", (("travel", *_Z, False, False), _CLAMP)), values)


@pytest.mark.parametrize("dialect", DIALECTS)
def test_a_witness_in_a_library_subprogram_stays_unsafe(tmp_path, dialect):
    library, sub = _library(tmp_path, dialect)
    text = _START + _CALL[dialect] + "M30\n"
    got = verify_text(text, _machine(dialect), params=["G54.Y=-1..1"], library=library)
    assert got.verdict.label == "unsafe", (got.reasons, got.notes)
    # (Fanuc: the G65 call's witness of the same line is not replayed again, a note says so)
    assert not any("refuses" in n or "stops before" in n for n in got.notes), got.notes
    first = got.violations[0]
    assert Path(first.span.file) == sub and first.line == 2, first.span
    assert dict(first.params)["G54.Y"] >= Fraction(1, 2)
    # the witness replays: its values written into the machine, the same file and line violate
    at = verify_text(text, _machine(dialect, dict(first.params)), library=library)
    assert at.verdict.label == "unsafe"
    assert any(Path(v.span.file) == sub and v.line == 2 for v in at.violations), at.violations


@pytest.mark.parametrize("dialect", DIALECTS)
def test_a_library_line_is_not_taken_for_the_main_files_line_of_that_number(tmp_path, dialect):
    library, sub = _library(tmp_path, dialect)
    text = _START + _ARC[dialect] + _CALL[dialect] + "M30\n"
    machine = _machine(dialect)
    with mock.patch.object(witnesses, "replayed_witnesses", lambda result, *args: result):
        unchecked = verify_text(text, machine, params=["G54.Y=-1..1"], library=library)
    assert unchecked.verdict.label == "unsafe"  # the prover's witness, before the replay
    found = {(Path(v.span.file), v.line) for v in unchecked.violations}
    assert (sub, 2) in found and {f for f, _ in found} == {sub}, found
    got = verify_text(text, machine, params=["G54.Y=-1..1"], library=library)
    assert got.verdict.label == "unknown" and not got.violations
    refused = [r for r in got.reasons if r.code == "VF232"]
    assert refused and all("line 5" in r.message for r in refused), [r.message for r in got.reasons]
    assert {(Path(r.span.file), r.span.line) for r in refused} == found


@pytest.mark.parametrize("dialect", DIALECTS)
def test_a_replay_that_moves_on_the_main_files_line_2_does_not_reach_the_librarys(tmp_path, dialect):
    from nczones.gcode.source import program_text
    from nczones.pipeline.verification import interpretation
    from nczones.prover.options import VerifyOptions

    library, sub = _library(tmp_path, dialect)
    machine = _machine(dialect)
    ranged = verify_text(_START + _CALL[dialect] + "M30\n", machine, params=["G54.Y=-1..1"], library=library)
    assert (Path(ranged.violations[0].span.file), ranged.violations[0].line) == (sub, 2)
    options = VerifyOptions.from_keywords(library=library)
    ends_early = program_text(_START + "M30\n", "<program>")  # the main file's lines 2-4 move, no call
    out = witnesses.replayed_witnesses(ranged, machine, lambda m: interpretation(ends_early, m, options))
    assert out.verdict.label == "unknown" and not out.violations
    assert all("stops before its line" in r.message for r in out.reasons if r.code == "VF232")
    reaches = program_text(_START + _CALL[dialect] + "M30\n", "<program>")
    assert witnesses.replayed_witnesses(ranged, machine, lambda m: interpretation(reaches, m, options)) == ranged
