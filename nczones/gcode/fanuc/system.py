"""Fanuc system variables (``#1000`` and up): what a program reads and writes of the control's state.

The variable map is data (:data:`READ_ONLY`, the offset tables below), read by
:func:`read` and :func:`write` on a :class:`~nczones.gcode.fanuc.interpreter.FanucInterpreter`.
Numbers follow the Fanuc 0i/30i-M operator's manuals ("System variables"),
axes numbered in the machine file's order (``#5001`` is the first axis):

==================  =====================================================  =======
variables           meaning                                                access
==================  =====================================================  =======
#2001-#2200         tool length wear H1-H200 (memory C; = #10001-)         r/w
#2201-#2400         tool length geometry H1-H200 (= #11001-)               r/w
#10001-#10999       tool length wear                                       r/w
#11001-#11999       tool length geometry (``[tool_lengths]``)              r/w
#12001-#12999       tool radius wear                                       r/w
#13001-#13999       tool radius geometry (``[tool_diameters]`` / 2)        r/w
#3000               alarm (the language layer stops the program)           w
#3001, #3002        millisecond and hour clocks: 0 at the start            r/w
#3003-#3005         single block / feed hold / settings control            w (no effect)
#3901, #3902        parts count, parts required                            w (no effect)
#4001-#4022         modal G codes of groups 1-22 (preceding block)         r
#4201-#4222         the same, block being executed                         r
#4107-#4130 (D F   the last D F H M N T words, #4130 the G54.1 P number;   r
H M N T P)          #4307-#4330 the same                                   r
#5001-#5020         block end point, workpiece coordinates (no offsets;    r
                    under G68/G51/G51.1/G16 the programmed point)
#5021-#5040         current position, machine coordinates                  r
#5041-#5060         current position, workpiece coordinates (with tool     r
                    length offset)
#5081-#5100         active tool length offset per axis                     r
#5201-#5220         external workpiece zero offset (EXT)                   r/w
#5221-#5340         G54 ... G59 (20 variables each)                        r/w
#7001-#7960         G54.1 P1 ... P48 (20 variables each)                  r/w
==================  =====================================================  =======

Values are in program units (mm, or inches under G20; degrees for rotary axes).
An offset written is stored in whole least input increments of its axis, rounded
as an address word is (``#5221 = 1.23456`` stores 1.235 on IS-B, as
``G10 L2 P1 X1.23456`` does).  Writing an offset changes the motion that follows (the active tool length only
at the next G43/G44, as on the control).  Anything else, and reading the
control's state while parameter ranges are proved (the value would depend on a
range), is ``unknown`` with the variable as its code.  (Haas numbers its tool
length geometry ``#2001-`` and wear ``#2201-``, the other way round: see
``specs/fanuc.md``.)
"""

from __future__ import annotations

from fractions import Fraction
from typing import TYPE_CHECKING, Protocol

from ...machine import WORK_OFFSETS
from ..interpreter import INCH
from .expr import VACANT, SystemVariableUnknown, round_to

if TYPE_CHECKING:
    from collections.abc import Sequence
    from typing import Any

    from ...machine import FanucSettings
    from ...motion import Plane


class MacroState(Protocol):
    """What system variables read and write of the Fanuc interpreter
    (:class:`nczones.gcode.fanuc.interpreter.FanucInterpreter` provides it): modal state, offsets and the
    tool offset memory.

    Declared here, below the interpreter, so that this module does not import the interpreter back.
    """

    @property
    def naxes(self) -> int: ...
    @property
    def rotary(self) -> tuple[bool, ...]: ...
    @property
    def inch(self) -> bool: ...
    @property
    def absolute(self) -> bool: ...
    @property
    def plane(self) -> Plane: ...
    @property
    def motion(self) -> int | None: ...
    @property
    def cycle(self) -> int | None: ...
    @property
    def retract_r(self) -> bool: ...
    @property
    def feed(self) -> Fraction: ...
    @property
    def feed_mode(self) -> int: ...
    @property
    def modal_flags(self) -> dict[int, bool]: ...
    @property
    def wcs(self) -> str: ...
    @property
    def g5x(self) -> dict[str, list[Fraction]]: ...
    @property
    def dep_g5x(self) -> dict[str, list[dict[str, int]]]: ...
    @property
    def off(self) -> list[Fraction]: ...
    @property
    def pos(self) -> Sequence[Fraction]: ...
    @property
    def prog(self) -> list[Fraction] | None: ...
    @property
    def last(self) -> dict[str, Any]: ...  # the last D F H M N T words (and "N*": FanucRunner.number_alone)
    @property
    def track(self) -> bool: ...
    @property
    def tool_axis(self) -> int | None: ...
    @property
    def tool_selected(self) -> int: ...
    @property
    def tool_register(self) -> int | None: ...
    @property
    def tlo(self) -> Fraction: ...
    @property
    def tlo_register(self) -> int | None: ...
    @property
    def tlo_sign(self) -> int: ...
    @property
    def h_geometry(self) -> dict[int, Fraction]: ...
    @property
    def h_wear(self) -> dict[int, Fraction]: ...
    @property
    def h_set(self) -> set[int]: ...
    @property
    def d_geometry(self) -> dict[int, Fraction]: ...
    @property
    def d_wear(self) -> dict[int, Fraction]: ...
    @property
    def clock(self) -> dict[int, tuple[float, Fraction]]: ...
    @property
    def settings(self) -> FanucSettings: ...

    def recompute_offsets(self) -> None: ...

