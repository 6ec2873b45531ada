"""Exact numbers: decimal text becomes an exact rational, never a float.

Every number read from a program or a machine file passes through
:func:`parse_decimal` (text) or :func:`exact` (public API values).  Floats are
refused with :class:`~nczones.errors.InvalidArgument`, because ``0.1`` as a
float is not one tenth.

>>> parse_decimal("0.1") + parse_decimal("0.2") == parse_decimal("0.3")
True
>>> exact("-.5")
Fraction(-1, 2)
>>> format_decimal(Fraction(1, 3), places=4)
'0.3333…'
"""

from __future__ import annotations

import decimal
import re
from fractions import Fraction

from ..errors import InvalidArgument

# not typing's: `import nczones` imports this module (its public exact()) before the program raises the
# collector's threshold, and typing is 2 ms of objects (issue 36); a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = [
    "Fraction",
    "DECIMAL_RE",
    "parse_decimal",
    "exact",
    "exact_or_none",
    "format_decimal",
    "format_rational",
    "parse_rational",
    "format_exact",
    "is_decimal_fraction",
    "decimal_places",
    "to_float",
    "seconds",
    "MAX_ABS_LENGTH",
]

#: An unsigned or signed decimal with optional integer or fraction part:
#: ``12``, ``+12``, ``-1.5``, ``.5``, ``5.``.  No exponent, no ``inf``/``nan``.
DECIMAL_RE = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)\Z")

#: Coordinates and lengths beyond a kilometre (in mm) are taken for typos.
MAX_ABS_LENGTH = Fraction(1_000_000)


def parse_decimal(text: str) -> Fraction:
    """Read decimal text exactly.

    Parameters
    ----------
    text : str
        A decimal such as ``"12"``, ``"-1.5"``, ``".5"`` or ``"5."``;
        surrounding blanks are ignored.

    Returns
    -------
    Fraction
        The exact value.

    Raises
    ------
    InvalidArgument
        If the text is not a plain decimal (exponents, ``inf`` and ``nan`` are
        refused).

    Examples
    --------
    >>> parse_decimal("500.1")
    Fraction(5001, 10)
    >>> parse_decimal("5.")
    Fraction(5, 1)
    >>> parse_decimal("1e3")
    Traceback (most recent call last):
    ...
    nczones.errors.InvalidArgument: Cannot read '1e3' as a decimal: expected digits with an optional sign and decimal point, such as '-12.5' or '.5'
    """
    stripped = text.strip()
    if not DECIMAL_RE.match(stripped):
        raise InvalidArgument(
            f"Cannot read {text!r} as a decimal: expected digits with an optional sign "
            "and decimal point, such as '-12.5' or '.5'"
        )
    return Fraction(decimal.Decimal(stripped))


def exact(value: Any) -> Fraction:
    """Convert a value from the public API into an exact rational.

    Accepts decimal text, ``int``, ``Fraction`` and ``decimal.Decimal``.

    Examples
    --------
    >>> exact(3)
    Fraction(3, 1)
    >>> exact(0.1)
    Traceback (most recent call last):
    ...
    nczones.errors.InvalidArgument: Cannot use the float 0.1 as an exact number: pass it as decimal text ('0.1'), a Fraction or a decimal.Decimal
    """
    if isinstance(value, bool):
        raise InvalidArgument(f"Cannot use the boolean {value!r} as a number")
    if isinstance(value, Fraction):
        return value
    if isinstance(value, int):
        return Fraction(value)
    if isinstance(value, str):
        return parse_decimal(value)
    if isinstance(value, decimal.Decimal):
        if not value.is_finite():
            raise InvalidArgument(f"Cannot use the non-finite number {value!r}")
        return Fraction(value)
    if isinstance(value, float):
        raise InvalidArgument(
            f"Cannot use the float {value!r} as an exact number: pass it as decimal text "
            f"('{value!r}'), a Fraction or a decimal.Decimal"
        )
    raise InvalidArgument(
        f"Cannot use {value!r} of type {type(value).__name__} as an exact number: "
        "expected decimal text, int, Fraction or decimal.Decimal"
    )


def exact_or_none(value: Any) -> Fraction | None:
    """:func:`exact`, passing ``None`` through."""
    return None if value is None else exact(value)


