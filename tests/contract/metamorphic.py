"""Metamorphic soundness of `safe` (issue 18): machines, programs and parameter ranges drawn where features meet.

Every property compares verdicts of the same program under related settings, each computed by
:func:`nczones.prover.verify_text`; the relations hold for any correct prover:

* **ranges vs concrete values** (:func:`check_ranges`): `safe` over parameter ranges implies `safe`
  at every sampled value (the corners, an interior value, and each value where the path branches and
  next to it); every `unsafe` witness, replayed at its own parameter values (and block-delete
  position), is `unsafe` at the same line; the machines for concrete values are built without prover
  code (:mod:`oracles.concrete`);
* **margins and shifts** (:func:`check_margins`): `safe` with margin ``d`` implies `safe` with every
  smaller margin, and with margin ``d - |v|`` for the path shifted by any ``v`` with ``|v| < d``
  (L-infinity; the zones are moved by ``-v``); `unsafe` at margin 0 implies `unsafe` at ``d``;
* **state reads** (:func:`check_state_reads`): a program and its copy with every state-parameter read
  replaced by the value it read verify alike (verdict, violating lines and zones).

Drawn machines have three axes, dogleg or linear rapids, work offsets, tool lengths, boxes that are
flat (no interior) or touch each other or the travel limits, tool-tip zones, sometimes a stepped
table.  Drawn programs (:func:`meta_programs`) mix what the issue-18 reproducers used: dogleg rapids
whose ends depend on different parameters (G53 and G28 legs, incremental moves from the start
position), ``G10 L1``/``L10`` tool lengths, canned cycles with G98/G99 whose R level lies near the
initial level, state-parameter reads (``#5221``, ``#5420``, ``#<_abs_z>``, ``#5161``, ``#5403``),
block-delete lines, and spiral arcs (end radius off by up to the arc tolerance).

Any exception other than a G-code input error is a failure: the internal-error rule (an internal
error is found here, never first by a user).
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import assume, currently_in_test_context, event
from hypothesis import strategies as st

from nczones.errors import InputError
from nczones.exact import format_decimal
from nczones.gcode import interpret_text
from nczones.machine import Machine, parse_machine
from nczones.prover import parse_param, verify_text

from .contract import STATS
from oracles.concrete import machine_at, shift_zones

F = Fraction
F0 = Fraction(0)


class MetamorphicViolation(AssertionError):
    """Two related verifications disagree: one of them is wrong."""


def _require(cond: bool, message: str) -> None:
    if not cond:
        raise MetamorphicViolation(message)


def _note(label: str) -> None:
    """Count an outcome (conftest prints the counts; NCZONES_CONTRACT_STATS writes them every 25 programs)."""
    STATS[f"metamorphic {label}"] += 1
    if currently_in_test_context():
        event(label)


def _counted(kind: str) -> None:
    import json
    import os

    STATS[f"metamorphic examples: {kind}"] += 1
    total = sum(n for k, n in STATS.items() if k.startswith("metamorphic examples"))
    out = os.environ.get("NCZONES_CONTRACT_STATS")
    if out and total % 25 == 0:
        with open(out, "w") as fh:
            json.dump(dict(STATS), fh, indent=2, sort_keys=True)


def _dec(q: Fraction) -> str:
    return format_decimal(q)


# ----------------------------------------------------------------------------- machines

GRID = F(1, 2)


def _vals(draw, lo, hi, step=GRID):
    n = int((hi - lo) / step)
    return lo + step * draw(st.integers(0, n))


@st.composite
def meta_machines(draw, *, posts_max: int = 2, flat: int = 5) -> tuple[Machine, str]:
    """(machine, its TOML text): X/Y/Z travel box or stepped table, posts, a tip vise, offsets, tool lengths."""
    rapid_mode = draw(st.sampled_from(("dogleg", "dogleg", "linear")))
    rates = [draw(st.sampled_from(("6000", "12000"))) for _ in range(3)]
    zones = []
    if draw(st.integers(0, 3)) == 0:
        # a stepped allow table over X (Y limited) with a raised middle step, plus the Z travel
        a, b = _vals(draw, F(20), F(45)), _vals(draw, F(55), F(80))
        mid_min = _vals(draw, F(10), F(40))
        zones.append("\n".join([
            "[[zones]]", 'name = "table"', 'kind = "stepped"', 'reference_axis = "X"', 'limited_axis = "Y"',
            'from = "0"', "regions = [",
            f'  {{ upto = "{_dec(a)}", min = "0", max = "100" }},',
            f'  {{ upto = "{_dec(b)}", min = "{_dec(mid_min)}", max = "100" }},',
            '  { upto = "100", min = "0", max = "100" },', "]"]))
        zones.append(_box("z travel", {"Z": F0}, {"Z": F(200)}, False))
    else:
        zones.append(_box("travel", {"X": F0, "Y": F0, "Z": F0}, {"X": F(100), "Y": F(100), "Z": F(200)}, False))
    posts = []
    for k in range(draw(st.sampled_from((0, 0, 1, 2)[:posts_max + 2]) if posts_max <= 2 else st.integers(1, posts_max))):
        lo = {a: _vals(draw, F(10), F(80)) for a in "XY"}
        if draw(st.integers(0, 4)) == 0:  # touching the travel limit
            lo["X"] = F0
        if posts and draw(st.integers(0, 2)) == 0:  # touching the other post
            lo["X"] = posts[-1][1]["X"]
        hi = {a: lo[a] + _vals(draw, F(1, 2), F(10)) for a in "XY"}
        if draw(st.integers(0, flat - 1)) == 0:  # flat: no interior on one axis
            a = draw(st.sampled_from("XY"))
            hi[a] = lo[a]
        if draw(st.booleans()):
            lo["Z"], hi["Z"] = F0, _vals(draw, F(40), F(160), F(1))
        posts.append((lo, hi))
        zones.append(_box(f"post{k + 1}", lo, hi, True))
    if draw(st.booleans()):
        lo = {a: _vals(draw, F(10), F(70)) for a in "XY"}
        hi = {a: lo[a] + _vals(draw, F(5), F(25)) for a in "XY"}
        lo["Z"], hi["Z"] = F0, _vals(draw, F(10), F(60), F(1))
        zones.append(_box("vise", lo, hi, True, tip=True))
    ref = {"X": _vals(draw, F(1), F(99)), "Y": _vals(draw, F(1), F(99)), "Z": _vals(draw, F(150), F(199))}
    start = dict(ref)
    if draw(st.booleans()):
        start = {"X": _vals(draw, F(1, 2), F(99)), "Y": _vals(draw, F(1, 2), F(99)), "Z": _vals(draw, F(100), F(199))}
    if draw(st.integers(0, 3)) == 0:  # the start on a travel limit: a range of start.* crosses it at once
        a = draw(st.sampled_from("XYZ"))
        start[a] = draw(st.sampled_from((F0, F(200) if a == "Z" else F(100))))
    g54 = {"X": _vals(draw, F0, F(20)), "Y": _vals(draw, F0, F(20)), "Z": _vals(draw, F(20), F(60), F(1))}
    g55 = {"X": _vals(draw, F(20), F(40)), "Y": g54["Y"], "Z": g54["Z"] + _vals(draw, F(-5), F(5))}
    tools = {n: _vals(draw, F(20), F(80)) for n in (1, 2)}
    text = "\n".join([
        "[machine]", 'name = "metamorphic"', 'axes = ["X", "Y", "Z"]', 'pulse = "0.01"',
        f'rapid_mode = "{rapid_mode}"',
        "[machine.rapid]", *(f'{a} = "{r}"' for a, r in zip("XYZ", rates)),
        "[machine.reference]", *(f'{a} = "{_dec(ref[a])}"' for a in "XYZ"),
        "[machine.start]", *(f'{a} = "{_dec(start[a])}"' for a in "XYZ"),
        "[offsets]",
        "G54 = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in g54.items()) + " }",
        "G55 = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in g55.items()) + " }",
        "[tool_lengths]", *(f'H{n} = "{_dec(v)}"' for n, v in tools.items()),
        *zones,
    ]) + "\n"
    from nczones.errors import MachineFileError

    try:
        machine = parse_machine(text, "metamorphic.toml")
    except MachineFileError as exc:
        if all(d.code == "ZN130" for d in exc.diagnostics):  # the start inside a post: draw again
            assume(False)
        raise
    return machine, text


def _box(name, lo, hi, forbid, tip=False) -> str:
    lines = ["[[zones]]", f'name = "{name}"', 'kind = "box"', f"forbid = {'true' if forbid else 'false'}"]
    if tip:
        lines.append('point = "tip"')
    lines.append("min = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in lo.items()) + " }")
    lines.append("max = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in hi.items()) + " }")
    return "\n".join(lines)


def _constants(machine: Machine, axis: str) -> list[Fraction]:
    out = set()
    for z in machine.zones:
        for a, (lo, hi) in z.bounds().items():
            if a == axis:
                out.update(v for v in (lo, hi) if v is not None)
        if z.kind == "stepped" and axis == z.reference_axis:
            out.update(z.uptos)
    return sorted(out)


# ----------------------------------------------------------------------------- programs


class _State:
    """The nominal state the generator aims with (its own small model; exactness is not needed except for
    arcs, which start from a point the generator has just programmed)."""

    def __init__(self, machine: Machine):
        self.m = machine
        self.pos = dict(zip("XYZ", machine.start))
        self.frame = "G54"
        self.inside = None
        self.tool = F0
        self.register = None
        self.table = {}
        #: the --param names the program's motion depends on (ranges are drawn mostly from these)
        self.used = {"start.X", "start.Y", "start.Z"}
        #: (--param name, +1/-1): a motion touches a travel limit, and that parameter moving in that
        #: direction pushes it over (ranges are oriented by these)
        self.probes = [(f"start.{a}", 1 if v == TRAVEL[a][1] else -1) for a, v in self.pos.items() if v in TRAVEL[a]]

    def moved(self, axes: str, frame: str | None, target: dict | None = None) -> None:
        if frame is not None:
            self.used.update(f"{frame}.{a}" for a in axes)
            tool = self.register is not None and self.register not in self.table
            if "Z" in axes and tool:
                self.used.add(f"H{self.register}")
            for a in axes if target is not None else ():
                if target[a] in TRAVEL[a]:
                    sign = 1 if target[a] == TRAVEL[a][1] else -1
                    self.probes.append((f"{frame}.{a}", sign))
                    if a == "Z" and tool:
                        self.probes.append((f"H{self.register}", sign))

    def off(self, a):
        o = dict(zip("XYZ", self.m.offset(self.frame)))[a]
        return o + (self.tool if a == "Z" else 0)


TRAVEL = {"X": (F0, F(100)), "Y": (F0, F(100)), "Z": (F0, F(200))}


@st.composite
def _machine_value(draw, machine: Machine, axis: str, state: _State, tip: bool = False) -> Fraction:
    """A machine coordinate: on a travel limit or just inside it (a range of offsets then crosses it),
    near another zone's boundary, or anywhere inside the travel."""
    how = draw(st.integers(0, 3))
    lo, hi = TRAVEL[axis]
    if state.inside is not None:  # clearance: on the margin's edge of the travel, or well inside it
        d = state.inside
        if how <= 1:
            edge = draw(st.sampled_from((lo, hi)))
            inward = draw(st.sampled_from((d, d, d + F(1, 100), 2 * d)))
            return edge + inward if edge == lo else edge - inward
        return _vals(draw, lo + 2 * d + F(1, 2), hi - 2 * d - F(1, 2))
    if how <= 1:
        edge = draw(st.sampled_from((lo, hi)))
        inward = draw(st.sampled_from((F0, F0, F0, F(1, 100), F(1, 2), F(1))))
        return edge + inward if edge == lo else edge - inward
    consts = _constants(machine, axis)
    if how == 2 and consts:
        base = draw(st.sampled_from(consts)) + (state.tool if tip else 0)
        return base + draw(st.sampled_from((F0, F(1, 100), F(-1, 100), F(1, 2), F(-1, 2))))
    return _vals(draw, lo + F(1, 2), hi - F(1, 2))


