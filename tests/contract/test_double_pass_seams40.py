"""Where the double pass's features meet (hunt40): generated programs that mix them, against oracles that do not
share the pass's code.

The pass (:mod:`nczones.gcode.linuxcnc.doubles`, "The subset") grew feature by feature, each with its own
tests; the wrong verdicts found so far sat where two features meet.  :func:`seam_programs` draws short LinuxCNC
programs that mix, in one program, G20/G21 switches, G90/G91 chains, I/J and R arcs (helices too) in the
program's plane (G17, G18 or G19; an arc in G91 now and then, which the pass declines), G81/G82/G83 with G98/G99
and sticky words, G64 / G64 P / G61 / G61.1, G43 H/G49, T/M6/M61, G4, o-word loops and a sub called with an
argument, work offsets G54-G56, a header that leaves units, distance, plane or offset to the machine file (whose
``modal`` may set G55 or G18, and whose ``path_mode`` is G61 or G64); on a lathe (``report_lathe``): G7/G8, G96
S D and G97, G18 arcs in either X mode.  A quarter of the mill programs carry a G64 P in the header and neither
arcs nor cycles (the pass proves those with the P's reach).  Every length is a token (``«q»``) so that a program
can be written in other units (:func:`render`).

Relations, for each program on a machine whose zone has a face exactly at the extreme of the full path's motion
end points and arcs' sweeps along a drawn axis (or one pulse, 1e-9 mm or 1e-12 mm either side of it, or outwards
about a G64 P's reach, P to 76 P; an allowed travel face or a forbidden slab):

1. the routed verdict (the double pass first, in its default windows or in windows of 2-8 motions) is the full
   path's with the pass off and without the vectorized tier (``fast=False``): verdict, violations, reasons, notes
   and motion count, or the same input error;
2. whenever the pass returns a path, the full interpreter completes with the notes the pass records, as many
   motions, and each exact motion inside the pass's box (``tests/gcode/test_double_pass.py``
   ``check_against_full``: corners, arcs at both radii too);
3. metamorphic: the zones, start position, reference and work offsets translated together keep the verdict and
   the violations' lines; ``safe`` with a margin of 0.5 is ``safe`` with margin 0; a program of one unit written
   in G20 with its lengths ``q`` and in G21 with ``25.4 q`` gets the same verdict (a face off the exact extreme
   and off a P's reach: on such a boundary the controller's doubles, which differ between the units, decide);
4. LinuxCNC's ``rs274`` (mills, rs274's inch setup): a program the pass takes runs in rs274 without error, the
   full path matches rs274's log, and the pass's rows are rs274's motion ends at the log's rounding
   (``tests/gcode/rs274_pass.py``); the standalone rs274's own artefacts are counted, not compared.

Teeth: with the G20 scaling of G64 P taken out of the pass (the merge's guard), relation 1 fails within some 200
randomized examples (specs/contract.md, hunt40).

CI: 8 mill, 4 lathe, 4 one-unit and 8 rs274 examples (derandomized); ``-m long`` with ``NCZONES_SEAMS40``
examples (default 400) per test.
"""

from __future__ import annotations

import math
import os
import re
from fractions import Fraction

import mpmath
import pytest
from hypothesis import HealthCheck, Phase, event, given, settings
from hypothesis import strategies as st

from nczones.errors import MachineFileError, NczonesError
from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc import doubles
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from nczones.pipeline import verification
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.rs274_arc_programs import SETUP, dec
from tests.gcode.rs274_pass import NEEDS_RS274
from tests.gcode.test_double_pass import _plane, arc_points, check_against_full
from tests.machines import box_zone, machine_text
from tests.prover.test_double_pass_proof import same_outcome

CI_EXAMPLES = 8
LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS40", "400"))
MAX_ITERATIONS = 200

#: the plane's (first, second, normal) axis letters and (first, second) centre words: LinuxCNC's G17/G18/G19
PLANES = {17: ("X", "Y", "Z", "I", "J"), 18: ("Z", "X", "Y", "K", "I"), 19: ("Y", "Z", "X", "J", "K")}
#: points of rational circles: (a, b) / 5 or / 13 unit vectors, so every arc's end is exactly on its circle
_UNITS = ((Fraction(3, 5), Fraction(4, 5)), (Fraction(4, 5), Fraction(-3, 5)), (Fraction(-1), Fraction(0)),
          (Fraction(0), Fraction(1)), (Fraction(-5, 13), Fraction(-12, 13)), (Fraction(12, 13), Fraction(5, 13)),
          (Fraction(-4, 5), Fraction(3, 5)), (Fraction(1), Fraction(0)))
