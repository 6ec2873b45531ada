"""An axis a block does not name under G51 scaling or G51.1 mirroring (``FanucInterpreter._unnamed_axis_moves``).

The model takes such an axis at its program value, transformed: on the first move after a G51 whose centre on
that axis is not where the tool stands, the axis would move.  Whether a control moves it or leaves it (the
independent reference reader, tests/oracles/fanuc_ref.py, leaves it) the manuals do not say, and either may be
the one that enters a zone: the block is ``unknown``.  Found by xform41 (2026-12-07): ``G51 X0 Y0 Z0 P0.5`` from
Z-10., then ``G01 X10. Y4.``, moved machine Z -209 -> -204 with a ``safe`` verdict.
"""

from __future__ import annotations

import pytest

from nczones.gcode import interpret_text
from nczones.prover import verify_text

from .helpers import mill

_HEAD = "O1\nG90 G17 G21 G54 G00 X0. Y0. Z-10.\nG01 F100.\n"
#: the same moves after the transform, 600 of them: past the fast path's threshold too
_MOVES = "".join(f"G01 X{k % 9}. Y{k % 4}.\n" for k in range(600))


@pytest.mark.parametrize("transform", ["G51 X0 Y0 Z0 P0.5", "G51 X0 Y0 Z0 I0.5 J0.5 K0.5", "G51 X0 Y0 Z0 I1. J1. K2.",
                                       "G51.1 Z-4."])
@pytest.mark.parametrize("fast", [True, False])
def test_an_unnamed_axis_that_would_move_is_unknown(transform, fast):
    text = _HEAD + transform + "\n" + _MOVES + "G50\nG50.1 Z0\nM30\n"
    run = interpret_text(text, mill(), fast=fast, file="t.nc")
    list(run.segments())  # (the interpretation is read as it is consumed)
    reasons = [u.reason for u in run.unsupported]
    assert any("not named in a block would move" in r for r in reasons), reasons
    assert verify_text(text, mill(), file="t.nc").verdict.label == "unknown"


@pytest.mark.parametrize("transform", ["G51 X0 Y0 P0.5", "G51 X0 Y0 Z-10. P0.5", "G51 X0 Y0 Z0 I0.5 J0.5 K1.",
                                       "G51 X0 Y0 Z0 P0.5\nG01 X1. Y1. Z-10."])
@pytest.mark.parametrize("fast", [True, False])
def test_an_unnamed_axis_at_its_place_is_modelled(transform, fast):
    """The centre where the tool stands, a factor of 1, or the axis named once: nothing moves unnamed."""
    text = _HEAD + transform + "\n" + _MOVES + "G50\nM30\n"
    run = interpret_text(text, mill(), fast=fast, file="t.nc")
    list(run.segments())
    assert not [u for u in run.unsupported if "not named in a block" in u.reason]
    assert run.status == "complete", run.unsupported