@st.composite
def meta_programs(draw, machine: Machine, *, reads: bool = True, deletes: bool = True, used: set | None = None,
                  inside: Fraction | None = None) -> str:
    """A program for a :func:`meta_machines` machine (see the module docstring); ``used`` collects the
    ``--param`` names its motion depends on."""
    s = _State(machine)
    s.inside = inside
    lines = ["G21 G90 G17 G40 G49 G54 G80 G94 F600"]
    if draw(st.integers(0, 3)) == 0:  # incremental moves from the start position: they carry start.*
        for _ in range(draw(st.integers(1, 2))):
            target = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
            d = {a: target[a] - s.pos[a] for a in "XY"}
            kind = draw(st.sampled_from(("G0", "G1")))
            lines.append(f"G91 {kind} X{_dec(d['X'])} Y{_dec(d['Y'])}")
            s.pos = {a: s.pos[a] + d.get(a, 0) for a in "XYZ"}
            s.probes += [(f"start.{a}", 1 if target[a] == TRAVEL[a][1] else -1) for a in "XY" if target[a] in TRAVEL[a]]
        lines.append("G90")
    kinds = ["move", "move", "move", "arc", "home", "tool", "tool", "cycle"] + (["read", "read"] if reads else [])
    for _ in range(draw(st.integers(1, 5))):
        kind = draw(st.sampled_from(kinds))
        block = draw(_block(machine, s, kind))
        if deletes and len(block) == 1 and draw(st.integers(0, 6)) == 0:
            block = ["/" + block[0]]
        lines += block
    lines.append("M30")
    if used is not None:
        used.update(s.used)
        used.update(s.probes)
    return "\n".join(lines) + "\n"


