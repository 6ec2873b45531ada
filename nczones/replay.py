"""``nczones replay REPORT.json``: re-check a report's counterexamples exactly, against the files it names.

A JSON report of ``nczones verify`` names the machine file and the program
with their SHA-256, every setting that changes the verdict, and each
counterexample as exact rationals (``point_exact``, ``path_point_exact``,
``params_exact``).  Replaying one does not run the prover again: it

1. loads the machine file and the program the report names (relative paths
   from the working directory, or ``--machine``/``--program``) and refuses
   them when their SHA-256 differs from the report's (``RP102``);
2. builds the machine the counterexample speaks of: every parameter value of
   the counterexample put into the machine file's values (a work offset
   component, a tool length register, the start position; a homing error
   shifts the machine coordinates of its axis);
3. interprets the program on that machine with the report's settings
   (arc tolerance, loop bound, block delete) and takes the motions of the
   violating block;
4. checks, in exact rational arithmetic, that the path point lies on one of
   those motions (a line, a rapid the way the machine moves it — straight
   or dogleg —, a circular arc, a NURBS curve at the reported parameter, a
   tool-break recovery leg from the reported break point), that the point
   lies within the margin of it on every axis, and that the point is outside
   the allowed set, in the zone the report names.  A tool solid in a fixture
   (``kind = "solid"``, or ``kind = "recovery"`` whose ``zones`` name a part
   and not its zone: a recovery leg of the solids proof) is checked instead by
   placing the named tool part at the path point and testing that the witness
   is inside it and inside the fixture (:func:`_check_solid`).

A path point that is irrational (on a helix, an R-format arc with an
irrational centre, a developed arc; the report marks it
``path_point_on_path: false``) cannot be checked exactly: the replay checks
that it lies within :data:`IRRATIONAL_TOLERANCE_MM` of the motion and says
so.  Exit status: 0 every counterexample confirmed, 1 one was not, 2 bad
input (an unreadable report, a missing or changed file).
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any

from .errors import Diagnostic, InputError, InvalidArgument
from .exact import parse_rational
from .machine import Machine, load_machine
from .motion import Segment, SegmentKind
from .pipeline.witnesses import concrete_machine
from .witness_geometry import (
    IRRATIONAL_TOLERANCE_MM,
    REPLAYED_KINDS,
    Point,
    in_zone,
    off_motion,
    on_arc,
    on_dogleg,
    on_line,
    on_motion,
    show_point,
)

__all__ = ["Check", "replay_report", "replay_file", "on_line", "on_dogleg", "on_arc", "ReplayError",
           "IRRATIONAL_TOLERANCE_MM", "REPLAYED_KINDS"]


class ReplayError(InputError):
    """A report that cannot be replayed (codes RP1xx)."""


@dataclass(frozen=True, slots=True)
class Check:
    """The replay of one counterexample: ``confirmed`` and what was checked (or what failed)."""

    program: str
    line: int | None
    block: int
    zone: str
    confirmed: bool
    exact: bool
    message: str

    def render(self) -> str:
        where = f"{self.program}:{self.line}" if self.line is not None else self.program
        return f"{where}: {'confirmed' if self.confirmed else 'NOT REPRODUCED'}: {self.message}"


# --------------------------------------------------------------------------- reading the report


def _fail(code: str, message: str, where: str) -> ReplayError:
    return ReplayError(Diagnostic(code, message, file=where))


def _point(raw: Any, axes: tuple[str, ...], what: str, where: str) -> Point:
    if not isinstance(raw, Mapping) or set(raw) != set(axes):
        raise _fail("RP104", f"{what} must map every axis of the machine ({', '.join(axes)}) to an exact "
                             f"rational such as \"1900/3\"; found {raw!r}", where)
    try:
        return tuple(parse_rational(raw[a]) for a in axes)
    except InvalidArgument as exc:
        raise _fail("RP104", f"{what}: {exc}", where) from None


def _resolve(path: str, base: str | None) -> str:
    return path if os.path.isabs(path) or base is None else os.path.join(base, path)


def _check_hash(kind: str, path: str, actual: str, expected: Any, where: str) -> None:
    if expected and actual != expected:
        raise _fail("RP102", f"the {kind} {path} is not the one the report was made from: its SHA-256 is "
                             f"{actual[:16]}…, the report names {str(expected)[:16]}…", where)


# --------------------------------------------------------------------------- checking one counterexample



def _recovery_legs(v: Mapping[str, Any], seg: Segment, segs: list[Segment], machine: Machine,
                   settings: Mapping[str, Any], break_point: Point) -> list[Segment]:
    """The recovery motion the counterexample names (a leg from the break point, or the resumed cut)."""
    from .plans.recovery import (
        RecoveryVariant,
        motion_sequences,
        recovery_legs,
        replacement_length,
        shift_segment,
        tool_axis_index,
        tool_change_config,
    )

    cfg = tool_change_config(machine, settings.get("recovery"))
    length = seg.tool_length
    new_length = replacement_length(cfg, machine, length)
    if v.get("leg") == "resume":
        return [shift_segment(seg, tool_axis_index(machine), new_length - length, new_length)]
    index = next(k for k, s in enumerate(segs) if s is seg)
    sequence_start = next(segs[a].start for a, b in motion_sequences(segs) if a <= index <= b)
    restart = break_point if cfg.variant is RecoveryVariant.BREAKPOINT else sequence_start
    legs = recovery_legs(cfg, machine, break_point, restart, length, new_length)
    # in the cut's frame: a fixture in a work offset is where the cut saw it (as the solids proof places it)
    return [replace(lg.segment(machine.axis_names, seg), frame=seg.frame) for lg in legs if lg.name == v.get("leg")]


def _check_violation(v: Mapping[str, Any], program: str, machine: Machine, segs: list[Segment],
                     shift: Point, margin: Fraction, settings: Mapping[str, Any], where: str) -> Check:
    axes = machine.axis_names
    block, zone, line = v.get("block"), v.get("zone", ""), v.get("line")
    exact = bool(v.get("path_point_on_path", True))

    def result(ok: bool, message: str) -> Check:
        return Check(program, line, block if isinstance(block, int) else -1, zone, ok, exact, message)

    # the witness is a point of X, Y, Z (inside a tool part and a fixture): a solid violation, or a recovery
    # leg's from the solids proof (its zones name the part, not its zone: a fixture)
    zones = v.get("zones") or ()
    solid = v.get("kind") == "solid" or (v.get("kind") == "recovery" and bool(zones) and zone not in zones)
    from .lathe_solids import is_lathe_axes

    space = (("X", "Z") if is_lathe_axes(axes) else ("X", "Y", "Z")) if solid else axes  # a lathe: its section
    point = _point(v.get("point_exact"), space, "point_exact", where)
    path = _point(v.get("path_point_exact"), axes, "path_point_exact", where)
    nominal = tuple(x - d for x, d in zip(path, shift))
    mine = [s for s in segs if s.block == block]
    if not mine:
        return result(False, f"the program has no motion in block {block} on this machine")
    parameter = None
    if v.get("segment_kind") == "spline" and v.get("parameter_rational") is not None:
        parameter = parse_rational(str(v["parameter_rational"]))
    what = v.get("segment_kind", "motion")
    if v.get("kind") == "recovery":
        brk = _point(v.get("break_point_exact"), axes, "break_point_exact", where)
        cutting = [s for s in mine if s.kind in (SegmentKind.LINE, SegmentKind.ARC)
                   and (s.kind is SegmentKind.LINE and on_line(brk, s.start, s.end) is not None or on_arc(brk, s))]
        if v.get("leg") != "resume" and not cutting:
            return result(False, f"the break point {show_point(axes, brk)} is not on a cutting motion of block {block}")
        base = cutting or [s for s in mine if s.kind in (SegmentKind.LINE, SegmentKind.ARC)]
        mine = [leg for s in base for leg in _recovery_legs(v, s, segs, machine, settings, brk)]
        what = f"recovery leg {v.get('leg')!r} after a tool break at {show_point(axes, brk)}"
    hits = [s for s in mine if on_motion(nominal, s, machine, exact, parameter)]
    if not hits:
        return result(False, off_motion(axes, path, what, block, exact))
    if solid:
        how = "exactly" if exact else f"within {IRRATIONAL_TOLERANCE_MM} mm (an irrational path point)"
        return result(*_check_solid(v, point, nominal, hits, machine, how, where))
    ok, message = in_zone(point, path, zone, hits, machine, margin)
    if not ok:
        return result(False, message)
    how = "exactly" if exact else f"within {IRRATIONAL_TOLERANCE_MM} mm (an irrational path point)"
    params = v.get("params_exact") or {}
    with_params = f" with {', '.join(f'{n}={x}' for n, x in params.items())}" if params else ""
    return result(True, f"{message} and the path point lies on the {what} of block {block} {how}{with_params}")


def _fixture_origin(fx: Any, seg: Segment, index: tuple[int, int, int]) -> tuple[Fraction, Fraction, Fraction] | None:
    """Where a fixture's coordinates start at a motion: machine zero, or its work offset's origin as the re-run
    motion records it (None: the motion runs in another or a rotated frame)."""
    if not fx.frame:
        return Fraction(0), Fraction(0), Fraction(0)
    frame = seg.frame
    if frame is None or frame.work != fx.frame or frame.rotation is not None or frame.work_offset is None:
        return None
    w = frame.work_offset
    return w[index[0]], w[index[1]], w[index[2]]


def _in_fixture_xy(fx: Any, x: Fraction, y: Fraction) -> bool:
    """Is ``(x, y)`` strictly inside the fixture's XY section (a circle, a box, or a polygon: an even-odd
    crossing count, a point on an edge is not inside)?  Replay's own test, exact."""
    from .solids import FixtureCylinder, FixturePrism

    if isinstance(fx, FixtureCylinder):
        return (x - fx.cx) ** 2 + (y - fx.cy) ** 2 < fx.radius ** 2
    if isinstance(fx, FixturePrism):
        vs = fx.vertices
        inside = False
        for (x0, y0), (x1, y1) in zip(vs, vs[1:] + vs[:1]):
            cross = (x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)
            if cross == 0 and min(x0, x1) <= x <= max(x0, x1) and min(y0, y1) <= y <= max(y0, y1):
                return False  # on the boundary: not in the open interior
            if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
                inside = not inside
        return inside
    return all((lo is None or lo < q) and (hi is None or q < hi) for q, lo, hi in ((x, fx.x0, fx.x1), (y, fx.y0, fx.y1)))