_TOKEN = re.compile(r"«([^»]*)»")


def render(template: str, scale: Fraction = Fraction(1)) -> str:
    """The program text of ``template``: each length token ``«q»`` written as the exact decimal ``q * scale``."""
    return _TOKEN.sub(lambda m: dec(Fraction(m.group(1)) * scale), template)


def _q(draw, lo: int = -400, hi: int = 400, places: int = 2) -> str:
    """A length token: a decimal with ``places`` places between lo and hi tenths."""
    n = draw(st.integers(lo * 10 ** (places - 1), hi * 10 ** (places - 1)))
    return f"«{Fraction(n, 10 ** places)}»"


class _State:
    """What the generator knows while it draws one program: the plane, the machine kind, labels used."""

    def __init__(self, plane: int, lathe: bool, one_unit: bool, arcs: bool = True, cycles: bool = True):
        self.plane, self.lathe, self.one_unit = plane, lathe, one_unit
        #: the program's flavour: without arcs (which the pass proves with no G64 P) or cycles, half the time
        self.arcs, self.cycles = arcs, cycles
        self.labels = 0
        self.subs: list[str] = []

    def label(self) -> int:
        self.labels += 1
        return self.labels


def _value(draw, st_: _State, counter: str | None) -> str:
    """An axis word's value: a token, or linear in #1, #2 or a loop counter (so that scaling stays exact)."""
    kind = draw(st.integers(0, 5))
    q = _q(draw, -200, 200)
    if kind <= 1:
        return q
    if kind == 2:
        return f"[#1 + {q}]"
    if kind == 3:
        return f"[#2 * 2 - {q}]"
    if kind == 4 and counter:
        return f"[{counter} * {_q(draw, -30, 30)} + {q}]"
    return f"[-#1 + {q}]"


def _straight(draw, st_: _State, counter: str | None) -> list[str]:
    axes = ("X", "Z") if st_.lathe else ("X", "Y", "Z")
    chosen = draw(st.lists(st.sampled_from(axes), min_size=1, max_size=len(axes), unique=True))
    code = draw(st.sampled_from(("G0", "G1", "G1")))
    return [" ".join([code] + [f"{a}{_value(draw, st_, counter)}" for a in chosen])]


def _arc(draw, st_: _State, counter: str | None) -> list[str]:
    """A move to a point of a rational circle (G90), then a G2/G3 to another (I/J or R; a helix now and then); or
    the same arc in G91 (the pass declines an arc in G91: the full path decides)."""
    a, b, n, i, j = PLANES[st_.plane]
    units = tuple(u for u in _UNITS if u[0].denominator != 13) if st_.lathe else _UNITS
    u0, u1 = draw(st.sampled_from(units)), draw(st.sampled_from(units))
    r = Fraction(draw(st.integers(1, 60 if st_.lathe else 400)), 10) * math.lcm(*(c.denominator for c in u0 + u1))
    cx, cy = (Fraction(draw(st.integers(-300, 300)), 10) for _ in range(2))
    sx, sy, ex, ey = cx + r * u0[0], cy + r * u0[1], cx + r * u1[0], cy + r * u1[1]
    code = draw(st.sampled_from(("G2", "G3")))
    lead = ""
    if st_.lathe:  # X words halved in G7: write the mode the arc's numbers mean
        lead = draw(st.sampled_from(("G8 ", "G7 ")))
    factor = {a: 1, b: 1}
    if lead == "G7 ":
        factor["X"] = 2
    helix = f" {n}{_q(draw, -50, 50)}" if not st_.lathe and draw(st.integers(0, 4)) == 0 else ""
    if draw(st.integers(0, 7)) == 0 and not st_.lathe:  # incremental: end and centre from the start
        return [f"G90 G1 {a}«{sx}» {b}«{sy}»",
                f"G91 {code} {a}«{ex - sx}» {b}«{ey - sy}» {i}«{cx - sx}» {j}«{cy - sy}»{helix}", "G90"]
    normal = f" {n}{_q(draw)}" if not st_.lathe and draw(st.booleans()) else ""
    start = f"{lead}G90 G1 {a}«{sx * factor[a]}» {b}«{sy * factor[b]}»{normal}"
    end = f"{a}«{ex * factor[a]}» {b}«{ey * factor[b]}»"
    if u0 != u1 and draw(st.booleans()):
        sign = draw(st.sampled_from(("", "-")))
        if (sx - ex) ** 2 + (sy - ey) ** 2 >= 4 * r * r * Fraction(99, 100):
            return [start, f"G1 {end}"]  # near a half circle by R: not drawn
        return [start, f"{code} {end} R{sign}«{r}»{helix}"]
    return [start, f"{code} {end} {i}«{cx - sx}» {j}«{cy - sy}»{helix}"]


