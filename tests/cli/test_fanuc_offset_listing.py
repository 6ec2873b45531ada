"""``nczones verify --tool-table LISTING``: a Fanuc tool offset listing as the control punches it out.

The block formats are the Fanuc manuals' "Programmable data input (G10)" ([0i-M], [16i-TB] B-63524EN/01
14.5.2 "Changing of tool offset value"):

* memory C: G10 L10 P<n> R = tool length geometry of H<n>, L11 its wear, L12 cutter radius geometry of D<n>,
  L13 its wear; the offset the control applies is geometry + wear (radius for D: the machine file keeps
  diameters, so 2 x (geometry + wear));
* memory A: G10 L11 P<n> R, one value used by H<n> and D<n>;
* lathe: G10 P<n> X Z R Q, P 1..64 (..9999) the wear of offset n, P 10000+n its geometry.

fanuc_mill.toml: travel Z -510..0 (machine), G54 Z = -300.  ``G43 H1 Z50.`` puts machine Z at
50 - 300 + H1 (G43 adds the offset: specs/machine-file.md [tool_lengths]), so H1 = 260 reaches Z10,
10 mm above travel (unsafe), H1 = 240 reaches Z-10 (safe).  The machine file's own H1 = 110: Z-140.
"""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction as F
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[2]
MILL = str(ROOT / "specs" / "machines" / "fanuc_mill.toml")
LATHE = str(ROOT / "specs" / "machines" / "fanuc_lathe.toml")
PROGRAM = "G90 G54 G0 X10. Y10.\nG43 H1 Z50.\nM30\n"


def listing(*blocks: str) -> str:
    return "%\nO0001 (TOOL OFFSET DATA)\n" + "".join(b + "\n" for b in blocks) + "%\n"


