"""Metamorphic soundness of `safe` in the Fanuc dialect: Macro B where it meets ranges, margins, state reads
and block delete.

The relations of :mod:`tests.contract.metamorphic` (issue 18) drew only LinuxCNC programs.  Here the drawn
programs are Fanuc/Haas mill programs (``dialect = "fanuc"``, specs/fanuc.md) mixing what that dialect
adds: Macro B (``#`` variables, ``WHILE``/``DO``/``END``, ``IF``/``THEN``, ``G65`` macro calls and
``M98 P L`` subprograms), ``G10 L2 P`` and ``#5221 =`` work offset writes (absolute and, in G91, added),
``G10 L10``/``L11`` and ``#11001 =``/``#2001 =`` tool length geometry and wear, ``G43 H`` with the tool axis
moving at once (TOS = 0), ``G53``, ``G28`` (``G91 G28 Z0.``), ``G52``, ``G92``/``G92.1``, ``G68``
rotation, canned cycles, system-variable reads (``#5221``.., ``#5001``.., ``#5021``.., ``#5083``,
``#11001``, ``#4014`` modal reads in ``IF .. THEN``) and block delete (``/``, also on macro statements
inside a loop, and ``/2``, ``/3``: switches of their own, BDT2 and BDT3).

Relations (each a test failure when broken; any exception other than a G-code input error fails too):

* **ranges vs concrete values** and **margins**: :func:`metamorphic.check_ranges` and
  :func:`metamorphic.check_margins` on these programs (concrete machines from :mod:`oracles.concrete`);
* **state reads** (:func:`check_fanuc_state_reads`): a program and its copy with every system-variable
  read replaced by the value it read verify alike (verdict, violating lines, zones), in each position of
  the block-delete switch (the values read differ between them);
* **dialect translation** (:func:`check_translation`): the same motion written in LinuxCNC and in Fanuc
  syntax, line for line, using only codes whose meaning specs/fanuc.md and specs/gcode-support.md
  document as identical, verify alike (verdict, violating lines and zones);
* **block delete** (:func:`check_block_delete`): the verdict with the switches in ``both`` positions is
  the worst over every combination of the switches the program uses, each verified alone with the
  switches fixed, and its violations are those of the combinations, each found in every combination
  that agrees with the switch positions it is labelled with (issue 33, class 5).
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import assume
from hypothesis import strategies as st

from nczones.exact import format_decimal
from nczones.machine import Machine, parse_machine

from .metamorphic import (
    TRAVEL,
    MetamorphicViolation,
    _counted,
    _machine_value,
    _note,
    _require,
    _State,
    _vals,
    _verify,
    meta_machines,
    meta_ranges,
)

F = Fraction
F0 = Fraction(0)

#: The cycle settings G73/G83/G76 need in the Fanuc dialect (else unknown).
FANUC_SETTINGS = '\n[fanuc]\ng73_retract = "0.5"\ng83_clearance = "1"\nboring_shift = "+X"\n'


def _fd(q: Fraction) -> str:
    """A Fanuc length literal: always with a decimal point (DPI plays no part)."""
    s = format_decimal(q)
    return s if "." in s else s + "."


# ----------------------------------------------------------------------------- machines


@st.composite
def fanuc_machines(draw, *, posts_max: int = 2, flat: int = 5) -> tuple[Machine, str]:
    """(machine, its TOML text): a :func:`metamorphic.meta_machines` machine read in the Fanuc dialect."""
    _, text = draw(meta_machines(posts_max=posts_max, flat=flat))
    text = text.replace("[machine]\n", '[machine]\ndialect = "fanuc"\n', 1) + FANUC_SETTINGS
    if draw(st.integers(0, 3)) == 0:  # parameter 5006#6 TOS = 1: the next tool axis move takes a G43 change
        text += 'tool_length_motion = "shift"\n'
    return parse_machine(text, "fanuc.toml"), text


# ----------------------------------------------------------------------------- programs


class _FanucState(_State):
    """The generator's nominal model of a Fanuc run: the offsets the program wrote, G52, G92, tool lengths."""

    def __init__(self, machine: Machine):
        super().__init__(machine)
        self.offsets = {name: dict(zip("XYZ", machine.offset(name))) for name in ("G54", "G55")}
        self.geometry = {n: machine.tool_length(n) for n in (1, 2)}
        self.wear = {1: F0, 2: F0}
        self.g52 = {a: F0 for a in "XYZ"}
        self.g92 = {a: F0 for a in "XYZ"}
        self.after_home = False  # G91 G28 Z0. with a tool length active: the next Z move needs G43/G49
        self.labels = 100
        self.subs: list[str] = []
        self.loop_var = 1

    def off(self, a):
        o = self.offsets[self.frame][a] + self.g52[a] + self.g92[a]
        return o + (self.tool if a == "Z" else 0)

    def label(self) -> int:
        self.labels += 10
        return self.labels


def _z_prefix(s: _FanucState, axes: str) -> str:
    """After G91 G28 Z0. with a tool length active, a Z move states the offset again (G49)."""
    if s.after_home and "Z" in axes:
        s.after_home = False
        s.tool, s.register = F0, None
        return "G49 "
    return ""


