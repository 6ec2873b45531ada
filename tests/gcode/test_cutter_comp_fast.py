"""Cutter compensation's faster arithmetic (comp39) against the formulas it replaced, kept here as references.

Every fast path must give the same bits: the same doubles LinuxCNC holds, the same exact Fractions.  The
references are the former code, unchanged; the whole-program test runs the interpreter once with the module as
it is and once with the references patched in, over Hypothesis G41/G42 programs (lines, I/J and R arcs,
expressions, G20 and G21, work offsets), and compares every segment.
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.exact import to_float
from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc import cutter_comp as cc
from nczones.machine import parse_machine
from tests.machines import machine_text
from tests.sizes import examples

_INCH = F(254, 10)


# ---------------------------------------------------------------------------------------------- references
def ref_fprog(self, i, machine_value):
    """The former ``CutterComp._fprog``."""
    return to_float((machine_value - self.it.off[i]) / self._unit())


def ref_fmachine(self, i, value):
    """The former ``CutterComp._fmachine``."""
    return Fraction_(value) * self._unit() + self.it.off[i]


Fraction_ = F


def ref_dequeue(self) -> None:
    """The former ``CutterComp._dequeue`` (before comp39), verbatim."""
    from nczones.gcode.segments import make_segment, with_tool_deps
    from nczones.motion import SegmentKind

    it = self.it
    self.endpoint_valid = False
    ia, ib, _ = self._axes()
    sa, sb = self._lathe_origin() if self.orientation else (F(0), F(0))
    for q in self.queue:
        start = self.machine_now
        assert start is not None  # set when compensation started (_start)
        if q.dwell is not None:
            end = tuple(start)
        else:
            e = list(q.end)
            e[ia] = self._fmachine(ia, q.a) + sa
            e[ib] = self._fmachine(ib, q.b) + sb
            end = tuple(e)
        ds: tuple = ()
        de: tuple = ()
        dt: tuple = ()
        if it.track:
            ds = it.deps_tuple(self.deps_now if self.deps_now is not None else it.dep_pos)
            de = it.deps_tuple(q.deps if q.deps is not None else (self.deps_now or it.dep_pos))
            dt = it.tool_dep_names()
        arc = q.kind is SegmentKind.ARC
        centre = q.centre if arc else None
        if centre is not None and (sa or sb):
            centre = (centre[0] + sa, centre[1] + sb)
        if not it.unsupported:
            seg = make_segment(q.kind, tuple(start), end, it.axes, q.block, q.span, it.tlo, q.feed,
                               it.plane if arc else None, arc and q.turn < 0, centre, None,
                               abs(q.turn) - 1 if arc else 0, q.dwell, q.derived, it.tool_register, ds, de, (),
                               it.program_frame())
            if dt:
                seg = with_tool_deps(seg, dt)
            it.emitted.append(seg)
            it.segment_count += 1
            it.kind_counts[q.kind] += 1
        self.machine_now = end
        if q.deps is not None:
            self.deps_now = q.deps
    self.queue = []


REFERENCES = {"_fprog": ref_fprog, "_fmachine": ref_fmachine, "_dequeue": ref_dequeue}


@contextmanager
def references():
    """CutterComp with the former methods (class attributes swapped back afterwards)."""
    saved = {name: getattr(cc.CutterComp, name) for name in REFERENCES}
    try:
        for name, fn in REFERENCES.items():
            setattr(cc.CutterComp, name, fn)
        yield
    finally:
        for name, fn in saved.items():
            setattr(cc.CutterComp, name, fn)


# ---------------------------------------------------------------------------------------------- the helpers
_DOUBLES = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e9, max_value=1e9) | st.floats(
    allow_nan=False, allow_infinity=False, min_value=-1e-3, max_value=1e-3)
_EXACT = st.fractions(max_denominator=10**6, min_value=-10**5, max_value=10**5) | st.builds(
    lambda x, o: F(x) + o, _DOUBLES, st.fractions(max_denominator=1000, min_value=-1000, max_value=1000))
_UNITS = st.sampled_from([(1, 1), (127, 5)])


def _same_double(a: float, b: float) -> bool:
    return a.hex() == b.hex()


@settings(max_examples=300, deadline=None, derandomize=True)
@given(_DOUBLES, _EXACT, _UNITS)
def test_machine_exact_is_the_fraction_formula(value, off, unit):
    got = cc.machine_exact(value, off, unit)
    want = F(value) * F(*unit) + off
    assert got == want and (got.numerator, got.denominator) == (want.numerator, want.denominator)


@settings(max_examples=300, deadline=None, derandomize=True)
@given(_EXACT, _EXACT, _UNITS)
def test_program_double_is_the_fraction_formula(value, off, unit):
    assert _same_double(cc.program_double(value, off, unit), to_float((value - off) / F(*unit)))


def test_program_double_rounds_as_the_formula_at_a_tie_and_near_one():
    # a value exactly between two doubles, and ones a 2**-80 either side: each rounds as the Fraction's division
    half_ulp = F(1, 2**53)
    for v in (1 + half_ulp, 1 + half_ulp + F(1, 2**80), 1 + half_ulp - F(1, 2**80), 1 + 3 * half_ulp):
        assert _same_double(cc.program_double(v + 100, F(100), (1, 1)), to_float(v))
    assert cc.program_double(F(1) + half_ulp, F(0), (1, 1)) == 1.0  # ties to even
    assert cc.program_double(F(1) + 3 * half_ulp, F(0), (1, 1)) == 1.0 + 2.0**-51


# ---------------------------------------------------------------------------------------------- whole programs
_MACHINES = {off: parse_machine(machine_text("mill_cutter_comp_g54", set={"offsets.G54": {"X": off[0], "Y": off[1]}}))
             for off in (("100", "50"), ("12.345", "-0.1"), ("0", "0"))}


def _num(x: float) -> str:
    return f"{x:.4f}"


@st.composite
def comp_programs(draw) -> tuple[str, tuple[str, str]]:
    """A G41/G42 contour: lines (some through an expression), I/J and R arcs, corners of every kind."""
    inch = draw(st.booleans())
    scale = 1 / 25.4 if inch else 1.0
    code = draw(st.sampled_from(["G41", "G42", "G41.1 D1.5", "G42.1 D0.8"]))
    out = ["G20" if inch else "G21", "G90 G17 G54 F500", "T1 M6", "#1 = 0.125", "G0 X0 Y0"]
    x, y = 0.0, 0.0
    first = True
    for _ in range(draw(st.integers(2, 9))):
        kind = "line" if first else draw(st.sampled_from(["line", "line", "expr", "ij", "r"]))
        ang = draw(st.floats(0, 2 * math.pi))
        length = draw(st.floats(4, 30)) * scale
        nx, ny = round(x + length * math.cos(ang), 4), round(y + length * math.sin(ang), 4)
        g = draw(st.sampled_from(["G2", "G3"]))
        if kind == "line":
            out.append(f"{code + ' ' if first else ''}G1 X{_num(nx)} Y{_num(ny)}")
        elif kind == "expr":
            out.append(f"G1 X{_num(nx)} Y[#1 + {_num(ny - 0.125)}]")
        elif kind == "r":
            chord = math.hypot(nx - x, ny - y)
            r = math.ceil(chord / 2 * draw(st.floats(1.05, 3)) * 10**4) / 10**4
            out.append(f"{g} X{_num(nx)} Y{_num(ny)} R{r:.4f}")
        else:  # I/J: a centre on the chord's bisector, the end on its circle (4 decimals: within tolerance)
            mx, my = (x + nx) / 2, (y + ny) / 2
            t = draw(st.floats(-2, 2))
            cx, cy = mx - t * (ny - y), my + t * (nx - x)
            r = math.hypot(x - cx, y - cy)
            a_end = math.atan2(ny - cy, nx - cx)
            nx, ny = round(cx + r * math.cos(a_end), 4), round(cy + r * math.sin(a_end), 4)
            out.append(f"{g} X{_num(nx)} Y{_num(ny)} I{_num(cx - x)} J{_num(cy - y)}")
        first = False
        x, y = nx, ny
    out += ["G40 G1 X0 Y0", "M30"]
    return "\n".join(out) + "\n", draw(st.sampled_from(sorted(_MACHINES)))


def _outcome(text: str, machine, track: bool) -> object:
    """Every segment's exact fields, or the error's code."""
    try:
        run = interpret_text(text, machine, track_dependencies=track)
        return [(s.kind, s.start, s.end, s.centre, s.clockwise, s.turns, s.block, s.derived, s.feed_mm_min,
                 s.deps_start, s.deps_end) for s in run.segments()] + [run.unknowns if hasattr(run, "unknowns") else ()]
    except GcodeError as exc:
        return exc.diagnostics[0].code


@settings(max_examples=examples(60, 1000), deadline=None, derandomize=True)
@given(comp_programs(), st.booleans())
def test_compensated_program_is_the_references_segment_for_segment(case, track):
    text, off = case
    machine = _MACHINES[off]
    fast = _outcome(text, machine, track)
    with references():
        slow = _outcome(text, machine, track)
    assert fast == slow
