"""What the LinuxCNC and the Fanuc language layers share (:mod:`nczones.gcode.program`,
:mod:`nczones.gcode.fanuc.program`): the loop bound, the budget's watch, the errors of unsupported language, the
program text as a source of lines and the fast path's request.

Its own module so that a Fanuc program does not import the LinuxCNC language layer (:mod:`nczones.gcode.program`
and its line shapes) at start-up (issue 36); :mod:`nczones.gcode.program` imports these names from here and
keeps them.
"""

from __future__ import annotations

from contextvars import ContextVar

from ..errors import Diagnostic, NczonesError, SourceSpan

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["DEFAULT_MAX_LOOP_ITERATIONS", "WATCHED_LIMITS", "interpretation_spent", "UnsupportedGcode",
           "IterationBoundExceeded", "LineSource", "StringSource", "FastRunRequest", "MODAL_GROUP_NAMES",
           "assumed_modal_notes"]

DEFAULT_MAX_LOOP_ITERATIONS = 100_000

#: Names of the modal groups the report mentions when the program never set them.
MODAL_GROUP_NAMES = {"units": "units (G20/G21)", "distance": "distance mode (G90/G91)",
                     "offset": "work offset (G54..G59.3)", "plane": "plane (G17/G18/G19)",
                     "feed": "feed mode (G93/G94/G95)", "tool": "tool length (G43/G49)",
                     "retract": "retract mode (G98/G99)"}


def assumed_modal_notes(assumed: Any, modal: Any, dialect: str) -> list[str]:
    """The report's lines for the modal groups a run assumed: ``assumed`` ``(group, code)`` pairs in the order
    they were noted, ``modal`` the machine file's start-up codes, ``dialect`` the control's.  The interpreter's
    (:meth:`nczones.gcode.Interpretation.assumed_modal_text`) and the LinuxCNC double pass's
    (:attr:`nczones.gcode.linuxcnc.doubles.DoublePath.assumed`) lines are these.

    >>> assumed_modal_notes([("offset", "G54")], ["G21"], "linuxcnc")
    ['work offset (G54..G59.3): assumed G54 from the machine file']
    >>> assumed_modal_notes([("retract", "G98")], [], "fanuc")[0].split(": ")[1][:38]
    "assumed G98 (the fanuc control's start"
    """
    named = set(modal)
    return [f"{MODAL_GROUP_NAMES[g]}: assumed {c} "
            + ("from the machine file" if g != "retract" or named & {"G98", "G99"} else
               f"(the {dialect} control's start-up mode; name G98 or G99 in [machine] modal "
               "if the control starts otherwise)")
            for g, c in assumed]

#: The run limits (:class:`nczones.prover.limits.RunLimits`) whose ``watch()`` block is executing: interpretation
#: is lazy, it runs inside that block, and its repetitions ask :func:`interpretation_spent`.
WATCHED_LIMITS: ContextVar[Any] = ContextVar("nczones_watched_limits", default=None)


def interpretation_spent() -> str | None:
    """Why interpretation must stop now: the watched run's budget (``--budget``) is spent; None when no run
    is watched, it has no budget or budget is left.  Asked at every repetition (a loop iteration, a jump
    back, a repeat of a call or of a canned cycle): a program that repeats for hours ends within the budget,
    as ``unknown`` (VF203) at the repetition that found it spent."""
    lim = WATCHED_LIMITS.get()
    if lim is None or lim.budget_s is None or not lim.budget_spent():
        return None
    return (f"budget of {lim.budget_s:g} s spent after {lim.spent_at or lim.elapsed():.1f} s while interpreting "
            "the program (raise --budget)")


class UnsupportedGcode(NczonesError):
    """The program uses language the layer cannot model: the verdict is ``unknown``.

    Attributes
    ----------
    diagnostic : Diagnostic
        Code (GC3xx), reason and span (file, line, column, source text).
    """

    def __init__(self, diagnostic: Diagnostic):
        self.diagnostic = diagnostic
        super().__init__(diagnostic.render())

    @property
    def code(self) -> str:
        return self.diagnostic.code

    @property
    def reason(self) -> str:
        return self.diagnostic.message

    @property
    def span(self) -> SourceSpan | None:
        return self.diagnostic.span


class IterationBoundExceeded(UnsupportedGcode):
    """A loop ran more often than ``max_loop_iterations`` (GC302)."""


class LineSource:
    """Random access to the lines of a program by offset (string or file)."""

    def line_at(self, pos: int) -> tuple[str | None, int]:
        """The line starting at ``pos`` (without newline) and the next offset; None at EOF."""
        raise NotImplementedError


class StringSource(LineSource):
    __slots__ = ("text", "n")
    text: str
    n: int

    def __init__(self, text: str):
        self.text = text
        self.n = len(text)

    def line_at(self, pos: int) -> tuple[str | None, int]:
        if pos >= self.n:
            return None, pos
        end = self.text.find("\n", pos)
        if end < 0:
            end = self.n
        line = self.text[pos:end]
        if pos == 0 and line.startswith("\ufeff"):
            line = line[1:]
        if line.endswith("\r"):
            line = line[:-1]
        return line, end + 1


class FastRunRequest:
    """What the runner yields, instead of a block, on reaching a line registered in ``fast_runs``.

    The caller may interpret lines from there on by itself (they must be
    lines of plain words the runner would yield as blocks, one block per
    line with words); it sets ``resume`` to ``(pos, lineno, index)``, the
    offset and number of the first line it did not take and the index of
    the next block, or leaves it None to let the runner read the line.
    """

    __slots__ = ("pos", "lineno", "index", "resume")
    resume: tuple[int, int, int] | None

    def __init__(self, pos: int, lineno: int, index: int):
        self.pos, self.lineno, self.index, self.resume = pos, lineno, index, None