@st.composite
def _block(draw, machine: Machine, s: _State, kind: str) -> list[str]:
    if kind == "move":
        how = draw(st.sampled_from(("G54", "G55", "G53", "G53")))
        axes = draw(st.sampled_from(("XY", "X", "Y", "Z", "XYZ")))
        target = dict(s.pos)
        for a in axes:
            target[a] = draw(_machine_value(machine, a, s, tip=(a == "Z")))
        g = draw(st.sampled_from(("G0", "G0", "G1")))
        if how == "G53":
            words = " ".join(f"{a}{_dec(target[a])}" for a in axes)
            s.pos = target
            return [f"G90 G53 {g} {words}"]
        pre = "" if how == s.frame else how + " "
        s.frame = how
        s.moved(axes, how, target)
        words = " ".join(f"{a}{_dec(target[a] - s.off(a))}" for a in axes)
        s.pos = target
        return [f"{pre}G90 {g} {words}"]
    if kind == "arc":
        a0 = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
        r = _vals(draw, F(1), F(15))
        quarter = draw(st.integers(1, 2))
        cw = draw(st.booleans())
        d = draw(st.sampled_from(((1, 0), (0, 1), (-1, 0), (0, -1))))
        grow = draw(st.sampled_from((F0, F0, F(1, 1000), F(2, 1000), F(-1, 1000))))  # spiral within tolerance
        c = (a0["X"] + d[0] * r, a0["Y"] + d[1] * r)
        v = (-d[0], -d[1])
        for _ in range(quarter):
            v = (v[1], -v[0]) if cw else (-v[1], v[0])
        end = (c[0] + v[0] * (r + grow), c[1] + v[1] * (r + grow))
        ox, oy = s.off("X"), s.off("Y")
        s.pos = {"X": end[0], "Y": end[1], "Z": s.pos["Z"]}
        s.moved("XY", s.frame)
        return [f"G90 G1 X{_dec(a0['X'] - ox)} Y{_dec(a0['Y'] - oy)}",
                f"{'G2' if cw else 'G3'} X{_dec(end[0] - ox)} Y{_dec(end[1] - oy)} "
                f"I{_dec(c[0] - a0['X'])} J{_dec(c[1] - a0['Y'])}"]
    if kind == "home":
        ref = dict(zip("XYZ", machine.reference))
        if draw(st.booleans()):
            s.pos = ref
            return ["G28"]
        mid = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
        s.pos = {"X": ref["X"], "Y": ref["Y"], "Z": s.pos["Z"]}
        s.moved("XY", s.frame)
        return [f"G90 G28 X{_dec(mid['X'] - s.off('X'))} Y{_dec(mid['Y'] - s.off('Y'))}"]
    if kind == "tool":
        choice = draw(st.sampled_from(("H", "H", "H", "G49", "L1", "L10")))
        z = draw(_machine_value(machine, "Z", s, tip=True))
        if choice == "G49":
            s.tool = F0
            s.register = None
            s.moved("Z", s.frame)
            return ["G49", f"G90 G0 Z{_dec(z - s.off('Z'))}"]
        if choice == "H":
            n = draw(st.sampled_from((1, 2)))
            s.tool = s.table.get(n, machine.tool_length(n))
            s.register = n
            s.moved("Z", s.frame, {"Z": z})
            return [f"G43 H{n}", f"G90 G0 Z{_dec(z - s.off('Z'))}"]
        n = draw(st.sampled_from((1, 2)))
        value = _vals(draw, F(10), F(90))
        s.register = n
        if choice == "L1":
            s.table[n] = value
            s.tool = value
            s.moved("Z", s.frame)
            return [f"G10 L1 P{n} Z{_dec(value)}", f"G43 H{n}", f"G90 G0 Z{_dec(z - s.off('Z'))}"]
        # L10: the length that makes the current Z read `value` in the current system (G54/G55 + G92 = 0)
        g5z = dict(zip("XYZ", machine.offset(s.frame)))["Z"]
        s.table[n] = s.pos["Z"] - g5z - value
        s.tool = s.table[n]
        s.moved("Z", s.frame)
        return [f"G10 L10 P{n} Z{_dec(value)}", f"G43 H{n}", f"G90 G0 Z{_dec(z - s.off('Z'))}"]
    if kind == "cycle":
        # the initial level: a machine Z (G53, depends on no offset) or a programmed Z (depends on them)
        init = _vals(draw, F(60), F(190))
        out = []
        if draw(st.booleans()):
            out.append(f"G90 G53 G0 Z{_dec(init)}")
        else:
            out.append(f"G90 G0 Z{_dec(init - s.off('Z'))}")
        s.pos["Z"] = init
        r_machine = init + draw(st.sampled_from((F0, F(1, 100), F(-1, 100), F(1, 2), F(-1, 2), F(2), F(-2))))
        depth = _vals(draw, F(1), min(F(40), r_machine - 1))
        xy = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
        retract = draw(st.sampled_from(("G98", "G99")))
        cycle = draw(st.sampled_from(("G81", "G81", "G83")))
        q = f" Q{_dec(_vals(draw, F(1), F(10)))}" if cycle == "G83" else ""
        out.append(f"{retract} {cycle} X{_dec(xy['X'] - s.off('X'))} Y{_dec(xy['Y'] - s.off('Y'))} "
                   f"Z{_dec(r_machine - depth - s.off('Z'))} R{_dec(r_machine - s.off('Z'))}{q}")
        out.append("G80")
        s.moved("XYZ", s.frame)
        s.pos.update(xy)
        s.pos["Z"] = max(init, r_machine) if retract == "G98" else r_machine
        return out
    if kind == "read":
        template = draw(st.sampled_from(("g5x", "pos", "abs", "home", "tool")))
        a = draw(st.sampled_from("XY"))
        target = draw(_machine_value(machine, a, s))
        if template == "g5x":  # machine target = G54 offset + c
            off = dict(zip("XYZ", machine.offset("G54")))[a]
            s.pos[a] = target
            return [f"G90 G53 G0 {a}[#{5221 + 'XYZ'.index(a)} + {_dec(target - off)}]"]
        if template == "pos":  # relative to where the program is: [#5420 + c] in the current frame
            c = target - s.pos[a]
            s.pos[a] = target
            return [f"G90 G0 {a}[#{5420 + 'XYZ'.index(a)} + {_dec(c)}]"]
        if template == "abs":
            c = target - s.pos[a]
            s.pos[a] = target
            return [f"G90 G53 G0 {a}[#<_abs_{a.lower()}> + {_dec(c)}]"]
        if template == "home":
            ref = dict(zip("XYZ", machine.reference))[a]
            s.pos[a] = target
            return [f"G90 G53 G0 {a}[#{5161 + 'XYZ'.index(a)} + {_dec(target - ref)}]"]
        n = draw(st.sampled_from((1, 2)))  # the tool table: T n M6, then a Z move by its length
        z = draw(_machine_value(machine, "Z", s))
        s.pos["Z"] = z
        length = s.table.get(n, machine.tool_length(n))
        return [f"T{n} M6", f"G90 G53 G0 Z[#5403 + {_dec(z - length)}]"]
    raise AssertionError(kind)


