"""Custom Macro B variables and expressions, the way a Fanuc control computes them.

Values are IEEE doubles (the 15i/30i manuals: "double-precision real data, as
laid down in the applicable IEEE standard"), each with the optional exact
*shadow* the LinuxCNC layer carries (:mod:`nczones.gcode.expr`): ``+ - * /``
of exact operands keep an exact rational as long as it rounds to the
controller's double.  Where a value becomes an address of an NC statement it
is rounded to the address's least input increment (``X#1`` with ``#1 =
12.3456`` is ``X12.346`` on a 0.001 mm control), so the positions nczones
proves are exact decimals.

Vacant
------
A variable never assigned (locals of a new call level, commons without an
initial value, ``#0`` always) is *vacant*.  Fanuc's rules: a vacant variable
in an address drops the word (``G90 X#1`` with ``#1`` vacant is ``G90``);
copied it stays vacant (``#2 = #1``); in arithmetic it is 0 (``#2 = #1 * 5``
is 0); in ``EQ``/``NE`` it differs from 0 (``#1 EQ #0`` is true only for a
vacant ``#1``); in ``GT GE LT LE`` it is 0.  :data:`VACANT` is one object,
recognised by identity.

Functions and operators (0i/30i operator's manuals, "Arithmetic and logic
operation"): ``FIX`` drops the fraction (towards 0: ``FIX[-1.2]`` is -1),
``FUP`` rounds away from 0, ``ROUND`` to the nearest integer (halves away from
0) and, inside an address, to the address's increment; ``MOD`` rounds both
operands to integers, the remainder has the dividend's sign; ``AND OR XOR``
on the integer parts bit by bit; ``ATAN[a]/[b]`` (and ``ATAN[a,b]``) in
0..360 degrees, ``ASIN`` in 270..90 (parameter 6004#0 NAT = 0) or in
-180..180 / -90..90 (NAT = 1); ``ACOS`` in 0..180; ``BIN``/``BCD`` convert
between BCD and binary; ``ADP`` multiplies by the inverse of the least input
increment (a G65 argument written without a decimal point comes in as a
count of increments); ``POW[a,b]`` is a to the b (a negative base needs an
integer exponent, 0 a positive one).  Relational operators compare the
doubles.

Readings
--------
How a control reads its double no manual says; the readings that fit what
the manuals do say are the double as it is, its 15-significant-digit decimal
and the exact decimal it stands for (the shadow), and for an address the
double scaled to increments in doubles (:func:`round_to`, GC399).  FIX, FUP,
ROUND outside an address, BIN, BCD, MOD, AND/OR/XOR, a variable number
(computed or a literal, :func:`literal_number`), the relational operators,
POW's integer exponent (:func:`_pow_domain`) and ASIN/ACOS's -1..1
(:func:`_arc_domain`) take the result every reading gives (:func:`integer_of`,
:func:`_related`, :func:`_agreed_binary`), decided in
doubles where the value is farther from where the readings part than they
reach; where the readings give different results :class:`ReadingsSplit`
(GC398) makes the line ``unknown``: ``FIX[0.3 / 0.1]`` is 2 for the double
2.9999999999999996 and 3 for its 15 digits.

Library functions
-----------------
SIN COS TAN ATAN ASIN ACOS LN EXP POW give CPython's double or one of its two neighbours on a control
(:class:`SpreadDouble`: the value carries the least and greatest double, through later arithmetic); every
decision and address above takes a result only where every double of the spread gives it (GC396, GC397).

>>> v = FanucVariables()
>>> v.read(1) is VACANT, v.read(0) is VACANT
(True, True)
>>> evaluate_tree((BIN, "+", (VAR, (NUM, 1.0, Fraction(1))), (NUM, 0.5, Fraction(1, 2))), v)
(0.5, Fraction(1, 2))
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from fractions import Fraction
from operator import attrgetter

from ..expr import EvalError, binary_op, check_double, q_add, q_div, q_sub
from ..lexer import fraction_raw, to_fraction
from .parser import BIN, FN, FN2, NEG, NUM, VAR

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, TypeAlias

__all__ = ["VACANT", "FanucVariables", "Context", "compile_tree", "evaluate_tree", "round_to", "denominator_of", "EvalError",
           "SystemVariableUnknown", "RoundingNotCertain", "ReadingsSplit", "readings", "SHADOW_ON_GRID_BOUND", "variable_index",
           "variable_number", "literal_number", "integer_of", "SpreadDouble", "LibmSplit", "value_as_is",
           "neighbours"]

#: The vacant value: 0 in arithmetic, distinct from 0 in EQ/NE, never written into an address.
VACANT = (0.0, Fraction(0))
#: A value: the double and its exact shadow (or None).
Value: TypeAlias = tuple
_TRUE = (1.0, Fraction(1))
_FALSE = (0.0, Fraction(0))
LOCALS = 33
COMMON_FIRST, COMMON_LAST = 100, 999
SYSTEM_FIRST = 1000


class FanucVariables:
    """The variables of one program run: locals per call level, commons, system variables.

    ``#1``..``#33`` are local to a macro call level (G65, G66, a custom G/M
    code call; M98 subprograms share their caller's level); ``#100``..``#999``
    are common (initial values from the machine file's ``[variables]``, the
    others vacant); ``#1000`` and up are system variables, read and written
    through ``system_read(n)`` and ``system_write(n, value)`` that the
    interpreter provides (:meth:`nczones.gcode.fanuc.interpreter.FanucInterpreter.bind_variables`).
    ``#34``..``#99`` do not exist (alarm).

    >>> v = FanucVariables({500: Fraction(5, 2)})
    >>> v.write(1, (3.0, Fraction(3))); v.read(500), v.read(1)
    ((2.5, Fraction(5, 2)), (3.0, Fraction(3, 1)))
    >>> saved = v.push_level({2: (7.0, Fraction(7))}); v.read(1) is VACANT, v.read(2)
    (True, (7.0, Fraction(7, 1)))
    >>> v.pop_level(saved); v.read(1)
    (3.0, Fraction(3, 1))
    """

    __slots__ = ("local", "common", "system_read", "system_write", "depth", "on_write")

    def __init__(self, initial: dict[int, Fraction] | None = None):
        self.local: list[Value] = [VACANT] * (LOCALS + 1)
        self.common: list[Value] = [VACANT] * (COMMON_LAST + 1)
        for k, q in (initial or {}).items():
            self.common[k] = (float(q), q)
        self.system_read: Callable[[int], tuple] = _no_system
        self.system_write: Callable[[int, tuple], None] = _no_system_write
        self.depth = 0  # macro call level (0: the main program)
        self.on_write: Callable[[int, tuple], None] | None = None

    def read(self, n: int) -> tuple:
        if n <= LOCALS:
            if n < 0:
                raise EvalError("GC205", f"variable number #{n} does not exist")
            return VACANT if n == 0 else self.local[n]
        if n <= COMMON_LAST:
            if n < COMMON_FIRST:
                raise EvalError("GC205", f"variable #{n} does not exist (local variables are #1-#33, common "
                                "variables #100-#999)")
            return self.common[n]
        return self.system_read(n)

    def write(self, n: int, value: tuple) -> None:
        if 0 < n <= LOCALS:
            self.local[n] = value
        elif COMMON_FIRST <= n <= COMMON_LAST:
            self.common[n] = value
        elif n >= SYSTEM_FIRST:
            self.system_write(n, value)
        elif n == 0:
            raise EvalError("GC205", "#0 is always vacant; it cannot be assigned")
        else:
            raise EvalError("GC205", f"variable #{n} does not exist (local variables are #1-#33, common "
                            "variables #100-#999)")
        if self.on_write is not None:
            self.on_write(n, value)

    def push_level(self, args: dict[int, tuple]) -> list:
        """Enter a macro call: a new local level with the arguments, the others vacant."""
        saved = self.local
        self.local = [VACANT] * (LOCALS + 1)
        for k, v in args.items():
            self.local[k] = v
        self.depth += 1
        return saved

    def enter_level(self, local: list) -> list:
        """:meth:`push_level` with the new level given whole (``LOCALS + 1`` values, vacant where no argument)."""
        saved = self.local
        self.local = local
        self.depth += 1
        return saved

    def pop_level(self, saved: list) -> None:
        self.local = saved
        self.depth -= 1


class SystemVariableUnknown(Exception):
    """A system variable nczones does not model was read or written: the result is ``unknown``.

    ``code`` names the variable (``"#5405"``), ``reason`` says why.
    """

    def __init__(self, code: str, reason: str):
        super().__init__(reason)
        self.code, self.reason = code, reason


def _no_system(n: int) -> tuple:
    raise SystemVariableUnknown(f"#{n}", f"system variable #{n} is not one nczones models (specs/fanuc.md)")


def _no_system_write(n: int, value: tuple) -> None:
    raise SystemVariableUnknown(f"#{n}", f"writing system variable #{n} is not modelled (specs/fanuc.md)")


def variable_index(value: tuple) -> int:
    """The variable number a ``#[...]`` value names (rounded to an integer, as Fanuc does)."""
    d = value[0]
    if d - d:
        raise EvalError("GC204", f"variable number {d!r} is not a number")
    n = int(math.floor(abs(d) + 0.5))
    return -n if d < 0 else n


#: ``(numerator, denominator)`` of a Fraction, read through its slots where Fractions have them (CPython)
_ratio = attrgetter("_numerator", "_denominator") if to_fraction is fraction_raw else attrgetter(
    "numerator", "denominator")
#: The denominator of a Fraction, the same way.
denominator_of = attrgetter("_denominator") if to_fraction is fraction_raw else attrgetter("denominator")


def double_of(q: Fraction) -> float:
    """The double nearest ``q``, infinite beyond the double range (``float(q)`` raises there).

    >>> double_of(Fraction(1, 10)), double_of(Fraction(-10**400))
    (0.1, -inf)
    """
    n: int
    d: int
    n, d = _ratio(q)
    try:
        return n / d
    except OverflowError:
        return math.inf if q > 0 else -math.inf


_floor = math.floor
_NEAR_HALF_LOW, _NEAR_HALF_HIGH = 0.5 - 2.0**-20, 0.5 + 2.0**-20
#: round_to's first screen for a value with a spread (below 2**20 increments): a spread narrower than
#: ``_SPREAD_WIDTH`` increments whose double is at least 2**-19 from a half passes :func:`_spread_round`'s test
#: (``2**-19 >= 2**-20 + 2 * 2**-21``); others go to it.
_SPREAD_HALF_LOW, _SPREAD_HALF_HIGH, _SPREAD_WIDTH = 0.5 - 2.0**-19, 0.5 + 2.0**-19, 2.0**-21
#: Below this many increments (``|value| / step``) round_to's double test decides (``x - floor(x)`` is exact there):
#: see :func:`round_to`.
_FAST_INCREMENTS = 4503599627370496.0  # 2**52
#: Above this many increments the window about a half grows with the value: ``x * 2**-40`` (:func:`round_to`).
_WIDE_INCREMENTS = 1048576.0  # 2**20
_WINDOW = 2.0**-40
#: A value already on the step's grid (its shadow a multiple of it) below this magnitude, in program units, stands
#: on that multiple in every reading (:func:`round_to`); the plain-move lane's inline test uses it too.
SHADOW_ON_GRID_BOUND = 1e8


class RoundingNotCertain(SystemVariableUnknown):
    """A macro value whose defensible readings round to different multiples of an address's step (GC399).

    The verdict is ``unknown`` at the word (it travels as :class:`SystemVariableUnknown` does); ``reason``
    names every reading and the multiple it rounds to.
    """

    def __init__(self, reason: str):
        super().__init__("GC399", reason)


