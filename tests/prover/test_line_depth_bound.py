"""A block that already is a violation skips a later motion that cannot be deeper (``Prover._no_deeper``, with
:func:`nczones.prover.exact.line_depth_bound`).

A report keeps each block's first violation and raises its depth when a later motion of the block (a loop's next
pass) goes deeper; building that later violation in full (witness, first exit, Z3's confirmation, depth) cost a
229-line unsafe program some 4,000 of them, seconds (issue 36's slow unsafe programs).  Held here:

* the bound is at least :func:`~nczones.prover.exact.line_depth` (and every sampled point's depth) for every zone
  kind, allowed and forbidden, with margins and tool-tip zones; a bound of the larger end alone is wrong for a
  forbidden box (a piece through it is deepest inside) and is caught;
* reports are the same, word for word, with the skip and without it, on drawn machines and programs whose body
  runs three times (its violations come back, deeper or not), and the skip is taken.
"""

from __future__ import annotations

from fractions import Fraction as F

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import NczonesError
from nczones.prover import core, verify_text
from nczones.prover import exact as ex
from nczones.prover.render import to_json_dict
from nczones.testing import machines, programs
from nczones.zones import BoxZone, PolygonZone, Region, SteppedZone, ZonePoint

AXES = ("X", "Y", "Z")
small = st.fractions(min_value=-40, max_value=40, max_denominator=8)


@st.composite
def zones(draw):
    kind = draw(st.sampled_from(("box", "stepped", "polygon")))
    forbid = draw(st.booleans())
    point = ZonePoint.TIP if draw(st.integers(0, 3)) == 0 else ZonePoint.MACHINE
    if kind == "box":
        limits = []
        for a in AXES:
            lo, hi = sorted((draw(small), draw(small)))
            limits.append((a, lo if draw(st.booleans()) else None, hi + 1 if draw(st.booleans()) else None))
        return BoxZone("z", tuple(limits), forbid=forbid, point=point)
    if kind == "stepped":
        start = draw(small)
        uptos = sorted({start + draw(st.fractions(min_value=F(1, 8), max_value=30, max_denominator=8))
                        for _ in range(draw(st.integers(1, 5)))})
        regions = []
        for u in uptos:
            lo, hi = sorted((draw(small), draw(small)))
            regions.append(Region(u, lo if draw(st.booleans()) else None, hi if draw(st.booleans()) else None))
        return SteppedZone("z", "X", "Y", start, tuple(regions), forbid=forbid, point=point)
    n = draw(st.integers(3, 8))  # a star around the origin: simple
    import math

    verts = []
    for i in range(n):
        r = draw(st.integers(2, 30))
        th = 2 * math.pi * i / n
        verts.append((F(round(r * math.cos(th) * 8), 8), F(round(r * math.sin(th) * 8), 8)))
    z_lo = draw(st.one_of(st.none(), small))
    limits = (("Z", z_lo, None),) if z_lo is not None else ()
    return PolygonZone("z", ("X", "Y"), tuple(verts), limits, forbid=forbid, point=point)


@settings(max_examples=150, deadline=None)
@given(zone=zones(), p0=st.tuples(small, small, small), p1=st.tuples(small, small, small),
       margin=st.sampled_from((F(0), F(1, 2), F(3))), tool=st.sampled_from((F(0), F(5))),
       ts=st.lists(st.fractions(min_value=0, max_value=1, max_denominator=97), max_size=8))
def test_the_bound_holds_the_depth(zone, p0, p1, margin, tool, ts):
    from nczones.machine import polygon_problem

    if isinstance(zone, PolygonZone) and polygon_problem(list(zone.vertices)):
        return
    bound = ex.line_depth_bound(zone, p0, p1, AXES, margin, tool, "Z")
    depth, _t, _exact = ex.line_depth(zone, p0, p1, AXES, margin, tool, "Z")
    assert depth <= bound
    shift = tool if zone.point is ZonePoint.TIP else F(0)
    for t in ts:
        p = {a: p0[i] + t * (p1[i] - p0[i]) - (shift if a == "Z" else 0) for i, a in enumerate(AXES)}
        assert ex.point_depth(zone, {a: p[a] for a in zone.axes}, margin) <= bound


