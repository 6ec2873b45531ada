"""LinuxCNC lathes: diameter mode G7/G8 and the G70-G72 cycles with their profile subroutines.

Two oracles: passes derived by hand on small profiles (derivations beside each test), and LinuxCNC's own
interpreter — the canon logs its ``rs274`` wrote for the G7x tests of its repository (in the corpus), which
the generated moves must reproduce to the log's four decimals.
"""

from __future__ import annotations

import re

import pytest

from nczones.controller import simulate
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import Verdict, verify_segments
from tests.corpus import CORPUS
from tests.gcode.turning.helpers import F, lathe, moves, unknown_reason
from tests.machines import machine_text


def _lc(diameter: bool = False, zones: str = ""):
    return lathe('[machine.start]\nX = "20"\nZ = "20"\n', dialect="linuxcnc", diameter=diameter, zones=zones)


STEP = """G18 G21 G8 F100
o1 sub
G1 X4
Z-10
X10
o1 endsub
G71 Q1 X10 Z1 D0 I2 R0.5
M2
"""


def test_g71_passes_derived_by_hand():
    """Start point A = (Z1, X10) (radius mode), profile A -> (Z1, X4) -> (Z-10, X4) -> (Z-10, X10); I2: levels
    10, 8, 6 (the first at A's level, as LinuxCNC cuts it), then 4 is the profile's bottom, which the last pass
    follows.  Each level: rapid infeed along X at Z1; cut at feed to where the level meets the wall Z-10;
    escape by R = 0.5 on both axes (scale min(1, 11/2/0.5) = 1): (Z-9.5, X+0.5); return at rapid to
    (Z1 - 0.5, X+0.5); back to the level at rapid (the first piece is the start's rapid)."""
    got = moves(STEP, _lc())
    expect = [("G71 to the start point", F(1), F(10)), ("G71 roughing: to the start", F(1), F(10))]
    for n, x in enumerate((10, 8, 6), start=1):
        expect += [(f"G71 roughing pass {n}: infeed", F(1), F(x)),
                   (f"G71 roughing pass {n}: cut", F(-10), F(x)),
                   (f"G71 roughing pass {n}: escape", F(-19, 2), F(x) + F(1, 2)),
                   (f"G71 roughing pass {n}: return", F(1, 2), F(x) + F(1, 2)),
                   (f"G71 roughing pass {n}: back to the level", F(1), F(x))]
    expect += [("G71 roughing pass 4: infeed", F(1), F(4)), ("G71 roughing pass 4: along the profile", F(-10), F(4)),
               ("G71 roughing pass 4: along the profile", F(-10), F(10))]
    assert got == expect


def test_diameter_mode_halves_x_words_of_blocks_and_profiles():
    """G7 (or a diameter axis in the machine file): every X word is a diameter, I and K stay radii; the same
    cycle written in diameters gives the same passes; G8 switches back."""
    in_diameters = STEP.replace("G8", "G7").replace("X4", "X8").replace("X10", "X20")
    assert moves(in_diameters, _lc()) == moves(STEP, _lc())
    started = STEP.replace("G8 ", "").replace("X4", "X8").replace("X10", "X20")
    assert moves(started, _lc(diameter=True)) == moves(STEP, _lc())
    segs = list(interpret_text("G18 G7 G0 X40 Z2\nG8 X40\nG7 G2 X76 Z0 I-1 K-1 F10\n", _lc()).segments())
    assert [[str(v) for v in s.end] for s in segs] == [["20", "2"], ["40", "2"], ["38", "0"]]


def test_g72_facing_passes_derived_by_hand():
    """G72 is G71 turned by 90 degrees.  Start A = (Z1, X10); profile A -> (Z-4, X10) -> (Z-4, X2) -> (Z1, X2): the
    depth goes along Z, levels Z1, Z-1, Z-3 (I2; the first at A's Z), each cut along X from X10 down to the
    profile's X2; escape by R0.5 on both axes away from the material: (Z+0.5, X2.5); return along X to
    (Z+0.5, X10 - 0.5); back to the level at rapid.  Level Z-4 is the profile's face, which the last pass
    follows to X2 and then along X2 back to Z1 (the profile's last piece)."""
    prog = "G18 G21 G8 F100\no2 sub\nG1 Z-4\nX2\nZ1\no2 endsub\nG72 Q2 X10 Z1 D0 I2 R0.5\nM2\n"
    expect = [("G72 to the start point", F(1), F(10)), ("G72 roughing: to the start", F(1), F(10))]
    for n, z in enumerate((1, -1, -3), start=1):
        expect += [(f"G72 roughing pass {n}: infeed", F(z), F(10)),
                   (f"G72 roughing pass {n}: cut", F(z), F(2)),
                   (f"G72 roughing pass {n}: escape", F(z) + F(1, 2), F(5, 2)),
                   (f"G72 roughing pass {n}: return", F(z) + F(1, 2), F(19, 2)),
                   (f"G72 roughing pass {n}: back to the level", F(z), F(10))]
    expect += [("G72 roughing pass 4: infeed", F(-4), F(10)), ("G72 roughing pass 4: along the profile", F(-4), F(2)),
               ("G72 roughing pass 4: along the profile", F(1), F(2))]
    assert moves(prog, _lc()) == expect