@st.composite
def fanuc_programs(draw, machine: Machine, *, reads: bool = True, deletes: bool = True, used: set | None = None,
                   inside: Fraction | None = None, header: bool | None = None, delete_odds: int = 5,
                   extra: tuple[str, ...] = ()) -> str:
    """A Fanuc mill program for a :func:`fanuc_machines` machine (see the module docstring); ``used``
    collects the ``--param`` names its motion depends on (and the probes that aim ranges)."""
    s = _FanucState(machine)
    s.inside = inside
    lines = []
    if header if header is not None else draw(st.booleans()):
        lines += ["%", "O1000 (METAMORPHIC)"]
    else:
        lines += ["O1000"]
    lines.append("G21 G90 G17 G40 G49 G54 G80 G94 F600.")
    if draw(st.integers(0, 3)) == 0:  # incremental moves from the start position: they carry start.*
        for _ in range(draw(st.integers(1, 2))):
            target = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
            d = {a: target[a] - s.pos[a] for a in "XY"}
            lines.append(f"G91 G{draw(st.sampled_from((0, 1)))} X{_fd(d['X'])} Y{_fd(d['Y'])}")
            s.pos.update(target)
            s.probes += [(f"start.{a}", 1 if target[a] == TRAVEL[a][1] else -1) for a in "XY"
                         if target[a] in TRAVEL[a]]
        lines.append("G90")
    kinds = ["move", "move", "move", "arc", "home", "tool", "tool", "offset", "local", "rotate", "cycle",
             "loop", "call"] + (["read", "read", "read"] if reads else []) + list(extra)
    for _ in range(draw(st.integers(1, 5))):
        kind = draw(st.sampled_from(kinds))
        block = draw(_fanuc_block(machine, s, kind, deletes))
        if deletes and len(block) == 1 and draw(st.integers(0, delete_odds)) == 0:
            block = [draw(st.sampled_from(("/", "/", "/", "/1 ", "/2 ", "/3 "))) + block[0]]
        lines += block
    lines.append("M30")
    for sub in s.subs:
        lines += sub.splitlines()
    if lines[0] == "%":
        lines.append("%")
    if used is not None:
        used.update(s.used)
        used.update(s.probes)
    return "\n".join(lines) + "\n"


def _arc(draw, machine: Machine, s: _State, spiral: bool) -> tuple[dict, tuple, tuple, bool]:
    """An arc of a quarter or a half turn from a drawn point (machine coordinates): (start, centre, end,
    clockwise); with ``spiral`` the end radius is off by up to the arc tolerance."""
    a0 = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
    r = _vals(draw, F(1), F(15))
    cw = draw(st.booleans())
    d = draw(st.sampled_from(((1, 0), (0, 1), (-1, 0), (0, -1))))
    grow = draw(st.sampled_from((F0, F0, F(1, 1000), F(-1, 1000)))) if spiral else F0
    c = (a0["X"] + d[0] * r, a0["Y"] + d[1] * r)
    v = (-d[0], -d[1])
    for _ in range(draw(st.integers(1, 2))):
        v = (v[1], -v[0]) if cw else (-v[1], v[0])
    return a0, c, (c[0] + v[0] * (r + grow), c[1] + v[1] * (r + grow)), cw


def _move(draw, machine, s: _FanucState, axes: str, how: str, g: str) -> str:
    target = dict(s.pos)
    for a in axes:
        target[a] = draw(_machine_value(machine, a, s, tip=(a == "Z")))
    if how == "G53":
        s.pos = target
        return f"G90 G53 G0 {' '.join(f'{a}{_fd(target[a])}' for a in axes)}"
    pre = "" if how == s.frame else how + " "
    s.frame = how
    pre += _z_prefix(s, axes)
    s.moved(axes, how, target)
    words = " ".join(f"{a}{_fd(target[a] - s.off(a))}" for a in axes)
    s.pos = target
    return f"{pre}G90 {g} {words}"