def test_the_larger_end_alone_is_not_a_bound_through_a_forbidden_box():
    hole = BoxZone("h", (("X", F(0), F(10)),), forbid=True)
    p0, p1 = (F(-2),), (F(12),)
    ends = max(ex.point_depth(hole, {"X": p0[0]}), ex.point_depth(hole, {"X": p1[0]}))
    assert ends == 0 and ex.line_depth(hole, p0, p1, ("X",), F(0), F(0), None)[0] == 5
    assert ex.line_depth_bound(hole, p0, p1, ("X",), F(0), F(0), None) >= 5


def _report(text: str, machine) -> dict:
    d = to_json_dict(verify_text(text, machine, file="t.ngc"))
    for k in ("stats", "timings", "profile"):
        d.pop(k, None)
    return d


def _with_holes(text: str, cycle: str) -> str:
    """The program with a canned cycle of several holes (one block, several motions of it) before its end."""
    lines = [ln for ln in text.splitlines() if ln.strip() not in ("%", "M30", "")]
    return "\n".join([*lines, cycle, "G90 G80", "M30", ""])


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(st.data())
def test_reports_are_the_same_with_and_without_the_skip(data):
    """Drawn machines (every zone kind) and programs, ended by a cycle of 2-6 holes at drawn steps and depths
    (in G91: each hole from the last), near and past the zones: the same report with and without the skip."""
    machine = data.draw(machines(axes=AXES, allow_kinds=("stepped", "box", "polygon")))
    body = data.draw(programs(machine, max_blocks=6, subprograms=False, arcs=False))
    step = st.sampled_from(("0", "0.5", "-1", "3", "-7.25"))
    cycle = (f"G91 G{data.draw(st.sampled_from(('81', '83 Q7')))} X{data.draw(step)} Y{data.draw(step)} "
             f"Z-{data.draw(st.sampled_from(('1', '4.5', '30', '90')))} R-{data.draw(st.sampled_from(('0', '2')))} "
             f"L{data.draw(st.integers(2, 6))}")
    text = _with_holes(body, cycle)
    try:
        with_skip = _report(text, machine)
    except NczonesError:
        return  # a cycle the machine's state refuses (the same refusal either way)
    real = core.Prover._no_deeper
    core.Prover._no_deeper = lambda self, seg, pieces, known: False
    try:
        without = _report(text, machine)
    finally:
        core.Prover._no_deeper = real
    assert with_skip == without


def _mill():
    from nczones.machine import parse_machine
    from tests.machines import box_zone, machine_text

    return parse_machine(machine_text("xyz_corner_screens", extra=box_zone(
        "table", {"X": "-60", "Y": "-60", "Z": "-50"}, {"X": "60", "Y": "60", "Z": "50"})))


#: One canned-cycle block of 40 holes (G91 ... L40), each drilled to Z-57, 7 mm below the table; and to Z{bottom}
HOLES = "G21 G90 G17 G54 F600\nG0 X0 Y0 Z10\nG91 G81 X1 Y0 Z{z} R-5 L40\nG90 G80\nM30\n"


def test_a_cycle_out_of_the_box_skips_its_later_holes(monkeypatch):
    """40 holes of one block, each 7 mm below the table: the later holes are not deeper, their violations are not
    built; the report is the one without the skip."""
    text = HOLES.format(z="-62")
    built = []
    real_line = core.Prover._line_violation
    monkeypatch.setattr(core.Prover, "_line_violation", lambda self, *a: built.append(1) or real_line(self, *a))
    report = _report(text, _mill())
    assert report["verdict"] == "unsafe" and len(report["violations"]) == 1 and len(built) == 1, len(built)
    assert F(report["violations"][0]["depth"]) == 7
    monkeypatch.setattr(core.Prover, "_no_deeper", lambda self, seg, pieces, known: False)
    assert _report(text, _mill()) == report and len(built) == 1 + 80  # each hole: its feed down and retract


@pytest.mark.parametrize("skip", [True, False])
def test_a_deeper_motion_still_deepens_the_report(skip, monkeypatch):
    """A peck cycle (G83) past the table's bottom: each peck deeper than the last; the depth reported is the
    bottom's, with the skip or without."""
    if not skip:
        monkeypatch.setattr(core.Prover, "_no_deeper", lambda self, seg, pieces, known: False)
    report = _report("G21 G90 G17 G54 F600\nG0 X0 Y0 Z10\nG83 X1 Y0 Z-58.5 R5 Q2\nG80\nM30\n", _mill())
    assert report["verdict"] == "unsafe" and [F(v["depth"]) for v in report["violations"]] == [F(17, 2)]
