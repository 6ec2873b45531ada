"""The tool-break recovery plan (JP S59-152050, "restart of profiling"; DESIGN §6).

A long unattended cut breaks its tool.  The controller stops, saves its state,
takes the spindle to the tool changer, changes the tool, comes back above the
place to restart, approaches slowly, restores the state and goes on.  The
moves are the controller's, not the program's.  This module says what they
are — the ``[tool_change]`` section, the legs from the break point to the
restart point with the tool length of each, the motion sequences a restart
goes back to — and is the meaning both witnesses read: the reference
controller runs the plan pulse by pulse (:mod:`nczones.controller.recovery`)
and the prover proves it for every possible break point
(:mod:`nczones.prover.recovery`).

The ``[tool_change]`` machine-file section (``specs/recovery.md``)::

    [tool_change]
    position = { X = "560", Y = "380", Z = "380" }   # where the tool is changed
    clearance = "300"          # retract to this machine coordinate of the retract axis
    # retract_distance = "50"  # ... or this far up (give one of the two)
    retract_axis = "Z"         # default: the machine's tool_axis, else Z
    approach_distance = "5"    # alpha: the rapid stops this far above the restart point
    approach_feed = "200"      # mm/min of the last, slow approach
    variant = "start"          # "start" | "breakpoint"
    length_register = "H2"     # the replacement tool's length (default: the broken tool's)

Motion sequence
---------------
A *motion sequence* is a maximal run of consecutive cutting motions (LINE and
ARC segments: G1, G2, G3 and derived feeds) run with the same tool length;
a rapid, a dwell, or a change of the active tool length ends it.  The
**sequence-start register** holds the commanded position at the start of the
current sequence; it is written when the first cutting motion of a sequence
begins.

Recovery path (all machine coordinates; ``z`` is the retract axis)
--------------------------------------------------------------------
With ``P`` the break point, ``R`` the restart point (``start``: the sequence
start register; ``breakpoint``: ``P``), ``L`` the broken tool's length and
``L'`` the replacement's, ``R' = R + (L' - L)`` on the tool axis (the tip goes
back to the same place), ``above(z) = max(z, clearance)`` or
``z + retract_distance``:

=================  ==========================================  ===========
leg                from -> to                                  moved as
=================  ==========================================  ===========
``retract``        ``P`` -> ``P`` with ``z = above(P_z)``      rapid, length L
``to tool change`` -> ``position``                             rapid, length L
(tool change)      the tool length becomes ``L'``
``to restart``     -> ``R'`` with ``z = max(above(R'_z), R'_z + alpha)``  rapid, L'
``rapid down``     -> ``R' + alpha`` on ``z``                  rapid, L'
``approach``       -> ``R'``                                   feed ``approach_feed``, L'
``resume``         the rest of the program, shifted by ``L' - L`` on the tool axis while the
                   broken tool's length is active (``start``: from the sequence start, re-cutting
                   up to the break)
=================  ==========================================  ===========

Rapids move as the machine's ``rapid_mode`` says (linear or dogleg).
"""

from __future__ import annotations

import enum
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any, Generic, Protocol, TypeVar

from ..errors import Diagnostic, InvalidArgument, MachineFileError, close_matches
from ..machine import Machine, as_written, read_number
from ..motion import Segment, SegmentKind, TipOffset, TurretTool

__all__ = [
    "RecoveryVariant",
    "ToolChangeConfig",
    "RecoveryLeg",
    "PlanTerms",
    "EXACT_TERMS",
    "plan_legs",
    "TOOL_CHANGE_KEYS",
    "LEG_NAMES",
    "parse_tool_change_section",
    "tool_change_config",
    "replacement_length",
    "tool_axis_index",
    "recovery_legs",
    "is_cutting",
    "motion_sequences",
    "same_tool",
    "shift_segment",
    "tip_offsets",
]


TOOL_CHANGE_KEYS = ("position", "clearance", "retract_distance", "retract_axis", "approach_distance",
                    "approach_feed", "variant", "length_register")
