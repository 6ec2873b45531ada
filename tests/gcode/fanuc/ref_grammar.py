"""A grammar of Fanuc mill programs (Hypothesis strategies) for the reference differential
(tests/oracles/fanuc_ref.py against nczones's Fanuc interpreter).

Each production says which codes of specs/fanuc.md it writes (``PRODUCTIONS``: production name -> codes);
``tests/gcode/fanuc/test_reference_differential.py::test_grammar_covers_every_modelled_code`` parses
specs/fanuc.md and fails when a code it marks modelled has no production.

The generator keeps to programs whose meaning the manual fixes.  The classes of issue 33 are fixed and
written: G43/G44/G49 with a Z word in G91 (class 1), a bare H in G43/G44 mode (2), G92 in G91 (3), lathe
G50 while a tool offset is active (4, ``lathe_programs``), ``/1``..``/9`` (5: the differential draws which
switches are on), M00/M01 (6), G92.1 with axis words, G84.2/G84.3 with K, G51 P without a decimal point,
transforms in G20 (the reference findings N1-N4).  ``p_closures`` writes lines that run again for the compiled
closures of nczones/gcode/fanuc/expr.py (a G65 macro looping over its locals with SIN/COS/TAN/ATAN/SQRT/ABS/
FUP/FIX/ROUND/MOD, comparisons, a nested WHILE and IF, called with L, or from a WHILE loop with computed arguments
beside an M98), keeping away from the divergences listed there (finding N5).  Repeat counts stay small (L, K at most 3: class 7's
bounds are tested in tests/gcode/fanuc/test_stops_and_bounds.py; the reference reader is slow).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

from hypothesis import strategies as st

#: production -> the codes (as specs/fanuc.md writes them) it can write.
PRODUCTIONS: dict[str, set[str]] = {
    "header": {"%", "O", "G17", "G20", "G21", "G40", "G80", "G90", "G94"},
    "move": {"G00", "G01", "G90", "G91", "N", ";", "( )", "G95", "G61", "G64"},
    "arc": {"G02", "G03"},
    "tool_length": {"G43", "G44", "G49"},
    "work": {"G54", "G55", "G56", "G57", "G58", "G59", "G54.1"},
    "g10": {"G10"},
    "g52": {"G52"},
    "g92": {"G92", "G92.1"},
    "g53": {"G53"},
    "reference": {"G28", "G30"},
    "dwell": {"G04"},
    "cycle": {"G73", "G74", "G76", "G81", "G82", "G83", "G84", "G84.2", "G84.3", "G85", "G86", "G89", "G98", "G99",
              "G80"},
    "macro": {"#", "IF", "GOTO", "WHILE", "DO", "END"},
    "m98": {"M98", "M99"},
    "g65": {"G65"},
    "g66": {"G66", "G67"},
    "skip": {"/"},
    "mcodes": {"M00", "M01", "M03", "M05", "M06", "M08", "M09", "M30"},
    "end": {"M02", "M30"},
    "planes": {"G18", "G19", "G17"},
    "g27_g29": {"G27", "G29"},
    "g33": {"G33"},
    "g93": {"G93", "G94"},
    "scaling": {"G50", "G51"},
    "mirror": {"G50.1", "G51.1"},
    "rotation": {"G68", "G69"},
    "polar": {"G15", "G16"},
    "m97": {"M97", "M99"},
    "m99p": {"M98", "M99"},
    "state_read": {"#5001", "#5021", "#4003", "#4001"},
    "g91_work": {"G54", "G55", "G91"},
    "cycle_tl": {"G43", "G81", "G83"},
    "vacant": {"#"},
    "computed_g": {"G"},
    "plain_run": {"G01"},
    "closures": {"G65", "M98", "M99", "WHILE", "DO", "END", "IF", "#"},
}

CYCLES = ("73", "74", "76", "81", "82", "83", "84", "84.2", "84.3", "85", "86", "89")


@dataclass
class GenState:
    absolute: bool = True
    inch: bool = False
    tl: bool = False  # a tool length offset is active
    tl_mode: int = 49  # the group 08 code in force (G43, G44, G49)
    g92: bool = False
    g52: bool = False
    lines: list = field(default_factory=list)
    subs: list = field(default_factory=list)  # (number, body lines)
    next_sub: int = 100
    next_label: int = 1000
    local_subs: list = field(default_factory=list)  # M97 targets: lines after M30 of the main program
    depth: int = 0  # call nesting while generating
    vars: int = 0


def _lit(draw, lo: int, hi: int, *, inch: bool, decimals=None) -> str:
    """A length literal: with a decimal point (0-3 decimals, 0-4 in inch) or an integer (DPI decides)."""
    d = draw(st.integers(0, 4 if inch else 3)) if decimals is None else decimals
    scale = 10 ** d
    n = draw(st.integers(lo * scale, hi * scale))
    if d == 0:
        return f"{n}." if draw(st.booleans()) else str(n)
    q = Fraction(n, scale)
    sign = "-" if q < 0 else ""
    q = abs(q)
    whole = q.numerator // q.denominator
    frac = q - whole
    digits = str(int(frac * scale)).rjust(d, "0")
    return f"{sign}{whole}.{digits}"


def _value(draw, st_: GenState, lo: int, hi: int) -> str:
    """A value: a literal, a common variable set just before, or an expression (Macro B doubles)."""
    inch = st_.inch
    if inch:
        lo, hi = lo // 10, max(hi // 10, 1)
    kind = draw(st.sampled_from(["lit", "lit", "lit", "var", "expr"]))
    if kind == "lit":
        return _lit(draw, lo, hi, inch=inch)
    a = _lit(draw, lo, hi, inch=inch, decimals=draw(st.integers(1, 3)))
    if kind == "var":
        n = 100 + draw(st.integers(0, 9))
        st_.lines.append(f"#{n} = {a}")
        return draw(st.sampled_from([f"#{n}", f"-#{n}", f"[#{n}]"]))
    b = _lit(draw, 0, 5, inch=inch, decimals=draw(st.integers(1, 3)))
    op = draw(st.sampled_from(["+", "-", "*2 +", "ROUND", "FIX"]))
    if op == "ROUND":
        return f"[ROUND[{a}] + {b}]"
    if op == "FIX":
        return f"[FIX[{a}] - {b}]"
    if op == "*2 +":
        return f"[{a} * 2 + {b}]"
    return f"[{a} {op} {b}]"


def _axes(draw, st_: GenState, letters="XYZ", *, lo=-40, hi=40, need=1) -> str:
    chosen = draw(st.lists(st.sampled_from(letters), min_size=need, max_size=len(letters), unique=True))
    chosen.sort(key=letters.index)
    return " ".join(f"{a}{_value(draw, st_, lo, hi)}" for a in chosen)


def _dist(draw, st_: GenState) -> str:
    c = draw(st.sampled_from(["", "", "G90", "G91"]))
    if c == "G90":
        st_.absolute = True
    elif c == "G91":
        st_.absolute = False
    return c


def p_move(draw, st_: GenState, *, allow_z=True):
    d = _dist(draw, st_)
    g = draw(st.sampled_from(["G00", "G01", "G0", "G1"]))
    letters = "XYZ" if allow_z else "XY"
    axes = _axes(draw, st_, letters)
    extra = draw(st.sampled_from(["", "", " F200.", " G95 F0.1 ", " G94 F300", " G61", " G64"]))
    n = draw(st.sampled_from(["", "", f"N{draw(st.integers(1, 99))} "]))
    comment = draw(st.sampled_from(["", "", " (move)", " ;"]))
    st_.lines.append(f"{n}{d} {g} {axes}{extra}{comment}".strip())


def p_arc(draw, st_: GenState):
    r = draw(st.integers(2, 9))
    dx = draw(st.integers(1, 2 * r - 1))
    g = draw(st.sampled_from(["G02", "G03"]))
    st_.absolute = False
    if draw(st.booleans()):
        rr = draw(st.sampled_from([f"R{r}.", f"R-{r}."]))
        st_.lines.append(f"G91 {g} X{dx}. Y0 {rr} F100.")
    else:
        # a half circle: the centre half way
        st_.lines.append(f"G91 {g} X{2 * r}. Y0 I{r}. J0 F100.")


def p_tool_length(draw, st_: GenState):
    h = draw(st.integers(0, 2))
    # a bare H in G43/G44 mode changes the offset (class 2)
    code = draw(st.sampled_from(["G43", "G44", "G49"] + (["", ""] if st_.tl_mode in (43, 44) else [])))
    hw = "" if code == "G49" else f" H{h}"
    z = ""
    if draw(st.booleans()):
        # G90 or G91 (class 1: in G91 the axis moves by the increment plus the change of offset)
        g9 = draw(st.sampled_from(["G90", "G91"]))
        st_.absolute = g9 == "G90"
        z = f" {g9} Z{_value(draw, st_, -20, 60) if st_.absolute else _value(draw, st_, -20, 20)}"
    g = draw(st.sampled_from(["G00", "G01 F500."]))
    st_.lines.append(f"{g} {code}{hw}{z}".replace("  ", " "))
    if code:
        st_.tl_mode = int(code[1:])
    st_.tl = st_.tl_mode != 49 and h != 0


def p_work(draw, st_: GenState):
    c = draw(st.sampled_from(["G54", "G55", "G56", "G54.1 P3", "G54.1 P1", "G57", "G58", "G59"]))
    tail = ""
    if draw(st.booleans()):
        st_.absolute = True
        tail = " G90 G00 " + _axes(draw, st_, "XY")
    st_.lines.append(f"{c}{tail}")


def p_g10(draw, st_: GenState):
    d = _dist(draw, st_)
    kind = draw(st.sampled_from(["L2", "L20", "L10", "L11"]))
    if kind == "L2":
        st_.lines.append(f"{d} G10 L2 P{draw(st.integers(0, 6))} {_axes(draw, st_, 'XYZ', lo=-300, hi=300)}")
    elif kind == "L20":
        st_.lines.append(f"{d} G10 L20 P{draw(st.integers(1, 3))} {_axes(draw, st_, 'XYZ', lo=-300, hi=300)}")
    else:
        st_.lines.append(f"{d} G10 {kind} P{draw(st.integers(1, 2))} R{_value(draw, st_, 0, 150)}")
        # a changed length takes effect at the next G43/G44 (specs/fanuc.md; the reader does the same)
        if st_.tl and draw(st.booleans()):
            st_.lines.append("G49")
            st_.tl = False
            st_.tl_mode = 49


def p_g52(draw, st_: GenState):
    if st_.g92:
        return
    st_.absolute = True
    st_.g52 = True
    st_.lines.append("G90 G52 " + _axes(draw, st_, "XYZ", lo=-20, hi=20))


def p_g92(draw, st_: GenState):
    if st_.g52:
        return
    if draw(st.integers(0, 3)) == 0 and st_.g92:
        # G92.1 (the preset's format "G92.1 IP 0": the axis words do not move, finding N1)
        st_.lines.append(draw(st.sampled_from(["G92.1", "G92.1 X0 Y0 Z0", "G92.1 X0"])))
        return
    d = draw(st.sampled_from(["G90", "G91"]))  # G92 in G91 (class 3): the increment adds to the reading
    st_.absolute = d == "G90"
    st_.g92 = True
    st_.lines.append(f"{d} G92 " + _axes(draw, st_, "XYZ", lo=-20, hi=20))


def p_g53(draw, st_: GenState):
    st_.absolute = True
    st_.lines.append("G90 G53 G00 " + _axes(draw, st_, "XYZ", lo=-200, hi=200))


def p_reference(draw, st_: GenState):
    d = _dist(draw, st_)
    c = draw(st.sampled_from(["G28", "G30 P2", "G30"]))
    st_.lines.append(f"{d} {c} " + _axes(draw, st_, "XY" if st_.tl else "XYZ", lo=-20, hi=20))


def p_dwell(draw, st_: GenState):
    st_.lines.append(draw(st.sampled_from(["G04 P500", "G04 X1.5", "G4 P10"])))


def p_cycle(draw, st_: GenState):
    c = draw(st.sampled_from(CYCLES))
    ret = draw(st.sampled_from(["G98", "G99"]))
    d = _dist(draw, st_)
    if st_.absolute:
        r = _value(draw, st_, 0, 10)
        z = _value(draw, st_, -30, -1)
    else:
        r = _value(draw, st_, -10, -1)
        z = _value(draw, st_, -20, -1)
    q = f" Q{_lit(draw, 1, 6, inch=st_.inch, decimals=1)}" if c in ("73", "76", "83") else ""
    p = " P200" if c in ("76", "82", "89", "74", "84") and draw(st.booleans()) else ""
    # small K only (the reference reader is slow); G84.2/G84.3 too (finding N3)
    k = draw(st.sampled_from(["", "", " K2", " K3", " K1", " K#121", " K[#121 + 1]"]))
    if "#121" in k:
        st_.lines.append(f"#121 = {draw(st.sampled_from(['0.5', '1.5', '2.5', '1.4', '0.49', '2.0']))}")
    st_.lines.append(f"{d} {ret} G{c} {_axes(draw, st_, 'XY', need=0)} R{r} Z{z}{q}{p}{k} F100.".replace("  ", " "))
    for _ in range(draw(st.integers(0, 3))):
        more = _axes(draw, st_, "XY")
        kk = draw(st.sampled_from(["", "", " K2", " K0"])) if c not in ("84.2", "84.3") else ""
        st_.lines.append(f"{more}{kk}")
    st_.lines.append(draw(st.sampled_from(["G80", "G00", "G80 G00"])))


def p_macro(draw, st_: GenState):
    kind = draw(st.sampled_from(["assign", "if_goto", "while", "if_then"]))
    n = 100 + draw(st.integers(0, 9))
    if kind == "assign":
        st_.lines.append(f"#{n} = {_value(draw, st_, -20, 20)}")
    elif kind == "if_then":
        st_.lines.append(f"#{n} = {draw(st.integers(0, 3))}")
        st_.lines.append(f"IF [#{n} {draw(st.sampled_from(['GT', 'EQ', 'LE', 'NE']))} 1] THEN #{n + 10} = "
                         f"{_lit(draw, -10, 10, inch=st_.inch, decimals=2)}")
        st_.lines.append(f"G91 G01 X#{n + 10} F100.")
        st_.absolute = False
    elif kind == "if_goto":
        lab = st_.next_label
        st_.next_label += 1
        st_.lines.append(f"#{n} = {draw(st.integers(0, 3))}")
        st_.lines.append(f"IF [#{n} {draw(st.sampled_from(['GT', 'EQ', 'LT', 'GE']))} 1] GOTO {lab}")
        _body(draw, st_, 1, safe=True)
        st_.lines.append(f"N{lab} G91 G00 X1.")
        st_.absolute = False
    else:
        st_.vars += 1
        cnt = 150 + st_.vars % 10
        m = 1
        st_.lines.append(f"#{cnt} = 0")
        st_.lines.append(f"WHILE [#{cnt} LT {draw(st.integers(1, 3))}] DO{m}")
        st_.lines.append(f"G91 G01 X{_lit(draw, -5, 5, inch=st_.inch)} Y#{cnt} F100.")
        st_.absolute = False
        _body(draw, st_, draw(st.integers(0, 1)), safe=True)
        st_.lines.append(f"#{cnt} = #{cnt} + 1")
        st_.lines.append(f"END{m}")


def _sub_body(draw, st_: GenState, args: bool) -> list:
    """A subprogram / macro body: explicit distance mode in each block, no offset changes."""
    saved = st_.lines
    st_.lines = []
    for _ in range(draw(st.integers(1, 3))):
        d = draw(st.sampled_from(["G90", "G91"]))
        st_.absolute = d == "G90"
        if args:
            w = draw(st.sampled_from(["X#24", "Y#25", "X[#24 / 2]", "Y-#25", "X#1 Y#2", "Z[#26 + 1]"]))
            st_.lines.append(f"{d} G01 {w} F100.")
        else:
            st_.lines.append(f"{d} G01 {_axes(draw, st_, 'XYZ' if d == 'G91' else 'XY')} F100.")
    body, st_.lines = st_.lines, saved
    return body


def p_m98(draw, st_: GenState):
    if st_.depth:
        return
    num = st_.next_sub
    st_.next_sub += 1
    st_.depth += 1
    body = _sub_body(draw, st_, args=False)
    st_.depth -= 1
    st_.subs.append((num, body + ["M99"]))
    form = draw(st.sampled_from(["L", "P", "none", "computed"]))
    if form == "computed":
        st_.lines.append(f"#120 = {draw(st.sampled_from(['0.5', '1.5', '2.5', '1.4', '2.49', '0.6', '1.0']))}")
        st_.lines.append(f"M98 P{num} L#120")
    elif form == "L":
        st_.lines.append(f"M98 P{num} L{draw(st.integers(0, 3))}")
    elif form == "P":
        st_.lines.append(f"M98 P{draw(st.integers(1, 3))}{num:04d}")
    else:
        st_.lines.append(f"M98 P{num}")


def p_g65(draw, st_: GenState):
    if st_.depth:
        return
    num = 9000 + st_.next_sub
    st_.next_sub += 1
    body = _sub_body(draw, st_, args=True)
    st_.subs.append((num, body + ["M99"]))
    args = " ".join(f"{a}{_lit(draw, -10, 10, inch=st_.inch, decimals=draw(st.integers(1, 3)))}"
                    for a in ("A", "B", "X", "Y", "Z"))
    L = draw(st.sampled_from(["", " L2", " L#122"]))
    if L == " L#122":
        st_.lines.append(f"#122 = {draw(st.sampled_from(['0.5', '1.5', '1.49', '0.7']))}")
    st_.lines.append(f"G65 P{num}{L} {args}")


def p_g66(draw, st_: GenState):
    if st_.depth:
        return
    num = 9000 + st_.next_sub
    st_.next_sub += 1
    # the macro drills: down by R at feed and back at rapid, in the caller's distance mode restored
    st_.subs.append((num, ["#30 = #4003", "G91 G01 Z-#18 F100.", "G00 Z#18", "G#30", "M99"]))
    st_.lines.append(f"G66 P{num} R{_lit(draw, 1, 5, inch=st_.inch, decimals=1)}")
    for _ in range(draw(st.integers(1, 3))):
        d = _dist(draw, st_)
        st_.lines.append(f"{d} G00 {_axes(draw, st_, 'XY')}")
    st_.lines.append("G67")


def p_skip(draw, st_: GenState):
    saved = st_.lines
    st_.lines = []
    p_move(draw, st_, allow_z=not st_.tl or True)
    lines, st_.lines = st_.lines, saved
    # '/' (switch 1) or '/1'..'/9' (class 5); the differential draws which switches are on
    sw = draw(st.sampled_from(["", "", "1", "2", "3", "9"]))
    st_.lines.extend(f"/{sw}" + ln if i == len(lines) - 1 else ln for i, ln in enumerate(lines))
    # the distance mode after a skipped block is either: make it explicit again
    st_.lines.append(draw(st.sampled_from(["G90", "G91"])))
    st_.absolute = st_.lines[-1] == "G90"


def p_mcodes(draw, st_: GenState):
    st_.lines.append(draw(st.sampled_from(["M03 S1000", "M05", "M08", "M09", "T2 M06", "M00", "M01",
                                           f"G91 G00 X{_lit(draw, -5, 5, inch=st_.inch)} M01"])))
    if st_.lines[-1].startswith("G91"):
        st_.absolute = False


def p_planes(draw, st_: GenState):
    plane = draw(st.sampled_from(["G18", "G19"]))
    d = _dist(draw, st_)
    letters = "XZ" if plane == "G18" else "YZ"
    st_.lines.append(f"{plane} {d} G01 {_axes(draw, st_, letters)} F200.")
    if draw(st.booleans()):
        # an R arc in that plane (G91: the chord shorter than the diameter)
        a, b = letters
        st_.absolute = False
        st_.lines.append(f"G91 G02 {a}3. {b}0 R2. F100.")
    st_.lines.append("G17")


def p_g27_g29(draw, st_: GenState):
    if st_.tl:
        return
    st_.absolute = True
    st_.lines.append(f"G90 G27 {_axes(draw, st_, 'XY')}")
    st_.lines.append(f"G90 G28 X{_value(draw, st_, -20, 20)} Y{_value(draw, st_, -20, 20)}")
    st_.lines.append(f"G29 {_axes(draw, st_, 'XY')}")


def p_g33(draw, st_: GenState):
    d = _dist(draw, st_)
    st_.lines.append(f"{d} G33 Z{_value(draw, st_, -10, 10)} F1.5")
    st_.lines.append("G00")


def p_g93(draw, st_: GenState):
    d = _dist(draw, st_)
    st_.lines.append(f"{d} G93 G01 {_axes(draw, st_)} F2.")
    st_.lines.append("G94 F500.")


def _transform_moves(draw, st_: GenState) -> None:
    for _ in range(draw(st.integers(1, 3))):
        g = draw(st.sampled_from(["G00", "G01"]))
        z = f" Z{_value(draw, st_, -10, 10)}" if draw(st.booleans()) else ""
        st_.lines.append(f"G90 {g} X{_value(draw, st_, -30, 30)} Y{_value(draw, st_, -30, 30)}{z}")


def p_scaling(draw, st_: GenState):
    st_.absolute = True
    # P without a decimal point is in scaling_unit (0.001) on every lane (finding N4)
    p = draw(st.sampled_from(["P2.", "P0.5", "P1.5", "P1.25", "P3.", "P2000", "P500", "P3"]))
    st_.lines.append(f"G90 G51 X{_value(draw, st_, -10, 10)} Y{_value(draw, st_, -10, 10)} {p}")
    _transform_moves(draw, st_)
    st_.lines.append("G50")
    _transform_moves(draw, st_)


def p_mirror(draw, st_: GenState):
    st_.absolute = True
    st_.lines.append(f"G90 G51.1 {_axes(draw, st_, 'XY', lo=-10, hi=10)}")
    _transform_moves(draw, st_)
    st_.lines.append(draw(st.sampled_from(["G50.1 X0 Y0", "G50.1"])))
    _transform_moves(draw, st_)


def p_rotation(draw, st_: GenState):
    st_.absolute = True
    r = draw(st.sampled_from(["90.", "180.", "270.", "-90.", "0."]))
    st_.lines.append(f"G90 G68 X{_value(draw, st_, -10, 10)} Y{_value(draw, st_, -10, 10)} R{r}")
    _transform_moves(draw, st_)
    st_.lines.append("G69")
    _transform_moves(draw, st_)


def p_polar(draw, st_: GenState):
    st_.absolute = True
    st_.lines.append("G90 G16")
    for _ in range(draw(st.integers(1, 3))):
        a = draw(st.sampled_from(["0.", "90.", "180.", "270.", "-90.", "450."]))
        st_.lines.append(f"G01 X{_value(draw, st_, 0, 30)} Y{a}")
    st_.lines.append("G15")
    _transform_moves(draw, st_)


def p_m97(draw, st_: GenState):
    if st_.depth:
        return
    lab = st_.next_label
    st_.next_label += 1
    st_.local_subs.append(f"N{lab} G91 G01 X{_lit(draw, -5, 5, inch=st_.inch, decimals=1)} "
                          f"Y{_lit(draw, -5, 5, inch=st_.inch, decimals=1)} F100.")
    st_.local_subs.append("M99")
    st_.lines.append(f"M97 P{lab}" + draw(st.sampled_from(["", " L2"])))
    st_.absolute = False


def p_m99p(draw, st_: GenState):
    if st_.depth:
        return
    num = st_.next_sub
    st_.next_sub += 1
    lab = st_.next_label
    st_.next_label += 1
    st_.subs.append((num, [f"G91 G01 X{_lit(draw, -5, 5, inch=st_.inch, decimals=1)} F100.", f"M99 P{lab}"]))
    st_.lines.append(f"M98 P{num}")
    st_.lines.append("G91 G01 Y7. F100.")  # jumped over by M99 P
    st_.lines.append(f"N{lab} G91 G01 X1. F100.")
    st_.absolute = False


def p_state_read(draw, st_: GenState):
    n = 100 + draw(st.integers(0, 9))
    var = draw(st.sampled_from(["#5001", "#5002", "#5003", "#5021", "#5022", "#5023"]))
    st_.lines.append(f"#{n} = {var} + {_lit(draw, -5, 5, inch=st_.inch, decimals=2)}")
    axis = "XYZ"[int(var[-1]) - 1]
    if var.startswith("#502"):
        # a machine position: back to the workpiece system through the offsets is not this test's point;
        # use it only as a number in an incremental move
        st_.absolute = False
        st_.lines.append(f"G91 G01 {axis}[[#{n} - {var}] * 2] F100.")
    else:
        st_.absolute = True
        st_.lines.append(f"G90 G01 {axis}#{n} F100.")
    if draw(st.booleans()):
        st_.lines.append(f"IF [#4003 EQ 91] THEN #{n} = 1.5")
        st_.lines.append(f"IF [#4001 EQ 1] THEN #{n} = #{n} + 1.")
        st_.lines.append(f"G91 G00 X#{n}")
        st_.absolute = False


def p_g91_work(draw, st_: GenState):
    st_.absolute = False
    c = draw(st.sampled_from(["G54", "G55", "G54.1 P3", "G56"]))
    st_.lines.append(f"G91 {c} G00 {_axes(draw, st_, 'XY' if st_.tl else 'XYZ', lo=-10, hi=10)}")


def p_cycle_tl(draw, st_: GenState):
    st_.absolute = True
    h = draw(st.sampled_from(["G43 H1", "G43 H2", "G44 H1", "G49"]))
    st_.lines.append(f"G90 G00 {h} Z{_value(draw, st_, 20, 60)}")
    st_.tl = h != "G49"
    st_.tl_mode = int(h[1:3])
    c = draw(st.sampled_from(["G81", "G83 Q2.", "G82 P100", "G73 Q1.5"]))
    ret = draw(st.sampled_from(["G98", "G99"]))
    st_.lines.append(f"{ret} {c} X{_value(draw, st_, -10, 10)} Y{_value(draw, st_, -10, 10)} "
                     f"R{_value(draw, st_, 1, 5)} Z{_value(draw, st_, -15, -1)} F100.")
    if draw(st.booleans()):
        st_.lines.append(f"X{_value(draw, st_, -10, 10)}")
    st_.lines.append("G80")


def p_vacant(draw, st_: GenState):
    d = _dist(draw, st_)
    n = 130 + draw(st.integers(0, 5))  # #130-#135 are never assigned: vacant, the word is dropped
    st_.lines.append(f"{d} G01 X#{n} Y{_value(draw, st_, -20, 20)} Z-#{n} F100.")


def p_computed_g(draw, st_: GenState):
    code = draw(st.sampled_from(["90", "91"]))
    st_.absolute = code == "90"
    st_.lines.append(f"#140 = {code}")
    st_.lines.append(f"#141 = {draw(st.sampled_from(['0', '1']))}")
    st_.lines.append(f"G#140 G[#141] {_axes(draw, st_, 'XY')} F100.")


def p_plain_run(draw, st_: GenState, *, force: bool = False):
    """A run of more than 512 plain G01 lines (decimal literals only): the vectorized fast path's tier
    (tests/gcode/fanuc/test_fastpath.py holds it to the full path; here both to the reference)."""
    if not force and draw(st.integers(0, 9)) != 0:
        return
    import random

    rnd = random.Random(draw(st.integers(0, 2**32 - 1)))
    n = rnd.randint(513, 560)
    g91 = draw(st.booleans())
    st_.absolute = not g91
    st_.lines.append("G91 G01 F300." if g91 else "G90 G01 F300.")
    span = 3 if g91 else 40
    for _ in range(n):
        axes = rnd.sample("XYZ", rnd.randint(1, 3))
        st_.lines.append(" ".join(f"{a}{rnd.randint(-span, span)}.{rnd.randint(0, 999):03d}" for a in "XYZ"
                                  if a in axes))


#: x and y of the closure macro's points (locals: #1 passes, #2 a length, #3 an angle step, #10 the pass)
#: (``#2 * 1.5 - #10`` and ``#2 * SIN[30.] + #10`` can be a half increment in exact arithmetic whose double lies
#: just under it, as 1.5 * 1.017: where the readings of the double split nczones says unknown, GC399, and the
#: comparison skips the program; where they agree nczones must move as the reference, which reads 15 digits;
#: test_reference_findings.py, N5)
_CLOSURE_X = ("#2 * COS[#10 * #3]", "[#2 + #10] * TAN[#3 / 2]", "SQRT[#2 * #2 + #10]", "ABS[#10 - 1.5] * 2 * #2",
              "FUP[#2 * #10 / 3]", "ATAN[#10 + 1]/[#2] / 10", "FIX[#2 * 1.7] - #10", "[#10 MOD 2] + #2",
              "ROUND[#2 / 3 * #10]", "#2 * 2 * #10", "-#2 + #10 * 0.5", "#2 * 1.5 - #10")
_CLOSURE_Y = ("#2 * SIN[#10 * #3] + 1", "#2 * COS[#3] - #10", "ATAN[#2, #10 + 1] / 20", "SQRT[ABS[#2 - #10]]",
              "#10 * #2 / 7", "[#2 - FUP[#10 / 2]] * 2", "#10 + 0.25", "#2 * SIN[30.] + #10")
#: the loop's condition on the pass #10 and the count #1
#: (no relations joined by AND/OR: nczones joins ``#1 GT 0 AND #2 LT 5`` as specs/fanuc.md writes it and refuses a
#: relation inside brackets, the reference reads AND/OR by the operators' precedence and joins bracketed ones)
_CLOSURE_WHILE = ("#10 LT #1", "#10 LE [#1 - 1]", "#1 GT #10", "#10 NE #1", "#10 - #1 LT 0", "#1 - #10 GE 1",
                  "[#10 + 1] * #2 LE #1 * #2")


def _closure_macro(draw, st_: GenState) -> int:
    """A G65 macro that loops over its local variables with functions (the compiled closures of
    nczones/gcode/fanuc/expr.py: locals with a number, SIN/COS, doubles only in conditions), a nested loop and an
    IF; its number."""
    num = 9000 + st_.next_sub
    st_.next_sub += 1
    fx, fy = draw(st.sampled_from(_CLOSURE_X)), draw(st.sampled_from(_CLOSURE_Y))
    # the length and the step come as B and C or, from the loop below, as Z and X (#26, #24)
    body = ["IF [#2 EQ #0] THEN #2 = #26", "IF [#3 EQ #0] THEN #3 = #24", "#10 = 0", f"WHILE [{draw(st.sampled_from(_CLOSURE_WHILE))}] DO2", f"#12 = {fx}", f"#14 = {fy}",
            f"IF [#10 EQ {draw(st.integers(0, 2))}] THEN #14 = #14 + {draw(st.sampled_from(['0.5', '1', '-2.25']))}",
            "G90 G01 X#12 Y#14 F100."]
    if draw(st.booleans()):
        body += ["#15 = 0", "WHILE [#15 LT 2] DO3", "G91 G01 Z[#15 * 0.5 - 0.25]", "#15 = #15 + 1", "END3"]
    body += ["#10 = #10 + 1", "END2", "M99"]
    st_.subs.append((num, body))
    return num


def p_closures(draw, st_: GenState):
    """Lines that run again: a G65 macro of :func:`_closure_macro` called once, L2 times or from a WHILE loop of
    the main program (with expressions as its arguments, an M98 subprogram beside it).  An argument computed by an
    expression is an integer (A) or a length on the increment's grid (X, Z): the reference rounds a computed
    argument of another letter to an integer, nczones to the increment (the manuals say neither)."""
    if st_.depth:
        return
    num = _closure_macro(draw, st_)
    # no step whose multiples (the loop's #10 * #3, #3 up to 3 steps) reach 30, 120 or 150 degrees: SIN[30] is the
    # double 0.49999999999999994, and a length times it can lie just under a half increment, where nczones says
    # unknown (GC399; _CLOSURE_Y draws #2 * SIN[30.] on purpose) and the comparison is skipped
    # (test_reference_findings.py, N5; and TAN[90] is 1.6e16)
    step = draw(st.sampled_from(["45.", "22.5", "36.", "72.5", "17.5", "54."]))
    r = _lit(draw, 1, 20, inch=st_.inch, decimals=draw(st.integers(1, 3)))
    if draw(st.booleans()):
        # A with a decimal point: in the increment setting an argument without one is a count of increments in
        # nczones (specs/fanuc.md, ADP), which the reference does not model
        st_.lines.append(f"G65 P{num}{draw(st.sampled_from(['', ' L2']))} A{draw(st.integers(1, 3))}. B{r} C{step}")
    else:
        sub = st_.next_sub
        st_.next_sub += 1
        st_.subs.append((sub, [f"G91 G01 X{_lit(draw, -3, 3, inch=st_.inch, decimals=1)} F100.", "M99"]))
        st_.lines += ["#150 = 0", f"WHILE [#150 LT {draw(st.integers(1, 3))}] DO1",
                      f"G65 P{num} A[#150 + 1] Z[{r} - #150 * 2] X[{step} * [#150 + 1]]", f"M98 P{sub}",
                      "#150 = #150 + 1", "END1"]
    st_.absolute = False  # the macro's last motion block is in G90 or G91: say it again
    st_.lines.append(draw(st.sampled_from(["G90", "G91"])))
    st_.absolute = st_.lines[-1] == "G90"


GENERATORS = {"move": p_move, "arc": p_arc, "tool_length": p_tool_length, "work": p_work, "g10": p_g10,
              "g52": p_g52, "g92": p_g92, "g53": p_g53, "reference": p_reference, "dwell": p_dwell,
              "cycle": p_cycle, "macro": p_macro, "m98": p_m98, "g65": p_g65, "g66": p_g66,
              "skip": p_skip, "mcodes": p_mcodes, "planes": p_planes, "g27_g29": p_g27_g29, "g33": p_g33,
              "g93": p_g93, "scaling": p_scaling, "mirror": p_mirror, "rotation": p_rotation, "polar": p_polar,
              "m97": p_m97, "m99p": p_m99p, "state_read": p_state_read, "g91_work": p_g91_work,
              "cycle_tl": p_cycle_tl, "vacant": p_vacant, "computed_g": p_computed_g, "plain_run": p_plain_run,
              "closures": p_closures}
SAFE = ("move", "arc", "dwell", "mcodes")


def _body(draw, st_: GenState, n: int, safe=False):
    names = SAFE if safe else tuple(GENERATORS)
    for _ in range(n):
        GENERATORS[draw(st.sampled_from(names))](draw, st_)


@st.composite
def fanuc_programs(draw, max_statements: int = 8):
    """``(text, inch)``: a main program O0001 and its subprograms/macros."""
    st_ = GenState(inch=draw(st.booleans()) if draw(st.integers(0, 4)) == 0 else False)
    st_.lines.append("%")
    st_.lines.append("O0001")
    st_.lines.append("G20" if st_.inch else "G21")
    st_.lines.append("G90 G17 G40 G49 G80 G94 G54 F500.")
    st_.lines.append("G00 " + _axes(draw, st_, "XYZ", need=3, lo=-10, hi=10))
    _body(draw, st_, draw(st.integers(1, max_statements)))
    st_.lines.append(draw(st.sampled_from(["M30", "M30", "M02"])))
    st_.lines.extend(st_.local_subs)
    for num, body in st_.subs:
        st_.lines.append(f"O{num:04d}")
        st_.lines.extend(body)
    st_.lines.append("%")
    return "\n".join(st_.lines) + "\n"


@st.composite
def closure_programs(draw, max_statements: int = 3):
    """A main program of :func:`p_closures` statements (and straight moves between them): the compiled closures'
    share of :func:`fanuc_programs`, drawn alone."""
    st_ = GenState(inch=draw(st.integers(0, 4)) == 0)
    st_.lines += ["%", "O0001", "G20" if st_.inch else "G21", "G90 G17 G40 G49 G80 G94 G54 F500.", "G00 X0 Y0 Z0"]
    for _ in range(draw(st.integers(1, max_statements))):
        p_closures(draw, st_)
        if draw(st.booleans()):
            p_move(draw, st_)
    st_.lines.append("M30")
    for num, body in st_.subs:
        st_.lines.append(f"O{num:04d}")
        st_.lines.extend(body)
    st_.lines.append("%")
    return "\n".join(st_.lines) + "\n"


# ------------------------------------------------------------------------------------------------ lathe

LATHE_PRODUCTIONS: dict[str, set[str]] = {
    "lathe_move": {"G00", "G01", "X", "Z", "U", "W"},
    "lathe_arc": {"G02", "G03"},
    "lathe_tool": {"T"},
    "lathe_g50": {"G50"},
    "lathe_cycle": {"G90", "G92", "G94"},
    "lathe_g32": {"G32"},
    "lathe_work": {"G54", "G55"},
    "lathe_g28": {"G28"},
}


def _lathe_xz(draw, st_: GenState, *, both: bool = False) -> str:
    words = []
    x = draw(st.sampled_from(["X", "U", ""])) if not both else draw(st.sampled_from(["X", "U"]))
    z = draw(st.sampled_from(["Z", "W", ""])) if not both else draw(st.sampled_from(["Z", "W"]))
    if not x and not z:
        x = "X"
    if x:
        lo, hi = (0, 120) if x == "X" else (-20, 20)
        words.append(f"{x}{_value(draw, st_, lo, hi)}")
    if z:
        lo, hi = (-60, 60) if z == "Z" else (-20, 20)
        words.append(f"{z}{_value(draw, st_, lo, hi)}")
    return " ".join(words)


@st.composite
def lathe_programs(draw, max_statements: int = 8):
    """A Fanuc lathe program (G code system A, X diameters)."""
    st_ = GenState()
    st_.lines += ["%", "O0002", "G21", "G18 G40 G97 G99 G54 F0.2"]
    must_both = False
    for _ in range(draw(st.integers(1, max_statements))):
        kind = draw(st.sampled_from(sorted(LATHE_PRODUCTIONS)))
        if kind == "lathe_move" or must_both:
            g = draw(st.sampled_from(["G00", "G01", "G0", "G1"]))
            st_.lines.append(f"{g} {_lathe_xz(draw, st_, both=must_both)}")
            must_both = False
        elif kind == "lathe_arc":
            r = draw(st.integers(3, 9))
            g = draw(st.sampled_from(["G02", "G03"]))
            st_.lines.append(f"{g} U{2 * draw(st.integers(1, r))}. W-{draw(st.integers(1, r))}. R{r}.")
        elif kind == "lathe_tool":
            st_.lines.append(draw(st.sampled_from(["T0101", "T0202", "T0303", "T0102", "T101", "T0203"])))
            must_both = True  # LGT = 0: the shift is taken by the next move; name both axes
        elif kind == "lathe_g50":
            # also while a tool offset is active (class 4: the position before offset reads the values)
            st_.lines.append(f"G50 X{_lit(draw, 100, 400, inch=False)} Z{_lit(draw, 100, 500, inch=False)}")
        elif kind == "lathe_cycle":
            c = draw(st.sampled_from(["G90", "G94", "G92"]))
            f = "F1.5" if c == "G92" else "F0.2"
            st_.lines.append(f"G00 X{_lit(draw, 60, 120, inch=False)} Z{_lit(draw, 5, 20, inch=False)}")
            st_.lines.append(f"{c} X{_lit(draw, 20, 58, inch=False)} Z{_lit(draw, -40, 0, inch=False)} {f}")
            for _ in range(draw(st.integers(0, 2))):
                st_.lines.append(draw(st.sampled_from([f"X{_lit(draw, 20, 58, inch=False)}",
                                                       f"Z{_lit(draw, -40, 0, inch=False)}"])))
            st_.lines.append("G00")
        elif kind == "lathe_g32":
            st_.lines.append(f"G32 W{_lit(draw, -20, -1, inch=False)} F1.5")
            st_.lines.append("G00")
        elif kind == "lathe_work":
            st_.lines.append(draw(st.sampled_from(["G54", "G55"])))
            must_both = True
        elif kind == "lathe_g28":
            st_.lines.append(draw(st.sampled_from(["G28 U0. W0.", "G28 U0.", "G28 W0."])))
            must_both = True
    st_.lines += ["M30", "%"]
    return "\n".join(st_.lines) + "\n"
