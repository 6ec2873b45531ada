"""State parameters: the controller state a program can read (``#5221``, ``#<_x>`` ...), as a table.

A dialect describes its state parameters as a mapping from the parameter's
key (a number, or a lower-case name for ``#<_name>``) to a
:class:`StateParameter`: what it means and how to read it from the
:class:`~nczones.gcode.interpreter.Interpreter`.  The interpreter provides
every entry of its table to the language layer (``Parameters.provide``) and
refuses assignments to them (``Parameters.guard``).  The LinuxCNC table is
:func:`linuxcnc_state_parameters`; another dialect builds its own table (or
extends this one) from the same readers and hands it on through
``Interpreter.state_parameters``.

The rule every entry follows (``specs/contract.md``, "What `safe` assumes"):

* a read gives the value the controller would hold, filled from the machine
  file and the interpreter's state (work offsets, G92, the G28/G30
  positions, the tool table, the current position ...), **together with the
  parameter sources it depends on** (:class:`StateValue`; the names of
  ``--param`` ranges: ``G54.X``, ``H1``, ``start.Z``);
* a read whose value depends on a parameter given as a range makes the
  interpretation ``unknown`` (nczones does not follow ranges through
  expressions; the nominal value alone would prove too much);
* a read of state nczones does not track (spindle, coolant, overrides,
  probe results, HAL pins ...) makes the interpretation ``unknown``;
* an assignment to a state parameter makes the interpretation ``unknown``
  (LinuxCNC refuses some and applies others at the next G54 or G28; neither
  is modelled).

Readers return a :class:`StateValue`, a plain number (state that depends on
no parameter, such as a modal code) or ``None`` (not modelled).

Examples
--------
>>> from nczones.machine import parse_machine
>>> from nczones.gcode import interpret_text
>>> m = parse_machine('''
... [machine]
... axes = ["X", "Y", "Z"]
... [machine.rapid]
... X = "1000"
... Y = "1000"
... Z = "1000"
... [machine.reference]
... X = "0"
... Y = "0"
... Z = "400"
... [offsets]
... G54 = { X = "150", Y = "100", Z = "100" }
... ''')
>>> [s.end for s in interpret_text("G53 G0 X[#5221 * 2 + 1]\\nM30\\n", m).segments()][0][0]
Fraction(301, 1)
>>> table = linuxcnc_state_parameters()
>>> table[5221].meaning, table["_abs_z"].meaning
('G54 X offset', 'current Z in machine coordinates (program units)')
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from fractions import Fraction
from types import MappingProxyType

from ...precompiled import dataclass, field  # dataclasses' without importing it (start-up)
from ..expr import EvalError

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:  # pragma: no cover
    from typing import Protocol

    from ...machine import Machine
    from ...motion import Plane
else:
    Protocol = object  # StateSource is a protocol to type checkers only


__all__ = [
    "StateValue",
    "StateParameter",
    "StateTable",
    "linuxcnc_state_parameters",
    "linuxcnc_state_numbers",
    "DEBUG_FLAG",
    "DEBUG_FLAG_DEFAULT",
    "AXIS_LETTERS",
    "WORK_OFFSET_NAMES",
]

AXIS_LETTERS = "XYZABCUVW"
WORK_OFFSET_NAMES = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")
_INCH = Fraction(254, 10)
_ZERO = Fraction(0)


@dataclass(frozen=True, slots=True)
class StateValue:
    """A state parameter's value and the parameter sources it depends on.

    ``deps`` maps a parameter name as ``--param`` writes it (``"G54.X"``,
    ``"H1"``, ``"start.Z"``) to its coefficient: the value is the nominal
    ``value`` plus the sum of ``coefficient * deviation`` over ``deps``.
    """

    value: Fraction
    deps: Mapping[str, int | Fraction] = field(default_factory=dict)


Reading = StateValue | Fraction | int | None


@dataclass(frozen=True, slots=True)
class StateParameter:
    """One readable piece of controller state.

    ``read(interpreter)`` returns a :class:`StateValue`, a number, or
    ``None`` when nczones does not model that state (the run is then
    ``unknown``).
    """

    key: int | str
    meaning: str
    read: Callable[["StateSource"], Reading]


StateTable = Mapping[int | str, StateParameter]


class StateSource(Protocol):
    """What the readers of state parameters read of the interpreter
    (:class:`nczones.gcode.interpreter.Interpreter` provides it): modal state and the ``state_*`` accessors.

    Declared here, below the interpreter, so that this module does not import the interpreter back.
    """

    @property
    def machine(self) -> Machine: ...
    @property
    def index(self) -> dict[str, int]: ...
    @property
    def inch(self) -> bool: ...
    @property
    def absolute(self) -> bool: ...
    @property
    def arc_absolute(self) -> bool: ...
    @property
    def plane(self) -> Plane: ...
    @property
    def motion(self) -> int | None: ...
    @property
    def feed(self) -> Fraction: ...
    @property
    def feed_mode(self) -> int: ...
    @property
    def wcs(self) -> str: ...
    @property
    def rot(self) -> dict[str, Fraction]: ...
    @property
    def retract_r(self) -> bool: ...
    @property
    def tool_axis(self) -> int | None: ...
    @property
    def tool_selected(self) -> int: ...
    @property
    def tool_in_spindle(self) -> int: ...
    @property
    def tlo(self) -> Fraction: ...
    @property
    def g92_applied(self) -> bool: ...

    def state_home(self, k: int, i: int) -> StateValue: ...
    def state_work_offset(self, name: str, i: int) -> StateValue: ...
    def state_spindle_tool_length(self) -> StateValue: ...
    def state_program_position(self, i: int) -> StateValue | None: ...
    def state_machine_position(self, i: int) -> StateValue | None: ...
    def state_g92(self, i: int) -> StateValue: ...
    def state_ccomp(self) -> int | None: ...
    def state_applied_tool_length(self) -> StateValue: ...


# --------------------------------------------------------------------------- readers


def _program_len(it: StateSource, sv: StateValue | None, rotary: bool) -> StateValue | None:
    """A length in mm as the program's current units (G20: inches; the coefficients scale too)."""
    if sv is None or rotary or not it.inch:
        return sv
    return StateValue(sv.value / _INCH, {k: Fraction(v) / _INCH for k, v in sv.deps.items()})


