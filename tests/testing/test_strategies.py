"""The public strategies produce what they promise."""

from fractions import Fraction

from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from nczones.exact import DECIMAL_RE, decimal_places
from nczones.testing import boundary_values, decimals, machines, programs, zone_tables

#: ``find`` without its shrink phase, on a fixed seed: the first example that fits (shrinking a machine or a
#: program to the smallest one took over a minute of the default run, and these tests need any example, not the
#: smallest)
FIRST_FIT = settings(phases=[Phase.generate], database=None, derandomize=True)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(zone_tables(places=2))
def test_zone_tables_are_valid_limit_value_tables(table):
    uptos = (table.start,) + table.uptos
    assert all(a < b for a, b in zip(uptos, uptos[1:]))
    for r in table.regions:
        if r.min is not None and r.max is not None:
            assert r.min <= r.max
        for v in (r.upto, r.min, r.max):
            if v is not None:
                assert decimal_places(v) <= 2


@settings(max_examples=40, deadline=None, derandomize=True)
@given(machines())
def test_generated_machines_start_inside_their_allowed_set(machine):
    assert machine.allowed.contains(machine.point(machine.start))


@settings(max_examples=40, deadline=None, derandomize=True)
@given(decimals(min_value=Fraction(-1, 3), max_value=Fraction(7, 2), places=3))
def test_decimals_respect_bounds_and_places(q):
    assert Fraction(-1, 3) <= q <= Fraction(7, 2)
    assert decimal_places(q) <= 3


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.data())
def test_programs_write_only_decimals_and_reach_boundaries(data):
    machine = data.draw(machines())
    text = data.draw(programs(machine, max_blocks=10, boundary_bias=1.0))
    assert text.startswith("%\nG21 G90 G17 G54 G94")
    for word in text.split():
        if word[0] in "XYIJ":
            assert DECIMAL_RE.match(word[1:]), word


def test_boundary_values_lists_every_edge_of_the_table():
    from hypothesis import find

    machine = find(machines(forbid_boxes=False), lambda m: len(m.zones[0].regions) >= 2,
                   settings=FIRST_FIT)
    table = machine.zones[0]
    xs = boundary_values(machine, "X")
    assert set(xs) == {table.start, *table.uptos}


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.data())
def test_every_zone_kind_and_three_axes_give_programs_the_interpreter_models(data):
    from nczones.gcode import interpret_text

    machine = data.draw(machines(axes=("X", "Y", "Z"), allow_kinds=("stepped", "box", "polygon"), size=100,
                                 pulse="0.01"))
    assert machine.allowed.contains(machine.point(machine.start))
    assert sorted(machine.tool_lengths) == [1, 2]
    text = data.draw(programs(machine, max_blocks=8, subprograms=True, inside_bias=0.5))
    run = interpret_text(text, machine, fast=False)
    segs = list(run.segments())
    assert not run.unsupported
    assert segs and segs[0].start == machine.start
    for s in segs:  # tool length follows G43/G49 as written
        assert s.tool_length in (0, *machine.tool_lengths.values())


@settings(max_examples=60, deadline=None, derandomize=True)
@given(st.data())
def test_polygons_are_simple_with_their_centre_inside(data):
    from nczones.machine import polygon_problem
    from nczones.testing import polygon_centre, polygons

    p = data.draw(polygons(min_vertices=3, max_vertices=8, places=2))
    assert polygon_problem(list(p.vertices)) is None
    assert p.interior_contains(dict(zip(p.plane, polygon_centre(p))))


def test_mix_weights_choose_the_block_kinds():
    from hypothesis import find

    machine = find(machines(allow_kinds=("box",)), lambda m: True, settings=FIRST_FIT)
    text = find(programs(machine, min_blocks=6, mix={"line": 0, "rapid": 0, "arc": 1}, incremental=False,
                         offsets=False), lambda t: True, settings=FIRST_FIT)
    body = [ln for ln in text.splitlines()[2:] if ln.startswith("G")]
    assert body and all(ln.split()[0] in ("G2", "G3") for ln in body)
