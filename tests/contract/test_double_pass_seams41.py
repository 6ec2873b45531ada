"""Where last session's new lanes of the double pass meet (hunt41): hunt40's generator
(:mod:`tests.contract.test_double_pass_seams40`) with the features merged since mixed in, against the same oracles.

New in the mix (each beside hunt40's G20/G21 switches, G91 chains, arcs, cycles, loops, subs, offsets, tools):

* cutter compensation (``double_comp.py``): a G41/G42 contour (``D1``, ``D2``, no D, or G41.1/G42.1 with a
  diameter) over straight moves in G17 G90, its entry from a rapid, a G40 and a move away; next to G91 chains and
  G20 switches (which the pass declines in a program that writes compensation: the full path decides), or, half
  the time, in a program the pass may take (no G20, G91 or cycle; G90 arcs, dwells, tool changes, path modes),
  on the mill with ``cutter_compensation = "linuxcnc"`` (and ``[tool_diameters]`` T1 2, T2 1.5) half the time;
* ``G64 P p Q q`` (in a block of its own, or with a move: the pass declines that Q) among the path modes;
* the cycles ``double_cycles.py`` added: G73 (Q), G84 (after M3, or not), G85, G86 (spindle on or off), G89 (P),
  with ``L`` repeats, in G90 or G91 (R from the initial level, the bottom from R), in G17/G18/G19;
* arcs in G91 in each plane, and plane switches between arcs (``double_arcs.py`` plane slots, ``chain_offb``);
* on a lathe: G7/G8 arcs in G91 too (an X increment halved in G7; I and K never).

Relations: hunt40's 1-3 (:func:`~tests.contract.test_double_pass_seams40.check_seams`: the routed verdict is the
full path's, the pass's rows enclose the full path's motion, translation, margin and the other unit) and 4
(rs274, on programs without compensation: rs274's setup has no tool diameters).

CI: 4 mill, 2 lathe, 2 one-unit and 4 rs274 examples (derandomized); ``-m long`` with ``NCZONES_SEAMS41``
examples (default 300) per test.
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import event, given, settings
from hypothesis import strategies as st

from tests.contract.test_double_pass_seams40 import (
    _SETTINGS,
    LATHE_OFFSETS,
    PLANES,
    _arc,
    _cycle,
    _mill,
    _q,
    _setting,
    _State,
    _straight,
    _value,
    check_rs274,
    check_seams,
)
from tests.gcode.rs274_pass import NEEDS_RS274

CI_EXAMPLES = 4
LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS41", "300"))


class _State41(_State):
    """hunt40's state, and whether the program may write compensation (the mill's machine then has it)."""

    def __init__(self, plane: int, lathe: bool, one_unit: bool, comp: bool, **kw):
        super().__init__(plane, lathe, one_unit, **kw)
        self.comp = comp
        #: a compensated program the pass may take: no G20, G91 or cycle anywhere (its compile check)
        self.clean = False


def _comp(draw, st_: _State41, counter: str | None) -> list[str]:
    """A compensated contour in G17 G21 G90: a rapid to the entry's start, G41/G42 with a feed move (longer than
    the radius), 1-4 feed moves (a loop's counter in one now and then), G40 with a move away, back to the plane.
    Outside a clean program, now and then the contour's moves in G91 or the whole contour in G20 (the pass's
    compile check declines both: the full path decides)."""
    side = draw(st.sampled_from(("G41", "G42", "G41", "G42", "G41.1", "G42.1")))
    tool = {"G41.1": f" D«{draw(st.sampled_from(('1', '2.5', '0.8')))}»", "G42.1": " D«1.5»"}.get(
        side, draw(st.sampled_from((" D1", " D2", ""))))
    x0, y0 = (Fraction(draw(st.integers(-300, 300)), 10) for _ in range(2))
    twist = 0 if st_.clean or st_.one_unit else draw(st.integers(0, 3))
    lines = [f"G17 {'G20' if twist == 1 else 'G21'} G90", f"G0 X«{x0}» Y«{y0}»", "T1 M6" if not tool else "",
             f"{side}{tool} G1 X«{x0 + Fraction(draw(st.integers(40, 200)), 10)}» Y«{y0}» F200"]
    if twist == 2:
        lines.append("G91")
    for _ in range(draw(st.integers(1, 4))):
        axes = draw(st.lists(st.sampled_from("XY"), min_size=1, max_size=2, unique=True))
        lines.append("G1 " + " ".join(f"{a}{_value(draw, st_, counter)}" for a in axes))
    lines += [f"G90 G40 G0 X«{x0}» Y«{y0 - 30}»", f"G{st_.plane}", "G21" if twist == 1 else ""]
    return [line for line in lines if line]


def _cycle41(draw, st_: _State41, counter: str | None) -> list[str]:
    """A cycle of the codes the pass took last session (G73 Q, G84, G85, G86, G89 P), L repeats, G90 or G91."""
    a, b, n, _i, _j = PLANES[st_.plane]
    code = draw(st.sampled_from(("G73", "G84", "G85", "G86", "G89", "G81", "G82", "G83")))
    extra = {"G73": f" Q{_q(draw, 1, 40)}", "G83": f" Q{_q(draw, 1, 40)}", "G82": " P0.5", "G89": " P0.25"}.get(
        code, "")
    repeats = f" L{draw(st.integers(1, 4))}" if draw(st.booleans()) else ""
    spindle = draw(st.sampled_from(("M3 S1000", "M3 S1000", "M5", "M4 S500")))
    retract = draw(st.sampled_from(("G98", "G99")))
    lines = [spindle, f"G90 G0 {n}«{Fraction(draw(st.integers(0, 300)), 10)}»"]
    if draw(st.booleans()):  # G91: R below the initial level, the bottom below R; the holes' increments
        r, z = Fraction(-draw(st.integers(1, 150)), 10), Fraction(-draw(st.integers(1, 150)), 10)
        lines.append(f"G91 {retract} {code} {a}{_q(draw, -100, 100)} {b}{_q(draw, -100, 100)} {n}«{z}» R«{r}»"
                     f"{extra}{repeats}")
        lines += [f"{a}{_q(draw, -50, 50)}{repeats}" for _ in range(draw(st.integers(0, 2)))]
        return lines + ["G80", "G90"]
    bottom = Fraction(draw(st.integers(-200, 0)), 10)
    r = bottom + Fraction(draw(st.integers(1, 150)), 10)
    lines.append(f"{retract} {code} {a}{_value(draw, st_, counter)} {b}{_q(draw)} {n}«{bottom}» R«{r}»{extra}"
                 f"{repeats}")
    lines += [f"{a}{_value(draw, st_, counter)}" for _ in range(draw(st.integers(0, 2)))]
    return lines + ["G80"]


def _planes(draw, st_: _State41, counter: str | None) -> list[str]:
    """A plane switch, then an arc in the new plane (G91 half the time: hunt40's ``_arc`` draws it 1 in 8)."""
    plane = draw(st.sampled_from((17, 18, 19)))
    st_.plane = plane
    if draw(st.booleans()):
        return [f"G{plane}", *_arc(draw, st_, counter)]
    a, b, _n, i, j = PLANES[plane]
    sx, sy = Fraction(draw(st.integers(-100, 100)), 10), Fraction(draw(st.integers(-100, 100)), 10)
    r = Fraction(draw(st.integers(5, 200)), 10)
    code = draw(st.sampled_from(("G2", "G3")))
    # a G91 arc from where the tool is: a half or a full circle about a centre r away along the first axis
    end = f"{a}«{2 * r}» {b}«0»" if draw(st.booleans()) else ""
    return [f"G{plane}", f"G91 G1 {a}«{sx}» {b}«{sy}»", f"{code} {end} {i}«{r}» {j}«0»".replace("  ", " "), "G90"]


def _lathe_arc(draw, st_: _State41, counter: str | None) -> list[str]:
    """On a lathe: a G91 arc in G7 or G8 (X increments halved in G7, K and I not), from where the tool is."""
    mode = draw(st.sampled_from(("G7", "G8")))
    r = Fraction(draw(st.integers(5, 50)), 10)
    half = 2 if mode == "G7" else 1
    code = draw(st.sampled_from(("G2", "G3")))
    return [f"{mode} G90 G1 X«{Fraction(draw(st.integers(20, 120)), 10) * half}» Z«{_frac(draw)}»",
            f"G91 {code} X«{2 * r * half}» Z«0» K«0» I«{r}»", "G90"]


def _frac(draw) -> Fraction:
    return Fraction(draw(st.integers(-300, 300)), 10)


#: the settings of a clean compensated program (:attr:`_State41.clean`)
_CLEAN = ("G4 P0.5", "G54", "G55", "F200", "M3 S1000", "M5", "#1 = [#1 + «0.5»]", "G61", "G64", "G64 P«0.01»",
          "T2 M6", "G43 H1", "G49", "G61.1", "#2 = [#1 * 0.5]")
_MODES41 = ("G64 P«0.01» Q«0.005»", "G64 P«0.05» Q«0.2»", "G64 P«0.002» Q«0»", "G64 P«0.1» Q«0.1»")


def _statement(draw, st_: _State41, depth: int, counter: str | None) -> list[str]:
    kind = draw(st.integers(0, 13 if depth else 10))
    if st_.clean:
        if 5 <= kind <= 9 and kind != 6:
            return [draw(st.sampled_from(_CLEAN))]
        if kind in (2, 3):
            lines = _arc(draw, st_, counter)
            return _straight(draw, st_, counter) if any("G91" in line for line in lines) else lines
    if kind <= 1:
        return _straight(draw, st_, counter)
    if kind == 2:
        return _arc(draw, st_, counter) if st_.arcs else _straight(draw, st_, counter)
    if kind == 3:
        if st_.lathe:
            return _lathe_arc(draw, st_, counter) if st_.arcs else _straight(draw, st_, counter)
        return _planes(draw, st_, counter) if st_.arcs else _straight(draw, st_, counter)
    if kind == 4 and st_.comp:
        return _comp(draw, st_, counter)
    if kind == 5 and not st_.lathe and st_.cycles:
        return _cycle41(draw, st_, counter) if draw(st.integers(0, 2)) else _cycle(draw, st_, counter)
    if kind == 6:
        return [draw(st.sampled_from(_MODES41))]
    if kind <= 9:
        return _setting(draw, st_, counter)
    if kind == 10 and st_.subs:
        return [f"o<{draw(st.sampled_from(st_.subs))}> call [{_q(draw)}]"]
    if kind <= 12 and depth:  # a counted loop
        label = st_.label()
        c = f"#{10 + depth}"
        body = [line for _ in range(draw(st.integers(1, 3))) for line in _statement(draw, st_, depth - 1, c)]
        times = draw(st.sampled_from((0, 1, 2, 3, 12 if depth == 2 else 3)))
        return [f"{c} = 0", f"o{label} while [{c} LT {times}]", *body, f"{c} = [{c} + 1]", f"o{label} endwhile"]
    if depth:  # an if on a parameter
        label = st_.label()
        body = _statement(draw, st_, depth - 1, counter)
        return [f"o{label} if [#1 GT «1»]", *body, f"o{label} else", *_straight(draw, st_, counter), f"o{label} endif"]
    return _straight(draw, st_, counter)


@st.composite
def seam41_programs(draw, lathe: bool = False, one_unit: bool = False, comp: bool = False) -> str:
    """A program template (hunt40's ``seam_programs`` header and lengths as ``«q»`` tokens) with the statements
    above; ``comp``: compensated contours (for the mill whose machine has compensation)."""
    plane = 18 if lathe else draw(st.sampled_from((17, 17, 18, 19)))
    st_ = _State41(plane, lathe, one_unit, comp and not lathe, arcs=draw(st.integers(0, 3)) > 0,
                   cycles=draw(st.booleans()))
    st_.clean = st_.comp and draw(st.booleans())
    head = []
    for words in (("G21", "G21", "G20"), ("G90", "G90", "G91"), (f"G{plane}",), ("G54", "G55", "G56")):
        if st_.clean and words[0] in ("G21", "G90"):
            words = words[:1]
        if draw(st.integers(0, 3)) or (one_unit and words[0] == "G21") or st_.clean:
            head.append("{UNITS}" if one_unit and words[0] == "G21" else draw(st.sampled_from(words)))
    head.append(draw(st.sampled_from(("F300 G64 P«0.01» Q«0.01»", "F300", "F300 G64 P«0.5»", "F300 G61"))))
    lines = [f"(seams40 G{plane})", " ".join(head), f"#1 = {_q(draw)}", f"#2 = {_q(draw)}"]
    if draw(st.integers(0, 2)) == 0:
        body = [line for _ in range(draw(st.integers(1, 3))) for line in _statement(draw, st_, 0, None)]
        st_.subs.append("s1")
        st_.plane = plane
        lines[2:2] = ["o<s1> sub", *body, "o<s1> endsub"]
    for _ in range(draw(st.integers(1, 6))):
        lines += _statement(draw, st_, 2, None)
    lines.append(draw(st.sampled_from(("M30", "M2"))))
    return "\n".join(lines) + "\n"


@st.composite
def programs_with(draw, statement, one_unit: bool = False, comp: bool = False) -> str:
    """hunt41's mill programs (:func:`seam41_programs`) whose statements ``statement(draw, st_, depth, counter)``
    draws (falling back to hunt41's own as it likes): the loops and ifs here draw their bodies through the
    module's name ``_statement``, set to it for the draw.  hunt42's and hunt43's generators draw theirs here."""
    global _statement
    base = _statement
    _statement = statement
    try:
        return draw(seam41_programs(one_unit=one_unit, comp=comp))
    finally:
        _statement = base


def _check(data, lathe: bool = False, one_unit: bool = False, units: str = "G21") -> None:
    draw = data.draw
    comp = not lathe and not one_unit and draw(st.booleans())
    template = draw(seam41_programs(lathe=lathe, one_unit=one_unit, comp=comp))
    base = "report_lathe" if lathe else "xyz_range_seams"
    values = LATHE_OFFSETS if lathe else _mill(draw, template)
    if comp:
        modal = [g for g in values.get("machine.modal", ()) if g not in ("G20", "G91")]
        values = {**values, "machine.cutter_compensation": "linuxcnc", "machine.modal": modal}
    event(check_seams(template, base, values, draw, units))


@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data())
def test_mill_seams41_agree_with_the_full_path(data):
    _check(data)


@settings(max_examples=CI_EXAMPLES // 2, derandomize=True, **_SETTINGS)
@given(st.data())
def test_lathe_seams41_agree_with_the_full_path(data):
    _check(data, lathe=True)


@settings(max_examples=CI_EXAMPLES // 2, derandomize=True, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")))
def test_one_unit_seams41_keep_their_verdict_in_the_other_unit(data, units):
    _check(data, one_unit=True, units=units)


@NEEDS_RS274
@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")))
def test_the_pass_is_rs274s_motion_at_the_seams41(tmp_path_factory, data, units):
    template = data.draw(seam41_programs(one_unit=data.draw(st.booleans())))
    event(check_rs274(template, units, tmp_path_factory.mktemp("rs274")))


@pytest.mark.long
@NEEDS_RS274
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")))
def test_rs274_seams41_long(tmp_path_factory, data, units):
    template = data.draw(seam41_programs(one_unit=data.draw(st.booleans())))
    event(check_rs274(template, units, tmp_path_factory.mktemp("rs274")))


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")), st.integers(0, 3))
def test_seams41_long(data, units, kind):
    _check(data, lathe=kind == 0, one_unit=kind == 1, units=units)
