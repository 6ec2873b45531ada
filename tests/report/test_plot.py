"""nczones plot and the notebook function plot_program."""

import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from nczones.errors import InvalidArgument  # noqa: E402
from nczones.report import plot_program, relevant_planes  # noqa: E402

from .helpers import EX, MACHINES, run_example  # noqa: E402


def _gids(fig):
    ax = fig.axes[0]
    return {a.get_gid() for a in [*ax.collections, *ax.lines, *ax.patches] if a.get_gid()}


def test_plot_program_marks_violations_when_given_a_result():
    result, m = run_example("programs/drill_vise.ngc", "mill.toml")
    fig = plot_program(str(EX / "programs/drill_vise.ngc"), m, plane=("X", "Z"), result=result)
    gids = _gids(fig)
    assert {"counterexample", "first-exit", "violating-block-1", "allowed-set"} <= gids
    assert "forbid-vise" in gids  # the tip zone drawn where the spindle would be (tests/report/test_figure_zones.py)
    sc = next(c for c in fig.axes[0].collections if c.get_gid() == "counterexample")
    assert sc.get_offsets().tolist() == [[120.0, 240.0]]  # X120 Z240, machine coordinates
    assert fig.axes[0].get_xlabel() == "X (mm)" and fig.axes[0].get_ylabel() == "Z (mm)"
    plt.close(fig)
    fig = plot_program(str(EX / "programs/drill_vise.ngc"), m)  # no result: nothing marked
    assert "counterexample" not in _gids(fig) and "toolpath-rapid" in _gids(fig)
    plt.close(fig)


def test_bad_plane_is_an_error():
    _, m = run_example("programs/notch_dip.ngc", "grinder.toml")
    with pytest.raises(InvalidArgument, match="'Q' is not an axis"):
        plot_program(str(EX / "programs/notch_dip.ngc"), m, plane=("X", "Q"))


def test_relevant_planes_follow_the_zones():
    from nczones import load_machine

    assert relevant_planes(load_machine(MACHINES / "mill.toml")) == [("X", "Y"), ("X", "Z")]
    assert relevant_planes(load_machine(MACHINES / "lathe.toml"))[0] in (("X", "Z"), ("Z", "X"))


def test_cli_plot_writes_a_png(tmp_path):
    out = tmp_path / "dip.png"
    r = subprocess.run([sys.executable, "-m", "nczones", "plot", "programs/notch_dip.ngc", "--machine",
                        "../machines/grinder.toml", "-o", str(out)], capture_output=True, text=True, cwd=EX)
    assert r.returncode == 0, r.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and "unsafe, 1 violating block" in r.stdout
    bad = subprocess.run([sys.executable, "-m", "nczones", "plot", "programs/notch_dip.ngc", "--machine",
                          "../machines/grinder.toml", "-o", str(out), "--plane", "X,X"],
                         capture_output=True, text=True, cwd=EX)
    assert bad.returncode == 2 and "PL101" in bad.stderr and "Traceback" not in bad.stderr


def test_a_counterexample_in_a_generated_pass_highlights_that_pass_alone():
    """g71_jaws: the third roughing pass cuts into the jaws; the drawing's red curves are that pass's segments
    (infeed, cut, escape, return), not the cycle block's every pass."""
    from nczones.gcode import interpret
    from nczones.report.figure import collect_path, hot_passes, pass_name

    result, m = run_example("programs/g71_jaws.nc", "fanuc_lathe.toml")
    v = result.violations[0]
    assert pass_name(v.derived) == "G71 roughing pass 3"
    block_segs = [s for s in interpret(str(EX / "programs/g71_jaws.nc"), m).segments() if s.block == v.block]
    in_pass = [s for s in block_segs if pass_name(s.derived) == "G71 roughing pass 3"]
    assert 2 <= len(in_pass) < len(block_segs)
    narrowed = collect_path(str(EX / "programs/g71_jaws.nc"), m, {v.block}, passes=hot_passes(result.violations))
    whole = collect_path(str(EX / "programs/g71_jaws.nc"), m, {v.block})
    assert len(narrowed.hot_curves) == len(in_pass) and len(whole.hot_curves) == len(block_segs)
    assert narrowed.segments == whole.segments