LEG_NAMES = ("retract", "to tool change", "to restart", "rapid down", "approach", "resume")


T = TypeVar("T")


class PlanTerms(Protocol[T]):
    """The arithmetic a recovery plan is computed in: exact numbers (:data:`EXACT_TERMS`) for the
    controller and a concrete break point, or a witness's own symbolic terms for a break point that is a
    variable (the prover's SMT terms). The plan needs only these three operations."""

    def number(self, v: Fraction) -> T: ...
    def plus(self, a: T, d: Fraction) -> T: ...
    def maximum(self, a: T, b: T) -> T: ...


class _ExactTerms:
    def number(self, v: Fraction) -> Fraction:
        return v

    def plus(self, a: Fraction, d: Fraction) -> Fraction:
        return a + d

    def maximum(self, a: Fraction, b: Fraction) -> Fraction:
        return max(a, b)


#: The plan in exact rational numbers.
EXACT_TERMS: PlanTerms[Fraction] = _ExactTerms()


class RecoveryVariant(enum.Enum):
    START = "start"  # restart from the start of the interrupted motion sequence
    BREAKPOINT = "breakpoint"  # restart exactly where the tool broke


@dataclass(frozen=True, slots=True)
class ToolChangeConfig:
    """The ``[tool_change]`` section (lengths in mm, feed in mm/min).

    Exactly one of ``clearance`` (absolute machine coordinate of
    ``retract_axis``) and ``retract_distance`` (relative) is set.
    ``length_register`` is None when the replacement has the broken tool's length.
    """

    position: tuple[tuple[str, Fraction], ...]
    retract_axis: str
    clearance: Fraction | None
    retract_distance: Fraction | None
    approach_distance: Fraction
    approach_feed: Fraction
    variant: RecoveryVariant
    length_register: int | None

    def position_tuple(self, axes: tuple[str, ...]) -> tuple[Fraction, ...]:
        d = dict(self.position)
        return tuple(d[a] for a in axes)

    def above(self, z: Fraction) -> Fraction:
        """The retract height over a point at ``z`` on the retract axis.

        >>> cfg = ToolChangeConfig((), "Z", Fraction(300), None, Fraction(5), Fraction(200),
        ...                        RecoveryVariant.START, None)
        >>> cfg.above(Fraction(120)), cfg.above(Fraction(350))
        (Fraction(300, 1), Fraction(350, 1))
        """
        return self.above_in(EXACT_TERMS, z)

    def above_in(self, terms: PlanTerms[T], z: T) -> T:
        """:meth:`above` computed in ``terms`` (exact numbers, or a witness's symbolic terms)."""
        if self.clearance is not None:
            return terms.maximum(z, terms.number(self.clearance))
        assert self.retract_distance is not None  # exactly one of the two is set (class docstring)
        return terms.plus(z, self.retract_distance)


class _Recode:
    """Passes diagnostics to the reader with the number codes renamed to ZN15x."""

    _MAP = {"ZN103": "ZN153", "ZN104": "ZN153", "ZN105": "ZN153", "ZN106": "ZN154"}

    def __init__(self, rd):
        self.rd = rd
        self.loc = rd.loc

    def report(self, code, message, span=None, *a, **k):
        self.rd.report(self._MAP.get(code, code), message, span, *a, **k)