def _check_solid(v: Mapping[str, Any], point: Point, path: Point, hits: list[Segment], machine: Machine,
                 how: str, where: str) -> tuple[bool, str]:
    """A tool solid in a fixture (``kind = "solid"``): the assembly placed with its controlled point at the
    path point (the part's heights from the motion's own tool length), the witness ``point`` inside the part
    the report names (a closed vertical cylinder) and inside the open interior of the fixture (its ``zone``),
    checked here in exact rationals, independently of the prover's distance computation."""
    from .lathe_solids import LatheSolids
    from .solids import machine_solids

    solids = machine_solids(machine)
    if solids is None:
        raise _fail("RP105", "a solid violation, but the machine file describes no tool or spindle solids "
                             "([[tools]], [spindle])", where)
    names = v.get("zones")
    if not isinstance(names, list) or len(names) != 1 or not isinstance(names[0], str):
        raise _fail("RP106", f"a solid violation names its part in zones = [part], got {names!r}", where)
    if isinstance(solids, LatheSolids):  # a lathe's turret tool against fixtures of revolution
        return _check_lathe_solid(v, point, path, hits, machine, solids, how)
    part_name, zone = names[0], v.get("zone", "")
    fixtures = [f for f in solids.fixtures if f.name == zone]
    if not fixtures:
        return False, f"the machine has no fixture {zone!r}"
    axes = machine.axis_names
    ix, iy, iz = axes.index("X"), axes.index("Y"), axes.index("Z")
    qx, qy, qz = point
    px, py, pz = path[ix], path[iy], path[iz]
    placed = False
    for seg in hits:
        for part in solids.parts_for(seg.tool_register) or ():
            if part.name != part_name:
                continue
            placed = True
            base = pz if part.spindle else pz - seg.tool_length
            if not ((qx - px) ** 2 + (qy - py) ** 2 <= part.radius ** 2 and base + part.z0 <= qz <= base + part.z1):
                continue
            for fx in fixtures:
                origin = _fixture_origin(fx, seg, (ix, iy, iz))
                if origin is None:
                    return False, (f"fixture {zone!r} moves with {fx.frame}, which block {v.get('block')} does not "
                                   "run in (unrotated): replay cannot place it")
                fx_q = (qx - origin[0], qy - origin[1], qz - origin[2])
                if _in_fixture_xy(fx, fx_q[0], fx_q[1]) and (fx.z0 is None or fx.z0 < fx_q[2]) \
                        and (fx.z1 is None or fx_q[2] < fx.z1):
                    return True, (f"the point {show_point(('X', 'Y', 'Z'), point)} is inside the {part.label()} placed at the path "
                                  f"point {show_point(axes, path)} and inside fixture {zone!r} (exact), and the path point "
                                  f"lies on the {v.get('segment_kind', 'motion')} of block {v.get('block')} {how}")
            return False, (f"the point {show_point(('X', 'Y', 'Z'), point)} is inside the {part.label()} at the path point, "
                           f"but not inside fixture {zone!r}")
    if not placed:
        return False, f"the tool assembly active at block {v.get('block')} has no part {part_name!r}"
    return False, (f"the point {show_point(('X', 'Y', 'Z'), point)} is not inside the part {part_name!r} placed at the path point "
                   f"{show_point(axes, path)}")


