"""Parameters and expression evaluation, the way LinuxCNC evaluates them.

Values are IEEE doubles, as in the controller: every arithmetic operation,
comparison, function and loop condition is computed on the double the
controller computes (trigonometry in degrees, ``COS[x]`` is
``cos((x * M_PIl) / 180.0)`` in x87 long double exactly as ``interp_execute.cc``
writes it and an x86-64 controller runs it, :mod:`nczones.gcode.linuxcnc.x87`).

Exact shadow (the documented choice for "plain decimals stay exact")
---------------------------------------------------------------------
Alongside each double the evaluator carries an optional exact rational
*shadow*.  Decimal literals have one (``0.1`` is exactly 1/10); ``+ - * /``,
unary minus, ``ABS``, ``FIX``, ``FUP``, ``ROUND``, comparisons and logic
propagate it; other functions (``SIN``, ``SQRT``, ``**`` ...) drop it.  After
every operation the shadow is kept **only if the controller's double is the
double nearest to it** (``float(shadow) == double``); otherwise it is dropped
and the value is the double itself.  A word finally receives the shadow when
there is one, else ``Fraction(double)`` (exact: every double is a rational).
So the value a word receives always rounds to exactly the double the
controller uses, and is the decimal the programmer wrote whenever that is
consistent: ``#1=0.1`` then ten ``G91 Y#1`` moves add exactly 1, while
``X[0.1+0.2]`` is ``Fraction(0.30000000000000004)`` because the controller's
sum is not the double nearest to 3/10.

>>> p = Parameters()
>>> p.set(1, Fraction("0.1"))
>>> p.get(1), p.get_exact(1)
(0.1, Fraction(1, 10))
>>> word_value(evaluate((NUM, 0.5, Fraction(1, 2)), p))
Fraction(1, 2)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from fractions import Fraction

from ..errors import InvalidArgument
from .lexer import fraction_raw, to_fraction
from .linuxcnc import x87
from .parser import ATAN, BIN, EXISTS, FN, NEG, NPAR, NUM, PAR

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = [
    "Parameters",
    "EvalError",
    "evaluate",
    "compile_expression",
    "word_value",
    "TOLERANCE_EQUAL",
    "MAX_PARAMETER",
    "format_parameter",
    "trig_degrees",
    "TRIG_DEGREES",
    "atan_degrees",
    "lcnc_integer",
    "read_only",
    "lcnc_round",
]

#: LinuxCNC compares EQ/NE with this absolute tolerance (``TOLERANCE_EQUAL``).
TOLERANCE_EQUAL = 0.0001

#: SIN, COS and TAN of degrees as LinuxCNC computes them: ``sin((x * M_PIl) / 180.0)`` in x87 long double, the
#: result rounded to double (:mod:`nczones.gcode.linuxcnc.x87`); the double formula where the host has no 80-bit ``sinl``.
TRIG_DEGREES: dict[str, Callable[[float], float]] = {
    "sin": x87.sin_degrees, "cos": x87.cos_degrees, "tan": x87.tan_degrees}


def trig_degrees(name: str, d: float) -> float:
    """SIN, COS or TAN of ``d`` degrees as LinuxCNC computes it (:data:`TRIG_DEGREES`).

    >>> trig_degrees("sin", 30.0), trig_degrees("tan", 90.0) < 0  # math.sin(math.pi / 6) is 0.49999999999999994
    (0.5, True)
    """
    return TRIG_DEGREES[name](d)


def to_degrees(r: float) -> float:
    """``(r * 180.0) / M_PIl`` rounded to double: LinuxCNC's radians to degrees after ASIN, ACOS and ATAN."""
    if not x87.available():
        return (r * 180.0) / math.pi
    return x87.degrees_from_radians(r)


def atan_degrees(y: float, x: float) -> float:
    """``ATAN[y]/[x]`` in degrees as LinuxCNC computes it (``atan2`` in double, the degrees in long double).

    >>> atan_degrees(1.0, 1.0), atan_degrees(0.0, -1.0)
    (45.0, 180.0)
    """
    return check_double(to_degrees(math.atan2(y, x)))