def _cycle(draw, st_: _State, counter: str | None) -> list[str]:
    """A drilling cycle in the program's plane, G90: G81, G82 (P) or G83 (Q), G98 or G99, and up to three more
    holes with sticky words (one may change R, the bottom, Q or the retract mode), then G80."""
    a, b, n, _i, _j = PLANES[st_.plane]
    bottom = Fraction(draw(st.integers(-200, 0)), 10)
    r = bottom + Fraction(draw(st.integers(1, 150)), 10)
    clear = r + Fraction(draw(st.integers(-30, 100)), 10)
    code = draw(st.sampled_from(("G81", "G82", "G83")))
    extra = {"G81": "", "G82": " P0.5", "G83": f" Q{_q(draw, 1, 40)}"}[code]
    lines = ["G90", f"G0 {n}«{clear}»",
             f"{draw(st.sampled_from(('G98', 'G99')))} {code} {a}{_value(draw, st_, counter)} {b}{_q(draw)} "
             f"{n}«{bottom}» R«{r}»{extra}"]
    for _ in range(draw(st.integers(0, 4))):
        kind = draw(st.integers(2, 7))
        if kind in (2, 6):  # a line between the holes while the cycle is modal
            lines.append(draw(st.sampled_from(_BETWEEN)))
            continue
        hole = _hole(draw, st_, counter, code, r, bottom)
        if kind == 7:  # holes in a loop while the cycle is modal
            label = st_.label()
            lines += ["#13 = 0", f"o{label} while [#13 LT {draw(st.integers(1, 3))}]",
                      _hole(draw, st_, "#13", code, r, bottom), "#13 = [#13 + 1]", f"o{label} endwhile"]
        else:
            lines.append(hole)
    return lines + ["G80"]


#: Lines between a cycle's holes (the pass declines a plane or offset change while a cycle is modal)
_BETWEEN = ("G43 H2", "G49", "G55", "G56", "G43 H1", "G18", "G4 P0.5", "G64 P«0.01»", "G61", "T2 M6", "G20", "G21",
            "G91", "#1 = [#1 + «1»]", "M3 S1000", "G17", "F100", "G98", "G99")


def _hole(draw, st_: _State, counter: str | None, code: str, r: Fraction, bottom: Fraction) -> str:
    """A sticky hole of a modal cycle: its first axis word, maybe a changed R, bottom, Q or retract mode."""
    a, _b, n, _i, _j = PLANES[st_.plane]
    words = [f"{a}{_value(draw, st_, counter)}"]
    change = draw(st.integers(0, 5))
    if change == 0:
        words.append(f"R«{r + Fraction(draw(st.integers(-5, 20)), 10)}»")
    elif change == 1:
        words.append(f"{n}«{bottom - Fraction(draw(st.integers(0, 20)), 10)}»")
    elif change == 2 and code == "G83":
        words.append(f"Q{_q(draw, 1, 40)}")
    elif change == 3:
        words.insert(0, draw(st.sampled_from(("G98", "G99"))))
    return " ".join(words)


_MODES = ("G64", "G61", "G61.1", "G64 P«0.01»", "G64 P«0.5»", "G64 P«0.002»")
_TOOLS = ("G43 H1", "G43 H2", "G49", "T1 M6", "T2", "M6", "M61 Q2", "T2 M6 G43 H2")
_LATHE = ("G7", "G8", "G96 S100 D2000", "G97 S500", "G96 S«50» D1500", "G97")