PARAM_NAMES = ("G54.X", "G54.Y", "G54.Z", "G55.X", "H1", "H2", "start.X", "start.Y", "start.Z")


@st.composite
def meta_ranges(draw, machine: Machine, used: set | None = None) -> tuple[str, ...]:
    """One or two ``--param`` ranges, mostly of parameters the program's motion depends on (``used``);
    some hold the machine file's value, some do not."""
    used = set(used or ())
    probes = sorted(u for u in used if isinstance(u, tuple))
    pool = sorted(u for u in used if isinstance(u, str) and u in PARAM_NAMES)
    direction = {}
    if probes and draw(st.integers(0, 9)) < 7:  # aim at a motion that touches a travel limit
        name = draw(st.sampled_from(sorted({n for n, _ in probes})))  # every parameter alike
        sign = draw(st.sampled_from([g for n, g in probes if n == name]))
        names = [name]
        direction[name] = sign
        if pool and draw(st.booleans()):
            other = draw(st.sampled_from(pool))
            if other != name:
                names.append(other)
    else:
        names = draw(st.lists(st.sampled_from(pool if pool and draw(st.integers(0, 4)) else PARAM_NAMES),
                              min_size=1, max_size=2, unique=True))
    out = []
    for name in names:
        width = draw(st.sampled_from((F(2, 100), F(1, 2), F(1), F(3))))
        if name in direction:  # over the limit in the probe's direction, the file's value in or out
            lo = draw(st.sampled_from((F0, -width / 2, F(1, 100)))) if direction[name] > 0 else \
                -width - draw(st.sampled_from((F0, -width / 2, F(1, 100))))
        elif draw(st.integers(0, 3)):
            lo = -width * draw(st.sampled_from((F0, F(1, 2), F(1))))
        else:  # the file's value outside the range
            lo = draw(st.sampled_from((F(1, 100), F(1, 2), -width - F(1, 2))))
        hi = lo + width
        if name.startswith("H"):
            nominal = machine.tool_length(int(name[1:]))
            lo, hi = nominal + lo, nominal + hi
        out.append(f"{name}={_dec(lo)}..{_dec(hi)}")
    return tuple(out)