__all__ = ["read", "write"]

_ZERO = Fraction(0)
_STRIDE = 20


def _value(q: Fraction) -> tuple:
    return (q.numerator / q.denominator, q)


def _unknown(n: int, why: str) -> SystemVariableUnknown:
    return SystemVariableUnknown(f"#{n}", why)


def _last(it: MacroState, n: int, letter: str) -> tuple:
    """``#n``, the last word ``letter`` (D, M or N) read: vacant before the first (:func:`_alone` for N)."""
    last = it.last.get(letter)
    if letter == "N":
        _alone(it, n, last)
    return VACANT if last is None else _value(last)


def _alone(it: MacroState, n: int, last: Fraction | None) -> None:
    """Unknown when ``#n`` (the last N) differs as a line with an N and no NC word counts or not: such a line
    (``N25`` alone, a macro statement's label) is no block for this reader, and whether the control's last
    sequence number then holds its N is not settled (``FanucRunner.number_alone`` keeps its N in ``last["N*"]``;
    a later block's N settles it: every setter of ``last["N"]`` drops the entry, ``Interpreter.keep_number``, so
    while it is there ``last`` is still the block's N of its time)."""
    alone = it.last.get("N*")
    if alone is not None and alone != last:
        raise _unknown(n, f"#{n} after N{alone} on a line without an NC word (a sequence number alone or a "
                       f"macro statement's): whether the control's last sequence number is then {alone} or "
                       "the last block's is not settled; write the N in a block with an NC word")


def _ranged(it: MacroState, n: int) -> None:
    if it.track:
        raise _unknown(n, f"reading #{n} while parameter ranges are proved: the value depends on the ranges, "
                       "and variables do not carry that dependency")


def _units(it: MacroState, q: Fraction, i: int | None) -> Fraction:
    """A length in mm as the program reads it (inches under G20; rotary axes in degrees)."""
    if it.inch and (i is None or not it.rotary[i]):
        return q / INCH
    return q


def _mm(it: MacroState, q: Fraction, i: int | None) -> Fraction:
    if it.inch and (i is None or not it.rotary[i]):
        return q * INCH
    return q


def _stored(it: MacroState, value: tuple, i: int | None) -> Fraction:
    """An offset value written by macro as the control stores it, in mm (degrees for a rotary axis).

    A Fanuc control keeps offsets as whole numbers of the least input increment (IS-B: 0.001 mm,
    0.0001 inch, 0.001 deg), so the value, in program units, is rounded to the increment of that axis
    in the input unit in effect (``i`` None: a tool offset, a length) by :func:`~.expr.round_to`, the rule
    the program's address words follow (``G10 L2 P1 X#1`` stores what ``#5221 = #1`` stores), and only then
    converted to mm.  Soundness: the stored value is the one the control holds, not the macro's exact
    value, which may lie on the other side of a zone face; where the readings of the double round to
    different multiples :class:`~.expr.RoundingNotCertain` (GC399) makes the verdict ``unknown``.
    """
    inc = it.settings.increment_mm
    linear = i is None or not it.rotary[i]
    step = inc / 10 if it.inch and linear else inc
    return _mm(it, round_to(value, step), i)


def _offset_table(n: int) -> tuple[str, int] | None:
    """``(name, axis index)`` of a work offset variable, or None."""
    if 5201 <= n <= 5340:
        k, i = divmod(n - 5201, _STRIDE)
        return (("EXT",) + WORK_OFFSETS[:6])[k], i
    if 7001 <= n <= 7960:
        k, i = divmod(n - 7001, _STRIDE)
        return f"G54.1P{k + 1}", i
    return None


def _tool_table(it: MacroState, n: int) -> tuple[dict[int, Fraction], int, bool] | None:
    """``(table, register, radius)`` of a tool offset variable (memory C), or None."""
    if 2001 <= n <= 2200:
        return it.h_wear, n - 2000, False
    if 2201 <= n <= 2400:
        return it.h_geometry, n - 2200, False
    if 10001 <= n <= 13999:
        kind, reg = divmod(n - 10000, 1000)
        table = (it.h_wear, it.h_geometry, it.d_wear, it.d_geometry)[kind]
        return table, reg, kind >= 2
    return None


