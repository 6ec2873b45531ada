"""The double pass in windows (issue 36: no size cliff, flat memory).

The pass hands its motion to the prover in windows of ``WINDOW`` motions and drops them
(:func:`nczones.gcode.linuxcnc.doubles.double_pass` with ``on_window``), so no program is too long for it and its
memory is flat.  Here the window is made tiny so that short programs cross many window edges, and:

- the windows, put back together (each window's first row is the last motion's start, the overlap of one
  motion), are exactly the rows of the pass without windows, and each window's boxes are the boxes of the
  same motions without windows: the windowed proof checks the same boxes as the old one;
- ``verify`` with tiny windows has the full path's verdict, violations and witnesses (a motion that leaves
  the allowed set, or crosses a forbidden box, on every side of a window edge);
- a program of many windows is proved by the pass itself, not handed to the full path.
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.gcode.linuxcnc.doubles as doubles
import nczones.pipeline.verification as pipeline
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.prover import verify_text
from nczones.prover.doubles import WindowProof, prove_double_path
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import parametric_programs
from tests.prover.test_double_pass_proof import ZONES, both_ways, machine_of, same_outcome

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "15"))
SETTINGS = settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                           HealthCheck.function_scoped_fixture])


def windows_of(text: str, machine, window: int):
    """The windows the pass hands over (copies), and the path it returns."""
    got = []

    def keep(path):
        got.append((path.row0, path.motions, tuple(list(c) for c in path.columns), path.first_row))
        return True

    last = double_pass(text, machine, max_iterations=1000, on_window=keep, window=window)
    got.append((last.row0, last.motions, tuple(list(c) for c in last.columns), last.first_row))
    return got, last


@SETTINGS
@given(parametric_programs(), st.sampled_from(sorted(ZONES)), st.integers(1, 5))
def test_the_windows_are_the_rows_of_the_pass_without_windows(text, kind, window):
    machine = machine_of(kind, 100, 200)
    try:
        whole = double_pass(text, machine, max_iterations=1000)
    except Declined:
        with pytest.raises(Declined):
            windows_of(text, machine, window)
        return
    got, last = windows_of(text, machine, window)
    assert (last.motions, last.lines, last.rapids, last.blocks) == (whole.motions, whole.lines, whole.rapids,
                                                                    whole.blocks)
    assert last.first_row == whole.first_row
    for row0, motions, columns, _first in got:
        # each window holds rows row0..motions of the whole pass; full windows hold window + 1 rows
        assert [c[row0:motions + 1] for c in map(list, whole.columns)] == list(columns)
        assert motions - row0 <= max(window, 2)  # (a window of one motion: the overlap and the next motion)
    # consecutive windows overlap by one motion: the next starts at the row before the last one's last row
    for (_r0, m0, _c0, _f0), (r1, _m1, _c1, _f1) in zip(got, got[1:]):
        assert r1 == m0 - 1
    assert got[0][0] == 0 and got[-1][1] == whole.motions
    # and each motion's box, and each window's box, is the box of the same motions without windows
    windowed = double_pass(text, machine, max_iterations=1000, window=window,
                           on_window=lambda p: all(p.enclosure(k, k) == whole.enclosure(k, k)
                                                   for k in range(p.row0 + 1, p.motions + 1))
                           and (p.motions == p.row0 or p.enclosure(p.row0 + 1, p.motions)
                                == whole.enclosure(p.row0 + 1, p.motions)))
    assert windowed.motions == whole.motions


@SETTINGS
@given(parametric_programs(), st.sampled_from(sorted(ZONES)), st.integers(2, 700), st.integers(-50, 700),
       st.sampled_from(["0", "0.5", "3"]), st.integers(1, 4))
def test_tiny_windows_give_the_full_paths_verdict(monkeypatch, text, kind, a, b, margin, window):
    machine = machine_of(kind, a, max(a + 1, b) if kind == "forbid" else b)
    monkeypatch.setattr(doubles, "WINDOW", window)
    try:
        with_pass, without = both_ways(text, machine, monkeypatch, margin=margin, max_iterations=1000)
    except Exception:  # noqa: BLE001  # a G-code error: tests/prover/test_double_pass_proof.py holds it the same
        return
    same_outcome(with_pass, without)
    assert [v.point for v in with_pass.violations] == [v.point for v in without.violations]


def line_program(n: int, out: int | None, y: str = "0") -> str:
    """``n`` motions along X (motion k to X = k), motion ``out`` instead to X = 500 (and back after it)."""
    parts = ["G21 G90 G54 F500 G1", "#1 = 1", f"o1 while [#1 LE {n}]"]
    if out is None:
        parts.append(f"G1 X#1 Y{y}")
    else:
        parts += [f"o2 if [#1 EQ {out}]", f"G1 X500 Y{y}", "o2 else", f"G1 X#1 Y{y}", "o2 endif"]
    parts += ["#1 = [#1 + 1]", "o1 endwhile", "M30"]
    return "\n".join(parts) + "\n"


@pytest.mark.parametrize("out", range(1, 12))
def test_a_motion_that_leaves_on_either_side_of_a_window_edge_is_found(monkeypatch, out):
    # the box machine allows |X| <= 100: motion `out` goes to X = 500 and motion out + 1 comes back, so
    # both leave; with windows of 4 motions (edges after motions 4, 7, 10: the overlap) every position of
    # the exit meets an edge somewhere.  The full path (the pass off) is the reference: UNSAFE at that line.
    monkeypatch.setattr(doubles, "WINDOW", 4)
    machine = machine_of("box", 100, 0)
    with_pass, without = both_ways(line_program(12, out), machine, monkeypatch)
    assert without.verdict is Verdict.UNSAFE
    same_outcome(with_pass, without)
    assert [v.point for v in with_pass.violations] == [v.point for v in without.violations]
    assert "double_pass_boxes" not in dict(with_pass.stats)


@pytest.mark.parametrize("clamp", range(1, 12))
def test_a_motion_across_a_forbidden_box_at_a_window_edge_is_found(monkeypatch, clamp):
    # a forbidden box X in [clamp + 0.25, clamp + 0.75], |Y| <= 5: no end point is in it, only motion
    # clamp + 1 (from X = clamp to X = clamp + 1 at Y = 0) crosses it; windows of 3 motions
    monkeypatch.setattr(doubles, "WINDOW", 3)
    from nczones.machine import parse_machine
    from tests.prover.test_double_pass_proof import HEAD

    machine = parse_machine(HEAD + ZONES["forbid"].format(a=f"{clamp}.25", b=f"{clamp}.75"))
    with_pass, without = both_ways(line_program(12, None), machine, monkeypatch)
    assert without.verdict is Verdict.UNSAFE
    same_outcome(with_pass, without)
    assert [v.point for v in with_pass.violations] == [v.point for v in without.violations]


@pytest.mark.parametrize("n", [40, 600])  # a short program, and one past the vectorized tier (> 512 motions)
def test_a_program_of_many_windows_is_proved_by_the_pass(monkeypatch, n):
    monkeypatch.setattr(doubles, "WINDOW", 16)
    machine = machine_of("box", 1000, 0)
    calls = []
    real = pipeline.interpretation
    monkeypatch.setattr(pipeline, "interpretation", lambda *a, **k: calls.append(1) or real(*a, **k))
    r = verify_text(line_program(n, None), machine)
    assert r.verdict is Verdict.SAFE
    assert not calls  # not handed to the full path
    stats = dict(r.stats)
    assert stats["segments"] == n and stats["double_pass_boxes"] >= n // 15  # one box per window at least
    _sure, without = both_ways(line_program(n, None), machine, monkeypatch)
    same_outcome(r, without)


def test_a_window_whose_boxes_do_not_fit_stops_the_pass():
    machine = machine_of("box", 100, 0)
    proof = WindowProof(machine, Fraction(0))
    with pytest.raises(Declined):
        double_pass(line_program(30, 20), machine, max_iterations=1000, on_window=proof, window=8)
    assert proof.windows == 2  # motions 1..8 and 8..15 were proved; the window of motion 20 was not
    proof = WindowProof(machine, Fraction(0))
    last = double_pass(line_program(30, None), machine, max_iterations=1000, on_window=proof, window=8)
    r = prove_double_path(last, machine, Fraction(0), None, proof)
    assert r is not None and r.verdict is Verdict.SAFE and proof.windows == 4  # 1..8, 8..15, 15..22, 22..29
    assert dict(r.stats)["double_pass_boxes"] == proof.boxes + 1  # the last window, 29..30, one box


@SETTINGS
@given(parametric_programs(), st.integers(1, 40))
def test_the_text_read_in_small_pieces_is_the_same_pass(monkeypatch, text, piece):
    # the pass splits the text into lines a piece of PIECE characters at a time (flat memory); in pieces of
    # a few characters every loop and branch jumps across pieces: the rows are those of one piece
    machine = machine_of("box", 100, 0)
    try:
        whole = double_pass(text, machine, max_iterations=1000)
    except Declined as exc:
        monkeypatch.setattr(doubles, "PIECE", piece)
        with pytest.raises(Declined) as again:
            double_pass(text, machine, max_iterations=1000)
        assert again.value.reason == exc.reason
        return
    monkeypatch.setattr(doubles, "PIECE", piece)
    small = double_pass(text, machine, max_iterations=1000)
    assert [list(c) for c in small.columns] == [list(c) for c in whole.columns]
    assert (small.motions, small.blocks, small.rapids, small.first_row) == (whole.motions, whole.blocks,
                                                                            whole.rapids, whole.first_row)