#: Highest numbered parameter (LinuxCNC ``RS274NGC_MAX_PARAMETERS - 1``).
MAX_PARAMETER = 5601
#: Subroutine arguments live in #1..#30 and are local to a call.
SUB_PARAMS = 30
#: The numbered parameters a subroutine call saves and sets (#1..#30).
_SUB_KEYS = frozenset(range(1, SUB_PARAMS + 1))
_ZERO: tuple = (0.0, Fraction(0))
_ONE: tuple = (1.0, Fraction(1))


#: LinuxCNC's predefined read-only named parameters; the interpreter may ``provide`` them.
PREDEFINED = frozenset(
    "_vmajor _vminor _line _motion_mode _plane _ccomp _metric _imperial _absolute _incremental _inverse_time "
    "_units_per_minute _units_per_rev _coord_system _tool_offset _retract_r_plane _retract_old_z "
    "_spindle_rpm_mode _spindle_css_mode _ijk_absolute_mode _lathe_diameter_mode _lathe_radius_mode "
    "_spindle_on _spindle_cw _mist _flood _speed_override _feed_override _adaptive_feed _feed_hold _feed _rpm "
    "_x _y _z _a _b _c _u _v _w _abs_x _abs_y _abs_z _abs_a _abs_b _abs_c _abs_u _abs_v _abs_w "
    "_current_tool _current_pocket _selected_tool _selected_pocket _task _call_level _remap_level".split()
)


#: Named parameters a program may not assign (LinuxCNC: "Cannot assign to read-only parameter"): the
#: predefined ones and the value of the last subroutine.  (``#<_hal[...]>``/``#<_ini[...]>``: rs274 without
#: HAL or INI takes the assignment; they stay unknown.)
READ_ONLY = PREDEFINED | {"_value", "_value_returned"}


def read_only(key: int | str) -> bool:
    """Is ``#key`` a parameter LinuxCNC refuses to assign?

    >>> read_only("_value"), read_only("_x"), read_only("_mine"), read_only(5220)
    (True, True, False, False)
    """
    return isinstance(key, str) and key in READ_ONLY


class EvalError(Exception):
    """Internal: a run-time language error; the caller attaches the span (GC3xx)."""

    def __init__(self, code: str, message: str):
        super().__init__(message)
        self.code = code
        self.message = message


Value = tuple  # (float, Fraction | None)


def pair(value: Any) -> Value:
    if isinstance(value, Fraction):
        return (value.numerator / value.denominator, value)
    if isinstance(value, bool):
        raise InvalidArgument(f"parameter value {value!r} is a boolean, expected a number")
    if isinstance(value, int):
        return (float(value), Fraction(value))
    if isinstance(value, float):
        if not math.isfinite(value):
            raise InvalidArgument(f"parameter value {value!r} is not finite")
        return (value, None)
    raise InvalidArgument(f"parameter value {value!r} must be a Fraction, int or float")


