"""``nczones export-zones``: the settings a control can hold for a machine file's zones.

LinuxCNC holds one box (its soft limits, ``[AXIS_<L>] MIN_LIMIT``/``MAX_LIMIT``);
a Fanuc control holds the box of stored stroke check 1 (1320/1321) and two
forbidden boxes (stroke checks 2 and 3, 1322–1325).  Neither holds a stepped
limit-value table, a polygon or a tool-tip zone — which is why a proof before
the run matters.

Invariant: the set of positions the written settings allow **contains** the
machine file's allowed set (a proven program never trips the control), and
:attr:`ExportResult.exact` is True only when the two are equal.  What could
not be written is said in a note (``EX1xx``): a zone the control cannot hold
(left out, so the control allows more), a value rounded to the control's
resolution (rounded outwards for the allowed box, inwards for a forbidden
one), a bound beyond the control's range.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from ..errors import Diagnostic, InvalidArgument, Severity
from ..exact import decimal_places, format_decimal
from ..machine import Machine
from ..zones import BoxZone, PolygonZone, SteppedZone, ZonePoint
from ..zones.kinds import KindTable
from .model import INCH

__all__ = ["EXPORT_KINDS", "ExportResult", "export_zones"]

EXPORT_KINDS = ("linuxcnc", "fanuc")

#: The largest magnitude of a Fanuc length parameter, in least command increments (8 digits).
FANUC_MAX_COUNT = 99_999_999

_FANUC_INCREMENTS = {Fraction(1, 100): "IS-A", Fraction(1, 1000): "IS-B", Fraction(1, 10000): "IS-C",
                     Fraction(1, 100000): "IS-D", Fraction(1, 1000000): "IS-E"}
#: Places LinuxCNC values are written with when the exact value is not a finite decimal.
_INI_PLACES = 7


@dataclass(frozen=True, slots=True)
class ExportResult:
    """The control's settings as text, whether they hold the allowed set exactly, and the notes."""

    kind: str
    text: str
    exact: bool
    notes: tuple[Diagnostic, ...]


class _Notes:
    def __init__(self, source: str):
        self.source = source
        self.items: list[Diagnostic] = []
        self.exact = True

    def add(self, code: str, message: str, *, loses: bool = True) -> None:
        self.items.append(Diagnostic(code, message, None, Severity.NOTE, file=self.source))
        if loses:
            self.exact = False


#: Per-axis bounds of a box; None is unbounded.
Bounds = dict[str, tuple[Fraction | None, Fraction | None]]


