"""The library functions' one-ulp spread (libm40; specs/fanuc.md, "Results of the library functions").

A control's SIN, COS, TAN, ATAN, ASIN, ACOS, LN, EXP and POW give CPython's double or one of its two neighbours
(exactly the true value where that is a double nczones knows: SIN/TAN/ATAN/ASIN of 0, COS/EXP of 0, LN/ACOS of 1,
an exact power).  A decision or an address takes a result only where every such double gives it (GC396 for a
decision, GC397 for an address; GC398/GC399 where the double's own readings part already).

* constructed cases at each edge: a comparison at the double's own value, FIX of ATAN/ASIN/ACOS results that are
  whole degrees, a WHILE bound, a position at half an increment, and the exact points that stay decided;
* every operation carries the spread (``+ - * /`` with a number or a variable on either side, NEG, ABS, SQRT), in
  an assignment (the exact path) and in a condition (the doubles-only path);
* Hypothesis: a program whose SIN/COS/TAN/ATAN/POW results feed a comparison, FIX/ROUND/FUP, a WHILE bound and a
  position, run by nczones and by the independent reference reader (tests/oracles/fanuc_ref.py) with its library
  replaced by one giving CPython's double shifted by -1, 0 or +1 ulp in every combination: where nczones
  interprets the program to its end, every combination moves the same.
"""

from __future__ import annotations

import itertools
import math
import re
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode.fanuc.expr import FanucVariables, SpreadDouble, compile_tree
from nczones.gcode.fanuc.parser import FN, NUM
from tests.oracles import fanuc_ref
from tests.oracles.fanuc_ref import RefError, RefUnknown

from .ref_differential import nczones_motion, normalise, ref_machine
from .test_macro_readings import _run

# -- constructed edges -------------------------------------------------------------------------------------------

#: name -> (body, the code and line it is unknown at; None: safe)
EDGES = {
    # the double's own 15 digits part already (readings39): GC398 stands
    "SIN[30] EQ 0.5": ("IF [SIN[30] EQ 0.5] GOTO 5\nG01 X1.\nN5 G01 X2.\n", ("GC398", 4)),
    # at the double's own value: its readings agree, its lower neighbour is below
    "SIN[30] GE its double": ("IF [SIN[30] GE 0.49999999999999994] GOTO 5\nG01 X1.\nN5 G01 X2.\n", ("GC396", 4)),
    "SIN[30] GT 0.4": ("IF [SIN[30] GT 0.4] GOTO 5\nG01 X1.\nN5 G01 X2.\n", None),
    "TAN[45] GE its double": ("IF [TAN[45] GE 0.9999999999999999] GOTO 5\nG01 X1.\nN5 G01 X2.\n", ("GC396", 4)),
    "FIX ATAN": ("#1 = FIX[ATAN[1]/[1]]\nG01 X#1\n", ("GC396", 4)),
    "FIX ATAN off": ("#1 = FIX[ATAN[1]/[1] + 0.5]\nG01 X#1\n", None),
    "FIX ASIN": ("#1 = FIX[ASIN[1]]\nG01 X#1\n", ("GC396", 4)),
    "ROUND ACOS": ("#1 = ROUND[ACOS[0]]\nG01 X[#1 / 100]\n", None),
    "FUP ACOS": ("#1 = FUP[ACOS[0]]\nG01 X#1\n", ("GC396", 4)),
    "POW not exact": ("IF [POW[2, 0.5] GE 1.4142135623730951] GOTO 5\nG01 X1.\nN5 G01 X2.\n", ("GC396", 4)),
    "LN EXP": ("IF [LN[EXP[1]] GE 1] GOTO 5\nG01 X1.\nN5 G01 X2.\n", ("GC396", 4)),
    "WHILE bound": ("#2 = 0\nWHILE [#2 LT SIN[90] * 3] DO1\n#2 = #2 + 1\nEND1\nG01 X#2\n", ("GC396", 5)),
    "WHILE bound off": ("#2 = 0\nWHILE [#2 LT SIN[90] * 3.5] DO1\n#2 = #2 + 1\nEND1\nG01 X#2\n", None),
    # 1.0 * 0.0005: the double 0.0005 and its 15 digits round to 0.001; the lower neighbour scaled in doubles
    # is 0.49999999999999994 increments
    "position at a half": ("G01 X[SIN[90] * 0.0005]\n", ("GC397", 4)),
    "position off a half": ("G01 X[SIN[90] * 0.0006] Y[COS[60] * 0.001]\n", None),
    "a divisor's spread reaches 0": ("#1 = 1 / [SIN[30] - 0.49999999999999994]\nG01 X1.\n", ("GC396", 4)),
    "F taken as it is": ("G01 X1. F[SIN[30] * 100]\n", ("GC397", 4)),
    # the exact points: a library whose error is below one ulp gives the true value where it is a double (a
    # wrong result would move to X9999., outside the machine: unsafe)
    "exact points": ("".join(f"IF [{c}] GOTO 5\n" for c in (
        "SIN[0] NE 0", "COS[0] NE 1", "TAN[0] NE 0", "LN[1] NE 0", "EXP[0] NE 1", "POW[2, 3] NE 8", "POW[1.5, 2] NE 2.25",
        "POW[7, 0] NE 1", "ATAN[0]/[1] NE 0", "ASIN[0] NE 0", "ACOS[1] NE 0")) + "G01 X2.\nGOTO 6\nN5 G01 X9999.\n"
        "N6 G01 X1.\n", None),
    "POW of a spread": ("#1 = POW[SIN[90] * 2, 2]\nIF [#1 GE 4] GOTO 5\nG01 X1.\nN5 G01 X2.\n", ("GC396", 5)),
    "SIN of a spread": ("#1 = SIN[ATAN[1]/[1] * 2]\nIF [#1 GE 1] GOTO 5\nG01 X1.\nN5 G01 X2.\n", ("GC396", 5)),
}