class Parameters:
    """The parameter store of one program run, shared with the interpreter.

    Numbered parameters ``#1``..``#5601`` read 0 until set.  Named parameters
    (``#<depth>``) are local to the current subroutine call (the main program
    has its own scope) and must be set before they are read; names starting
    with ``_`` are global.  Names are lower case without blanks, as written
    between ``<`` and ``>`` after LinuxCNC's blank removal.

    The interpreter hooks its state in two ways:

    * ``set(key, value)`` at any time (e.g. after a G10 changes #5221); the
      language layer reads parameters lazily, so a block yielded after the
      call sees the new value;
    * ``provide(key, getter)`` registers a computed, read-only parameter
      (``5420`` current X, ``"_x"``...): every read calls ``getter()``, which
      may raise :class:`EvalError` (a ``GC30x`` code makes the language layer
      report the program as unknown at that word);
    * ``guard(key, reason)``: an assignment the program makes to ``#key`` is
      unknown, for ``reason`` (state the interpreter cannot follow).

    ``on_write``, if set, is called as ``on_write(key, value)`` for every
    assignment the *program* makes (``#5221 = 10``), after it takes effect.

    >>> p = Parameters()
    >>> p.provide(5420, lambda: Fraction(3, 2))
    >>> p.get(5420), p.get(7)
    (1.5, 0.0)
    >>> p.set("_feed", 200); p.get("_feed")
    200.0
    """

    __slots__ = ("_num", "_globals", "_scopes", "_providers", "_guarded", "on_write", "max_parameter")

    def __init__(self, numbered: dict | None = None, named: dict | None = None):
        self._num: dict[int, Value] = {}
        self._globals: dict[str, Value] = {}
        self._scopes: list[dict[str, Value]] = [{}]
        self._providers: dict[int | str, Callable[[], object]] = {}
        self._guarded: dict[int | str, str] = {}
        self.on_write: Callable[[int | str, float], None] | None = None
        self.max_parameter = MAX_PARAMETER
        self._globals["_value"] = (0.0, Fraction(0))
        self._globals["_value_returned"] = (0.0, Fraction(0))
        for k, v in (numbered or {}).items():
            self.set(k, v)
        for k, v in (named or {}).items():
            self.set(k, v)

    # -- public API -------------------------------------------------------------
    @property
    def scopes(self) -> list[dict[str, Value]]:
        """The local scopes of named parameters, innermost last (one per o-word call)."""
        return self._scopes

    def get(self, key: int | str) -> float:
        """The controller's double for ``#key`` (KeyError for an unset name)."""
        return float(self.read(key)[0])

    def get_exact(self, key: int | str) -> Fraction:
        """The exact value a word ``X#key`` would receive."""
        return word_value(self.read(key))

    def set(self, key: int | str, value: Any) -> None:
        """Set ``#key`` from a Fraction, int or float (no ``on_write`` call)."""
        self._store(self._key(key), pair(value))

    def unprovide(self, key: int | str) -> None:
        """Take back what :meth:`provide` gave ``#key`` (its stored value is read again)."""
        self._providers.pop(self._key(key), None)

    def provide(self, key: int | str, getter: Callable[[], object]) -> None:
        """Make ``#key`` a computed parameter: reads call ``getter()``."""
        self._providers[self._key(key)] = getter

    def guard(self, key: int | str, reason: str) -> None:
        """Make an assignment to ``#key`` by the program unknown (the language layer's GC395), for ``reason``."""
        self._guarded[self._key(key)] = reason

    def guarded(self, key: int | str) -> str | None:
        """Why the program may not assign ``#key`` (None: it may)."""
        return self._guarded.get(key) if self._guarded else None

    def exists(self, key: int | str) -> bool:
        key = self._key(key)
        if isinstance(key, int):
            return 1 <= key <= self.max_parameter
        if key in self._providers:
            return True
        return key in (self._globals if key.startswith("_") else self._scopes[-1])

    # -- used by the language layer -------------------------------------------------
    @staticmethod
    def _key(key):
        if isinstance(key, str):
            return key.replace(" ", "").lower()
        if isinstance(key, bool) or not isinstance(key, int):
            raise InvalidArgument(f"parameter key {key!r} must be an int or a name")
        return key

    def read(self, key: int | str) -> Value:
        getter = self._providers.get(key)
        if getter is not None:
            return pair(getter())
        if isinstance(key, int):
            return self._num.get(key, (0.0, Fraction(0)))
        scope = self._globals if key.startswith("_") else self._scopes[-1]
        try:
            return scope[key]
        except KeyError:
            raise KeyError(key) from None

    def write(self, key: int | str, value: Value) -> None:
        """An assignment made by the program (calls ``on_write``)."""
        self._store(key, value)
        if self.on_write is not None:
            self.on_write(key, value[0])

    def _store(self, key: int | str, value: Value) -> None:
        if isinstance(key, int):
            self._num[key] = value
        elif key.startswith("_"):
            self._globals[key] = value
        else:
            self._scopes[-1][key] = value

    def push_scope(self, args: tuple[Value, ...]) -> dict:
        """Enter a subroutine: save #1..#30, set them from ``args``, new local names.  The saved frame is the
        caller's #1..#30 that were set (a dict: the unset ones read 0 again after :meth:`pop_scope`)."""
        num = self._num
        saved = {k: num[k] for k in num.keys() & _SUB_KEYS}
        for k in saved:
            del num[k]
        if args:
            num.update(zip(range(1, SUB_PARAMS + 1), args))
        self._scopes.append({})
        return saved

    def set_returned(self, value: Value | None) -> None:
        """``#<_value>`` and ``#<_value_returned>`` as an endsub, return or M99 leaves them: ``value`` and 1,
        else (None) 0 and 0; a computed read of either (:meth:`provide`) is taken back.  Each is an assignment
        by the program (``on_write`` is called)."""
        providers = self._providers
        if "_value" in providers or "_value_returned" in providers:
            providers.pop("_value", None)
            providers.pop("_value_returned", None)
        got = (value, _ONE) if value is not None else (_ZERO, _ZERO)
        self._globals["_value"], self._globals["_value_returned"] = got
        if self.on_write is not None:
            self.on_write("_value", got[0][0])
            self.on_write("_value_returned", got[1][0])

    def push_locals(self) -> None:
        """Enter an M98 subprogram: a new frame of local names (LinuxCNC's enter_context), #1..#30 shared."""
        self._scopes.append({})

    def pop_locals(self) -> None:
        """Leave an M98 subprogram (M99): its local names are discarded (leave_context)."""
        if len(self._scopes) > 1:
            self._scopes.pop()

    def pop_scope(self, saved: dict) -> None:
        """Leave a subroutine: restore #1..#30 (``saved``, from :meth:`push_scope`) and the caller's local names."""
        num = self._num
        for k in num.keys() & _SUB_KEYS:
            del num[k]
        num.update(saved)
        if len(self._scopes) > 1:
            self._scopes.pop()

