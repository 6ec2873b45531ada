"""The tool-solids contract on what the first suite (contract.check_solids_contract) does not draw: a lathe's
turret tools against chucks (Fanuc, ``T0101`` changes), fixture prisms (forbidden XY polygons) and fixtures
in a work offset (``frame = "G55"``, moved by ``G10 L2 P2``).  specs/contract.md, "Tool solids: lathes,
prisms and work offsets".

The clauses are those of the first suite, on three provers (the machine ``r0``, every fixture grown by
:data:`SOLIDS_GROW` pulses ``rg``, shrunk by as much ``rs``) and the per-pulse controller:

* (S1) ``rg`` safe => no solid alarm; a solid alarm in block b => ``rg`` has a solid violation or an
  ``unknown`` reason in a block <= b;
* (S2) ``rs`` has a solid violation in block b => the controller alarms (solid or stroke) in a block <= b;
* (S3) every solid witness of ``r0`` is inside its part and its fixture, decided by the independent oracles
  (tests/oracles/solids.py, tests/oracles/lathe_solids.py);
* gray band: ``r0`` safe and a solid alarm: at the alarm position no part may meet a shrunk fixture.

Why ``G = 4u`` on a lathe: a pulse position is within one pulse per axis of a path point (two for slack) and
the controller grows each part by half a pulse per axis, all per axis (the section is checked with
rectangles): less than 3 pulses per axis.  A prism is grown (shrunk) by moving each edge out (in) by ``G``
along its normal: the generated prisms are convex with edges along X, Y and 3:4 diagonals, so the moved
edges meet at rational vertices and the grown prism contains every point within ``G`` of the prism (the
shrunk one every point ``G`` inside it).
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction as F

from hypothesis import strategies as st

from nczones.exact import format_decimal as fd

from .contract import (
    SOLIDS_GROW,
    ContractViolation,
    _count,
    _first_block,
    _flush,
    _require,
    program_segments,
)
from .strategies import SOLID_GAPS, _toml_table, solid_tools

__all__ = ["mill_cases", "lathe_cases", "check_mill", "check_lathe", "ContractViolation"]

GAPS = [F(g) for g in SOLID_GAPS]


# --------------------------------------------------------------------------- prisms and work offsets (mill)

def prism_vertices(p: dict, grow: F) -> list[tuple[F, F]]:
    """A right triangle with its right angle at ``(x0, y0)``, legs ``4k`` along X and ``3k`` along Y (signs
    ``sx``, ``sy``), every edge moved out by ``grow`` (its hypotenuse ``3u + 4v = 12k`` in the legs'
    coordinates ``u, v`` becomes ``3u + 4v = 12k + 5 grow``, the legs ``u = -grow``, ``v = -grow``)."""
    x0, y0, k, sx, sy, g = F(p["x0"]), F(p["y0"]), F(p["k"]), p["sx"], p["sy"], grow
    local = [(-g, -g), (4 * k + 3 * g, -g), (-g, 3 * k + 2 * g)]  # the moved lines' meeting points
    return [(x0 + sx * u, y0 + sy * v) for u, v in local]


def mill_machine_text(pulse: str, tools: dict, fixtures: list, *, grow: F = F(0), g55: tuple = (F(0),) * 3) -> str:
    """Tools 1 and 2, a spindle nose, and the fixtures grown by ``grow``: boxes and cylinders as
    ``[[fixtures]]`` (``frame = "G55"`` when drawn so), prisms as forbidden tip polygon zones."""
    lines = ['[machine]', 'axes = ["X", "Y", "Z"]', f'pulse = "{pulse}"', 'rapid_mode = "linear"',
             'path_mode = "G61"', '[machine.rapid]', 'X = "6000"', 'Y = "6000"', 'Z = "6000"',
             # the reference (the start) away from the fixtures: a tip prism must not hold it
             '[machine.reference]', 'X = "-300"', 'Y = "-300"', 'Z = "300"', '[offsets]',
             'G54 = { X = "0", Y = "0", Z = "0" }',
             f'G55 = {{ X = "{fd(g55[0])}", Y = "{fd(g55[1])}", Z = "{fd(g55[2])}" }}', '[tool_lengths]',
             *(f'H{n} = "{h}"' for n, (_, h) in tools.items()),
             '[[zones]]', 'name = "travel"', 'kind = "box"', 'min = { X = "-500", Y = "-500", Z = "-300" }',
             'max = { X = "500", Y = "500", Z = "800" }']
    for n, (parts, _) in tools.items():
        lines += ['[[tools]]', f'number = {n}', 'parts = [' + ", ".join(
            f'{{ name = "{name}", diameter = "{d}", length = "{ln}" }}' for name, d, ln in parts) + ']']
    lines += ['[spindle]', 'parts = [{ name = "spindle nose", diameter = "60", length = "50" }]']
    for f in fixtures:
        lines += _fixture_lines(f, grow)
    return "\n".join(lines) + "\n"


def _z_range(f: dict, grow: F) -> tuple[F | None, F | None] | None:
    z0 = None if f["z0"] is None else F(f["z0"]) - grow
    z1 = None if f["z1"] is None else F(f["z1"]) + grow
    return None if z0 is not None and z1 is not None and z0 >= z1 else (z0, z1)


def _fixture_lines(f: dict, grow: F) -> list[str]:
    zr = _z_range(f, grow)
    if zr is None:
        return []
    if f["kind"] == "prism":
        if F(f["k"]) + grow <= 0:  # shrunk away (the triangle's inradius is k)
            return []
        verts = ", ".join(f'["{fd(x)}", "{fd(y)}"]' for x, y in prism_vertices(f, grow))
        out = ['[[zones]]', f'name = "{f["name"]}"', 'kind = "polygon"', 'forbid = true', 'point = "tip"',
               'plane = ["X", "Y"]', f'vertices = [{verts}]']
        out += [f'min = {_toml_table({"Z": zr[0]})}'] if zr[0] is not None else []
        return out + ([f'max = {_toml_table({"Z": zr[1]})}'] if zr[1] is not None else [])
    frame = ['frame = "G55"'] if f.get("frame") else []
    zs = ([f'min_z = "{fd(zr[0])}"'] if zr[0] is not None else []) + ([f'max_z = "{fd(zr[1])}"'] if zr[1] is not None
                                                                      else [])
    if f["kind"] == "cylinder":
        r = F(f["r"]) + grow
        if r <= 0:
            return []
        return ['[[fixtures]]', f'name = "{f["name"]}"', 'kind = "cylinder"', *frame,
                f'centre = {{ X = "{f["cx"]}", Y = "{f["cy"]}" }}', f'radius = "{fd(r)}"', *zs]
    lo = {"X": F(f["x0"]) - grow, "Y": F(f["y0"]) - grow}
    hi = {"X": F(f["x1"]) + grow, "Y": F(f["y1"]) + grow}
    if lo["X"] >= hi["X"] or lo["Y"] >= hi["Y"]:
        return []
    if zr[0] is not None:
        lo["Z"] = zr[0]
    if zr[1] is not None:
        hi["Z"] = zr[1]
    return ['[[fixtures]]', f'name = "{f["name"]}"', 'kind = "box"', *frame, f'min = {_toml_table(lo)}',
            f'max = {_toml_table(hi)}']


@st.composite
def mill_fixtures(draw, framed: bool):
    """1..3 fixtures near the origin: prisms (right triangles with a 3:4 hypotenuse), boxes and cylinders;
    with ``framed`` the boxes and cylinders are in G55 (the program runs in G55: one frame for all)."""
    out = []
    for k in range(draw(st.integers(1, 3))):
        z1 = draw(st.sampled_from(["20", "35", "50", None]))
        kind = draw(st.sampled_from(["prism", "prism", "box", "cylinder"]))
        if kind == "prism":
            out.append({"kind": "prism", "name": f"wedge{k}", "x0": str(draw(st.integers(-40, 20))),
                        "y0": str(draw(st.integers(-40, 20))), "k": str(draw(st.integers(2, 8))),
                        "sx": draw(st.sampled_from([1, -1])), "sy": draw(st.sampled_from([1, -1])), "z0": "0",
                        "z1": z1})
        elif kind == "box":
            x0, y0 = draw(st.integers(-40, 20)), draw(st.integers(-40, 20))
            out.append({"kind": "box", "name": f"box{k}", "x0": str(x0), "x1": str(x0 + draw(st.integers(5, 30))),
                        "y0": str(y0), "y1": str(y0 + draw(st.integers(5, 30))), "z0": "0", "z1": z1,
                        "frame": framed})
        else:
            out.append({"kind": "cylinder", "name": f"post{k}", "cx": str(draw(st.integers(-40, 40))),
                        "cy": str(draw(st.integers(-40, 40))), "r": draw(st.sampled_from(["3", "8", "12.5"])),
                        "z0": "0", "z1": z1, "frame": framed})
    return out


def _near_mill(draw, fixtures: list, tools: dict, h: int, origin: tuple) -> tuple[F, F, F]:
    """A tip position (the program's frame, whose origin is ``origin``) where a part of tool ``h`` passes a
    fixture's side or top at one of the gaps, or a point in the open."""
    if draw(st.integers(0, 4)) == 0:
        return F(draw(st.integers(-60, 60))), F(draw(st.integers(-60, 60))), F(draw(st.integers(0, 120)))
    f = draw(st.sampled_from(fixtures))
    x, y, z = _near_fixture(draw, f, tools, h)
    if f.get("frame"):  # in the program's frame already
        return x, y, z
    return x - origin[0], y - origin[1], z - origin[2]


def _near_fixture(draw, f: dict, tools: dict, h: int) -> tuple[F, F, F]:
    parts = tools[h][0]
    k = draw(st.integers(0, len(parts) - 1))
    z0 = sum(F(ln) for _, _, ln in parts[:k])
    r = F(parts[k][1]) / 2
    gap = draw(st.sampled_from(GAPS))
    top = F(f["z1"]) if f["z1"] is not None else F(40)
    if draw(st.booleans()):  # above it: the part's bottom `gap` above the top, its axis over the fixture
        x, y = _inside_point(f)
        return x, y, top - z0 + gap
    z = top - z0 - draw(st.sampled_from([F(1), F(5), F(10)]))
    if f["kind"] == "prism":  # beside the hypotenuse (its outward normal (3, 4) / 5 in the legs' frame)
        _, (ax, ay), (bx, by) = prism_vertices(f, F(0))
        t = draw(st.sampled_from([F(0), F(1, 4), F(1, 2), F(1), F(-1, 10), F(11, 10)]))
        px, py = ax + t * (bx - ax), ay + t * (by - ay)
        return px + f["sx"] * F(3, 5) * (r + gap), py + f["sy"] * F(4, 5) * (r + gap), z
    if f["kind"] == "cylinder":
        dx, dy = draw(st.sampled_from([(1, 0), (0, 1), (-1, 0), (0, -1), (F(3, 5), F(4, 5))]))
        reach = F(f["r"]) + r + gap
        return F(f["cx"]) + dx * reach, F(f["cy"]) + dy * reach, z
    return F(f["x0"]) - r - gap, (F(f["y0"]) + F(f["y1"])) / 2 + draw(st.sampled_from([F(0), F(1), F(-2)])), z


def _inside_point(f: dict) -> tuple[F, F]:
    if f["kind"] == "prism":
        x0, y0, k = F(f["x0"]), F(f["y0"]), F(f["k"])
        return x0 + f["sx"] * k, y0 + f["sy"] * k  # (k, k) in the legs' frame: inside (3k + 4k < 12k)
    if f["kind"] == "cylinder":
        return F(f["cx"]), F(f["cy"])
    return F(f["x0"]) + 1, F(f["y0"]) + 1


@st.composite
def mill_cases(draw, *, max_moves=4):
    """(pulse, tools, fixtures, G55 origin, program text): prisms always possible; with G55 (half the cases)
    the boxes and cylinders move with it, the program runs in G55 and may move it with ``G10 L2 P2``."""
    pulse = draw(st.sampled_from(["0.01", "0.005"]))
    framed = draw(st.booleans())
    fixtures, tools = draw(mill_fixtures(framed)), draw(solid_tools())
    g55 = (F(draw(st.sampled_from([0, 100, -150]))), F(draw(st.sampled_from([0, 50]))), F(0)) if framed else (F(0),) * 3
    start_g55 = g55
    h = draw(st.sampled_from([1, 2]))
    work = "G55" if framed else "G54"
    lines = [f"G21 G90 G17 {work}", f"T{h} M6", f"G43 H{h}", "G0 X-70 Y-70 Z150"]
    px, py, pz = F(-70), F(-70), F(150)
    for _ in range(draw(st.integers(1, max_moves))):
        what = draw(st.sampled_from(["line", "line", "rapid", "arc", "tool"] + (["g10", "g10"] if framed else [])))
        if what == "tool":
            h = 3 - h
            lines += [f"T{h} M6", f"G43 H{h}"]
            continue
        if what == "g10":  # the fixtures move with G55, the tool stays: checked at rest, then along a move to
            # a point next to a G55 fixture where it is now (a controller that kept the old origin would differ)
            dx = draw(st.sampled_from([F(-10), F(-2), F("-0.5"), F("0.5"), F(2), F(10)]))
            g55 = (g55[0] + dx, g55[1], g55[2])
            lines.append(f"G10 L2 P2 X{fd(g55[0])} Y{fd(g55[1])} Z{fd(g55[2])}")
            px -= dx
            framed_fx = [f for f in fixtures if f.get("frame")]
            x, y, z = _near_fixture(draw, draw(st.sampled_from(framed_fx)), tools, h) if framed_fx else (px, py, pz)
            lines.append(f"G1 X{fd(x)} Y{fd(y)} Z{fd(z)} F2000")
            px, py, pz = x, y, z
            continue
        x, y, z = _near_mill(draw, fixtures, tools, h, g55)
        if what in ("line", "rapid") or (x, y) == (px, py):
            lines.append(f"{'G1' if what == 'line' else 'G0'} X{fd(x)} Y{fd(y)} Z{fd(z)} F2000")
        else:  # a half turn about the midpoint, ending exactly on the circle
            lines.append(f"G{draw(st.sampled_from([2, 3]))} X{fd(x)} Y{fd(y)} I{fd((x - px) / 2)} J{fd((y - py) / 2)} "
                         "F2000")
            z = pz
        px, py, pz = x, y, z
    return pulse, tools, fixtures, start_g55 if framed else None, "\n".join(lines) + "\nM30\n"


def _placed(fx, seg):
    """A fixture where a motion sees it, in machine coordinates (its work offset's origin from the motion's
    frame; None: the motion does not carry that offset)."""
    from nczones.solids import FixtureCylinder, FixturePrism

    if not fx.frame:
        return fx
    fr = seg.frame
    if fr is None or fr.work != fx.frame or fr.rotation is not None or fr.work_offset is None:
        return None
    ox, oy, oz = fr.work_offset
    add = (lambda v, d: None if v is None else v + d)  # noqa: E731
    zs = {"z0": add(fx.z0, oz), "z1": add(fx.z1, oz), "frame": ""}
    if isinstance(fx, FixturePrism):
        return replace(fx, vertices=tuple((x + ox, y + oy) for x, y in fx.vertices), **zs)
    if isinstance(fx, FixtureCylinder):
        return replace(fx, cx=fx.cx + ox, cy=fx.cy + oy, **zs)
    return replace(fx, x0=add(fx.x0, ox), x1=add(fx.x1, ox), y0=add(fx.y0, oy), y1=add(fx.y1, oy), **zs)


def _mill_replay(solids, r0, by_block) -> None:
    from oracles.solids import inside_part_and_fixture

    for v in (v for v in r0.violations if v.kind == "solid"):
        seg = by_block[v.block][0]
        part = next((p for p in solids.parts_for(seg.tool_register) or () if p.name in v.zones), None)
        fx = next((f for f in solids.fixtures if f.name == v.zone), None)
        fx = None if fx is None else _placed(fx, seg)
        _require(part is not None and fx is not None, f"witness names {v.zones} / {v.zone!r}: not placed")
        point, path = tuple(x for _, x in v.point), tuple(x for _, x in v.path_point)
        _require(inside_part_and_fixture(point, path, part, fx, seg.tool_length),
                 f"solid witness {point} is not inside {part.label()} at {path} and inside `{fx.name}`: {v.note}")
        _count("solids+: unsafe witness replayed")


def _mill_gray(machine, shrunk, alarm, seg) -> None:
    from nczones.solids import machine_solids

    from oracles.solids import part_hits

    solids, small = machine_solids(machine), machine_solids(shrunk)
    x, y, z = alarm.position
    for part in solids.parts_for(seg.tool_register) or solids.spindle:
        for fx in small.fixtures if small is not None else ():
            placed = _placed(fx, seg)
            _require(placed is None or not part_hits(part, placed, x, y, z, seg.tool_length),
                     f"prover: safe; controller alarm at {alarm.position}, where {part.label()} is in `{fx.name}` "
                     f"shrunk by {SOLIDS_GROW} pulses")


def check_mill(pulse: str, tools: dict, fixtures: list, g55, text: str, *, prove=None) -> str:
    """The contract on a mill with prisms and (maybe) fixtures in G55."""
    u = F(pulse)
    origin = g55 if g55 is not None else (F(0),) * 3
    texts = [mill_machine_text(pulse, tools, fixtures, grow=g * SOLIDS_GROW * u, g55=origin) for g in (0, 1, -1)]
    return _check(texts, text, _mill_replay, _mill_gray, prove)


# --------------------------------------------------------------------------- a lathe's turret tools

LATHE_OFFSETS = {1: (F(50), F(100)), 2: (F(60), F(120))}


@st.composite
def lathe_tools(draw):
    """Tools 1 and 2: 1..3 rectangles relative to the tip, stacked up Z, some with a thickness."""
    tools = {}
    for n in (1, 2):
        parts, z = [], F(0)
        for k in range(draw(st.integers(1, 3))):
            x0 = F(draw(st.integers(-20, 10)))
            ln = F(draw(st.sampled_from([5, 10, 30])))
            parts.append((["insert", "bar", "holder"][k], x0, x0 + draw(st.sampled_from([2, 8, 16, 40])), z, z + ln,
                          F(draw(st.sampled_from([0, 0, 5, 20])))))
            z += ln
        tools[n] = parts
    return tools


@st.composite
def lathe_fixtures(draw):
    """1..2 solids of revolution: chucks (rings or solid) near Z 0, a tailstock quill further up Z."""
    out = []
    for k in range(draw(st.integers(1, 2))):
        if draw(st.integers(0, 3)):
            r = draw(st.integers(40, 100))
            out.append({"name": f"chuck{k}", "kind": "chuck", "r": F(r),
                        "r_in": F(draw(st.sampled_from([0, 10, 25, 35]))),
                        "z0": draw(st.sampled_from([F(0), None])), "z1": F(draw(st.sampled_from([30, 60, 90])))})
        else:
            out.append({"name": f"quill{k}", "kind": "cylinder", "r": F(draw(st.sampled_from([10, 20]))), "r_in": F(0),
                        "z0": F(draw(st.sampled_from([200, 260]))), "z1": None})
    return out


def lathe_machine_text(pulse: str, tools: dict, fixtures: list, *, grow: F = F(0)) -> str:
    """A Fanuc lathe (X a diameter, G54 zero, tool offsets :data:`LATHE_OFFSETS`), the fixtures grown by
    ``grow`` on every side of their sections (a ring's inner radius down to 0 at least; shrunk away: left out)."""
    lines = ['[machine]', 'type = "lathe"', 'dialect = "fanuc"', 'axes = ["X", "Z"]', 'diameter_axes = ["X"]',
             f'pulse = "{pulse}"', 'rapid_mode = "linear"', 'path_mode = "G61"', '[machine.rapid]', 'X = "6000"',
             'Z = "6000"', '[machine.reference]', 'X = "300"', 'Z = "500"', '[offsets]', 'G54 = { X = "0", Z = "0" }',
             '[tool_offsets]', *(f'{n} = {{ X = "{fd(x)}", Z = "{fd(z)}", R = "0.4", tip = {2 + n} }}'
                                 for n, (x, z) in LATHE_OFFSETS.items()),
             '[[zones]]', 'name = "travel"', 'kind = "box"', 'min = { X = "-400", Z = "-300" }',
             'max = { X = "600", Z = "900" }']
    for n, parts in tools.items():
        lines += ['[[tools]]', f'number = {n}', 'parts = [' + ", ".join(
            f'{{ name = "{nm}", x = ["{fd(a)}", "{fd(b)}"], z = ["{fd(c)}", "{fd(d)}"], thickness = "{fd(w)}" }}'
            for nm, a, b, c, d, w in parts) + ']']
    for f in fixtures:
        r, r_in = f["r"] + grow, max(F(0), f["r_in"] - grow) if f["r_in"] else F(0)
        z0 = None if f["z0"] is None else f["z0"] - grow
        z1 = None if f["z1"] is None else f["z1"] + grow
        if r <= r_in or (z0 is not None and z1 is not None and z0 >= z1):
            continue
        zs = ([f'min_z = "{fd(z0)}"'] if z0 is not None else []) + ([f'max_z = "{fd(z1)}"'] if z1 is not None else [])
        lines += ['[[fixtures]]', f'name = "{f["name"]}"', f'kind = "{f["kind"]}"', f'radius = "{fd(r)}"',
                  *([f'inner_radius = "{fd(r_in)}"'] if r_in else []), *zs]
    return "\n".join(lines) + "\n"


def _near_lathe(draw, fixtures: list, tools: dict, t: int) -> tuple[F, F]:
    """A controlled (machine) position where a part of tool ``t`` passes a fixture's section at one of the
    gaps (on X or on Z), or a point in the open.  The part's rectangle ``a..b × c..d`` (grown by half its
    thickness) at the tip ``(X - sx, Z - sz)`` meets the section ``f0..f1 × g0..g1`` when ``X`` is in
    ``(f0 - b + sx, f1 - a + sx)`` and ``Z`` in ``(g0 - d + sz, g1 - c + sz)``."""
    sx, sz = LATHE_OFFSETS[t]
    if draw(st.integers(0, 4)) == 0:
        return sx + draw(st.integers(-80, 120)), sz + draw(st.integers(-20, 300))
    f = draw(st.sampled_from(fixtures))
    _, a, b, c, d, w = draw(st.sampled_from(tools[t]))
    a, b = a - w / 2, b + w / 2
    f0, f1 = draw(st.sampled_from([(f["r_in"], f["r"])] + ([(-f["r"], -f["r_in"])] if f["r_in"] else [])))
    if not f["r_in"]:
        f0 = -f["r"]
    g0 = f["z0"] if f["z0"] is not None else F(-100)
    g1 = f["z1"] if f["z1"] is not None else g0 + 100
    gap = draw(st.sampled_from(GAPS))
    qx0, qx1, qz0, qz1 = f0 - b + sx, f1 - a + sx, g0 - d + sz, g1 - c + sz
    inside_x = draw(st.sampled_from([(qx0 + qx1) / 2, qx0 + 1, qx1 - 1]))
    inside_z = draw(st.sampled_from([(qz0 + qz1) / 2, qz0 + 1, qz1 - 1]))
    side = draw(st.sampled_from(["x0", "x1"] + (["z0"] if f["z0"] is not None else [])
                                + (["z1"] if f["z1"] is not None else [])))
    if side == "x0":
        return qx0 - gap, inside_z
    if side == "x1":
        return qx1 + gap, inside_z
    return inside_x, (qz1 + gap if side == "z1" else qz0 - gap)


@st.composite
def lathe_cases(draw, *, max_moves=4):
    """(pulse, tools, fixtures, program text): a Fanuc lathe program (G98 feed per minute, X diameters) of
    lines, rapids, arcs in ZX (a half turn about the midpoint, I K) and ``T0101``/``T0202`` changes, passing
    close to the chucks and the quill."""
    pulse = draw(st.sampled_from(["0.01", "0.005"]))
    tools, fixtures = draw(lathe_tools()), draw(lathe_fixtures())
    t = draw(st.sampled_from([1, 2]))
    px, pz = F(250), F(450)  # machine, well away
    lines = ["G21 G18 G98 G40", f"T0{t}0{t}"]

    def prog(x: F, z: F) -> str:
        sx, sz = LATHE_OFFSETS[t]
        return f"X{fd(2 * (x - sx))} Z{fd(z - sz)}"
    lines.append(f"G00 {prog(px, pz)}")
    for _ in range(draw(st.integers(1, max_moves))):
        what = draw(st.sampled_from(["line", "line", "rapid", "arc", "tool"]))
        if what == "tool":
            t = 3 - t
            lines.append(f"T0{t}0{t}")
            continue
        x, z = _near_lathe(draw, fixtures, tools, t)
        if what in ("line", "rapid") or (x, z) == (px, pz):
            lines.append(f"{'G01' if what == 'line' else 'G00'} {prog(x, z)} F2000")
        else:
            lines.append(f"G0{draw(st.sampled_from([2, 3]))} {prog(x, z)} I{fd((x - px) / 2)} K{fd((z - pz) / 2)} "
                         "F2000")
        px, pz = x, z
    return pulse, tools, fixtures, "%\nO1\n" + "\n".join(lines) + "\nM30\n%\n"


def _section_part(part):
    """The part as the machine file means it in the section: its rectangle grown by half its thickness."""
    h = part.thickness / 2
    return replace(part, x0=part.x0 - h, x1=part.x1 + h, thickness=F(0))


def _lathe_replay(solids, r0, by_block) -> None:
    from oracles.lathe_solids import contact_inside, tip_of, tool_of

    for v in (v for v in r0.violations if v.kind == "solid"):
        seg = by_block[v.block][0]
        part = next((p for p in solids.tools.get(tool_of(seg), ()) if p.name in v.zones), None)
        fx = next((f for f in solids.fixtures if f.name == v.zone), None)
        _require(part is not None and fx is not None, f"witness names {v.zones} / {v.zone!r}: not of the tool")
        tip = tip_of(seg, tuple(x for _, x in v.path_point))
        point = tuple(x for _, x in v.point)
        _require(contact_inside(point, tip, _section_part(part), fx),
                 f"solid witness {point} is not inside {part.label()} at the tip {tip} and inside `{fx.name}`")
        _count("solids+: unsafe witness replayed (lathe)")


def _lathe_gray(machine, shrunk, alarm, seg) -> None:
    from nczones.solids import machine_solids

    from oracles.lathe_solids import part_meets, tip_of, tool_of

    solids, small = machine_solids(machine), machine_solids(shrunk)
    tip = tip_of(seg, alarm.position)
    for part in solids.tools.get(tool_of(seg), ()):
        for fx in small.fixtures if small is not None else ():
            _require(not part_meets(_section_part(part), fx, *tip),
                     f"prover: safe; controller alarm at {alarm.position}, where {part.label()} is in `{fx.name}` "
                     f"shrunk by {SOLIDS_GROW} pulses")


def check_lathe(pulse: str, tools: dict, fixtures: list, text: str, *, prove=None) -> str:
    """The contract on a Fanuc lathe with turret tool solids."""
    u = F(pulse)
    texts = [lathe_machine_text(pulse, tools, fixtures, grow=g * SOLIDS_GROW * u) for g in (0, 1, -1)]
    return _check(texts, text, _lathe_replay, _lathe_gray, prove)


# --------------------------------------------------------------------------- the clauses

def _check(texts: list[str], text: str, replay, gray, prove) -> str:
    from nczones.controller import simulate
    from nczones.machine import parse_machine
    from nczones.prover import Verdict, VerifyOptions
    from nczones.prover import prove as _prove
    from nczones.solids import machine_solids

    prove = prove or _prove
    machine, grown, shrunk = (parse_machine(t, f"{n}.toml") for t, n in zip(texts, ("solids", "grown", "shrunk")))
    segs = program_segments(text, machine)
    by_block: dict[int, list] = {}
    for s in segs:
        by_block.setdefault(s.block, []).append(s)
    opts = VerifyOptions(max_violations=1000)
    r0, rg, rs = (prove(segs, m, opts) for m in (machine, grown, shrunk))
    replay(machine_solids(machine), r0, by_block)
    sim = simulate(segs, machine, start=machine.start, monitor="pulse", mode="check")
    alarm = sim.alarms[0] if sim.alarms else None
    solid_alarm = alarm if alarm is not None and alarm.kind == "solid" else None
    solid = [v for v in rg.violations if v.kind == "solid"]
    if rg.verdict is Verdict.SAFE:  # (S1)
        _require(solid_alarm is None, f"prover: safe with the fixtures grown by {SOLIDS_GROW} pulses; controller: "
                                      f"{solid_alarm}")
        _count("solids+: grown safe, no solid alarm")
    if solid_alarm is not None:
        first = _first_block(solid + list(rg.reasons))
        _require(first is not None and first <= solid_alarm.block,
                 f"controller: {solid_alarm.part} enters `{solid_alarm.zone}` in block {solid_alarm.block}; the "
                 f"prover with the fixtures grown finds nothing there or before (first: {first})")
    deep = _first_block([v for v in rs.violations if v.kind == "solid"])
    if deep is not None:  # (S2)
        _require(alarm is not None and alarm.block is not None and alarm.block <= deep,
                 f"prover: a part enters a fixture shrunk by {SOLIDS_GROW} pulses in block {deep}; controller: "
                 f"{'no alarm' if alarm is None else f'alarm only in block {alarm.block}'}")
        _count("solids+: deep (shrunk unsafe), alarm at or before" + (" (stroke)" if solid_alarm is None else ""))
    if r0.verdict is Verdict.SAFE and solid_alarm is not None:  # the gray band
        gray(machine, shrunk, solid_alarm, by_block[solid_alarm.block][0])
        _count("solids+: gray band (safe, solid alarm)")
    outcome = {Verdict.SAFE: "safe", Verdict.UNSAFE: "unsafe"}.get(r0.verdict, "unknown")
    _count(f"solids+: prover {outcome}, controller {alarm.kind if alarm else 'clean'}")
    _flush()
    return outcome