@pytest.mark.parametrize("name", sorted(EDGES))
def test_an_edge_is_unknown_where_a_neighbour_parts_it(name):
    body, expected = EDGES[name]
    r, reasons = _run(body)
    if expected is None:
        assert r.verdict.label == "safe" and not reasons, reasons
    else:
        assert r.verdict.label == "unknown" and reasons == [expected], reasons
        if expected[0] in ("GC396", "GC397"):
            assert "which double a control's library gives is not known" in r.reasons[0].message


def test_the_reason_names_the_neighbours_and_what_they_give():
    r, _reasons = _run("#1 = FIX[ATAN[1]/[1]]\nG01 X#1\n")
    message = r.reasons[0].message
    assert "the least double 44.99999999999999" in message and "gives 44" in message and "gives 45" in message


# -- every operation carries the spread ----------------------------------------------------------------------------

#: An expression of ``@`` (each ``@`` a call SIN[90]: CPython's 1.0, its neighbours 0.9999999999999999 and
#: 1.0000000000000002) and the same in Python: ``IF [<expr> GE <its double>]`` is unknown (GC396) exactly where
#: some choice of neighbours gives a double below it (computed here, call by call).
OPERATIONS = {
    "@ * 3": lambda s: s * 3, "3 * @": lambda s: 3 * s, "@ + 2": lambda s: s + 2, "@ + 0.001": lambda s: s + 0.001,
    "0.001 + @": lambda s: 0.001 + s, "@ - 0.25": lambda s: s - 0.25, "0.25 - @": lambda s: 0.25 - s,
    "@ / 4": lambda s: s / 4, "4 / @": lambda s: 4 / s, "-@": lambda s: -s, "ABS[-@]": lambda s: abs(-s),
    "SQRT[@ * 4]": lambda s: math.sqrt(s * 4), "[@ * 3] * [@ * 3]": lambda s, t: (s * 3) * (t * 3),
    "[@ + 1] - [@ * 3]": lambda s, t: (s + 1) - (t * 3), "ADP[@]": lambda s: s * 1000,
    "[@ * 1000000] / 1000000": lambda s: (s * 1000000) / 1000000,
}
_NEIGHBOURS = (0.9999999999999999, 1.0, 1.0000000000000002)


def _parts_below(name: str) -> bool:
    fn = OPERATIONS[name]
    value = fn(*[1.0] * name.count("@"))
    return any(fn(*c) < value for c in itertools.product(_NEIGHBOURS, repeat=name.count("@")))


def test_the_operations_table_keeps_spreads_and_absorbs_some():
    parted = [name for name in OPERATIONS if _parts_below(name)]
    assert "@ + 2" not in parted and len(parted) >= len(OPERATIONS) - 3, parted