@st.composite
def range_cases(draw):
    machine, _ = draw(meta_machines())
    used: set = set()
    text = draw(meta_programs(machine, used=used))
    return machine, text, draw(meta_ranges(machine, used))


@st.composite
def margin_cases(draw):
    machine, _ = draw(meta_machines(posts_max=3, flat=2))
    margin = draw(st.sampled_from((F(1, 100), F(1, 10), F(1, 2), F(2))))
    text = draw(meta_programs(machine, reads=False, inside=margin if draw(st.integers(0, 3)) else None))
    frac = [draw(st.sampled_from((F0, F(1, 3), F(-1, 2), F(9, 10), F(-99, 100)))) for _ in range(3)]
    shift = {a: margin * f for a, f in zip("XYZ", frac)}
    return machine, text, margin, shift


@st.composite
def read_cases(draw):
    machine, _ = draw(meta_machines())
    text = draw(meta_programs(machine, reads=True, deletes=False))
    assume("#" in text)
    return machine, text


# ----------------------------------------------------------------------------- the properties


def _verify(text: str, machine: Machine, **options):
    """verify_text, with G-code input errors (a drawn program the interpreter refuses) rejected."""
    try:
        return verify_text(text, machine, max_violations=50, **options)
    except InputError as exc:
        _note(f"rejected: {exc.diagnostics[0].code if hasattr(exc, 'diagnostics') else type(exc).__name__}")
        assume(False)
        raise


