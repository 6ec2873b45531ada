"""Reports people read and tools ingest (DESIGN §8, issue 10).

* :func:`render_report` dispatches on the format: ``text``
  (:mod:`nczones.report.text`, compiler-style), ``json``
  (``specs/report.schema.json``), ``html`` (:mod:`nczones.report.html`, one
  self-contained file with plots) and ``sarif`` (:mod:`nczones.report.sarif`,
  SARIF 2.1.0).
* :func:`plot_program` draws a program over a machine's allowed set (the
  notebooks' and ``nczones plot``'s entry point).
* :mod:`nczones.report.progress`: the progress bar on standard error.

Submodules are imported lazily: importing :mod:`nczones.report` does not load
matplotlib.

>>> from nczones import load_machine
>>> from nczones.prover import verify
>>> m = load_machine("specs/machines/grinder.toml")
>>> r = verify("specs/examples/programs/notch_over.ngc", m)
>>> render_report(r, "text", deterministic=True).splitlines()[-1]
'specs/examples/programs/notch_over.ngc: safe: every motion stays inside the allowed set; 3 segments checked; dialect linuxcnc; solver z3'
"""

from __future__ import annotations

from collections.abc import Callable

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["render_report", "plot_program", "relevant_planes", "FORMATS", "RENDERERS"]

def _text(result: Any, machine: Any, program: Any, color: bool, deterministic: bool) -> str:
    from .numbers import resolution_of
    from .text import render_text

    return render_text(result, program if isinstance(program, str) else "", color=color,
                       deterministic=deterministic, resolution=resolution_of(machine))


def _json(result: Any, machine: Any, program: Any, color: bool, deterministic: bool) -> str:
    from ..prover.render import render_json

    return render_json(result, deterministic=deterministic)


def _sarif(result: Any, machine: Any, program: Any, color: bool, deterministic: bool) -> str:
    from .sarif import render_sarif

    return render_sarif(result, machine=machine, deterministic=deterministic)


def _html(result: Any, machine: Any, program: Any, color: bool, deterministic: bool) -> str:
    if machine is None:
        from ..errors import InvalidArgument

        raise InvalidArgument("the html report needs the machine (render_report(..., machine=m))")
    use_agg_backend()
    from .html import render_html

    return render_html(result, machine, program, deterministic=deterministic)


#: The renderer of each report format, by the name ``--format`` takes (docs/design.md §10 "How to add a
#: report format"); each imports its module when it runs, so importing this package loads none of them.
RENDERERS: dict[str, Callable[[Any, Any, Any, bool, bool], str]] = {
    "text": _text, "json": _json, "html": _html, "sarif": _sarif}
FORMATS = tuple(RENDERERS)


def render_report(result: Any, fmt: str = "text", *, machine: Any = None, program: Any = None, color: bool = False,
                  deterministic: bool = False) -> str:
    """Render a verification :class:`~nczones.prover.Result` in one of :data:`FORMATS`.

    ``machine`` is needed for ``html`` (the plots); ``program`` (a path or a
    :class:`~nczones.gcode.source.ProgramSource`) defaults to ``result.file``.
    """
    renderer = RENDERERS.get(fmt)
    if renderer is None:
        from ..errors import InvalidArgument

        raise InvalidArgument(f"unknown report format {fmt!r}; allowed: {', '.join(FORMATS)}")
    return renderer(result, machine, program, color, deterministic)


def use_agg_backend() -> None:
    """Use the non-interactive Agg backend unless pyplot is already set up (CLI, headless CI)."""
    import sys

    if "matplotlib.pyplot" not in sys.modules:
        import matplotlib

        matplotlib.use("Agg")


def plot_program(program, machine, plane=None, result=None, **kwargs):
    """See :func:`nczones.report.figure.plot_program`."""
    from .figure import plot_program as _plot

    return _plot(program, machine, plane, result, **kwargs)


def relevant_planes(machine, result=None):
    """See :func:`nczones.report.figure.relevant_planes`."""
    from .figure import relevant_planes as _planes

    return _planes(machine, result)