def lcnc_integer(value: Fraction) -> int | None:
    """The integer LinuxCNC reads for an integer word (H, L, T, M, an O number, M98's P): its double
    within 0.0001 of an integer (``Interp::read_integer_value``: floor, then ceil when the rest is above
    0.9999), None when it is farther (LinuxCNC: "Non-integer value for integer").

    >>> lcnc_integer(Fraction("2.00001")), lcnc_integer(Fraction("2.99995")), lcnc_integer(Fraction("2.5"))
    (2, 3, None)
    """
    if value.denominator == 1:
        return value.numerator
    d = value.numerator / value.denominator
    n = math.floor(d)
    if d - n > 0.9999:
        return math.ceil(d)
    return None if d - n > 0.0001 else n


def lcnc_round(value: Fraction) -> int:
    """LinuxCNC's ``round_to_int`` of a word's double: ``nearbyint``, to the nearest integer, halves to even
    (``o.. repeat [2.6]`` runs 3 times, ``[2.5]`` twice).

    >>> lcnc_round(Fraction("2.6")), lcnc_round(Fraction("2.5")), lcnc_round(Fraction("3.5"))
    (3, 2, 4)
    """
    return value.numerator if value.denominator == 1 else round(value.numerator / value.denominator)


def word_value(value: Value) -> Fraction:
    """The exact value a word receives: the shadow, else the double exactly.

    >>> word_value((0.1, None)) == Fraction(0.1)
    True
    """
    q = value[1]
    return q if q is not None else to_fraction(*value[0].as_integer_ratio())


def _keep(d: float, q: Fraction | None) -> Value:
    """Keep the shadow only if it rounds to the controller's double."""
    if q is not None and q.numerator / q.denominator != d:
        q = None
    return (d, q)


def check_double(d: float) -> float:
    if d != d:
        raise EvalError("GC312", "calculation resulted in 'not a number'")
    if d in (math.inf, -math.inf):
        raise EvalError("GC312", "calculation resulted in 'infinity'")
    return d


def parameter_key(node: Any, params: Parameters) -> int | str:
    """The key (int or name) a PAR/NPAR tree refers to, range-checked."""
    if node[0] == NPAR:
        return str(node[1])
    d = evaluate(node[1], params)[0]
    if d - d:  # inf (a literal too large for a double) or NaN
        raise EvalError("GC204", f"parameter number {d!r} is not an integer")
    index: int = round(d)
    if abs(d - index) > 0.0001:
        raise EvalError("GC204", f"parameter number {d!r} is not an integer")
    if not 1 <= index <= params.max_parameter:
        raise EvalError("GC205", f"parameter number {index} out of range; allowed are 1 to {params.max_parameter}")
    return index