def _setting(draw, st_: _State, counter: str | None) -> list[str]:
    kind = draw(st.integers(0, 6))
    if kind == 0 and not st_.one_unit:
        return [draw(st.sampled_from(("G20", "G21")))]
    if kind == 1:
        return [draw(st.sampled_from(("G90", "G91", "G91", "G90")))]
    if kind == 2:
        return [draw(st.sampled_from(_MODES))]
    if kind == 3 and not st_.lathe and not st_.one_unit:
        return [draw(st.sampled_from(_TOOLS))]
    if kind == 4:
        return [draw(st.sampled_from(("G4 P0.5", "G54", "G55", "G56", "F200", "M3 S1000", "M5")))]
    if kind == 5 and st_.lathe:
        return [draw(st.sampled_from(_LATHE))]
    return [draw(st.sampled_from(("#1 = [#1 + «0.5»]", "#2 = [#1 * 0.5]", "#2 = [#2 - #1]")))]


def _statement(draw, st_: _State, depth: int, counter: str | None) -> list[str]:
    kind = draw(st.integers(0, 11 if depth else 8))
    if kind <= 2:
        return _straight(draw, st_, counter)
    if kind <= 4:
        return _arc(draw, st_, counter) if st_.arcs else _straight(draw, st_, counter)
    if kind in (5, 6) and not st_.lathe and st_.cycles:
        return _cycle(draw, st_, counter)
    if kind <= 7:
        return _setting(draw, st_, counter)
    if kind == 8 and st_.subs:
        return [f"o<{draw(st.sampled_from(st_.subs))}> call [{_q(draw)}]"]
    if kind <= 10 and depth:  # a counted loop
        label = st_.label()
        c = f"#{10 + depth}"
        body = [line for _ in range(draw(st.integers(1, 3))) for line in _statement(draw, st_, depth - 1, c)]
        # 25 (an outer loop): long G91 chains, windows of many rows
        times = draw(st.sampled_from((0, 1, 2, 3, 3, 25 if depth == 2 else 3)))
        return ([f"{c} = 0", f"o{label} while [{c} LT {times}]", *body, f"{c} = [{c} + 1]",
                 f"o{label} endwhile"])
    if depth:  # an if on a parameter
        label = st_.label()
        body = [line for _ in range(draw(st.integers(1, 2))) for line in _statement(draw, st_, depth - 1, counter)]
        other = _statement(draw, st_, depth - 1, counter)
        return [f"o{label} if [#1 GT «1»]", *body, f"o{label} else", *other, f"o{label} endif"]
    return _straight(draw, st_, counter)


@st.composite
def seam_programs(draw, lathe: bool = False, one_unit: bool = False, tolerance: bool = False) -> str:
    """A program template (lengths as ``«q»`` tokens): a header that may leave groups to the machine file, maybe
    a sub defined first, then statements; ``one_unit``: no G20/G21 but the header's ``{UNITS}`` and no G43;
    ``tolerance``: a G64 P in the header, no arcs and no cycles (the pass proves those with the P's reach)."""
    plane = 18 if lathe else draw(st.sampled_from((17, 17, 18, 19)))
    st_ = _State(plane, lathe, one_unit, arcs=draw(st.booleans()) and not tolerance,
                 cycles=draw(st.booleans()) and not tolerance)
    head = []
    for words in (("G21", "G21", "G20"), ("G90", "G90", "G91"), (f"G{plane}",), ("G54", "G55", "G56")):
        if tolerance and words[0] == "G21":  # the P in either unit, half the time in inches
            words = ("G21", "G20")
        if draw(st.integers(0, 3)) or (one_unit and words[0] == "G21") or (tolerance and words[0] == "G21"):
            head.append("{UNITS}" if one_unit and words[0] == "G21" else draw(st.sampled_from(words)))
    heads = ("F300 G64 P«0.01»", "F300 G64 P«0.5»", "F300 G64 P«0.002»", "F300", "F300", "F50", "F300 G61")
    head.append(draw(st.sampled_from(heads[:3] if tolerance else heads[:5])))
    lines = [f"(seams40 G{plane})", " ".join(head), f"#1 = {_q(draw)}", f"#2 = {_q(draw)}"]
    if draw(st.integers(0, 2)) == 0:
        body = [line for _ in range(draw(st.integers(1, 3))) for line in _statement(draw, st_, 0, None)]
        st_.subs.append("s1")
        lines[2:2] = ["o<s1> sub", *body, "o<s1> endsub"]
    for _ in range(draw(st.integers(1, 6))):
        lines += _statement(draw, st_, 2, None)
    lines.append(draw(st.sampled_from(("M30", "M2"))))
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------- machines
def _mill(draw, template: str) -> dict:
    """``set`` values of the mill (tests/machines/xyz_range_seams.toml: offsets G54-G59, H1, H2, start); the
    machine file's plane is the program's when its header leaves the plane to it."""
    values: dict[str, object] = {"machine.path_mode": draw(st.sampled_from(("G61", "G64", "G64")))}
    modal = draw(st.sampled_from(((), (), (), (), (), ("G55",), ("G56",), ("G91",), ("G20",))))
    plane = re.match(r"\(seams40 (G1[789])\)\n(.*)", template)
    if plane and plane.group(1) not in plane.group(2) and (plane.group(1) != "G17" or draw(st.booleans())):
        modal = (*modal, plane.group(1))
    if modal:
        values["machine.modal"] = list(modal)
    if draw(st.booleans()):
        values["offsets.G54"] = {"X": "0.1", "Y": "-33.3", "Z": "-0.7"}
    return values