def _round(q: Fraction, step: Fraction, up: bool) -> Fraction:
    n = q / step
    k = -((-n.numerator) // n.denominator) if up else n.numerator // n.denominator
    return k * step


#: The zone as the box a control's limits hold, or (a string) what it is when the control has no equivalent
#: ("a polygon": an allowed one is written as its bounding box, a forbidden one is left out), per zone kind.
#: Fallback: no equivalent.
CONTROL_BOX: KindTable[Callable[[Any], BoxZone | str]] = KindTable(
    "imports.export.control_box", fallback=lambda z: f"a {z.kind} zone")
CONTROL_BOX.set(BoxZone, lambda z: z)
CONTROL_BOX.set(SteppedZone, lambda z: "a stepped limit-value table")
CONTROL_BOX.set(PolygonZone, lambda z: "a polygon")


def _held_zones(machine: Machine, notes: _Notes, forbid_slots: int) -> tuple[Bounds, list[BoxZone]]:
    """The allowed box (intersection of the allow boxes) and the forbid boxes the control can take."""
    box: Bounds = {}
    forbids: list[BoxZone] = []
    for z in machine.zones:
        where = f"zone \"{z.name}\""
        if z.point is ZonePoint.TIP:
            notes.add("EX101", f"{where}: a tool-tip zone; the control's limits see the machine position only, so it "
                      "is left out (the control allows more than the machine file)")
            continue
        held = CONTROL_BOX(z)
        if isinstance(held, str):
            what = held
            if not z.forbid:
                bounds = ", ".join(f"{a} [{_b(lo)}, {_b(hi)}]" for a, (lo, hi) in z.bounds().items())
                notes.add("EX101", f"{where}: {what} has no equivalent on this control; its bounding box "
                          f"({bounds}) is written instead, so the control allows more than the machine file")
                for a, (lo, hi) in z.bounds().items():
                    _narrow(box, a, lo, hi)
            else:
                notes.add("EX101", f"{where}: a forbidden {what[2:]} has no equivalent on this control; left out "
                          "(the control allows more than the machine file)")
            continue
        if not held.forbid:
            for a, lo, hi in held.limits:
                _narrow(box, a, lo, hi)
        elif len(forbids) < forbid_slots:
            forbids.append(held)
        else:
            why = ("LinuxCNC's soft limits hold no forbidden area" if forbid_slots == 0
                   else "a Fanuc control holds two forbidden boxes (stored stroke checks 2 and 3)")
            notes.add("EX101", f"{where}: a forbidden box; {why}, so it is left out (the control allows more than "
                      "the machine file)")
    return box, forbids


def _narrow(box: Bounds, a: str, lo: Fraction | None, hi: Fraction | None) -> None:
    old_lo, old_hi = box.get(a, (None, None))
    new_lo = lo if old_lo is None else old_lo if lo is None else max(lo, old_lo)
    new_hi = hi if old_hi is None else old_hi if hi is None else min(hi, old_hi)
    box[a] = (new_lo, new_hi)


def _b(q: Fraction | None) -> str:
    return "unbounded" if q is None else format_decimal(q)


def export_zones(
    machine: Machine,
    kind: str,
    *,
    units: str = "mm",
    increment: str = "0.001",
    include_machine: bool = False,
) -> ExportResult:
    """The settings ``kind`` can hold for ``machine``'s zones (see the module docstring).

    Parameters
    ----------
    machine : Machine
    kind : {"linuxcnc", "fanuc"}
    units : {"mm", "inch"}
        LinuxCNC: the machine units of the target INI (``LINEAR_UNITS``).
    increment : str
        Fanuc: the least command increment in mm (deg) of the target control:
        ``"0.01"`` (IS-A), ``"0.001"`` (IS-B), ``"0.0001"`` (IS-C), ``"0.00001"``,
        ``"0.000001"``; integer parameter values count it.
    include_machine : bool
        Also write the axes' names, rapid rates and the reference position, so
        that the text describes the whole machine (and imports back).

    Examples
    --------
    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X", "Z"]
    ... rapid = { X = "6000", Z = "8000" }
    ... reference = { X = "50", Z = "100" }
    ... [[zones]]
    ... name = "travel"
    ... kind = "box"
    ... min = { X = "0", Z = "-10" }
    ... max = { X = "120.5", Z = "300" }
    ... ''')
    >>> r = export_zones(m, "fanuc")
    >>> r.exact, [line for line in r.text.splitlines() if line.startswith("N")]
    (True, ['N01320A1P120500A2P300000', 'N01321A1P0A2P-10000'])
    """
    if kind not in EXPORT_KINDS:
        raise InvalidArgument(f"--kind {kind!r}: export-zones writes {' or '.join(EXPORT_KINDS)} settings")
    notes = _Notes(machine.source)
    if kind == "linuxcnc":
        if units not in ("mm", "inch"):
            raise InvalidArgument(f"--units {units!r}: use mm or inch (the INI's LINEAR_UNITS)")
        text = _linuxcnc(machine, notes, units, include_machine)
    else:
        try:
            step = Fraction(increment)
        except (ValueError, ZeroDivisionError):
            step = Fraction(0)
        if step not in _FANUC_INCREMENTS:
            raise InvalidArgument(f"--increment {increment!r}: use the control's least command increment in mm: "
                                  "0.01 (IS-A), 0.001 (IS-B), 0.0001 (IS-C), 0.00001 (IS-D) or 0.000001 (IS-E)")
        text = _fanuc(machine, notes, step, include_machine)
    return ExportResult(kind, text, notes.exact, tuple(notes.items))


# --------------------------------------------------------------------------- LinuxCNC


def _ini_value(q: Fraction, factor: Fraction, rounding: str, notes: _Notes, what: str, *, loses: bool = True) -> str:
    """``q`` (mm) in the INI's units: exact when a finite decimal, else rounded ``"up"``, ``"down"`` or
    ``"nearest"``; ``loses`` says whether rounding changes the set the control allows."""
    v = q / factor
    places = decimal_places(v)
    if places is not None and places <= 12:
        return format_decimal(v)
    step = Fraction(1, 10**_INI_PLACES)
    r = Fraction(round(v / step)) * step if rounding == "nearest" else _round(v, step, rounding == "up")
    notes.add("EX102", f"{what}: {format_decimal(v, 12)} in the INI's units is not a finite decimal; written as "
              f"{format_decimal(r)}" + (" (rounded so that the control allows a little more)" if loses else ""),
              loses=loses)
    return format_decimal(r)


def _linuxcnc(machine: Machine, notes: _Notes, units: str, include_machine: bool) -> str:
    box, _ = _held_zones(machine, notes, forbid_slots=0)
    factor = INCH if units == "inch" else Fraction(1)
    axes = machine.axis_names
    coords = "".join(a.lower() for a in axes)
    out = [
        "[KINS]",
        f"KINEMATICS = trivkins coordinates={coords}",
        f"JOINTS = {len(axes)}",
        "",
        "[TRAJ]",
        f"COORDINATES = {' '.join(axes)}",
        f"LINEAR_UNITS = {units}",
        "ANGULAR_UNITS = degree",
    ]
    sections: list[tuple[str, list[str]]] = []
    for j, a in enumerate(axes):
        f = Fraction(1) if a in "ABC" else factor
        lo, hi = box.get(a, (None, None))
        lines = []
        if lo is not None:
            lines.append(f"MIN_LIMIT = {_ini_value(lo, f, 'down', notes, f'axis {a} minimum')}")
        if hi is not None:
            lines.append(f"MAX_LIMIT = {_ini_value(hi, f, 'up', notes, f'axis {a} maximum')}")
        axis_lines = list(lines)
        joint_lines = list(lines)
        if include_machine:
            v = machine.axis(a).rapid_mm_min / 60
            axis_lines.append(f"MAX_VELOCITY = {_ini_value(v, f, 'down', notes, f'axis {a} MAX_VELOCITY (the rapid rate per second)', loses=False)}")
            joint_lines.append(axis_lines[-1])
            ref = machine.reference[j]
            joint_lines.append(f"HOME = {_ini_value(ref, f, 'nearest', notes, f'axis {a} reference', loses=False)}")
        sections.append((f"AXIS_{a}", axis_lines))
        sections.append((f"JOINT_{j}", joint_lines))
    for name, lines in sections:
        out += ["", f"[{name}]", *lines]
    head = [
        f"# Soft limits for LinuxCNC from {machine.source} (nczones export-zones).",
        "# Merge these settings into the machine's INI file. LinuxCNC's soft limits are one box:",
        "# " + ("it holds the machine file's allowed set exactly." if notes.exact else
                "it cannot hold everything the machine file says (see the notes); the box contains the allowed "
                "set, and the proof before the run covers the rest."),
        f"# Values in {units} (the INI's LINEAR_UNITS); rotary axes in degrees. An axis with no limit",
        "# gets no MIN_LIMIT / MAX_LIMIT (LinuxCNC's default is no limit).",
        "",
    ]
    return "\n".join(head + out) + "\n"


# --------------------------------------------------------------------------- Fanuc


def _fanuc(machine: Machine, notes: _Notes, step: Fraction, include_machine: bool) -> str:
    box, forbids = _held_zones(machine, notes, forbid_slots=2)
    axes = machine.axis_names
    limit = FANUC_MAX_COUNT * step

    def count(q: Fraction, up: bool | None, what: str) -> int:
        n = q / step
        if n.denominator != 1:
            r = _round(q, step, bool(up)) / step if up is not None else Fraction(round(n))
            notes.add("EX102", f"{what}: {format_decimal(q)} is not a whole number of {format_decimal(step)}; written "
                      f"as {format_decimal(r * step)}" + (" (rounded so that the control allows a little more)"
                                                          if up is not None else ""), loses=up is not None)
            n = r
        return int(n)

    # a diameter axis (diameter_axes, parameter 1006#3 DIA = 1): the control's machine coordinates and the
    # parameters holding them (1240, 1320-1325) are diameters; the machine file's are radii
    dia = {a: Fraction(2) if a in machine.diameter_axes else Fraction(1) for a in axes}
    plus: list[str] = []
    minus: list[str] = []
    for k, a in enumerate(axes, 1):
        lo, hi = box.get(a, (None, None))
        if lo is not None:
            lo = lo * dia[a]
        if hi is not None:
            hi = hi * dia[a]
        if lo is None and hi is None:
            plus.append(f"A{k}P-1")
            minus.append(f"A{k}P1")
            continue
        if lo is None or hi is None or abs(lo) > limit or abs(hi) > limit:
            why = ("is unbounded on one side" if lo is None or hi is None
                   else f"goes beyond the parameters' range (±{format_decimal(limit)})")
            notes.add("EX103", f"axis {a}: the allowed set {why}; stored stroke check 1 cannot hold that, so it is "
                      "written as infinite on this axis (1320 < 1321: no check; the control allows more)")
            plus.append(f"A{k}P-1")
            minus.append(f"A{k}P1")
            continue
        plus.append(f"A{k}P{count(hi, True, f'axis {a} stroke check 1 plus')}")
        minus.append(f"A{k}P{count(lo, False, f'axis {a} stroke check 1 minus')}")
    out: list[str] = []
    if include_machine:
        out.append("(MACHINE PARAMETERS " + ("1006, " if machine.diameter_axes else "")
                   + "1020, 1240, 1420 FOLLOW: CHECK THEM BEFORE LOADING)")
        if machine.diameter_axes:
            # 1006 #3 DIA on the diameter axes (#0 ROT on A B C): the other bits of 1006 are the machine's
            out.append("(1006: ONLY #3 DIA AND #0 ROT ARE SET HERE; MERGE THE MACHINE'S OTHER BITS)")
            out.append("N01006" + "".join(
                f"A{k}P{'00001000' if a in machine.diameter_axes else '00000001' if a in 'ABC' else '00000000'}"
                for k, a in enumerate(axes, 1)))
        out.append("N01020" + "".join(f"A{k}P{ord(a)}" for k, a in enumerate(axes, 1)))
        out.append("N01240" + "".join(f"A{k}P{count(machine.reference[k - 1] * dia[a], None, f'axis {a} reference')}"
                                      for k, a in enumerate(axes, 1)))
        rates = []
        for k, a in enumerate(axes, 1):
            rate = machine.axis(a).rapid_mm_min
            if rate.denominator != 1:
                notes.add("EX102", f"axis {a}: rapid rate {format_decimal(rate)} mm/min written as "
                          f"{rate.numerator // rate.denominator} (1420 counts 1 mm/min)", loses=False)
            rates.append(f"A{k}P{rate.numerator // rate.denominator}")
        out.append("N01420" + "".join(rates))
    out.append("N01320" + "".join(plus))
    out.append("N01321" + "".join(minus))
    for number, (z, plus_n, minus_n) in enumerate(zip(forbids, (1322, 1324), (1323, 1325)), 2):
        p_words: list[str] = []
        m_words: list[str] = []
        bounds = z.bounds()
        for k, a in enumerate(axes, 1):
            lo, hi = bounds.get(a, (None, None))
            alo, ahi = box.get(a, (None, None))
            lo, hi, alo, ahi = (None if v is None else v * dia[a] for v in (lo, hi, alo, ahi))
            for side, value, allow_bound in (("minus", lo, alo), ("plus", hi, ahi)):
                if value is None or abs(value) >= limit:
                    if allow_bound is None or abs(allow_bound) >= limit:
                        notes.add("EX103", f"zone \"{z.name}\": unbounded on the {side} side of {a}, where the "
                                  f"allowed set is not bounded within the parameters' range; written as "
                                  f"{'-' if side == 'minus' else ''}{format_decimal(limit)} (the forbidden area is "
                                  "smaller on the control)")
                    (m_words if side == "minus" else p_words).append(
                        f"A{k}P{-FANUC_MAX_COUNT if side == 'minus' else FANUC_MAX_COUNT}")
                else:
                    # a forbidden box shrinks when rounded: the control then allows more
                    n = count(value, side == "minus", f"zone \"{z.name}\" {side} {a}")
                    (m_words if side == "minus" else p_words).append(f"A{k}P{n}")
        label = "INSIDE FORBIDDEN: 1300#0 OUT MUST BE 0" if number == 2 else "INSIDE FORBIDDEN"
        out.append(f"(STROKE CHECK {number}: {_tape(z.name)}; {label})")
        out.append(f"N0{plus_n}" + "".join(p_words))
        out.append(f"N0{minus_n}" + "".join(m_words))
    names = " ".join(f"A{k}={a}" for k, a in enumerate(axes, 1))
    head = [
        "%",
        f"(STORED STROKE CHECKS FROM {_tape(machine.source)} BY NCZONES EXPORT-ZONES)",
        f"(AXES {names}; INTEGER LENGTHS IN {format_decimal(step)} MM OR DEG, {_FANUC_INCREMENTS[step]})",
        *(["(" + " ".join(f"A{k}={a}" for k, a in enumerate(axes, 1) if a in machine.diameter_axes)
           + ": DIAMETER VALUES, FOR 1006#3 DIA = 1)"] if machine.diameter_axes else []),
        "(" + ("THESE HOLD THE MACHINE FILE'S ALLOWED SET EXACTLY" if notes.exact
               else "THE CONTROL CANNOT HOLD EVERY ZONE: IT ALLOWS MORE THAN THE MACHINE FILE") + ")",
    ]
    return "\n".join(head + out + ["%"]) + "\n"


def _tape(text: str) -> str:
    """Text for a tape comment: upper case, no parentheses (they end the comment)."""
    return "".join(ch for ch in text.upper() if ch not in "()%;\n\r")