def evaluate(node: Any, params: Parameters) -> Value:
    """Evaluate an expression tree to ``(double, exact shadow or None)``.

    >>> from nczones.gcode.parser import parse_line
    >>> tree = parse_line("X[1 + 2 * 3 ** 2 - 10 MOD 4]", 1, "p").words[0][1]
    >>> evaluate(tree, Parameters())
    (17.0, Fraction(17, 1))
    >>> tree = parse_line("X[COS[60]]", 1, "p").words[0][1]
    >>> evaluate(tree, Parameters())[0]  # cos((60 * M_PIl) / 180.0) in long double; the double formula's is not 0.5
    0.5
    """
    tag = node[0]
    if tag == NUM:
        return (node[1], node[2])
    if tag == PAR and node[1][0] == NUM:
        # #<number literal>: parameter_key and Parameters.read, inlined
        d = node[1][1]
        if d - d:
            parameter_key(node, params)  # raises its error
        index = round(d)
        if abs(d - index) > 0.0001 or not 1 <= index <= params.max_parameter:
            parameter_key(node, params)  # raises its error
        getter = params._providers.get(index)
        if getter is None:
            return params._num.get(index, UNSET)
        return pair(getter())
    if tag == PAR or tag == NPAR:
        key = parameter_key(node, params)
        try:
            return params.read(key)
        except KeyError:
            if isinstance(key, str) and (key.startswith(("_hal[", "_ini[")) or key in PREDEFINED):
                raise EvalError("GC395", f"#<{key}> reads controller state (HAL pins, INI values, predefined "
                                "parameters) that nobody provided") from None
            raise EvalError("GC310", f"named parameter #<{key}> is not defined") from None
    if tag == BIN:
        return binary_op(node[1], evaluate(node[2], params), evaluate(node[3], params))
    if tag == NEG:
        d, q = evaluate(node[1], params)
        return (-d, -q if q is not None else None)
    if tag == FN:
        return unary_op(node[1], evaluate(node[2], params))
    if tag == ATAN:
        y = evaluate(node[1], params)[0]
        x = evaluate(node[2], params)[0]
        return (atan_degrees(y, x), None)
    if tag == EXISTS:
        par = node[1]
        if par[0] == NPAR:
            return _TRUE if params.exists(par[1]) else _FALSE
        d = evaluate(par[1], params)[0]  # errors inside the index propagate (##2 with #2 = 99999)
        if d - d:
            return _FALSE
        return _TRUE if 1 <= round(d) <= params.max_parameter and abs(d - round(d)) <= 0.0001 else _FALSE
    raise AssertionError(f"unknown expression node {node!r}")  # pragma: no cover


_TRUE = (1.0, Fraction(1))
_FALSE = (0.0, Fraction(0))
UNSET = (0.0, Fraction(0))  # what an unset numbered parameter reads

#: Trees deeper than this are not compiled (:func:`compile_expression` leaves them to :func:`evaluate`).
MAX_COMPILED_DEPTH = 64


def compile_expression(node: Any) -> Callable[[Parameters], Value]:
    """``evaluate(node, params)`` as a function of ``params``, the tree read once.

    For expressions that run again (loop conditions, subroutine lines): the
    nodes become nested closures that make the same double operations in the
    same order with the same exact shadows and raise the same errors (each
    operator, function and parameter read is :func:`evaluate`'s own:
    :func:`binary_op`, :func:`unary_op`, the same parameter store; a
    comparison reads the same two doubles).  Named parameters, computed
    parameter numbers, ``EXISTS`` and ``ATAN`` are left to :func:`evaluate`
    itself, as is a tree deeper than :data:`MAX_COMPILED_DEPTH` (whose
    recursion limit must stay :func:`evaluate`'s).

    >>> from nczones.gcode.parser import parse_line
    >>> tree = parse_line("o1 while [#1 LT [2 * COS[60]] AND #2 EQ 0]", 1, "p").oword.args[0]
    >>> params = Parameters()
    >>> compile_expression(tree)(params) == evaluate(tree, params) == (1.0, Fraction(1))
    True
    """
    if _depth(node, MAX_COMPILED_DEPTH) > MAX_COMPILED_DEPTH:
        return lambda params: evaluate(node, params)
    return _compile(node)


