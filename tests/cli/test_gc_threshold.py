"""``nczones verify`` collects the youngest generation less often (``commands.verify.fewer_collections``)."""

from __future__ import annotations

import gc
from pathlib import Path

from nczones import cli
from nczones.commands.verify import GC_THRESHOLD, fewer_collections

MILL = Path(__file__).resolve().parents[2] / "specs" / "machines" / "mill.toml"


def test_the_first_threshold_is_raised_never_lowered_and_a_disabled_collector_stays_off():
    saved = gc.get_threshold()
    try:
        gc.set_threshold(700, 10, 10)
        fewer_collections()
        assert gc.get_threshold() == (GC_THRESHOLD, 10, 10)
        gc.set_threshold(GC_THRESHOLD * 5, 3, 4)
        fewer_collections()
        assert gc.get_threshold() == (GC_THRESHOLD * 5, 3, 4)
        gc.set_threshold(0, 10, 10)  # threshold 0: collection turned off, and it stays off
        fewer_collections()
        assert gc.get_threshold() == (0, 10, 10)
    finally:
        gc.set_threshold(*saved)


def test_the_verify_command_runs_with_the_raised_threshold(tmp_path, capsys):
    program = tmp_path / "p.ngc"
    program.write_text("G90 G21\nG1 X10 Y10 F100\nM2\n")
    saved = gc.get_threshold()
    try:
        gc.set_threshold(700, 10, 10)
        assert cli.main(["verify", str(program), "--machine", str(MILL), "--format", "json"]) == 0
        assert gc.get_threshold()[0] == GC_THRESHOLD
    finally:
        gc.set_threshold(*saved)
    assert '"verdict"' in capsys.readouterr().out