def _check_lathe_solid(v: Mapping[str, Any], point: Point, path: Point, hits: list[Segment], machine: Machine,
                       solids: Any, how: str) -> tuple[bool, str]:
    """A lathe's turret tool part in a fixture of revolution, in the section through the spindle axis
    (``specs/turning.md``, "Tool and fixture solids"): the part's rectangle relative to the tip (grown by half
    its thickness, as the proof uses it) placed at the path point minus the motion's tool offsets, the
    witness ``(X, Z)`` in that closed rectangle and in the open section of the fixture (``|X|`` between its
    radii, Z inside its range), in exact rationals, independently of the prover's Minkowski rectangles."""
    from .prover.lathe_solids import segment_tool, tip_shift

    part_name, zone = v["zones"][0], v.get("zone", "")
    fixtures = [f for f in solids.fixtures if f.name == zone]
    if not fixtures:
        return False, f"the machine has no fixture {zone!r}"
    axes = machine.axis_names
    qx, qz = point
    px, pz = path[axes.index("X")], path[axes.index("Z")]
    shown = show_point(("X", "Z"), point)
    placed = False
    for seg in hits:
        tool = segment_tool(seg)
        for part in solids.tools.get(tool, ()) if tool is not None else ():
            if part.name != part_name:
                continue
            placed = True
            sx, sz = tip_shift(seg, machine.tool_axis)
            a, b, c, d = part.rect()
            if not (px - sx + a <= qx <= px - sx + b and pz - sz + c <= qz <= pz - sz + d):
                continue
            for fx in fixtures:
                in_r = fx.r_in < abs(qx) and (fx.r_out is None or abs(qx) < fx.r_out)
                if in_r and (fx.z0 is None or fx.z0 < qz) and (fx.z1 is None or qz < fx.z1):
                    return True, (f"the point {shown} is inside the {part.label()} of tool {tool} placed at the "
                                  f"path point {show_point(axes, path)} and inside fixture {zone!r} (exact, in the "
                                  f"section through the spindle axis), and the path point lies on the "
                                  f"{v.get('segment_kind', 'motion')} of block {v.get('block')} {how}")
            return False, (f"the point {shown} is inside the {part.label()} at the path point, but not inside "
                           f"fixture {zone!r}")
    if not placed:
        return False, f"the turret tool active at block {v.get('block')} has no part {part_name!r}"
    return False, (f"the point {shown} is not inside the part {part_name!r} placed at the path point "
                   f"{show_point(axes, path)}")