def _face(segments, axes, draw) -> tuple[int, int, Fraction]:
    """(axis index, side +-1, the extreme along it of the motion's end points and of its arcs' sweeps)."""
    k = draw(st.integers(0, len(axes) - 1))
    side = draw(st.sampled_from((1, -1)))
    values = [p[k] for s in segments for p in (s.start, s.end)]
    for seg in segments:
        if seg.kind is SegmentKind.ARC and k in _plane(seg, axes):
            at = _plane(seg, axes).index(k)
            with mpmath.workprec(200):  # the sweep's points at both radii and its axis extremes (200 bits)
                values += [Fraction(int(mpmath.nint(p[at] * 10**40)), 10**40) for p in arc_points(seg, axes)]
    return k, side, max(v * side for v in values) * side


def _decimal(v: Fraction) -> str:
    """``v`` as decimal text, rounded to 30 places when it is not a short decimal (an extreme that is a double's
    exact value: the face is then within 1e-30 mm of it, on one side or the other; both paths judge the same face)."""
    n = round(v * 10**30)
    sign, n = ("-" if n < 0 else ""), abs(n)
    return f"{sign}{n // 10**30}.{n % 10**30:030d}".rstrip("0").rstrip(".")


def _zones(axes, face: tuple[int, int, Fraction] | None, forbid: bool, shift: dict[str, Fraction],
           travel: bool = True) -> str:
    """The zones appended to the machine: a travel box (``travel``) of +-20000 with one face at ``face`` (or a
    travel box of +-80000 and a forbidden slab beyond the face, ``forbid``), all moved by ``shift``."""
    far = Fraction(20000)
    low = {a: -far + shift.get(a, 0) for a in axes}
    high = {a: far + shift.get(a, 0) for a in axes}

    def text(name, lo, hi, forbid=False):
        return box_zone(name, {x: _decimal(v) for x, v in lo.items()}, {x: _decimal(v) for x, v in hi.items()},
                        forbid=forbid)

    if face is None:
        return text("bounds", low, high) if travel else ""
    k, side, at = face
    a = axes[k]
    if forbid:  # a slab beyond the face
        (low if side > 0 else high)[a] = at
        (high if side > 0 else low)[a] = at + side * 10 * far
        wide = text("bounds", {x: -4 * far + shift.get(x, 0) for x in axes},
                    {x: 4 * far + shift.get(x, 0) for x in axes}) if travel else ""
        return wide + text("slab", low, high, forbid=True)
    (high if side > 0 else low)[a] = at
    return text("bounds", low, high)


_ZONE_LINE = re.compile(r'^(min|max) = \{(.*)\}$', re.M)
_ZONE_VALUE = re.compile(r'([A-Z]) = "([^"]*)"')