@st.composite
def _fanuc_block(draw, machine: Machine, s: _FanucState, kind: str, deletes: bool) -> list[str]:
    if kind == "move":
        how = draw(st.sampled_from(("G54", "G55", "G53", "G53")))
        axes = draw(st.sampled_from(("XY", "X", "Y", "Z", "XYZ")))
        return [_move(draw, machine, s, axes, how, draw(st.sampled_from(("G0", "G0", "G1"))))]
    if kind == "arc":
        a0, c, end, cw = _arc(draw, machine, s, spiral=True)
        ox, oy = s.off("X"), s.off("Y")
        s.pos = {"X": end[0], "Y": end[1], "Z": s.pos["Z"]}
        s.moved("XY", s.frame)
        return [f"G90 G1 X{_fd(a0['X'] - ox)} Y{_fd(a0['Y'] - oy)}",
                f"G{'2' if cw else '3'} X{_fd(end[0] - ox)} Y{_fd(end[1] - oy)} "
                f"I{_fd(c[0] - a0['X'])} J{_fd(c[1] - a0['Y'])}"]
    if kind == "home":
        ref = dict(zip("XYZ", machine.reference))
        if draw(st.booleans()):  # the Fanuc idiom: Z home through the current point
            if s.tool:
                s.after_home = True
            s.pos["Z"] = ref["Z"]
            return ["G91 G28 Z0.", "G90"]
        mid = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
        s.moved("XY", s.frame, mid)
        words = f"X{_fd(mid['X'] - s.off('X'))} Y{_fd(mid['Y'] - s.off('Y'))}"
        s.pos.update({"X": ref["X"], "Y": ref["Y"]})
        out = [f"G90 G28 {words}"]
        if draw(st.booleans()):  # back through the intermediate point (G29) to a target
            axes = draw(st.sampled_from(("X", "Y", "XY")))
            target = {a: draw(_machine_value(machine, a, s)) for a in axes}
            s.moved(axes, s.frame, target)
            out.append("G29 " + " ".join(f"{a}{_fd(target[a] - s.off(a))}" for a in axes))
            s.pos.update(target)
        return out
    if kind == "tool":
        return draw(_tool_block(machine, s))
    if kind == "offset":
        return draw(_offset_block(machine, s))
    if kind == "local":
        return draw(_local_block(machine, s))
    if kind == "rotate":
        return draw(_rotate_block(machine, s))
    if kind == "cycle":
        return draw(_cycle_block(machine, s))
    if kind == "loop":
        return draw(_loop_block(machine, s, deletes))
    if kind == "call":
        return draw(_call_block(machine, s))
    if kind == "read":
        return draw(_read_block(machine, s))
    raise AssertionError(kind)


@st.composite
def _tool_block(draw, machine: Machine, s: _FanucState) -> list[str]:
    """G43 H / G49 with a Z move in the block; tool length geometry or wear written first (G10 L10/L11 in G90
    or G91, #11001 =, #2001 =)."""
    choice = draw(st.sampled_from(("H", "H", "G49", "L10", "L10+", "L11", "geo#", "wear#", "G53")))
    n = draw(st.sampled_from((1, 2)))
    out = []
    if choice == "G53":  # the tool axis moves by the change with a G53 move of the other axes
        x = draw(_machine_value(machine, "X", s))
        old = s.tool
        s.tool, s.register, s.after_home = s.geometry[n] + s.wear[n], n, False
        s.pos["Z"] += s.tool - old
        s.used.add(f"H{n}")
        if s.pos["Z"] in TRAVEL["Z"]:
            s.probes.append((f"H{n}", 1 if s.pos["Z"] == TRAVEL["Z"][1] else -1))
        s.pos["X"] = x
        return [f"G43 H{n} G53 X{_fd(x)}"]
    if choice == "G49":
        s.tool, s.register, s.after_home = F0, None, False
        z = draw(_machine_value(machine, "Z", s, tip=True))
        s.moved("Z", s.frame)
        return [f"G49 G90 G0 Z{_fd(z - s.off('Z'))}"]
    if choice in ("L10", "geo#"):
        value = _vals(draw, F(10), F(90))
        s.geometry[n] = value
        out.append(f"G10 L10 P{n} R{_fd(value)}" if choice == "L10" else f"#{11000 + n} = {_fd(value)}")
    elif choice == "L10+":
        d = _vals(draw, F(-5), F(5))
        s.geometry[n] += d
        out += [f"G91 G10 L10 P{n} R{_fd(d)}", "G90"]
    elif choice in ("L11", "wear#"):
        w = _vals(draw, F(-2), F(2), F(1, 4))
        s.wear[n] = w
        out.append(f"G10 L11 P{n} R{_fd(w)}" if choice == "L11" else f"#{2000 + n} = {_fd(w)}")
    s.tool = s.geometry[n] + s.wear[n]
    s.register = n
    s.after_home = False
    z = draw(_machine_value(machine, "Z", s, tip=True))
    s.used.add(f"H{n}")  # also when the program set it: then a range of H<n> must change nothing
    if z in TRAVEL["Z"]:
        s.probes.append((f"H{n}", 1 if z == TRAVEL["Z"][1] else -1))
    s.moved("Z", s.frame, {"Z": z})
    out.append(f"G43 H{n} G90 G0 Z{_fd(z - s.off('Z'))}")
    s.pos["Z"] = z
    return out


@st.composite
def _offset_block(draw, machine: Machine, s: _FanucState) -> list[str]:
    """A work offset written (G10 L2 P1/P2 in G90: the range no longer applies; in G91: added) and a move."""
    name = draw(st.sampled_from(("G54", "G55")))
    p = 1 if name == "G54" else 2
    how = draw(st.sampled_from(("L2", "L2", "L2+", "#")))
    axes = draw(st.sampled_from(("X", "XY", "Z")))
    out = []
    if how == "L2+":
        d = {a: _vals(draw, F(-5), F(5)) for a in axes}
        for a in axes:
            s.offsets[name][a] += d[a]
        out += [f"G91 G10 L2 P{p} " + " ".join(f"{a}{_fd(d[a])}" for a in axes), "G90"]
    else:
        new = {a: _vals(draw, F(0), F(40)) if a != "Z" else _vals(draw, F(20), F(60), F(1)) for a in axes}
        for a in axes:
            s.offsets[name][a] = new[a]
        if how == "L2":
            out.append(f"G10 L2 P{p} " + " ".join(f"{a}{_fd(new[a])}" for a in axes))
        else:
            out += [f"#{5221 + 20 * (p - 1) + 'XYZ'.index(a)} = {_fd(new[a])}" for a in axes]
    out.append(_move(draw, machine, s, axes, name, draw(st.sampled_from(("G0", "G1")))))
    return out