@pytest.mark.parametrize("name", sorted(OPERATIONS))
@pytest.mark.parametrize("path", ["condition", "assigned", "local"])
def test_every_operation_carries_the_spread(name, path):
    value = OPERATIONS[name](*[1.0] * name.count("@"))
    if path == "condition":  # the doubles-only closures (an IF's condition)
        body = f"IF [{name.replace('@', 'SIN[90]')} GE {value!r}] GOTO 5\nG01 X1.\nN5 G01 X2.\n"
        line = 4
    elif path == "assigned":  # the exact closures (an assignment)
        body = f"#1 = {name.replace('@', 'SIN[90]')}\nIF [#1 GE {value!r}] GOTO 5\nG01 X1.\nN5 G01 X2.\n"
        line = 5
    else:  # local variables holding the spreads (#9 op a number: the local closures)
        body = (f"#9 = SIN[90]\n#8 = SIN[90]\n#1 = {name.replace('@', '#9', 1).replace('@', '#8')}\n"
                f"IF [#1 GE {value!r}] GOTO 5\nG01 X1.\nN5 G01 X2.\n")
        line = 7
    r, reasons = _run(body)
    if _parts_below(name):
        assert r.verdict.label == "unknown" and reasons == [("GC396", line)], (body, reasons)
    else:
        assert r.verdict.label == "safe" and not reasons, (body, reasons)


def test_a_value_without_a_library_ancestor_carries_nothing():
    v = FanucVariables()
    got = compile_tree((FN, "sqrt", (NUM, 2.0, Fraction(2))), v)()
    assert got[0].__class__ is float  # SQRT is correctly rounded: the control's double is nczones's
    got = compile_tree((FN, "sin", (NUM, 30.0, Fraction(30))), v)()
    assert got[0].__class__ is SpreadDouble and (got[0].lo, got[0].hi) == (0.4999999999999999, 0.5)


def test_too_wide_a_spread_for_a_function_is_unknown():
    # SIN[30] - its double: a spread across 0 holding every double from -5.55e-17 to 5.55e-17
    r, reasons = _run("#1 = SIN[[SIN[30] - 0.49999999999999994] * 1000]\nG01 X1.\n")
    assert r.verdict.label == "unknown" and reasons == [("GC396", 4)], reasons
    assert "more than 64" in r.reasons[0].message


# -- the reference reader with its library's neighbours --------------------------------------------------------

def _shift(x: float, k: int) -> float:
    for _ in range(abs(k)):
        x = math.nextafter(x, math.inf if k > 0 else -math.inf)
    return x


def _library(shifts: tuple[int, ...]):
    """A control's library for the reference reader: CPython's double (the degrees in doubles, ``d * pi / 180``,
    as nczones computes them) shifted by the next of ``shifts`` ulps, call by call; the true value where it is a
    double (the exact points, an exact power)."""
    calls = itertools.count()

    def libm(name: str, *args: float) -> float:
        k = shifts[next(calls) % len(shifts)]
        if name in ("SIN", "COS", "TAN"):
            x = args[0]
            r = x * math.pi / 180.0
            c = {"SIN": math.sin, "COS": math.cos, "TAN": math.tan}[name](r)
            return c if x == 0.0 else _shift(c, k)
        if name == "ATAN":
            y, x = args
            r = math.atan2(y, x)
            if not (y == 0.0 and math.copysign(1.0, x) > 0.0):
                r = _shift(r, k)
            return r * 180.0 / math.pi
        a, b = args
        c = math.pow(a, b)
        exact = b == 0.0 or a == 1.0 or (b == math.floor(b) and abs(b) <= 64 and a != 0.0
                                          and Fraction(c) == Fraction(a) ** int(b))
        return c if exact else _shift(c, k)
    return libm


_FUNCTION = st.one_of(
    st.builds(lambda f, a: f"{f}[{a}]", st.sampled_from(["SIN", "COS"]),
              st.sampled_from([0, 30, 45, 60, 90, 120, 150, 180, 270, 300, 36, 72, 7.5, 0.1 * 3 * 100])
              | st.integers(-400, 400)),
    st.builds(lambda a: f"TAN[{a}]", st.sampled_from([30, 45, 60, 135, 10, 80])),
    st.builds(lambda y, x: f"ATAN[{y}]/[{x}]", st.sampled_from([1, -1, 0, 3, 0.5]), st.sampled_from([1, -1, 2, 3])),
    st.builds(lambda a, b: f"POW[{a}, {b}]", st.sampled_from([2, 3, 10, 1.5]), st.sampled_from([0.5, 2, 3, -1, 1.5])))
_MULTIPLIER = st.sampled_from(["1", "2", "3", "10", "0.5", "4", "1000", "0.001"])
_POSITION_SCALE = st.sampled_from(["1", "0.001", "0.0005", "0.5", "0.01", "0.0015"])