def nczones(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    r = subprocess.run([sys.executable, "-m", "nczones", *args], capture_output=True, text=True, cwd=cwd)
    assert "Traceback" not in r.stderr, r.stderr
    return r


@pytest.mark.parametrize("blocks, verdict", [
    (("G10 L10 P1 R200.", "G10 L11 P1 R60."), "unsafe"),   # H1 = 200 + 60 = 260: Z10
    (("G10 L10 P1 R200.", "G10 L11 P1 R40."), "safe"),     # H1 = 240: Z-10
    (("G10L10P1R200.", "G10L11P1R60.", "G10L12P1R5.", "G10L13P1R0"), "unsafe"),  # packed words, memory C
    (("G10 G90 L11 P1 R260.",), "unsafe"),                  # memory A: H1 = 260
    (("G10 G90 L11 P1 R240.",), "safe"),
])
def test_mill_listing_lengths_reach_the_proof(tmp_path, blocks, verdict):
    from nczones.commands.verify import with_tool_table
    from nczones.machine import load_machine
    from nczones.prover import verify_text

    machine = load_machine(MILL)
    assert verify_text(PROGRAM, machine).verdict.label == "safe"  # the machine file's H1 = 110: Z-140
    (tmp_path / "ofs.txt").write_text(listing(*blocks))
    with_table, note = with_tool_table(machine, str(tmp_path / "ofs.txt"), "mm")
    assert verify_text(PROGRAM, with_table).verdict.label == verdict
    # the vectorized tier (> 512 motions) sees the same lengths
    long = "G90 G54 G0 X10. Y10.\n" + "G1 X20. F1000.\nG1 X10.\n" * 300 + "G43 H1 Z50.\nM30\n"
    assert verify_text(long, with_table).verdict.label == verdict
    assert note.startswith(f"tool lengths and diameters from the Fanuc offset listing {tmp_path / 'ofs.txt'} "
                           "(memory ")


def test_memory_c_and_a_registers(tmp_path):
    from nczones.imports.fanuc_offsets import read_fanuc_listing

    (tmp_path / "c.txt").write_text(listing("G10 L10 P1 R200.", "G10 L11 P1 R-0.5", "G10 L12 P1 R5.",
                                            "G10 L13 P1 R-0.02", "G10 L11 P2 R0.1", "G10 L12 P3 R3."))
    c = read_fanuc_listing(tmp_path / "c.txt", "mm", lathe=False)
    assert c.memory == "C"
    # geometry and wear kept apart, as the control's registers (#11001.. and #10001..); a register given only
    # in one half has 0 in the other
    assert c.lengths == {1: F(200), 2: F(0)} and c.length_wear == {1: F("-0.5"), 2: F("0.1")}
    assert c.diameters == {1: F(10), 3: F(6)} and c.radius_wear == {1: F("-0.02"), 3: F(0)}  # diameter 2 x radius
    (tmp_path / "a.txt").write_text(listing("G10 L11 P1 R5.", "G10 L11 P2 R100."))
    a = read_fanuc_listing(tmp_path / "a.txt", "inch", lathe=False)
    assert a.memory == "A"                                    # one value for H and D (a radius for D)
    assert a.length_wear == {} and a.radius_wear == {}
    assert a.lengths == {1: F(127), 2: F(2540)}               # inches x 25.4
    assert a.diameters == {1: F(254), 2: F(5080)}
    (tmp_path / "g20.txt").write_text(listing("G20", "G10 L11 P1 R1."))
    assert read_fanuc_listing(tmp_path / "g20.txt", None, lathe=False).lengths == {1: F("25.4")}


@pytest.mark.parametrize("program, verdict", [
    # the listing: H1 geometry 240, wear -40 (the control applies 200: Z-50).  G10 L11 (G90) replaces the wear
    # only: 240 + 20 = 260 reaches Z10, above travel.  Summing the two halves into one length would have
    # proved 200 + 20 = 220 (Z-30) safe.
    ("G90 G54 G0 X10. Y10.\nG10 L11 P1 R20.\nG43 H1 Z50.\nM30\n", "unsafe"),
    ("G90 G54 G0 X10. Y10.\nG43 H1 Z50.\nM30\n", "safe"),
    # #10001 reads the wear (-40), #11001 the geometry (240); machine Z = Z - 300 + 200
    ("G90 G54 G0 X10. Y10.\nG43 H1 Z[50. - #10001 - 50.]\nM30\n", "safe"),    # Z40: 40 - 300 + 200 = -60
    ("G90 G54 G0 X10. Y10.\nG43 H1 Z[#11001 - 130.]\nM30\n", "unsafe"),       # Z110: 110 - 300 + 200 = 10
])
def test_memory_c_wear_stays_apart_from_geometry(tmp_path, program, verdict):
    from nczones.commands.verify import with_tool_table
    from nczones.machine import load_machine
    from nczones.prover import verify_text

    (tmp_path / "ofs.txt").write_text(listing("G10 L10 P1 R240.", "G10 L11 P1 R-40."))
    machine, _ = with_tool_table(load_machine(MILL), str(tmp_path / "ofs.txt"), "mm")
    assert verify_text(program, machine).verdict.label == verdict


def test_lathe_listing(tmp_path):
    from nczones.commands.verify import with_tool_table
    from nczones.machine import load_machine

    # diameter X (parameter 5004#1 ORC = 0): X160. is radius 80 as [tool_offsets] keeps it
    (tmp_path / "t.txt").write_text(listing("G10 P10001 X160. Z50. R0.4 Q3", "G10 P1 X0.02 Z-0.01 R0.01 Q3",
                                            "G10 P10002 X170. Z45. R0.2 Q2"))
    machine = load_machine(LATHE)
    lathe, note = with_tool_table(machine, str(tmp_path / "t.txt"), "mm", "diameter")
    one, two = lathe.tool_offsets[1], lathe.tool_offsets[2]
    assert dict(one.geometry) == {"X": 80, "Z": 50} and dict(one.wear) == {"X": F("0.01"), "Z": F("-0.01")}
    assert (one.nose_radius, one.wear_radius, one.tip) == (F("0.4"), F("0.01"), 3)
    assert dict(two.geometry) == {"X": 85, "Z": 45} and two.tip == 2 and two.wear == ()
    assert set(lathe.tool_offsets) == {1, 2} and "sha256" in note
    radius, _ = with_tool_table(machine, str(tmp_path / "t.txt"), "mm", "radius")
    assert dict(radius.tool_offsets[1].geometry)["X"] == 160
    from nczones.errors import InputError
    with pytest.raises(InputError) as e:  # diameter or radius is the control's parameter: never guessed
        with_tool_table(machine, str(tmp_path / "t.txt"), "mm")
    assert e.value.diagnostics[0].code == "VF111" and "ORC" in e.value.diagnostics[0].message


@pytest.mark.parametrize("block, column, words", [
    ("G10 L10 P1 R200", 12, "decimal point"),      # no decimal point: DPI decides its value
    ("G10 G91 L10 P1 R2.", 5, "G91"),              # an increment on an unknown value
    ("G10 L10 P1 K2.", 12, "takes"),
    ("G10 L2 P1 R2.", 5, "L10/L11/L12/L13"),
])
def test_a_bad_line_is_named_with_its_column(tmp_path, block, column, words):
    (tmp_path / "p.nc").write_text(PROGRAM)
    (tmp_path / "ofs.txt").write_text(listing("G10 L10 P2 R1.", block))
    r = nczones("verify", "p.nc", "--machine", MILL, "--tool-table", "ofs.txt", "--tool-table-units", "mm",
                cwd=tmp_path)
    assert r.returncode == 2, r.stdout + r.stderr
    assert f"ofs.txt:4:{column}: error[VF111]" in r.stderr and words in r.stderr


def test_the_command_line(tmp_path):
    (tmp_path / "p.nc").write_text(PROGRAM)
    (tmp_path / "ofs.txt").write_text(listing("G10 L10 P1 R200.", "G10 L11 P1 R60."))
    r = nczones("verify", "p.nc", "--machine", MILL, "--tool-table", "ofs.txt", cwd=tmp_path)
    assert r.returncode == 2 and "error[VF111]" in r.stderr and "--tool-table-units" in r.stderr
    r = nczones("verify", "p.nc", "--machine", MILL, "--tool-table", "ofs.txt", "--tool-table-units", "mm",
                cwd=tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr  # H1 = 260: 10 mm above travel
    assert "p.nc: note: tool lengths and diameters from the Fanuc offset listing ofs.txt (memory C, mm, sha256 " \
        in r.stdout
    (tmp_path / "odd.txt").write_text("hello\n")
    r = nczones("verify", "p.nc", "--machine", MILL, "--tool-table", "odd.txt", "--tool-table-units", "mm",
                cwd=tmp_path)
    assert r.returncode == 2 and "error[VF111]" in r.stderr
    assert "LinuxCNC tool table" in r.stderr and "Fanuc tool offset listing" in r.stderr
    r = nczones("verify", "p.nc", "--machine", str(ROOT / "specs" / "machines" / "mill.toml"), "--tool-table",
                "ofs.txt", "--tool-table-units", "mm", cwd=tmp_path)
    assert r.returncode == 2 and "error[VF111]" in r.stderr and "dialect is linuxcnc" in r.stderr


@pytest.mark.parametrize("blocks, verdict", [
    (("G10 P10001 X160. Z50. R0.4 Q3",), "safe"),                    # machine Z = -60 + 200 + 50 = 190
    (("G10 P10001 X160. Z-150. R0.4 Q3",), "unsafe"),                # -60 + 200 - 150 = -10 < travel's 0
    (("G10 P10001 X160. Z50. R0.4 Q3", "G10 P1 X0 Z-200. R0 Q3"), "unsafe"),  # geometry + wear = -150
])
def test_a_lathe_listing_moves_the_carriage(tmp_path, blocks, verdict):
    """fanuc_lathe.toml: G54 Z = 200, travel Z 0..700; T0101 adds offset 1 (geometry + wear) to the machine
    position (machine = program + work offset + geometry + wear, specs/machine-file.md [tool_offsets])."""
    (tmp_path / "l.nc").write_text("T0101\nG0 X100. Z-60.\nM30\n")
    (tmp_path / "t.txt").write_text(listing(*blocks))
    r = nczones("verify", "l.nc", "--machine", LATHE, "--tool-table", "t.txt", "--tool-table-units", "mm",
                "--tool-table-x-offset", "diameter", cwd=tmp_path)
    assert r.returncode == {"safe": 0, "unsafe": 1}[verdict], r.stdout + r.stderr
    assert "l.nc: note: lathe tool offsets from the Fanuc offset listing t.txt (mm, sha256 " in r.stdout


_DECIMAL = st.builds(lambda i, f, neg: f"{'-' if neg else ''}{i}.{f}", st.integers(0, 999), st.integers(0, 9999),
                     st.booleans())


@settings(max_examples=30, deadline=None)
@given(st.dictionaries(st.tuples(st.sampled_from((10, 11, 12, 13)), st.integers(1, 200)), _DECIMAL, min_size=1,
                       max_size=8), st.booleans(), st.sampled_from(("mm", "inch")))
def test_a_memory_c_listing_reads_back_exactly(values, packed, units):
    """Every register written is read back as the exact decimal (x 25.4 for inch; x 2 for a D diameter),
    spaces between words or none; a register given in one half has 0 in the other."""
    import tempfile

    from nczones.imports.fanuc_offsets import read_fanuc_listing

    if not any(L != 11 for L, _ in values):
        values[(10, 1)] = "1.5"  # an L11-only listing is memory A
    sep = "" if packed else " "
    text = listing(*(sep.join(("G10", f"L{L}", f"P{n}", f"R{v}")) for (L, n), v in values.items()))
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "ofs.txt"
        path.write_text(text)
        got = read_fanuc_listing(path, units, lathe=False)
    k = F(254, 10) if units == "inch" else F(1)
    tables = {10: got.lengths, 11: got.length_wear, 12: got.diameters, 13: got.radius_wear}
    for (L, n), v in values.items():
        assert tables[L][n] == F(v) * k * (2 if L == 12 else 1)
    for a, b in ((10, 11), (12, 13)):
        assert set(tables[a]) == set(tables[b]) == {n for (L, n) in values if L in (a, b)}
        for n in tables[a]:
            if (a, n) not in values:
                assert tables[a][n] == 0
            if (b, n) not in values:
                assert tables[b][n] == 0
