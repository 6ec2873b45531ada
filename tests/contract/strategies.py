"""The generated machines and programs the contract is checked on."""

from hypothesis import strategies as st

from nczones.testing import machines, programs


@st.composite
def contract_cases(draw, *, axes=(("X", "Y"), ("X", "Y", "Z")), allow_kinds=("stepped", "box", "polygon"),
                   pulses=("0.01", "0.01", "0.001"), max_blocks=6, arcs=True, inside_biases=(0.3, 0.6, 0.9),
                   boundary_bias=0.7, mix=None):
    """(machine, program text): every zone kind, 2 or 3 axes, boundary-biased programs."""
    machine = draw(
        machines(
            axes=draw(st.sampled_from(axes)),
            allow_kinds=allow_kinds,
            size=100,
            pulse=draw(st.sampled_from(pulses)),
        )
    )
    text = draw(
        programs(
            machine,
            max_blocks=max_blocks,
            arcs=arcs,
            subprograms=True,
            inside_bias=draw(st.sampled_from(inside_biases)),
            boundary_bias=boundary_bias,
            mix=mix,
        )
    )
    return machine, text


@st.composite
def roughing_profiles(draw):
    """A monotone turning contour for a roughing cycle: its (z, x) points (x a radius that grows as z falls
    from 0), the stock's radius above it, and the cycle's depth of cut and retract (decimal text)."""
    n = draw(st.integers(1, 3))
    x, z = draw(st.integers(2, 6)), 0
    points = [(z, x)]
    for _ in range(n):
        z -= draw(st.integers(2, 8))
        x += draw(st.integers(0, 3))
        points.append((z, x))
    top = x + draw(st.integers(1, 4))
    depth = draw(st.sampled_from(["1", "1.5", "2"]))
    retract = draw(st.sampled_from(["0.3", "0.5", "1"]))
    return points, top, depth, retract


# --------------------------------------------------------------------------- tool solids (issue 39)

#: Where a generated tool part passes a fixture: the gap between them (negative: that deep in it), in mm.
SOLID_GAPS = ("-2", "-0.5", "-0.05", "-0.01", "0", "0.01", "0.02", "0.05", "0.2", "1", "5")


@st.composite
def solid_fixtures(draw):
    """1..3 fixtures near the origin: boxes (some sides unbounded, one may be a tip forbid zone) and vertical
    cylinders, as ``dict`` (rendered by :func:`solids_machine_text`)."""
    out = []
    for k in range(draw(st.integers(1, 3))):
        z1 = draw(st.sampled_from(["20", "35", "50", None]))
        if draw(st.booleans()):
            x0 = draw(st.integers(-40, 20))
            y0 = draw(st.integers(-40, 20))
            box = {"kind": "box", "name": f"box{k}", "x0": str(x0), "x1": str(x0 + draw(st.integers(5, 30))),
                   "y0": str(y0), "y1": str(y0 + draw(st.integers(5, 30))), "z0": "0", "z1": z1}
            if draw(st.integers(0, 5)) == 0:
                box["y1" if draw(st.booleans()) else "x0"] = None  # an unbounded side
            box["zone"] = z1 is not None and draw(st.integers(0, 3)) == 0  # also a forbid zone for the tip
            out.append(box)
        else:
            out.append({"kind": "cylinder", "name": f"post{k}", "cx": str(draw(st.integers(-40, 40))),
                        "cy": str(draw(st.integers(-40, 40))), "r": draw(st.sampled_from(["3", "8", "12.5"])),
                        "z0": "0", "z1": z1})
    return out


@st.composite
def solid_tools(draw):
    """Tools 1 and 2: stacks of 1..3 cylinders from the tip up, and their lengths H1, H2 (the stack's height
    or more)."""
    tools = {}
    for n in (1, 2):
        parts = []
        for k in range(draw(st.integers(1, 3))):
            parts.append((["cutter", "shank", "holder"][k], draw(st.sampled_from(["4", "6", "10", "20", "40"])),
                          draw(st.sampled_from(["10", "15", "25", "40"]))))
        height = sum(int(ln) for _, _, ln in parts)
        tools[n] = (parts, str(height + draw(st.sampled_from([0, 0, 10]))))
    return tools


