"""Where last session's merges of the double pass meet (hunt42): hunt41's generator
(:mod:`tests.contract.test_double_pass_seams41`) with what merged since mixed in, against hunt40's relations.

New in the mix:

* compensated contours with arcs (``double_comp.py`` ``Comp.arc``, ``comp_floats.py``): after the G41/G42 entry,
  lines and G2/G3 arcs by I/J or by R (rational circles: every end exactly on its circle), the contour in G91 or
  in G20 now and then, a ``G64 P Q`` inside it, a cycle right after its G40;
* plane-mix arcs under ``G64 P Q`` with tiny motions between them (1e-5 mm lines, which LinuxCNC's naive CAM
  detector may fold) and tiny arcs (``double_reach.py``: a box grown by one motion's reach);
* cycles in G20 (``double_cycles.py``'s inch hole templates), R equal to the initial level by value (written
  through a parameter), G73/G83 in G91 with Q.

Relations: hunt40's 1-3 (:func:`~tests.contract.test_double_pass_seams40.check_seams`) and 4 (rs274, on programs
without compensation).

CI: 3 mill and 2 rs274 examples (derandomized); ``-m long`` with ``NCZONES_SEAMS42`` examples (default 300).
"""

from __future__ import annotations

import math
import os
from fractions import Fraction

from hypothesis import event
from hypothesis import strategies as st

from tests.contract import test_double_pass_seams41 as s41
from tests.contract.mill_seams import check_rs274_drawn, mill_case, seam_tests
from tests.contract.test_double_pass_seams40 import (
    _UNITS,
    PLANES,
    _q,
    check_seams,
)

CI_EXAMPLES = 3
LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS42", "300"))


def _t(v: Fraction) -> str:
    return f"«{v}»"


def _circle(draw, scale: int = 1) -> tuple[Fraction, tuple, tuple]:
    """(a radius, the start's and the end's unit vectors from the centre): rational points of one circle."""
    u0, u1 = draw(st.sampled_from(_UNITS)), draw(st.sampled_from(_UNITS))
    r = Fraction(draw(st.integers(5, 300)), 10 * scale) * math.lcm(*(c.denominator for c in u0 + u1))
    return r, u0, u1


def _contour_arc(draw, pos: tuple[Fraction, Fraction], incremental: bool) -> tuple[str, tuple]:
    """A G2/G3 from ``pos`` on a rational circle, by I/J or (not near a half circle) by R; its line and end."""
    r, u0, u1 = _circle(draw)
    cx, cy = pos[0] - r * u0[0], pos[1] - r * u0[1]
    end = (cx + r * u1[0], cy + r * u1[1])
    code = draw(st.sampled_from(("G2", "G3")))
    words = (f"X{_t(end[0] - pos[0])} Y{_t(end[1] - pos[1])}" if incremental else
             f"X{_t(end[0])} Y{_t(end[1])}")
    chord = (end[0] - pos[0]) ** 2 + (end[1] - pos[1]) ** 2
    if u0 != u1 and draw(st.booleans()) and chord < 4 * r * r * Fraction(99, 100):
        return f"{code} {words} R{draw(st.sampled_from(('', '-')))}{_t(r)}", end
    return f"{code} {words} I{_t(cx - pos[0])} J{_t(cy - pos[1])}", end


def _comp42(draw, st_: s41._State41, counter: str | None) -> list[str]:
    """A compensated contour (G17) of lines and arcs; G91 or G20 around it now and then (outside a clean
    program), a ``G64 P Q`` in it, a cycle after its G40."""
    side = draw(st.sampled_from(("G41", "G42", "G41.1", "G42.1")))
    tool = {"G41.1": f" D«{draw(st.sampled_from(('1', '2.5', '0.8')))}»", "G42.1": " D«1.5»"}.get(
        side, draw(st.sampled_from((" D1", " D2", ""))))
    x0, y0 = (Fraction(draw(st.integers(-300, 300)), 10) for _ in range(2))
    twist = 0 if st_.clean or st_.one_unit else draw(st.integers(0, 4))
    pos = (x0 + Fraction(draw(st.integers(40, 200)), 10), y0)
    lines = [f"G17 {'G20' if twist == 1 else 'G21'} G90", f"G0 X«{x0}» Y«{y0}»", "T1 M6" if not tool else "",
             f"{side}{tool} G1 X{_t(pos[0])} Y{_t(pos[1])} F200"]
    incremental = twist == 2
    if incremental:
        lines.append("G91")
    for _ in range(draw(st.integers(1, 5))):
        kind = draw(st.integers(0, 5))
        if kind <= 2:
            line, pos = _contour_arc(draw, pos, incremental)
            lines.append(line)
        elif kind == 3 and not st_.clean:
            lines.append(draw(st.sampled_from(s41._MODES41)))
        else:
            d = (Fraction(draw(st.integers(-200, 200)), 10), Fraction(draw(st.integers(-200, 200)), 10))
            words = d if incremental else (pos[0] + d[0], pos[1] + d[1])
            pos = (pos[0] + d[0], pos[1] + d[1])
            lines.append(f"G1 X{_t(words[0])} Y{_t(words[1])}")
    lines += [f"G90 G40 G0 X«{x0}» Y«{y0 - 30}»", f"G{st_.plane}", "G21" if twist == 1 else ""]
    if twist == 3 and st_.cycles:
        lines += cycles42(draw, st_, counter)
    return [line for line in lines if line]


