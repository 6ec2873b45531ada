"""Verdicts, violations and results of the prover (the public value types)."""

from __future__ import annotations

import enum
from fractions import Fraction

from ..errors import SourceSpan
from ..motion import ProgramFrame
from ..precompiled import dataclass, field  # dataclasses' without importing it (start-up)

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from ..digest import LaterDigest

__all__ = ["Verdict", "Violation", "Reason", "Result", "ParamRange", "Outcome", "reason_code", "NOT_MODELLED",
           "point_program_missing"]

#: The reason code of a construct nczones does not model (a G/M code in a mode it does not follow, LinuxCNC
#: polar words in a cycle, a Fanuc system variable ...): the interpreter names the construct (``G41``,
#: ``@ ^``, ``#5405``), which the reason's message starts with; the code stays in the ``XX123`` scheme.
NOT_MODELLED = "GC390"


def reason_code(code: str) -> str:
    """The code a :class:`Reason` carries for an interpreter's unknown named ``code``: itself when it is in
    the ``XX123`` scheme, else :data:`NOT_MODELLED` (the construct stays first in the message).

    >>> reason_code("GC302"), reason_code("@ ^"), reason_code("#5405"), reason_code("G10 L2 R"), reason_code("")
    ('GC302', 'GC390', 'GC390', 'GC390', '')
    """
    if not code or (len(code) == 5 and code[:2].isalpha() and code[:2].isupper() and code[2:].isdigit()):
        return code
    return NOT_MODELLED


class Verdict(enum.IntEnum):
    """Ordered so that "worst wins" is ``min``: UNSAFE < UNKNOWN < SAFE.

    >>> min(Verdict.SAFE, Verdict.UNKNOWN), Verdict.UNSAFE.label
    (<Verdict.UNKNOWN: 1>, 'unsafe')
    """

    UNSAFE = 0
    UNKNOWN = 1
    SAFE = 2

    @property
    def label(self) -> str:
        return self.name.lower()

    @property
    def exit_code(self) -> int:
        """CLI exit status (DESIGN §8): 0 safe, 1 unsafe, 3 unknown."""
        return {Verdict.SAFE: 0, Verdict.UNSAFE: 1, Verdict.UNKNOWN: 3}[self]


@dataclass(frozen=True, slots=True)
class ParamRange:
    """A parameter range (DESIGN §5).

    ``name`` is ``G54.X`` (work offset component, deviation from the machine
    file), ``H1`` (tool length register, absolute range), ``start.Z`` (start
    position component, deviation) or ``home.X`` (homing error: deviation
    added to every machine coordinate of the axis).  ``lo``/``hi`` are
    deviations from the nominal value (``H`` ranges are converted); ``written``
    keeps the range as the user gave it.

    When a branch of the path switches inside a range, :func:`verify` proves
    the sides as separate cases: a case's ``lo``/``hi`` may be open
    (``lo_open``/``hi_open``) and is relative to a nominal value moved into
    it, ``centre`` (the deviation from the machine file's value at which that
    case's path was built; witnesses add it back).
    """

    name: str
    lo: Fraction
    hi: Fraction
    written: tuple[Fraction, Fraction]
    absolute: bool = False
    lo_open: bool = False
    hi_open: bool = False
    centre: Fraction = Fraction(0)


@dataclass(frozen=True, slots=True)
class Reason:
    """Why (part of) a program could not be proved."""

    message: str
    span: SourceSpan | None = None
    block: int | None = None
    code: str = ""


@dataclass(frozen=True, slots=True)
class Violation:
    """One violating block with an exactly re-checked counterexample.

    ``point`` is strictly outside the allowed set (with margin 0); with a
    margin it lies in the margin box around ``path_point``, the exact point of
    the motion whose margin box does not fit (equal without a margin).
    ``parameter`` is the segment parameter of ``path_point`` (``t`` in
    ``[0, 1]``: the fraction of a line's length, of a rapid's duration, or of
    an arc's swept angle — approximate for arcs, ``parameter_exact`` says).
    ``first_exit`` is the infimum of the violating parameters of the block's
    first violating segment and the path point there (may itself be on the
    boundary).  ``depth`` is how far past the boundary the block goes (see
    :func:`nczones.prover.exact.point_depth`); ``depth_exact`` is False when
    it is a lower bound.  ``params`` are the parameter values (as written by
    the user) of the counterexample.  ``on_path`` is True when ``path_point``
    lies exactly on the motion (every line and rapid, a rational point of a
    circular arc); False when the exact path point is irrational (a helix, an
    R-format arc with an irrational centre, a developed arc) and
    ``path_point`` is the centre of a small rational box around it, all of
    whose points violate.
    """

    block: int
    span: SourceSpan | None
    zone: str
    point: tuple[tuple[str, Fraction], ...]
    path_point: tuple[tuple[str, Fraction], ...]
    parameter: Fraction
    parameter_exact: bool
    first_exit: tuple[tuple[str, Fraction], ...]
    first_exit_parameter: Fraction
    first_exit_exact: bool
    depth: Fraction
    depth_exact: bool
    engine: str
    segment_kind: str
    derived: str = ""
    kind: str = "motion"
    params: tuple[tuple[str, Fraction], ...] = ()
    zones: tuple[str, ...] = ()
    note: str = ""
    on_path: bool = True
    # kind == "recovery" (tool-break recovery, nczones.prover.recovery): the line of the cutting
    # motion where the tool breaks, the break parameter there, the break point, the recovery leg
    break_line: int | None = None
    break_parameter: Fraction | None = None
    break_point: tuple[tuple[str, Fraction], ...] = ()
    leg: str = ""
    #: the switch positions the violation was found with when the proof covered several (``(("block_delete", "on"),)``;
    #: Fanuc ``/2`` .. ``/9``: ``block_delete/2`` ..): only the switches it depends on, empty when found in every one
    switches: tuple[tuple[str, str], ...] = ()
    #: False when :attr:`first_exit` only repeats the witness of an enclosed irrational path (developed arcs,
    #: polar moves, splines): outside, but not necessarily where the path first leaves the allowed set
    exit_located: bool = True
    #: the program's coordinate frame at the violating block (work offset, G92/G52, rotation, diameter, units,
    #: tool offsets; :class:`~nczones.motion.ProgramFrame`), from the segment; None when not recorded
    frame: ProgramFrame | None = field(default=None, compare=False)

    @property
    def line(self) -> int | None:
        return None if self.span is None else self.span.line

    @property
    def point_program(self) -> tuple[tuple[str, Fraction], ...] | None:
        """:attr:`point` in the program's coordinates (program units, diameters on diameter axes, the tool
        tip): the inverse of :attr:`frame` (exact unless ``frame.exact`` is False: a rotation).  None without
        a frame, for a recovery move (it runs outside the program's frame), with parameter ranges (the
        frame holds the nominal offsets, the witness deviated ones) and when the frame cannot be inverted
        (:func:`point_program_missing` says why)."""
        if point_program_missing(self):
            return None
        assert self.frame is not None
        return self.frame.program_point(tuple(a for a, _ in self.point), tuple(x for _, x in self.point))

    @property
    def source(self) -> str:
        return "" if self.span is None else self.span.text.rstrip("\r\n")