@st.composite
def _local_block(draw, machine: Machine, s: _FanucState) -> list[str]:
    """G52 (a local system on every workpiece system) or G92 (the current point reads the given values), a
    move in it, and sometimes the cancel."""
    out = []
    if draw(st.booleans()) or any(s.g92.values()):
        g = {a: _vals(draw, F(-10), F(10)) for a in "XY"}
        s.g52.update(g)
        out.append(f"G52 X{_fd(g['X'])} Y{_fd(g['Y'])}")
    elif not any(s.g52.values()):
        here = {a: _vals(draw, F(-20), F(20)) for a in "XY"}
        for a in "XY":  # machine = program + offsets (G92 included): the current point reads `here`
            s.g92[a] = F0
            s.g92[a] = s.pos[a] - here[a] - s.off(a)
        s.used.update(f"start.{a}" for a in "XY")
        out.append(f"G92 X{_fd(here['X'])} Y{_fd(here['Y'])}")
    out.append(_move(draw, machine, s, "XY", s.frame, draw(st.sampled_from(("G0", "G1")))))
    if draw(st.booleans()):
        if any(s.g52.values()):
            s.g52 = {a: F0 for a in "XYZ"}
            out.append("G52 X0. Y0.")
        else:
            s.g92 = {a: F0 for a in "XYZ"}
            out.append("G92.1")
    return out


@st.composite
def _rotate_block(draw, machine: Machine, s: _FanucState) -> list[str]:
    """A programmable transform about a centre (written, or the current point when its words are left out):
    G68 by a multiple of 90 degrees (targets aimed exactly) or by 30/45 (not aimed), G51 scaling by P, G51.1
    mirror image; one or two absolute moves under it, the cancel, and an absolute move."""
    here = {a: s.pos[a] - s.off(a) for a in "XY"}
    written = draw(st.booleans())
    centre = {a: _vals(draw, F(-10), F(60)) for a in "XY"} if written else here
    at = f"X{_fd(centre['X'])} Y{_fd(centre['Y'])} " if written else ""
    kind = draw(st.sampled_from(("G68", "G68", "G51", "G51.1")))
    if kind == "G68":
        angle = draw(st.sampled_from((90, 180, 270, -90, 30, 45)))
        out = [f"G90 G68 {at}R{angle}."]
        quarter = {90: (0, 1, -1, 0), 180: (-1, 0, 0, -1), 270: (0, -1, 1, 0), -90: (0, -1, 1, 0)}

        def inverse(w):  # the program point whose rotation about the centre is the workpiece point w
            if angle not in quarter:
                return None
            c, m, n, d = quarter[angle]
            return {"X": c * w["X"] + m * w["Y"], "Y": n * w["X"] + d * w["Y"]}
        cancel = "G69"
    elif kind == "G51":
        factor = draw(st.sampled_from((F(2), F(1, 2), F(3, 2))))
        out = [f"G90 G51 {at}P{_fd(factor)}"]

        def inverse(w):
            return {a: w[a] / factor for a in "XY"}
        cancel = "G50"
    else:
        axes = draw(st.sampled_from(("X", "Y", "XY")))
        out = ["G90 G51.1 " + " ".join(f"{a}{_fd(centre[a])}" for a in axes)]

        def inverse(w):
            return {a: -w[a] if a in axes else w[a] for a in "XY"}
        cancel = "G50.1"
    for _ in range(draw(st.integers(1, 2))):
        target = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
        w = {a: target[a] - s.off(a) - centre[a] for a in "XY"}
        p = inverse(w)
        if p is None or any(1000 % (p[a] + centre[a]).denominator for a in "XY"):
            p = w  # not aimed
        else:
            s.pos.update(target)
        s.moved("XY", s.frame, target if p is not w else None)
        if not written and kind != "G51.1":  # the centre moves with what the current point depends on
            s.probes += [(f"{src}.{b}", sign) for src in ("start", s.frame) for b in "XY" for sign in (1, -1)
                         if any(target[a] in TRAVEL[a] for a in "XY")]
        out.append(f"G90 G{draw(st.sampled_from((0, 1)))} X{_fd(p['X'] + centre['X'])} Y{_fd(p['Y'] + centre['Y'])}")
    out.append(cancel)
    out.append(_move(draw, machine, s, "XY", s.frame, "G0"))
    return out