def _machine_len(it: StateSource, sv: StateValue | None, rotary: bool = False) -> StateValue | None:
    """A length in mm as the control's own units (``[machine] control_units``, LinuxCNC's
    ``[TRAJ] LINEAR_UNITS``), whatever G20/G21 is active: LinuxCNC keeps its offsets, stored positions and
    tool table in them (on an inch machine ``#5221`` after ``G21 G10 L2 P1 X25.4`` reads 1)."""
    if sv is None or rotary or getattr(it.machine, "control_units", "mm") != "inch":
        return sv
    return StateValue(sv.value / _INCH, {k: Fraction(v) / _INCH for k, v in sv.deps.items()})


def _axis_reader(letter: str, what: Callable[[StateSource, int], StateValue | None], *, program_units: bool,
                 absent: Fraction = _ZERO) -> Callable[[StateSource], Reading]:
    rotary = letter in "ABC"

    def read(it: StateSource) -> Reading:
        i = it.index.get(letter)
        if i is None:
            return absent
        sv = what(it, i)
        # LinuxCNC keeps offsets and stored positions in its "user units", the machine's
        # ([machine] control_units)
        return _program_len(it, sv, rotary) if program_units else _machine_len(it, sv, rotary)

    return read


def _offset_reader(name: str, letter: str) -> Callable[[StateSource], Reading]:
    return _axis_reader(letter, lambda it, i: it.state_work_offset(name, i), program_units=False)


def _constant(value: int) -> Callable[[StateSource], Reading]:
    return lambda it: value


def _unknown(it: StateSource) -> Reading:
    return None


def _tool_axis_only(what: Callable[[StateSource], StateValue | None], letter: str) -> Callable[[StateSource], Reading]:
    def read(it: StateSource) -> Reading:
        i = it.index.get(letter)
        if i is None or i != it.tool_axis:
            return _ZERO
        return _machine_len(it, what(it))

    return read


#: LinuxCNC's ``#5599``: whether ``(DEBUG, ...)`` comments print (1) or not (0).  It moves nothing, so a program may
#: set and read it as any parameter; it is volatile (not kept in the parameter file) and starts at 1, as
#: ``rs274`` shows: ``G0 X[#5599]`` at the start of a program traverses to X1.
DEBUG_FLAG = 5599
DEBUG_FLAG_DEFAULT = 1


def _not_under_comp(read: Callable[[StateSource], Reading]) -> Callable[[StateSource], Reading]:
    """``#5420``-``#5428``: LinuxCNC refuses to read them while cutter compensation is on
    (``read_parameter`` in interp_read.cc: "Cannot read current position with cutter radius compensation on");
    ``#<_x>`` .. read the compensated point instead (``Interpreter.state_program_position``)."""

    def guarded(it: StateSource) -> Reading:
        if getattr(it, "comp_on", False) and getattr(it, "dialect", "linuxcnc") == "linuxcnc":
            raise EvalError("GC325", "cannot read the current position (#5420-#5428) with cutter radius "
                                     "compensation on (LinuxCNC refuses it; #<_x> .. read the compensated point)")
        return read(it)

    return guarded