def _ranges(machine: Machine, params: tuple[str, ...]):
    return [parse_param(p, machine) for p in params]


def _samples(machine: Machine, params: tuple[str, ...], splits) -> list[dict[str, Fraction]]:
    """Concrete parameter values to compare a range verdict with: corners, an interior point, switches."""
    rs = _ranges(machine, params)
    lows = {r.name: r.written[0] for r in rs}
    highs = {r.name: r.written[1] for r in rs}
    mids = {r.name: (2 * r.written[0] + r.written[1]) / 3 for r in rs}
    out = [lows, highs, mids]
    if len(rs) == 2:
        a, b = rs
        out.append({a.name: a.written[0], b.name: b.written[1]})
        out.append({a.name: a.written[1], b.name: b.written[0]})
    for name, value in splits:
        for d in (F0, F(1, 1000), F(-1, 1000)):
            r = next(r for r in rs if r.name == name)
            v = value + d
            if r.written[0] <= v <= r.written[1]:
                out.append({**mids, name: v})
    return out


def check_ranges(machine: Machine, text: str, params: tuple[str, ...]) -> None:
    """A range verdict against verdicts at concrete values of the ranges.

    Per line, which implies the verdict-level relation (`safe` over the ranges -> `safe` at every
    value): a line that violates a zone at a sampled value must violate over the ranges, unless the
    range verification is `unknown` at or before it.  Every `unsafe` witness of the ranges, replayed at
    its own values (and block-delete position), is `unsafe` at its line.
    """
    result = _verify(text, machine, params=params)
    _counted("ranges")
    _note(f"ranges: {result.verdict.label}")
    splits = result.extra.get("splits", ())
    if splits:
        _note("ranges: the path branches inside a range")
    lines = {v.line for v in result.violations}
    # a blended corner's reason (VF208, specs/path-modes.md) stops nothing: the motions after it are proved
    excused = min([r.span.line if r.span is not None else 0 for r in result.reasons if r.code != "VF208"],
                  default=None)
    for values in _samples(machine, params, splits):
        concrete = _verify(text, machine_at(machine, values))
        for v in concrete.violations:
            if v.line in lines or (excused is not None and excused <= (v.line or 0)):
                continue
            raise MetamorphicViolation(
                f"line {v.line} leaves zone {v.zone!r} at {values}"
                f"{' (block delete ' + dict(v.switches)['block_delete'] + ')' if v.switches else ''}, but the "
                f"verification over {params} is {result.verdict.label} there "
                f"(violations at lines {sorted(x for x in lines if x is not None)})")
    for v in result.violations[:3]:
        values = dict(v.params)
        position = dict(v.switches).get("block_delete")
        replay = _verify(text, machine_at(machine, values), block_delete=position or "both")
        found = {(w.line, w.zone) for w in replay.violations}
        _require(replay.verdict.label == "unsafe" and any(line == v.line for line, _ in found),
                 f"the witness of line {v.line} ({v.zone}) over {params} at {values}"
                 f"{' block delete ' + position if position else ''} does not replay: {replay.verdict.label}, "
                 f"violations at {sorted(found)}")


