"""Properties of the generated passes: an independent oracle for G71 type I on random shapes, parameter
ranges against their concrete values, and continuity of every cycle's path."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from pathlib import Path
from types import MappingProxyType

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.machine import load_machine
from nczones.prover import verify
from tests.gcode.turning.helpers import F, lathe

ROOT = Path(__file__).resolve().parents[3]


@st.composite
def monotone_shapes(draw):
    """A type I shape for G71 (lines only): A' below A, X never decreasing and Z never increasing after it,
    in whole and half millimetres (diameters in whole mm)."""
    n = draw(st.integers(1, 5))
    x = draw(st.integers(2, 20))  # radius of A' (diameter 2x)
    z = 0
    points = [(z, x)]
    for _ in range(n):
        dz = draw(st.integers(0, 10))
        dx = draw(st.integers(0, 6))
        if dz == 0 and dx == 0:
            dz = 1
        z -= dz
        x += dx
        points.append((z, x))
    if points[-1][0] == points[0][0]:
        points.append((points[-1][0] - 3, points[-1][1]))
    top = draw(st.integers(points[-1][1] - 2, points[-1][1] + 8))
    return points, max(top, x + 1 if top <= points[0][1] else top)


def _program(points, top, depth, retract):
    lines = [f"G00 X{2 * top}. Z2.", f"G71 U{depth} R{retract}", "G71 P10 Q20 F0.2", f"N10 G00 X{2 * points[0][1]}."]
    lines.append(f"G01 Z{points[0][0]}.")
    body = [f"X{2 * x}. Z{z}." for z, x in points[1:]]
    body[-1] = "N20 " + body[-1]
    return "\n".join(lines + body) + "\n"


def _oracle_cut_end(points, level):
    """Where a roughing level first meets the shape: the first element, walking from A', that rises to the
    level (its Z interpolated), else the shape's end.  The shape's first point is (2, x(A')) then (z0, x0)."""
    path = [(Fraction(2), Fraction(points[0][1]))] + [(Fraction(z), Fraction(x)) for z, x in points]
    for (z1, x1), (z2, x2) in zip(path, path[1:]):
        if x1 < level <= x2:
            z = z1 + (z2 - z1) * (level - x1) / (x2 - x1)
            n = int(abs(z) * 1000 + Fraction(1, 2))  # to the 0.001 increment, halves away from zero
            return Fraction(n if z >= 0 else -n, 1000)
    return path[-1][0]


@settings(max_examples=60, deadline=None)
@given(monotone_shapes(), st.sampled_from(["1.", "2.", "2.5", "3."]), st.sampled_from(["0", "0.5", "1."]))
def test_g71_type_one_matches_an_independent_oracle(shape, depth, retract):
    points, top = shape
    m = lathe()
    program = _program(points, top, depth, retract)
    run = interpret_text(program, m)
    segs = list(run.segments())
    assert not run.unsupported, (program, run.unsupported)
    d, e = Fraction(depth), Fraction(retract)
    lowest = Fraction(points[0][1])
    levels = []
    k = 1
    while top - k * d > lowest:
        levels.append(top - k * d)
        k += 1
    cuts = [(s.end[1], s.end[0]) for s in segs if s.derived.endswith(": cut")]
    assert [x for _z, x in cuts] == levels
    for (z, x) in cuts:
        assert z == _oracle_cut_end(points, x)
    # every move starts where the previous one ended; the escapes go e up and e back
    for a, b in zip(segs, segs[1:]):
        assert a.end == b.start
    escapes = [s for s in segs if s.derived.endswith(": escape")]
    assert all(s.end[0] - s.start[0] == e and s.end[1] - s.start[1] == e for s in escapes)
    assert segs[-1].end == (Fraction(top), Fraction(2))  # back at A


def _with_g54z(machine, dz):
    offsets = {k: list(v) for k, v in machine.offsets.items()}
    i = machine.axis_names.index("Z")
    offsets["G54"][i] += dz
    return replace(machine, offsets=MappingProxyType({k: tuple(v) for k, v in offsets.items()}))


def test_parameter_range_on_the_work_offset_moves_every_pass():
    # g71_clear.nc leaves its passes 2.1 mm before the jaws' face, 1.3 mm once the reach of tool 1's nose
    # (R 0.4 at tip 3: 2R = 0.8, specs/turning.md "Tool nose radius") is taken off: safe for G54.Z in -1..1,
    # unsafe for -3..0 (at -3 the nose's square reaches 1.7 mm into the jaws); every concrete value agrees
    # with the range's verdict (at -1.3 the square touches the face: safe).
    m = load_machine(ROOT / "specs/machines/fanuc_lathe.toml")
    prog = ROOT / "specs/examples/programs/g71_clear.nc"
    assert verify(prog, m, params=["G54.Z=-1..1"]).verdict.label == "safe"
    r = verify(prog, m, params=["G54.Z=-3..0"])
    assert r.verdict.label == "unsafe" and "roughing pass" in r.violations[0].derived
    value = dict(r.violations[0].params)["G54.Z"]
    assert value < Fraction(-13, 10)
    for dz, label in ((F(-3), "unsafe"), (F(-13, 10), "safe"), (F(-14, 10), "unsafe"), (F(-1), "safe"), (F(1), "safe"), (value, "unsafe")):
        assert verify(prog, _with_g54z(m, dz)).verdict.label == label, dz


def test_cycle_from_a_point_that_moves_with_a_range_is_unknown():
    # G53 puts the tool at a machine position (X240. a diameter: radius 120): its workpiece coordinates move
    # with G54.Z, and so would the number and places of the passes
    m = load_machine(ROOT / "specs/machines/fanuc_lathe.toml")
    text = (ROOT / "specs/examples/programs/g71_clear.nc").read_text().replace("G00 X80. Z2.", "G53 G00 X240. Z252.")
    from nczones.prover import verify_text

    r = verify_text(text, m, params=["G54.Z=-1..1"])
    assert r.verdict.label == "unknown"
    assert any("depends on" in x.message and "G54.Z" in x.message for x in r.reasons), [x.message for x in r.reasons]
    # at the nominal value the same program is proved
    assert verify_text(text, m).verdict.label == "safe"