def _spindle_entry(read: Callable[[StateSource], Reading]) -> Callable[[StateSource], Reading]:
    """A reading of the spindle slot's tool table entry: after T0 M6 or M61 rs274 keeps the entry that was there
    (``#5400`` reads 0 after ``M61 Q2``, rs274_findings/m61-current-tool.ngc): unknown there."""
    def guarded(it: StateSource) -> Reading:
        if getattr(it, "spindle_slot_stale", False):
            return None
        return read(it)

    return guarded


def _tool_diameter(it: StateSource) -> Reading:
    get = getattr(it, "tool_diameter", None)
    d = get(it.tool_in_spindle) if get is not None else it.machine.tool_diameters.get(it.tool_in_spindle)
    if d is None:
        return None
    sv = _machine_len(it, StateValue(d))
    return None if sv is None else sv.value


def linuxcnc_state_numbers() -> frozenset[int]:
    """The numbered keys of :func:`linuxcnc_state_parameters`, without making its 230 readers (the double pass's
    test of a parameter read, once a pass: line44, some 1.4M instructions).  ``tests/gcode/test_double_pass_line_cost.py``
    holds it to the table's keys.

    >>> 5221 in linuxcnc_state_numbers(), 5599 in linuxcnc_state_numbers(), len(linuxcnc_state_numbers())
    (True, False, 173)
    """
    k = len(AXIS_LETTERS)
    numbers = {5070, 5210, 5220, 5399, 5400, 5410, 5411, 5412, 5413, 5600, 5601}
    for first in (5021, 5061, 5081, 5161, 5181, 5211, 5401, 5420):
        numbers.update(range(first, first + k))
    for n in range(len(WORK_OFFSET_NAMES)):
        numbers.update(range(5221 + 20 * n, 5221 + 20 * n + k))
        numbers.add(5230 + 20 * n)
    return frozenset(numbers)


