"""The exact core: decimal text as exact rationals, and enclosures of what is irrational.

Everything the proofs rest on lives here, once, below every other module of nczones:

* :mod:`nczones.exact.decimals` — decimal text becomes an exact
  ``Fraction``, never a float (:func:`parse_decimal`, :func:`exact`) and is
  written back (:func:`format_decimal`, :func:`format_rational`, ...).
* :mod:`nczones.exact.interval` — the one outward-rounded rational
  :class:`Interval`, its roundings, square roots (:func:`sqrt_interval`,
  :func:`is_square`) and the None-aware :func:`max_bound`/:func:`min_bound`.
* :mod:`nczones.exact.elementary` — π (:func:`pi_interval`), arctangent
  (:func:`atan_interval`, :func:`atan2_interval`), arcsine, sine and cosine in
  radians (:func:`sin_cos_interval`) and in degrees (:func:`sin_cos_degrees`);
  imported at the first use of one of its names here (PEP 562: ``import nczones``
  and a verify that proves no arc load none of it, issue 36).

Each enclosure contains the exact real value (the argument is in each
docstring; ``tests/exact/test_exact_core.py`` checks them against mpmath).

>>> parse_decimal("0.1") + parse_decimal("0.2") == parse_decimal("0.3")
True
>>> from nczones.exact import pi_interval
>>> p = pi_interval()
>>> Fraction("3.14159265358979323846264338327950288419716939937510") < p.lo <= p.hi < Fraction("3.1415926535897932384626433832795028841971693993751059")
True
"""

from __future__ import annotations

from .decimals import (
    DECIMAL_RE,
    MAX_ABS_LENGTH,
    Fraction,
    decimal_places,
    exact,
    exact_or_none,
    format_decimal,
    format_exact,
    format_rational,
    is_decimal_fraction,
    parse_decimal,
    parse_rational,
    seconds,
    to_float,
)
from .interval import (
    GRID_BITS,
    Bounds,
    Interval,
    is_square,
    max_bound,
    min_bound,
    round_down,
    round_down_scaled,
    round_up,
    round_up_scaled,
    sqrt_interval,
)

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from .elementary import (
        asin_interval,
        atan2_interval,
        atan_interval,
        atan_range,
        degrees,
        pi_interval,
        radians,
        sin_cos_degrees,
        sin_cos_interval,
    )

#: The names of :mod:`nczones.exact.elementary` given here, imported at their first use (:func:`__getattr__`).
_ELEMENTARY = frozenset(("asin_interval", "atan2_interval", "atan_interval", "atan_range", "degrees", "pi_interval",
                         "radians", "sin_cos_degrees", "sin_cos_interval"))


def __getattr__(name: str) -> Any:
    """A name of :mod:`nczones.exact.elementary`, imported at its first use (then kept here)."""
    if name not in _ELEMENTARY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from . import elementary

    value = getattr(elementary, name)
    globals()[name] = value
    return value


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
    "GRID_BITS",
    "Interval",
    "Bounds",
    "round_down_scaled",
    "round_up_scaled",
    "round_down",
    "round_up",
    "max_bound",
    "min_bound",
    "is_square",
    "sqrt_interval",
    "pi_interval",
    "atan_interval",
    "atan_range",
    "atan2_interval",
    "asin_interval",
    "sin_cos_interval",
    "sin_cos_degrees",
    "degrees",
    "radians",
]