def solids_machine_text(pulse: str, tools: dict, fixtures: list, *, grow: str = "0", spindle: bool = True) -> str:
    """The machine file: a wide travel box, tools 1 and 2, a spindle nose, the fixtures grown by ``grow`` mm
    on every side (negative: shrunk; a shrunk-away fixture is left out).  With ``grow`` not 0 every fixture is a
    ``[[fixtures]]`` solid (no tip zones): what the contract's grown and shrunk provers are run on."""
    from fractions import Fraction as F

    from nczones.exact import format_decimal as fd

    g = F(grow)
    lines = ['[machine]', 'axes = ["X", "Y", "Z"]', f'pulse = "{pulse}"', 'rapid_mode = "linear"',
             'path_mode = "G61"', '[machine.rapid]', 'X = "6000"', 'Y = "6000"', 'Z = "6000"',
             '[machine.reference]', 'X = "0"', 'Y = "0"', 'Z = "300"', '[offsets]',
             'G54 = { X = "0", Y = "0", Z = "0" }', '[tool_lengths]',
             *(f'H{n} = "{h}"' for n, (_, h) in tools.items()),
             '[[zones]]', 'name = "travel"', 'kind = "box"', 'min = { X = "-500", Y = "-500", Z = "-300" }',
             'max = { X = "500", Y = "500", Z = "800" }']
    for n, (parts, _) in tools.items():
        lines += ['[[tools]]', f'number = {n}', 'parts = [' + ", ".join(
            f'{{ name = "{name}", diameter = "{d}", length = "{ln}" }}' for name, d, ln in parts) + ']']
    if spindle:
        lines += ['[spindle]', 'parts = [{ name = "spindle nose", diameter = "60", length = "50" }]']
    for f in fixtures:
        z0 = None if f["z0"] is None else F(f["z0"]) - g
        z1 = None if f["z1"] is None else F(f["z1"]) + g
        if z0 is not None and z1 is not None and z0 >= z1:
            continue
        zs = [f'min_z = "{fd(z0)}"'] if z0 is not None else []
        zs += [f'max_z = "{fd(z1)}"'] if z1 is not None else []
        if f["kind"] == "cylinder":
            r = F(f["r"]) + g
            if r <= 0:
                continue
            lines += ['[[fixtures]]', f'name = "{f["name"]}"', 'kind = "cylinder"',
                      f'centre = {{ X = "{f["cx"]}", Y = "{f["cy"]}" }}', f'radius = "{fd(r)}"', *zs]
            continue
        lo, hi = {}, {}
        for a in "xyz":
            v0, v1 = f[a + "0"], f[a + "1"]
            v0 = None if v0 is None else F(v0) - g
            v1 = None if v1 is None else F(v1) + g
            if v0 is not None and v1 is not None and v0 >= v1:
                break
            if v0 is not None:
                lo[a.upper()] = v0
            if v1 is not None:
                hi[a.upper()] = v1
        else:
            if f.get("zone") and g == 0:
                lines += ['[[zones]]', f'name = "{f["name"]}"', 'kind = "box"', 'forbid = true', 'point = "tip"']
            else:
                lines += ['[[fixtures]]', f'name = "{f["name"]}"', 'kind = "box"']
            lines += [f'min = {_toml_table(lo)}', f'max = {_toml_table(hi)}']
    return "\n".join(lines) + "\n"


def _toml_table(d: dict) -> str:
    from nczones.exact import format_decimal as fd

    return "{ " + ", ".join(f'{a} = "{fd(v)}"' for a, v in d.items()) + " }"