def _segments(source: Any, machine: Machine, settings: Mapping[str, Any], skip: frozenset[int]) -> list[Segment]:
    """The motion of the program as the report's settings interpret it (:class:`VerifyOptions`), with the
    block-skip switches ``skip`` on."""
    from .pipeline.verification import interpretation
    from .prover.options import VerifyOptions

    options = VerifyOptions.from_settings(settings)
    return list(interpretation(source, machine, options, skip=skip).segments())


def _skips_deleted_blocks(v: Mapping[str, Any], settings: Mapping[str, Any]) -> frozenset[int]:
    """The block-skip switches on along the violation's path (their lines skipped): those the violation
    names on, and those the settings fix on; a switch left to both that it does not name is off."""
    from .blockskip import parse_block_delete

    mode = settings.get("block_delete")
    try:
        modes = parse_block_delete("on" if mode is True else mode if isinstance(mode, str) else "both")
    except ValueError:
        modes = parse_block_delete("both")
    on = {n for n, p in modes.items() if p == "on"}
    switches = v.get("switches")
    if isinstance(switches, Mapping):
        for name, position in switches.items():
            if name == "block_delete" or (isinstance(name, str) and name.startswith("block_delete/")
                                          and name[13:].isdigit()):
                n = 1 if name == "block_delete" else int(name[13:])
                if position == "on":
                    on.add(n)
                else:
                    on.discard(n)
    return frozenset(on)