def _near(value: float) -> st.SearchStrategy:
    """A constant where a comparison with ``value`` is at its edge: the double itself, its 15 digits, its
    neighbours, a rounded decimal."""
    return st.sampled_from([repr(value), format(value, ".15g"), repr(_shift(value, 1)), repr(_shift(value, -1)),
                            format(value, ".3f"), str(round(value))])


@st.composite
def _programs(draw) -> str:
    f = draw(_FUNCTION)
    g = draw(st.sampled_from(["", " * SIN[90]", " + COS[60]", " * ATAN[1]/[1] / 45"]))
    m, c = draw(_MULTIPLIER), draw(st.sampled_from(["0", "0.5", "-1", "1"]))
    # CPython's double of #2 (nczones's own formula), for constants at its edges
    value = _value(f + g, m, c)
    if value is None or abs(value) > 1e6:
        return ""
    k = draw(_near(value))
    rel = draw(st.sampled_from(["EQ", "NE", "GE", "GT", "LE", "LT"]))
    integer = draw(st.sampled_from(["FIX", "FUP", "ROUND"]))
    p = draw(st.sampled_from(["1", "10", "2", "0.5"]))
    s = draw(_POSITION_SCALE)
    return (f"#1 = {f}{g}\n#2 = #1 * {m} + {c}\n"
            f"IF [#2 {rel} {k}] GOTO 5\n#3 = 1.\nGOTO 6\nN5 #3 = 2.\n"
            f"N6 #4 = {integer}[#2 * {p}]\n#5 = 0\n"
            f"WHILE [#5 LT #2] DO1\n#5 = #5 + 1\nIF [#5 GT 20] GOTO 9\nEND1\n"
            f"N9 G01 X[#2 * {s}] Y[#3 + #4 * 0.001] Z[#5 * 0.1]\nM30\n")


def _value(expr: str, m: str, c: str) -> float | None:
    """``#2`` in CPython's doubles, through the reference reader's expression evaluator and CPython's library."""
    reader = fanuc_ref.Reader(ref_machine("calculator"))
    reader.libm = _library((0,))
    try:
        e = fanuc_ref._Expr(f"[{expr}]*{m}+{c}".replace(" ", "")).additive()
        return reader.num(reader.ev(e))
    except (RefError, RefUnknown, ValueError, OverflowError, ZeroDivisionError):
        return None


_HEAD = "O1000\nG21 G90 G54 G17 G40 G80 G94 F100.\nG00 X0 Y0 Z0\n"


def _reference(text: str, shifts: tuple[int, ...]):
    """The reference reader's motion (:func:`reference_motion`) with the library :func:`_library` ``shifts``."""
    reader = fanuc_ref.Reader(ref_machine("calculator"))
    reader.libm = _library(shifts)  # (an instance's attribute: called as it is)
    try:
        return normalise(reader.run(text))
    except (RefError, RefUnknown, ValueError, OverflowError) as e:
        return ("reference", type(e).__name__)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(_programs())
def test_where_nczones_decides_every_neighbour_moves_the_same(program):
    if not program:
        return
    text = _HEAD + program
    try:
        run, segs = nczones_motion(text, "calculator", False)
    except GcodeError:  # an alarm (GC311/GC312) nczones gives for every double
        return
    calls = len(re.findall(r"\b(?:SIN|COS|TAN|ATAN|POW)\[", text))
    motions = {str(_reference(text, shifts)) for shifts in itertools.product((-1, 0, 1), repeat=calls)}
    if run.status != "complete":
        codes = [u.code for u in run.unsupported]
        assert codes and set(codes) <= {"GC396", "GC397", "GC398", "GC399", "GC312", "GC311"}, codes
        return
    assert motions == {str(normalise(segs))}, (text, motions)


def test_the_differential_sees_neighbours_move_differently():
    """The reference with its library's neighbours is not blind: where nczones is unknown (GC396: FIX of ATAN[1]
    whose lower neighbour is 44.99999999999999) the neighbours move to different X."""
    text = _HEAD + "#1 = FIX[ATAN[1]/[1]]\nG01 X[#1 / 100]\nM30\n"
    assert len({str(_reference(text, (k,))) for k in (-1, 0, 1)}) == 2
    run, _segs = nczones_motion(text, "calculator", False)
    assert run.status != "complete" and [u.code for u in run.unsupported] == ["GC396"]