def check_margins(machine: Machine, text: str, margin: Fraction, shift: dict[str, Fraction]) -> None:
    """Margin monotonicity, and the margin as clearance against a shifted path."""
    at_d = _verify(text, machine, margin=margin)
    at_0 = _verify(text, machine)
    _counted("margins")
    _note(f"margin: {at_0.verdict.label} at 0, {at_d.verdict.label} at d")
    if at_0.verdict.label == "unsafe":
        _require(at_d.verdict.label == "unsafe", f"unsafe at margin 0 but {at_d.verdict.label} at margin {margin}")
    if at_d.verdict.label != "safe":
        return
    _require(at_0.verdict.label == "safe", f"safe at margin {margin} but {at_0.verdict.label} at 0")
    half = _verify(text, machine, margin=margin / 2)
    _require(half.verdict.label == "safe", f"safe at margin {margin} but {half.verdict.label} at {margin / 2}")
    length = max(abs(x) for x in shift.values())
    moved = shift_zones(machine, {a: -x for a, x in shift.items()})
    shifted = _verify(text, moved, margin=margin - length)
    _require(shifted.verdict.label == "safe",
             f"safe at margin {margin} but the path shifted by {shift} is {shifted.verdict.label} at margin "
             f"{margin - length}: {[(w.line, w.zone) for w in shifted.violations[:3]]}")


