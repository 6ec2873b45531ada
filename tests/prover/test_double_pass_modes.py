"""``safe`` from the double pass with a tool change, dwells and path modes (issue 36) against the full path.

The pass takes T, M6, M61, G4, G61, G61.1 and G64 (nczones/gcode/linuxcnc/doubles.py); its proof
(nczones/prover/doubles.py) proves a blended corner only where the full path's corner check has one.  Each test
verifies a program both ways (``both_ways``: with the pass tried first, and without it) and asks for the same
outcome, and says which way proved it: a corner the full path cannot prove (VF208) is never ``safe`` by the
pass, a corner G61 or a dwell removes is proved by the pass (not declined), and a motion's extreme on a zone's
face is decided alike.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover.result import Verdict
from tests.machines import box_zone, machine_text
from tests.prover.test_double_pass_proof import both_ways, same_outcome

#: A forbidden block inside the corner at (10, 0): the programmed path (along Y = 0, then X = 10) misses it, the
#: region G64 may round the corner through (the box [5, 10] x [0, 5]) does not.
CLAMP = parse_machine(machine_text("box_5000", extra=box_zone("clamp", {"X": "8", "Y": "0.5"}, {"X": "9.5", "Y": "2"},
                                                              forbid=True)))
CORNER = "G21 G90 G17 G54 F500\nT1 M6\n#1 = 10\n{mode}G1 X[#1] Y0\n{pause}G1 X[#1] Y[#1]\nM30\n"


def _proved_by_the_pass(result) -> bool:
    return "double_pass_boxes" in dict(result.stats)


@pytest.mark.parametrize(("mode", "pause", "verdict", "by_pass"), [
    ("", "", Verdict.UNKNOWN, False),  # the machine starts in G64: the corner may enter the clamp (VF208)
    ("G61\n", "", Verdict.SAFE, True),  # exact stop: no corner
    ("G61.1\n", "", Verdict.SAFE, True),
    ("G61\nG64\n", "", Verdict.UNKNOWN, False),  # back to G64 before the motion
    ("G61\nG1 X1\nG64\n", "", Verdict.UNKNOWN, False),  # G64 set before the corner's first motion
    ("G64 G1 X1\nG61\n", "", Verdict.SAFE, True),  # G61 on the motion before the corner
    ("", "G4 P0.5\n", Verdict.SAFE, True),  # a dwell stops the machine at the corner
    ("", "G4 P[#1 / 20]\nG61\n", Verdict.SAFE, True),
    ("", "G61\n", Verdict.UNKNOWN, False),  # G61 after the corner's first motion: that motion blends
    # 14 motions first: the boxes split in pairs, the corner's first motion and a 1e-9 mm move after it in G61
    # share one (the boundary falls after the short move); LinuxCNC drops that move and joins the two motions
    # around it in the first one's mode, G64 (tests/contract/test_seam_hunt.py found the pass proving it safe)
    ("G1 X-20 Y0\nG1 X-10 Y0\n" * 7, "G61\nG1 X[#1 + 0.000000001] Y0\n", Verdict.UNKNOWN, False),
    ("G1 X-20 Y0\nG1 X-10 Y0\n" * 7, "G61\nG1 X[#1 + 0.000000001] Y0\nG4 P0.1\n", Verdict.SAFE, True),
])
def test_a_corner_is_blended_where_the_full_path_blends_it(monkeypatch, mode, pause, verdict, by_pass):
    text = CORNER.format(mode=mode, pause=pause)
    with_pass, without = both_ways(text, CLAMP, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is verdict
    assert _proved_by_the_pass(with_pass) is by_pass


#: An expression program of issue 36's class: a tool change, a dwell and an exact-stop mode.
TOOLED = ("G21 G90 G17 G54 F800\nT{t} M6\nS1000 M3\nG61\n#1 = 0\n#2 = 0\no1 while [#1 LT 30]\n"
          "G1 X[#1 * 3 + {x}] Y[#2 + 15.085]\nG4 P0.1\nG64 G1 Z[#1 - 2]\nG61.1\n#1 = [#1 + 1]\no1 endwhile\n"
          "M61 Q2\nM30\n")


@settings(max_examples=12, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(st.sampled_from(["0", "1", "7"]), st.sampled_from(["0", "12", "12.9", "13", "13.0000000001", "14"]),
       st.sampled_from(["100", "99.99999999", "100.0000000001"]))
def test_a_motions_extreme_on_a_face_is_decided_alike(monkeypatch, t, x, face):
    """The farthest motion ends at X = 87 + x (``#1 = 29``): on, just inside or just past the face X = 100 of
    the allowed box, or of a forbidden box beyond it; routed and full path agree, and the pass proves the
    programs whose boxes fit."""
    text = TOOLED.format(t=t, x=x)
    allowed = parse_machine(machine_text("box_5000").replace('max = { X = "5000"', f'max = {{ X = "{face}"'))
    forbid = parse_machine(machine_text("box_5000", extra=box_zone("wall", {"X": face}, {"X": "200"}, forbid=True)))
    for machine in (allowed, forbid):
        with_pass, without = both_ways(text, machine, monkeypatch, max_iterations=1000)
        same_outcome(with_pass, without)
        if with_pass.verdict is Verdict.SAFE and 87 + float(x) < float(face) - 1e-6:
            assert _proved_by_the_pass(with_pass)


def test_the_tool_change_program_is_proved_by_the_pass(monkeypatch):
    machine = parse_machine(machine_text("box_5000"))
    with_pass, without = both_ways(TOOLED.format(t="1", x="0"), machine, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE and _proved_by_the_pass(with_pass)
    assert with_pass.extra["counts"]["dwell"] == without.extra["counts"]["dwell"] == 30
    # the same on a machine whose M6 moves (TOOL_CHANGE_QUILL_UP): the full path's, with its tool change moves
    quill = parse_machine(machine_text("box_5000", set={"machine.tool_change_quill_up": True}))
    with_pass, without = both_ways(TOOLED.format(t="1", x="0"), quill, monkeypatch)
    same_outcome(with_pass, without)
    assert not _proved_by_the_pass(with_pass)


#: 1000 G91 steps of 0.1 mm in X: the exact end is X = 100, the controller's doubles end 1.4e-12 mm short of it.
CHAIN = ("G21 G90 G17 G54 F800\n#1 = 0\nG91\no1 while [#1 LT 1000]\nG1 X0.1\n#1 = [#1 + 1]\no1 endwhile\n"
         "G90 G1 X50\nM30\n")


@pytest.mark.parametrize(("face", "verdict", "by_pass"), [
    ("100", Verdict.SAFE, False),  # on the face: the pass's box crosses it, the full path proves it
    ("100.000000001", Verdict.SAFE, True),  # 1e-9 past the drift and the bound: the pass proves it
    ("99.9999999999999", Verdict.UNSAFE, False),  # the exact end is past the face, the doubles' end is not
])
def test_a_g91_chain_at_a_face_is_decided_alike(monkeypatch, face, verdict, by_pass):
    machine = parse_machine(machine_text("box_5000").replace('max = { X = "5000"', f'max = {{ X = "{face}"'))
    with_pass, without = both_ways(CHAIN, machine, monkeypatch, max_iterations=2000)
    same_outcome(with_pass, without)
    assert with_pass.verdict is verdict
    assert _proved_by_the_pass(with_pass) is by_pass
