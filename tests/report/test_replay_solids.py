"""``nczones replay`` of a tool solid in a fixture (issue 39, ``kind = "solid"``).

The example machine specs/machines/mill_solids.toml: the vise's jaw is the box X 100..250, Y 0..80, Z 0..60
(machine coordinates); tool 1 is cutter Ø10 × 25, shank Ø10 × 15, holder Ø63 × 60 (40..100 above the tip),
H1 = 100, so with the controlled point at machine Z ``z`` the holder spans Z ``z - 60 .. z``.  The replay puts
the part at the report's path point and checks that the witness is inside it and inside the fixture."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from nczones.machine import load_machine
from nczones.prover import verify
from nczones.prover.render import to_json_dict
from nczones.replay import ReplayError, replay_report

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"
GOLDEN = EX / "reports" / "holder_hits_vise.json"


def test_the_holder_example_replays_confirmed():
    r = subprocess.run([sys.executable, "-m", "nczones", "replay", str(GOLDEN)], capture_output=True, text=True,
                       cwd=ROOT)
    assert r.returncode == 0, r.stdout + r.stderr
    first = r.stdout.splitlines()[0]
    # line 6 (G1 Z10): the witness the report gives is X102.875 Y40 Z57.5 at the path point X80 Y40 Z115
    assert first == ("specs/examples/programs/holder_hits_vise.ngc:6: confirmed: the point X102.875 Y40 Z57.5 is "
                     "inside the holder (Ø63 × 60 at 40..100 above the tip) placed at the path point X80 Y40 Z115 "
                     "and inside fixture 'vise' (exact), and the path point lies on the line of block 4 exactly")
    assert r.stdout.splitlines()[-1] == "replay: 3 of 3 counterexamples confirmed"


@pytest.mark.parametrize("point, why", [
    # inside the holder (X 80 ± 31.5 = 48.5..111.5 at Y40), left of the jaw face X100: not in the vise
    ({"X": "99", "Y": "40", "Z": "115/2"}, "but not inside fixture 'vise'"),
    # inside the jaw, right of the holder's reach X111.5
    ({"X": "112", "Y": "40", "Z": "115/2"}, "is not inside the part 'holder'"),
    # inside the jaw and under the holder's axis, but below its bottom 115 - 60 = 55
    ({"X": "102", "Y": "40", "Z": "54"}, "is not inside the part 'holder'"),
])
def test_a_moved_witness_is_not_reproduced(point, why):
    # (the command's exit status for a check not reproduced, 1, is tested in tests/report/test_replay.py)
    doc = json.loads(GOLDEN.read_text())
    doc["violations"] = doc["violations"][:1]
    doc["violations"][0]["point_exact"] = point
    (check,) = replay_report(doc, base=str(ROOT))
    assert not check.confirmed and why in check.message, check.message


def test_a_path_point_off_the_motion_is_not_reproduced():
    doc = json.loads(GOLDEN.read_text())
    doc["violations"] = doc["violations"][:1]
    doc["violations"][0]["path_point_exact"] = {"X": "81", "Y": "40", "Z": "115"}  # line 6 runs at X80
    (check,) = replay_report(doc, base=str(ROOT))
    assert not check.confirmed and "is not on the line of block 4" in check.message


def test_an_arc_contact_replays(tmp_path):
    # a quarter arc about (60, -40) of radius 40 from (60, 0) to (100, -40) with the tip at Z10: the holder
    # (radius 31.5, Z 50..110 in machine coordinates) enters the jaw's corner near the arc's middle
    # (tests/prover/test_solids.py::test_arc_past_the_jaw_corner_is_decided_by_pieces)
    prog = tmp_path / "arc.ngc"
    prog.write_text("G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X60 Y0 Z100\nG1 Z10 F300\nG2 X100 Y-40 I0 J-40\n"
                    "G0 Z100\nM30\n")
    machine = load_machine(ROOT / "specs/machines/mill_solids.toml")
    doc = to_json_dict(verify(str(prog), machine))
    assert doc["verdict"] == "unsafe" and doc["violations"][0]["segment_kind"] == "arc"
    checks = replay_report(doc)
    assert checks and all(c.confirmed and c.exact for c in checks), [c.message for c in checks]


def test_malformed_solid_violations_are_input_errors():
    doc = json.loads(GOLDEN.read_text())
    doc["violations"][0]["zones"] = []
    with pytest.raises(ReplayError) as err:
        replay_report(doc, base=str(ROOT))
    assert err.value.code == "RP106"
    # a solid violation against a machine without solids (the grinder of notch_dip)
    doc = json.loads((EX / "reports" / "notch_dip.json").read_text())
    doc["violations"][0].update(kind="solid", zones=["holder"], point_exact={"X": "0", "Y": "0", "Z": "0"})
    with pytest.raises(ReplayError) as err:
        replay_report(doc, base=str(ROOT))
    assert err.value.code == "RP105"
