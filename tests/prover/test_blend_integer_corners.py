"""The corner check's per-motion shortcuts (``nczones/prover/blend.py``) decide as the plain Fraction code does.

The corner check runs on every motion of the full path (issue 36: programs the double pass declines), so its
per-motion tests are written for speed (full38):

* ``_short`` (may LinuxCNC drop this motion?) compares ``|e - s| < DROPPED_BELOW`` in integers: it is checked
  against the Fraction expression on numbers at and about the bound;
* a LinuxCNC corner of two straight motions keeps its three points as integers and takes the first two from
  the corner before it (a chain of motions shares them) and its mode's facts from the last mode asked: the
  reasons and the corner count are checked against the same check with that integer screen off (every corner
  screened by its exact Fraction box, :meth:`CornerCheck._screen_box`), on random walks next to a clamp with
  mode changes and G61 stretches (the chain and the facts start over), one motion at a time;
* a mutation: a chain that takes a stale point (the corner's first point from two corners back) proves a
  corner the exact boxes do not, and the agreement check sees it.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.motion import DROPPED_BELOW, MotionChunk
from nczones.prover import blend
from tests.prover.test_blend_screens import MACHINE, _capture, _mm, _program

# ---------------------------------------------------------------------------------------------- _short

_AROUND = st.one_of(
    st.builds(lambda k, d: DROPPED_BELOW + Fraction(k, d), st.integers(-3, 3), st.sampled_from([10**9, 10**20, 2**60])),
    st.fractions(max_denominator=10**12), st.integers(-2, 2),
    st.builds(Fraction, st.floats(-1e-6, 1e-6, allow_nan=False)))


@settings(max_examples=150, deadline=None)
@given(start=st.lists(st.one_of(st.fractions(-10, 10), st.integers(-5, 5), st.builds(Fraction, st.floats(-10, 10))),
                      min_size=1, max_size=4),
       step=st.lists(_AROUND, min_size=4, max_size=4), sign=st.lists(st.sampled_from([1, -1]), min_size=4, max_size=4))
def test_short_is_the_fraction_test(start, step, sign):
    """Ends at, just inside and just outside DROPPED_BELOW from the start (either side), ints among them."""
    end = [s + k * d for s, k, d in zip(start, sign, step)]
    end = [int(e) if isinstance(s, int) and e == int(e) else e for s, e in zip(start, end)]
    want = all(abs(e - s) < DROPPED_BELOW for s, e in zip(start, end))
    assert blend._short(tuple(start), tuple(end)) == want
    assert blend._short(tuple(start), tuple(start))


# ---------------------------------------------------------------------------------------------- the integer corners

def _exact_only(monkeypatch) -> None:
    """No integer screen: every LinuxCNC corner of two straight motions screened by its exact Fraction box."""
    facts = blend.CornerCheck._facts

    def no_ints(self, mode):
        naive, fanuc_run, _bound = facts(self, mode)
        return naive, fanuc_run, False

    monkeypatch.setattr(blend.CornerCheck, "_facts", no_ints)


def _one_motion(args: tuple, chunks: list) -> tuple:
    """The reasons and corner count of a fresh check given ``chunks`` one motion at a time."""
    check = blend.CornerCheck(*args)
    for chunk in chunks:
        for seg in (chunk.segments() if isinstance(chunk, MotionChunk) else [chunk]):
            check.take(seg)
    reasons = check.finish()
    return sorted((r.code, r.message, r.block) for r in reasons), check.corners


def _agree(program: str, m, monkeypatch) -> tuple:
    monkeypatch.setattr(blend, "MAX_REASONS", 10**6)  # every failing corner named
    _result, args, chunks = _capture(program, m, monkeypatch)
    fast = _one_motion(args, chunks)
    with monkeypatch.context() as mp:
        _exact_only(mp)
        exact = _one_motion(args, chunks)
    assert fast == exact
    return fast


MODES = ["G64", "G64 P0.5", "G64 P0.01 Q0.02", "G64 P2"]


def _clamp_at(pts: list, at: int, face: int, size: int, side: int) -> str:
    px, py = pts[at]
    x0, y0 = [(px + face, py - size // 2), (px - face - size, py - size // 2), (px - size // 2, py + face),
              (px - size // 2, py - face - size)][side]
    return MACHINE.format(x0=_mm(x0), y0=_mm(y0), x1=_mm(x0 + size), y1=_mm(y0 + size))


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1), mode=st.sampled_from(MODES), g61=st.sampled_from([0.0, 0.05, 0.2]),
       at=st.integers(1, 500), face=st.sampled_from([0, 1, 500, 1500]), size=st.integers(1, 4000),
       side=st.integers(0, 3))
def test_the_integer_corners_agree_with_the_exact_boxes(seed, mode, g61, at, face, size, side, monkeypatch):
    """Lines only (the integer screen's corners), a clamp face ``face`` thousandths beyond a point of the walk."""
    program, pts = _program(seed, mode, g61, arcs=0.0)
    _agree(program, parse_machine(_clamp_at(pts, at, face, size, side)), monkeypatch)


def _trusted_chain(monkeypatch) -> None:
    """Mutation: the chain's points taken for the corner's first two without checking they are its points."""
    queue = blend.CornerCheck._queue

    def trusting(self, a, b, mode):
        (q0, i0), (q1, i1) = self._chain
        if q0 is not None:
            self._chain = ((a.start, i0), (a.end, i1))
        queue(self, a, b, mode)

    monkeypatch.setattr(blend.CornerCheck, "_queue", trusting)


# Lines along Y0 (their corners' chain), a stop (G61), then back in G64 a line out to X50 Y0 and back to X2 Y1: the
# corner at X50 Y0 may be rounded over X26..50 Y0..0.5 (half of each line), which passes the clamp X45..47
# Y0.01..0.05 between the two lines (line 2 is at Y0.0625..0.104 there).  The chain's points (X1, X2 on Y0) would
# give that corner the box X1..2 Y0..1.
CHAIN = ("G17 G21 G90 G54\nG0 X0 Y0\nG64\nG1 F800 X1\nX2\nX3\nG61\nX2\nG64\nX50 Y0\nX2 Y1\nX3\nM2\n")


def test_a_trusted_chain_is_caught(monkeypatch):
    m = parse_machine(MACHINE.format(x0="45", y0="0.01", x1="47", y1="0.05"))
    reasons, _corners = _agree(CHAIN, m, monkeypatch)
    assert len(reasons) == 1 and "lines 10 and 11" in reasons[0][1] and "`clamp`" in reasons[0][1]
    with monkeypatch.context() as mp:
        _trusted_chain(mp)
        with pytest.raises(AssertionError):
            _agree(CHAIN, m, mp)


@pytest.mark.parametrize("mode", MODES)
def test_mode_changes_and_stops_between_corners(mode, monkeypatch):
    """A walk that changes its mode and stops (G61) every few blocks: the facts and the chain start over."""
    program, pts = _program(5, mode, 0.3, arcs=0.0)
    for at in (10, 200):
        _agree(program, parse_machine(_clamp_at(pts, at, 0, 2000, 1)), monkeypatch)