def parse_tool_change_section(rd: Any, raw: Any, axes: tuple[str, ...]) -> ToolChangeConfig | None:
    """The ``[tool_change]`` parser, listed in :data:`nczones.machine.SECTION_PARSERS`.

    Problems are reported with codes ZN150-ZN156 (``specs/recovery.md``).

    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X", "Z"]
    ... [machine.rapid]
    ... X = "10000"
    ... Z = "10000"
    ... [machine.reference]
    ... X = "0"
    ... Z = "0"
    ... [tool_change]
    ... position = { X = "500", Z = "300" }
    ... clearance = "250"
    ... approach_distance = "5"
    ... approach_feed = "100"
    ... ''')
    >>> cfg = m.sections["tool_change"]
    >>> cfg.variant.value, cfg.retract_axis, cfg.clearance
    ('start', 'Z', Fraction(250, 1))
    """
    header = rd.loc.section("tool_change")
    nrd: Any = _Recode(rd)
    if not isinstance(raw, Mapping):
        rd.report("ZN151", f"[tool_change]: expected a table, got {as_written(raw)}", rd.loc.key("tool_change", None))
        return None
    bad = False
    for key in raw:
        if key not in TOOL_CHANGE_KEYS:
            close = close_matches(key, TOOL_CHANGE_KEYS, n=1)
            hint = f"; did you mean {as_written(close[0])}?" if close else f"; allowed keys: {', '.join(TOOL_CHANGE_KEYS)}"
            rd.report("ZN150", f"[tool_change]: unknown key {as_written(key)}{hint}", rd.loc.key(key, header))
            bad = True
    for key in ("position", "approach_distance", "approach_feed"):
        if key not in raw:
            rd.report("ZN151", f"[tool_change]: missing {key} (see specs/recovery.md)", rd.loc.header(header))
            bad = True
    # position: every axis
    position: dict[str, Fraction] = {}
    pos_raw = raw.get("position")
    if pos_raw is not None:
        span = rd.loc.key("position", header)
        if not isinstance(pos_raw, Mapping):
            rd.report("ZN153", f"[tool_change] position: expected a table of axis values such as "
                      f"{{ X = \"0\" }}, got {as_written(pos_raw)}", span)
            bad = True
        else:
            for axis, v in pos_raw.items():
                if axis not in axes:
                    close = close_matches(axis, axes, n=1)
                    hint = f"; did you mean {close[0]!r}?" if close else ""
                    rd.report("ZN152", f"[tool_change] position: unknown axis {as_written(axis)}; the machine's "
                              f"axes are {', '.join(axes)}{hint}", span)
                    bad = True
                    continue
                q = read_number(nrd, v, f"[tool_change] position.{axis}", span)
                if q is None:
                    bad = True
                else:
                    position[axis] = q
            missing = [a for a in axes if a not in pos_raw]
            if missing:
                rd.report("ZN151", f"[tool_change] position: missing value for axis {', '.join(missing)} "
                          "(the tool-change position names every axis)", span)
                bad = True
    # retract axis
    default_axis = "Z" if "Z" in axes else axes[-1]
    retract_axis = raw.get("retract_axis", default_axis)
    if not isinstance(retract_axis, str) or retract_axis not in axes:
        close = close_matches(str(retract_axis), axes, n=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        rd.report("ZN152", f"[tool_change] retract_axis: {as_written(retract_axis)} is not an axis of the machine "
                  f"({', '.join(axes)}){hint}", rd.loc.key("retract_axis", header))
        bad = True
    elif retract_axis in ("A", "B", "C"):
        rd.report("ZN152", f"[tool_change] retract_axis: {as_written(retract_axis)} is rotary; the retract "
                  "needs a linear axis", rd.loc.key("retract_axis", header))
        bad = True
    # clearance xor retract_distance
    clearance = retract_distance = None
    has_c, has_d = "clearance" in raw, "retract_distance" in raw
    if has_c == has_d:
        what = "both clearance and retract_distance" if has_c else "neither clearance nor retract_distance"
        rd.report("ZN156", f"[tool_change]: {what} given; give exactly one (clearance = an absolute height "
                  "on the retract axis, retract_distance = how far to go up)", rd.loc.header(header))
        bad = True
    if has_c:
        clearance = read_number(nrd, raw["clearance"], "[tool_change] clearance", rd.loc.key("clearance", header))
        bad |= clearance is None
    if has_d:
        retract_distance = read_number(nrd, raw["retract_distance"], "[tool_change] retract_distance",
                                   rd.loc.key("retract_distance", header), nonnegative=True)
        bad |= retract_distance is None
    alpha = feed = None
    if "approach_distance" in raw:
        alpha = read_number(nrd, raw["approach_distance"], "[tool_change] approach_distance",
                        rd.loc.key("approach_distance", header), nonnegative=True)
        bad |= alpha is None
    if "approach_feed" in raw:
        feed = read_number(nrd, raw["approach_feed"], "[tool_change] approach_feed",
                       rd.loc.key("approach_feed", header), positive=True)
        bad |= feed is None
    variant_raw = raw.get("variant", "start")
    try:
        variant = RecoveryVariant(variant_raw)
    except ValueError:
        close = close_matches(str(variant_raw), [v.value for v in RecoveryVariant], n=1)
        hint = f"; did you mean {as_written(close[0])}?" if close else ""
        rd.report("ZN155", f"[tool_change] variant: {as_written(variant_raw)} is not allowed; use \"start\" or "
                  f"\"breakpoint\"{hint}", rd.loc.key("variant", header))
        variant = None
        bad = True
    register = None
    if "length_register" in raw:
        reg_raw = raw["length_register"]
        text = str(reg_raw) if isinstance(reg_raw, (str, int)) and not isinstance(reg_raw, bool) else ""
        text = text.strip().upper()
        if text.startswith("H"):
            text = text[1:]
        if text.isdigit():
            register = int(text)
        else:
            rd.report("ZN157", f"[tool_change] length_register: {as_written(reg_raw)} is not a length register; "
                      "write H followed by its number, such as \"H2\"", rd.loc.key("length_register", header))
            bad = True
    if bad:
        return None
    assert alpha is not None and feed is not None and variant is not None  # else bad is set
    return ToolChangeConfig(tuple((a, position[a]) for a in axes), retract_axis, clearance, retract_distance,
                            alpha, feed, variant, register)




def tool_change_config(machine: Machine, variant: RecoveryVariant | str | None = None) -> ToolChangeConfig:
    """The machine's ``[tool_change]`` section, optionally with another variant.

    Raises
    ------
    InvalidArgument
        When the machine has no ``[tool_change]`` section.
    MachineFileError
        ZN157 when ``length_register`` names a register ``[tool_lengths]`` lacks.
    """
    cfg: ToolChangeConfig | None = machine.sections.get("tool_change")
    if cfg is None:
        raise InvalidArgument(f"{machine.source or 'the machine'}: no [tool_change] section; tool-break recovery "
                              "needs the tool-change position, clearance and approach (see specs/recovery.md)")
    if cfg.length_register is not None and cfg.length_register not in machine.tool_lengths:
        have = ", ".join(f"H{k}" for k in sorted(machine.tool_lengths)) or "none"
        raise MachineFileError(Diagnostic("ZN157", f"[tool_change] length_register: H{cfg.length_register} is not "
                                          f"in [tool_lengths] (registers: {have})", file=machine.source or None))
    if variant is not None:
        cfg = replace(cfg, variant=RecoveryVariant(variant))
    return cfg


def replacement_length(cfg: ToolChangeConfig, machine: Machine, broken: Fraction) -> Fraction:
    """The replacement tool's length: the register's value, else the broken tool's."""
    return broken if cfg.length_register is None else machine.tool_length(cfg.length_register)


def tool_axis_index(machine: Machine) -> int | None:
    """Index of the axis tool lengths act on (``tool_axis``, else Z), or None."""
    name = machine.tool_axis or ("Z" if "Z" in machine.axis_names else None)
    return None if name is None else machine.axis_names.index(name)


@dataclass(frozen=True, slots=True)
class RecoveryLeg(Generic[T]):
    """One controller-made motion of a recovery (machine coordinates, as numbers or as a witness's terms)."""

    name: str
    kind: SegmentKind  # RAPID or LINE
    start: tuple[T, ...]
    end: tuple[T, ...]
    tool_length: Fraction
    feed_mm_min: Fraction | None = None

    def segment(self: RecoveryLeg[Fraction], axes: tuple[str, ...], like: Segment | None = None) -> Segment:
        """As a :class:`Segment` (block and source of ``like``, ``derived`` names the leg).

        The leg keeps the broken motion's tip offset (:func:`tip_offsets`): a lathe tool offset off the
        tool axis moves the tip during the recovery as during the cut; and its turret tool (a lathe's T word's
        :class:`~nczones.motion.TurretTool`, whose solids move with the turret: the replacement is the same
        tool).
        """
        turret = tuple(e for e in like.extra if type(e) is TurretTool) if like else ()
        return Segment(self.kind, self.start, self.end, axes, block=like.block if like else 0,
                       span=like.span if like else None, tool_length=self.tool_length,
                       feed_mm_min=self.feed_mm_min, derived=f"tool-break recovery: {self.name}",
                       tool_register=like.tool_register if like else None,
                       extra=tip_offsets(like) + turret if like else ())


def tip_offsets(seg: Segment) -> tuple[TipOffset, ...]:
    """The :class:`~nczones.motion.TipOffset` of a motion's ``extra`` (a lathe tool offset off the tool axis; tool-tip zones
    see the machine position minus it), which every recovery leg from a break in that motion carries too:
    the broken tool's tip, and the replacement's, which differs from it on the tool axis only."""
    return tuple(e for e in seg.extra if type(e) is TipOffset)


def recovery_legs(cfg: ToolChangeConfig, machine: Machine, break_point: Sequence[Fraction],
                  restart_point: Sequence[Fraction],
                  length: Fraction, new_length: Fraction) -> tuple[RecoveryLeg[Fraction], ...]:
    """The five moves from the break point ``P`` to the restart point ``R'`` (module docstring), exact.

    ``restart_point`` is ``R`` for the broken tool; the legs end at ``R'`` =
    ``R`` shifted by ``new_length - length`` on the tool axis.

    >>> from nczones.machine import load_machine
    >>> m = load_machine("specs/examples/machines/mill_toolchange.toml")
    >>> cfg = tool_change_config(m)
    >>> F = Fraction
    >>> P = (F(200), F(100), F(230))
    >>> [(l.name, [str(v) for v in l.end]) for l in recovery_legs(cfg, m, P, P, F(120), F(120))]
    ... # doctest: +NORMALIZE_WHITESPACE
    [('retract', ['200', '100', '300']), ('to tool change', ['560', '200', '380']),
     ('to restart', ['200', '100', '300']), ('rapid down', ['200', '100', '235']),
     ('approach', ['200', '100', '230'])]
    """
    return plan_legs(cfg, machine, tuple(Fraction(v) for v in break_point),
                     tuple(Fraction(v) for v in restart_point), length, new_length, EXACT_TERMS)


def plan_legs(cfg: ToolChangeConfig, machine: Machine, break_point: Sequence[T], restart_point: Sequence[T],
              length: Fraction, new_length: Fraction, terms: PlanTerms[T]) -> tuple[RecoveryLeg[T], ...]:
    """The recovery plan in ``terms``: which legs, from where to where, with which tool and how moved.

    :func:`recovery_legs` is this plan in exact numbers; a witness that treats the break point as a
    variable passes its own terms (the prover's SMT terms of ``P(s)``) and gets the same legs as terms.
    A coordinate the plan does not change is passed through as the very same term, so a leg whose ends
    differ in one coordinate only moves along that axis alone.

    >>> from nczones.machine import load_machine
    >>> m = load_machine("specs/examples/machines/mill_toolchange.toml")
    >>> class Text:
    ...     def number(self, v): return str(v)
    ...     def plus(self, a, d): return a if d == 0 else f"{a}+{d}"
    ...     def maximum(self, a, b): return f"max({a},{b})"
    >>> P = ("px", "py", "pz")
    >>> [(l.name, l.end) for l in plan_legs(tool_change_config(m), m, P, P, Fraction(120), Fraction(120), Text())]
    ... # doctest: +NORMALIZE_WHITESPACE
    [('retract', ('px', 'py', 'max(pz,300)')), ('to tool change', ('560', '200', '380')),
     ('to restart', ('px', 'py', 'max(max(pz,300),pz+5)')), ('rapid down', ('px', 'py', 'pz+5')),
     ('approach', ('px', 'py', 'pz'))]
    """
    axes = machine.axis_names
    z = axes.index(cfg.retract_axis)
    ti = tool_axis_index(machine)
    P = tuple(break_point)
    R = tuple(terms.plus(v, new_length - length) if k == ti else v for k, v in enumerate(restart_point))
    T = tuple(terms.number(v) for v in cfg.position_tuple(axes))
    P1 = tuple(cfg.above_in(terms, v) if k == z else v for k, v in enumerate(P))
    A = tuple(terms.plus(v, cfg.approach_distance) if k == z else v for k, v in enumerate(R))
    Q = tuple(terms.maximum(cfg.above_in(terms, v), A[z]) if k == z else v for k, v in enumerate(R))
    rapid = SegmentKind.RAPID
    return (
        RecoveryLeg("retract", rapid, P, P1, length),
        RecoveryLeg("to tool change", rapid, P1, T, length),
        RecoveryLeg("to restart", rapid, T, Q, new_length),
        RecoveryLeg("rapid down", rapid, Q, A, new_length),
        RecoveryLeg("approach", SegmentKind.LINE, A, R, new_length, cfg.approach_feed),
    )


def is_cutting(seg: Segment) -> bool:
    """True for a cutting motion (LINE or ARC): where a tool can break."""
    return seg.kind in (SegmentKind.LINE, SegmentKind.ARC)


def motion_sequences(segments: Sequence[Segment]) -> list[tuple[int, int]]:
    """``(first, last)`` indices of the motion sequences of a segment list (module docstring).

    >>> from nczones.motion import Segment, SegmentKind as K
    >>> F = Fraction
    >>> o, a, b = (F(0),), (F(1),), (F(2),)
    >>> segs = [Segment(K.RAPID, o, a, ("X",)), Segment(K.LINE, a, b, ("X",)), Segment(K.LINE, b, a, ("X",)),
    ...         Segment(K.RAPID, a, o, ("X",)), Segment(K.LINE, o, a, ("X",))]
    >>> motion_sequences(segs)
    [(1, 2), (4, 4)]
    """
    out: list[tuple[int, int]] = []
    first = None
    prev = None
    for i, seg in enumerate(segments):
        if is_cutting(seg) and first is not None and prev is not None and same_tool(prev, seg):
            out[-1] = (first, i)
        elif is_cutting(seg):
            first = i
            out.append((i, i))
        else:
            first = None
        prev = seg if is_cutting(seg) else None
    return out


def same_tool(a: Segment, b: Segment) -> bool:
    """Two cutting motions run with the same tool (length and register): one motion sequence."""
    return a.tool_length == b.tool_length and a.tool_register == b.tool_register


def shift_segment(seg: Segment, axis: int | None, delta: Fraction, new_length: Fraction) -> Segment:
    """``seg`` moved by ``delta`` on axis ``axis``, run with tool length ``new_length``."""
    if axis is None or delta == 0:
        return replace(seg, tool_length=new_length) if seg.tool_length != new_length else seg
    start = tuple(v + delta if k == axis else v for k, v in enumerate(seg.start))
    end = tuple(v + delta if k == axis else v for k, v in enumerate(seg.end))
    centre = seg.centre
    if seg.kind is SegmentKind.ARC and centre is not None:
        i, j, _ = seg.plane_indices()
        centre = (centre[0] + (delta if i == axis else 0), centre[1] + (delta if j == axis else 0))
    return replace(seg, start=start, end=end, centre=centre, tool_length=new_length)
