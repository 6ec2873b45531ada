"""Where the time goes: ``--stats`` and the JSON report's ``stats.profile`` (issue 19)."""

import json
from pathlib import Path

from nczones.cli import main

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"


def _arcs_program(tmp_path: Path) -> Path:
    # a loop of arcs (decided one by one) and lines (screened), one arc leaving the travel box
    prog = tmp_path / "loop.ngc"
    prog.write_text("G21 G90 G54 G17\nG0 X10 Y10 Z10\n#1 = 0\no100 while [#1 LT 20]\n"
                    "G2 X30 Y10 I10 J0 F500\nG1 X10\n#1 = [#1 + 1]\no100 endwhile\n"
                    "G3 X-200 Y10 I-105 J0\nM2\n")
    return prog


def test_stats_in_text(tmp_path, capsys):
    code = main(["verify", str(_arcs_program(tmp_path)), "--machine", str(ROOT / "specs/machines/mill.toml"),
                 "--stats"])
    out = capsys.readouterr().out
    assert code == 1
    stats = [line for line in out.splitlines() if ": stats: " in line]
    assert len(stats) == 4, out
    assert " motions in " in stats[0] and "blocks" in stats[0]
    assert "time by tier: vectorized screen " in stats[1] and "solver " in stats[1] and " call" in stats[1]
    assert "arc 21 motions" in stats[2] or "arc 20 motions" in stats[2], stats[2]
    assert stats[3].startswith(str(tmp_path / "loop.ngc") + ": stats: slowest blocks: line ")


def test_stats_in_json(tmp_path, capsys):
    code = main(["verify", str(_arcs_program(tmp_path)), "--machine", str(ROOT / "specs/machines/mill.toml"),
                 "--format", "json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 1
    prof = doc["stats"]["profile"]
    assert set(prof["tiers"]) == {"screen_vectorized_s", "exact_per_motion_s", "solver_s",
                                  "interpretation_and_rest_s"}
    assert prof["motions"] >= 41 and prof["blocks"] >= prof["motions"]
    assert prof["kinds"]["arc"]["motions"] == 21 and prof["kinds"]["line"]["motions"] == 20
    assert prof["solver"]["calls"] == doc["stats"]["z3_queries"]
    slow = prof["slowest"]
    assert slow and all(x["line"] in (5, 9) for x in slow if x["kind"] == "arc")
    assert [x["seconds"] for x in slow] == sorted((x["seconds"] for x in slow), reverse=True)


def test_budget_option_is_checked(tmp_path, capsys):
    prog = EX / "programs" / "notch_over.ngc"
    machine = str(EX / ".." / "machines" / "grinder.toml")
    assert main(["verify", str(prog), "--machine", machine, "--budget", "0"]) == 2
    assert "VF109" in capsys.readouterr().err
    assert main(["verify", str(prog), "--machine", machine, "--budget", "none", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["budget_s"] is None
    assert main(["verify", str(prog), "--machine", machine, "--budget", "2.5", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["budget_s"] == 2.5 and doc["settings"]["budget_s"] == 2.5


def test_the_slowest_motions_are_the_slowest_however_many_are_decided():
    # the list of the slowest is a plain list until it holds `slowest` entries, then a heap (issue 36: heapq is
    # imported only then); either way it is the `slowest` largest times, slowest first
    from fractions import Fraction as F

    from nczones.motion import Segment, SegmentKind
    from nczones.prover.profile import RunProfile

    times = [0.3, 0.1, 0.7, 0.2, 0.9, 0.05, 0.6, 0.8, 0.4, 0.5]
    for n in (0, 3, 9):
        prof = RunProfile(slowest=3)
        for k, s in enumerate(times[:n]):
            prof.decided(Segment(SegmentKind.LINE, (F(0),), (F(1),), ("X",), block=k), s)
        expected = sorted(times[:n], reverse=True)[:3]
        assert [x["seconds"] for x in prof.slowest()] == expected
        assert [x["block"] for x in prof.slowest()] == [times.index(s) for s in expected]