def _near(draw, fixtures, tools, h):
    """A controlled point (program X Y Z = tip, G54 zero) where a part of tool ``h`` passes a fixture's side or
    top at one of :data:`SOLID_GAPS`, or a point in the open."""
    from fractions import Fraction as F

    if draw(st.integers(0, 4)) == 0:
        return (F(draw(st.integers(-60, 60))), F(draw(st.integers(-60, 60))), F(draw(st.integers(0, 120))))
    f = draw(st.sampled_from(fixtures))
    parts = tools[h][0]
    k = draw(st.integers(0, len(parts) - 1))
    z0 = sum(F(ln) for _, _, ln in parts[:k])
    r = F(parts[k][1]) / 2
    gap = F(draw(st.sampled_from(SOLID_GAPS)))
    top = F(f["z1"]) if f["z1"] is not None else F(40)
    if draw(st.booleans()):  # beside it, at its heights: the part's side `gap` from the fixture's side
        z = top - z0 - draw(st.sampled_from([F(1), F(5), F(10)]))
        if f["kind"] == "cylinder":
            cx, cy = F(f["cx"]), F(f["cy"])
            reach = F(f["r"]) + r + gap
            dx, dy = draw(st.sampled_from([(1, 0), (0, 1), (-1, 0), (0, -1), (F(3, 5), F(4, 5))]))
            return cx + dx * reach, cy + dy * reach, z
        x0 = F(f["x0"]) if f["x0"] is not None else F(-60)
        y0 = F(f["y0"]) if f["y0"] is not None else F(-60)
        y1 = F(f["y1"]) if f["y1"] is not None else y0 + 20
        return x0 - r - gap, (y0 + y1) / 2 + draw(st.sampled_from([F(0), F(1), F(-2)])), z
    # above it: the part's bottom `gap` above the fixture's top, its axis over the fixture
    if f["kind"] == "cylinder":
        x, y = F(f["cx"]) + draw(st.sampled_from([F(0), F(f["r"]) + r - 1])), F(f["cy"])
    else:
        x = (F(f["x0"]) if f["x0"] is not None else F(f["x1"]) - 5) + 1
        y = (F(f["y0"]) if f["y0"] is not None else F(f["y1"]) - 5) + 1
    return x, y, top - z0 + gap


@st.composite
def solids_contract_cases(draw, *, max_moves=4, pulses=("0.01", "0.005")):
    """(pulse, tools, fixtures, program text): lines, rapids, arcs and helices (I J, quarter or half turns,
    ending exactly on the circle) and tool changes, passing close to the fixtures."""
    from fractions import Fraction as F

    from nczones.exact import format_decimal as fd

    pulse = draw(st.sampled_from(pulses))
    fixtures, tools = draw(solid_fixtures()), draw(solid_tools())
    h = draw(st.sampled_from([1, 2]))
    lines = ["G21 G90 G17 G54", f"T{h} M6", f"G43 H{h}", "G0 X-70 Y-70 Z150"]
    px, py, pz = F(-70), F(-70), F(150)
    for _ in range(draw(st.integers(1, max_moves))):
        what = draw(st.sampled_from(["line", "line", "rapid", "arc", "helix", "tool"]))
        if what == "tool":
            h = 3 - h
            lines += [f"T{h} M6", f"G43 H{h}"]
            continue
        x, y, z = _near(draw, fixtures, tools, h)
        if what in ("line", "rapid") or (x, y) == (px, py):
            lines.append(f"{'G1' if what == 'line' else 'G0'} X{fd(x)} Y{fd(y)} Z{fd(z)} F2000")
        else:  # an arc from the current point about a centre halfway to (x, y): a half turn ending at (x, y)
            cw = draw(st.booleans())
            cx, cy = (px + x) / 2, (py + y) / 2
            if draw(st.booleans()):  # a quarter turn instead: the end is the start turned by 90 degrees
                ux, uy = px - cx, py - cy
                x, y = (cx + uy, cy - ux) if cw else (cx - uy, cy + ux)
            z = z if what == "helix" else pz
            lines.append(f"G{2 if cw else 3} X{fd(x)} Y{fd(y)} Z{fd(z)} I{fd(cx - px)} J{fd(cy - py)} F2000")
        px, py, pz = x, y, z
    return pulse, tools, fixtures, "\n".join(lines) + "\nM30\n"
