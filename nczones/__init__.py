"""nczones: prove that a CNC program keeps the machine inside its allowed area.

The stages follow the data flow (DESIGN §1): :mod:`nczones.gcode` (text to
motion), :mod:`nczones.zones` and :mod:`nczones.machine`, :mod:`nczones.prover`
(Z3), :mod:`nczones.controller` (the reference controller),
:mod:`nczones.report`, and :mod:`nczones.cli`.
"""

__version__ = "0.1.0"

from .precompiled import seed_patterns  # noqa: E402

seed_patterns()  # re.compile finds the patterns of a start-up compiled (issue 36: see nczones.precompiled)

from .errors import GcodeError, InputError, InvalidArgument, MachineFileError, NczonesError  # noqa: E402
from .exact import exact, format_decimal, parse_decimal  # noqa: E402
from .machine import Machine, load_machine, parse_machine  # noqa: E402
from .motion import Plane, Segment, SegmentKind  # noqa: E402
from .zones import AllowedSet, BoxZone, PolygonZone, Region, SteppedZone, ZonePoint  # noqa: E402

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