def _machine_toml(base: str, values: dict, face, forbid: bool, shift: dict[str, Fraction]) -> str:
    """The machine file: ``base`` with ``values`` set, its own zones moved by ``shift``, and :func:`_zones`."""
    text = machine_text(base, set=values)
    text = _ZONE_LINE.sub(lambda m: f"{m.group(1)} = {{" + _ZONE_VALUE.sub(
        lambda v: f'{v.group(1)} = "{dec(Fraction(v.group(2)) + shift.get(v.group(1), 0))}"', m.group(2)) + "}",
        text)
    travel = "[[zones]]" not in text
    return text + _zones(parse_machine(text).axis_names, face, forbid, shift, travel)


def _shifted(values: dict, base: str, t: dict[str, Fraction]) -> dict:
    """``set`` values with the start, reference and every work offset of ``base`` (and of ``values``) moved by t."""
    machine = parse_machine(machine_text(base, set=values))
    out = dict(values)
    axes = machine.axis_names
    tables = (("machine.start", machine.start), ("machine.reference", machine.reference))
    for key, point in tables if "[machine.start]" in machine_text(base) else tables[1:]:
        for a, v in zip(axes, point):
            out[f"{key}.{a}"] = dec(Fraction(v) + t[a])
    for name in ("G54", "G55", "G56", "G57", "G58", "G59"):
        out[f"offsets.{name}"] = {a: dec(Fraction(v) + t[a]) for a, v in zip(axes, machine.offset(name))}
    return out


# ---------------------------------------------------------------------------------------------- relations
def _run(text: str, machine, full: bool, window: int | None = None, **options):
    """``verify_text``'s Result, or the input error: as routed (the pass's windows of ``window`` motions, None:
    its default), or (``full``) the pass off and ``fast=False``."""
    if not full:
        saved_window = doubles.WINDOW
        doubles.WINDOW = window or saved_window
        try:
            return verify_text(text, machine, max_iterations=MAX_ITERATIONS, **options)
        except NczonesError as exc:
            return exc
        finally:
            doubles.WINDOW = saved_window
    saved = verification.double_pass_result, verification.interpretation
    inner = verification.interpretation
    verification.double_pass_result = lambda *a, **k: None
    verification.interpretation = lambda *a, **k: inner(*a, **{**k, "fast": False})
    try:
        return verify_text(text, machine, max_iterations=MAX_ITERATIONS, **options)
    except NczonesError as exc:
        return exc
    finally:
        verification.double_pass_result, verification.interpretation = saved


def _same(a, b, case: str) -> None:
    if isinstance(a, Exception) or isinstance(b, Exception):
        assert type(a) is type(b) and str(a) == str(b), f"{case}\nrouted: {a!r}\nfull: {b!r}"
        return
    try:
        same_outcome(a, b)
    except AssertionError as exc:
        raise AssertionError(f"{case}\nrouted: {a.verdict} {a.reasons} {a.violations[:2]} {a.notes}\n"
                             f"full: {b.verdict} {b.reasons} {b.violations[:2]} {b.notes}") from exc


def _verdict(r) -> str:
    return type(r).__name__ if isinstance(r, Exception) else r.verdict.name


def _text(template: str, units: str) -> str:
    """The program of ``template`` in ``units``: a one-unit template's tokens are inches (x 25.4 in G21)."""
    if "{UNITS}" not in template:
        return render(template)
    return render(template.replace("{UNITS}", units), Fraction(254, 10) if units == "G21" else Fraction(1))