def point_program_missing(v: Violation) -> str:
    """Why a violation has no :attr:`Violation.point_program` ("" when it has one).

    >>> point_program_missing(Violation(0, None, "z", (), (), Fraction(0), True, (), Fraction(0), True,
    ...                                 Fraction(0), True, "exact", "line"))
    'the program frame was not recorded'
    """
    if v.frame is None:
        return "the program frame was not recorded"
    if v.kind != "motion":
        return "a recovery move runs in machine coordinates"
    if v.params:
        return "with parameter ranges the witness's offsets differ from the frame's nominal ones"
    return v.frame.opaque


@dataclass(frozen=True, slots=True)
class Result:
    """The outcome of :func:`nczones.prover.verify`.

    ``engines`` maps each flagged block (one tier 1 could not prove) to the
    engine that decided it (``"exact"``: rational decision procedure,
    ``"z3"``, ``"unknown"``).  ``stats`` holds counters (segments, pieces,
    screened, z3 queries); ``timings`` seconds per phase.

    What makes a result replayable (``nczones replay``): ``program_sha256``
    (of the program's bytes; ``program_digest`` holds it, or the bytes
    until it is first asked for), ``machine_file``/``machine_sha256`` (the
    machine file as loaded) and ``settings``, every option of
    :func:`~nczones.prover.verify` that can change the verdict, as
    JSON values (``margin``, ``engine``, ``recovery``, ``arc_tolerance``,
    ``max_iterations``, ``max_violations``, ``dialect``, ``budget_s``, ...).

    ``interrupted``: Ctrl-C stopped the run, the result covers only what was
    checked before (the CLI exits 130).  ``budget_s``: the run's budget for
    solver work and refinement (:mod:`nczones.prover.limits`).  ``profile``:
    where the time went (:mod:`nczones.prover.profile`; ``--stats``).
    """

    verdict: Verdict
    violations: tuple[Violation, ...] = ()
    reasons: tuple[Reason, ...] = ()
    engines: tuple[tuple[int, str], ...] = ()
    solver: str = "z3"
    solver_version: str = ""
    timings: tuple[tuple[str, float], ...] = ()
    notes: tuple[str, ...] = ()
    stats: tuple[tuple[str, int], ...] = ()
    margin: Fraction = Fraction(0)
    params: tuple[ParamRange, ...] = ()
    engine: str = "auto"
    truncated: bool = False
    file: str = ""
    extra: dict = field(default_factory=dict, compare=False)
    program_digest: str | LaterDigest = ""
    machine_name: str = ""
    machine_file: str = ""
    machine_sha256: str = ""
    settings: tuple[tuple[str, object], ...] = ()
    interrupted: bool = False
    budget_s: float | None = None
    profile: dict = field(default_factory=dict, compare=False)

    @property
    def safe(self) -> bool:
        return self.verdict is Verdict.SAFE

    @property
    def program_sha256(self) -> str:
        """The SHA-256 (hex) of the program's bytes (``program_digest``, computed at the first call when the
        verify left it for later: :class:`~nczones.digest.LaterDigest`); ``""`` when not known."""
        return str(self.program_digest)

    @property
    def dialect(self) -> str:
        """How the program text was read (``"linuxcnc"`` or ``"fanuc"``; every report names it)."""
        return str(dict(self.settings).get("dialect") or "linuxcnc")


@dataclass(slots=True)
class Outcome:
    """What the prover decided about one segment: a violation, a reason for ``unknown``, or neither (proved),
    and which engine decided it."""

    violation: Violation | None = None
    reason: Reason | None = None
    engine: str = "exact"
