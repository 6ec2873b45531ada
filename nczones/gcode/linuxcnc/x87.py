"""LinuxCNC's trigonometry as an x86-64 controller computes it: in x87 long double, the result rounded to double.

``interp_execute.cc`` computes ``SIN[x]`` as ``sin((x * M_PIl) / 180.0)``: ``M_PIl`` is a long double, so the
product, the quotient and ``sinl`` run in the x87's 80-bit format (64-bit significand, rounded to nearest
even) and only the result becomes a double; ``ASIN``, ``ACOS`` and ``ATAN`` compute ``(r * 180.0) / M_PIl``
with ``r`` a double.  The two roundings to 64 bits and the final one to 53 are made here exactly, on
integers; ``sinl``, ``cosl`` and ``tanl`` are the C library's (the functions LinuxCNC calls), through
:mod:`ctypes`, with the 80-bit arguments and results passed as bytes.  No numpy: the double pass of a
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
        lib = ctypes.CDLL("libm.so.6")
    except OSError:
        from ctypes.util import find_library

        name = find_library("m")
        if name is None:
            return None
        try:
            lib = ctypes.CDLL(name)
        except OSError:
            return None

    class LongDouble(ctypes.c_longdouble):  # a subclass: ctypes hands it back as is, not as a Python float
        pass

    out = []
    for fname in ("sinl", "cosl", "tanl"):
        fn = getattr(lib, fname, None)
        if fn is None:
            return None
        fn.argtypes = [LongDouble]
        fn.restype = LongDouble
        out.append(fn)
    # an x87 long double in memory: significand, sign and exponent, padding (struct: loaded here, issue 36)
    return LongDouble, *out, struct.Struct("<QH6x").pack_into, struct.Struct("<QH").unpack_from


#: ``[LongDouble, sinl, cosl, tanl, pack_into, unpack_from]``, loaded at the first call that needs them (importing :mod:`ctypes`
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
    """
    m, e = math.frexp(abs(x))
    p = int(m * 9007199254740992.0) * PI64
    extra = 53 if p >> 116 else 52
    q = p >> extra
    rest = p - (q << extra)
    half = 1 << (extra - 1)
    if rest > half or (rest == half and q & 1):
        q += 1
        if q == _TOP:
            q >>= 1
            extra += 1
    quotient, remainder = divmod(q << 72, 180)
    extra2 = 65 if quotient >> 128 else 64
    q2 = quotient >> extra2
    rest = quotient - (q2 << extra2)
    half = 1 << (extra2 - 1)
    if rest > half or (rest == half and (remainder or q2 & 1)):
        q2 += 1
        if q2 == _TOP:
            q2 >>= 1
            extra2 += 1
    return q2, e - 115 + extra - 72 + extra2


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
        arg = last[1]
    else:
        sig, exp = _argument(x)
        arg = long_double()
        lib[4](arg, 0, sig, (exp + 16446) | (0x8000 if x < 0.0 else 0))
        last[0], last[1] = x, arg
    sig, se = lib[5](lib[which](arg))
    biased = se & 0x7FFF
    if biased == 0x7FFF:
        return math.nan
    if sig and sig.bit_length() + biased - 16446 >= -1021:
        value = math.ldexp(float(sig), biased - 16446)  # a normal double (|value| <= 2**16384 does not occur)
    else:
        value = _to_double(sig, (biased or 1) - 16446)
    return -value if se & 0x8000 else value


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