def state_reads_substituted(machine: Machine, text: str) -> str | None:
    """The program with every state-parameter read replaced by the value it read (None: a read repeats or
    its value is no decimal)."""
    import re

    from nczones.gcode.interpreter import Interpreter

    values = []
    original = Interpreter._state_reader

    def recording(self, entry):
        read = original(self, entry)

        def wrapped():
            v = read()
            values.append(v)
            return v
        return wrapped

    Interpreter._state_reader = recording
    try:
        run = interpret_text(text, machine, fast=False)
        list(run.segments())
    finally:
        Interpreter._state_reader = original
    tokens = list(re.finditer(r"#(?:\d+|<_[a-z_]+>)", text))
    if run.unsupported or len(tokens) != len(values):
        return None
    out, pos = [], 0
    for tok, value in zip(tokens, values):
        value = Fraction(value)
        if 10**12 % value.denominator:
            return None
        out.append(text[pos:tok.start()])
        out.append(f"[{_dec(value)}]")
        pos = tok.end()
    out.append(text[pos:])
    return "".join(out)


def check_state_reads(machine: Machine, text: str) -> None:
    """A program and its copy with every state read replaced by its value verify alike."""
    copy = state_reads_substituted(machine, text)
    assume(copy is not None)
    a = _verify(text, machine)
    b = _verify(copy, machine)
    _counted("state reads")
    _note(f"state reads: {a.verdict.label}")
    key_a = [(v.line, v.zone, v.switches) for v in a.violations]
    key_b = [(v.line, v.zone, v.switches) for v in b.violations]
    _require(a.verdict.label == b.verdict.label and key_a == key_b,
             f"reads {a.verdict.label} {key_a} but values {b.verdict.label} {key_b}\n{copy}")
