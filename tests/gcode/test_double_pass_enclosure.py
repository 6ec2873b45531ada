"""The double pass's boxes (:class:`nczones.gcode.linuxcnc.doubles.DoublePath`) and the corner tests on them.

* :func:`~nczones.gcode.linuxcnc.doubles.widened` (integers) is the ``Fraction`` formula it replaced, on
  doubles of every magnitude (subnormals included), offset bounds and G91 chain bounds.
* :meth:`~nczones.gcode.linuxcnc.doubles.DoublePath.apart` is sound: rows it calls apart have boxes farther
  apart than the gap on some axis; and :func:`nczones.prover.doubles.may_be_zero`, which asks it first, gives
  the answer of the boxes compared exactly on paths of motions around the dropped length.
* The box of rows ``k - 1``..``k + 1``, which the corner test tries first, holds the corner's own box (the
  points ``P1 + a (M1 - P1) + b (M2 - P1)`` bounded with the rows' boxes).
"""

from __future__ import annotations

import math
from array import array
from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.doubles import DoublePath, widened
from nczones.motion import DROPPED_BELOW
from nczones.prover.doubles import may_be_zero
from tests.sizes import examples

ULP, TINY, GRID = F(1, 2**52), F(1, 2**8), 2**60

doubles = st.one_of(st.floats(allow_nan=False, allow_infinity=False, min_value=-1e12, max_value=1e12),
                    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e-300, max_value=1e-300),
                    st.sampled_from([0.0, -0.0, 5e-324, 0.1, 100.0001, 2.0**-60, 3e-7]))
offset_bounds = st.sampled_from([F(0), F(0), F(1, 10), F(123456789, 1000), F(1, 3), F(10**9)])
incs = st.sampled_from([0.0, 0.0, 1e-12, 2.0**-40, 3.3e-9])


def fraction_widened(a_lo, a_hi, ob, inc):
    """The formula :func:`widened` replaced, in ``Fraction``."""
    widen = (4 * (F(max(abs(a_lo), abs(a_hi))) + ob) + TINY) * ULP
    if inc:
        widen += F(inc)
    return F(math.floor((F(a_lo) - widen) * GRID), GRID), F(math.ceil((F(a_hi) + widen) * GRID), GRID)


@settings(max_examples=examples(400, 3000), deadline=None, derandomize=True)
@given(doubles, doubles, offset_bounds, incs)
def test_widened_is_the_fraction_formula(x, y, ob, inc):
    a_lo, a_hi = min(x, y), max(x, y)
    assert widened(a_lo, a_hi, ob, inc) == fraction_widened(a_lo, a_hi, ob, inc)


steps = st.sampled_from([0.0, 1e-7, 2.9e-7, 2.9999999e-7, 3e-7, 3.0000001e-7, 3.1e-7, 6e-7, 6.1e-7, 1e-3, 7.0])


@st.composite
def paths(draw):
    """A path of two axes: rows near a random base, moving by steps around the dropped length, maybe at the
    start on one axis for a while (exact there), with offsets' and G91 chains' bounds."""
    n = draw(st.integers(3, 8))
    base = draw(st.sampled_from([0.0, 1.0, 100.0001, 123456.789, -3e5]))
    cols, first = [], []
    for _ in range(2):
        rows = [base]
        for _ in range(n):
            rows.append(rows[-1] + draw(steps) * draw(st.sampled_from([1, -1])))
        cols.append(array("d", rows))
        first.append(draw(st.sampled_from([1, 1, 2, 0])))
    first = [0 if f == 0 else f for f in first]
    for c, f in zip(cols, first):  # rows before the first motion of an axis stay at its start
        for r in range(1, f if f else n + 1):
            c[r] = c[0]
    ob = draw(offset_bounds)
    inc = tuple(draw(st.sampled_from([(), (0.0, 0.0), (1e-9, 0.0), (2.0**-30, 2.0**-30)])))
    return DoublePath(("X", "Y"), tuple(cols), (ob, ob), n, n, 0, n, (F(base), F(base)), tuple(first), inc_bound=inc)


def row_box(path, r):
    return path.enclosure(r + 1, r)


@settings(max_examples=examples(200, 1200), deadline=None, derandomize=True)
@given(paths(), st.data())
def test_apart_is_sound_and_may_be_zero_is_the_boxes_answer(path, data):
    k = data.draw(st.integers(1, path.motions))
    gap = data.draw(st.sampled_from([F(0), DROPPED_BELOW, F(1, 10**6)]))
    (l0, h0), (l1, h1) = row_box(path, k - 1), row_box(path, k)
    if path.apart(k - 1, k, gap):
        assert any(l0[a] - h1[a] >= gap or l1[a] - h0[a] >= gap for a in l0)
    exact = all(l0[a] - h1[a] < DROPPED_BELOW and l1[a] - h0[a] < DROPPED_BELOW for a in l0)
    assert may_be_zero(path, k) == exact


def test_apart_answers_at_once_for_rows_well_apart():
    # the quick answer is the common one: a motion of a millimetre is apart; one at the dropped length is not shown
    path = DoublePath(("X",), (array("d", [0.0, 50.0, 51.0, 51.0 + 3e-7]),), (F(0),), 3, 3, 0, 3, (F(0),), (1,))
    assert path.apart(1, 2, DROPPED_BELOW)
    assert not path.apart(2, 3, DROPPED_BELOW)


@settings(max_examples=examples(150, 800), deadline=None, derandomize=True)
@given(paths(), st.data())
def test_the_rows_box_holds_the_corners_box(path, data):
    k = data.draw(st.integers(1, path.motions - 1))
    (l0, h0), (l1, h1), (l2, h2) = (row_box(path, r) for r in (k - 1, k, k + 1))
    lo = {a: min(l1[a], (l0[a] + l1[a]) / 2, (l1[a] + l2[a]) / 2, (l0[a] + l2[a]) / 2) for a in l1}
    hi = {a: max(h1[a], (h0[a] + h1[a]) / 2, (h1[a] + h2[a]) / 2, (h0[a] + h2[a]) / 2) for a in h1}
    rlo, rhi = path.enclosure(k, k + 1)
    assert all(rlo[a] <= lo[a] and hi[a] <= rhi[a] for a in lo)
