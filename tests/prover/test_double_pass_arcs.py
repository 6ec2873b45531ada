"""Arcs and G43 in the double pass (issue 36) against the full path's verdict, end to end through ``verify``.

Every verdict, violation, reason and note is the same with the pass tried first and without it
(:func:`tests.prover.test_double_pass_proof.both_ways`), on generated arc programs (I/J and R, both directions,
small and large radii, near half circles, whole circles, G43) against forbidden boxes, stepped tables and
polygons; on a zone face an arc's extreme touches exactly and one it crosses by less than the pass's rounding
bound; and on G43 lengths that decide a Z face.  Each fixed case runs short, with more than 512 motions (the
vectorized tier when the pass is off) and with ``#`` in the text.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import arc_programs
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import EXAMPLES, ZONES, both_ways, same_outcome

HEAD = machine_text("mill_g55_zones_head")
TOOLS = '[tool_lengths]\nH1 = "100"\n'


def machine_of(kind: str, a: int, b: int, extra: str = TOOLS):
    return parse_machine(HEAD + extra + ZONES[kind].format(a=a, b=b))


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(arc_programs(), st.sampled_from(sorted(ZONES)), st.integers(2, 150), st.integers(-50, 150),
       st.sampled_from(["0", "0", "0.5"]))
def test_arc_programs_get_the_full_paths_verdict(monkeypatch, text, kind, a, b, margin):
    machine = machine_of(kind, a, max(a + 1, b) if kind == "forbid" else b)
    try:
        with_pass, without = both_ways(text, machine, monkeypatch, margin=margin)
    except Exception as exc:  # noqa: BLE001  # a G-code error: the same error both ways
        with monkeypatch.context() as m:
            import nczones.pipeline.verification as verification

            m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
            from nczones.prover import verify_text

            with pytest.raises(type(exc)):
                verify_text(text, machine, margin=margin)
        return
    same_outcome(with_pass, without)


def _variants(lines: list[str]) -> dict[str, str]:
    """The program short, repeated past 512 motions, and with ``#`` in the text."""
    head = "G21 G90 G17 G54 F300\n"
    body = "\n".join(lines) + "\n"
    return {"short": head + body + "M30\n", "long": head + body * (520 // len(lines) + 1) + "M30\n",
            "hash": head + "#1 = 0\n" + body + "M30\n"}


def _face(xmax: str) -> object:
    """X <= ``xmax`` (else wide): the face the arcs' extreme X = 5 meets; exact stop (G61) at every corner,
    so that only the arcs meet the face (a rounded corner next to an arc is enclosed by the two motions'
    boxes, which reach the face: the full path answers unknown there, VF208)."""
    return parse_machine(machine_text("mill_g55_zones_head", set={"machine.path_mode": "G61"}) + '[[zones]]\nname = "travel"\nkind = "box"\n'
                         f'min = {{ X = "-1000", Y = "-1000", Z = "-1000" }}\nmax = {{ X = "{xmax}", Y = "1000", Z = "1000" }}\n')


# arcs about the origin of radius 5 that reach X = 5 at (5, 0)
FACE_ARCS = {
    "I/J": ["G1 X0 Y-5", "G3 X0 Y5 I0 J5", "G2 X0 Y-5 I0 J-5"],  # the +X half both ways (G2 back: cw from the top)
    "R": ["G1 X-3 Y-4", "G3 X-3 Y4 R-5", "G1 X-3 Y-4"],  # from (-3, -4) ccw to (-3, 4) the long way: through (5, 0)
}


@pytest.mark.parametrize("arcs", sorted(FACE_ARCS))
@pytest.mark.parametrize("variant", ["short", "long", "hash"])
def test_an_arc_that_touches_a_face_is_safe_and_one_over_it_by_less_than_the_rounding_is_not(monkeypatch, arcs,
                                                                                              variant):
    # The arc's exact extreme is X = 5 (centre (0, 0), radius 5: 3**2 + 4**2 = 5**2 for the R arc, whose
    # centre is to the right of its chord for G3 with R < 0, LinuxCNC arc_data_r): a face at X = 5 holds it
    # (safe); a face 1e-14 below it, far within the pass's rounding bound (64 * 5 * 2**-52 ~ 7e-14), does not:
    # the full path finds the crossing and the pass must not prove it.
    text = _variants(FACE_ARCS[arcs])[variant]
    with_pass, without = both_ways(text, _face("5"), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    with_pass, without = both_ways(text, _face("4.99999999999999"), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.UNSAFE
    with_pass, without = both_ways(text, _face("5.001"), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    if variant != "short":  # (a plain program below FAST_PATH_MIN_LINES lines is not given to the pass)
        assert "double_pass_boxes" in dict(with_pass.stats), "the pass proves it 0.001 away from the face"


@pytest.mark.parametrize("variant", ["short", "long", "hash"])
def test_g43_adds_the_machines_tool_length_on_z(monkeypatch, variant):
    # LinuxCNC G43 H1: the tool axis's machine coordinate is the program's plus the length of register 1 (100 in
    # [tool_lengths]); a face at Z = 150 holds Z40 + 100, not Z60 + 100; after G49 Z60 is 60
    zface = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             'max = { X = "1000", Y = "1000", Z = "150" }\n')
    machine = parse_machine(HEAD + TOOLS + zface)
    for lines, verdict in ((["G43 H1 G0 Z40", "G1 X1 Y1", "G1 X0 Y0"], Verdict.SAFE),
                           (["G43 H1 G0 Z60", "G1 X1 Y1", "G1 X0 Y0"], Verdict.UNSAFE),
                           (["G43 H1", "G49", "G0 Z60", "G1 X1 Y1", "G1 X0 Y0"], Verdict.SAFE)):
        with_pass, without = both_ways(_variants(lines)[variant], machine, monkeypatch)
        same_outcome(with_pass, without)
        assert with_pass.verdict is verdict, lines
    tip = machine_text("mill_g55_zones_head") + TOOLS + zface.replace('kind = "box"', 'kind = "box"\npoint = "tip"')
    with_pass, without = both_ways(_variants(["G43 H1 G0 Z60", "G1 X1"])[variant], parse_machine(tip), monkeypatch)
    same_outcome(with_pass, without)  # a tip zone: the pass declines G43, the full path decides
    assert "double_pass_boxes" not in dict(with_pass.stats)
