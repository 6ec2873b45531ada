"""Small lathes for the turning tests: machine coordinates equal program coordinates (radius) unless a test
gives offsets, so expected points read straight from the derivations."""

from __future__ import annotations

from fractions import Fraction

from nczones.gcode import interpret_text
from nczones.machine import parse_machine

F = Fraction


def lathe(extra: str = "", *, dialect: str = "fanuc", fanuc: str = "", diameter: bool = True, zones: str = "",
          offsets: str = "", axes: str = '["X", "Z"]'):
    """A lathe machine: X and Z, X a diameter axis, reference X200 Z200 (radius), rapid 10 m/min."""
    names = [a.strip().strip('"') for a in axes.strip("[]").split(",")]
    text = (
        '[machine]\ntype = "lathe"\n'
        f'dialect = "{dialect}"\naxes = {axes}\n'
        + ('diameter_axes = ["X"]\n' if diameter else "")
        + extra
        + "\n[machine.rapid]\n" + "".join(f'{a} = "10000"\n' for a in names)
        + "[machine.reference]\n" + "".join(f'{a} = "{200 if a in "XZ" else 0}"\n' for a in names)
        + (f"[tool_offsets]\n{offsets}\n" if offsets else "")
        + (f"[fanuc]\n{fanuc}\n" if fanuc and dialect == "fanuc" else "")
        + zones
    )
    return parse_machine(text, "lathe.toml")


def moves(program: str, machine, **options):
    """``[(label, Z, X)]`` of every segment (label = the segment's ``derived`` text; X a radius)."""
    run = interpret_text(program, machine, **options)
    segs = list(run.segments())
    assert not run.unsupported, run.unsupported
    iz, ix = machine.axis_names.index("Z"), machine.axis_names.index("X")
    return [(s.derived, s.end[iz], s.end[ix]) for s in segs]


def unknown_reason(program: str, machine, **options) -> str:
    run = interpret_text(program, machine, **options)
    list(run.segments())
    assert run.unsupported, "expected unknown"
    u = run.unsupported[0]
    return f"{u.code}: {u.reason}"
