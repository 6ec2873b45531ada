"""LinuxCNC's trigonometry as an x86-64 controller computes it: in x87 long double, the result rounded to double.

``interp_execute.cc`` computes ``SIN[x]`` as ``sin((x * M_PIl) / 180.0)``: ``M_PIl`` is a long double, so the
product, the quotient and ``sinl`` run in the x87's 80-bit format (64-bit significand, rounded to nearest
even) and only the result becomes a double; ``ASIN``, ``ACOS`` and ``ATAN`` compute ``(r * 180.0) / M_PIl``
with ``r`` a double.  The two roundings to 64 bits are made here exactly, on integers (the argument is
passed as the bytes of an 80-bit ``c_longdouble``); ``sinl``, ``cosl`` and ``tanl`` are the C library's (the
functions LinuxCNC calls), through :mod:`ctypes`, whose ``c_longdouble`` result becomes a Python float by C's
conversion of the long double to double, the one rounding to 53 bits LinuxCNC's assignment makes.  No numpy: the double pass of a
program with trigonometry loads none.

Invariant (``tests/gcode/test_x87.py``): on x86-64 every function returns the double numpy's 80-bit
``longdouble`` gives for the same formula, and the values ``rs274`` computes.  Where the host has no 80-bit
``sinl`` (another architecture), :func:`available` is False and SIN, COS and TAN are the double formulas.

>>> sin_degrees(30.0) if available() else 0.5  # the double formula gives 0.49999999999999994
0.5
"""

from __future__ import annotations

import math
import os
from fractions import Fraction

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["available", "sin_degrees", "cos_degrees", "tan_degrees", "degrees_from_radians"]

#: ``M_PIl``: pi rounded to a 64-bit significand, ``PI64 * 2**-62``.
PI64 = 0xC90FDAA22168C235
_TOP = 1 << 64


def _libm() -> tuple | None:
    import ctypes
    import struct

    machine = os.uname().machine.lower() if hasattr(os, "uname") else ""
    if machine not in ("x86_64", "amd64") or ctypes.sizeof(ctypes.c_longdouble) != 16:
        return None
    try:
        lib = ctypes.PyDLL("libm.so.6")  # the GIL kept: sinl calls back into nothing
    except OSError:
        from ctypes.util import find_library

        name = find_library("m")
        if name is None:
            return None
        try:
            lib = ctypes.PyDLL(name)
        except OSError:
            return None

    out = []
    for fname in ("sinl", "cosl", "tanl"):
        fn = getattr(lib, fname, None)
        if fn is None:
            return None
        # the argument an 80-bit c_longdouble built by pack_into; the result a Python float: ctypes converts
        # the long double to double in C (an x87 store to 64 bits, rounded once to nearest even), the cast
        # LinuxCNC's assignment to a double makes.  No argtypes: the instance is passed as is, without from_param.
        fn.restype = ctypes.c_longdouble
        out.append(fn)
    # an x87 long double in memory: significand, sign and exponent, padding (struct: loaded here, issue 36)
    return ctypes.c_longdouble, *out, struct.Struct("<QH6x").pack_into


#: ``[c_longdouble, sinl, cosl, tanl, pack_into]``, loaded at the first call that needs them (importing :mod:`ctypes`
#: costs about 2 ms of every start-up, and most programs compute no SIN, COS or TAN); ``[None]`` where the host
#: has no 80-bit ``sinl`` (then SIN, COS and TAN are the double formulas).
_LIB: list[Any] = []


def _library() -> list[Any]:
    if not _LIB:
        _LIB.extend(_libm() or (None,))
    return _LIB


def available() -> bool:
    """Can the C library's 80-bit ``sinl``/``cosl``/``tanl`` be called here (x86-64)?  Loads them."""
    return _library()[0] is not None