def _depth(node: Any, limit: int) -> int:
    """The depth of a tree, counted up to ``limit + 1``."""
    if limit < 0:
        return 1
    tag = node[0]
    if tag == BIN or tag == ATAN:
        return 1 + max(_depth(node[-2], limit - 1), _depth(node[-1], limit - 1))
    if tag == NEG or tag == PAR:
        return 1 + _depth(node[1], limit - 1)
    if tag == FN:
        return 1 + _depth(node[2], limit - 1)
    return 1


_COMPARE = {
    "gt": lambda a, b: a > b,
    "ge": lambda a, b: a >= b,
    "lt": lambda a, b: a < b,
    "le": lambda a, b: a <= b,
}


def _compile(node: Any) -> Callable[[Parameters], Value]:
    tag = node[0]
    if tag == NUM:
        value = (node[1], node[2])
        return lambda params: value
    if tag == PAR and node[1][0] == NUM:
        d = node[1][1]
        if d - d or abs(d - round(d)) > 0.0001:
            return lambda params: evaluate(node, params)  # raises the parameter number's error
        index = round(d)

        def read(params: Parameters) -> Value:
            if not 1 <= index <= params.max_parameter:
                return evaluate(node, params)  # raises GC205
            getter = params._providers.get(index)
            if getter is None:
                return params._num.get(index, UNSET)
            return pair(getter())

        return read
    if tag == BIN:
        op = node[1]
        left, right = _compile(node[2]), _compile(node[3])
        if node[3][0] == NUM and op in _COMPARE:
            b = node[3][1]
            if op == "lt":
                return lambda params: _TRUE if left(params)[0] < b else _FALSE
            if op == "gt":
                return lambda params: _TRUE if left(params)[0] > b else _FALSE
        test = _COMPARE.get(op)
        if test is not None:
            return lambda params: _TRUE if test(left(params)[0], right(params)[0]) else _FALSE
        return lambda params: binary_op(op, left(params), right(params))
    if tag == NEG:
        inner = _compile(node[1])

        def negate(params: Parameters) -> Value:
            d, q = inner(params)
            return (-d, -q if q is not None else None)

        return negate
    if tag == FN:
        name = node[1]
        arg = _compile(node[2])
        return lambda params: unary_op(name, arg(params))
    return lambda params: evaluate(node, params)  # NPAR, computed parameter numbers, ATAN, EXISTS


def q_add(a: Any, b: Any) -> Fraction:  # Fractions, read through their slots
    """``a + b`` by integer arithmetic (the result is normalized, equal to Fraction's)."""
    if not a._numerator:
        same: Fraction = b
        return same
    da, db = a._denominator, b._denominator
    if da == db:
        return to_fraction(a._numerator + b._numerator, da)
    return to_fraction(a._numerator * db + b._numerator * da, da * db)


def q_sub(a: Any, b: Any) -> Fraction:
    if not b._numerator:
        same: Fraction = a
        return same
    da, db = a._denominator, b._denominator
    if da == db:
        return to_fraction(a._numerator - b._numerator, da)
    return to_fraction(a._numerator * db - b._numerator * da, da * db)


def q_mul(a: Any, b: Any) -> Fraction:
    return to_fraction(a._numerator * b._numerator, a._denominator * b._denominator)


def q_div(a: Any, b: Any) -> Fraction:
    """``a / b`` for ``b != 0``."""
    n, d = a._numerator * b._denominator, a._denominator * b._numerator
    return to_fraction(-n, -d) if d < 0 else to_fraction(n, d)


if to_fraction is not fraction_raw:  # pragma: no cover - a Python whose Fraction has other slots
    def q_add(a: Any, b: Any) -> Fraction:  # noqa: F811
        return Fraction(a + b)

    def q_sub(a: Any, b: Any) -> Fraction:  # noqa: F811
        return Fraction(a - b)

    def q_mul(a: Any, b: Any) -> Fraction:  # noqa: F811
        return Fraction(a * b)

    def q_div(a: Any, b: Any) -> Fraction:  # noqa: F811
        return Fraction(a / b)