def test_g70_finishing_follows_the_profile():
    """G70 P1 D0 E0: one pass at distance 0: rapid to the profile's first point's level, then the profile."""
    prog = STEP.replace("G71 Q1 X10 Z1 D0 I2 R0.5", "G70 Q1 X10 Z1 D0 E0 P1")
    got = moves(prog, _lc())
    assert [(z, x) for _l, z, x in got][-3:] == [(F(1), F(4)), (F(-10), F(4)), (F(-10), F(10))]
    assert all(lab.startswith("G70 ") for lab, _z, _x in got)


@pytest.mark.parametrize("case,why", [
    ("G41.1 D1\n", "with cutter compensation on is not modelled"),
    ("", "the profile (line 3) is not modelled"),
])
def test_what_the_model_cannot_follow_is_unknown(case, why):
    prog = "G18 G21 G8 F100\no1 sub\nG1 X4 Y2\nZ-10\nX10\no1 endsub\n" + case + "G71 Q1 X10 Z1 D0 I2 R0.5\nM2\n"
    if case:
        prog = prog.replace(" Y2", "")
    m = lathe('cutter_compensation = "linuxcnc"\n[machine.start]\nX = "20"\nY = "0"\nZ = "20"\n[tool_diameters]\nT1 = "1"\n', dialect="linuxcnc",
              diameter=False, axes='["X", "Y", "Z"]')
    assert why in unknown_reason(prog, m)


def test_a_g71_profile_linuxcnc_rejects_is_unknown_with_its_reason():
    """A profile that turns back along Z: LinuxCNC stops with "Not monotonic"; nczones says unknown, with it."""
    prog = "G18 G21 G8 F100\no1 sub\nG1 X4\nZ-5\nX6 Z-3\nZ-10\nX10\no1 endsub\nG71 Q1 X10 Z1 D0 I2 R0.5\nM2\n"
    assert unknown_reason(prog, _lc()).startswith("G71: G71: LinuxCNC stops this cycle with an error")
    assert "Not monotonic" in unknown_reason(prog, _lc())


def test_profile_with_parameters_and_control_flow_is_read():
    prog = "#<_d>=4\nG18 G21 G8 F100\no1 sub\no2 if [#<_d> GT 3]\nG1 X#<_d>\no2 endif\nZ-10\nX10\no1 endsub\n" \
           "G71 Q1 X[10] Z1 D0 I2 R0.5\nM2\n"
    assert moves(prog, _lc()) == moves(STEP, _lc())


def test_the_prover_names_the_pass_and_the_controller_agrees():
    """Jaws at Z [-12, -8], X [6.25, 6.75] (radius), between the levels X6 and X8: every cut is clear (X8 above,
    X6 below them), and so is the profile; but pass 3's escape from (Z-10, X6) to (Z-9.5, X6.5) enters them."""
    zones = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "0", Z = "-50" }\nmax = { X = "30", Z = "30" }\n'
             '[[zones]]\nname = "jaws"\nkind = "box"\nforbid = true\nmin = { X = "6.25", Z = "-12" }\n'
             'max = { X = "6.75", Z = "-8" }\n')
    m = _lc(zones=zones)
    segs = list(interpret_text(STEP, m).segments())
    result = verify_segments(segs, m)
    assert result.verdict is Verdict.UNSAFE
    first = result.violations[0]
    assert first.derived == "G71 roughing pass 3: escape" and first.zone == "jaws"
    run = simulate(segs, m, mode="check")
    assert run.alarms and run.alarms[0].zone == "jaws" and run.alarms[0].line == 7
    assert segs[[s.derived for s in segs].index("G71 roughing pass 3: escape")].span.line == 7


CANON = CORPUS / "linuxcnc" / "tests" / "interp"
_MACHINE = machine_text("xz_fine_h2")


@pytest.mark.skipif(not CANON.is_dir(), reason="the external corpus is not here")
@pytest.mark.parametrize("test", ["g71-with-g70", "g72-facing", "g72-missing-iteration", "g71-endless-loop",
                                  "g71-endless-loop2"])