def is_decimal_fraction(q: Fraction) -> bool:
    """True if ``q`` has a terminating decimal expansion.

    >>> is_decimal_fraction(Fraction(1, 8)), is_decimal_fraction(Fraction(1, 3))
    (True, False)
    """
    d = q.denominator
    for p in (2, 5):
        while d % p == 0:
            d //= p
    return d == 1


def decimal_places(q: Fraction) -> int | None:
    """Digits after the point needed to write ``q`` exactly (None if it repeats).

    >>> decimal_places(Fraction("12.250")), decimal_places(Fraction(7)), decimal_places(Fraction(1, 3))
    (2, 0, None)
    """
    if not is_decimal_fraction(q):
        return None
    d = q.denominator
    twos = fives = 0
    while d % 2 == 0:
        d //= 2
        twos += 1
    while d % 5 == 0:
        d //= 5
        fives += 1
    return max(twos, fives)


def format_decimal(q: Fraction, places: int | None = None) -> str:
    """Write ``q`` as a decimal string.

    Exact when the expansion terminates within ``places`` digits (all digits
    when ``places`` is None and the expansion terminates); otherwise rounded
    half-even to ``places`` digits (12 when None) and marked with ``…``.

    Examples
    --------
    >>> format_decimal(Fraction("-0.500"))
    '-0.5'
    >>> format_decimal(Fraction(300))
    '300'
    >>> format_decimal(Fraction(2, 3), places=3)
    '0.667…'
    """
    needed = decimal_places(q)
    if needed is not None and (places is None or needed <= places):
        digits = needed
        marker = ""
    else:
        digits = 12 if places is None else places
        marker = "…"
    scaled = q * 10**digits
    n = round(scaled)  # Fraction.__round__ is exact half-even
    sign = "-" if n < 0 else ""
    n = abs(n)
    if digits == 0:
        text = str(n)
    else:
        whole, frac = divmod(n, 10**digits)
        text = f"{whole}.{frac:0{digits}d}"
        if not marker:
            text = text.rstrip("0").rstrip(".")
    if text in ("0", "0.0") and not marker:
        sign = ""
    return f"{sign}{text}{marker}"


def format_rational(q: Fraction) -> str:
    """Write ``q`` exactly as ``"p/q"`` (``"p"`` for an integer); :func:`parse_rational` reads it back.

    >>> format_rational(Fraction(1900, 3)), format_rational(Fraction(-5)), format_rational(Fraction("0.25"))
    ('1900/3', '-5', '1/4')
    """
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


_RATIONAL_RE = re.compile(r"[+-]?\d+(?:/\d+)?\Z")


def parse_rational(text: str) -> Fraction:
    """Read ``"p/q"`` or ``"p"`` (what :func:`format_rational` writes), or a decimal, exactly.

    >>> parse_rational("1900/3"), parse_rational("-0.5")
    (Fraction(1900, 3), Fraction(-1, 2))
    >>> parse_rational("1/0")
    Traceback (most recent call last):
    ...
    nczones.errors.InvalidArgument: '1/0' is not an exact rational: expected p/q with q > 0, or a decimal
    """
    t = text.strip() if isinstance(text, str) else ""
    if _RATIONAL_RE.match(t) and not t.endswith("/0"):
        return Fraction(t)
    if DECIMAL_RE.match(t):
        return parse_decimal(t)
    raise InvalidArgument(f"{text!r} is not an exact rational: expected p/q with q > 0, or a decimal")


def format_exact(q: Fraction) -> str:
    """A terminating decimal as a decimal (``"0.25"``), anything else as ``"p/q"``: exact either way.

    >>> format_exact(Fraction(1, 4)), format_exact(Fraction(1, 3))
    ('0.25', '1/3')
    """
    return format_decimal(q) if is_decimal_fraction(q) else format_rational(q)


def seconds(t: float | Fraction) -> float:
    """A duration as every JSON report writes it: a number of seconds, rounded to the microsecond.

    One format for wall-clock timings (``verify``), simulated time
    (``simulate``) and homing event times (``home``).

    >>> seconds(Fraction(1, 3)), seconds(0.12345678), seconds(2)
    (0.333333, 0.123457, 2.0)
    """
    return round(float(t), 6)


def to_float(q: Fraction) -> float:
    """A float for plots and reports only; never feed it back into a proof."""
    return q.numerator / q.denominator
