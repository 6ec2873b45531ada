"""Tool tables into tool solids (issue 39): ``import-machine`` writes the ``[[tools]]`` a tool table can start,
commented out — a table gives the cutter's diameter (D) and the whole tool's length below the gauge line (Z),
but neither the cutter's own length nor the holder, and a made-up length would be a proof about an invented
tool (specs/machine-import.md, "Tool solids")."""

from __future__ import annotations

import re
from decimal import Decimal
from fractions import Fraction
from fractions import Fraction as F
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

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


# --------------------------------------------------------------------------- Fanuc tool offset listings
#
# import-machine PARAMS.prm --tool-table LISTING: a Fanuc tool offset listing (G10 blocks as the control punches
# its offset memory out; nczones/imports/fanuc_offsets.py) starts commented-out [[tools]] solids.  The block
# meanings are the manuals': Series 0i-B Connection Manual B-63833EN-1 10.2.1 "Tool compensation memory C: ...
# separate memories are prepared for cutter compensation (for D code) and for tool length compensation (for H
# code)", geometry and wear apart; G10 L10/L11 H geometry/wear, L12/L13 D geometry/wear ("Programmable data
# input (G10)"); memory A: one value per number, G10 L11 (specs/machine-file.md); a lathe's G10 P<n> X Z R Q,
# P 1-64 the wear, P 10000+n the geometry, R the nose radius, Q the imaginary tool nose (16i-TB B-63524EN
# 14.5.2).  The listings in tests/golden/import/fanuc/offsets/ are written after these formats (no listing
# punched by a control is in the corpus: /work/shared/corpus/fanuc/README.md lists G10 L10/L11/L12 as not
# covered).

FANUC = Path(__file__).resolve().parents[1] / "golden" / "import" / "fanuc"
REGEN = __import__("os").environ.get("NCZONES_REGEN_GOLDEN") == "1"
FANUC_CASES = [("mill_16i.prm", "mill_c"), ("mill_16i.prm", "mill_a"), ("mill_16i.prm", "mill_b"),
               ("router_inch.prm", "router_inch"), ("lathe_30i.prm", "lathe")]


