"""nczones: prove that a CNC program keeps the machine inside its allowed area.

The stages follow the data flow (DESIGN §1): :mod:`nczones.gcode` (text to
motion), :mod:`nczones.zones` and :mod:`nczones.machine`, :mod:`nczones.prover`
(Z3), :mod:`nczones.controller` (the reference controller),
:mod:`nczones.report`, and :mod:`nczones.cli`.

The public names below, but :func:`exact` and its two neighbours, are imported from their modules when first
asked for (PEP 562, issue 36): ``import nczones`` alone loads neither them nor :mod:`typing`, so the
``nczones`` program can tune the process (the collector's threshold, :mod:`nczones.__main__`) before the
modules that make most of a start's objects are imported.  ``re``'s cache is seeded here
(:func:`nczones.precompiled.seed_patterns`).
"""

from __future__ import annotations

__version__ = "0.1.0"


def _as_the_program() -> None:
    """In the ``nczones`` program (its console script, whose ``__main__`` imports :mod:`nczones.cli`), raise the
    collector's first threshold now, as :func:`nczones.cli.run` does once called: the modules a start imports
    make some 20,000 objects, all of which live, and at Python's threshold of 700 the dozen collections they set
    off before ``run`` traverse them for nothing (some 5 million instructions, issue 36).  Raised, never
    lowered; 0 (collection off) stays 0.  An ``import nczones`` in any other program changes nothing."""
    import sys

    script = getattr(sys.modules.get("__main__"), "__file__", None)
    if not isinstance(script, str) or script.replace("\\", "/").rsplit("/", 1)[-1] not in ("nczones",
                                                                                           "nczones-script.py"):
        return
    import gc

    first, second, third = gc.get_threshold()
    if 0 < first < 50_000:  # nczones.cli.YOUNG_OBJECTS
        gc.set_threshold(50_000, second, third)


_as_the_program()
del _as_the_program

from .precompiled import seed_patterns  # noqa: E402

seed_patterns()  # re.compile finds the patterns of a start-up compiled (issue 36: see nczones.precompiled)

# exact() is imported here, not at first use: it has the name of its subpackage, which an import of the subpackage
# binds here (to the module) before any lookup of the name would reach __getattr__
from .exact import exact, format_decimal, parse_decimal  # noqa: E402

# not typing's (importing typing is 2 ms): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from .errors import GcodeError, InputError, InvalidArgument, MachineFileError, NczonesError
    from .machine import Machine, load_machine, parse_machine
    from .motion import Plane, Segment, SegmentKind
    from .zones import AllowedSet, BoxZone, PolygonZone, Region, SteppedZone, ZonePoint
del TYPE_CHECKING

#: Each public name → the module (under ``nczones``) that defines it.
_MODULE_OF = {
    **dict.fromkeys(("GcodeError", "InputError", "InvalidArgument", "MachineFileError", "NczonesError"), "errors"),
    **dict.fromkeys(("Machine", "load_machine", "parse_machine"), "machine"),
    **dict.fromkeys(("Plane", "Segment", "SegmentKind"), "motion"),
    **dict.fromkeys(("AllowedSet", "BoxZone", "PolygonZone", "Region", "SteppedZone", "ZonePoint"), "zones"),
}

__all__ = [
    "__version__",
    "AllowedSet",
    "BoxZone",
    "GcodeError",
    "InputError",
    "InvalidArgument",
    "Machine",
    "MachineFileError",
    "NczonesError",
    "Plane",
    "PolygonZone",
    "Region",
    "Segment",
    "SegmentKind",
    "SteppedZone",
    "ZonePoint",
    "exact",
    "format_decimal",
    "load_machine",
    "parse_decimal",
    "parse_machine",
]


def __getattr__(name: str) -> Any:
    """A public name, imported from its module at its first use (then kept here)."""
    module = _MODULE_OF.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    import sys

    __import__(f"{__name__}.{module}")
    value = getattr(sys.modules[f"{__name__}.{module}"], name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