def binary_op(op: str, left: Value, right: Value) -> Value:
    a, qa = left
    b, qb = right
    exact = qa is not None and qb is not None
    if op == "+":
        return _keep(check_double(a + b), q_add(qa, qb) if exact else None)
    if op == "-":
        return _keep(check_double(a - b), q_sub(qa, qb) if exact else None)
    if op == "*":
        return _keep(check_double(a * b), q_mul(qa, qb) if exact else None)
    if op == "/":
        if b == 0.0:
            raise EvalError("GC311", "attempt to divide by zero")
        return _keep(check_double(a / b), q_div(qa, qb) if exact and qb != 0 else None)
    if op == "mod":
        if b == 0.0:
            raise EvalError("GC311", "attempt to take MOD by zero")
        if a - a or b - b:
            raise EvalError("GC312", f"MOD of {a!r} by {b!r} cannot be computed")
        r = math.fmod(a, b)
        if r < 0.0:
            r = r + abs(b)
        return (check_double(r), None) if r != int(r) else (r, Fraction(int(r)))
    if op == "**":
        if a < 0.0 and math.floor(b) != b:
            raise EvalError("GC312", f"attempt to raise negative {a!r} to the non-integer power {b!r}")
        try:
            r = math.pow(a, b)
        except (OverflowError, ValueError):
            raise EvalError("GC312", f"{a!r} ** {b!r} cannot be computed") from None
        return (check_double(r), Fraction(int(r)) if r == int(r) else None)
    if op == "eq":
        return _TRUE if abs(a - b) < TOLERANCE_EQUAL else _FALSE
    if op == "ne":
        return _TRUE if abs(a - b) >= TOLERANCE_EQUAL else _FALSE
    if op == "gt":
        return _TRUE if a > b else _FALSE
    if op == "ge":
        return _TRUE if a >= b else _FALSE
    if op == "lt":
        return _TRUE if a < b else _FALSE
    if op == "le":
        return _TRUE if a <= b else _FALSE
    if op == "and":
        return _FALSE if (a == 0.0 or b == 0.0) else _TRUE
    if op == "or":
        return _TRUE if (a != 0.0 or b != 0.0) else _FALSE
    if op == "xor":
        return _TRUE if ((a == 0.0) != (b == 0.0)) else _FALSE
    raise AssertionError(op)  # pragma: no cover


def unary_op(name: str, value: Value) -> Value:
    d, q = value
    if d - d:  # only a literal too large for a double (or a parameter set from one) reaches here as inf
        raise EvalError("GC312", f"argument to {name.upper()} is {d!r}")
    if name == "abs":
        return (abs(d), abs(q) if q is not None else None)
    if name == "fix":
        r = math.floor(d)
        return (float(r), Fraction(r))
    if name == "fup":
        r = math.ceil(d)
        return (float(r), Fraction(r))
    if name == "round":
        r = int(d + (-0.5 if d < 0.0 else 0.5))
        return (float(r), Fraction(r))
    if name == "acos" or name == "asin":
        if d < -1.0 or d > 1.0:
            raise EvalError("GC312", f"argument to {name.upper()} out of range: {d!r} (allowed -1 to 1)")
        r = math.acos(d) if name == "acos" else math.asin(d)
        return (check_double(to_degrees(r)), None)
    if name in ("cos", "sin", "tan"):
        return (check_double(trig_degrees(name, d)), None)
    if name == "exp":
        try:
            return (check_double(math.exp(d)), None)
        except OverflowError:
            raise EvalError("GC312", "calculation resulted in 'infinity'") from None
    if name == "ln":
        if d <= 0.0:
            raise EvalError("GC312", f"zero or negative argument to LN: {d!r}")
        return (math.log(d), None)
    if name == "sqrt":
        if d < 0.0:
            raise EvalError("GC312", f"negative argument to SQRT: {d!r}")
        r = math.sqrt(d)
        return (r, Fraction(r) if r == int(r) else None)
    raise AssertionError(name)  # pragma: no cover


def format_parameter(value: float) -> str:
    """How ``(DEBUG, #1)`` prints a value (C ``%lf``: six decimals).

    >>> format_parameter(1.5)
    '1.500000'
    """
    return f"{value:.6f}"
