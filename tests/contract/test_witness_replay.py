"""A ranged witness must replay (:mod:`nczones.pipeline.witnesses`): a witness at values where the control
refuses an earlier block is dropped; none left, the verdict is ``unknown`` (VF232), never ``safe``.

The LinuxCNC case (an I/J arc whose end is off its circle away from ``G54.Y = 0``) is
``tests/contract/test_range_seams.py::test_a_witness_stands_where_the_control_runs_the_program``."""

from __future__ import annotations

from fractions import Fraction
from unittest import mock

import pytest

from nczones.gcode.source import program_text
from nczones.pipeline import witnesses
from nczones.pipeline.verification import interpretation
from nczones.prover import verify_text
from nczones.prover.options import VerifyOptions
from tests.contract.test_range_seams import Setup, machine_for

_Z = (Fraction(-80), Fraction(-80), Fraction(-30)), (Fraction(80), Fraction(80), Fraction(260))
#: a clamp the rapid along work Y0 meets only when G54.Y is 0.5 or more
_CLAMP = ("clamp", (Fraction(25), Fraction(1, 2), Fraction(-30)), (Fraction(40), Fraction(5), Fraction(260)), True,
          False)
#: the first arc runs from the start (a machine position): its chord grows with |G54.Y|
_R_ARC = "G21 G90 G17 G54 F600.\nG2 X-10. Y0. R5.\nG0 X30. Y0.\nM30\n"
_IJ_ARC = "G21 G90 G17 G54 F600.\nG2 X-10. Y0. I-5. J0.\nG0 X30. Y0.\nM30\n"


def _setup(dialect: str) -> Setup:
    return Setup(dialect, "G61", "linear", (("travel", *_Z, False, False), _CLAMP))


def test_a_fanuc_r_arc_too_short_at_the_witness_drops_it():
    """Fanuc: ``R5`` reaches the end only while the chord is 10 (within the tolerance), so the control runs line
    2 only near ``G54.Y = 0`` and the clamp (from 0.5) is never reached: the witness is dropped (GC302 there)."""
    setup = _setup("fanuc")
    for y in ("0", "0.1"):
        assert verify_text(_R_ARC, machine_for(setup, {"G54.Y": Fraction(y)})).verdict.label == "safe"
    got = verify_text(_R_ARC, machine_for(setup), params=["G54.Y=-1..1"])
    assert got.verdict.label == "unknown" and not got.violations
    (why,) = [r for r in got.reasons if r.code == "VF232"]
    assert "refuses an earlier block, line 2" in why.message and "GC302" in why.message, why.message


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_a_witness_that_replays_stays_unsafe(dialect):
    """Without the arc the rapid runs at every value: its witness replays and the verdict stays ``unsafe``."""
    text = "G21 G90 G17 G54 F600.\nG0 X30. Y0.\nM30\n"
    got = verify_text(text, machine_for(_setup(dialect)), params=["G54.Y=-1..1"])
    assert got.verdict.label == "unsafe"
    assert all(dict(v.params)["G54.Y"] >= Fraction(1, 2) for v in got.violations)
    assert not any("dropped" in n for n in got.notes)


#: a post the rapid to X45 meets while ``|G54.Y|`` is under 0.1, where the control runs the arc
_POST = ("post", (Fraction(42), Fraction(-1, 10), Fraction(-30)), (Fraction(44), Fraction(1, 10), Fraction(260)), True,
         False)


def test_a_witness_kept_beside_one_dropped():
    """Line 3's rapid meets the post near ``G54.Y = 0``, where the control runs the arc (kept); line 4's meets
    the clamp only from 0.5, where it refuses the arc (dropped, with a note): the verdict stays ``unsafe``."""
    setup = Setup("linuxcnc", "G61", "linear", (("travel", *_Z, False, False), _CLAMP, _POST))
    text = "G21 G90 G17 G54 F600.\nG2 X-10. Y0. I-5. J0.\nG0 X45. Y0.\nG0 X30. Y0.\nM30\n"
    machine = machine_for(setup)
    with mock.patch.object(witnesses, "replayed_witnesses", lambda result, *args: result):
        ranged = verify_text(text, machine, params=["G54.Y=-1..1"])
    post, clamp = ranged.violations
    assert (post.line, post.zone, clamp.line, clamp.zone) == (3, "post", 4, "clamp")
    assert abs(dict(post.params)["G54.Y"]) < Fraction(1, 10) <= Fraction(1, 2) <= dict(clamp.params)["G54.Y"]
    source, options = program_text(text, "<program>"), VerifyOptions.from_keywords()
    out = witnesses.replayed_witnesses(ranged, machine, lambda m: interpretation(source, m, options))
    assert out.violations == (post,)
    assert out.verdict.label == "unsafe"
    assert any("witness of line 4 was dropped" in n and "earlier block, line 2" in n and "GC301" in n
               for n in out.notes), out.notes
    assert verify_text(text, machine, params=["G54.Y=-1..1"]).violations == (post,)