def _modal(it: MacroState, group: int) -> Fraction | None:
    """The G code (number) of a modal group as #4001.. read it."""
    if group == 1:
        return Fraction(it.motion, 10) if it.motion is not None else None
    if group == 2:
        return Fraction(int(it.plane))
    if group == 3:
        return Fraction(90 if it.absolute else 91)
    if group == 5:
        return Fraction(it.feed_mode)
    if group == 6:
        return Fraction(20 if it.inch else 21)
    if group == 7:
        return Fraction(40)
    if group == 8:
        return Fraction(49) if it.tool_register is None else Fraction(43 if it.tlo_sign > 0 else 44)
    if group == 9:
        return Fraction(it.cycle, 10) if it.cycle is not None else Fraction(80)
    if group == 10:
        return Fraction(99 if it.retract_r else 98)
    if group == 14:
        return Fraction(54) if it.wcs.startswith("G54.1") else Fraction(it.wcs[1:])
    if group in (11, 12, 16, 17, 22):
        on = {11: (510, 500), 12: (660, 670), 16: (680, 690), 17: (160, 150), 22: (511, 501)}[group]
        active = it.modal_flags.get(group, False) if hasattr(it, "modal_flags") else False
        return Fraction(on[0] if active else on[1], 10)
    if group == 13:
        return Fraction(97)
    if group == 15:
        return Fraction(64)
    return None


def read(it: MacroState, n: int) -> tuple:
    """The value of system variable ``#n`` (a double and its exact shadow)."""
    axes = it.naxes
    if 5001 <= n <= 5100:
        block, i = divmod(n - 5001, _STRIDE)
        if i >= axes:
            return VACANT
        if block == 3:
            raise _unknown(n, f"#{n} is the skip signal position (G31), which depends on the part")
        _ranged(it, n)
        if block == 0:  # block end point in workpiece coordinates, without tool length (the programmed point)
            q = it.prog[i] if it.prog is not None else it.pos[i] - it.off[i]
        elif block == 1:
            q = it.pos[i]
        elif block == 2:
            tl = it.tlo if i == it.tool_axis else _ZERO
            q = it.pos[i] - it.off[i] + tl
        else:  # block == 4: tool length offset
            q = it.tlo if i == it.tool_axis else _ZERO
        return _value(_units(it, q, i))
    where = _offset_table(n)
    if where is not None:
        name, i = where
        if i >= axes:
            return VACANT
        _ranged(it, n)
        return _value(_units(it, it.g5x[name][i], i))
    tool = _tool_table(it, n)
    if tool is not None:
        table, reg, radius = tool
        if radius:
            return _value(_units(it, table.get(reg, _ZERO), None))
        _ranged(it, n)
        return _value(_units(it, table.get(reg, _ZERO), None))
    if n in (3001, 3002):
        return it.clock[n]
    if n == 3000:
        return VACANT
    if 4001 <= n <= 4030 or 4201 <= n <= 4230:
        code = _modal(it, (n - 4000) % 200)
        if code is None:
            raise _unknown(n, f"#{n}: the modal state of G code group {(n - 4000) % 200} is not modelled")
        return _value(code)
    if 4101 <= n <= 4130 or 4301 <= n <= 4330:
        letter = {7: "D", 9: "F", 11: "H", 13: "M", 14: "N", 20: "T", 30: "P"}.get((n - 4100) % 200)
        if letter is None:
            raise _unknown(n, f"#{n} is not modelled")
        if letter == "F":
            return _value(it.feed)
        if letter == "H":
            return _value(Fraction(it.tlo_register)) if it.tlo_register is not None else VACANT
        if letter == "T":
            return _value(Fraction(it.tool_selected))
        if letter == "P":
            return _value(Fraction(int(it.wcs[6:]))) if it.wcs.startswith("G54.1P") else VACANT
        return _last(it, n, letter)
    raise _unknown(n, f"system variable #{n} is not one nczones models (specs/fanuc.md lists those it does)")


def write(it: MacroState, n: int, value: tuple) -> None:
    """Set system variable ``#n``: offsets change the motion that follows."""
    where = _offset_table(n)
    if where is not None:
        name, i = where
        if i >= it.naxes:
            raise _unknown(n, f"#{n} names axis {i + 1}; this machine has {it.naxes} axes")
        if it.prog is not None:
            raise _unknown(n, f"writing #{n} (a work offset) while a coordinate transform is active is not modelled")
        if value is VACANT:
            raise _unknown(n, f"#{n} = <vacant>: what a control stores for a vacant offset is not modelled")
        it.g5x[name][i] = _stored(it, value, i)
        it.dep_g5x[name][i] = {}
        it.recompute_offsets()
        return
    tool = _tool_table(it, n)
    if tool is not None:
        table, reg, radius = tool
        table[reg] = _stored(it, value, None) if value is not VACANT else _ZERO
        if table is it.h_geometry:
            it.h_set.add(reg)
        return
    if n in (3001, 3002):
        it.clock[n] = value
        return
    if n in (3003, 3004, 3005, 3901, 3902) or 1100 <= n <= 1135:
        return  # single block, feed hold, settings, parts counts, output signals: no effect on motion
    if 4001 <= n <= 4330 or 5001 <= n <= 5100:
        from ..expr import EvalError

        raise EvalError("GC205", f"#{n} is read-only (Fanuc alarm PS0116)")
    raise _unknown(n, f"writing system variable #{n} is not modelled (specs/fanuc.md lists the variables "
                   "nczones models)")
