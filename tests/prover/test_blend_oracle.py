"""The prover's blend enclosure holds the planner's blends (issue 35, specs/path-modes.md §5).

``tests/oracles/blend.py`` models LinuxCNC's parabolic blends and blend arcs from ``src/emc/tp``; for
generated corners every point it moves through must lie in the enclosure, checked two ways: in the
coordinates of the spec's parallelogram (``C + a (M1 - C) + b (M2 - C)``, ``a, b`` in ``[0, 1]``), and end
to end, a small forbidden box around a blend point off the programmed path must make ``verify`` not
``safe``.  Shrinking the enclosure to a quarter of each motion (``BLEND_FRACTION``) lets such a box through.
"""

from __future__ import annotations

import math
from decimal import Decimal

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import blend as blend_module
from nczones.prover import verify_text
from tests.oracles.blend import blend_arc, parabolic_blend

MACHINE = """
[machine]
name = "blend oracle"
axes = ["X", "Y"]
pulse = "0.001"
monitor_period_ms = "5"
[machine.rapid]
X = "10000"
Y = "10000"
[machine.reference]
X = "0"
Y = "0"
[[zones]]
name = "table"
kind = "box"
min = {{ X = "-500", Y = "-500" }}
max = {{ X = "500", Y = "500" }}
[[zones]]
name = "probe"
kind = "box"
forbid = true
min = {{ X = "{x0}", Y = "{y0}" }}
max = {{ X = "{x1}", Y = "{y1}" }}
"""
HALF = Decimal("0.01")  # the probe box's half-width


def _coords(p0, c, p1, q):
    """(a, b) with q - c = a (m1 - c) + b (m2 - c), m1 and m2 the midpoints of the two motions."""
    d1 = ((p0[0] - c[0]) / 2, (p0[1] - c[1]) / 2)
    d2 = ((p1[0] - c[0]) / 2, (p1[1] - c[1]) / 2)
    det = d1[0] * d2[1] - d1[1] * d2[0]
    r = (q[0] - c[0], q[1] - c[1])
    return (r[0] * d2[1] - r[1] * d2[0]) / det, (d1[0] * r[1] - d1[1] * r[0]) / det


def _dist_to_path(p0, c, p1, q):
    def seg(a, b):
        ab = (b[0] - a[0], b[1] - a[1])
        t = max(0.0, min(1.0, ((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / (ab[0] ** 2 + ab[1] ** 2)))
        return math.hypot(q[0] - a[0] - t * ab[0], q[1] - a[1] - t * ab[1])
    return min(seg(p0, c), seg(c, p1))


def _probe_verdict(p0, c, p1, q) -> str:
    x, y = (Decimal(repr(v)).quantize(Decimal("0.001")) for v in q)
    m = parse_machine(MACHINE.format(x0=x - HALF, y0=y - HALF, x1=x + HALF, y1=y + HALF))
    prog = (f"G61\nG0 X{p0[0]} Y{p0[1]}\nG64\nG1 F6000 X{c[0]} Y{c[1]}\nG1 X{p1[0]} Y{p1[1]}\n")
    return verify_text(prog, m).verdict.label


def _corner_cases():
    pt = st.tuples(st.integers(-200, 200), st.integers(-200, 200))
    return st.tuples(pt, pt, pt).filter(lambda t: abs((t[0][0] - t[1][0]) * (t[2][1] - t[1][1])
                                                       - (t[0][1] - t[1][1]) * (t[2][0] - t[1][0])) > 50)


def _blend_points(p0, c, p1, a1, a2, v1, v2):
    return (parabolic_blend(p0, c, p1, a1=a1, a2=a2, v1=v1, v2=v2)
            + blend_arc(p0, c, p1, a_max=min(a1, a2), v_goal=min(v1, v2)))


@settings(max_examples=40, deadline=None)
@given(_corner_cases(), st.floats(20, 3000), st.floats(20, 3000), st.floats(5, 800), st.floats(5, 800))
def test_every_blend_point_is_in_the_parallelogram(case, a1, a2, v1, v2):
    p0, c, p1 = case
    for q in _blend_points(p0, c, p1, a1, a2, v1, v2):
        a, b = _coords(p0, c, p1, q)
        assert -1e-6 <= a <= 1 + 1e-6 and -1e-6 <= b <= 1 + 1e-6, (q, a, b)


def _far_points(p0, c, p1, pts):
    """The blend points worth a probe: off the path by more than the probe, the farthest and the deepest into
    the motions."""
    off = [q for q in pts if _dist_to_path(p0, c, p1, q) > 0.05]
    if not off:
        return []
    far = max(off, key=lambda q: _dist_to_path(p0, c, p1, q))
    deep = max(off, key=lambda q: max(_coords(p0, c, p1, q)))
    return [far] if far == deep else [far, deep]


@settings(max_examples=8, deadline=None)
@given(_corner_cases(), st.floats(50, 2000), st.floats(50, 2000), st.floats(50, 800), st.floats(50, 800))
def test_a_probe_at_a_blend_point_is_never_proved_safe(case, a1, a2, v1, v2):
    p0, c, p1 = case
    for q in _far_points(p0, c, p1, _blend_points(p0, c, p1, a1, a2, v1, v2)):
        assert _probe_verdict(p0, c, p1, q) != "safe", q


# Corners whose blends use more than a quarter of a motion (short motions, slow deceleration of the first).
DEEP = [((0, 0), (10, 0), (10, 10), 50.0, 500.0, 500.0, 500.0),
        ((0, 0), (20, 5), (5, 20), 40.0, 400.0, 800.0, 800.0),
        ((-30, 0), (0, 0), (0, -8), 30.0, 300.0, 500.0, 500.0)]


def test_shrinking_the_enclosure_lets_a_blend_through(monkeypatch):
    probes = [(p0, c, p1, q) for p0, c, p1, a1, a2, v1, v2 in DEEP
              for q in _far_points(p0, c, p1, _blend_points(p0, c, p1, a1, a2, v1, v2))]
    assert probes and all(_probe_verdict(*p) != "safe" for p in probes)
    monkeypatch.setattr(blend_module, "BLEND_FRACTION", blend_module.BLEND_FRACTION / 2)
    assert any(_probe_verdict(*p) == "safe" for p in probes), "a quarter of each motion must not hold them"