def check_seams(template: str, base: str, values: dict, draw, units: str = "G21") -> str:
    """Relations 1-3 for one program template on machine ``base`` with ``values``; what happened (an event)."""
    text = _text(template, units)
    plain = parse_machine(_machine_toml(base, values, None, False, {}))
    try:
        segments = list(interpret_text(text, plain, max_loop_iterations=MAX_ITERATIONS, fast=False).segments())
    except NczonesError:
        segments = []
    face = _face(segments, plain.axis_names, draw) if segments else None
    forbid = draw(st.booleans()) or base == "report_lathe"
    moved, tiny_moves = 0, Fraction(0)
    if face is not None:
        pulse = plain.axes[face[0]].pulse
        tiny = draw(st.sampled_from((pulse, Fraction(1, 10**9), Fraction(1, 10**12))))
        # or outwards about a G64 P's reach: 2 P in mm, 50.8 P in inches, for a P of the program
        reach = [Fraction(v) * k for v in re.findall(r"G64 P([0-9.]+)", text) for k in (1, 2, 3, 10, 25, 50, 76)]
        far = face[1] * draw(st.sampled_from(reach or [Fraction(3, 10)]))
        moved = draw(st.sampled_from((0, tiny, -tiny, far, far, far) if reach else (0, tiny, -tiny)))
        tiny_moves = tiny if moved else Fraction(-1)  # on the extreme (0) or at a P's reach: an exact boundary
        face = (face[0], face[1], face[2] + moved)
    toml = _machine_toml(base, values, face, forbid, {})
    try:
        machine = parse_machine(toml)
    except MachineFileError as exc:  # the face one pulse inside the start, its extreme: one pulse outside it
        assert "ZN130" in str(exc) and face is not None, exc
        pulse = plain.axes[face[0]].pulse
        face, moved = (face[0], face[1], face[2] - moved + face[1] * pulse), face[1] * pulse
        toml = _machine_toml(base, values, face, forbid, {})
        machine = parse_machine(toml)
    case = f"program:\n{text}\nmachine:\n{toml}"
    window = draw(st.sampled_from((None, None, 2, 3, 5, 8)))
    routed, full = _run(text, machine, False, window), _run(text, machine, True)
    _same(routed, full, f"relation 1: routed (windows of {window}) and full differ\n" + case)
    taken = _invariant(text, machine, case)
    by_pass = not isinstance(routed, Exception) and "double_pass_boxes" in dict(routed.stats)
    if isinstance(routed, Exception):
        return "error"
    _metamorphic(template, base, values, face, forbid, draw, units, routed, case, on_extreme=bool(face) and abs(moved) > tiny_moves)
    return f"{routed.verdict.name} {'by the pass' if by_pass else ('taken' if taken else 'declined')}"


def _axes(base: str) -> tuple[str, ...]:
    return parse_machine(machine_text(base)).axis_names


def _invariant(text: str, machine, case: str) -> bool:
    try:
        path = check_against_full(text, machine, MAX_ITERATIONS)
    except NczonesError as exc:
        raise AssertionError(f"relation 2: the pass returned, the full path failed: {exc}\n{case}") from None
    except AssertionError as exc:
        raise AssertionError(f"relation 2: {exc}\n{case}") from None
    return path is not None


def _metamorphic(template, base, values, face, forbid, draw, units, routed, case, on_extreme: bool) -> None:
    """Relation 3: translation, margin and (a one-unit program whose face is not exactly on an extreme: there the
    controller's doubles, which differ between the units, decide) the other unit."""
    text = _text(template, units)
    axes = _axes(base)
    t = {a: Fraction(draw(st.sampled_from(("0.1", "-33.3", "1000.001", "-0.0005", "7")))) for a in axes}
    moved = _shifted(values, base, t)
    face_t = None if face is None else (face[0], face[1], face[2] + t[axes[face[0]]])
    machine = parse_machine(_machine_toml(base, moved, face_t, forbid, t))
    other = _run(text, machine, False)
    assert _verdict(other) == _verdict(routed), f"relation 3: translated by {t}: {_verdict(other)}\n{case}"
    if not isinstance(other, Exception):
        assert [v.line for v in other.violations] == [v.line for v in routed.violations], case
    original = parse_machine(_machine_toml(base, values, face, forbid, {}))
    margin = _run(text, original, False, margin="0.5")
    if not isinstance(margin, Exception) and margin.verdict is Verdict.SAFE:
        assert routed.verdict is Verdict.SAFE, f"relation 3: safe with margin 0.5, {routed.verdict} with 0\n{case}"
    if "{UNITS}" in template and not on_extreme:
        flipped = "G20" if units == "G21" else "G21"
        inch = _text(template, flipped)
        got = _run(inch, original, False)
        assert _verdict(got) == _verdict(routed), (f"relation 3: in {flipped}: {_verdict(got)}\n{inch}\n"
                                                   f"{case}")


#: the lathe's work offsets (report_lathe.toml has G54 X10 Z200): X words (+-20 mm, diameters or radii) and arcs
#: stay above the travel's X0
LATHE_OFFSETS = {"offsets.G54": {"X": "60", "Z": "200"}, "offsets.G55": {"X": "55.5", "Z": "190"},
                 "offsets.G56": {"X": "70", "Z": "210.25"}}