def linuxcnc_state_parameters() -> StateTable:
    """The state parameters of LinuxCNC's interpreter (numbering of ``interp_parameter_def.hh``).

    Lengths of ``#5081``-``#5089``, ``#5161``-``#5390``, ``#5401``-``#5409`` and ``#5410``
    are in the control's units (LinuxCNC's "user units", ``[machine] control_units``: mm unless the
    machine file says "inch"), whatever G20/G21 is active; positions
    ``#5420``-``#5428``, ``#5021``-``#5029`` and ``#<_x>``, ``#<_abs_x>`` ...
    in the program's current units.  An axis the machine lacks reads 0.
    """
    t: dict[int | str, StateParameter] = {}

    def add(key, meaning, read):
        t[key] = StateParameter(key, meaning, read)

    for k, a in enumerate(AXIS_LETTERS):
        machine_position = _axis_reader(a, lambda it, i: it.state_machine_position(i), program_units=True)
        # rs274 of LinuxCNC 2.9.0~pre1 (the installed reference) reads #5021-#5029 and #5081-#5089 as 0 whatever
        # the position and the applied tool length (newer LinuxCNC: the position, the length): version-dependent
        add(5021 + k, f"current {a} in machine coordinates (LinuxCNC 2.9.0~pre1 reads 0, newer versions the "
            "position: version-dependent)", _unknown)
        add(5061 + k, f"probe result {a}", _unknown)
        add(5081 + k, f"tool length offset applied to {a} (G43; LinuxCNC 2.9.0~pre1 reads 0, newer versions the "
            "length: version-dependent)", _unknown)
        add(5161 + k, f"G28 position {a}",
            _axis_reader(a, lambda it, i: it.state_home(280, i), program_units=False))
        add(5181 + k, f"G30 position {a}",
            _axis_reader(a, lambda it, i: it.state_home(300, i), program_units=False))
        add(5211 + k, f"stored G92 offset {a}",
            _axis_reader(a, lambda it, i: it.state_g92(i), program_units=False))
        for n, name in enumerate(WORK_OFFSET_NAMES):
            add(5221 + 20 * n + k, f"{name} {a} offset", _offset_reader(name, a))
        add(5401 + k, f"stored {a} offset of the tool in the spindle (tool table; unknown after T0 M6 or M61)",
            _spindle_entry(_tool_axis_only(lambda it: it.state_spindle_tool_length(), a)))
        position = _axis_reader(a, lambda it, i: it.state_program_position(i), program_units=True)
        add(5420 + k, f"current {a} in program coordinates", _not_under_comp(position))
        low = a.lower()
        add("_" + low, f"current {a} in program coordinates", position)
        add("_abs_" + low, f"current {a} in machine coordinates (program units)", machine_position)
    add(5070, "probe result", _unknown)
    add(5210, "G92 offset applied (1) or not (0)", lambda it: 1 if it.g92_applied else 0)
    add(5220, "active coordinate system (1 = G54 ... 9 = G59.3)",
        lambda it: WORK_OFFSET_NAMES.index(it.wcs) + 1)
    for n, name in enumerate(WORK_OFFSET_NAMES):
        add(5230 + 20 * n, f"{name} XY rotation (degrees, G10 L2 R)", lambda it, name=name: it.rot[name])
    add(5399, "M66 input wait result", _unknown)
    add(5400, "tool in the spindle (unknown after T0 M6 or M61: rs274 keeps the spindle slot's old entry)",
        _spindle_entry(lambda it: it.tool_in_spindle))
    add(5410, "diameter of the tool in the spindle (unknown after T0 M6 or M61)", _spindle_entry(_tool_diameter))
    for key, what in ((5411, "front angle"), (5412, "back angle"), (5413, "orientation")):
        add(key, f"lathe tool {what} of the tool in the spindle", _unknown)
    # #5599 (the (DEBUG,) output flag) is not state: an ordinary volatile parameter that starts at
    # DEBUG_FLAG_DEFAULT (see there); #5600/#5601 are the tool changer's fault flag and code (iocontrol v2)
    for key in (5600, 5601):
        add(key, "controller flag (tool changer fault)", _unknown)
    # named parameters (interp_namedparams.cc)
    add("_current_tool", "tool in the spindle", t[5400].read)
    add("_selected_tool", "tool selected by T", lambda it: it.tool_selected)
    add("_metric", "G21 active", lambda it: 0 if it.inch else 1)
    add("_imperial", "G20 active", lambda it: 1 if it.inch else 0)
    add("_absolute", "G90 active", lambda it: 1 if it.absolute else 0)
    add("_incremental", "G91 active", lambda it: 0 if it.absolute else 1)
    add("_inverse_time", "G93 active", lambda it: 1 if it.feed_mode == 93 else 0)
    add("_units_per_minute", "G94 active", lambda it: 1 if it.feed_mode == 94 else 0)
    add("_units_per_rev", "G95 active", lambda it: 1 if it.feed_mode == 95 else 0)
    add("_ijk_absolute_mode", "G90.1 active", lambda it: 1 if it.arc_absolute else 0)
    add("_coord_system", "active coordinate system (540 ... 593)",
        lambda it: int(Fraction(it.wcs[1:]) * 10))
    add("_tool_offset", "a tool length offset is active", lambda it: 1 if it.tlo != 0 else 0)
    add("_motion_mode", "active motion mode (G number x 10; 800 for G80)",
        lambda it: 800 if it.motion is None else it.motion)
    add("_plane", "active plane (170, 180, 190)", lambda it: int(it.plane) * 10)
    add("_ccomp", "cutter compensation (400 off, 410 left, 420 right)", lambda it: it.state_ccomp())
    add("_retract_r_plane", "G99 active (retract to R)", lambda it: 1 if it.retract_r else 0)
    add("_retract_old_z", "G98 active (retract to the initial level)", lambda it: 0 if it.retract_r else 1)
    add("_feed", "feed rate (program units; after a feed move in G93 LinuxCNC's is that move's length x F, "
        "not followed)", lambda it: None if getattr(it, "feed_inverse_rate", False) else it.feed)
    # G7/G8 live in the lathe interpreter (nczones.gcode.linuxcnc.lathe); the others have no diameter mode (G8)
    add("_lathe_diameter_mode", "G7 active", lambda it: 1 if getattr(it, "diameter_mode", False) else 0)
    add("_lathe_radius_mode", "G8 active", lambda it: 0 if getattr(it, "diameter_mode", False) else 1)
    for name, what in (("_line", "current sequence number"), ("_vmajor", "LinuxCNC version"),
                       ("_vminor", "LinuxCNC version"), ("_spindle_on", "spindle state"),
                       ("_spindle_cw", "spindle direction"), ("_mist", "mist coolant"), ("_flood", "flood coolant"),
                       ("_speed_override", "spindle speed override"), ("_feed_override", "feed override"),
                       ("_adaptive_feed", "adaptive feed"), ("_feed_hold", "feed hold"), ("_rpm", "spindle speed"),
                       ("_spindle_rpm_mode", "spindle mode G97"), ("_spindle_css_mode", "spindle mode G96"),
                       ("_current_pocket", "tool changer pocket"), ("_selected_pocket", "tool changer pocket"),
                       ("_task", "whether the interpreter runs in the controller or a preview"),
                       ("_call_level", "subroutine call level"), ("_remap_level", "remap level")):
        add(name, what, _unknown)
    return MappingProxyType(t)