def test_moves_are_linuxcncs_own(test, monkeypatch):
    """Every STRAIGHT_TRAVERSE, STRAIGHT_FEED and ARC_FEED end point of LinuxCNC's canon log, in order, to its four
    decimals (these programs use no offsets: program and machine coordinates agree).

    The logs are those of LinuxCNC's repository, written by the versions that added these tests — after
    2.9.0~pre1 for g72-missing-iteration and the endless loops (commits 03793cc9, 48a3ee4a, 111fd213).  nczones
    follows the installed 2.9.0~pre1 and is unknown where the two differ; so the moves are checked with the later
    versions' rules (``later=True``), and without them the cycle is either the same or unknown for that reason."""
    import functools

    from nczones.gcode.linuxcnc import g7x

    folder = CANON / test
    plain = interpret_text(next(folder.glob("*.ngc")).read_text(), parse_machine(_MACHINE, "m.toml"))
    list(plain.segments())
    assert all("the later 2.9 versions" in u.reason for u in plain.unsupported), plain.unsupported
    monkeypatch.setattr(g7x, "g71", functools.partial(g7x.g71, later=True))
    folder = CANON / test
    program = next(folder.glob("*.ngc"))
    expected = []
    for line in (folder / "expected").read_text().splitlines():
        m = re.search(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\((.*)\)", line)
        if m:
            v = [float(t) for t in m.group(2).split(",")]
            kind = {"STRAIGHT_TRAVERSE": "RAPID", "STRAIGHT_FEED": "LINE", "ARC_FEED": "ARC"}[m.group(1)]
            expected.append((kind, v[1], v[0]) if kind == "ARC" else (kind, v[0], v[2]))  # (kind, X, Z)
    machine = parse_machine(_MACHINE, "m.toml")
    run = interpret_text(program.read_text(), machine, file=str(program))
    segs = list(run.segments())
    assert not run.unsupported, run.unsupported
    got = [(s.kind.name, float(s.end[0]), float(s.end[1])) for s in segs]
    assert len(got) == len(expected)
    for g, e in zip(got, expected):
        assert g[0] == e[0] and abs(g[1] - e[1]) <= 0.00005 + 1e-9 and abs(g[2] - e[2]) <= 0.00005 + 1e-9, (g, e)
    assert any("roughing pass" in s.derived for s in segs) or test == "g71-endless-loop2"


_G7X_LINE = re.compile(r"^[^;(\n]*G7[012](\.[12])?(?![\d.])", re.I | re.M)


@pytest.mark.skipif(not CANON.is_dir(), reason="the external corpus is not here")
def test_linuxcnc_corpus_programs_with_lathe_cycles(capsys):
    """Every LinuxCNC corpus program with G70-G72 is interpreted completely or unknown for a named reason (a G70
    under cutter compensation, a lathe tool orientation from the tool table: specs/turning.md); none is
    rejected, none ends in a traceback."""
    from tests.corpus import corpus_programs
    from tests.gcode.test_corpus_coverage import LINUXCNC_MACHINE

    outcomes = []
    for path, dialect in corpus_programs():
        program = CORPUS / path
        if not dialect.startswith("LinuxCNC") or not _G7X_LINE.search(program.read_text(errors="replace")):
            continue
        run = interpret_text(program.read_text(), LINUXCNC_MACHINE, file=path)
        n = len(list(run.segments()))
        outcomes.append((path, "unknown" if run.unsupported else "complete", n,
                         run.unsupported[0].reason if run.unsupported else ""))
    with capsys.disabled():
        print(f"\nLinuxCNC corpus programs with G70-G72: {len(outcomes)}, complete "
              f"{sum(o[1] == 'complete' for o in outcomes)}")
        for o in outcomes:
            print(f"  {o[1]:8} {o[0]}: {o[2]} segments {o[3][:100]}")
    assert len(outcomes) >= 9
    assert sum(o[1] == "complete" for o in outcomes) >= 4
    # G70 under cutter compensation; three cycles that the installed 2.9.0~pre1 cuts otherwise than the 2.9
    # versions after it (each matches rs274 2.9.0~pre1 motion for motion when the pre1 rules alone are taken:
    # tests/gcode/test_rs274_g7x.py); and endless-loop_2's G71, which 2.9.0~pre1 never ends (its bug #2939)
    later = "LinuxCNC 2.9.0~pre1 (the reference nczones follows) and the later 2.9 versions"
    expected = {
        "linuxcnc/nc_files/lathe_g70_71_demo.ngc": "G70 with cutter compensation on is not m",
        "linuxcnc/nc_files/lathe_g7x_quadrants.ngc": f"G71: {later}",
        "linuxcnc/tests/interp/g71-endless-loop/g71-endless-loop.ngc": f"G71.1: {later}",
        "linuxcnc/tests/interp/g72-missing-iteration/g72-iterations-missing.ngc": f"G72: {later}",
        "linuxcnc/tests/interp/g71-endless-loop_2/g71-endless-loop_2.ngc": "G71: LinuxCNC stops this cycle with an "}
    got = {o[0]: o[3] for o in outcomes if o[1] == "unknown"}
    assert got.keys() == expected.keys() and all(got[k].startswith(v) for k, v in expected.items()), got
