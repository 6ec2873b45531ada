"""Run a Fanuc program through nczones and through the reference reader (tests/oracles/fanuc_ref.py) and
compare the motion.

nczones's side is what ``verify`` proves: ``nczones.gcode.interpret`` on the machine, its
``segments()`` (``nczones.prover.verify`` calls the same ``interpret`` and proves those segments).
Both sides are normalised the same way: dwells and motions that do not move (start == end) are dropped
(they cannot take the machine anywhere), then the kind (rapid / line / arc) and the exact end point of
every motion must be equal.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.motion import SegmentKind
from tests.machines import machine_text
from tests.oracles.fanuc_ref import (
    RefError,
    RefLathe,
    RefMachine,
    RefUnknown,
    reference_lathe_motion,
    reference_motion,
)

from .helpers import mill

F = Fraction

_KIND = {SegmentKind.RAPID: "rapid", SegmentKind.LINE: "line", SegmentKind.ARC: "arc",
         SegmentKind.DWELL: "dwell"}


def ref_machine(dpi: str = "calculator") -> RefMachine:
    """The reference's copy of tests/gcode/fanuc/helpers.py's mill (the numbers written again, not read from
    nczones's parsed machine)."""
    return RefMachine(
        work={"G54": [F(100), F(50), F(-200)], "G55": [F(300), F(50), F(-200)], "EXT": [F(0), F(0), F(1)],
              "G54.1P3": [F(500), F(20), F(-210)]},
        lengths={1: F(100), 2: F("150.5")},
        ref1=(F(0), F(0), F(0)), ref2=(F(-100), F(-50), F(-10)), start=(F(0), F(0), F(0)),
        g73_retract=F("0.5"), g83_clearance=F(1), boring_shift="+X", decimal_point_input=dpi,
        common={"#500": "2.5"})


_MILLS: dict = {}


def nczones_machine(dpi: str = "calculator"):
    if dpi not in _MILLS:
        _MILLS[dpi] = mill(f'decimal_point_input = "{dpi}"')
    return _MILLS[dpi]


ORIGIN = (F(0), F(0), F(0))


def normalise(motions, start=ORIGIN) -> list:
    out, here = [], tuple(start)
    for kind, end in motions:
        end = tuple(end)
        if kind == "dwell" or (kind != "arc" and end == here):
            here = end
            continue
        out.append((kind, end))
        here = end
    return out


@dataclass
class Outcome:
    status: str  # "same", "differ", "skip" (one side does not model it), "reject" (both refuse the program)
    reason: str = ""
    ours: list | None = None
    ref: list | None = None


def nczones_motion(text: str, dpi: str, block_delete):
    """``block_delete``: True (switch 1 on), False, or the collection of the switches that are on."""
    run = interpret_text(text, nczones_machine(dpi), file="gen.nc", block_delete=block_delete)
    segs = [(_KIND.get(s.kind, str(s.kind)), tuple(s.end)) for s in run.segments()]
    return run, segs


def compare(text: str, dpi: str = "calculator", block_delete=False) -> Outcome:
    try:
        ref = normalise(reference_motion(text, ref_machine(dpi), block_delete=block_delete))
        ref_err = None
    except RefUnknown as exc:
        return Outcome("skip", f"reference: {exc}")
    except RefError as exc:
        ref, ref_err = None, str(exc)
    try:
        run, segs = nczones_motion(text, dpi, block_delete)
    except GcodeError as exc:
        if ref_err is not None:
            return Outcome("reject", "both reject")
        return Outcome("differ", f"nczones rejects: {exc}", None, ref)
    if run.status != "complete":
        return Outcome("skip", f"nczones {run.status}: {[u.code for u in run.unsupported]}")
    ours = normalise(segs)
    if ref_err is not None:
        return Outcome("differ", f"reference rejects: {ref_err}", ours, None)
    if ours != ref:
        return Outcome("differ", "motion", ours, ref)
    return Outcome("same")


def first_difference(o: Outcome) -> str:
    if o.ours is None or o.ref is None:
        return o.reason
    for i, (a, b) in enumerate(zip(o.ours, o.ref)):
        if a != b:
            return f"motion {i}: nczones {a} reference {b}"
    return f"lengths: nczones {len(o.ours)} reference {len(o.ref)}"


LATHE = machine_text("fanuc_reference_lathe")


def ref_lathe() -> RefLathe:
    """The reference's copy of LATHE (geometry + wear added by hand)."""
    return RefLathe(work={"G54": [F(0), F(200)], "G55": [F(5), F(180)]},
                    tool_offsets={1: (F(80), F(50)), 2: (F("85.01"), F("44.98")), 3: (F(70), F(60))})


_LATHES: list = []


def compare_lathe(text: str) -> Outcome:
    from nczones.machine import parse_machine

    if not _LATHES:
        _LATHES.append(parse_machine(LATHE, "lathe.toml"))
    start = (F(240), F(650))
    try:
        ref = normalise(reference_lathe_motion(text, ref_lathe()), start)
    except RefUnknown as exc:
        return Outcome("skip", f"reference: {exc}")
    run = interpret_text(text, _LATHES[0], file="lathe.nc")
    segs = [(_KIND.get(s.kind, str(s.kind)), tuple(s.end)) for s in run.segments()]
    if run.status != "complete":
        return Outcome("skip", f"nczones {run.status}: {[u.code for u in run.unsupported]}")
    ours = normalise(segs, start)
    if ours != ref:
        return Outcome("differ", "motion", ours, ref)
    return Outcome("same")