def round_to(value: tuple, step: Fraction) -> Fraction:
    """The value rounded to a multiple of ``step``, halves away from zero; :class:`RoundingNotCertain` when
    the readings a control could make of a macro double round to different multiples.

    ``value`` is ``(double, shadow)``: a macro value (the double the control holds and the exact rational it
    stands for, or None), or ``(None, q)`` for an exact rational (a transformed point, a literal: rounded as
    it is, never in doubt).  How a control turns a macro double into increments no manual says; the
    :func:`readings` are the ways that fit what the manuals do say: the 15-significant-digit decimal ([15i]
    "Custom macro variables are decimal numbers with a precision of 15 digits"), the double scaled to
    increments in double arithmetic, and the exact decimal the value stands for (a control computing in
    decimals; nczones's shadow).  The double's exact binary value is not one of them: the 0i manual's ROUND
    example (``#1 = 1.2345``, ``X-#1`` moves 1.235) contradicts it (the double is 1.23449999999999993...).
    When the readings round to one multiple that is the result; when not (N5 of
    ``tests/gcode/fanuc/test_reference_findings.py``: ``1.5 * 1.017``, 1.525 or 1.526), the position is not known.

    Soundness: every reading differs from the double's exact value ``d`` by less than ``5.1e-15 |d|`` (the
    shadow rounds to ``d``: half an ulp; a 15-digit decimal: half a unit in the 15th digit, ``5e-15 |d|``; a
    product or quotient in doubles: an ulp of the result), ``k 2**-47`` increments for ``k`` increments, so
    where ``d``'s quotient is farther than ``w = max(2**-20, k 2**-40)`` from a half every reading (the shadow
    too) rounds as ``d`` does: the double quotient ``x = |d| * (1 / step)`` (within ``k 2**-52`` of the exact
    one; below ``2**52`` its fraction ``x - floor(x)`` is exact) decides that, else the exact remainder
    (:func:`_near_tie`), and only nearer than ``w`` are the readings computed and compared.  (The window grows
    with the value, so a long program's large coordinates are not all compared reading by reading: a bound of
    ``2**24`` increments did that, a size cliff at 16.8 m in IS-B.)  A shadow on the grid below
    :data:`SHADOW_ON_GRID_BOUND` is kept: its readings are within 0.05 increments of it (``5e-15 * 1e8``
    program units, a step at least 1e-5: IS-C inch).

    A value with a spread (a libm result, :class:`SpreadDouble`) is decided here only below ``2**20``
    increments, its quotient's fraction at least ``2**-19`` from a half and its spread narrower than ``2**-21``
    increments: every double of the spread is then within ``2**-21`` increments of ``d`` and each of its
    readings within ``2**-26`` more, so every reading of every double is farther than ``2**-20`` from the half
    on ``d``'s side and rounds as ``d`` does (a spread across 0 is below ``2**-21`` increments: 0 for all).
    Anything else goes to :func:`_spread_round` (its ends' readings, GC397 where they part).

    >>> round_to((12.3456, None), Fraction(1, 1000)), round_to((-2.5, Fraction(-5, 2)), Fraction(1))
    (Fraction(6173, 500), Fraction(-3, 1))
    >>> round_to((1.2345, None), Fraction(1, 1000))  # 15 digits: 1.2345, in doubles 1234.5 increments
    Fraction(247, 200)
    >>> round_to((1.5 * 1.017, None), Fraction(1, 1000))
    Traceback (most recent call last):
    ...
    nczones.gcode.fanuc.expr.RoundingNotCertain: a macro value at half an increment (0.001): ...
    """
    q: Fraction | None = value[1]
    sn, sd = (step._numerator, step._denominator) if _SLOTS else _ratio(step)  # type: ignore[attr-defined]
    d = value[0]
    if q is not None:
        qn, qd = _ratio(q)
        # already a multiple of the step (a decimal literal, an exact sum): every reading stands on it
        if sn == 1 and sd % qd == 0 and (d is None or -1e8 < d < 1e8):  # (SHADOW_ON_GRID_BOUND, as constants)
            return q
    if d is not None:
        if sn == 1:
            # |d| / step in doubles (relative error 2**-53): away from a half by max(2**-20, x 2**-40) the
            # nearest integer is that of the exact quotient, of the shadow's and of every reading; nearer, or
            # beyond 2**52, the exact path below decides.  A libm result (a spread) passes only as far from a
            # half as _spread_round's screen asks (its width twice more), else goes to _spread_round
            x = abs(d) * sd
            if x < _FAST_INCREMENTS:
                m = _floor(x)
                frac = x - m  # exact (x and m are doubles below 2**52)
                if d.__class__ is SpreadDouble:
                    if x < _WIDE_INCREMENTS and not _SPREAD_HALF_LOW < frac < _SPREAD_HALF_HIGH and (
                            d.hi - d.lo) * sd < _SPREAD_WIDTH:
                        n = m + 1 if frac > 0.5 else m
                        return to_fraction(-n if d < 0 else n, sd)
                elif not _NEAR_HALF_LOW < frac < _NEAR_HALF_HIGH and (
                        x < _WIDE_INCREMENTS or abs(frac - 0.5) > x * _WINDOW):
                    n = m + 1 if frac > 0.5 else m
                    return to_fraction(-n if d < 0 else n, sd)
        if d.__class__ is SpreadDouble:
            return _spread_round(value, step, sn, sd)  # a libm result: every double of its spread (GC397)
        if q is None:
            # the double's exact value (its ratio is in lowest terms), without building a Fraction first
            qn, qd = d.as_integer_ratio()
    # k = q / step = (qn * sd) / (qd * sn); n = floor(|k| + 1/2)
    num, den = abs(qn) * sd, qd * sn
    n = (2 * num + den) // (2 * den)
    if d is not None and _near_tie(num, den, n):
        return _agreed(value, step)
    return to_fraction(-n * sn if qn < 0 else n * sn, sd)


def _near_tie(num: int, den: int, n: int) -> bool:
    """Whether ``k = num / den`` (increments, ``n`` its rounding) is within ``max(2**-20, k 2**-40)`` of a
    half: where a reading of the double might round elsewhere (:func:`round_to`).

    >>> _near_tie(3 * 2**40 + 1, 2, 3 * 2**39 + 1)  # k = 3 2**39 + 1/2: a half exactly
    True
    >>> _near_tie(3 * 2**26 + 1, 4, 3 * 2**24)  # k = 3 2**24 + 1/4: far from a half (beyond 2**24 too)
    False
    """
    below = 2 * num - (2 * n - 1) * den  # 2 den (k - (n - 1/2)) >= 0
    above = (2 * n + 1) * den - 2 * num  # 2 den ((n + 1/2) - k) > 0
    gap = min(below, above)  # 2 den |k - the nearest half|
    return (gap << 19) <= den or (gap << 39) <= num


def readings(value: tuple, step: Fraction) -> list[tuple[str, Fraction]]:
    """The values in program units a control could read a macro value ``(double, shadow)`` as, for an address
    of increment ``step``, each with its name (:func:`round_to`): the exact value it stands for (the shadow, when
    kept), the double's 15-significant-digit decimal ([15i] 17 "Limitation"; the reading of
    ``tests/oracles/fanuc_ref.py``) and the double scaled to increments in doubles (times ``1 / step`` and
    divided by ``step``).

    >>> for name, r in readings((1.5 * 1.017, None), Fraction(1, 1000)):
    ...     print(f"{name}: {float(r)!r} -> {float(_half_away(r, Fraction(1, 1000)))}")
    its 15-digit decimal, 1.5255,: 1.5255 -> 1.526
    the double times 1000 in doubles, 1525.4999999999998 increments,: 1.5254999999999999 -> 1.525
    the double divided by 0.001 in doubles, 1525.4999999999998 increments,: 1.5254999999999999 -> 1.525
    """
    d, q = value
    out = [] if q is None else [(f"the exact value it stands for, {_decimal(q)},", q)]
    fifteen = Fraction(format(d, ".15g")) if d else Fraction(0)
    out.append((f"its 15-digit decimal, {_decimal(fifteen)},", fifteen))
    for name, x in ((f"times {_decimal(1 / step)}", d * float(1 / step)), (f"divided by {_decimal(step)}",
                                                                           d / float(step))):
        out.append((f"the double {name} in doubles, {x!r} increments,", Fraction(x) * step))
    return out


def _half_away(r: Fraction, step: Fraction) -> Fraction:
    k = abs(r) / step
    n = _floor(k + Fraction(1, 2))
    return (-n if r < 0 else n) * step


def _agreed(value: tuple, step: Fraction) -> Fraction:
    """The multiple of ``step`` every one of the :func:`readings` of ``value`` rounds to; else
    :class:`RoundingNotCertain` naming each reading and where it rounds."""
    got = [(name, r, _half_away(r, step)) for name, r in readings(value, step)]
    if len({g[2] for g in got}) == 1:
        return got[0][2]
    shown = "; ".join(f"{name} rounds to {_decimal(m)}" for name, _r, m in got)
    raise RoundingNotCertain(
        f"a macro value at half an increment ({_decimal(step)}): the double {value[0]!r} (exactly "
        f"{_decimal(Fraction(value[0]))}): {shown}; which reading the control rounds is not known "
        "(specs/fanuc.md, \"A value at half an increment\")")


def _decimal(r: Fraction) -> str:
    """``r`` as a decimal: exactly when 28 significant digits hold it, else those and an ellipsis.

    >>> _decimal(Fraction(3051, 2000)), _decimal(Fraction(1, 3))
    ('1.5255', '0.3333333333333333333333333333...')
    """
    from decimal import Decimal, localcontext

    with localcontext() as c:
        c.prec = 28
        shown = Decimal(r.numerator) / Decimal(r.denominator)
    if Fraction(shown) == r:
        return f"{shown.normalize():f}"
    return f"{shown:f}..."


class ReadingsSplit(RoundingNotCertain):
    """A macro value whose readings give different results for FIX, FUP, ROUND (outside an address), MOD,
    AND/OR/XOR, BIN/BCD, a comparison, a variable number, POW's integer exponent or ASIN/ACOS's -1..1 (GC398).

    It travels as :class:`RoundingNotCertain` does: the verdict is ``unknown`` at the line; ``reason`` names
    every reading and its result.
    """

    def __init__(self, reason: str):
        SystemVariableUnknown.__init__(self, "GC398", reason)


#: Twice the readings' reach, relative: every reading of a double ``d`` (its 15-digit decimal: within
#: ``5e-15 |d|``; a shadow that rounds to it: half an ulp, ``2**-53 |d|``) lies within ``2**-47 |d|`` of it,
#: plus :data:`_TINY` (a subnormal's half ulp is ``2**-1075``).
_WINDOW_READINGS = 2.0**-46
_TINY = 2.0**-1000
_LARGE = 4503599627370496.0  # 2**52: above it every double is an integer (the exact path decides)


def _fifteen(d: float) -> Fraction:
    """The double's 15-significant-digit decimal ([15i] 17 "Limitation").

    >>> _fifteen(0.3 / 0.1), _fifteen(7.0)
    (Fraction(3, 1), Fraction(7, 1))
    """
    if -1e15 < d < 1e15 and d == _floor(d):
        return Fraction(int(d))
    return Fraction(format(d, ".15g"))


def _trunc(r: Fraction) -> int:
    return int(r)  # towards zero