def replay_report(doc: Mapping[str, Any], *, base: str | None = None, machine_file: str | None = None,
                  program_file: str | None = None, where: str = "<report>") -> list[Check]:
    """Replay every counterexample of one JSON report (a dict, as ``nczones verify --format json`` writes).

    Relative paths in the report are taken from ``base`` (default: the
    working directory); ``machine_file`` and ``program_file`` replace the
    files the report names (their SHA-256 must still match).

    >>> import json, subprocess, sys
    >>> out = subprocess.run([sys.executable, "-m", "nczones", "verify", "specs/examples/programs/notch_dip.ngc",
    ...                       "--machine", "specs/machines/grinder.toml", "--format", "json"],
    ...                      capture_output=True, text=True).stdout
    >>> [(c.line, c.zone, c.confirmed, c.exact) for c in replay_report(json.loads(out))]
    [(5, 'wheel area', True, True)]
    """
    from .gcode.source import load_program

    if not isinstance(doc, Mapping) or "verdict" not in doc or not isinstance(doc.get("violations"), list):
        raise _fail("RP101", "not a report of nczones verify (a JSON object with verdict and violations)", where)
    violations = doc["violations"]
    if not violations:
        return []
    machine_info: Mapping[str, Any] = doc["machine"] if isinstance(doc.get("machine"), Mapping) else {}
    mpath = machine_file or machine_info.get("file")
    if not mpath:
        raise _fail("RP103", "the report names no machine file; pass --machine", where)
    machine = load_machine(_resolve(mpath, base if machine_file is None else None))
    _check_hash("machine file", mpath, machine.sha256, machine_info.get("sha256"), where)
    ppath = program_file or doc.get("program")
    if not ppath or (program_file is None and str(ppath).startswith("<")):
        raise _fail("RP103", f"the report's program is {ppath or 'unnamed'} (not a file); pass --program", where)
    source = load_program(_resolve(ppath, base if program_file is None else None), name=doc.get("program") or ppath)
    _check_hash("program", ppath, source.sha256, doc.get("program_sha256"), where)
    settings: Mapping[str, Any] = doc["settings"] if isinstance(doc.get("settings"), Mapping) else {}
    try:
        margin = parse_rational(str(settings.get("margin", doc.get("margin", "0"))))
    except InvalidArgument as exc:
        raise _fail("RP104", f"margin: {exc}", where) from None
    cache: dict[tuple, tuple[list[Segment], Point, Machine]] = {}
    checks = []
    for v in violations:
        raw = v.get("params_exact") or {}
        try:
            params = {str(n): parse_rational(x) for n, x in raw.items()}
        except InvalidArgument as exc:
            raise _fail("RP104", f"params_exact: {exc}", where) from None
        skip = _skips_deleted_blocks(v, settings)
        key = (tuple(sorted(params.items())), skip)
        if key not in cache:
            concrete, shift = concrete_machine(machine, params)
            cache[key] = (_segments(source, concrete, settings, skip), shift, concrete)
        segs, shift, concrete = cache[key]
        checks.append(_check_violation(v, source.name, concrete, segs, shift, margin, settings, where))
    return checks


def _documents(data: Any) -> Iterator[Mapping[str, Any]]:
    if isinstance(data, list):
        for d in data:
            if isinstance(d, Mapping) and d.get("verdict") == "error":
                continue  # a program the verification could not read: nothing to replay
            yield d
    else:
        yield data


def replay_file(path: str, *, base: str | None = None, machine_file: str | None = None,
                program_file: str | None = None) -> list[Check]:
    """:func:`replay_report` of every report in a JSON file (one report, or a list of them)."""
    try:
        with open(path, encoding="utf-8") as fh:
            data = json.load(fh)
    except OSError as exc:
        raise _fail("RP100", f"cannot read the report: {exc.strerror or exc}", path) from None
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise _fail("RP101", f"not a JSON report: {exc}", path) from None
    docs = list(_documents(data))
    if len(docs) > 1 and (machine_file or program_file):
        raise _fail("RP103", "--machine and --program apply to a report of one program", path)
    out: list[Check] = []
    for doc in docs:
        out.extend(replay_report(doc, base=base, machine_file=machine_file, program_file=program_file, where=path))
    return out
