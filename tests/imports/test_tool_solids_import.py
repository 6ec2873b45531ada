"""Tool tables into tool solids (issue 39): ``import-machine`` writes the ``[[tools]]`` a tool table can start,
commented out — a table gives the cutter's diameter (D) and the whole tool's length below the gauge line (Z),
but neither the cutter's own length nor the holder, and a made-up length would be a proof about an invented
tool (specs/machine-import.md, "Tool solids")."""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

from nczones.cli import main
from nczones.machine import parse_machine
from nczones.solids import machine_solids

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "import" / "linuxcnc"


def _import(capsys, monkeypatch, name: str) -> str:
    monkeypatch.chdir(GOLDEN)
    assert main(["import-machine", name]) in (0, 3)
    return capsys.readouterr().out


def test_a_tool_table_diameter_becomes_a_commented_cutter(capsys, monkeypatch):
    text = _import(capsys, monkeypatch, "mill_mm.ini")
    # mill_mm.tbl: T1 D6.0, T2 D12.7, T3 without D (LinuxCNC's diameter 0: no solid), T17 D3.175
    numbers = [int(n) for n in re.findall(r"^# number = (\d+)", text, re.M)]
    assert numbers == [1, 2, 17]
    # nothing is active: the imported machine proves the tip only, as before
    assert machine_solids(parse_machine(text, "m.toml")) is None
    # filled in and uncommented, it is a valid machine file with the table's diameters
    block = text.split("# [[tools]] is not written", 1)[1].split("\n\n", 1)[0]
    solids = "\n".join(line[2:] for line in block.splitlines() if line.startswith("# [[tools]]")
                       or line.startswith("# number") or line.startswith("# parts")).replace('"?"', '"20"')
    m = parse_machine(text + "\n" + solids + "\n", "m.toml")
    tools = machine_solids(m).tools
    assert {n: p[0].radius * 2 for n, p in tools.items()} == {1: Fraction(6), 2: Fraction(127, 10),
                                                             17: Fraction(3175, 1000)}


def test_a_lathe_table_writes_no_tool_solids(capsys, monkeypatch):
    # a lathe's turret tools are rectangles relative to the tip: a tool table (X Z offsets, the nose D,
    # the orientation Q) has nothing for them
    text = _import(capsys, monkeypatch, "lathe_inch.ini")
    assert "[tool_diameters]" in text and "[[tools]]" not in text
