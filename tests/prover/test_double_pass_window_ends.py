"""A window of the double pass that ends on a motion of length 0 (issue 36: the LinuxCNC call rows).

A zero-length motion is dropped by LinuxCNC's planner: the corner is then between the motions around it
(specs/path-modes.md §1), and a window that ends on one cannot prove that corner (the next window holds only
the motion after it).  The window proof used to stop the pass there, so a program whose every other motion
has length 0 (bench_fanuc's ``linuxcnc_call_program``: ``G0 X#1 Y#2`` then ``G1 Z-#3`` at the same depth, the
LinuxCNC equivalent of the Fanuc G65 row) went the full path, 5x slower, past one window (65,536 motions).
Now :class:`~nczones.prover.doubles.WindowProof` asks for the window again a motion later, and the pass
hands it over at the next motion that may end it (a window grows to twice its size at most, then declines).
"""

from __future__ import annotations

from fractions import Fraction

import pytest

import nczones.gcode.linuxcnc.doubles as doubles
import nczones.pipeline.verification as pipeline
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.prover.doubles import WindowProof
from nczones.prover.result import Verdict
from tests.prover.test_double_pass_proof import HEAD, ZONES, both_ways, machine_of, same_outcome


def call_program(n: int, out: int | None = None) -> str:
    """bench_fanuc.linuxcnc_call_program's shape, ``n`` calls: motions 2k - 1 (G0 to X k/10, Y k/20) and
    2k (G1 to Z-2: length 0 from the second call on).  Call ``out`` goes to X 500 instead."""
    x = "[#1 * 0.1]" if out is None else f"[#1 * 0.1 + 500 * [#1 EQ {out}]]"
    return "\n".join(["o9010 sub", "G0 X#1 Y#2", "G1 Z-#3", "o9010 endsub", "G90 G17 G21 G54 F300", "#1 = 0",
                      f"o100 while [#1 LT {n}]", f"o9010 call {x} [#1 * 0.05] [2]", "#1 = [#1 + 1]",
                      "o100 endwhile", "M30"]) + "\n"


@pytest.mark.parametrize("n", [20, 300])  # a short program, and one past the vectorized tier (> 512 motions)
@pytest.mark.parametrize("window", [8, 16])  # even: the first window ends on a G1 of length 0
def test_windows_ending_on_a_zero_length_motion_are_proved_by_the_pass(monkeypatch, n, window):
    # before: WindowProof returned False at the first window edge on a G1 Z-2 (length 0) and the full path ran
    monkeypatch.setattr(doubles, "WINDOW", window)
    machine = machine_of("box", 1000, 0)
    calls = []
    real = pipeline.interpretation
    monkeypatch.setattr(pipeline, "interpretation", lambda *a, **k: calls.append(1) or real(*a, **k))
    r = verify_text(call_program(n), machine)
    assert r.verdict is Verdict.SAFE and not calls  # proved by the pass, not handed to the full path
    stats = dict(r.stats)
    assert stats["segments"] == 2 * n and stats["double_pass_boxes"] >= 2 * n // (2 * window)
    _sure, without = both_ways(call_program(n), machine, monkeypatch)
    same_outcome(r, without)


@pytest.mark.parametrize("out", range(1, 12))
def test_a_motion_out_next_to_a_deferred_window_edge_is_found(monkeypatch, out):
    # |X| <= 100 allowed; call `out` moves to X 500 (motion 2 out - 1) and down at X 500 (2 out: length 0 or
    # not), the next call back: the exit meets the window edges (every 4 motions, deferred past zero lengths)
    # at every position.  The full path (the pass off) is the reference.
    monkeypatch.setattr(doubles, "WINDOW", 4)
    machine = machine_of("box", 100, 0)
    with_pass, without = both_ways(call_program(12, out), machine, monkeypatch)
    assert without.verdict is Verdict.UNSAFE
    same_outcome(with_pass, without)
    assert [v.point for v in with_pass.violations] == [v.point for v in without.violations]


def test_a_window_of_zero_length_motions_grows_to_twice_its_size_then_declines(monkeypatch):
    # every motion after the first has length 0: no motion may end a window; the pass declines when the window
    # holds twice its rows (memory stays bounded) and the full path decides, with the same verdict
    text = "G21 G90 G54 F500\n#1 = 0\no1 while [#1 LT 60]\nG1 X1 Y1\n#1 = [#1 + 1]\no1 endwhile\nM30\n"
    machine = machine_of("box", 100, 0)
    sizes = []
    proof = WindowProof(machine, Fraction(0))

    def on_window(path):
        sizes.append(path.motions - path.row0)
        return proof(path)

    with pytest.raises(Declined):
        double_pass(text, machine, max_iterations=1000, on_window=on_window, window=8)
    assert max(sizes) <= 2 * 9 and proof.windows == 0
    monkeypatch.setattr(doubles, "WINDOW", 8)
    with_pass, without = both_ways(text, machine, monkeypatch)
    assert with_pass.verdict is Verdict.SAFE and "double_pass_boxes" not in dict(with_pass.stats)
    same_outcome(with_pass, without)


def test_a_forbidden_box_crossed_after_a_zero_length_motion_at_a_window_edge(monkeypatch):
    # a forbidden clamp X in [0.25, 0.27], |Y| <= 5: no end point is in it; the G0 of the call with #1 = 3
    # goes from X 0.2 Y 0.1 to X 0.3 Y 0.15 and crosses it, right after a G1 of length 0
    machine = parse_machine(HEAD + ZONES["forbid"].format(a="0.25", b="0.27"))
    for window in (3, 4, 5):
        monkeypatch.setattr(doubles, "WINDOW", window)
        with_pass, without = both_ways(call_program(6), machine, monkeypatch)
        assert without.verdict is Verdict.UNSAFE
        same_outcome(with_pass, without)
        assert [v.point for v in with_pass.violations] == [v.point for v in without.violations]
