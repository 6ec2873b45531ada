"""The settings of one verification: :class:`VerifyOptions` (DESIGN §5).

One frozen value carries every setting a verification takes, wherever it comes from: the keywords of
:func:`nczones.prover.verify` (:meth:`VerifyOptions.from_keywords`), the command line
(:meth:`VerifyOptions.from_args`), the ``settings`` of a JSON report or of a fleet job
(:meth:`VerifyOptions.from_settings`).  :meth:`VerifyOptions.to_settings` writes the settings a report
carries (every setting that changes the verdict, as JSON values) and :meth:`VerifyOptions.validate` is the
one place the values are checked (``VF1xx`` diagnostics).

>>> from nczones.machine import parse_machine
>>> m = parse_machine('[machine]\\naxes=["X"]\\n[machine.rapid]\\nX="1"\\n[machine.reference]\\nX="0"\\n')
>>> o = VerifyOptions.from_keywords(margin="0.50", params=["start.X=-1..1"])
>>> dict(o.to_settings(m))["margin"], dict(o.to_settings(m))["params"]
('0.5', ('start.X=-1..1',))
>>> VerifyOptions.from_settings(dict(o.to_settings(m))).margin
Fraction(1, 2)
>>> [d.code for d in VerifyOptions(max_violations=0).validate()]
['VF103']
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable, Mapping
from fractions import Fraction

from ..errors import Diagnostic, InputError, InvalidArgument
from ..exact import exact, format_exact, parse_decimal, parse_rational
from ..gcode.runner_common import DEFAULT_MAX_LOOP_ITERATIONS
from ..machine import Machine
from ..precompiled import dataclass, field, replace  # dataclasses' without importing it (start-up)
from .limits import DEFAULT_BUDGET_S, RunLimits
from .result import ParamRange

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    import argparse
    from typing import Any

__all__ = ["VerifyOptions", "parse_param", "ParamError", "COMMAND_LINE", "budget_seconds", "library_folders",
           "arc_tolerance_option", "block_delete_option"]

#: Where the command line's diagnostics point.
COMMAND_LINE = "<command line>"

F0 = Fraction(0)


class ParamError(InputError):
    """A bad ``--param`` value (code VF1xx)."""


def parse_param(text: str, machine: Machine) -> ParamRange:
    """Read ``NAME=LO..HI`` (``G54.X=-2..2``, ``H1=195..205``, ``start.Z=-10..0``, ``home.X=-0.5..0.5``).

    Work offsets, start position and homing errors are deviations from the
    machine file's values; tool lengths are absolute ranges.

    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('[machine]\\naxes=["X","Z"]\\n[machine.rapid]\\nX="1"\\nZ="1"\\n'
    ...                   '[machine.reference]\\nX="0"\\nZ="0"\\n[tool_lengths]\\nH1="200"\\n')
    >>> p = parse_param("H1=195..205", m); (p.lo, p.hi)
    (Fraction(-5, 1), Fraction(5, 1))
    >>> parse_param("G54.X=-2..2", m).hi
    Fraction(2, 1)
    >>> parse_param("G54.X=0...5", m)  # 0. to 5, or 0 to .5?
    Traceback (most recent call last):
    ...
    nczones.prover.options.ParamError: <command line>: error[VF101]: --param 'G54.X=0...5': '...' is ambiguous: write a digit on both sides of a bound's point (0..5, 0..0.5)
    """
    def fail(msg: str) -> ParamError:
        return ParamError(Diagnostic("VF101", f"--param {text!r}: {msg}", file=COMMAND_LINE))

    m = re.match(r"^\s*([A-Za-z0-9_.]+)\s*=\s*(.+?)\s*$", text)
    if not m or ".." not in m.group(2):
        raise fail("expected NAME=LO..HI, e.g. G54.X=-2..2, H1=195..205, start.Z=-10..0 or home.X=-0.5..0.5")
    if "..." in m.group(2):  # 0...5: 0. to 5, or 0 to .5? (read as the second, a range ten times narrower)
        raise fail("'...' is ambiguous: write a digit on both sides of a bound's point (0..5, 0..0.5)")
    name = m.group(1)
    lo_s, hi_s = m.group(2).split("..", 1)
    try:
        lo, hi = parse_decimal(lo_s.strip()), parse_decimal(hi_s.strip())
    except (InvalidArgument, ValueError):
        raise fail(f"bounds {lo_s.strip()!r} and {hi_s.strip()!r} must be decimal numbers") from None
    if lo > hi:
        raise fail(f"the low bound {lo_s.strip()} is greater than the high bound {hi_s.strip()}")
    axes = machine.axis_names
    hm = re.fullmatch(r"H(\d+)", name)
    if hm:
        reg = int(hm.group(1))
        nominal = machine.tool_length(reg)
        return ParamRange(f"H{reg}", lo - nominal, hi - nominal, (lo, hi), absolute=True)
    if "." not in name:
        raise fail(f"unknown parameter {name!r}; allowed: G54.X .. G59.3.Z (work offsets), Hn (tool lengths), "
                   "start.AXIS, home.AXIS")
    head, axis = name.rsplit(".", 1)
    if axis not in axes:
        raise fail(f"axis {axis!r} is not an axis of the machine ({', '.join(axes)})")
    if head in ("start", "home") or re.fullmatch(r"G5[4-9](\.[123])?", head):
        return ParamRange(name, lo, hi, (lo, hi))
    raise fail(f"unknown parameter {name!r}; allowed: G54.X .. G59.3.Z (work offsets), Hn (tool lengths), "
               "start.AXIS, home.AXIS")


def _fail(code: str, message: str) -> InputError:
    return InputError(Diagnostic(code, message, file=COMMAND_LINE))


@dataclass(frozen=True, slots=True)
class VerifyOptions:
    """Every setting of one verification (the keywords of :func:`nczones.prover.verify`, the options of
    ``nczones verify``); immutable.

    ``params`` are :class:`ParamRange` values or ``"NAME=LO..HI"`` text (read against the machine by
    :meth:`ranges`); ``arc_tolerance``, ``dialect`` and ``block_delete`` None take the machine file's;
    ``library`` is one folder or several joined by ``os.pathsep``.  ``limits`` is the run's budget object
    when a caller shares one (its ``budget_s`` then wins).  The ``tool_table*`` fields are the command
    line's ``--tool-table`` (they change the machine the command verifies against, not the proof).
    ``written`` keeps the command line's text of some values, as its diagnostics quote it.
    """

    margin: Fraction = F0
    params: tuple[ParamRange | str, ...] = ()
    engine: str = "auto"
    max_violations: int = 20
    arc_tolerance: Fraction | str | None = None
    recovery: str | None = None
    max_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS
    dialect: str | None = None
    library: str | None = None
    block_delete: str | None = None
    budget_s: float | None = DEFAULT_BUDGET_S
    limits: RunLimits | None = field(default=None, compare=False)
    tool_table: str | None = None
    tool_table_units: str | None = None
    tool_table_x_offset: str | None = None
    written: tuple[tuple[str, str], ...] = field(default=(), compare=False, repr=False)

    # -- construction ---------------------------------------------------------------------------------------

    @classmethod
    def from_keywords(cls, *, margin: Fraction | str | int = 0,
                      params: Iterable[ParamRange | str] = (), engine: str = "auto", max_violations: int = 20,
                      arc_tolerance: Fraction | str | None = None, recovery: str | None = None,
                      max_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS, dialect: str | None = None,
                      library: str | os.PathLike | Iterable[str | os.PathLike] | None = None,
                      block_delete: str | None = None, budget_s: float | None = DEFAULT_BUDGET_S,
                      limits: RunLimits | None = None) -> VerifyOptions:
        """The options from the keywords of :func:`nczones.prover.verify` (their loose types: a margin as
        text or int, params as a list, library folders as a list or ``PathLike``)."""
        if isinstance(margin, str):
            margin = parse_decimal(margin)
        margin = exact(margin)
        if not isinstance(max_violations, int) or max_violations < 1:
            raise InvalidArgument(f"max_violations must be a positive integer, got {max_violations!r}")
        if library is not None and not isinstance(library, (str, os.PathLike)):
            library = os.pathsep.join(os.fspath(f) for f in library)  # several folders, in order
        return cls(margin=margin, params=tuple(params), engine=engine, max_violations=max_violations,
                   arc_tolerance=arc_tolerance, recovery=recovery, max_iterations=max_iterations,
                   dialect=dialect, library=None if library is None else os.fspath(library),
                   block_delete=block_delete, budget_s=budget_s, limits=limits)

    @classmethod
    def from_args(cls, args: argparse.Namespace, machine: Machine | None = None) -> VerifyOptions:
        """The options of a command's arguments (``nczones verify``; a command without some option leaves
        it at its default), read and checked: an :class:`~nczones.errors.InputError` with every ``VF1xx``
        diagnostic.  With the machine, ``--param`` ranges are read against it (``VF101``)."""

        def arg(name: str, default: Any = None) -> Any:
            return getattr(args, name, default)

        written: list[tuple[str, str]] = []
        problems: list[Diagnostic] = []

        def read(reader: Any, *a: Any) -> Any:
            try:
                return reader(*a)
            except InputError as exc:
                problems.extend(exc.diagnostics)
                return None

        margin = F0
        if arg("margin") is not None:
            try:
                margin = parse_decimal(args.margin)
                written.append(("margin", args.margin))
            except ValueError:  # InvalidArgument is a ValueError
                problems.append(Diagnostic("VF102", f"--margin {args.margin!r}: expected a decimal number of mm "
                                                    "(e.g. 0.001)", file=COMMAND_LINE))
        options = cls(margin=margin, engine=arg("engine", "auto"), max_violations=arg("max_violations", 20),
                      recovery=arg("recovery"), max_iterations=arg("max_iterations", DEFAULT_MAX_LOOP_ITERATIONS),
                      dialect=arg("dialect"), tool_table=arg("tool_table"), tool_table_units=arg("tool_table_units"),
                      tool_table_x_offset=arg("tool_table_x_offset"), written=tuple(written))
        problems += options.validate()
        params: tuple[ParamRange | str, ...] = tuple(arg("param", ()))
        if machine is not None:
            params = tuple(r for p in params for r in [read(parse_param, p, machine)] if r is not None)
        options = replace(options, params=params, arc_tolerance=read(arc_tolerance_option, arg("arc_tolerance")),
                          library=read(library_folders, arg("library")),
                          block_delete=read(block_delete_option, arg("block_delete")),
                          budget_s=read(budget_seconds, arg("budget")))
        if problems:
            raise InputError(problems)
        return options

    @classmethod
    def from_settings(cls, settings: Mapping[str, Any] | Iterable[tuple[str, Any]], *,
                      root: str | os.PathLike | None = None) -> VerifyOptions:
        """The options of settings as JSON values: a report's ``settings`` (:meth:`to_settings`) or a fleet
        job's normalized settings (``budget`` for ``budget_s``, ``library`` relative to ``root``).  A
        setting of the wrong type is left at its default (a report is read as far as it can be)."""
        s = dict(settings.items() if isinstance(settings, Mapping) else settings)
        kw: dict[str, Any] = {}
        if isinstance(s.get("margin"), (str, int)) and not isinstance(s.get("margin"), bool):
            kw["margin"] = parse_rational(str(s["margin"]))
        if isinstance(s.get("params"), (list, tuple)):
            kw["params"] = tuple(str(p) for p in s["params"])
        for name in ("engine", "recovery", "block_delete"):
            if isinstance(s.get(name), str):
                kw[name] = s[name]
        for name in ("max_iterations", "max_violations"):
            if isinstance(s.get(name), int) and not isinstance(s.get(name), bool):
                kw[name] = s[name]
        tol = s.get("arc_tolerance")
        if tol is not None:
            kw["arc_tolerance"] = tol if tol in ("linuxcnc", "grbl") else parse_rational(tol)
        if s.get("dialect") in ("linuxcnc", "fanuc"):
            kw["dialect"] = s["dialect"]
        if isinstance(s.get("library"), str):
            from pathlib import Path  # here, not at start-up

            kw["library"] = s["library"] if root is None else str(Path(root) / s["library"])
        for name in ("budget_s", "budget"):
            if name in s and (s[name] is None or isinstance(s[name], (int, float))) and not isinstance(s[name], bool):
                kw["budget_s"] = None if s[name] is None else float(s[name])
        return cls(**kw)

    # -- reading against a machine --------------------------------------------------------------------------

    def ranges(self, machine: Machine) -> tuple[ParamRange, ...]:
        """The parameter ranges, text read against ``machine`` (``VF101``)."""
        return tuple(parse_param(p, machine) if isinstance(p, str) else p for p in self.params)

    def block_delete_modes(self, machine: Machine) -> dict[int, str]:
        """The position setting of every block-skip switch: the option's, else the machine file's
        ``block_delete`` (itself ``both`` by default); :class:`~nczones.errors.InvalidArgument` when bad."""
        from ..blockskip import parse_block_delete

        try:
            return parse_block_delete(self.block_delete if self.block_delete is not None
                                      else getattr(machine, "block_delete", "both"))
        except ValueError as e:
            raise InvalidArgument(f"block_delete: {e}") from None

    def machine_tolerance(self, machine: Machine) -> Fraction | str | None:
        """The arc tolerance the interpretation is given: the option's, else the machine file's (None: the
        interpreter's default)."""
        return self.arc_tolerance if self.arc_tolerance is not None else machine.arc_tolerance

    def effective_dialect(self, machine: Machine) -> str:
        return machine.dialect if self.dialect is None else self.dialect

    def interpret_keywords(self, machine: Machine) -> dict[str, Any]:
        """The keywords of :func:`nczones.gcode.interpret` these options give (block skip aside)."""
        extra: dict[str, Any] = {"max_loop_iterations": self.max_iterations}
        tolerance = self.machine_tolerance(machine)
        if tolerance is not None:
            extra["arc_tolerance"] = tolerance
        if self.dialect is not None:
            extra["dialect"] = self.dialect
        if self.library is not None:
            extra["library"] = self.library
        return extra

    def to_settings(self, machine: Machine) -> tuple[tuple[str, object], ...]:
        """Every setting that can change the verdict, as JSON values in report order (a report's
        ``settings``; ``nczones replay`` re-runs with them).  A new setting belongs here too."""
        from ..blockskip import format_block_delete
        from ..gcode import DEFAULT_ARC_TOLERANCE

        ranges = self.ranges(machine)
        tolerance = self.machine_tolerance(machine)
        if tolerance is None:
            tolerance = DEFAULT_ARC_TOLERANCE
        settings: dict[str, object] = {
            "margin": format_exact(self.margin),
            "params": tuple(f"{r.name}={format_exact(r.written[0])}..{format_exact(r.written[1])}" for r in ranges),
            "engine": self.engine,
            "recovery": self.recovery,
            "arc_tolerance": tolerance if isinstance(tolerance, str) else format_exact(exact(tolerance)),
            "max_iterations": self.max_iterations,
            "max_violations": self.max_violations,
            "block_delete": format_block_delete(self.block_delete_modes(machine)),
            "dialect": self.effective_dialect(machine),
            "budget_s": self.budget_s if self.limits is None else self.limits.budget_s,
        }
        if self.library is not None:
            settings["library"] = str(self.library)
        return tuple(settings.items())

    def run_limits(self) -> RunLimits:
        """The run's budget: the shared ``limits`` if given, else a new one of ``budget_s`` seconds."""
        return self.limits if self.limits is not None else RunLimits(self.budget_s)

    # -- checking -------------------------------------------------------------------------------------------

    def validate(self) -> tuple[Diagnostic, ...]:
        """Every value out of its range, as ``VF1xx`` diagnostics naming the command-line option (empty:
        all good).  The types are the constructors' business."""
        written = dict(self.written)
        out: list[Diagnostic] = []

        def bad(code: str, message: str) -> None:
            out.append(Diagnostic(code, message, file=COMMAND_LINE))

        if self.margin < 0:
            bad("VF102", f"--margin {written.get('margin', format_exact(self.margin))}: must not be negative")
        if self.max_violations < 1:
            bad("VF103", f"--max-violations {self.max_violations}: must be at least 1")
        if self.max_iterations < 1:
            bad("VF105", f"--max-iterations {self.max_iterations}: must be at least 1")
        if isinstance(self.arc_tolerance, Fraction) and self.arc_tolerance < 0:
            bad("VF104", f"--arc-tolerance {format_exact(self.arc_tolerance)!r}: expected a non-negative decimal "
                         "number of mm (e.g. 0.002), 'linuxcnc' or 'grbl'")
        if self.budget_s is not None and not self.budget_s > 0:
            bad("VF109", f"--budget {self.budget_s!r}: expected a positive number of seconds (e.g. 60) or 'none'")
        if self.block_delete is not None:
            from ..blockskip import parse_block_delete

            try:
                parse_block_delete(self.block_delete)
            except ValueError as e:
                bad("VF110", f"--block-delete {self.block_delete!r}: {e}")
        return tuple(out)


def budget_seconds(text: str | None) -> float | None:
    """``--budget``: positive seconds, or "none" (``VF109``)."""
    if text is None:
        return DEFAULT_BUDGET_S
    if text.strip().lower() == "none":
        return None
    try:
        value: float | None = float(parse_decimal(text))
    except ValueError:  # InvalidArgument is a ValueError
        value = None
    if value is None or not value > 0:
        raise _fail("VF109", f"--budget {text!r}: expected a positive number of seconds (e.g. 60) or 'none'")
    return value


def library_folders(path: str | list[str] | None) -> str | None:
    """``--library DIR`` (repeated, or folders joined by ``os.pathsep``): existing folders, joined by
    ``os.pathsep`` in the order given, or an input error (exit 2)."""
    if path is None:
        return None
    folders = [f for p in ([path] if isinstance(path, str) else path) for f in p.split(os.pathsep) if f]
    for folder in folders:
        if not os.path.isdir(folder):
            raise _fail("VF112", f"--library {folder!r}: not a folder of subprogram files")
    return os.pathsep.join(folders) if folders else None


def arc_tolerance_option(text: str | None) -> Fraction | str | None:
    """``--arc-tolerance``: "linuxcnc", "grbl" or a non-negative decimal (mm); None (not given) stays None.

    >>> arc_tolerance_option("0.002"), arc_tolerance_option("linuxcnc")
    (Fraction(1, 500), 'linuxcnc')
    """
    if text is None or text in ("linuxcnc", "grbl"):  # None: the machine file's arc_tolerance, else 0.002
        return text
    try:
        q: Fraction | None = parse_decimal(text)
    except ValueError:  # InvalidArgument is a ValueError
        q = None
    if q is None or q < 0:
        raise _fail("VF104", f"--arc-tolerance {text!r}: expected a non-negative decimal number "
                             "of mm (e.g. 0.002), 'linuxcnc' or 'grbl'")
    return q


def block_delete_option(text: str | None) -> str | None:
    """``--block-delete``: both|off|on, or positions per switch (``1=on,2=off``), canonical (``VF110``)."""
    from ..blockskip import format_block_delete, parse_block_delete

    if text is None:
        return None
    try:
        return format_block_delete(parse_block_delete(text))
    except ValueError as e:
        raise _fail("VF110", f"--block-delete {text!r}: {e}") from None
