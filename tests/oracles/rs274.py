"""LinuxCNC's standalone interpreter ``rs274 -g`` as an oracle for nczones's interpreted motion.

``rs274`` prints one canonical call per line (``src/emc/sai/saicanon.cc``): ``STRAIGHT_TRAVERSE``,
``STRAIGHT_FEED``, ``ARC_FEED`` and ``RIGID_TAP`` in *program* coordinates and current units (4 decimals),
the offsets they exclude as separate calls (``SET_G5X_OFFSET``, ``SET_G92_OFFSET``,
``USE_TOOL_LENGTH_OFFSET``, ``SET_XY_ROTATION``) in the units current when they are printed, and on an
error its message and the text of the offending line on stderr (``driver.cc`` ``report_error``).
:func:`canon_motion` turns the log into motions in machine millimetres (machine = rotate(program + G92)
+ G5x + tool length, as ``emccanon.cc``) with an error bound per motion: every printed number is rounded
to 0.0001 of its unit, so a coordinate built from k printed numbers is within k x 0.00005 units of the
truth.  :func:`compare` holds nczones's segments to them.

The standalone interpreter's tool table and parameter file are in inches (its external length unit):
``Z0.5`` in the ``-t`` table is a 12.7 mm tool.  It starts at machine zero in G21 G90 G17 G54 G94.

Only this module, ``tests/tools/rs274_diff.py`` (runs ``rs274``) and the tests read it; it shares no
code with nczones's interpreter.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from fractions import Fraction

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.machine import Machine, parse_machine

AXES6 = ("X", "Y", "Z", "A", "B", "C")
_CALL = re.compile(r"^\s*(?:\d+\s+)?N\S*\s+([A-Z_0-9]+)\((.*)\)\s*$")
INCH = Fraction(254, 10)
#: Half the last printed digit: the rounding of one 4-decimal number.
HALF_DIGIT = Fraction(5, 100000)
#: Beyond the log's rounding: a value nczones holds as LinuxCNC's double (``#<_y> + #<_value>``) may sit a
#: few ulps across the printed digit's half (seed 331616: 2.33155 as a double prints 2.3316)
_SLACK = Fraction(1, 10**9)


@dataclass(frozen=True, slots=True)
class CanonMove:
    """One motion of the log in machine mm (degrees for A B C).

    ``kind``: ``RAPID``, ``LINE``, ``ARC``, ``DWELL`` or ``SPLINE`` (its end is not printed: the start);
    ``end``: X Y Z A B C; ``tol``: the rounding
    bound of the linear coordinates (mm); ``rotation``/``direction``/``centre``/``plane`` for arcs
    (``direction`` is LinuxCNC's signed turn count: > 0 counterclockwise, ``abs - 1`` full turns);
    ``dwell_s`` for dwells.
    """

    kind: str
    end: tuple[Fraction, ...]
    tol: Fraction
    direction: int = 0
    centre: tuple[Fraction, Fraction] | None = None
    plane: str = "XY"
    dwell_s: Fraction | None = None
    unit: Fraction = Fraction(1)  # mm per program unit when it was printed
    rotation: Fraction = Fraction(0)  # the XY rotation in force (degrees)

    def to_json(self) -> list:
        """A compact row: trailing zero axes and the usual bound (0.00005) left out."""
        end = list(self.end)
        while len(end) > 3 and not end[-1]:
            end.pop()
        row: list = [self.kind, [_dec(v) for v in end], "" if self.tol == HALF_DIGIT else _dec(self.tol)]
        if self.kind == "ARC":
            assert self.centre is not None
            row += [self.direction, [_dec(v) for v in self.centre], self.plane]
        if self.kind == "DWELL":
            row += [_dec(self.dwell_s or Fraction(0))]
        return row

    @classmethod
    def from_json(cls, row: list) -> CanonMove:
        end = tuple(Fraction(v) for v in row[1]) + (Fraction(0),) * (6 - len(row[1]))
        kind, tol = row[0], Fraction(row[2]) if row[2] else HALF_DIGIT
        if kind == "ARC":
            return cls(kind, end, tol, int(row[3]), (Fraction(row[4][0]), Fraction(row[4][1])), row[5])
        if kind == "DWELL":
            return cls(kind, end, tol, dwell_s=Fraction(row[3]))
        return cls(kind, end, tol)


def _dec(v: Fraction) -> str:
    """A value of the log as text: exact when it is a short decimal, else 9 decimals (rotated doubles)."""
    d = v.denominator
    while d % 2 == 0:
        d //= 2
    while d % 5 == 0:
        d //= 5
    if d == 1 and v.denominator <= 10**9:
        s = f"{float(v):.9f}" if v.denominator > 1 else str(v.numerator)
        return s.rstrip("0").rstrip(".") if "." in s else s
    return f"{float(v):.9f}"


def _num(s: str) -> Fraction:
    return Fraction(s.strip())


def canon_motion(log: str) -> list[CanonMove]:
    """Motions of an ``rs274 -g`` log in machine mm, each with its rounding bound.

    >>> log = '''  1 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)
    ...   2 N..... SET_G5X_OFFSET(1, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    ...   3 N..... STRAIGHT_FEED(1.0000, 2.0000, 0.0000, 0.0000, 0.0000, 0.0000)'''
    >>> m = canon_motion(log)[0]
    >>> m.kind, m.end[:3], m.tol
    ('LINE', (Fraction(254, 5), Fraction(254, 5), Fraction(0, 1)), Fraction(127, 50000))
    """
    unit = Fraction(1)
    g5x = [Fraction(0)] * 6
    g92 = [Fraction(0)] * 6
    tlo = [Fraction(0)] * 6
    # rounding bound (mm) of each offset component
    g5x_e = [Fraction(0)] * 6
    g92_e = [Fraction(0)] * 6
    tlo_e = [Fraction(0)] * 6
    plane = "XY"
    rotation = Fraction(0)
    moves: list[CanonMove] = []

    def place(x: Fraction, y: Fraction) -> tuple[Fraction, Fraction]:
        """Machine XY of program XY (mm, G92 not yet added): rotate(program + G92) + G5x + tool."""
        x, y = x + g92[0], y + g92[1]
        if rotation:
            t = math.radians(float(rotation))
            c, s = math.cos(t), math.sin(t)
            x, y = Fraction(float(x) * c - float(y) * s), Fraction(float(x) * s + float(y) * c)
        return x + g5x[0] + tlo[0], y + g5x[1] + tlo[1]

    def bound(i: int) -> Fraction:
        e = HALF_DIGIT * unit + g5x_e[i] + g92_e[i] + tlo_e[i]
        return e * 2 if rotation else e

    def scaled(values: list[Fraction]) -> tuple[list[Fraction], list[Fraction]]:
        return ([v * unit if i < 3 else v for i, v in enumerate(values)],
                [(HALF_DIGIT * unit if i < 3 else HALF_DIGIT) if v else Fraction(0) for i, v in enumerate(values)])

    for line in log.splitlines():
        m = _CALL.match(line)
        if not m:
            continue
        name, args = m.group(1), m.group(2)
        if name == "USE_LENGTH_UNITS":
            unit = INCH if "INCHES" in args else Fraction(1)
        elif name == "SET_G5X_OFFSET":
            g5x, g5x_e = scaled([_num(a) for a in args.split(",")[1:7]])
        elif name == "SET_G92_OFFSET":
            g92, g92_e = scaled([_num(a) for a in args.split(",")[:6]])
        elif name == "SET_XY_ROTATION":
            rotation = _num(args)
        elif name == "USE_TOOL_LENGTH_OFFSET":
            tlo, tlo_e = scaled([_num(a) for a in re.split(r"[ ,]+", args.strip())][:6])
        elif name == "SELECT_PLANE":
            plane = {"CANON_PLANE_XY": "XY", "CANON_PLANE_XZ": "XZ", "CANON_PLANE_YZ": "YZ"}.get(args.strip(), args)
        elif name == "DWELL":
            prev, ptol = (moves[-1].end, moves[-1].tol) if moves else (tuple([Fraction(0)] * 6), Fraction(0))
            moves.append(CanonMove("DWELL", prev, ptol, dwell_s=_num(args)))
        elif name == "NURBS_FEED":
            # G5.1/G5.2 (saicanon prints the number of control points only): a SPLINE whose end is not in
            # the log; compare() checks its kind, the next motion's end checks where it went
            prev, ptol = (moves[-1].end, moves[-1].tol) if moves else (tuple([Fraction(0)] * 6), Fraction(0))
            moves.append(CanonMove("SPLINE", prev, ptol, unit=unit, rotation=rotation))
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED", "STRAIGHT_PROBE", "RIGID_TAP"):
            off = [g5x[i] + g92[i] + tlo[i] for i in range(6)]
            v = [_num(a) for a in args.split(",")]
            tol = max(bound(i) for i in range(3))
            if name == "ARC_FEED":
                fe, se, fc, sc, rot, ne, a, b, c = v
                fa, sa, na = {"XY": ("X", "Y", "Z"), "XZ": ("Z", "X", "Y"), "YZ": ("Y", "Z", "X")}[plane]
                prog = {fa: fe, sa: se, na: ne, "A": a, "B": b, "C": c}
                pt = [prog[ax] * (unit if i < 3 else 1) + off[i] for i, ax in enumerate(AXES6)]
                if rotation:
                    if plane != "XY":  # rotated outside its plane: not followed (nczones: unknown); stop here
                        moves.append(CanonMove("UNPARSED", tuple(pt), tol))
                        break
                    pt[0], pt[1] = place(prog["X"] * unit, prog["Y"] * unit)
                    centre = place(fc * unit, sc * unit)
                else:
                    centre = (fc * unit + off[AXES6.index(fa)], sc * unit + off[AXES6.index(sa)])
                moves.append(CanonMove("ARC", tuple(pt), tol, int(rot), centre, plane, unit=unit, rotation=rotation))
            else:
                pt = [x * (unit if i < 3 else 1) + off[i] for i, x in enumerate(v[:6])]
                if rotation:
                    pt[0], pt[1] = place(v[0] * unit, v[1] * unit)
                if name == "RIGID_TAP":  # X Y Z only: tap to the point, back to the start (nczones's two LINEs)
                    prev, ptol = (moves[-1].end, moves[-1].tol) if moves else (tuple([Fraction(0)] * 6), tol)
                    moves.append(CanonMove("LINE", tuple(pt[:3]) + prev[3:], tol, unit=unit, rotation=rotation))
                    # back to where the last printed move ended, within that print's rounding
                    moves.append(CanonMove("LINE", prev, max(tol, ptol), unit=unit, rotation=rotation))
                    continue
                kind = {"STRAIGHT_TRAVERSE": "RAPID", "STRAIGHT_FEED": "LINE"}.get(name, name)
                moves.append(CanonMove(kind, tuple(pt), tol, unit=unit, rotation=rotation))
    return moves


def canon_error(returncode: int, stderr: str) -> tuple[str, str] | None:
    """(message, offending line text) of a failed run, None for a clean one."""
    if returncode == 0:
        return None
    lines = [ln for ln in stderr.splitlines() if ln.strip() and ln.strip() != "executing"]
    lines = [ln.replace("executing", "") for ln in lines]
    message = lines[0] if lines else "rs274 failed"
    text = lines[1] if len(lines) > 1 else ""
    return message.strip(), text


def error_lines(program: str, text: str) -> tuple[int, ...]:
    """1-based lines of ``program`` whose text is ``text`` (rs274 names the line by its text only)."""
    want = text.strip()
    return tuple(i for i, ln in enumerate(program.splitlines(), 1) if ln.strip() == want)


WORK_OFFSETS = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")


def machine_text(axes: tuple[str, ...], tools_inch: dict[int, Fraction],
                 offsets_inch: dict[str, dict[str, Fraction]] | None = None) -> str:
    """The nczones machine file of an rs274 run (an inch control: ``control_units = "inch"``, as the standalone
    interpreter keeps its numbered parameters in inches): its axes at machine zero, ``[tool_lengths]`` from the
    tool table and ``[offsets]`` from the parameter file (both in inches, so x 25.4; degrees for A)."""
    rapid = "\n".join(f'{a} = "10000"' for a in axes)
    ref = "\n".join(f'{a} = "0"' for a in axes)
    tools = "\n".join(f'H{n} = "{_dec(z * INCH)}"' for n, z in sorted(tools_inch.items()))
    names = ", ".join(f'"{a}"' for a in axes)
    offsets = ""
    for name, values in (offsets_inch or {}).items():
        vals = ", ".join(f'{a} = "{_dec(v if a in "ABC" else v * INCH)}"' for a, v in values.items())
        offsets += f'"{name}" = {{ {vals} }}\n'
    return (f'[machine]\naxes = [{names}]\npulse = "0.0001"\ncontrol_units = "inch"\n[machine.rapid]\n{rapid}\n'
            f"[machine.reference]\n{ref}\n[tool_lengths]\n{tools}\n"
            + (f"[offsets]\n{offsets}" if offsets else ""))


def var_file(offsets_inch: dict[str, dict[str, Fraction]]) -> str:
    """The ``rs274 -v`` parameter file of the same work offsets (#5221 + 20 k: X, Y, Z, A of G54 + k)."""
    lines = []
    for name, values in offsets_inch.items():
        base = 5221 + 20 * WORK_OFFSETS.index(name)
        for a, v in values.items():
            lines.append((base + "XYZA".index(a), _dec(v)))
    return "".join(f"{k} {v}\n" for k, v in sorted(lines))  # rs274 wants them in order


def tool_table(tools_inch: dict[int, Fraction]) -> str:
    """The ``rs274 -t`` tool table of the same tools.

    The standalone interpreter starts with its current pocket at the table's first entry, so ``G43``
    without H or a tool change would read that tool, and ``G10 L1`` to it would also load it: a first
    entry T99 of length 0 the programs never name stands for the empty spindle."""
    return "T99 P99 Z0 D0.1 ;\n" + "".join(f"T{n} P{n} Z{_dec(z)} D0.1 ;\n" for n, z in sorted(tools_inch.items()))


@dataclass(frozen=True, slots=True)
class Outcome:
    """How nczones and the log compare: ``match``, ``unknown`` (nczones stopped where the log goes on;
    the motion before it matched), ``path`` (a motion differs), ``missed-error`` (LinuxCNC refuses, nczones
    runs past), ``false-error`` (nczones refuses what LinuxCNC runs), ``error-line`` (both refuse, on
    different lines)."""

    status: str
    detail: str = ""


def nczones_motion(program: str, machine: Machine, **options):
    """(segments, error, unsupported) of nczones on the program (DWELLs included); ``options`` as
    :func:`nczones.gcode.interpret` (the corpus run passes ``arc_tolerance="linuxcnc"``)."""
    run = interpret_text(program, machine, file="prog.ngc", **options)
    segs = []
    error = None
    try:
        for chunk in run:
            segs.extend(chunk.segments())
    except GcodeError as exc:
        error = exc
    return segs, error, tuple(run.unsupported)


def _moving(items, kind, end, start, tol):
    """Drop straight moves that end where they start (nczones leaves some out, LinuxCNC prints them)."""
    out = []
    for it in items:
        if kind(it) in ("RAPID", "LINE") and start(it) is not None and all(abs(a - b) <= tol for a, b in zip(start(it), end(it))):
            continue
        out.append(it)
    return out


def _canon_moving(moves: list[CanonMove], names: tuple[str, ...]) -> list[CanonMove]:
    out = []
    prev: tuple[Fraction, ...] | None = tuple([Fraction(0)] * 6)
    ptol = Fraction(0)
    for mv in moves:
        # within the rounding of both prints (each is within its own of the same point): an end printed in
        # inches and the same point printed again in mm after G21 differ by up to 0.00127 + 0.00005 mm
        # (seed 343058: 0.52585 in printed 0.5258, then 13.3566 mm)
        if mv.kind in ("RAPID", "LINE") and prev is not None and all(
                abs(mv.end[AXES6.index(a)] - prev[AXES6.index(a)]) <= mv.tol + ptol for a in names):
            prev, ptol = mv.end, mv.tol
            continue
        prev = None if mv.kind == "SPLINE" else mv.end  # a spline's end is not in the log
        ptol = mv.tol
        out.append(mv)
    return out


#: A straight move this short (in units of the log's last digit) may vanish in the log's rounding, or appear
#: there as a step of one digit: where the two sides differ, such a move of either side is skipped (a CAM
#: program's 0.0000001 mm moves).
TINY_DIGITS = 4


def _tiny_seg(s, names: tuple[str, ...], unit: Fraction) -> bool:
    if s.kind.name not in ("RAPID", "LINE") or not s.start:
        return False
    lim = TINY_DIGITS * HALF_DIGIT * unit
    return all(abs(s.end[k] - s.start[k]) <= lim for k in range(len(names)))


def _tiny_move(moves: list[CanonMove], j: int, names: tuple[str, ...]) -> bool:
    mv = moves[j]
    if mv.kind not in ("RAPID", "LINE") or (j and moves[j - 1].kind == "SPLINE"):
        return False
    prev = moves[j - 1].end if j else tuple([Fraction(0)] * 6)
    lim = TINY_DIGITS * HALF_DIGIT * mv.unit
    return all(abs(mv.end[AXES6.index(a)] - prev[AXES6.index(a)]) <= lim for a in names)


def _differs(s, mv: CanonMove, names: tuple[str, ...], k: int) -> str | None:
    """How nczones's segment ``s`` differs from the log's motion ``mv`` (None: they agree)."""
    where = f"motion {k} (line {s.span.line if s.span else '?'})"
    kind = s.kind.name
    if kind != mv.kind:
        return f"{where}: {kind} vs rs274 {mv.kind}"
    if kind == "SPLINE":
        return None
    for a in names:
        i = AXES6.index(a)
        e, x = s.end[names.index(a)], mv.end[i]
        t = mv.tol if i < 3 else HALF_DIGIT * 2
        if abs(e - x) > t + _SLACK:
            return f"{where} {kind} axis {a}: {float(e):.5f} vs rs274 {float(x):.5f}"
    if kind == "ARC":
        assert mv.centre is not None
        turns = abs(mv.direction) - 1
        if (mv.direction < 0) != s.clockwise or turns != s.turns or s.plane.name != mv.plane:
            return f"{where}: arc cw={s.clockwise} turns={s.turns} {s.plane.name} vs rs274 {mv.direction} {mv.plane}"
        if s.centre is not None:
            for c, x in zip(s.centre, mv.centre):
                if abs(c - x) > mv.tol * 2 + Fraction(1, 10**9):
                    return f"{where}: centre {float(c):.5f} vs rs274 {float(x):.5f}"
    if kind == "DWELL" and s.dwell_s is not None and mv.dwell_s is not None:
        if abs(s.dwell_s - mv.dwell_s) > HALF_DIGIT:
            return f"{where}: dwell {s.dwell_s} vs rs274 {mv.dwell_s}"
    return None


#: G73/G83 in a program (the peck-count allowance of :func:`compare` applies to such programs only).
_PECKING = re.compile(r"G0*(73|83)(?![\d.])", re.IGNORECASE)


def _extra_pecks(points: list[tuple[Fraction, ...]], kinds: list[str], at: int, n: int, tol: Fraction,
                 after: tuple[Fraction, ...] | None = None) -> bool:
    """Whether the ``n`` straight moves from ``at`` (end points ``points``, kinds ``kinds``) are a G73/G83 peck
    more than the other side makes where the hole's depth is a whole number of pecks (LinuxCNC's peck loop
    compares doubles an ulp off: ``peck-count-after-g49.ngc``, seed 202145): they stay on the hole's line inside
    the part of it already swept, and each of their feeds ends at the hole's bottom or one peck above it.

    The hole: the moves before ``at`` back to the last one that changed an axis other than the one the skipped
    moves move along; the swept part: the range of their end points on that axis, with ``after`` (the point
    both sides reach next) when it is on the line (a continuous path covers that range); the bottom: the lowest
    of them; the peck: the step between the hole's last two feeds.  A peck count off by a fraction of a peck
    (a broken count rule) ends its extra feed elsewhere and stays a difference."""
    if at == 0 or at + n > len(points) or any(k not in ("RAPID", "LINE") for k in kinds[at:at + n]):
        return False
    prev = points[at - 1]
    moving = {k for p in points[at:at + n] for k in range(len(prev)) if abs(p[k] - prev[k]) > tol}
    if len(moving) != 1:
        return False
    (c,) = moving

    def on_line(p: tuple[Fraction, ...]) -> bool:
        return all(abs(p[k] - prev[k]) <= tol for k in range(len(prev)) if k != c)

    b = at - 1
    while b > 0 and on_line(points[b - 1]):
        b -= 1
    if b == at - 1:
        return False
    levels = [p[c] for p in points[b:at]] + ([after[c]] if after is not None and on_line(after) else [])
    lo, hi = min(levels), max(levels)
    feeds = [points[k][c] for k in range(b, at) if kinds[k] == "LINE"]
    peck = abs(feeds[-1] - feeds[-2]) if len(feeds) >= 2 else None
    for k in range(at, at + n):
        e = points[k][c]
        if not lo - tol <= e <= hi + tol:
            return False
        if kinds[k] == "LINE" and abs(e - lo) > tol and (peck is None or abs(e - lo - peck) > tol):
            return False
    return True


def compare(program: str, machine: Machine, moves: list[CanonMove], error: tuple[str, str] | None,
            **options) -> Outcome:
    """Hold nczones's interpretation of ``program`` to the log's motions and error (``options`` go to the
    interpreter)."""
    segs, err, unsupported = nczones_motion(program, machine, **options)
    names = machine.axis_names
    segs = _moving(segs, lambda s: s.kind.name, lambda s: tuple(s.end[names.index(a)] for a in names),
                   lambda s: s.start and tuple(s.start[names.index(a)] for a in names), Fraction(0))
    moves = _canon_moving(moves, names)
    if any(m.kind == "UNPARSED" for m in moves):
        cut = next(k for k, m in enumerate(moves) if m.kind == "UNPARSED")
        moves = moves[:cut]
        if not unsupported:
            return Outcome("oracle-gap", f"rs274 moves on with an arc outside XY under rotation after motion {cut}")
    i = j = matched = pecks = 0
    pecking = bool(_PECKING.search(program))
    if pecking:
        s_pts = [tuple(s.end[names.index(a)] for a in names) for s in segs]
        s_kinds = [s.kind.name for s in segs]
        m_pts = [tuple(m.end[AXES6.index(a)] for a in names) for m in moves]
        m_kinds = [m.kind for m in moves]
    while i < len(segs) and j < len(moves):
        why = _differs(segs[i], moves[j], names, i)
        if why is None:
            i, j, matched = i + 1, j + 1, matched + 1
            continue
        if pecking and pecks < 50:
            # one peck more or less (G73/G83 whose depth is a whole number of pecks, from a position LinuxCNC
            # holds as a double off by an ulp): the same swept set, its moves skipped on the side that has them
            tol = moves[j].tol * 2
            skip = next(((n, 0) for n in (1, 2, 3) if j + n < len(moves)
                         and _extra_pecks(m_pts, m_kinds, j, n, tol, m_pts[j + n])
                         and _differs(segs[i], moves[j + n], names, i) is None), None) or next(
                ((0, n) for n in (1, 2, 3) if i + n < len(segs) and _extra_pecks(s_pts, s_kinds, i, n, tol, s_pts[i + n])
                 and _differs(segs[i + n], moves[j], names, i + n) is None), None)
            if skip is not None:
                j, i, pecks = j + skip[0], i + skip[1], pecks + 1
                continue
        if _tiny_seg(segs[i], names, moves[j].unit):
            i += 1
        elif _tiny_move(moves, j, names):
            j += 1
        elif i and j and moves[j - 1].kind == "SPLINE" and moves[j].kind in ("RAPID", "LINE") and all(
                abs(moves[j].end[AXES6.index(a)] - segs[i - 1].end[k]) <= moves[j].tol + _SLACK
                for k, a in enumerate(names)):
            j += 1  # a move to where the spline ended (not in the log: nczones left it out)
        else:
            return Outcome("path", why)
    if pecking and pecks < 50:  # the same at the end of either side: the last hole's extra peck
        if i == len(segs) and 0 < len(moves) - j <= 3 and _extra_pecks(m_pts, m_kinds, j, len(moves) - j,
                                                                        moves[j].tol * 2):
            j, pecks = len(moves), pecks + 1
        elif j == len(moves) and 0 < len(segs) - i <= 3 and moves and _extra_pecks(
                s_pts, s_kinds, i, len(segs) - i, moves[-1].tol * 2):
            i, pecks = len(segs), pecks + 1
    while i and i == len(segs) and j < len(moves) and moves[j - 1].kind == "SPLINE" and moves[j].kind in (
            "RAPID", "LINE") and all(abs(moves[j].end[AXES6.index(a)] - segs[i - 1].end[k]) <= moves[j].tol + _SLACK
                                     for k, a in enumerate(names)):
        j += 1  # the same after the last segment (rs274 prints a bare G0 after a spline as that move)
    n_segs = matched + sum(1 for s in segs[i:] if not _tiny_seg(s, names, moves[-1].unit if moves else Fraction(1)))
    n_moves = matched + sum(1 for k in range(j, len(moves)) if not _tiny_move(moves, k, names))
    if unsupported:
        if n_segs > n_moves and not (error is not None and error[0] == "rs274 timed out" and j == len(moves)):
            return Outcome("path", f"{n_segs} motions before unknown, rs274 has {n_moves}")
        return Outcome("unknown", unsupported[0].render())
    if err is not None:
        span = err.diagnostics[0].span
        line = span.line if span is not None else None
        first = err.render().splitlines()[0]
        if error is None:
            return Outcome("false-error", first)
        lines = error_lines(program, error[1])
        if lines and line not in lines:
            return Outcome("error-line", f"nczones: {first} / rs274 lines {lines}: {error[0]}")
        return Outcome("match", f"both refuse: {error[0]}")
    if n_segs != n_moves:
        extra = f"; rs274 error: {error[0]} at {error[1]!r}" if error else ""
        return Outcome("missed-error" if error and n_segs > n_moves else "path",
                       f"{n_segs} motions, rs274 {n_moves}{extra}")
    if error is not None:
        return Outcome("missed-error", f"rs274: {error[0]} at {error[1]!r}")
    return Outcome("match", f"{pecks} G73/G83 peck(s) more or less than rs274, inside the hole" if pecks else "")


def parse(text: str) -> Machine:
    return parse_machine(text)