@st.composite
def _cycle_block(draw, machine: Machine, s: _FanucState) -> list[str]:
    """G81/G83/G85 with G98/G99; the R level on, just above or just below the initial level."""
    init = _vals(draw, F(60), F(190))
    out = []
    if draw(st.booleans()):
        out.append(f"G90 G53 G0 Z{_fd(init)}")
    else:
        out.append(f"{_z_prefix(s, 'Z')}G90 G0 Z{_fd(init - s.off('Z'))}")
    s.pos["Z"] = init
    r_machine = init + draw(st.sampled_from((F0, F(1, 100), F(-1, 100), F(1, 2), F(-1, 2), F(2), F(-2))))
    depth = _vals(draw, F(1), min(F(40), r_machine - 1))
    xy = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
    retract = draw(st.sampled_from(("G98", "G99")))
    cycle = draw(st.sampled_from(("G81", "G81", "G83", "G85")))
    q = f" Q{_fd(_vals(draw, F(1), F(10)))}" if cycle == "G83" else ""
    out.append(f"{retract} {cycle} X{_fd(xy['X'] - s.off('X'))} Y{_fd(xy['Y'] - s.off('Y'))} "
               f"Z{_fd(r_machine - depth - s.off('Z'))} R{_fd(r_machine - s.off('Z'))}{q}")
    out.append("G80")
    s.moved("XYZ", s.frame)
    s.pos.update(xy)
    s.pos["Z"] = max(init, r_machine) if retract == "G98" else r_machine
    return out


@st.composite
def _loop_block(draw, machine: Machine, s: _FanucState, deletes: bool) -> list[str]:
    """A WHILE loop stepping an axis; the last pass aimed (on a limit, near a zone); sometimes a
    block-deleted second increment (the switch changes the number of passes)."""
    v = s.loop_var
    s.loop_var += 1
    n = draw(st.integers(2, 4))
    a = draw(st.sampled_from("XY"))
    step = draw(st.sampled_from((F(-5), F(5, 2), F(10), F(-1, 2))))
    last = draw(_machine_value(machine, a, s))
    first = last - (n - 1) * step - s.off(a)
    g = draw(st.sampled_from(("G0", "G1")))
    out = [f"#{v} = 0", f"WHILE [#{v} LT {n}] DO1", f"G90 {g} {a}[{_fd(first)} + #{v} * {_fd(step)}]",
           f"#{v} = #{v} + 1"]
    if deletes and draw(st.integers(0, 3)) == 0:
        out.append(f"/#{v} = #{v} + 1")
    out.append("END1")
    s.moved(a, s.frame, {a: last})
    s.pos[a] = last
    return out


@st.composite
def _call_block(draw, machine: Machine, s: _FanucState) -> list[str]:
    """A G65 macro call with X Y arguments (#24 #25), or an M98 subprogram repeated L times (G91 steps)."""
    if draw(st.booleans()):
        number = 9001 + len(s.subs)
        target = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
        dz = _vals(draw, F(-3), F(3))
        s.subs.append(f"O{number}\nG90 G1 X#24 Y#25\nG91 G1 Z#26\nG90\nM99")
        s.moved("XY", s.frame, target)
        words = f"X{_fd(target['X'] - s.off('X'))} Y{_fd(target['Y'] - s.off('Y'))} Z{_fd(dz)}"
        s.pos.update(target)
        s.pos["Z"] += dz
        return [f"G65 P{number} {words}"]
    number = 9101 + len(s.subs)
    a = draw(st.sampled_from("XY"))
    times = draw(st.integers(1, 3))
    last = draw(_machine_value(machine, a, s))
    step = (last - s.pos[a]) / times
    if 1000 % step.denominator:  # no decimal of the increment: one call
        times, step = 1, last - s.pos[a]
    s.subs.append(f"O{number}\nG91 G1 {a}{_fd(step)}\nG90\nM99")
    s.pos[a] = last
    s.probes += [(f"start.{a}", 1 if last == TRAVEL[a][1] else -1)] if last in TRAVEL[a] else []
    return [f"M98 P{number} L{times}"]


@st.composite
def _read_block(draw, machine: Machine, s: _FanucState) -> list[str]:
    """A move computed from a system variable: a work offset (#5221..), the block end point (#5001..), the
    machine position (#5021..), the active tool length (#5083), a geometry (#11001), a modal group (#4014)."""
    template = draw(st.sampled_from(("g5x", "pos", "mpos", "tlo", "geo", "modal")))
    a = draw(st.sampled_from("XY"))
    target = draw(_machine_value(machine, a, s))
    i = "XYZ".index(a)
    if template == "g5x":  # machine target = G54/G55 offset + c
        name = draw(st.sampled_from(("G54", "G55")))
        off = s.offsets[name][a]
        s.pos[a] = target
        return [f"G90 G53 G0 {a}[#{5221 + 20 * (name == 'G55') + i} + {_fd(target - off)}]"]
    if template == "pos":  # the programmed end point of the previous block, in the current frame
        c = target - s.pos[a]
        s.pos[a] = target
        return [f"G90 G0 {a}[#{5001 + i} + {_fd(c)}]"]
    if template == "mpos":
        c = target - s.pos[a]
        s.pos[a] = target
        return [f"G90 G53 G0 {a}[#{5021 + i} + {_fd(c)}]"]
    if template in ("tlo", "geo"):
        z = draw(_machine_value(machine, "Z", s))
        if template == "tlo":
            s.pos["Z"] = z
            return [f"G90 G53 G0 Z[#5083 + {_fd(z - s.tool)}]"]
        n = draw(st.sampled_from((1, 2)))
        s.pos["Z"] = z
        return [f"G90 G53 G0 Z[#{11000 + n} + {_fd(z - s.geometry[n])}]"]
    other = draw(_machine_value(machine, a, s))
    mine = target if s.frame == "G55" else other
    s.pos[a] = mine
    v = 30 + s.loop_var
    s.loop_var += 1
    v = min(v, 33)
    return [f"#{v} = {_fd(other)}", f"IF [#4014 EQ 55] THEN #{v} = {_fd(target)}", f"G90 G53 G0 {a}#{v}"]