def _tiny_mix(draw, st_: s41._State41, counter: str | None) -> list[str]:
    """Under ``G64 P Q``: arcs in changing planes with tiny motions between them (a 1e-5 line, a tiny arc)."""
    lines = [draw(st.sampled_from(s41._MODES41))]
    for _ in range(draw(st.integers(1, 3))):
        plane = draw(st.sampled_from((17, 18, 19)))
        st_.plane = plane
        a, b, n, i, j = PLANES[plane]
        r, u0, u1 = _circle(draw, draw(st.sampled_from((1, 1, 1000))))
        cx, cy = (Fraction(draw(st.integers(-300, 300)), 10) for _ in range(2))
        code = draw(st.sampled_from(("G2", "G3")))
        lines += [f"G{plane}", f"G90 G1 {a}{_t(cx + r * u0[0])} {b}{_t(cy + r * u0[1])}",
                  f"{code} {a}{_t(cx + r * u1[0])} {b}{_t(cy + r * u1[1])} {i}{_t(-r * u0[0])} {j}{_t(-r * u0[1])}"]
        tiny = Fraction(draw(st.sampled_from((1, 5, 10, 100))), 10**5)
        axis = draw(st.sampled_from((a, b, n)))
        mark = " (tiny)" if tiny < Fraction(1, 1000) else ""  # below rs274's log's resolution: check_rs274_any
        lines.append(draw(st.sampled_from((f"G91 G1 {axis}{_t(tiny)}", f"G91 G1 {axis}{_t(-tiny)}",
                                           f"G91 G0 {axis}{_t(tiny)}"))) + mark)
        lines.append("G90")
    return lines


def cycles42(draw, st_: s41._State41, counter: str | None) -> list[str]:
    """G20 around a cycle, R equal to the initial level by value, or G73/G83 in G91 with Q."""
    a, b, n, _i, _j = PLANES[st_.plane]
    kind = draw(st.integers(0, 2))
    code = draw(st.sampled_from(("G81", "G82", "G83", "G73", "G85", "G86", "G89")))
    extra = {"G73": f" Q{_q(draw, 1, 40)}", "G83": f" Q{_q(draw, 1, 40)}", "G82": " P0.5", "G89": " P0.25"}.get(
        code, "")
    retract = draw(st.sampled_from(("G98", "G99")))
    if kind == 2:  # G91, Q
        code = draw(st.sampled_from(("G73", "G83")))
        r, z = Fraction(-draw(st.integers(0, 150)), 10), Fraction(-draw(st.integers(1, 150)), 10)
        return ["M3 S1000", f"G90 G0 {n}«{Fraction(draw(st.integers(0, 300)), 10)}»",
                f"G91 {retract} {code} {a}{_q(draw, -100, 100)} {b}{_q(draw, -100, 100)} {n}«{z}» R«{r}» "
                f"Q{_q(draw, 1, 40)}" + (f" L{draw(st.integers(1, 3))}" if draw(st.booleans()) else ""),
                *[f"{a}{_q(draw, -50, 50)}" for _ in range(draw(st.integers(0, 2)))], "G80", "G90"]
    level = Fraction(draw(st.integers(0, 200)), 10)
    bottom = level - Fraction(draw(st.integers(1, 200)), 10)
    if kind == 1:  # R equal to the level by value, written through a parameter
        r = f"[#3 + {_t(level / 2)}]"
        pre = [f"#3 = [{_t(level)} - {_t(level / 2)}]"]
    else:
        r, pre = _t(bottom + Fraction(draw(st.integers(1, 100)), 10)), []
    inch = kind == 0 and not st_.one_unit
    lines = ["G20" if inch else "", *pre, "M3 S1000", f"G90 G0 {n}{_t(level)}",
             f"{retract} {code} {a}{s41._value(draw, st_, counter)} {b}{_q(draw)} {n}{_t(bottom)} R{r}{extra}"]
    lines += [f"{a}{s41._value(draw, st_, counter)}" for _ in range(draw(st.integers(0, 2)))]
    return [line for line in [*lines, "G80", "G21" if inch else ""] if line]


def _statement(draw, st_: s41._State41, depth: int, counter: str | None) -> list[str]:
    kind = draw(st.integers(0, 9))
    if kind <= 2 and st_.comp:
        return _comp42(draw, st_, counter)
    if kind == 3 and st_.arcs and not st_.clean:
        return _tiny_mix(draw, st_, counter)
    if kind == 4 and st_.cycles and not st_.clean:
        return cycles42(draw, st_, counter)
    return _base(draw, st_, depth, counter)


_base = s41._statement


def seam42_programs(one_unit: bool = False, comp: bool = False) -> st.SearchStrategy[str]:
    """hunt41's mill programs with :func:`_statement`'s statements among theirs."""
    return s41.programs_with(_statement, one_unit=one_unit, comp=comp)


def check_any(data, units: str | None = None) -> None:
    """Relations 1-3 on a drawn mill program (compensated half the time, one unit a quarter of the time)."""
    template, values, units = mill_case(data, seam42_programs, units)
    event(check_seams(template, "xyz_range_seams", values, data.draw, units))


def check_rs274_any(data, workdir) -> None:
    """Relation 4 on a drawn program without compensation (``mill_seams.check_rs274_drawn``)."""
    check_rs274_drawn(data, workdir, seam42_programs)


(test_mill_seams42_agree_with_the_full_path, test_the_pass_is_rs274s_motion_at_the_seams42, test_seams42_long,
 test_rs274_seams42_long) = seam_tests(check_any, check_rs274_any, CI_EXAMPLES, LONG_EXAMPLES)