def _fanuc_import(capsys, monkeypatch, prm: str, listing: str) -> tuple[str, str]:
    monkeypatch.chdir(FANUC)
    code = main(["import-machine", prm, "--tool-table", f"offsets/{listing}.txt"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "Traceback" not in err
    return out, err


def _uncomment(text: str, replace: dict[str, str]) -> str:
    """The commented-out [[tools]] blocks, uncommented, with each "?" replaced in turn from ``replace``."""
    rows = [line[2:].split(" # ")[0] for line in text.splitlines()
            if line.startswith(("# [[tools]]", "# number", "# parts")) and "is not written" not in line]
    block = "\n".join(rows)
    for key, value in replace.items():
        block = block.replace(key, value)
    return block


@pytest.mark.parametrize("prm, listing", FANUC_CASES, ids=[c[1] for c in FANUC_CASES])
def test_fanuc_listing_golden(prm, listing, capsys, monkeypatch, tmp_path):
    out, err = _fanuc_import(capsys, monkeypatch, prm, listing)
    for text, golden in ((out, FANUC / "offsets" / f"{listing}.toml"), (err, FANUC / "offsets" / f"{listing}.out")):
        if REGEN:
            golden.write_text(text, encoding="utf-8")
        assert text == golden.read_text(encoding="utf-8")
    # the written file loads and checks, and proves the tip only (every solid is commented out)
    assert machine_solids(parse_machine(out, "m.toml")) is None
    (tmp_path / "m.toml").write_text(out)
    assert main(["check-machine", str(tmp_path / "m.toml")]) == 0
    capsys.readouterr()


def test_fanuc_memory_c_cutters_round_trip(capsys, monkeypatch):
    out, err = _fanuc_import(capsys, monkeypatch, "mill_16i.prm", "mill_c")
    # mill_c.txt: D1 R5 wear -0.01; D2 R3 wear +0.015; D3 R0 (a drill's: no size); D4 R6.35 (no H4); D5 R8 (H5
    # -350, set from the table); D6 wear only.  Solids are numbered by offset number, the [[tools]] number the
    # machine file activates under G43 H<n> (specs/machine-file.md "Which tool").
    assert [int(n) for n in re.findall(r"^# number = (\d+)", out, re.M)] == [1, 2, 4, 5]
    assert "note[IM205]" in err and "paired by offset number" in err
    block = _uncomment(out, {'"?"': '"20"'})
    tools = machine_solids(parse_machine(out + "\n" + block + "\n", "m.toml")).tools
    # the cutter's diameter is twice the D geometry radius; a negative wear (a worn, smaller cutter) is not
    # added, a positive one is (the enclosing cylinder: the larger of geometry and geometry + wear)
    assert {n: parts[0].radius * 2 for n, parts in tools.items()} == {
        1: 2 * F(5), 2: 2 * (F(3) + F("0.015")), 4: 2 * F("6.35"), 5: 2 * F(8)}
    assert all(parts[0].z0 == 0 and parts[0].z1 == 20 for parts in tools.values())
    # the tool length is in the comment: H1 = 150 + wear -0.02, tip below the gauge line
    assert re.search(r"^# number = 1 .*H1 = 150 \+ wear -0\.02 = 149\.98 mm", out, re.M)
    assert re.search(r"^# number = 5 .*H5 = -350 mm is no length from the gauge line", out, re.M)


@pytest.mark.parametrize("listing, memory", [("mill_a", "memory A"), ("mill_b", "memory B")])
def test_fanuc_memory_a_and_b_write_no_cutter(listing, memory, capsys, monkeypatch):
    # memory A/B: H and D share the registers (a register holds a length or a radius, which the program's
    # words decide), so a diameter from the listing would need a mapping the listing does not hold
    out, err = _fanuc_import(capsys, monkeypatch, "mill_16i.prm", listing)
    assert "[[tools]]" not in out
    assert f"note[IM201]: no cutter solid from the tool offset listing: it holds {memory}" in err


def test_fanuc_unit_from_the_input_unit_parameter(capsys, monkeypatch):
    # router_inch.prm: 0000 #2 INI = 1 (input in inches); its listing states no G20/G21: R0.125 in = 3.175 mm
    out, err = _fanuc_import(capsys, monkeypatch, "router_inch.prm", "router_inch")
    assert "note[IM203]: the tool offset listing states no G20/G21" in err and "inch by 0000 #2 INI = 1" in err
    tools = machine_solids(parse_machine(out + "\n" + _uncomment(out, {'"?"': '"10"'}) + "\n", "m.toml")).tools
    assert tools[1][0].radius == F("0.125") * F("25.4")


def test_fanuc_lathe_offsets_give_the_nose_only(capsys, monkeypatch):
    from nczones.lathe_solids import lathe_solids

    out, err = _fanuc_import(capsys, monkeypatch, "lathe_30i.prm", "lathe")
    assert "a tool offset listing gives no body" in out
    # offsets 1 (R0.8 + wear 0.02, tip 3), 2 (R0.4, tip 0), 11 (R1.2 - 0.05, tip 8); 3 has R0: no nose.  The
    # tool number is not in the listing: "?" until the user names the turret tool (T0101, T0111 ...)
    assert out.count('# number = "?"') == 3 and "No nose for offset 3" in out
    block = _uncomment(out, {})
    for k in (1, 2, 11):
        block = block.replace('number = "?"', f"number = {k}", 1)
    block = block.replace('thickness = "?"', 'thickness = "5"')
    tools = lathe_solids(parse_machine(out + "\n" + block + "\n", "m.toml")).tools
    # the nose centre lies within R of the imaginary tip on X and Z (tip 0/9: at it; 1-8: on one or both axes,
    # B-64304EN "Imaginary tool nose"), so the nose circle lies within R (0/9) or 2R (1-8) on each axis: the
    # square of that half-width about the tip holds it whichever way the machine's tip numbers turn
    reach = {1: 2 * max(F("0.8"), F("0.8") + F("0.02")), 2: F("0.4"), 11: 2 * max(F("1.2"), F("1.2") - F("0.05"))}
    for k, r in reach.items():
        (nose,) = tools[k]
        assert (nose.x0, nose.x1, nose.z0, nose.z1, nose.thickness) == (-r, r, -r, r, 5)


@pytest.mark.parametrize("tip", range(10))
def test_the_nose_square_holds_the_nose_circle_for_every_tip(tip):
    # the nose centre relative to the imaginary tip, for each direction: (0, 0) for 0/9, R along one axis for
    # 5-8, R along both for 1-4 (signs: any; the square does not depend on them); every point of the circle is
    # within the square of half-width R (0/9) or 2R (1-8)
    r = F(4, 5)
    reach = r if tip in (0, 9) else 2 * r
    centres = [(F(0), F(0))] if tip in (0, 9) else (
        [(sx * r, sz * r) for sx in (-1, 1) for sz in (-1, 1)] if tip <= 4 else
        [(s * r, F(0)) for s in (-1, 1)] + [(F(0), s * r) for s in (-1, 1)])
    for cx, cz in centres:
        assert abs(cx) + r <= reach and abs(cz) + r <= reach


def test_fanuc_listing_solid_reaches_the_proof(capsys, monkeypatch):
    # the whole path: import-machine writes D1's cutter (diameter 10); uncommented with a 20 mm cutter and a
    # vise, verify --tool-table reads H1 = 149.98 from the same listing.  The tip runs along X = 96 .. 94
    # (Y 150, tip Z -350: machine Z -350 + 149.98; G43 H1 before the first move, as the solids need the
    # active register, VF211); the vise starts at X 100: the cutter's edge is at 101 (in)
    # or 99 (clear), and the point alone is clear in both.
    from nczones.commands.verify import with_tool_table
    from nczones.prover import verify_text

    out, _ = _fanuc_import(capsys, monkeypatch, "mill_16i.prm", "mill_c")
    vise = ('[[fixtures]]\nname = "vise"\nkind = "box"\nmin = { X = "100", Y = "100", Z = "-500" }\n'
            'max = { X = "200", Y = "200", Z = "-300" }\n')
    text = out.replace("[machine]\n", '[machine]\npath_mode = "G61"\n', 1)
    machine = parse_machine(text + "\n" + _uncomment(out, {'"?"': '"20"'}) + "\n" + vise, "m.toml")
    machine, _ = with_tool_table(machine, str(FANUC / "offsets" / "mill_c.txt"), None)
    for x, verdict in (("96.", "unsafe"), ("94.", "safe")):
        start = "G90 G43 H1 Z-200.\nG0 X50. Y150.\nG1 Z-350. F500.\n"
        short = f"{start}G1 X{x}\nG0 Z-200.\nM30\n"
        long = start + "G1 X60.\nG1 X50.\n" * 300 + f"G1 X{x}\nG0 Z-200.\nM30\n"
        for program in (short, long):
            result = verify_text(program, machine)
            assert result.verdict.label == verdict, (x, result.verdict)


def test_a_listing_that_states_its_unit_first_is_a_listing():
    # a listing may state G21/G20 (and G90) before its G10 blocks (the reader accepts them); verify --tool-table
    # tells the format by the first block, which took such a listing for a .tbl before
    from nczones.imports.fanuc_offsets import is_fanuc_listing

    assert is_fanuc_listing((FANUC / "offsets" / "mill_c.txt").read_text())
    assert is_fanuc_listing("%\nO0001\nN1 G90 G21\nG10 L10 P1 R100.\n%\n")
    assert not is_fanuc_listing("T1 P1 Z100 D6\n") and not is_fanuc_listing("G21\nT1 P1 Z100\n")


def test_a_wrong_listing_is_refused_at_its_line(capsys, monkeypatch):
    # a lathe listing (G10 P X Z R Q) for a mill: the reader's VF111 at file:line:column, exit 2, nothing written
    monkeypatch.chdir(FANUC)
    assert main(["import-machine", "mill_16i.prm", "--tool-table", "offsets/lathe.txt"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "Traceback" not in err
    assert err.startswith("offsets/lathe.txt:5:12: error[VF111]: 'X-160.': a mill listing takes N L P R after G10")
    assert main(["import-machine", "mill_16i.prm", "--tool-table", "offsets/missing.txt"]) == 2
    assert "offsets/missing.txt: error[VF111]: cannot read the tool offset listing" in capsys.readouterr().err
    # a Grbl dump has no tool offsets to read
    monkeypatch.chdir(FANUC.parent / "grbl")
    assert main(["import-machine", "router_grbl11.settings", "--tool-table", "x.txt"]) == 2
    assert "--tool-table belongs to LinuxCNC configurations" in capsys.readouterr().err


_RADIUS = st.decimals(min_value=Decimal("-3"), max_value=Decimal("40"), places=3)
_WEAR = st.decimals(min_value=Decimal("-0.5"), max_value=Decimal("0.5"), places=3)


@settings(max_examples=25, deadline=None)
@given(st.dictionaries(st.integers(1, 400), st.tuples(_RADIUS, st.one_of(st.none(), _WEAR)), min_size=1,
                       max_size=6))
def test_every_memory_c_radius_becomes_its_cutter(registers):
    # property: for any memory C listing of D registers (L12 geometry, optional L13 wear), the starts written,
    # uncommented, are exactly the registers whose geometry is above 0, each of diameter 2 x max(g, g + w)
    import tempfile

    from nczones.imports import import_machine

    blocks = ["%", "G21"]
    for n, (g, w) in registers.items():
        blocks.append(f"G10 L12 P{n} R{g:.3f}")
        if w is not None:
            blocks.append(f"G10 L13 P{n} R{w:.3f}")
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "ofs.txt"
        path.write_text("\n".join(blocks + ["%"]) + "\n")
        text = import_machine(FANUC / "mill_16i.prm", tool_table=str(path)).text
    expected = {n: 2 * max(Fraction(g), Fraction(g) + Fraction(w or 0)) for n, (g, w) in registers.items() if g > 0}
    block = _uncomment(text, {'"?"': '"1"'})
    solids = machine_solids(parse_machine(text + "\n" + block + "\n", "m.toml")) if expected else None
    got = {} if solids is None else {n: parts[0].radius * 2 for n, parts in solids.tools.items()}
    assert got == expected


def test_a_lathe_with_a_y_axis_reads_its_lathe_listing(capsys, monkeypatch, tmp_path):
    # a lathe control (1006 #3 DIA on X) with a Y axis keeps lathe offsets (G10 P X Z R Q, B-63524EN 14.5.2 also
    # allows Y); its solids take the mill form (X, Y, Z), where a nose square has no place: the listing is read
    # (a wrong line would be VF111) and nothing is written, with a note -- not refused as a mill listing
    prm = (FANUC / "lathe_30i.prm").read_text()
    for old, new in (("N01006Q1A1P00001000A2P00000000;", "N01006Q1A1P00001000A2P00000000A3P00000000;"),
                     ("N01013Q1A1P00000010A2P00000010;", "N01013Q1A1P00000010A2P00000010A3P00000010;"),
                     ("N01020Q1A1P88A2P90;", "N01020Q1A1P88A2P90A3P89;"),
                     ("N01240Q1A1M220.0000A2M300.0000;", "N01240Q1A1M220.0000A2M300.0000A3M0.0;"),
                     ("N01420Q1A1M15000.0A2M20000.0;", "N01420Q1A1M15000.0A2M20000.0A3M5000.0;")):
        assert old in prm
        prm = prm.replace(old, new)
    (tmp_path / "lathe_y.prm").write_text(prm)
    (tmp_path / "ofs.txt").write_text((FANUC / "offsets" / "lathe.txt").read_text())
    monkeypatch.chdir(tmp_path)
    assert main(["import-machine", "lathe_y.prm", "--tool-table", "ofs.txt"]) == 0
    out, err = capsys.readouterr()
    assert 'axes = ["X", "Z", "Y"]' in out and "[[tools]]" not in out
    assert "ofs.txt: note[IM201]: no solid from the lathe tool offset listing ofs.txt: this lathe has a Y axis" in err
