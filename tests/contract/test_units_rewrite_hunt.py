"""The inch <-> mm rewrite of a LinuxCNC program with G64 P Q corners keeps the verdict (hunt36).

A program written in inches (every length ``v``) and the same program in millimetres (every length ``25.4 v``,
exact decimals) move the machine along the same path in the same path mode, so with exact numbers the verdict
is the same, in every lane: the short program (the exact path), after 600 motions (the vectorized tier) and with
'#' in the text (the double pass).  The programs start in the other unit and switch, in the block of the G64 or
in the block before it; corners of lines (and at times an R arc) next to a small forbidden probe.  The relation
found ``G20 G64 P`` in one block read in the old units (the inch version ``safe``, the mm one ``unknown``: 17 of
60 programs before the fix).  CI: a few examples; ``-m long``: ``UNITS_EXAMPLES["long"]``.
"""

from __future__ import annotations

from fractions import Fraction
from unittest import mock

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.machine import parse_machine
from nczones.prover import verify_text

UNITS_EXAMPLES = {"ci": 4, "long": 600}
OUTCOMES: dict[str, int] = {}
INCH = Fraction(254, 10)


def _machine(probe: tuple[str, ...]):
    return parse_machine(
        '[machine]\nname = "units"\naxes = ["X", "Y", "Z"]\n[machine.rapid]\nX = "10000"\nY = "10000"\n'
        'Z = "10000"\n[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n[[zones]]\nname = "travel"\nkind = "box"\n'
        'min = {{ X = "-300", Y = "-300", Z = "-100" }}\nmax = {{ X = "300", Y = "300", Z = "100" }}\n[[zones]]\n'
        'name = "probe"\nkind = "box"\nforbid = true\n'
        'min = {{ X = "{}", Y = "{}", Z = "-1" }}\nmax = {{ X = "{}", Y = "{}", Z = "1" }}\n'.format(*probe))


def _dec(q: Fraction) -> str:
    for k in range(12):
        if (q * 10**k).denominator == 1:
            n = int(q * 10**k)
            t = str(abs(n)).rjust(k + 1, "0")
            return ("-" if n < 0 else "") + (t[:-k] + "." + t[-k:] if k else t)
    raise ValueError(q)


def program(inch: bool, pts, p: Fraction, q: Fraction | None, same: bool, arc: bool, lane: str) -> str:
    """``pts``, ``p``, ``q`` in inches; written in inches (``inch``) or millimetres."""
    u = Fraction(1) if inch else INCH
    unit = "G20" if inch else "G21"
    mode = f"G64 P{_dec(p * u)}" + (f" Q{_dec(q * u)}" if q is not None else "")
    lines = ["G21" if inch else "G20", "G17 G90 G61 F10"] + ([f"{unit} {mode}"] if same else [unit, mode])
    if lane == "double pass":
        lines.append("#1 = 0")
    if lane != "short":
        lines += [f"G1 X0 Y{_dec(-k % 2 * Fraction(1, 100) * u)}" for k in range(600)]
    lines.append("G1 X0 Y0")
    for k, (x, y) in enumerate(pts):
        lines.append(f"G2 X{_dec(x * u)} Y{_dec(y * u)} R{_dec(3 * u)}" if arc and k == 1 else
                     f"G1 X{_dec(x * u)} Y{_dec(y * u)}")
    return "\n".join(lines + ["G61", "G1 X0 Y0", "M2"]) + "\n"


_P = st.tuples(st.integers(-2000, 2000), st.integers(-2000, 2000))


def _examples() -> int:
    return UNITS_EXAMPLES["long" if settings.default.max_examples > 100 else "ci"]


def test_inch_and_mm_programs_decide_alike():
    @settings(max_examples=_examples(), deadline=None)
    @given(st.lists(_P, min_size=3, max_size=3), st.sampled_from([1, 5, 10, 40]),
           st.sampled_from([None, 0, 2]), st.booleans(), st.booleans(),
           st.tuples(st.integers(-300, 300), st.integers(-300, 300)),
           st.sampled_from(["short", "vectorized", "double pass"]))
    def run(raw, p, q, same, arc, off, lane):
        pts = [(Fraction(x, 1000), Fraction(y, 1000)) for x, y in raw]
        # a 0.2 mm probe near the first corner (mm), not around the start
        cx, cy = pts[0][0] * INCH + Fraction(off[0], 100), pts[0][1] * INCH + Fraction(off[1], 100)
        if abs(cx) <= Fraction(1, 10) and abs(cy) <= Fraction(1, 10):
            return
        d = Fraction(1, 10)
        probe = tuple(_dec(v) for v in (cx - d, cy - d, cx + d, cy + d))
        got = {}
        for inch in (True, False):
            text = program(inch, pts, Fraction(p, 1000), None if q is None else Fraction(q, 1000), same, arc, lane)
            try:
                got[inch] = verify_text(text, _machine(probe)).verdict.label
            except GcodeError as exc:  # an R arc too short for its chord: refused alike in both units
                got[inch] = type(exc).__name__
        OUTCOMES[got[True]] = OUTCOMES.get(got[True], 0) + 1
        assert got[True] == got[False], (got, program(True, pts, Fraction(p, 1000), q, same, arc, lane))

    run()


@pytest.mark.long
def test_units_hunt_long():
    OUTCOMES.clear()
    with mock.patch.dict(UNITS_EXAMPLES, {"ci": UNITS_EXAMPLES["long"]}):
        test_inch_and_mm_programs_decide_alike()
    print(f"units hunt: {sorted(OUTCOMES.items())}")