def _up(r: Fraction) -> int:
    n = -(-abs(r) // 1)
    return n if r >= 0 else -n


def _nearest(r: Fraction) -> int:
    n = (abs(r) * 2 + 1) // 2
    return n if r >= 0 else -n


#: The integer an operation takes of a value, per kind: FIX and AND/OR/XOR its integer part, FUP away from
#: zero, ROUND/MOD/BIN/BCD/a variable number the nearest integer, halves away from zero.
_INTEGER_OF: dict[str, Callable[[Fraction], int]] = {"fix": _trunc, "fup": _up, "round": _nearest}


def _integer_fast(value: Value, kind: str) -> int | None:
    """The integer every reading of ``value`` gives (:data:`_INTEGER_OF` ``kind``), decided in doubles; None
    where the double is too near where the readings could part (then :func:`_agreed_integer` decides).

    Soundness: every reading lies within ``w/2`` of the double's exact value (``w = |d| 2**-46 + 2**-1000``,
    :data:`_WINDOW_READINGS`); below ``2**52`` the fraction ``f = |d| - floor(|d|)`` is exact, so a fraction
    farther than ``w`` from where the kind's integer changes (0 and 1 for FIX/FUP, a half for ROUND) keeps every
    reading on the double's side.  At an integer ``d`` (``f = 0``) FIX and FUP give ``d`` for the double and its
    15 digits (below ``1e15``) and for an integer shadow (it rounds to ``d``: it is ``d``); a shadow that may
    be anything else is the exact path's; FIX of ``0 <= |d| < 1`` is 0 in every reading (a reading keeps the
    value's sign).

    >>> _integer_fast((2.9999999999999996, None), "fix") is None, _integer_fast((2.5, None), "fix")
    (True, 2)
    >>> _integer_fast((-2.5, None), "round") is None, _integer_fast((-2.4, None), "round")
    (True, -2)
    """
    d = value[0]
    a = d if d >= 0.0 else -d
    if a >= _LARGE:
        return None
    m: int = _floor(a)
    frac = a - m
    w = a * _WINDOW_READINGS + _TINY
    if kind == "round":
        if abs(frac - 0.5) <= w:
            return None
        n = m + 1 if frac > 0.5 else m
    elif frac >= 1.0 - w:
        return None
    elif frac > w:
        n = m if kind == "fix" else m + 1
    elif kind == "fix" and m == 0:
        n = 0
    elif frac == 0.0 and value[1] is not None and a < 1e15 and denominator_of(value[1]) == 1:
        n = m
    else:
        return None
    return -n if d < 0 else n


def _value_readings(value: Value) -> list[tuple[str, Fraction]]:
    """Each reading of one macro value, named: the double as it is, its 15-digit decimal, the exact value it
    stands for (the shadow, when kept)."""
    d, q = value
    exact, fifteen = Fraction(d), _fifteen(d)
    out = [(f"the double as it is, {_decimal(exact)},", exact), (f"its 15-digit decimal, {_decimal(fifteen)},", fifteen)]
    if q is not None:
        out.append((f"the exact value it stands for, {_decimal(q)},", q))
    return out


def _integer_readings(value: Value, kind: str) -> list[tuple[str, int]]:
    """Each reading of ``value`` (:func:`_value_readings`) and the integer it gives (:data:`_INTEGER_OF`)."""
    of = _INTEGER_OF[kind]
    return [(name, of(r)) for name, r in _value_readings(value)]


def _agreed_integer(value: Value, kind: str, what: str) -> int:
    """The integer every reading of ``value`` gives; else :class:`ReadingsSplit` naming them."""
    got = _integer_readings(value, kind)
    if len({n for _name, n in got}) == 1:
        return got[0][1]
    raise _split(what, value, [(name, str(n)) for name, n in got])


def _split(what: str, value: Value, results: list[tuple[str, str]]) -> ReadingsSplit:
    shown = "; ".join(f"{name} gives {r}" for name, r in results)
    return ReadingsSplit(f"{what}: the readings of the macro value {value[0]!r} give different results: {shown}; "
                         "which reading the control takes is not known (specs/fanuc.md, \"A value at half an "
                         "increment\")")


def integer_of(value: Value, kind: str, what: str, again: Callable[[], Value] | None = None) -> int:
    """The integer FIX (``kind`` ``"fix"``), FUP (``"fup"``) or ROUND (``"round"``) takes of a macro value
    ``(double, shadow)``, the same in every reading (:func:`round_to`'s readings that fit an integer: the
    double as it is, its 15-digit decimal, the exact value it stands for); :class:`ReadingsSplit` (GC398,
    ``what`` names the operation) when they differ.  ``again``: the value evaluated again with its shadow,
    when the one given was computed without it (only asked near a split).

    >>> integer_of((0.3 / 0.1, None), "fup", "FUP"), integer_of((0.1 * 3 * 10, None), "round", "ROUND")
    (3, 3)
    >>> integer_of((0.3 / 0.1, None), "fix", "FIX")
    Traceback (most recent call last):
    ...
    nczones.gcode.fanuc.expr.ReadingsSplit: FIX: the readings of the macro value 2.9999999999999996 give ...
    """
    if value[0].__class__ is SpreadDouble:
        return _spread_integer(value, kind, what)
    n = _integer_fast(value, kind)
    if n is not None:
        return n
    return _agreed_integer(again() if again is not None else value, kind, what)


def variable_number(value: Value) -> int:
    """The variable number a computed ``#[...]`` names: rounded to the nearest integer, halves away from zero
    ([Sinha] "Real versus integer values": a real number where an integer is expected is rounded), the same
    in every reading (:func:`integer_of`; GC398 when not).

    >>> variable_number((100.49, Fraction(10049, 100))), variable_number((2.0 * 0.75, None))
    (100, 2)
    """
    d = value[0]
    if d - d:
        raise EvalError("GC204", f"variable number {d!r} is not a number")
    return integer_of(value, "round", "the variable number #[...]")


def literal_number(index: tuple) -> int | None:
    """The variable number ``#n`` or ``#[literal]`` names, a number node's, when every reading of the literal
    gives it (:func:`variable_number`: the literal's double, its 15 digits and its exact decimal; ``#[125.4999999
    9999999999]`` is the double 125.5, #126, and the decimal it was written as, #125); None where they part,
    or for a node that is not a number: the caller compiles it as a computed ``#[...]`` then, which is
    :class:`ReadingsSplit` (GC398) where the line runs, not where it is compiled.

    >>> literal_number((NUM, 7.0, Fraction(7))), literal_number((NUM, 125.5, Fraction("125.49999999999999999")))
    (7, None)
    """
    if index[0] != NUM:
        return None
    d, q = index[1], index[2]
    if q is not None and denominator_of(q) == 1 and -1e15 < d < 1e15:
        return int(d)  # #n: an integer below 1e15 is its double, its 15 digits and its shadow (it rounds to it)
    try:
        return variable_number((d, q))
    except ReadingsSplit:
        return None


def _reading_pairs(x: Value, y: Value) -> list[tuple[str, Fraction, Fraction]]:
    """The readings of two macro values a control could compare or combine, one reading for both: the
    doubles as they are, their 15-digit decimals, and (when both keep one) the exact values they stand for (a
    control computing in decimals; what such a control would hold for a value without a shadow, a sine or a
    rounded product, nczones does not know, and reading it as its double or its 15 digits there would split
    readings that only the stand-in parts: ``1/3`` against a sine's ``0.333...``)."""
    a, qa = x
    b, qb = y
    fa, fb = _fifteen(a), _fifteen(b)
    pairs = [(f"the doubles as they are ({_decimal(Fraction(a))} and {_decimal(Fraction(b))})", Fraction(a),
              Fraction(b)), (f"their 15-digit decimals ({_decimal(fa)} and {_decimal(fb)})", fa, fb)]
    if qa is not None and qb is not None:
        pairs.append((f"the exact values they stand for ({_decimal(qa)} and {_decimal(qb)})", qa, qb))
    return pairs


def _related(op: str, x: Value, y: Value) -> Value:
    """``x op y`` (EQ NE GT GE LT LE) the same under every reading pair (:func:`_reading_pairs`), else
    :class:`ReadingsSplit`.  No manual gives the relational operators a tolerance: the [15i] and [30i]
    "Limitation" sections say ``IF [#1 EQ #2]`` "cannot always determine" equality because of the error and
    tell the programmer to write ``IF [ABS[#1-#2] LT 0.1]``."""
    test = _RELATIONS[op][2]
    a, qa = x
    b, qb = y
    if a == b and (qa is None or qb is None or qa == qb):
        return _TRUE if test(0, 0) else _FALSE  # one double, one 15-digit decimal, one exact value
    pairs = _reading_pairs(x, y)
    truths = [test(p, q) for _name, p, q in pairs]
    if len(set(truths)) == 1:
        return _TRUE if truths[0] else _FALSE
    shown = "; ".join(f"{name}: {'true' if t else 'false'}" for (name, _p, _q), t in zip(pairs, truths))
    raise ReadingsSplit(f"{op.upper()}: the readings of the macro values {a!r} and {b!r} compare differently: "
                        f"{shown}; which reading the control compares is not known (specs/fanuc.md, \"A value at "
                        "half an increment\")")


def _certain_bounds(b: Value) -> tuple[float, float]:
    """``(lo, hi)`` for a constant ``b``: a double ``a < lo`` has every reading below every reading of ``b``,
    ``a > hi`` every reading above (between them :func:`_related` decides).

    Soundness: every reading of a double ``x`` lies within ``e(x) = |x| 2**-47 + 2**-1074`` of it (the shadow
    too: it rounds to ``x``; a shadow of ``b`` that does not is taken as its own nearest double ``c``, within
    ``2**-53 |c|`` of it).  ``lo = b' - (|b'| 2**-44 + 2**-999)`` in doubles, ``b'`` the least of ``b`` and
    ``c``: the subtraction rounds by at most ``2**-53 (|b'| + s)``, so ``lo + e(lo)`` stays below ``b' - e(b')``
    with ``|b'| 2**-46`` to spare, and ``a < lo`` (``a + e(a)`` grows with ``a``) puts every reading of ``a``
    below every reading of ``b``; ``hi`` the same way from above.  Doubles only: a comparison compiles in
    about a microsecond.

    >>> lo, hi = _certain_bounds((10.0, Fraction(10))); 9.999999999999 < lo < 10.0 < hi < 10.000000000001
    True
    """
    low = high = b[0]
    if b[1] is not None:
        c = double_of(b[1])
        if c != low:
            low, high = min(low, c), max(low, c)
    return low - (abs(low) * _BOUND_SLACK + _BOUND_TINY), high + (abs(high) * _BOUND_SLACK + _BOUND_TINY)


_BOUND_SLACK, _BOUND_TINY = 2.0**-44, 2.0**-999


def _mod(i: int, j: int) -> Value:
    if j == 0:
        raise EvalError("GC311", "attempt to take MOD by zero")
    r = abs(i) % abs(j)
    return _num(float(-r if i < 0 else r))


#: MOD (both operands rounded to integers, the remainder with the dividend's sign) and AND/OR/XOR (bit by bit
#: on the integer parts): the integer each operand is taken as (:data:`_INTEGER_OF`) and the operation.
_INTEGER_BINARY: dict[str, tuple[str, Callable[[int, int], Value]]] = {
    "mod": ("round", _mod), "and": ("fix", lambda i, j: _num(float(i & j))),
    "or": ("fix", lambda i, j: _num(float(i | j))), "xor": ("fix", lambda i, j: _num(float(i ^ j)))}


def _agreed_binary(op: str, x: Value, y: Value) -> Value:
    """MOD/AND/OR/XOR of ``x`` and ``y`` under every reading pair (:func:`_reading_pairs`): the result (or the
    error) they all give, else :class:`ReadingsSplit`."""
    kind, fn = _INTEGER_BINARY[op]
    of = _INTEGER_OF[kind]
    outcomes: list[tuple[str, Any, str]] = []
    first: tuple[int, int] | None = None
    for name, p, q in _reading_pairs(x, y):
        i, j = of(p), of(q)
        first = first or (i, j)
        try:
            v = fn(i, j)
            outcomes.append((name, ("value", v[0]), f"{i} {op.upper()} {j} = {_decimal(Fraction(v[0]))}"))
        except EvalError as e:
            outcomes.append((name, ("error", e.code, e.message), f"{i} {op.upper()} {j}: {e.message}"))
    if len({o[1] for o in outcomes}) == 1 and first is not None:
        return fn(*first)  # the value, or the error, every reading gives
    shown = "; ".join(f"{name}: {text}" for name, _key, text in outcomes)
    raise ReadingsSplit(f"{op.upper()}: the readings of the macro values {x[0]!r} and {y[0]!r} give different "
                        f"results: {shown}; which reading the control takes is not known (specs/fanuc.md, \"A "
                        "value at half an increment\")")


def _num(d: float) -> tuple:
    """A double as a value, with the exact shadow when it is an integer."""
    return (d, Fraction(int(d))) if d == int(d) and abs(d) < 2.0**63 else (d, None)


def _bcd(k: int, d: float) -> Value:
    if k < 0:
        raise EvalError("GC312", f"BCD of a negative number {d!r}")
    return _num(float(int(str(k), 16)))


def _bin(k: int, d: float) -> Value:
    digits = f"{k:x}" if k >= 0 else "-"
    if not digits.isdigit():
        raise EvalError("GC312", f"BIN of {d!r}: not a BCD number (a nibble above 9)")
    return _num(float(int(digits)))


#: FIX, FUP, ROUND outside an address, BCD, BIN: the integer each takes of its operand (:data:`_INTEGER_OF`)
#: and the value made of it (``d`` the operand's double: ROUND keeps the sign of a zero, as the double
#: arithmetic ``floor(|d| + 0.5) * sign`` did).
_INTEGER_FUNCTIONS: dict[str, tuple[str, Callable[[int, float], Value]]] = {
    "fix": ("fix", lambda n, d: _num(float(n))), "fup": ("fup", lambda n, d: _num(float(n))),
    "round": ("round", lambda n, d: _num(float(n) if d >= 0 else -float(-n))), "bcd": ("round", _bcd),
    "bin": ("round", _bin)}


def _int_of(d: float, what: str) -> int:
    if d - d:
        raise EvalError("GC312", f"{what} of {d!r} cannot be computed")
    return int(d)


class Context:
    """What a compiled tree needs besides the variables: the ATAN/ASIN range (NAT) and the least input
    increment of the address for ROUND/ADP (``increment()`` gives it, in program units)."""

    __slots__ = ("signed_angles", "increment")

    def __init__(self, signed_angles: bool = False, increment: Callable[[], Fraction] | None = None):
        self.signed_angles = signed_angles
        self.increment = increment or (lambda: Fraction(1, 1000))


def _angle(d: float, ctx: Context, full: bool) -> tuple:
    """An angle in degrees in Fanuc's range: ``full`` (ATAN of two arguments) 0..360 or -180..180; else
    (ASIN, one-argument ATAN) 270..90 (i.e. a negative result + 360) or -90..90.

    What the angle functions read (readings39).  SIN COS TAN ATAN ASIN ACOS take their argument's double as
    it is: the control computes them in its doubles ([15i] "Limitation": IEEE double precision, errors as the
    standard has them), as it does ``+ - * /``, and the readings are taken where a value becomes an integer, a
    truth or an address (:func:`integer_of`, :func:`_related`, :func:`round_to`), so of the angle's result,
    not of its argument: ``SIN[0.1 * 3 * 100]`` is the sine of 30.000000000000004, 0.5, and ``2.001 *`` it is
    then at half an increment (GC399).  The argument's 15 digits or exact decimal would be the input of a
    control computing in decimals, whose sine nczones does not know (a value without a shadow,
    :func:`_reading_pairs`).  The one place an angle function decides on its argument, ASIN/ACOS's -1..1,
    takes every reading (:func:`_arc_domain`).  A range shift (a negative result + 360) keeps the sign of the
    argument, the same in every reading.

    The result keeps a shadow only where its double is an integer, and that shadow is the double (ATAN[1] is
    45).  Soundness, whatever the argument's readings: the shadow is one of the double's readings already
    (an integer angle, at most 360, is its own 15 digits), so FIX/FUP/ROUND/MOD/a variable number and
    :func:`round_to` give what the double alone gives; in a comparison with a value that keeps a shadow it
    adds the pair of exact values (:func:`_reading_pairs`), one reading more, and a result is given only where
    every reading agrees, so it can part a result (GC398), never give another; arithmetic keeps it only where
    the exact result rounds to the double it computes, as for every shadow
    (``tests/gcode/fanuc/test_macro_readings_functions.py`` holds both to readings computed independently).
    """
    if not ctx.signed_angles and d < 0.0:
        d = d + 360.0
    return (check_double(d), None) if d != int(d) else (d, Fraction(int(d)))


def _arc_function(name: str, arg: Callable[[], Value], again: Callable[[], Value] | None,
                  ctx: Context) -> Callable[[], Value]:
    """``ASIN[arg]`` or ``ACOS[arg]`` in degrees (:func:`_angle`), of the argument's double; an argument outside
    -1..1 is the alarm GC312, and that bound is a comparison with 1: it takes every reading's answer
    (:func:`_arc_domain`; GC398 where they part, as EQ/LE do)."""
    upper = name.upper()
    fn = math.asin if name == "asin" else math.acos

    def core(c: float) -> Value:
        if not -1.0 <= c <= 1.0:
            raise EvalError("GC312", f"argument to {upper} out of range: {c!r} (allowed -1 to 1)")
        r = fn(c)
        if c == (0.0 if name == "asin" else 1.0):  # ASIN of 0, ACOS of 1: 0 exactly
            return _angle(r * 180.0 / math.pi, ctx, False)
        return _angle_spread(r, ctx, False)

    def arc() -> Value:
        value = arg()
        d = value[0]
        if d - d:
            raise EvalError("GC312", f"argument to {upper} is {d!r}")
        if d.__class__ is SpreadDouble:
            _spread_arc_domain(upper, d)
            return _over_spread(upper, core, d)
        if not -_ARC_INSIDE < d < _ARC_INSIDE:
            _arc_domain(upper, value, again)
        return core(d)
    return arc


def _spread_arc_domain(upper: str, d: float) -> None:
    """:func:`_arc_domain` for an argument with a spread: nothing where every reading of every double of it is
    inside -1..1 (readings are non-decreasing in the double, and -1..1 is an interval: its ends' readings
    decide), the alarm where all are beyond one end, else :class:`LibmSplit` (GC396)."""
    lo, hi = _bounds(d)
    got = [r for c in (lo, hi) for _name, r in _value_readings((c, None))]
    if all(-1 <= r <= 1 for r in got):
        return
    if all(r > 1 for r in got) or all(r < -1 for r in got):
        raise EvalError("GC312", f"argument to {upper} out of range: {float(d)!r} (allowed -1 to 1)")
    raise LibmSplit("GC396", f"{upper}: a result of SIN/COS/TAN/ATAN/ASIN/ACOS/LN/EXP/POW, {float(d)!r}, whose one-ulp "
                    f"neighbours ({lo!r} .. {hi!r}) lie inside and outside -1..1 (an alarm there); {_SPREAD_NOTE}")


def _angle_spread(r: float, ctx: Context, full: bool) -> Value:
    """A library angle ``r`` in radians (ATAN, ASIN, ACOS) in degrees in Fanuc's range (:func:`_angle`), with
    the spread of its two neighbours (:func:`_libm_value`) taken through the same doubles: the degrees and the
    range shift of each of the three (a shift that parts them gives a spread over the whole range)."""
    got = [_angle(x * 180.0 / math.pi, ctx, full)[0] for x in (r, _nextafter(r, -_INF), _nextafter(r, _INF))]
    return (_spread(got[0], min(got), max(got)), None)


#: An ASIN/ACOS argument ``|d| < _ARC_INSIDE`` is inside -1..1 in every reading, ``|d| > _ARC_OUTSIDE`` outside
#: in every reading: every reading lies within ``|d| 2**-47 + 2**-1001`` of the double (:data:`_WINDOW_READINGS`),
#: less than ``2**-45`` from a double near 1.
_ARC_INSIDE, _ARC_OUTSIDE = 1.0 - 2.0**-45, 1.0 + 2.0**-45


def _arc_domain(upper: str, value: Value, again: Callable[[], Value] | None) -> None:
    """The alarm for an ASIN/ACOS argument ``value`` outside -1..1 in every reading, nothing where every
    reading is inside, else :class:`ReadingsSplit`: ``ACOS[#1 / 3]`` with ``#1 = 0.1 * 3 * 10`` is the double
    1.0000000000000002 (the alarm) and its 15 digits 1 (0 degrees); ``again`` gives the argument with its
    shadow (``ACOS[1.0000000000000000001]`` is the double 1.0 and a literal beyond 1)."""
    d = value[0]
    if -_ARC_OUTSIDE <= d <= _ARC_OUTSIDE:
        got = [(name, -1 <= r <= 1) for name, r in _value_readings(again() if again is not None else value)]
        inside = {ok for _name, ok in got}
        if inside == {True}:
            return
        if len(inside) > 1:
            shown = "; ".join(f"{name} is {'inside' if ok else 'outside'} -1..1" for name, ok in got)
            raise ReadingsSplit(f"{upper}: the readings of the macro value {d!r} give different results: {shown} "
                                "(an alarm there); which reading the control takes is not known (specs/fanuc.md, "
                                "\"A value at half an increment\")")
    raise EvalError("GC312", f"argument to {upper} out of range: {d!r} (allowed -1 to 1)")


def _radians(d: float, name: str) -> float:
    """``d`` degrees in radians, in the control's doubles; an angle whose radians overflow is GC312.

    >>> _radians(1.7e308, "sin")
    Traceback (most recent call last):
    ...
    nczones.gcode.expr.EvalError: argument to SIN is 1.7e+308: its radians overflow a double
    """
    r = d * math.pi / 180.0
    if r - r:
        raise EvalError("GC312", f"argument to {name.upper()} is {d!r}" + (": its radians overflow a double"
                                                                            if not d - d else ""))
    return r


def _circular(name: str, d: float) -> tuple:
    """SIN, COS or TAN of ``d`` degrees (a plain double), with the spread of :func:`_libm_value` (none at 0)."""
    r = _radians(d, name)
    if name == "sin":
        c = math.sin(r)
    elif name == "cos":
        c = math.cos(r)
    else:
        c = check_double(math.tan(r))
    return (_libm_value(c, d == 0.0), None)


def _atan(d: float, ctx: Context) -> Value:
    """ATAN of one argument (a plain double) in degrees, with its spread (none at 0)."""
    r = math.atan(d)
    if d == 0.0:
        return _angle(r * 180.0 / math.pi, ctx, False)
    return _angle_spread(r, ctx, False)


def _atan2(y: float, x: float, ctx: Context) -> Value:
    """``ATAN[y]/[x]`` in degrees (0..360, or -180..180 with NAT), with its spread: none for a zero ``y`` and a
    positive ``x`` (IEEE's atan2 of +-0 and +x is +-0); arguments with a spread over their doubles."""
    if y.__class__ is SpreadDouble or x.__class__ is SpreadDouble:
        return _over_spread("ATAN", lambda p, q: _atan2(p, q, ctx), y, x)
    r = math.atan2(y, x)
    if y == 0.0 and math.copysign(1.0, x) > 0.0:
        return _angle(r * 180.0 / math.pi, ctx, True)
    return _angle_spread(r, ctx, True)


def _ln(d: float) -> Value:
    if d <= 0.0:
        raise EvalError("GC312", f"zero or negative argument to LN: {d!r}")
    return (_libm_value(math.log(d), d == 1.0), None)


def _exp(d: float) -> Value:
    try:
        return (_libm_value(check_double(math.exp(d)), d == 0.0), None)
    except OverflowError:
        raise EvalError("GC312", "calculation resulted in 'infinity'") from None


def _spread_function(name: str, value: Value, ctx: Context) -> Value:
    """:func:`_function` of a value with a spread."""
    d = value[0]
    if name == "abs":
        return _absolute(value)
    if name == "sqrt":
        return _square_root(value)
    if name == "round":  # in an address: every double of the spread rounds to one multiple, else GC397
        r = round_to(value, ctx.increment())
        return (float(r), r)
    if name == "adp":
        inc = ctx.increment()
        return _spread_arithmetic("*", value, (float(1 / inc), 1 / inc))
    upper = name.upper()
    if name in ("sin", "cos", "tan"):
        return _over_spread(upper, lambda c: _circular(name, c), d)
    if name == "atan":
        return _over_spread(upper, lambda c: _atan(c, ctx), d)
    return _over_spread(upper, _ln if name == "ln" else _exp, d)


def _function(name: str, value: tuple, ctx: Context, in_address: bool) -> tuple:
    d, q = value
    if d - d:
        raise EvalError("GC312", f"argument to {name.upper()} is {d!r}")
    if d.__class__ is SpreadDouble:
        return _spread_function(name, value, ctx)
    if name == "abs":
        return (abs(d), abs(q) if q is not None else None)
    if name == "round":  # in an address (outside one: _integer_function)
        step = ctx.increment()
        r = round_to(value, step)
        return (float(r), r)
    if name in ("sin", "cos", "tan"):
        return _circular(name, d)
    if name == "atan":
        return _atan(d, ctx)
    if name == "sqrt":
        if d < 0.0:
            raise EvalError("GC312", f"negative argument to SQRT: {d!r}")
        root = math.sqrt(d)
        return (root, Fraction(int(root)) if root == int(root) else None)
    if name == "ln":
        return _ln(d)
    if name == "exp":
        return _exp(d)
    if name == "adp":
        inc = ctx.increment()
        return binary_op("*", value, (float(1 / inc), 1 / inc))
    raise AssertionError(name)  # pragma: no cover


def _pow(a: Value, b: Value, again_a: Callable[[], Value] | None, again_b: Callable[[], Value] | None) -> Value:
    """``POW[a,b]``, a to the b in doubles; a base not above 0 is :func:`_pow_domain`'s first (an alarm, or
    GC398 where the readings part on it)."""
    x, y = a[0], b[0]
    if x.__class__ is SpreadDouble or y.__class__ is SpreadDouble:
        return _spread_pow(x, y)
    if not x > 0.0:
        _pow_domain(a, b, again_a, again_b)
    try:
        r = math.pow(x, y)
    except (OverflowError, ValueError):
        raise EvalError("GC312", f"POW[{x!r},{y!r}] cannot be computed") from None
    r = check_double(r)
    if _pow_exact(x, y, r):
        return _num(r)
    return (_libm_value(r, False), None)


def _pow_exact(x: float, y: float, r: float) -> bool:
    """Whether CPython's ``r = POW[x, y]`` is the true power (a library whose error is below one ulp gives it
    then): an exponent 0 or a base 1 (1 exactly), or an integer exponent (at most 64 in size) whose exact power
    is ``r``."""
    if y == 0.0 or x == 1.0:
        return True
    if y != _floor(y) or abs(y) > 64.0:
        return False
    n = int(y)
    if x == 0.0:
        return n > 0
    return Fraction(r) == Fraction(x) ** n


def _spread_pow(x: float, y: float) -> Value:
    """POW where an operand carries a spread: over the doubles of the spreads (:func:`_over_spread`) when every
    double of the base is above 0; a base whose spread reaches 0 or below is GC396 (whether the exponent is an
    integer and which parity it has would be taken over a spread: not modelled)."""
    lo, _hi = _bounds(x)
    if not lo > 0.0:
        raise LibmSplit("GC396", f"POW of the base {float(x)!r} (its spread from {lo!r}) and the exponent {float(y)!r}"
                        f" where one carries a spread: a base not above 0 is not modelled there; {_SPREAD_NOTE}")
    return _over_spread("POW", lambda p, q: _pow((p, None), (q, None), None, None), x, y)


def _pow_alarm(x: float, y: float, case: str) -> EvalError:
    if case == _POW_NEGATIVE_FRACTION:
        return EvalError("GC312", f"POW of negative {x!r} to the non-integer power {y!r}")
    return EvalError("GC312", f"POW of 0 to the negative power {y!r}")


#: What POW does with a base not above 0, per reading (:func:`_pow_case`).
_POW_NEGATIVE_FRACTION = "an alarm (a negative base to a non-integer power)"
_POW_ZERO_NEGATIVE = "an alarm (0 to a negative power)"
_POW_ALARMS = frozenset((_POW_NEGATIVE_FRACTION, _POW_ZERO_NEGATIVE))


def _pow_case(base_sign: int, r: Fraction) -> str:
    """What POW does with a base of this sign and the exponent reading ``r``: an alarm, or a power of which
    sign (a negative base to an integer power: the parity of the exponent)."""
    if base_sign < 0:
        if denominator_of(r) != 1:
            return _POW_NEGATIVE_FRACTION
        return "a negative power" if r % 2 else "a power not negative"
    if base_sign == 0 and r < 0:
        return _POW_ZERO_NEGATIVE
    return "a power not negative"


def _pow_exponent_fast(y: Value, shadow_known: bool) -> str | None:
    """:func:`_pow_case` of a negative base, the same for every reading of the exponent ``y``, decided in
    doubles; None where the exponent is too near an integer (or one whose shadow is not known).

    Soundness: as :func:`_integer_fast`: every reading lies within ``w/2`` of the double (``w = |y| 2**-46 +
    2**-1000``), so a fraction ``f`` of ``|y|`` (exact below ``2**52``) with ``w < f < 1 - w`` leaves every
    reading strictly between the same two integers (not an integer: the alarm); at an integer double below
    ``1e15`` its 15 digits are that integer and a shadow that rounds to it and is an integer is that integer
    (one parity).
    """
    d = y[0]
    t = d if d >= 0.0 else -d
    if t >= _LARGE:
        return None
    m: int = _floor(t)
    frac = t - m
    w = t * _WINDOW_READINGS + _TINY
    if w < frac < 1.0 - w:
        return _POW_NEGATIVE_FRACTION
    if frac == 0.0 and t < 1e15 and shadow_known and (y[1] is None or denominator_of(y[1]) == 1):
        return _pow_case(-1, Fraction(m))
    return None


def _pow_domain(a: Value, b: Value, again_a: Callable[[], Value] | None, again_b: Callable[[], Value] | None) -> None:
    """POW with a base ``a`` not above 0: the alarm every reading gives (GC312), nothing where every reading
    computes a power of one sign, else :class:`ReadingsSplit` (GC398) naming each reading and what it does.

    Whether the exponent is an integer (and its parity) is an integer the control takes of a value, as FIX
    takes one: the readings rule of :func:`integer_of` (the double as it is, its 15 digits, the exact value it
    stands for), each operand read on its own, since the case depends on the base's sign alone and on the
    exponent alone.  A negative double's readings are all negative (a 15-digit decimal keeps the sign, a shadow
    rounds to the double), so only a zero base reads its shadow (``again_a``: one that underflowed to 0 keeps
    its sign).  ``POW[-2, 0.3 / 0.1]``: the double 2.9999999999999996 is the alarm, its 15 digits -8.  The
    power itself is the doubles' (``math.pow``), as the other arithmetic is.
    """
    x, y = a[0], b[0]
    if x < 0.0:
        case = _pow_exponent_fast(b, again_b is None)
        if case is not None:
            if case in _POW_ALARMS:
                raise _pow_alarm(x, y, case)
            return
        signs = [-1]
    else:
        signs = sorted({(r > 0) - (r < 0) for _name, r in _value_readings(again_a() if again_a is not None else a)})
    got = [(f"{name} with a {_SIGN_NAMES[s]} base", _pow_case(s, r)) for s in signs
           for name, r in _value_readings(again_b() if again_b is not None else b)]
    cases = {case for _name, case in got}
    if len(cases) > 1:
        shown = "; ".join(f"{name} gives {case}" for name, case in got)
        raise ReadingsSplit(f"POW: the readings of the exponent {y!r} of the base {x!r} give different results: "
                            f"{shown}; which reading the control takes is not known (specs/fanuc.md, \"A value at "
                            "half an increment\")")
    case = cases.pop()
    if case in _POW_ALARMS:
        raise _pow_alarm(x, y, case)


_SIGN_NAMES = {-1: "negative", 0: "zero", 1: "positive"}


# -- the spread of a libm result (libm40) --------------------------------------------------------------------------


class SpreadDouble(float):
    """A macro double that came from SIN, COS, TAN, ATAN, ASIN, ACOS, LN, EXP or POW (or from arithmetic on
    such a result): the double nczones computes with CPython's library, and ``lo``/``hi``, the least and the
    greatest double the control can hold there (specs/fanuc.md, "Results of the library functions").

    A control's library is taken to give CPython's result or one of its two neighbours (``math.nextafter``);
    the spread is carried through ``+ - * /``, NEG, ABS, SQRT, ADP and further functions, and every decision and
    address takes a result only where every double of the spread gives it (:func:`_spread_integer`,
    :func:`_spread_related`, :func:`_spread_round`; GC396 and GC397 where not).  A value of plain class
    ``float`` carries no spread: the control computes that double itself (IEEE ``+ - * /`` and SQRT are
    correctly rounded).  Its value is ``(SpreadDouble, None)``: no exact shadow (none is known).

    >>> v = _libm_value(0.49999999999999994, False); (v, v.lo, v.hi)
    (0.49999999999999994, 0.4999999999999999, 0.5)
    """

    __slots__ = ("lo", "hi")
    lo: float
    hi: float


class LibmSplit(ReadingsSplit):
    """A decision (GC396) or an address (GC397) that the doubles of a libm result's spread take differently
    (:class:`SpreadDouble`): the verdict is ``unknown`` at the line, as for :class:`ReadingsSplit`."""

    def __init__(self, code: str, reason: str):
        SystemVariableUnknown.__init__(self, code, reason)


_INF = math.inf
_nextafter = math.nextafter
#: At most this many doubles of an argument's spread are given to a library function one by one
#: (:func:`_candidates`); a wider spread is GC396.
_MAX_CANDIDATES = 64
_SPREAD_NOTE = ("which double a control's library gives is not known: CPython's or one of its neighbours "
                "(specs/fanuc.md, \"Results of the library functions\")")


def _spread(d: float, lo: float, hi: float) -> float:
    """``d`` (a plain double) with the spread ``lo..hi`` of the doubles the control can hold (``lo <= d <= hi``):
    ``d`` itself where that is one double; GC396 where a neighbour overflows (the control may alarm)."""
    if lo == hi:
        return d
    if not (-_INF < lo and hi < _INF):
        raise LibmSplit("GC396", f"a result {d!r} whose neighbours reach {lo!r} .. {hi!r} (an overflow there, "
                        f"an alarm); {_SPREAD_NOTE}")
    s = SpreadDouble(d)
    s.lo, s.hi = lo, hi
    return s


def _libm_value(c: float, exact: bool) -> float:
    """CPython's library result ``c`` as the control's: ``c`` where the function's true value is known to be
    ``c`` (``exact``: SIN of 0, COS of 0, EXP of 0, LN of 1, an exact power ...; a library whose error is below
    one ulp gives a double that is the true value), else ``c`` with its two neighbours."""
    if exact:
        return c
    return _spread(c, _nextafter(c, -_INF), _nextafter(c, _INF))


#: ``c * _NEIGHBOUR`` (:func:`neighbours`): just over half an ulp of ``c``, below one and a 2**-53 part of it.
_NEIGHBOUR = 2.0**-53 + 2.0**-105
#: Below this magnitude ``c * _NEIGHBOUR`` would be subnormal (inexact): :func:`neighbours` takes nextafter.
_NEIGHBOUR_SMALL = 2.0**-969


def neighbours(c: float) -> tuple[float, float]:
    """The two doubles next to ``c`` (below, above), as ``math.nextafter`` gives them, in three floating-point
    operations where ``|c|`` is at least 2**-969 and at most 1 (a SIN/COS result: the libm spread's hot path).

    Soundness (exactly the neighbours, so the spread is the one libm40 defined): for ``c`` in ``[2**e,
    2**(e+1))`` with ulp ``u = 2**(e-52)``, ``c * K`` with ``K = 2**-53 + 2**-105`` is ``c 2**-53`` (a double:
    no underflow above 2**-969) plus ``c 2**-105``, one to two ulps ``v = u 2**-53`` of it, so the rounded
    ``e = fl(c K)`` lies in ``[c 2**-53 + v, c 2**-53 + 2v]``: above ``u / 2`` (``c >= 2**e``) and at most
    ``u + v`` (``c 2**-53 <= u - v``).  ``c + e`` is then past the midpoint ``c + u/2`` and within ``v`` of
    ``c + u``: it rounds to ``c + u``, the next double (also where that is ``2**(e+1)``: the spacing there is
    ``2u``).  ``c - e`` lies in ``[c - u - v, c - u/2)``: below a ``c`` that is not a power of two the spacing
    is ``u`` and it rounds to ``c - u``; at ``c = 2**e`` the spacing below is ``u/2``, ``e`` is exactly
    ``u/2 + v`` and ``c - e`` rounds to ``c - u/2``.  A negative ``c`` is the mirror image (rounding to nearest
    is symmetric).  tests/gcode/fanuc/test_spread_carry.py compares it with ``math.nextafter``.

    >>> neighbours(1.0), neighbours(-0.49999999999999994)
    ((0.9999999999999999, 1.0000000000000002), (-0.5, -0.4999999999999999))
    """
    if -_NEIGHBOUR_SMALL < c < _NEIGHBOUR_SMALL or not -1.0 <= c <= 1.0:
        return _nextafter(c, -_INF), _nextafter(c, _INF)
    e = c * _NEIGHBOUR
    return (c - e, c + e) if c > 0.0 else (c + e, c - e)


def _bounds(d: float) -> tuple[float, float]:
    """``(lo, hi)`` of a double: its spread, or the double twice."""
    if d.__class__ is SpreadDouble:
        return d.lo, d.hi
    return d, d


def _spread_binary(op: str, a: float, b: float, d: float) -> float:
    """``a op b`` (+ - * /, ``d`` the double computed of ``a`` and ``b``) with the spread of every double the
    control can compute from the doubles of ``a``'s and ``b``'s spreads (:data:`_SPREAD_OPS`).

    Soundness: IEEE rounding to nearest is non-decreasing, so the control's ``fl(x op y)`` lies between
    ``fl`` of the least and of the greatest exact ``x op y`` over the two intervals, and those are at their
    corners (``+ -``: monotone in each operand; ``* /``: bilinear, or monotone in each operand on a box whose
    divisors do not cross 0); the corners computed here in doubles are those very ``fl`` values.  A divisor
    whose spread reaches 0 is GC396 (the control may alarm, GC311)."""
    return _SPREAD_OPS[op](a, b, d)


def _spread_add(a: float, b: float, d: float) -> float:
    """``a + b`` with its spread (:func:`_spread_binary`): the sums of the least and of the greatest ends."""
    if b.__class__ is not SpreadDouble:  # a carries the spread
        p, r = a.lo + b, a.hi + b  # type: ignore[attr-defined]
    elif a.__class__ is not SpreadDouble:
        p, r = a + b.lo, a + b.hi
    else:
        p, r = a.lo + b.lo, a.hi + b.hi
    if p < r and -_INF < p and r < _INF:  # (_spread inline)
        s = SpreadDouble(d)
        s.lo, s.hi = p, r
        return s
    return _spread(d, p, r)


def _spread_sub(a: float, b: float, d: float) -> float:
    """``a - b`` with its spread (:func:`_spread_binary`): least minus greatest, greatest minus least."""
    alo, ahi = _bounds(a)
    blo, bhi = _bounds(b)
    return _spread(d, alo - bhi, ahi - blo)


def _spread_mul(a: float, b: float, d: float) -> float:
    """``a * b`` with its spread (:func:`_spread_binary`): a plain factor scales the other's two ends (the
    product is monotone in the spread operand, its direction the plain factor's sign: sorted after), two
    spreads take the least and the greatest of the four corner products."""
    if b.__class__ is not SpreadDouble:  # a carries the spread, b is plain: two corners
        p, r = a.lo * b, a.hi * b  # type: ignore[attr-defined]
    elif a.__class__ is not SpreadDouble:
        p, r = a * b.lo, a * b.hi
    else:
        alo, ahi, blo, bhi = a.lo, a.hi, b.lo, b.hi
        corners = (alo * blo, alo * bhi, ahi * blo, ahi * bhi)
        return _spread(d, min(corners), max(corners))
    if p > r:
        p, r = r, p
    if p < r and -_INF < p and r < _INF:  # (_spread inline)
        s = SpreadDouble(d)
        s.lo, s.hi = p, r
        return s
    return _spread(d, p, r)


def _spread_div(a: float, b: float, d: float) -> float:
    """``a / b`` with its spread (:func:`_spread_binary`): the four corner quotients, the divisor's spread not
    reaching 0 (GC396 where it does)."""
    alo, ahi = _bounds(a)
    blo, bhi = _bounds(b)
    if blo <= 0.0 <= bhi:
        raise LibmSplit("GC396", f"a divisor {b!r} whose spread {blo!r} .. {bhi!r} reaches 0 (an alarm there, "
                        f"GC311); {_SPREAD_NOTE}")
    corners = (alo / blo, alo / bhi, ahi / blo, ahi / bhi)
    return _spread(d, min(corners), max(corners))


#: ``+ - * /`` of operands one at least with a spread (:func:`_spread_binary`).
_SPREAD_OPS: dict[str, Callable[[float, float, float], float]] = {
    "+": _spread_add, "-": _spread_sub, "*": _spread_mul, "/": _spread_div}


def _spread_arithmetic(op: str, x: Value, y: Value) -> Value:
    """``x op y`` (+ - * /) of values one of which at least carries a spread: the double as
    :func:`nczones.gcode.expr.binary_op` computes it, no shadow, the spread of :func:`_spread_binary`."""
    a, b = x[0], y[0]
    if op == "/" and b == 0.0:
        _zero_divisor(b)
    d = check_double(float(_PLAIN_OPS[op](a, b)))
    return (_spread_binary(op, a, b, d), None)


_PLAIN_OPS: dict[str, Callable[[float, float], float]] = {
    "+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv}


def _zero_divisor(b: float) -> None:
    """A divisor whose double is 0: the alarm (GC311), or GC396 where its spread holds other doubles."""
    lo, hi = _bounds(b)
    if lo != hi:
        raise LibmSplit("GC396", f"a divisor 0.0 whose spread {lo!r} .. {hi!r} holds other doubles (an alarm for "
                        f"0 only, GC311); {_SPREAD_NOTE}")
    raise EvalError("GC311", "attempt to divide by zero")


def _negative(value: Value) -> Value:
    """NEG of a value with a spread."""
    d = value[0]
    lo, hi = _bounds(d)
    return (_spread(-float(d), -hi, -lo), None)


def _absolute(value: Value) -> Value:
    """ABS of a value with a spread (``|x|`` is exact)."""
    d = value[0]
    lo, hi = _bounds(d)
    if lo >= 0.0:
        return (_spread(abs(float(d)), lo, hi), None)
    if hi <= 0.0:
        return (_spread(abs(float(d)), -hi, -lo), None)
    return (_spread(abs(float(d)), 0.0, max(-lo, hi)), None)


def _square_root(value: Value) -> Value:
    """SQRT of a value with a spread: IEEE's square root is correctly rounded, so non-decreasing: the spread's
    ends' roots bound every root; a spread reaching below 0 is the alarm (GC312) for some doubles only."""
    d = value[0]
    lo, hi = _bounds(d)
    if lo < 0.0:
        if hi < 0.0:
            raise EvalError("GC312", f"negative argument to SQRT: {float(d)!r}")
        raise LibmSplit("GC396", f"SQRT of {float(d)!r} whose spread {lo!r} .. {hi!r} reaches below 0 (an alarm "
                        f"there, GC312); {_SPREAD_NOTE}")
    return (_spread(math.sqrt(d), math.sqrt(lo), math.sqrt(hi)), None)


def _candidates(d: float, what: str) -> list[float]:
    """Every double of ``d``'s spread, in order (at most :data:`_MAX_CANDIDATES`, else GC396)."""
    lo, hi = _bounds(d)
    out = [lo]
    c = lo
    while c < hi:
        if len(out) >= _MAX_CANDIDATES:
            raise LibmSplit("GC396", f"{what} of {float(d)!r}, which could be any of more than {_MAX_CANDIDATES} "
                            f"doubles from {lo!r} to {hi!r}; {_SPREAD_NOTE}")
        c = _nextafter(c, _INF)
        out.append(c)
    return out


def _over_spread(what: str, fn: Callable[..., Value], *args: float) -> Value:
    """``fn`` (a library function of plain doubles giving a value) of arguments one of which at least carries
    a spread: the double of ``fn`` of the arguments' own doubles, with the spread of every result over every
    combination of their doubles (:func:`_candidates`); an alarm for some of them only is GC396."""
    combos: list[tuple[float, ...]] = [()]
    for a in args:
        combos = [c + (x,) for c in combos for x in _candidates(a, what)]
        if len(combos) > 4 * _MAX_CANDIDATES:
            raise LibmSplit("GC396", f"{what} of arguments whose spreads hold more than {4 * _MAX_CANDIDATES} "
                            f"combinations of doubles; {_SPREAD_NOTE}")
    lows, highs, alarms = [], [], []
    for combo in combos:
        try:
            lo, hi = _bounds(fn(*combo)[0])
        except EvalError as e:
            alarms.append((combo, e))
            continue
        lows.append(lo)
        highs.append(hi)
    if alarms:
        if lows:
            first, alarm = alarms[0]
            raise LibmSplit("GC396", f"{what}: the doubles {', '.join(map(repr, first))} of the arguments' spreads "
                            f"give an alarm ({alarm.message}), others a result; {_SPREAD_NOTE}")
        fn(*(float(a) for a in args))  # every double alarms, the arguments' own too: that alarm, as without a spread
        raise alarms[0][1]  # pragma: no cover (the own doubles are among the combinations)
    mine = fn(*(float(a) for a in args))
    lo, hi = min(lows), max(highs)
    if lo == hi:
        return mine  # one double for every combination: the value as the plain arguments give it
    return (_spread(float(mine[0]), lo, hi), None)


def _spread_integer(value: Value, kind: str, what: str) -> int:
    """The integer FIX/FUP/ROUND (:data:`_INTEGER_OF` ``kind``) takes of a value with a spread, the same for
    every reading of every double of the spread; else :class:`LibmSplit` (GC396).

    Soundness: each reading (the double, its 15-digit decimal) is non-decreasing in the double, and so is each
    kind's integer of a reading (towards zero, away from zero, nearest with halves away: all non-decreasing),
    so every double of ``lo..hi`` gives an integer between the least that ``lo``'s readings give and the
    greatest that ``hi``'s give."""
    d = value[0]
    lo, hi = _bounds(d)
    got = [(f"the least double {lo!r}, {name}", n) for name, n in _integer_readings((lo, None), kind)] + [
        (f"the greatest double {hi!r}, {name}", n) for name, n in _integer_readings((hi, None), kind)]
    if len({n for _name, n in got}) == 1:
        return got[0][1]
    _agreed_integer((float(d), None), kind, what)  # GC398 where the double's own readings part already
    shown = "; ".join(f"{name} gives {n}" for name, n in got)
    raise LibmSplit("GC396", f"{what}: a result of SIN/COS/TAN/ATAN/ASIN/ACOS/LN/EXP/POW, {float(d)!r}, whose one-ulp "
                    f"neighbours give a different integer: {shown}; {_SPREAD_NOTE}")


def _spread_related(op: str, x: Value, y: Value) -> Value:
    """``x op y`` (EQ NE GT GE LT LE) where one operand at least carries a spread: the truth every double of
    the spreads gives in every reading (the doubles as they are, their 15-digit decimals), else
    :class:`LibmSplit` (GC396).

    Soundness: both readings are non-decreasing in the double, so over the spreads the left operand's readings
    lie in ``[r(xlo), r(xhi)]`` and the right's in ``[r(ylo), r(yhi)]``: "below" can happen only where
    ``r(xlo) < r(yhi)``, "above" only where ``r(xhi) > r(ylo)``, "equal" only where the two meet; a truth
    is given only where every outcome that can happen gives it."""
    test = _RELATIONS[op][2]
    xlo, xhi = _bounds(x[0])
    ylo, yhi = _bounds(y[0])
    truths = set()
    shown = []
    for name, read in (("the doubles as they are", Fraction), ("their 15-digit decimals", _fifteen)):
        a0, a1, b0, b1 = read(xlo), read(xhi), read(ylo), read(yhi)
        outcomes = []
        if a0 < b1:
            outcomes.append(test(0, 1))
        if a0 <= b1 and b0 <= a1:
            outcomes.append(test(0, 0))
        if a1 > b0:
            outcomes.append(test(1, 0))
        truths.update(outcomes)
        shown.append(f"{name} ({_decimal(a0)} .. {_decimal(a1)} and {_decimal(b0)} .. {_decimal(b1)}): "
                     + " or ".join(sorted({"true" if t else "false" for t in outcomes})))
    if len(truths) == 1:
        return _TRUE if truths.pop() else _FALSE
    _related(op, _plain(x), _plain(y))  # GC398 where the doubles' own readings part already
    raise LibmSplit("GC396", f"{op.upper()}: a result of SIN/COS/TAN/ATAN/ASIN/ACOS/LN/EXP/POW whose one-ulp neighbours "
                    f"compare differently: {float(x[0])!r} and {float(y[0])!r}; {'; '.join(shown)}; {_SPREAD_NOTE}")


def _plain(value: Value) -> Value:
    """A value's own double without its spread (the readings of that double alone)."""
    d = value[0]
    return (float(d), value[1]) if d.__class__ is SpreadDouble else value


def _fast_multiple(c: float, sd: int) -> int | None:
    """:func:`round_to`'s test in doubles for one double ``c`` and a step ``1 / sd``: the multiple every reading
    of ``c`` rounds to, or None where the exact path must decide."""
    x = abs(c) * sd
    if x < _FAST_INCREMENTS:
        m = _floor(x)
        frac = x - m
        if not _NEAR_HALF_LOW < frac < _NEAR_HALF_HIGH and (x < _WIDE_INCREMENTS or abs(frac - 0.5) > x * _WINDOW):
            n = m + 1 if frac > 0.5 else m
            return -n if c < 0 else n
    return None


def _spread_round(value: Value, step: Fraction, sn: int, sd: int) -> Fraction:
    """:func:`round_to` of a value with a spread: the multiple of ``step`` every reading of every double of the
    spread rounds to, else :class:`LibmSplit` (GC397).

    Soundness: the readings of :func:`readings` (the 15-digit decimal, the double scaled in doubles) are
    non-decreasing in the double, and so is rounding with halves away from zero, so every double of
    ``lo..hi`` rounds between where ``lo``'s readings and ``hi``'s round; where the test in doubles decides
    both ends alike (:func:`_fast_multiple`) so do all their readings."""
    d = value[0]
    lo, hi = d.lo, d.hi  # (d carries a spread; sn / sd: step's ratio)
    if sn == 1:
        # round_to's test in doubles with the window grown by twice the spread's width in increments: every
        # double of the spread lies within (hi - lo) sd increments of d (the factor 2 covers the rounding of it)
        x = abs(d) * sd
        if x < _FAST_INCREMENTS:
            m = _floor(x)
            frac = x - m
            if abs(frac - 0.5) > max(2.0**-20, x * _WINDOW) + 2.0 * (hi - lo) * sd:
                n = m + 1 if frac > 0.5 else m
                return to_fraction(-n if d < 0 else n, sd)
        n = _fast_multiple(lo, sd)
        if n is not None and n == _fast_multiple(hi, sd):
            return to_fraction(n, sd)
    got = [(f"the least double {lo!r}: {name}", _half_away(r, step)) for name, r in readings((lo, None), step)] + [
        (f"the greatest double {hi!r}: {name}", _half_away(r, step)) for name, r in readings((hi, None), step)]
    if len({m for _name, m in got}) == 1:
        return got[0][1]
    _agreed((float(d), None), step)  # GC399 where the double's own readings part already
    shown = "; ".join(f"{name} rounds to {_decimal(m)}" for name, m in got)
    raise LibmSplit("GC397", f"a result of SIN/COS/TAN/ATAN/ASIN/ACOS/LN/EXP/POW, {float(d)!r}, at half an increment "
                    f"({_decimal(step)}) whose one-ulp neighbours round to different increments: {shown}; "
                    f"{_SPREAD_NOTE}")


def value_as_is(value: Value, what: str) -> Fraction:
    """The exact value an address takes as it is (F, E, G51's factors, a count): the shadow, else the double's
    exact value; GC397 for a value with a spread (which of its doubles the control holds is not known)."""
    q: Fraction | None = value[1]
    if q is not None:
        return q
    d = value[0]
    if d.__class__ is SpreadDouble:
        lo, hi = _bounds(d)
        raise LibmSplit("GC397", f"{what}: a result of SIN/COS/TAN/ATAN/ASIN/ACOS/LN/EXP/POW, {float(d)!r}, taken as "
                        f"it is, could be any double from {lo!r} to {hi!r}; {_SPREAD_NOTE}")
    return Fraction(d)


def compile_tree(node: tuple, variables: FanucVariables, ctx: Context | None = None,
                 in_address: bool = False, exact: bool = True) -> Callable[[], Value]:
    """A function of no arguments that evaluates the tree with these variables (read when called).

    ``in_address``: the tree is the value of an NC address (``ROUND`` then rounds to the address's
    increment).  ``exact=False``: the caller reads only the double of the value (a condition of ``IF`` or
    ``WHILE``): the arithmetic then computes no exact shadow, which no operation reads from an operand of a
    comparison, of ``EQ``/``NE``/``MOD``/``AND``/``OR``/``XOR``, of a function other than ``ABS``/``ROUND``/``ADP``
    or of ``ATAN``/``POW`` of two arguments either: those operands are compiled so (the same doubles, checked
    for NaN and infinity in the same order, so the same values and errors; a variable is read as it is, so a
    vacant one stays :data:`VACANT` for ``EQ``/``NE``).  Where FIX/FUP/BIN/BCD, a relation, MOD/AND/OR/XOR,
    POW (its exponent, a zero base) or ASIN/ACOS must compare the readings of such an operand (near a split
    only) it is evaluated again with its shadow (:func:`_again`).
    """
    ctx = ctx or Context()
    tag = node[0]
    if tag == NUM:
        value = (node[1], node[2])
        return lambda: value
    if tag == VAR:
        index = node[1]
        n = literal_number(index)
        if n is not None:
            if 0 < n <= LOCALS:
                return lambda: variables.local[n]
            if COMMON_FIRST <= n <= COMMON_LAST:
                common = variables.common
                return lambda: common[n]
            return lambda: variables.read(n)
        inner = compile_tree(index, variables, ctx)
        return lambda: variables.read(variable_number(inner()))
    if tag == NEG:
        inner = compile_tree(node[1], variables, ctx, in_address, exact)
        if not exact:
            def neg_double() -> Value:
                d = inner()[0]
                if d.__class__ is SpreadDouble:
                    return _negative((d, None))
                return (-d, None)
            return neg_double

        def neg():
            x = inner()
            d, q = x
            if q is None:
                if d.__class__ is SpreadDouble:
                    return _negative(x)
                return (-d, None)
            n, den = _ratio(q)
            return (-d, _negated(n, den))
        return neg
    if tag == BIN:
        return _compile_binary(node, variables, ctx, in_address, exact)
    if tag == FN:
        name = node[1]
        # ABS keeps its operand's shadow, ROUND rounds it (in an address), ADP multiplies it: the others read the
        # double only
        arg = compile_tree(node[2], variables, ctx, in_address, (exact or name != "abs") and name in _SHADOW_FUNCTIONS)
        trig = _TRIGONOMETRY.get(name)
        if trig is not None:
            return _trigonometric(name, trig, arg)
        if name in ("asin", "acos"):
            return _arc_function(name, arg, _again(node[2], variables, ctx, in_address), ctx)
        if name in _INTEGER_FUNCTIONS and not (name == "round" and in_address):
            # ROUND's operand carries its shadow already; the others' is computed again only near a split
            again = None if name == "round" else _again(node[2], variables, ctx, in_address)
            return _integer_function(name, arg, again)
        return lambda: _function(name, arg(), ctx, in_address)
    if tag == FN2:
        a = compile_tree(node[2], variables, ctx, in_address, False)
        b = compile_tree(node[3], variables, ctx, in_address, False)
        if node[1] == "atan":
            return lambda: _atan2(a()[0], b()[0], ctx)
        again_a = _again(node[2], variables, ctx, in_address)
        again_b = _again(node[3], variables, ctx, in_address)
        return lambda: _pow(a(), b(), again_a, again_b)
    raise AssertionError(f"unknown expression node {node!r}")  # pragma: no cover


#: The functions whose result reads the operand's exact shadow (:func:`_function`).
_SHADOW_FUNCTIONS = frozenset(("abs", "round", "adp"))
#: SIN and COS: :func:`_function`'s cases without its dispatch (:func:`_trigonometric`).
_TRIGONOMETRY = {"sin": math.sin, "cos": math.cos}


def _again(node: tuple, variables: FanucVariables, ctx: Context, in_address: bool) -> Callable[[], Value] | None:
    """A function that evaluates ``node`` again with its exact shadow (compiled at its first call), for an
    operand compiled without it (``exact=False``) whose readings must be compared; None for a number or a
    variable (their value carries its shadow as it is)."""
    if node[0] in (NUM, VAR):
        return None
    compiled: list[Callable[[], Value]] = []

    def again() -> Value:
        if not compiled:
            compiled.append(compile_tree(node, variables, ctx, in_address, True))
        return compiled[0]()
    return again


def _integer_function(name: str, arg: Callable[[], Value], again: Callable[[], Value] | None) -> Callable[[], Value]:
    """FIX, FUP, ROUND (outside an address), BCD or BIN of ``arg``: the integer every reading of the operand
    gives (:func:`integer_of`: decided in doubles away from where readings part), GC398 where they differ."""
    kind, make = _INTEGER_FUNCTIONS[name]
    upper = name.upper()

    def integer_function() -> Value:
        value = arg()
        d = value[0]
        if d - d:
            raise EvalError("GC312", f"argument to {upper} is {d!r}")
        if d.__class__ is SpreadDouble:
            return make(_spread_integer(value, kind, f"{upper}[...]"), float(d))
        n = _integer_fast(value, kind)
        if n is None:
            n = _agreed_integer(again() if again is not None else value, kind, f"{upper}[...]")
        return make(n, d)
    return integer_function


def _trigonometric(name: str, fn: Callable[[float], float], arg: Callable[[], Value]) -> Callable[[], Value]:
    """``SIN[arg]`` or ``COS[arg]`` as :func:`_function` computes them (degrees; a NaN or infinite argument
    is the same error)."""
    upper = name.upper()

    def trig() -> Value:
        d = arg()[0]
        if d.__class__ is SpreadDouble or d == 0.0:
            return _trigonometric_value(name, fn, upper, d)
        r = d * math.pi / 180.0
        if r - r:  # NaN or infinite, or radians that overflow
            _radians(d, upper)
        c = fn(r)
        s = SpreadDouble(c)  # (_libm_value inline: |c| <= 1, its neighbours are finite)
        if -_NEIGHBOUR_SMALL < c < _NEIGHBOUR_SMALL:
            s.lo, s.hi = _nextafter(c, -_INF), _nextafter(c, _INF)
        else:  # (neighbours inline)
            e = c * _NEIGHBOUR
            s.lo, s.hi = (c - e, c + e) if c > 0.0 else (c + e, c - e)
        return (s, None)
    return trig


def _trigonometric_value(name: str, fn: Callable[[float], float], upper: str, d: float) -> Value:
    """SIN or COS (``fn``, ``upper`` its name) of ``d`` degrees with its spread (none at 0)."""
    if d.__class__ is SpreadDouble:
        return _over_spread(upper, lambda c: _circular(name, c), d)
    r = d * math.pi / 180.0
    if r - r:  # NaN or infinite, or radians that overflow
        _radians(d, upper)
    c = fn(r)
    if d == 0.0:  # SIN of 0 is 0, COS of 0 is 1: exactly (_libm_value)
        return (c, None)
    s = SpreadDouble(c)  # (_libm_value inline: |c| <= 1, its neighbours are finite)
    s.lo, s.hi = _nextafter(c, -_INF), _nextafter(c, _INF)
    return (s, None)


def _compile_polar(node: tuple, variables: FanucVariables, ctx: Context,
                   in_address: bool) -> Callable[[], Value] | None:
    """``r * SIN[t]`` or ``r * COS[t]`` (a radius times the sine or cosine of an angle: bolt circles, spirals)
    as one closure, else None.  The product of the trigonometric function's result (no shadow, a spread) has no
    shadow, so ``r`` is compiled for its double only; the same operations in the same order as the two closures
    (:func:`_trigonometric`, then ``*``: ``r`` read first, the angle's errors next) give the same value, without
    building the function's spread as a value: for a plain ``r`` and a plain angle other than 0 the product's
    spread is ``r`` times the result's two neighbours (:func:`_spread_mul`, sorted: multiplying by ``r`` is
    monotone), anything else goes through :func:`_trigonometric`'s value and :func:`_spread_mul`."""
    right = node[3]
    if right[0] != FN or right[1] not in _TRIGONOMETRY:
        return None
    name = right[1]
    fn = _TRIGONOMETRY[name]
    upper = name.upper()
    left = compile_tree(node[2], variables, ctx, in_address, False)
    angle = compile_tree(right[2], variables, ctx, in_address, False)
    pi, spread, small, k, inf = math.pi, SpreadDouble, _NEIGHBOUR_SMALL, _NEIGHBOUR, _INF  # (closure cells)
    minus_small, minus_inf = -small, -inf

    def polar() -> Value:
        a = left()[0]
        t = angle()[0]
        if t.__class__ is spread or a.__class__ is spread or t == 0.0:
            return _product(a, _trigonometric_value(name, fn, upper, t)[0])
        r = t * pi / 180.0
        if r - r:  # NaN or infinite, or radians that overflow
            _radians(t, upper)
        c = fn(r)
        d = a * c
        if d - d:
            check_double(d)
        if minus_small < c < small:
            p, q = a * _nextafter(c, minus_inf), a * _nextafter(c, inf)
        else:  # (neighbours inline: c - e and c + e are c's two neighbours)
            e = c * k
            p, q = a * (c - e), a * (c + e)
        if p > q:
            p, q = q, p
        if p < q and minus_inf < p and q < inf:  # (_spread inline)
            s = spread(d)
            s.lo, s.hi = p, q
            return (s, None)
        return (_spread(d, p, q), None)
    return polar


def _product(a: float, b: float) -> Value:
    """``a * b`` of two doubles without shadows (:func:`_double_arithmetic`'s ``mul``), a spread carried."""
    d = a * b
    if d - d:
        check_double(d)
    if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
        return (_spread_mul(a, b, d), None)
    return (d, None)


def _compile_binary(node: tuple, variables: FanucVariables, ctx: Context, in_address: bool,
                    exact: bool) -> Callable[[], Value]:
    """:func:`compile_tree` of a ``BIN`` node."""
    op = node[1]
    if op in _RELATIONS:
        return _compile_relation(op, node, variables, ctx, in_address)
    if op in _INTEGER_BINARY:
        return _compile_integer_binary(op, node, variables, ctx, in_address)
    if op == "*":
        polar = _compile_polar(node, variables, ctx, in_address)
        if polar is not None:
            return polar
    # + - * / read their operands' shadows (only for a caller that reads the result's)
    inner_exact = exact
    if node[3][0] == NUM and _SLOTS:
        n = _local_index(node[2])
        if n is not None:  # a local variable and a number (#1 + 1, #1 * 0.01): no call for either
            local = _local_constant(op, variables, n, (node[3][1], node[3][2]), exact)
            if local is not None:
                return local
    left = compile_tree(node[2], variables, ctx, in_address, inner_exact)
    if node[3][0] == NUM and _SLOTS:  # a number on the right (#1 + 1, #2 / 2): no call for it
        const = (node[3][1], node[3][2])
        fast = _with_constant(op, left, const) if exact else _double_constant(op, left, const[0])
        if fast is not None:
            return fast
    right = compile_tree(node[3], variables, ctx, in_address, inner_exact)
    if not exact:
        return _double_arithmetic(op, left, right)
    if _SLOTS:
        return _arithmetic(op, left, right)
    return lambda: _generic_arithmetic(op, left(), right())


#: Per relation: its value when every reading has the left operand below the right, when every reading has
#: it above, and the test on exact readings (:func:`_related`).
_RELATIONS: dict[str, tuple[Value, Value, Callable[[Any, Any], bool]]] = {
    "lt": (_TRUE, _FALSE, operator.lt), "le": (_TRUE, _FALSE, operator.le), "gt": (_FALSE, _TRUE, operator.gt),
    "ge": (_FALSE, _TRUE, operator.ge), "eq": (_FALSE, _FALSE, operator.eq), "ne": (_TRUE, _TRUE, operator.ne)}


def _compile_relation(op: str, node: tuple, variables: FanucVariables, ctx: Context,
                      in_address: bool) -> Callable[[], Value]:
    """EQ NE GT GE LT LE: the doubles compared (vacant is 0, and differs from 0 in EQ/NE), the result the same
    in every reading of the operands (:func:`_related`; GC398 where not).  Decided in doubles where the
    operands are farther apart than the readings reach (:func:`_certain_bounds` for a number on the right:
    one more comparison than the plain test), so a WHILE condition costs about what it did.  A value with a
    spread against a number is decided on the spread's ends where all of it lies beyond a bound (every double
    of it then does: the ends are the least and the greatest), else by :func:`_spread_related`."""
    below, above, _test = _RELATIONS[op]
    vacancy = op in ("eq", "ne")
    again_a = _again(node[2], variables, ctx, in_address)
    if node[3][0] == NUM:
        const = (node[3][1], node[3][2])
        lo, hi = _certain_bounds(const)
        n = None if vacancy else _local_index(node[2])
        if n is not None:  # a local variable and a number (#1 LT 10): read in the closure
            return _local_relation(op, variables, n, const)
        left = compile_tree(node[2], variables, ctx, in_address, False)

        def relation_constant() -> Value:
            x = left()
            if x is VACANT and vacancy:
                return above  # a vacant value differs from a number (EQ false, NE true)
            a = x[0]
            if a.__class__ is SpreadDouble:  # (as in local_relation)
                if a.hi < lo:
                    return below
                if a.lo > hi:
                    return above
                return _spread_related(op, x, const)
            if a < lo:
                return below
            if a > hi:
                return above
            return _related(op, again_a() if again_a is not None else x, const)
        return relation_constant
    left = compile_tree(node[2], variables, ctx, in_address, False)
    right = compile_tree(node[3], variables, ctx, in_address, False)
    again_b = _again(node[3], variables, ctx, in_address)
    equal = op == "eq"

    def relation() -> Value:
        x = left()
        y = right()
        if vacancy and (x is VACANT or y is VACANT):
            return _TRUE if (x is VACANT and y is VACANT) == equal else _FALSE
        a, b = x[0], y[0]
        if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
            return _spread_pair(op, x, y)
        diff = a - b
        m = (abs(a) + abs(b)) * _WINDOW_READINGS + _TINY
        if diff > m:
            return above
        if diff < -m:
            return below
        return _related(op, again_a() if again_a is not None else x, again_b() if again_b is not None else y)
    return relation


def _local_relation(op: str, variables: FanucVariables, n: int, const: Value) -> Callable[[], Value]:
    """``#n op const`` (:func:`_compile_relation`) for a local variable ``n`` and a number: read in the closure;
    a value with a spread decided on its ends where all of it lies beyond a bound."""
    below, above, _test = _RELATIONS[op]
    lo, hi = _certain_bounds(const)

    def local_relation() -> Value:
        x = variables.local[n]
        a = x[0]
        if a.__class__ is SpreadDouble:  # all of the spread beyond a bound: every double of it is
            if a.hi < lo:
                return below
            if a.lo > hi:
                return above
            return _spread_related(op, x, const)
        if a < lo:
            return below
        if a > hi:
            return above
        return _related(op, variables.local[n], const)
    return local_relation


def _spread_pair(op: str, x: Value, y: Value) -> Value:
    """A relation of two values one at least with a spread: decided on the spreads' ends where they are farther
    apart than the readings reach (as ``relation`` does for two doubles), else :func:`_spread_related`."""
    below, above, _test = _RELATIONS[op]
    alo, ahi = _bounds(x[0])
    blo, bhi = _bounds(y[0])
    m = (max(-alo, ahi) + max(-blo, bhi)) * _WINDOW_READINGS + _TINY
    if alo - bhi > m:
        return above
    if ahi - blo < -m:
        return below
    return _spread_related(op, x, y)


def _operand_integer(value: Value, kind: str, what: str, again: Callable[[], Value] | None) -> int:
    """The integer MOD/AND/OR/XOR take of one operand, the same in every reading (:func:`integer_of`), each
    operand on its own: used where one operand carries a spread."""
    return integer_of(value, kind, what, again)


def _compile_integer_binary(op: str, node: tuple, variables: FanucVariables, ctx: Context,
                            in_address: bool) -> Callable[[], Value]:
    """MOD, AND, OR, XOR (:data:`_INTEGER_BINARY`): the integers the operands are taken as decided in doubles
    (:func:`_integer_fast`), else under every reading pair (:func:`_agreed_binary`; GC398 where they differ)."""
    kind, fn = _INTEGER_BINARY[op]
    upper = op.upper()
    left = compile_tree(node[2], variables, ctx, in_address, False)
    right = compile_tree(node[3], variables, ctx, in_address, False)
    again_a = _again(node[2], variables, ctx, in_address)
    again_b = _again(node[3], variables, ctx, in_address)

    def integer_binary() -> Value:
        x = left()
        y = right()
        if x[0] - x[0]:
            _int_of(x[0], upper)
        if y[0] - y[0]:
            _int_of(y[0], upper)
        if x[0].__class__ is SpreadDouble or y[0].__class__ is SpreadDouble:
            return fn(_operand_integer(x, kind, upper, again_a), _operand_integer(y, kind, upper, again_b))
        i = _integer_fast(x, kind)
        j = _integer_fast(y, kind)
        if i is None or j is None:
            return _agreed_binary(op, again_a() if again_a is not None else x,
                                  again_b() if again_b is not None else y)
        return fn(i, j)
    return integer_binary


def _local_index(node: tuple) -> int | None:
    """``n`` of a ``#n`` node that reads local variable n (a number 1..33 written as a constant), else None."""
    if node[0] != VAR:
        return None
    n = literal_number(node[1])
    return n if n is not None and 0 < n <= LOCALS else None


def _local_constant(op: str, variables: FanucVariables, n: int, const: Value,
                    exact: bool) -> Callable[[], Value] | None:
    """``#n op const`` with ``#n`` a local variable, read in the closure (``variables.local``: the call level's
    at each call) instead of through a closure of its own: ``+`` and ``*`` (as
    :func:`_with_constant`, and as :func:`_double_constant` when only the double is read); None for the others."""
    b, qb = const
    if qb is None or op not in ("+", "*"):
        return None
    if not exact:
        if op != "*":
            return None

        def mul_double() -> Value:
            a = variables.local[n][0]
            d = a * b
            if d - d:
                check_double(d)
            if a.__class__ is SpreadDouble:
                return (_spread_mul(a, b, d), None)
            return (d, None)
        return mul_double
    if op == "+":
        def add() -> Value:
            a, qa = variables.local[n]
            d = a + b
            if d - d:
                check_double(d)
            if qa is None:
                if a.__class__ is SpreadDouble:
                    return (_spread_add(a, b, d), None)
                return (d, None)
            q: Any = q_add(qa, qb)
            return (d, q) if q._numerator / q._denominator == d else (d, None)
        return add
    bn, bd = qb._numerator, qb._denominator

    def mul() -> Value:
        a, qa = variables.local[n]
        d = a * b
        if d - d:
            check_double(d)
        if qa is None:
            if a.__class__ is SpreadDouble:
                return (_spread_mul(a, b, d), None)
            return (d, None)
        m, den = qa._numerator * bn, qa._denominator * bd  # q_mul, built only when it rounds to the double
        return (d, to_fraction(m, den)) if m / den == d else (d, None)
    return mul


def _generic_arithmetic(op: str, x: Value, y: Value) -> Value:
    """:func:`binary_op` (Fractions without slots), a spread carried (:func:`_spread_arithmetic`)."""
    if x[0].__class__ is SpreadDouble or y[0].__class__ is SpreadDouble:
        return _spread_arithmetic(op, x, y)
    return binary_op(op, x, y)


def _double_arithmetic(op: str, left: Callable[[], Value], right: Callable[[], Value]) -> Callable[[], Value]:
    """``left op right`` for + - * / when only the double is read: :func:`_arithmetic` without the shadow (the same
    IEEE operation, operands read in the same order, the same checks; a spread carried, :func:`_spread_binary`)."""
    if op == "/":
        def div() -> Value:
            a = left()[0]
            b = right()[0]
            if b == 0.0:
                _zero_divisor(b)
            d = a / b
            if d - d:  # NaN or infinity (d - d is NaN for both, 0.0 otherwise)
                check_double(d)
            if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
                return (_spread_div(a, b, d), None)
            return (d, None)
        return div
    if op == "+":
        def add() -> Value:
            a = left()[0]
            b = right()[0]
            d = a + b
            if d - d:
                check_double(d)
            if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
                return (_spread_add(a, b, d), None)
            return (d, None)
        return add
    if op == "-":
        def sub() -> Value:
            a = left()[0]
            b = right()[0]
            d = a - b
            if d - d:
                check_double(d)
            if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
                return (_spread_sub(a, b, d), None)
            return (d, None)
        return sub

    def mul() -> Value:
        a = left()[0]
        b = right()[0]
        d = a * b
        if d - d:
            check_double(d)
        if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
            return (_spread_mul(a, b, d), None)
        return (d, None)
    return mul


def _double_constant(op: str, left: Callable[[], Value], b: float) -> Callable[[], Value] | None:
    """``left op b`` for + - * / (a divisor not 0) when only the double is read, else None."""
    if op == "/" and b == 0.0:
        return None
    fn, spread = _PLAIN_OPS[op], _SPREAD_OPS[op]

    def constant() -> Value:
        a = left()[0]
        d = fn(a, b)
        if d - d:
            check_double(d)
        if a.__class__ is SpreadDouble:
            return (spread(a, b, d), None)
        return (d, None)
    return constant


#: Whether Fractions are read through their slots (CPython): the arithmetic closures then inline
#: :func:`nczones.gcode.expr.binary_op` (the same operations in the same order, one call less per node).
_SLOTS = to_fraction is fraction_raw
_new = object.__new__


def _negated(n: int, den: int) -> Fraction:
    """``-Fraction(n, den)`` of a Fraction's own ``(n, den)`` (in lowest terms already: no gcd to take)."""
    if not _SLOTS:
        return to_fraction(-n, den)
    q: Fraction = _new(Fraction)
    q._numerator, q._denominator = -n, den  # type: ignore[attr-defined]
    return q


def _arithmetic(op: str, left: Callable[[], Value], right: Callable[[], Value]) -> Callable[[], Value]:
    """``left op right`` for + - * /: :func:`binary_op` inlined (bit-identical: the double is the same IEEE
    operation, checked for NaN/infinity the same way, the exact shadow kept only if it rounds to it; a spread
    carried where a shadow is missing, :func:`_spread_binary`)."""
    return _EXACT_ARITHMETIC[op](left, right)


def _exact_div(left: Callable[[], Value], right: Callable[[], Value]) -> Callable[[], Value]:
    def div() -> Value:
        a, qa = left()
        b, qb = right()
        if b == 0.0:
            _zero_divisor(b)
        d = a / b
        if d - d:  # NaN or infinity (d - d is NaN for both, 0.0 otherwise)
            check_double(d)
        if qa is None or qb is None or not qb._numerator:
            if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
                return (_spread_div(a, b, d), None)
            return (d, None)
        q: Any = q_div(qa, qb)
        return (d, q) if q._numerator / q._denominator == d else (d, None)
    return div


def _exact_add(left: Callable[[], Value], right: Callable[[], Value]) -> Callable[[], Value]:
    qop = q_add

    def add() -> Value:
        a, qa = left()
        b, qb = right()
        d = a + b
        if d - d:
            check_double(d)
        if qa is None or qb is None:
            if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
                return (_spread_add(a, b, d), None)
            return (d, None)
        q: Any = qop(qa, qb)
        return (d, q) if q._numerator / q._denominator == d else (d, None)
    return add


def _exact_sub(left: Callable[[], Value], right: Callable[[], Value]) -> Callable[[], Value]:
    qop = q_sub

    def sub() -> Value:
        a, qa = left()
        b, qb = right()
        d = a - b
        if d - d:
            check_double(d)
        if qa is None or qb is None:
            if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
                return (_spread_sub(a, b, d), None)
            return (d, None)
        q: Any = qop(qa, qb)
        return (d, q) if q._numerator / q._denominator == d else (d, None)
    return sub


def _exact_mul(left: Callable[[], Value], right: Callable[[], Value]) -> Callable[[], Value]:
    def mul() -> Value:
        a, qa = left()
        b, qb = right()
        d = a * b
        if d - d:
            check_double(d)
        if qa is None or qb is None:
            if a.__class__ is SpreadDouble or b.__class__ is SpreadDouble:
                return (_spread_mul(a, b, d), None)
            return (d, None)
        # q_mul, the Fraction built only when it rounds to the double (int / int rounds correctly)
        n, den = qa._numerator * qb._numerator, qa._denominator * qb._denominator
        return (d, to_fraction(n, den)) if n / den == d else (d, None)
    return mul


_EXACT_ARITHMETIC: dict[str, Callable[[Callable[[], Value], Callable[[], Value]], Callable[[], Value]]] = {
    "/": _exact_div, "+": _exact_add, "-": _exact_sub, "*": _exact_mul}


def _with_constant(op: str, left: Callable[[], Value], const: Value) -> Callable[[], Value] | None:
    """``left op const`` for + - * / (a divisor not 0): :func:`_arithmetic` with the right operand read once
    (the same operations in the same order), else None."""
    b, qb = const
    if (op == "/" and b == 0.0) or qb is None:
        return None
    return _CONSTANT_ARITHMETIC[op](left, b, qb)


def _constant_div(left: Callable[[], Value], b: float, qb: Any) -> Callable[[], Value]:
    exact = bool(qb._numerator)
    # qa / qb = (qa's numerator * bn) / (qa's denominator * bd) with bd > 0 (q_div's sign rule)
    bn, bd = (qb._denominator, qb._numerator) if qb._numerator > 0 else (-qb._denominator, -qb._numerator)

    def div() -> Value:
        a, qa = left()
        d = a / b
        if d - d:
            check_double(d)
        if qa is None or not exact:
            if a.__class__ is SpreadDouble:
                return (_spread_div(a, b, d), None)
            return (d, None)
        n, den = qa._numerator * bn, qa._denominator * bd
        return (d, to_fraction(n, den)) if n / den == d else (d, None)
    return div


def _constant_add(left: Callable[[], Value], b: float, qb: Any) -> Callable[[], Value]:
    def add() -> Value:
        a, qa = left()
        d = a + b
        if d - d:
            check_double(d)
        if qa is None:
            if a.__class__ is SpreadDouble:
                return (_spread_add(a, b, d), None)
            return (d, None)
        q: Any = q_add(qa, qb)
        return (d, q) if q._numerator / q._denominator == d else (d, None)
    return add


def _constant_sub(left: Callable[[], Value], b: float, qb: Any) -> Callable[[], Value]:
    def sub() -> Value:
        a, qa = left()
        d = a - b
        if d - d:
            check_double(d)
        if qa is None:
            if a.__class__ is SpreadDouble:
                return (_spread_sub(a, b, d), None)
            return (d, None)
        q: Any = q_sub(qa, qb)
        return (d, q) if q._numerator / q._denominator == d else (d, None)
    return sub


def _constant_mul(left: Callable[[], Value], b: float, qb: Any) -> Callable[[], Value]:
    bn, bd = qb._numerator, qb._denominator

    def mul() -> Value:
        a, qa = left()
        d = a * b
        if d - d:
            check_double(d)
        if qa is None:
            if a.__class__ is SpreadDouble:
                return (_spread_mul(a, b, d), None)
            return (d, None)
        n, den = qa._numerator * bn, qa._denominator * bd  # q_mul, built only when it rounds to the double
        return (d, to_fraction(n, den)) if n / den == d else (d, None)
    return mul


_CONSTANT_ARITHMETIC: dict[str, Callable[[Callable[[], Value], float, Any], Callable[[], Value]]] = {
    "/": _constant_div, "+": _constant_add, "-": _constant_sub, "*": _constant_mul}


def evaluate_tree(node: tuple, variables: FanucVariables, ctx: Context | None = None) -> Value:
    """Evaluate a tree once (compiles it; for tests and one-off use)."""
    return compile_tree(node, variables, ctx)()

