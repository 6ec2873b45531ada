"""Generated Fanuc mill programs where last session's merges meet (hunt42): hunt41's generator
(:mod:`tests.contract.fanuc_seams41`) with G68 rotation and G51 scaling mixed in.

New in the mix, each beside hunt41's statements (plain moves, cycles and hole runs, macro lines, G91, G20, G54/G55,
long runs of plain moves the vectorized fast path takes):

* a transform block: ``G68 X Y R`` (angles of exact quarter turns, 30/45 degrees, or any with three decimals),
  ``G51 X Y Z P`` or ``G51 X Y Z I J K`` (a negative factor mirrors; unequal I/J ellipses an arc), now and then
  with an axis the block does not name (the interpreter's ``unknown``), or ``G51.1`` (a mirror image), then a
  body of hunt41's statements and arcs (I/J or R, G02/G03, in G90 or G91), a long run of plain moves and arcs
  (the column lane, ``transform_columns.py``), then G69/G50 (or G50.1) - before, inside or after the run;
* now and then that run repeated 7 times (past ``FAST_PATH_MIN_LINES``: verify's vectorized path);
* a cycle started under a transform whose hole lines go on after ``G69``/``G50`` (``transform_just_cancelled``:
  the box route's hole reader and the fast path's hole template);
* ``#4113`` after an ``M`` alone on a line inside a transformed run.

The oracles are hunt41's (:func:`~tests.contract.fanuc_seams41.lanes_agree`, ``verdicts_agree``,
``reference_agrees``), and :func:`offsets_agree`: the zones, the work offsets and the reference positions moved
together by one vector keep the verdict and the violating lines (with every route as routed, so each lane meets its
own translation), and ``safe`` with a margin of 0.5 is ``safe`` with none.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

from tests.contract import fanuc_seams41 as s41
from tests.contract.fanuc_seams41 import _Draw, _num, _text

#: angles: exact quarter turns, 30/45 degree turns, or any with three decimals
ANGLES = ("0.", "90.", "180.", "270.", "30.", "45.", "150.", "-90.")
#: scale factors: halves, mirrors, and 1 (a coordinate not moved)
FACTORS = ("0.5", "1.5", "2.", "-1.", "0.25", "-0.5", "1.")


def _factor(d: _Draw) -> str:
    draw = d.draw
    if draw(st.integers(0, 2)):
        return draw(st.sampled_from(FACTORS))
    return _text(Fraction(draw(st.integers(-3000, 3000).filter(bool)), 1000), 3)


def transform_block(d: _Draw, drilling: bool = False) -> tuple[str, str]:
    """(the transform's block, its cancel): G68, G51 P, G51 I/J/K, G51 without an axis, G51.1; ``drilling``:
    mostly one that leaves Z (a cycle's drilling axis) alone, G68 or G51 with K1."""
    draw = d.draw
    centre = f"X{d.length(-40, 40)} Y{d.length(-40, 40)}"
    kind = draw(st.integers(0, 9))
    if drilling and 4 <= kind <= 7 and draw(st.integers(0, 3)):
        return f"G51 {centre} Z0. I{_factor(d)} J{_factor(d)} K1.", "G50"
    if kind <= 3:
        angle = draw(st.sampled_from(ANGLES)) if draw(st.booleans()) else _num(draw, -360, 360)
        return f"G68 {centre} R{angle}", draw(st.sampled_from(("G69", "G69", "G69 G01")))
    if kind <= 5:
        return f"G51 {centre} Z{d.length(-10, 10)} P{_factor(d)}", "G50"
    if kind <= 7:
        i = _factor(d)
        j = draw(st.sampled_from((i, i[1:] if i.startswith("-") else "-" + i, _factor(d))))
        return f"G51 {centre} Z{d.length(-10, 10)} I{i} J{j} K{_factor(d)}", "G50"
    if kind == 8:  # an axis the block does not name: unknown on the general path (stop 52)
        return f"G51 {centre} P{_factor(d)}", "G50"
    return f"G51.1 {draw(st.sampled_from(('X', 'Y')))}{d.length(-30, 30)}", "G50.1"


def arc(d: _Draw) -> list[str]:
    """A G17 arc from where the tool is: I/J (a quarter or half turn about a centre ``r`` away) or R, in G90 via
    a G91 block of its own (the end relative to the start) or in G91."""
    draw = d.draw
    r = Fraction(draw(st.integers(5, 400)), 10)
    code = draw(st.sampled_from(("G02", "G03")))
    rt = _text(r, 1)
    if draw(st.booleans()):  # a half turn along X
        end, centre = f"X{_text(2 * r, 1)} Y0.", f"I{rt} J0."
        rr = f"R{rt}"
    else:  # a quarter turn: centre (r, 0), end (r, r) or (r, -r)
        sign = 1 if (code == "G03") else -1
        end, centre = f"X{rt} Y{_text(sign * r, 1)}", f"I{rt} J0."
        rr = f"R{rt}"
    word = centre if draw(st.integers(0, 2)) else rr
    if d.incremental:  # G01 after: a move without a G code is a line (an arc without I/J/R is an error)
        return [f"{d.number()}{code} {end} {word}", "G01"]
    lines = [f"{d.number()}G91 {code} {end} {word}"]
    if draw(st.booleans()):
        lines.append("G90 G01")
    else:
        lines.append("G01")
        d.incremental = True
    return lines


def _body(d: _Draw, size: int) -> list[str]:
    lines: list[str] = []
    for _ in range(size):
        kind = d.draw(st.integers(0, 5))
        lines += arc(d) if kind == 0 else s41._statement(d)
    return lines


def absolute(d: _Draw) -> list[str]:
    """The first move after a transform's block or its cancel: absolute, every axis named (else the general
    path's ``unknown``: an incremental first move, an unnamed axis that would move), 5 times in 6."""
    if d.draw(st.integers(0, 5)) == 0:
        return []
    d.incremental = False
    code = d.draw(st.sampled_from(("G00", "G01")))
    return [f"G90 {code} X{d.length(-40, 40)} Y{d.length(-40, 40)} Z{d.length(-20, 20)}"]


def _transformed_run(d: _Draw, cancel: str) -> list[str]:
    """A long run of plain moves and arcs (every number with its point: the column lane takes it), with an M
    alone and a read of ``#4113`` after now and then, the cancel before, inside or after it."""
    draw = d.draw
    d.in_run = True
    where = draw(st.integers(0, 3))
    run: list[str] = [cancel, *absolute(d)] if where == 0 else []
    core: list[str] = []
    for _ in range(draw(st.integers(62, 90))):
        pick = draw(st.integers(0, 9))
        core += arc(d) if pick == 0 and d.incremental else s41._run_line(d)
    if draw(st.integers(0, 7)) == 0:  # repeated past FAST_PATH_MIN_LINES: verify's vectorized path
        core *= 7
    if where == 1:
        half = len(core) // 2
        back = ["G91"] if d.incremental else []  # the core after it was drawn in the mode it had
        core[half:half] = [cancel, *absolute(d), *back]
        d.incremental = bool(back) or d.incremental
    run += core
    d.in_run = False
    if draw(st.integers(0, 2)) == 0 and not d.plain:
        run += ["M04", "#7 = #4113", "G01 X[#7 + 0.5] Y1."]
    if where >= 2:
        run += [cancel, *absolute(d)]
    return run


def _hole_after_cancel(d: _Draw, cancel: str) -> list[str]:
    """A cycle started under the transform, a hole or two, the cancel, a hole right after it, G80."""
    draw = d.draw
    code = draw(st.sampled_from(sorted(s41.CYCLES)))
    extra = s41.CYCLES[code].format(q=d.length(1, 12), p="500")
    if d.incremental:
        z, r = d.length(-30, -1), d.length(-40, -1)
    else:
        z, r = d.length(-60, -5), d.length(-4, 20)
    spindle = {"G74": "M04", "G84": "M03"}.get(code, "M03")
    lines = [spindle, f"{draw(st.sampled_from(('G98 ', 'G99 ', '')))}{code} X{d.length(-40, 40)} "
             f"Y{d.length(-40, 40)} Z{z} R{r}{extra} F200."]
    lines += [f"X{d.length(-40, 40)} Y{d.length(-40, 40)}" for _ in range(draw(st.integers(0, 2)))]
    lines.append(cancel)
    lines += [f"X{d.length(-40, 40)}" + (f" Y{d.length(-40, 40)}" if draw(st.booleans()) else "")
              for _ in range(draw(st.integers(1, 3)))]
    return lines + ["G80"]


def transformed(d: _Draw) -> list[str]:
    """A transform block, a body, and its cancel (module docstring)."""
    kind = d.draw(st.integers(0, 3))
    block, cancel = transform_block(d, drilling=kind == 1)
    lines = ["G90"] if d.incremental and d.draw(st.integers(0, 5)) else []  # a centre in G91: unknown
    d.incremental = d.incremental and not lines
    lines += [f"{d.number()}{block}", *absolute(d)]
    if kind == 0:
        return lines + _body(d, d.draw(st.integers(0, 3))) + _transformed_run(d, cancel)
    if kind == 1:
        return lines + _body(d, d.draw(st.integers(0, 2))) + _hole_after_cancel(d, cancel)
    return lines + _body(d, d.draw(st.integers(1, 4))) + [cancel, *absolute(d)]


def _statement(d: _Draw) -> list[str]:
    kind = d.draw(st.integers(0, 5))
    if kind <= 2:
        return transformed(d)
    if kind == 3:
        return arc(d)
    return s41._statement(d)


@st.composite
def fanuc_programs42(draw) -> tuple[str, str]:
    """hunt41's program parts with :func:`_statement`'s transforms and arcs among the statements."""
    inch = draw(st.integers(0, 3)) == 0
    return s41.parts(_Draw(draw, inch, plain=draw(st.integers(0, 3)) == 0), _statement, 5, ["G69 G50 G50.1 G90"])


# ---------------------------------------------------------------------------------------------- oracle 2b
def verdicts_agree_at(text: str, face: tuple[int, int, int, bool], pick: int, dpi: str) -> str:
    """Oracle 2 with the face at the end of one motion (``pick`` modulo their number) rather than at the extreme
    (or one pulse, 1e-9 mm either side): motions cross it, so the verdict and the first violations' lines are
    compared where the lanes and the general path must both find them."""
    from tests.gcode.fanuc.helpers import mill

    extra = f'decimal_point_input = "{dpi}"'
    plain = mill(extra)
    got = s41._motion(text, plain, False)
    if isinstance(got, str) or not got[0]:
        return "no motion"
    segments = [g[0] for g in got[0]]
    k = face[0] % 3
    at = segments[pick % len(segments)].end[k]
    face = (k, 1 if at >= segments[0].start[k] else -1, face[2], face[3])  # the start inside (else ZN130)
    machine = mill(extra, tables=s41.travel(segments, plain.axis_names, face, Fraction(1, 1000), at=at))
    routed, off = s41.verify_routed(text, machine), s41.verify_off(text, machine)
    if isinstance(routed, Exception) or isinstance(off, Exception):
        assert type(routed) is type(off) and str(routed) == str(off), f"oracle 2': {routed!r}\n{off!r}\n{text}"
        return "error"
    case = (f"oracle 2': routed {routed.verdict} {routed.reasons[:2]} {routed.violations[:1]}\n"
            f"off {off.verdict} {off.reasons[:2]} {off.violations[:1]}\nprogram:\n{text}\nzones:{machine}")
    assert routed.verdict == off.verdict, case
    assert [v.line for v in routed.violations] == [v.line for v in off.violations], case
    return routed.verdict.name


# ---------------------------------------------------------------------------------------------- oracle 4
def offsets_agree(text: str, shift: tuple[int, int, int], face: tuple[int, int, int, bool], dpi: str) -> str:
    """Zones and work offsets moved together by ``shift`` (mm) keep the verdict and the violating lines (the
    routed verify both times); what happened."""
    from nczones.machine import parse_machine
    from tests.gcode.fanuc.helpers import MILL, mill

    if "#502" in text:  # a machine position read into a program position moves the other way
        return "skip"
    extra = f'decimal_point_input = "{dpi}"'
    plain = mill(extra)
    got = s41._motion(text, plain, False)
    if isinstance(got, str) or not got[0]:
        return "no motion"
    zones = s41.travel([g[0] for g in got[0]], plain.axis_names, face, Fraction(1, 1000))
    base = mill(extra, tables=zones)
    moved_text = _moved(MILL.replace("{fanuc_extra}", extra).replace("{tables}", zones), shift)
    moved = parse_machine(moved_text, "mill.toml")
    a, b = s41.verify_routed(text, base), s41.verify_routed(text, moved)
    if isinstance(a, Exception) or isinstance(b, Exception):
        assert type(a) is type(b), f"oracle 4: {a!r}\n{b!r}\n{text}"
        return "error"
    case = (f"oracle 4: {a.verdict} {a.reasons[:2]} {a.violations[:1]}\nmoved {shift}: {b.verdict} {b.reasons[:2]} "
            f"{b.violations[:1]}\nprogram:\n{text}\nzones:{zones}")
    assert a.verdict == b.verdict, case
    assert [v.line for v in a.violations] == [v.line for v in b.violations], case
    margin = _with_margin(text, base)
    if not isinstance(margin, Exception) and margin.verdict.name == "SAFE":
        assert a.verdict.name == "SAFE", f"oracle 4: safe with margin 0.5, {a.verdict.name} with 0\n{case}"
    return a.verdict.name


def _with_margin(text: str, machine):
    from nczones.errors import NczonesError
    from nczones.prover import verify_text

    try:
        return verify_text(text, machine, file="t.nc", margin="0.5")
    except NczonesError as exc:
        return exc


def _moved(toml: str, shift: tuple[int, int, int]) -> str:
    """The mill's text with its work offsets, reference positions and every zone's min/max moved by ``shift``
    (the whole picture moved: the start too)."""
    import re

    def one(m: re.Match) -> str:
        axis, value = m.group(1), Fraction(m.group(2))
        moved = value + shift["XYZ".index(axis)]
        return f'{axis} = "{_decimal(moved)}"'

    out, section = [], ""
    for line in toml.splitlines():
        section = line if line.startswith("[") else section
        if line.startswith(("G54 ", "G55 ", '"G54.1P3"', "min ", "max ")) or section.startswith(
                "[machine.reference"):
            line = re.sub(r'([XYZ]) = "(-?[0-9.]+)"', one, line)
        out.append(line)
    return "\n".join(out) + "\n"


def _decimal(q: Fraction) -> str:
    n = round(q * 10**12)
    assert Fraction(n, 10**12) == q
    sign, n = ("-" if n < 0 else ""), abs(n)
    return f"{sign}{n // 10**12}.{n % 10**12:012d}"