_SETTINGS = dict(deadline=None, suppress_health_check=list(HealthCheck),
                 phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink])


def _check(data, lathe: bool = False, one_unit: bool = False, units: str = "G21") -> None:
    draw = data.draw
    tolerance = not lathe and draw(st.integers(0, 3)) == 0
    template = draw(seam_programs(lathe=lathe, one_unit=one_unit, tolerance=tolerance))
    base = "report_lathe" if lathe else "xyz_range_seams"
    values = LATHE_OFFSETS if lathe else _mill(draw, template)
    event(check_seams(template, base, values, draw, units))


@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data())
def test_mill_seams_agree_with_the_full_path(data):
    _check(data)


@settings(max_examples=CI_EXAMPLES // 2, derandomize=True, **_SETTINGS)
@given(st.data())
def test_lathe_seams_agree_with_the_full_path(data):
    _check(data, lathe=True)


@settings(max_examples=CI_EXAMPLES // 2, derandomize=True, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")))
def test_one_unit_programs_keep_their_verdict_in_the_other_unit(data, units):
    _check(data, one_unit=True, units=units)


def check_rs274(template: str, units: str, workdir) -> str:
    """Relation 4: a mill program the pass takes on rs274's setup (inch offsets and tool table) runs in rs274
    without error, the full path matches its log, and the pass's rows are its motion ends, as many."""
    from tests.oracles.rs274 import compare
    from tests.tools.rs274_diff import machine_of, run_rs274

    text = _text(template, units)
    lines = text.split("\n")
    if any("M6" in line and "G43" in line for line in lines) or ("G20" in text and "G43" in text):
        # the standalone rs274's own doing (specs/gcode-support.md): after M6 it re-reads a position without the
        # tool length; under G20 it re-reads the length unconverted
        return "rs274's own (M6 and G43 in a block, or G43 and G20)"
    if re.search(r"G8[59]\b", text):
        # rs274 -g prints G85's and G89's traverse to the clear level where the tool already is at R (G99, or G98
        # from below R: convert_cycle_g85/g89's last cycle_traverse), a motion LinuxCNC's canonical layer does not
        # queue and the full path and the pass do not emit (hunt41's F2: 9 rows, rs274 10 motions)
        return "rs274's own (G85 or G89: a traverse that does not move)"
    machine = machine_of(SETUP)
    try:
        path = double_pass(text, machine, max_iterations=MAX_ITERATIONS, arc_tolerance="linuxcnc")
    except Declined:
        return "declined"
    moves, error, log = run_rs274(text, SETUP, workdir)
    case = f"program:\n{text}\nrs274: {error}"
    assert error is None, f"relation 4: the pass takes a program rs274 refuses\n{case}\n{log[-1500:]}"
    outcome = compare(text, machine, moves, error)
    assert outcome.status == "match", f"relation 4: the full path and rs274 differ: {outcome}\n{case}"
    assert path.motions == len(moves), f"relation 4: {path.motions} rows, rs274 {len(moves)} motions\n{case}"
    for k, move in enumerate(moves, start=1):
        for i in range(3):
            assert abs(Fraction(path.columns[i][k]) - move.end[i]) <= move.tol + Fraction(1, 10**9), (
                f"relation 4: motion {k} axis {i}: pass {path.columns[i][k]!r}, rs274 {move}\n{case}")
    return f"rs274 agrees ({path.motions} motions)"


@NEEDS_RS274
@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")))
def test_the_pass_is_rs274s_motion_at_the_seams(tmp_path_factory, data, units):
    template = data.draw(seam_programs(one_unit=data.draw(st.booleans())))
    event(check_rs274(template, units, tmp_path_factory.mktemp("rs274")))


@pytest.mark.long
@NEEDS_RS274
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")))
def test_rs274_seams_long(tmp_path_factory, data, units):
    template = data.draw(seam_programs(one_unit=data.draw(st.booleans())))
    event(check_rs274(template, units, tmp_path_factory.mktemp("rs274")))


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data(), st.sampled_from(("G20", "G21")), st.integers(0, 3))
def test_seams_long(data, units, kind):
    _check(data, lathe=kind == 0, one_unit=kind == 1, units=units)
