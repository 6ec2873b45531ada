"""``r_screen``'s quick decline test gives the full test's answer (issue 36, boot42).

``double_arcs.r_screen`` skips its last decline test, ``x > 8 e_x``, where ``ed (l1 + ed) < _QUICK_X R**2``
and ``x > 1e-9 R**2``: its docstring argues that the two imply it.  Here the function is held, bit for bit, to
the test as it was written before (every test computed), on arcs drawn about that boundary: coordinates of any
magnitude, radii down to a millionth of them, chords up to a little over ``2|R|``, and doubles of no size.
"""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import double_arcs
from nczones.gcode.linuxcnc.double_arcs import r_screen

_U = 2.0**-52


def full_r_screen(sx, sy, ex, ey, r, offb, rel=2.0**-51):
    """``r_screen`` with its decline test written out in full (as before the quick test)."""
    dx, dy = ex - sx, ey - sy
    ax, ay, ar = abs(dx), abs(dy), abs(r)
    l1 = ax + ay
    m = 2.0 * (abs(sx) + abs(sy) + ar) + l1 + offb
    ed = (9.0 * m + 2.0**-7 + l1) * _U
    dd = dx * dx + dy * dy
    rr = r * r
    x = rr - dd / 4
    if not (dd > 17 * ed * ed and x > 1e-9 * rr
            and x > 8 * (rr * rel + (l1 * ed + ed * ed + dd * _U) / 2 + (rr + dd) * _U)):
        return "an R arc of a chord about 0 or about 2|R| or longer"
    return "taken"


@st.composite
def arcs(draw):
    """An R arc about the decline's boundary: start at magnitude 10**a, |R| = 10**(a - b), a chord of c 2|R|."""
    a = draw(st.integers(-3, 13))
    b = draw(st.integers(0, 9))
    scale = 10.0**a
    sx = draw(st.floats(-1, 1)) * scale
    sy = draw(st.floats(-1, 1)) * scale
    r = draw(st.sampled_from([1.0, -1.0])) * 10.0**(a - b) * draw(st.floats(0.5, 5))
    near = 1 - draw(st.floats(0, 1)) * 10.0**-draw(st.integers(4, 15))  # a chord within 10**-k of 2|R|
    c = draw(st.one_of(st.floats(0, 1.0001), st.just(near), st.floats(0, 1e-6)))
    t = draw(st.floats(0, 2 * math.pi))
    chord = 2 * abs(r) * c
    ex, ey = sx + chord * math.cos(t), sy + chord * math.sin(t)
    offb = draw(st.sampled_from([0.0, 100.00000000000001, scale]))
    rel = draw(st.sampled_from([2.0**-51, 2.0**-50]))
    return sx, sy, ex, ey, r, offb, rel


def _same(args):
    got = r_screen(*args)
    want = full_r_screen(*args)
    assert (got if got.__class__ is str else "taken") == want, args


@settings(max_examples=3000, deadline=None)
@given(arcs())
def test_the_quick_test_answers_as_the_full_one_about_the_boundary(args):
    _same(args)


@settings(max_examples=500, deadline=None)
@given(st.tuples(*[st.floats(allow_nan=True, allow_infinity=True)] * 5),
       st.sampled_from([0.0, 1e300, math.inf]), st.sampled_from([2.0**-51, 2.0**-50]))
def test_the_quick_test_answers_as_the_full_one_on_any_doubles(ends, offb, rel):
    _same((*ends, offb, rel))


def test_the_quick_test_is_taken_and_has_teeth(monkeypatch):
    # a common arc takes the quick test (x > 8 e_x not computed); a quick constant five times too large accepts
    # an arc the full test declines: the boundary draws above find such arcs
    args = (0.0, 0.0, 3.0, 4.0, 2.6, 100.00000000000001, 2.0**-51)
    assert r_screen(*args).__class__ is tuple and full_r_screen(*args) == "taken"
    monkeypatch.setattr(double_arcs, "_QUICK_X", 2e-9)
    found = [a for a in _boundary_sample() if (r_screen(*a).__class__ is str) != (full_r_screen(*a) != "taken")]
    assert found, "a quick constant too large must change some answer"


def _boundary_sample():
    """Arcs whose x lies between 1e-9 R**2 and 8 e_x when the coordinates are large: c close to 1."""
    out = []
    for a in range(3, 12):
        for b in range(3, 9):
            r = 10.0**(a - b)
            for k in range(1, 400):
                c = 1 - k * 10.0**(-12 + (b - 3))
                out.append((10.0**a, 10.0**a, 10.0**a + 2 * r * c, 10.0**a, r, 0.0, 2.0**-51))
    return out