# ----------------------------------------------------------------------------- cases


@st.composite
def fanuc_range_cases(draw):
    machine, _ = draw(fanuc_machines())
    used: set = set()
    text = draw(fanuc_programs(machine, used=used, extra=("rotate", "home", "tool", "offset")))
    return machine, text, draw(meta_ranges(machine, used))


@st.composite
def fanuc_margin_cases(draw):
    machine, _ = draw(fanuc_machines(posts_max=3, flat=2))
    margin = draw(st.sampled_from((F(1, 100), F(1, 10), F(1, 2), F(2))))
    text = draw(fanuc_programs(machine, reads=False, inside=margin if draw(st.integers(0, 3)) else None))
    frac = [draw(st.sampled_from((F0, F(1, 3), F(-1, 2), F(9, 10), F(-99, 100)))) for _ in range(3)]
    return machine, text, margin, {a: margin * f for a, f in zip("XYZ", frac)}


@st.composite
def fanuc_read_cases(draw):
    machine, _ = draw(fanuc_machines())
    text = draw(fanuc_programs(machine, reads=True))
    assume("#5" in text or "#11" in text or "#40" in text)
    return machine, text


@st.composite
def fanuc_delete_cases(draw):
    machine, _ = draw(fanuc_machines())
    text = draw(fanuc_programs(machine, delete_odds=1))
    assume("\n/" in text)
    return machine, text


# ----------------------------------------------------------------------------- state reads


def fanuc_reads_substituted(machine: Machine, text: str, block_delete: bool = False) -> str | None:
    """The program with every system-variable read (``#1000`` and up) replaced by the value it read with the
    block-delete switch in the given position, as a bracketed decimal (None: the reads do not follow the
    text one to one, or a value is no short decimal)."""
    import re

    from nczones.gcode import interpret_text
    from nczones.gcode.fanuc.interpreter import FanucInterpreter

    values: list[tuple[int, tuple]] = []
    original = FanucInterpreter.system_read

    def recording(self, n):
        v = original(self, n)
        values.append((n, v))
        return v

    FanucInterpreter.system_read = recording  # type: ignore[method-assign]
    try:
        run = interpret_text(text, machine, fast=False, block_delete=block_delete)
        list(run.segments())
    finally:
        FanucInterpreter.system_read = original  # type: ignore[method-assign]
    # a read on the left of "=" is a write; the written ones are not reads
    skipped = re.compile(r"[ \t]*/")  # a line the switches skip when on ('/', '/1' .. '/9')
    tokens = [m for m in re.finditer(r"#(\d+)", text) if int(m.group(1)) >= 1000
              and not re.match(r"\s*=(?!=)", text[m.end():])
              and not (block_delete and skipped.match(text, text.rfind("\n", 0, m.start()) + 1))]
    if run.unsupported or len(tokens) != len(values):
        return None
    out, pos = [], 0
    for tok, (n, value) in zip(tokens, values):
        if int(tok.group(1)) != n or value[1] is None:
            return None
        q = Fraction(value[1])
        if 10**6 % q.denominator:
            return None
        out.append(text[pos:tok.start()])
        out.append(f"[{_fd(q)}]")
        pos = tok.end()
    out.append(text[pos:])
    return "".join(out)


def check_fanuc_state_reads(machine: Machine, text: str) -> None:
    """A Fanuc program and its copy with every system-variable read replaced by its value verify alike."""
    positions = ("off", "on") if "\n/" in text else ("off",)
    copies = [fanuc_reads_substituted(machine, text, position == "on") for position in positions]
    assume(all(copy is not None for copy in copies))
    _counted("fanuc state reads")
    for position, copy in zip(positions, copies):
        assert copy is not None
        a = _verify(text, machine, block_delete=position)
        b = _verify(copy, machine, block_delete=position)
        _note(f"fanuc state reads: {a.verdict.label}")
        key_a = [(v.line, v.zone) for v in a.violations]
        key_b = [(v.line, v.zone) for v in b.violations]
        _require(a.verdict.label == b.verdict.label and key_a == key_b,
                 f"block delete {position}: reads {a.verdict.label} {key_a} {[r.code for r in a.reasons]} but "
                 f"values {b.verdict.label} {key_b} {[r.code for r in b.reasons]}\n{copy}")


# ----------------------------------------------------------------------------- block delete


_ORDER = {"safe": 0, "unknown": 1, "unsafe": 2}


