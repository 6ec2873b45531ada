"""Numbers people read in reports (text and HTML); JSON keeps the exact values.

* A coordinate that is an exact decimal of at most 12 places is written exactly, as short as it
  is (``X110 Y60``, ``Z189.05``).
* Any other value (a repeating decimal, or the rational enclosure of an irrational point such as a
  helix's) is rounded to the machine's resolution on that axis (the places of its ``pulse``) and
  marked ``≈`` (``Z≈242.097``); without a machine, to 6 places.
* A depth is written to the pulse length: exact when it is a short exact decimal, otherwise rounded
  *down* when it is a lower bound (so ``at least``/``≥`` stays true) and marked ``≈`` when exact but
  long.

>>> from fractions import Fraction as F
>>> coord(F(110)), coord(F("189.05")), coord(F(2, 3), F("0.001")), coord(F(110) - F(1, 10**20), F("0.0005"))
('110', '189.05', '≈0.667', '≈110')
>>> depth(F(6786885245901, 10**12), False, F("0.001")), depth(F(19, 10)), depth(F(1, 3), True, F("0.001"))
('6.786', '1.9', '≈0.333')
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from fractions import Fraction

from ..exact import decimal_places, format_decimal

__all__ = ["coord", "point", "depth", "resolution_of", "checked_in_words", "program_point"]

#: the most places an exact decimal is written with
EXACT_PLACES = 12
#: places of a rounded value when the machine's resolution is not known
DEFAULT_PLACES = 6


def _places(step: Fraction | None) -> int:
    if step is None or step <= 0:
        return DEFAULT_PLACES
    p = decimal_places(step)
    return DEFAULT_PLACES if p is None else p


def _short(q: Fraction) -> str | None:
    p = decimal_places(q)
    return format_decimal(q) if p is not None and p <= EXACT_PLACES else None


def coord(q: Fraction, step: Fraction | None = None) -> str:
    """One coordinate: exact when short, else ``≈`` and rounded (half-even) to ``step``'s places."""
    exact = _short(q)
    if exact is not None:
        return exact
    places = _places(step)
    return "≈" + format_decimal(Fraction(round(q * 10**places), 10**places))


def point(pairs: Iterable[tuple[str, Fraction]], resolution: Mapping[str, Fraction] | None = None) -> str:
    """``X110 Y60 Z≈242.097``: each axis to its own resolution."""
    res = resolution or {}
    return " ".join(f"{a}{coord(v, res.get(a))}" for a, v in pairs)


def program_point(v: object, resolution: Mapping[str, Fraction] | None = None) -> str | None:
    """A violation's point in the program's coordinates, as people read it, with its frame:
    ``X62 Z-60.95 (program coordinates: G54, X as diameter)``; None when the report has no program point
    (:attr:`nczones.prover.Violation.point_program`).  A diameter axis is written to twice its pulse, an
    inch program to 6 places; a rotated frame's point is marked approximate."""
    pp = getattr(v, "point_program", None)
    frame = getattr(v, "frame", None)
    if pp is None or frame is None:
        return None
    res: dict[str, Fraction] = {}
    if not frame.inch:
        res = {a: (2 * r if a in frame.diameter else r) for a, r in (resolution or {}).items()}
    text = point(pp, res)
    how = frame.describe() + ("" if frame.exact else "; approximate: the control rounds the rotation")
    return f"{text} (program coordinates: {how})"


def depth(q: Fraction, exact: bool = True, step: Fraction | None = None) -> str:
    """A depth to the pulse length (see the module docstring)."""
    short = _short(q)
    if short is not None and exact:
        return short
    places = _places(step)
    scale = 10**places
    if not exact:  # a lower bound: round down so the bound stays true
        return format_decimal(Fraction(math.floor(q * scale), scale))
    return "≈" + format_decimal(Fraction(round(q * scale), scale))


def resolution_of(machine: object) -> dict[str, Fraction]:
    """Axis -> pulse of a machine (its resolution); {} when not a machine."""
    return {a.name: a.pulse for a in getattr(machine, "axes", ()) if hasattr(a, "pulse")}


def depth_step(resolution: Mapping[str, Fraction] | None) -> Fraction | None:
    """The pulse a depth is written to: the finest of the axes'."""
    return min(resolution.values()) if resolution else None


_WORDS = (
    ("segments", "{n} motion segment{s} checked"),
    ("pieces", "{n} piece{s} (rapids split as the machine moves them)"),
    ("screened", "{n} proved by the fast screen"),
    ("exact_decided", "{n} decided by exact arithmetic"),
    ("z3_segments", "{n} sent to the solver"),
    ("z3_queries", "{n} solver quer{ies}"),
    ("arc_pieces", "{n} arc piece{s} examined"),
    ("arc_pieces_proved", "{n} arc piece{s} proved"),
    ("arc_enclosures", "{n} arc enclosure{s}"),
    ("refined_pieces", "{n} piece{s} refined (split and tried again)"),
    ("budget_undecided", "{n} left undecided when the budget was spent"),
    ("recovery_motions", "{n} recovery motion{s}"),
    ("recovery_proved_legs", "{n} recovery leg{s} proved"),
    ("recovery_queries", "{n} recovery solver quer{ies}"),
    ("double_pass_boxes", "{n} box{es} of the double pass"),
    ("fanuc_boxes", "{n} box{es} of the Fanuc box route (no numpy)"),
    ("fast_lines", "{n} line{s} by the vectorized path"),
)


def checked_in_words(stats: Mapping[str, object]) -> str:
    """The "Checked" row of a report in words (no internal keys); counters the reader does not need at 0
    are left out, an unknown counter keeps its key with underscores as spaces.

    >>> checked_in_words({"segments": 40, "pieces": 40, "screened": 30, "exact_decided": 1, "z3_segments": 0})
    '40 motion segments checked: 30 proved by the fast screen, 1 decided by exact arithmetic'
    """
    words = dict(_WORDS)
    counts = {k: v for k, v in stats.items() if isinstance(v, int) and not isinstance(v, bool)}
    if not counts:
        return "—"

    def say(key: str, n: int) -> str:
        if key not in words:
            return f"{key.replace('_', ' ')} {n}"
        one = n == 1
        return words[key].format(n=f"{n:,}", s="" if one else "s", ies="y" if one else "ies",
                                 es="" if one else "es")

    head = say("segments", counts.pop("segments", 0))
    counts.pop("pieces", None)  # an internal split, the same as segments but for doglegs
    order = {k: i for i, (k, _) in enumerate(_WORDS)}
    rest = [say(k, counts[k]) for k in sorted((k for k in counts if counts[k]), key=lambda k: order.get(k, 99))]
    return head + (": " + ", ".join(rest) if rest else "")