def __getattr__(name: str) -> Any:
    if name == "AVAILABLE":  # True where the C library's 80-bit sinl/cosl/tanl can be called (x86-64)
        return available()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: SIN, COS and TAN as double formulas, where the host has no 80-bit ``sinl`` (not LinuxCNC's rounding).
_DOUBLE_FORMULAS = (math.sin, math.cos, math.tan)


def _round64(n: int, shift: int, sticky: bool) -> tuple[int, int]:
    """``n * 2**shift`` (plus a little more when ``sticky``: a non-zero remainder below the last bit of ``n``)
    rounded to a 64-bit significand, to nearest even: ``(significand, exponent)``."""
    extra = n.bit_length() - 64
    if extra <= 0:
        return n << -extra, shift + extra
    q = n >> extra
    rest = n & ((1 << extra) - 1)
    half = 1 << (extra - 1)
    if rest > half or (rest == half and (sticky or q & 1)):
        q += 1
        if q == _TOP:
            q >>= 1
            extra += 1
    return q, shift + extra


def _argument(x: float) -> tuple[int, int]:
    """``(x * M_PIl) / 180.0`` in long double, ``x`` finite and not 0: ``(significand, exponent)``, sign apart.

    :func:`_round64` twice, unrolled for the sizes that occur: the 53-bit significand of ``x`` times ``M_PIl``
    has 116 or 117 bits, that product rounded to 64 bits and shifted by 72, divided by 180, 128 or 129.
    Each rounding to nearest even is one sum: ``(n + 2**(k-1) - 1 + bit k of n) >> k`` rounds ``n * 2**-k``
    (above half: up; below: down; at half: up exactly when bit ``k`` is odd).  The division's remainder is a
    sticky bit or-ed into the lowest bit of the 128-bit quotient, 64 bits below the rounding position: it
    turns an exact half into just above it and changes no other case.

    Neither rounding meets an exact half, so the even bit and the sticky bit never decide (they are kept: the
    rule, one operation each).  The product: ``PI64`` is odd, so its dropped ``k`` bits are a half exactly when
    the significand ``M`` has ``k - 1`` trailing zeros: ``M = 2**52`` has 52 and is rounded by 52 (exact), ``M = 3 *
    2**51`` has 51 and is rounded by 53 (its product has 117 bits).  The quotient: with ``q = 45a + b``
    its low 70 bits are those of ``floor(b * 2**70 / 45)``, a fraction ``b / 45`` whose binary digits repeat
    (period 12) and are never a one followed by zeros (``test_x87.test_no_quotient_is_half_way``).
    """
    m, e = math.frexp(abs(x))
    p = int(m * 9007199254740992.0) * PI64
    if p >> 116:
        q, extra = (p + _H52 + ((p >> 53) & 1)) >> 53, 53
    else:
        q, extra = (p + _H51 + ((p >> 52) & 1)) >> 52, 52
    if q >> 64:  # rounded up to 2**64
        q >>= 1
        extra += 1
    quotient, remainder = divmod(q << 72, 180)
    if remainder:
        quotient |= 1
    if quotient >> 128:
        q2, extra2 = (quotient + _H64 + ((quotient >> 65) & 1)) >> 65, 65
    else:
        q2, extra2 = (quotient + _H63 + ((quotient >> 64) & 1)) >> 64, 64
    if q2 >> 64:
        q2 >>= 1
        extra2 += 1
    return q2, e - 115 + extra - 72 + extra2


#: ``_Hn`` is ``2**n - 1``: the ``2**(k-1) - 1`` of a rounding of :func:`_argument` by ``k = n + 1`` bits
_H51, _H52, _H63, _H64 = (1 << 51) - 1, (1 << 52) - 1, (1 << 63) - 1, (1 << 64) - 1


def _to_double(significand: int, exponent: int) -> float:
    """``significand * 2**exponent`` rounded to a double (nearest even), the sign apart."""
    if significand == 0:
        return 0.0
    if significand.bit_length() + exponent >= -1021:  # a normal double: float() rounds the integer once
        try:
            return math.ldexp(float(significand), exponent)
        except OverflowError:
            return math.inf
    return float(Fraction(significand, 1 << -exponent))


#: The last argument: SIN and COS of one angle (``#2 * COS[#1]``, ``#2 * SIN[#1]``) compute it once.
_last: list = [None, None]


def _call(which: int, x: float) -> float:
    """``sinl``, ``cosl`` or ``tanl`` (``which`` 1, 2, 3) of ``(x * M_PIl) / 180.0``, rounded to double; ``x``
    finite, not 0.  Where the host has no 80-bit functions: the double formula ``sin((x * pi) / 180.0)``."""
    lib = _LIB or _library()
    long_double = lib[0]
    if long_double is None:
        return float(_DOUBLE_FORMULAS[which - 1]((x * math.pi) / 180.0))
    last = _last
    if x == last[0]:
        return lib[which](last[1])  # type: ignore[no-any-return]
    sig, exp = _argument(x)
    arg = long_double()
    lib[4](arg, 0, sig, (exp + 16446) | (0x8000 if x < 0.0 else 0))
    last[0], last[1] = x, arg
    return lib[which](arg)  # type: ignore[no-any-return]


def sin_degrees(x: float) -> float:
    """``sin((x * M_PIl) / 180.0)`` as a double (x finite).

    >>> sin_degrees(30.0) == 0.5 or not available()
    True
    """
    return x if x == 0.0 else _call(1, x)  # sinl(-0) is -0


def cos_degrees(x: float) -> float:
    """``cos((x * M_PIl) / 180.0)`` as a double (x finite).

    >>> cos_degrees(60.0) == 0.5 or not available()
    True
    """
    return 1.0 if x == 0.0 else _call(2, x)


def tan_degrees(x: float) -> float:
    """``tan((x * M_PIl) / 180.0)`` as a double (x finite; TAN[90] is -3.98679762981171e19 on LinuxCNC).

    >>> tan_degrees(90.0) < -1e19 or not available()
    True
    """
    return x if x == 0.0 else _call(3, x)


def degrees_from_radians(r: float) -> float:
    """``(r * 180.0) / M_PIl`` as a double: the product in double, the quotient in long double, then rounded.

    >>> degrees_from_radians(math.atan2(1.0, 1.0))
    45.0
    """
    y = r * 180.0
    if y == 0.0 or y - y:
        return y / math.pi if y - y else y
    m, e = math.frexp(abs(y))
    mant = int(m * 9007199254740992.0)
    quotient, remainder = divmod(mant << 128, PI64)
    sig, exp = _round64(quotient, e - 53 - 128 + 62, remainder != 0)
    value = _to_double(sig, exp)
    return -value if y < 0 else value