def check_block_delete(machine: Machine, text: str) -> None:
    """``both`` is the worst over every combination of the switches used (each verified with the switches
    fixed); its violations are theirs, each found in every combination agreeing with its labels."""
    import itertools

    from nczones.blockskip import used_switches

    both = _verify(text, machine, block_delete="both")
    used = sorted(used_switches(text, "fanuc"))
    names = ["block_delete" if n == 1 else f"block_delete/{n}" for n in used]
    found: dict[tuple[str, ...], set] = {}
    labels = []
    for bits in itertools.product(("off", "on"), repeat=len(used)):
        run = _verify(text, machine, block_delete=",".join(f"{n}={p}" for n, p in zip(used, bits)) or "off")
        found[bits] = {(v.line, v.zone) for v in run.violations}
        labels.append(run.verdict.label)
    _counted("fanuc block delete")
    _note(f"block delete: {len(used)} switch(es), " + ", ".join(sorted(set(labels))))
    worst = max(labels, key=_ORDER.__getitem__)
    _require(both.verdict.label == worst, f"block delete both: {both.verdict.label}, but the combinations {labels}")
    for v in both.violations:
        named = dict(v.switches)
        for bits, keys in found.items():
            if all(named.get(name, p) == p for name, p in zip(names, bits)):
                _require((v.line, v.zone) in keys,
                         f"block delete both reports line {v.line} ({v.zone}) with {named}, but the combination "
                         f"{dict(zip(names, bits))} does not find it: {sorted(keys, key=str)}")
    reported = {(v.line, v.zone) for v in both.violations}
    for bits, keys in found.items():
        for key in keys:
            _require(key in reported or len(both.violations) >= 20,
                     f"line {key[0]} ({key[1]}) violates with {dict(zip(names, bits))} but not in 'both'")


# ----------------------------------------------------------------------------- dialect translation


@st.composite
def twin_programs(draw, machine: Machine) -> tuple[str, str]:
    """(LinuxCNC text, Fanuc text), line for line the same motion, in codes both documents give one meaning:
    G0/G1 in G54/G55 and G53, G91 steps, G2/G3 with I J (end absolute or incremental), G28 with X Y, G43 H /
    G49 with a Z move, G10 L2 P in G90, G52 or G92 (not both: LinuxCNC shares their registers), G81 with R at
    or below the initial level, #5221 reads, a WHILE loop, block delete."""
    s = _State(machine)
    lin = ["G21 G90 G17 G40 G49 G54 G80 G94 F600"]
    fan = ["G21 G90 G17 G40 G49 G54 G80 G94 F600."]

    def both(line: str, loop: tuple[str, str] | None = None) -> None:
        lin.append(line if loop is None else loop[0])
        fan.append(line if loop is None else loop[1])

    if draw(st.integers(0, 3)) == 0:
        target = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
        both(f"G91 G{draw(st.sampled_from((0, 1)))} X{_fd(target['X'] - s.pos['X'])} "
             f"Y{_fd(target['Y'] - s.pos['Y'])}")
        s.pos.update(target)
        both("G90")
    offsets = {name: dict(zip("XYZ", machine.offset(name))) for name in ("G54", "G55")}
    g52 = {"X": F0, "Y": F0}

    def off(a):
        return offsets[s.frame][a] + (g52[a] if a in g52 else 0) + (s.tool if a == "Z" else 0)

    loops = 0
    shifted = False
    for _ in range(draw(st.integers(1, 5))):
        kind = draw(st.sampled_from(("move", "move", "arc", "home", "tool", "offset", "local", "cycle", "read",
                                     "loop")))
        start = len(lin)
        if kind == "move":
            how = draw(st.sampled_from(("G54", "G55", "G53")))
            axes = draw(st.sampled_from(("XY", "X", "Z", "XYZ")))
            target = dict(s.pos)
            for a in axes:
                target[a] = draw(_machine_value(machine, a, s, tip=(a == "Z")))
            g = draw(st.sampled_from(("G0", "G1")))
            if how == "G53":
                both(f"G90 G53 G0 {' '.join(f'{a}{_fd(target[a])}' for a in axes)}")
            else:
                pre = "" if how == s.frame else how + " "
                s.frame = how
                both(f"{pre}G90 {g} {' '.join(f'{a}{_fd(target[a] - off(a))}' for a in axes)}")
            s.pos = target
        elif kind == "arc":
            a0, c, end, cw = _arc(draw, machine, s, spiral=False)
            both(f"G90 G1 X{_fd(a0['X'] - off('X'))} Y{_fd(a0['Y'] - off('Y'))}")
            if draw(st.booleans()):
                both(f"G{'2' if cw else '3'} X{_fd(end[0] - off('X'))} Y{_fd(end[1] - off('Y'))} "
                     f"I{_fd(c[0] - a0['X'])} J{_fd(c[1] - a0['Y'])}")
            else:  # incremental: the end from the start, I J as always
                both(f"G91 G{'2' if cw else '3'} X{_fd(end[0] - a0['X'])} Y{_fd(end[1] - a0['Y'])} "
                     f"I{_fd(c[0] - a0['X'])} J{_fd(c[1] - a0['Y'])}")
                both("G90")
            s.pos.update({"X": end[0], "Y": end[1]})
        elif kind == "home":
            mid = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
            both(f"G90 G28 X{_fd(mid['X'] - off('X'))} Y{_fd(mid['Y'] - off('Y'))}")
            s.pos.update(dict(zip("XY", machine.reference[:2])))
        elif kind == "tool":
            if draw(st.integers(0, 3)) == 0:
                s.tool = F0
                z = draw(_machine_value(machine, "Z", s, tip=True))
                both(f"G49 G90 G0 Z{_fd(z - off('Z'))}")
            else:
                n = draw(st.sampled_from((1, 2)))
                s.tool = machine.tool_length(n)
                z = draw(_machine_value(machine, "Z", s, tip=True))
                both(f"G43 H{n} G90 G0 Z{_fd(z - off('Z'))}")
            s.pos["Z"] = z
        elif kind == "offset":
            name = draw(st.sampled_from(("G54", "G55")))
            axes = draw(st.sampled_from(("X", "XY", "Z")))
            new = {a: _vals(draw, F(0), F(40)) if a != "Z" else _vals(draw, F(20), F(60), F(1)) for a in axes}
            offsets[name].update(new)
            both(f"G10 L2 P{1 if name == 'G54' else 2} " + " ".join(f"{a}{_fd(new[a])}" for a in axes))
        elif kind == "local" and not shifted:  # G52 or G92 in one program (LinuxCNC shares their registers)
            if draw(st.booleans()):
                g52.update({a: _vals(draw, F(-10), F(10)) for a in "XY"})
                both(f"G52 X{_fd(g52['X'])} Y{_fd(g52['Y'])}")
            else:
                here = {a: _vals(draw, F(-20), F(20)) for a in "XY"}
                for a in "XY":  # G92: the current point reads `here` in every workpiece system
                    g52[a] = F0
                    g52[a] = s.pos[a] - here[a] - off(a)
                both(f"G92 X{_fd(here['X'])} Y{_fd(here['Y'])}")
            shifted = True
        elif kind == "cycle":
            init = _vals(draw, F(60), F(190))
            both(f"G90 G53 G0 Z{_fd(init)}")
            r_machine = init - draw(st.sampled_from((F0, F(1, 100), F(1, 2), F(2))))
            depth = _vals(draw, F(1), min(F(40), r_machine - 1))
            xy = {a: draw(_machine_value(machine, a, s)) for a in "XY"}
            retract = draw(st.sampled_from(("G98", "G99")))
            both(f"{retract} G81 X{_fd(xy['X'] - off('X'))} Y{_fd(xy['Y'] - off('Y'))} "
                 f"Z{_fd(r_machine - depth - off('Z'))} R{_fd(r_machine - off('Z'))}")
            both("G80")
            s.pos.update(xy)
            s.pos["Z"] = init if retract == "G98" else r_machine
        elif kind == "read":
            a = draw(st.sampled_from("XY"))
            target = draw(_machine_value(machine, a, s))
            both(f"G90 G53 G0 {a}[#{5221 + 'XYZ'.index(a)} + {_fd(target - offsets['G54'][a])}]")
            s.pos[a] = target
        else:
            loops += 1
            v = loops
            n = draw(st.integers(2, 3))
            a = draw(st.sampled_from("XY"))
            step = draw(st.sampled_from((F(-5), F(5, 2), F(10))))
            last = draw(_machine_value(machine, a, s))
            first = last - (n - 1) * step - off(a)
            both(f"#{v} = 0")
            both("", (f"o{100 + v} while [#{v} LT {n}]", f"WHILE [#{v} LT {n}] DO1"))
            both(f"G90 G1 {a}[{_fd(first)} + #{v} * {_fd(step)}]")
            both(f"#{v} = [#{v} + 1]")
            both("", (f"o{100 + v} endwhile", "END1"))
            s.pos[a] = last
        if len(lin) == start + 1 and not lin[-1].startswith("#") and draw(st.integers(0, 5)) == 0:
            lin[-1], fan[-1] = "/" + lin[-1], "/" + fan[-1]
    both("", ("M2", "M30"))
    return "\n".join(lin) + "\n", "\n".join(fan) + "\n"


@st.composite
def twin_cases(draw):
    machine, _ = draw(fanuc_machines())
    return (machine, *draw(twin_programs(machine)))


def check_translation(machine: Machine, linuxcnc: str, fanuc: str) -> None:
    """The same motion in the two dialects verifies alike: verdict, violating lines, zones and positions."""
    a = _verify(linuxcnc, machine, dialect="linuxcnc")
    b = _verify(fanuc, machine, dialect="fanuc")
    _counted("dialect translation")
    _note(f"translation: {a.verdict.label}")
    key_a = sorted({(v.line, v.zone, v.switches) for v in a.violations}, key=str)
    key_b = sorted({(v.line, v.zone, v.switches) for v in b.violations}, key=str)
    if a.verdict.label == b.verdict.label == "unsafe" and key_a != key_b:
        lines_a = sorted({(v.line, v.switches) for v in a.violations}, key=str)
        lines_b = sorted({(v.line, v.switches) for v in b.violations}, key=str)
        if lines_a == lines_b:  # the same lines: a line leaving two zones may name either at its witness
            _note("translation: same lines, other zone named")
            return
    if a.verdict.label != b.verdict.label or key_a != key_b:
        raise MetamorphicViolation(
            f"linuxcnc {a.verdict.label} {key_a} {[(r.code, r.message[:80]) for r in a.reasons]} but fanuc "
            f"{b.verdict.label} {key_b} {[(r.code, r.message[:80]) for r in b.reasons]}\n--- linuxcnc\n{linuxcnc}"
            f"--- fanuc\n{fanuc}")
