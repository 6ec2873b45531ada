"""The box route and the box run reader held to the independent reference reader (issue 36).

Plain Fanuc mill programs of more than 512 text lines (tests/gcode/fanuc/ref_plain.py: no ``#``, no call; straight
moves, R and I/J arcs and helices in three planes, G90/G91, offsets, G43, inch input, and lines that end a box run
in the middle) are proved by ``nczones/prover/fanucboxes.py`` from the exact box of their motion, read by
``nczones/gcode/fanuc/boxrun.py`` where it can.  tests/oracles/fanuc_ref.py reads the same text; its motion's exact
box (tests/gcode/fanuc/ref_boxes.py: arc extremes as exact surds, decided by angles, no nczones code) must be

* **inside** the box the route tests (``box_fits``, on a zone that holds everything) when the route decides:
  soundness — a route box that misses a point the reference reaches could prove a wrong ``safe``;
* tested at every tool length the reference's motions carry (a tip zone sees the position less it);
* and close to it (within ``1e-6`` mm per face: the route's box is the motion's box, rounded outward by a few
  ``1e-9`` only), so the comparison is not vacuous;
* the box of the whole motion is the same with the reader on and off (``boxrun.BOX_RUNS``);
* on a zone made from the reference's box (grown a little: it fits; one face moved inside the reference's
  extreme: it does not), the verdict is the full path's (``fanucboxes.ROUTE`` off: the vectorized fast path), and
  never ``safe`` when the reference's motion leaves the zone.

Programs under 512 lines of the reference differential's grammar (tests/gcode/fanuc/ref_grammar.py: Macro B,
calls, cycles; the route takes any Fanuc program that short) are held to the first two relations when the route
proves them ``safe`` (``FANUC_REF_BOX_SHORT``, default 60; long ``FANUC_REF_BOX_SHORT_LONG``, default 3,000).

CI size: ``FANUC_REF_BOX_EXAMPLES`` (default 6, both decimal point settings); the long profile (``-m long``):
``FANUC_REF_BOX_LONG`` (default 300), seed ``FANUC_REF_SEED``.  ``test_box_mutations_are_caught`` (long): a
deliberate break of ``columns.r_arc_box`` (the minor and the major arc's side swapped) and of the box run reader's
offset (a straight move's end without the work offset) each make this differential fail.
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode.fanuc import boxrun
from nczones.prover import fanucboxes
from tests.machines import box_zone
from tests.oracles.fanuc_ref import RefError, RefUnknown, reference_motion_with_circles

from .helpers import mill, probe_route
from .ref_boxes import reference_box
from .ref_differential import ref_machine
from .ref_grammar import fanuc_programs
from .ref_plain import plain_program

F = Fraction
EXAMPLES = int(os.environ.get("FANUC_REF_BOX_EXAMPLES", "6"))
LONG = int(os.environ.get("FANUC_REF_BOX_LONG", "300"))
SHORT = int(os.environ.get("FANUC_REF_BOX_SHORT", "60"))
SHORT_LONG = int(os.environ.get("FANUC_REF_BOX_SHORT_LONG", "3000"))
#: how far the route's box may lie outside the reference's (mm): its outward rounding is a few 1e-9
CLOSE = 1e-6
_AXES = ("X", "Y", "Z")
_WIDE = box_zone("wide", {a: "-5000" for a in _AXES}, {a: "5000" for a in _AXES})
_MILLS: dict = {}


def _mill(dpi: str, zone: str = _WIDE):
    key = (dpi, zone)
    if key not in _MILLS:
        if len(_MILLS) > 64:
            _MILLS.clear()
        _MILLS[key] = mill(f'decimal_point_input = "{dpi}"', tables=zone)
    return _MILLS[key]


def route_run(text: str, machine, *, runs: bool = True, route: bool = True) -> tuple:
    """``(result, boxes tested, lines the reader took)`` of ``verify`` on ``text`` (a G-code error raised); a box's
    ``lo`` and ``hi`` are the values of X, Y and Z."""
    result, tested, taken = probe_route(text, machine, "plain.nc", runs=runs, route=route)
    if isinstance(result, GcodeError):
        raise result
    return result, [(tuple(v for _a, v in lo), tuple(v for _a, v in hi), tl) for lo, hi, tl in tested], taken


def _decided(result) -> bool:
    return dict(result.stats).get("fanuc_boxes") == 1


def _micro(q: float, up: bool) -> Fraction:
    """``q`` rounded outward (up or down) to a multiple of 1e-6, with a float's slack."""
    n = q * 1_000_000
    k = int(n) + (1 if up else -1) * 2
    return F(k, 1_000_000)


def _dec(q: Fraction) -> str:
    """A multiple of 1e-6 as a decimal string."""
    n = q * 1_000_000
    assert n.denominator == 1
    sign = "-" if n < 0 else ""
    n = abs(n.numerator)
    return f"{sign}{n // 1_000_000}.{n % 1_000_000:06d}"


def check_program(seed: int, dpi: str, counts: dict, *, zones: bool, size: int = 540, one_run: bool = False) -> None:
    """One program (module docstring); ``counts`` collects the outcomes."""
    text = plain_program(seed, dpi, size, one_run=one_run)
    try:
        motion, circles, lengths = reference_motion_with_circles(text, ref_machine(dpi))
    except (RefUnknown, RefError) as exc:
        counts["ref_skip"] += 1
        counts.setdefault("ref_reasons", []).append(str(exc)[:80])
        return
    ref = reference_box(motion, circles, ref_machine(dpi).start)
    assert ref is not None, "an arc the reference box does not take (the generator writes none)"
    result, boxes, taken = route_run(text, _mill(dpi))
    counts["taken"] += taken
    if not _decided(result):
        counts["declined"] += 1
        return
    counts["decided"] += 1
    assert result.verdict.label == "safe"
    lo, hi, _tl = boxes[-1]
    # every tool length a motion carried is one the box was tested at (a tip zone sees the position less it)
    assert set(lengths) <= {tl for _lo, _hi, tl in boxes}, f"seed {seed} {dpi}: a tool length never tested"
    outside = ref.contained_in(list(lo), list(hi))
    assert not outside, f"the route's box misses the reference's motion (seed {seed}, {dpi}): {outside[:3]}"
    flo, fhi = ref.float_bounds()
    for i, a in enumerate(_AXES):
        assert float(lo[i]) >= flo[i] - CLOSE and float(hi[i]) <= fhi[i] + CLOSE, \
            f"seed {seed} {dpi} axis {a}: route {float(lo[i])}..{float(hi[i])} reference {flo[i]}..{fhi[i]}"
    lanes, lane_boxes, none = route_run(text, _mill(dpi), runs=False)
    assert none == 0 and _decided(lanes)
    # the whole motion's box (the boxes of the chunks before may differ: a straight move whose letters the lane
    # meets first is the general lane's segment, which the reader puts in its run's box)
    assert lane_boxes[-1] == boxes[-1], f"seed {seed} {dpi}: the box differs with the box run reader off"
    if zones:
        _check_zone(text, seed, dpi, ref, counts)


def _check_zone(text: str, seed: int, dpi: str, ref, counts: dict) -> None:
    """The verdict on a zone made from the reference's box: the full path's, and not ``safe`` when cut."""
    import random

    rnd = random.Random(seed)
    flo, fhi = ref.float_bounds()
    low = [_micro(v, False) - F(1, 1000) for v in flo]
    high = [_micro(v, True) + F(1, 1000) for v in fhi]
    # a face the reference's motion reaches beyond the start (machine zero: a zone must hold the start position)
    faces = [(i, up) for i in range(3) for up in (False, True) if (fhi[i] if up else -flo[i]) > 0.002]
    cut = bool(faces) and rnd.random() < 0.5
    if cut:  # that face inside the reference's extreme by 0.0005 mm
        i, up = rnd.choice(faces)
        if up:
            high[i] = _micro(fhi[i], False) - F(5, 10000)
        else:
            low[i] = _micro(flo[i], True) + F(5, 10000)
    zone = box_zone("fit", {a: _dec(low[i]) for i, a in enumerate(_AXES)},
                    {a: _dec(high[i]) for i, a in enumerate(_AXES)})
    machine = _mill(dpi, zone)
    inside = not ref.contained_in(low, high)
    assert inside != cut
    routed, _, _ = route_run(text, machine)
    full, _, _ = route_run(text, machine, route=False)
    label = routed.verdict.label
    assert label == full.verdict.label, f"seed {seed} {dpi}: route {label}, full path {full.verdict.label}"
    assert inside or label != "safe", f"a wrong safe: seed {seed} {dpi}, the reference leaves the zone"
    counts["zone_" + label] += 1


def _new_counts() -> dict:
    from collections import Counter

    return Counter()


def _differential(n: int, *, zones: bool, seed: int | None = None, size: int = 540, shrink: bool = True):
    counts = _new_counts()
    phases = tuple(Phase) if shrink else (Phase.generate,)

    @settings(max_examples=n, deadline=None, database=None, derandomize=seed is None, phases=phases,
              suppress_health_check=list(HealthCheck))
    @given(st.integers(0, 2**32 - 1), st.sampled_from(["calculator", "increment"]))
    def check(program_seed, dpi):
        try:
            check_program(program_seed, dpi, counts, zones=zones, size=size)
        except AssertionError as exc:
            counts.setdefault("failures", []).append(str(exc)[:300])
            raise

    if seed is not None:
        from hypothesis import seed as hseed
        check = hseed(seed)(check)
    return check, counts


def _not_vacuous(counts: dict, n: int) -> None:
    assert counts["decided"] >= 0.8 * n, dict(counts)
    assert counts["taken"] >= 100 * counts["decided"], dict(counts)


def test_the_box_route_holds_the_reference_motion():
    check, counts = _differential(EXAMPLES, zones=True)
    check()
    _not_vacuous(counts, EXAMPLES)


@pytest.mark.long
def test_the_box_route_holds_the_reference_motion_long():
    check, counts = _differential(LONG, zones=True, seed=int(os.environ.get("FANUC_REF_SEED", "36")))
    check()
    print(f"fanuc box route reference differential: {dict(counts)}")
    _not_vacuous(counts, LONG)


@pytest.mark.long
@pytest.mark.parametrize("seed", [1, 2])
def test_one_run_past_the_row_limit_holds_the_reference_motion(seed, monkeypatch):
    """A program of one run longer than ``columns.MAX_ROWS`` (8,192) lines the reader takes: the run's box is full
    and a new one opens in the middle (``BoxRows.full``), on the reader's side and the lanes'."""
    from nczones.gcode.fanuc.columns import MAX_ROWS

    full = []
    real = fanucboxes.BoxWalk._run

    def run(self, rows):
        full.append(rows.full)
        return real(self, rows)

    monkeypatch.setattr(fanucboxes.BoxWalk, "_run", run)
    counts = _new_counts()
    check_program(seed, "calculator", counts, zones=True, size=MAX_ROWS + 900, one_run=True)
    assert counts["decided"] == 1 and counts["taken"] > MAX_ROWS, dict(counts)
    assert any(full), "no run reached the row limit"


# ------------------------------------------------------------------------------------------- findings

_TIP_TABLE = (box_zone("room", {a: "-1000" for a in _AXES}, {a: "1000" for a in _AXES})
              + box_zone("table", {a: "-1000" for a in _AXES}, {"X": "1000", "Y": "1000", "Z": "-100"}, forbid=True)
              + 'point = "tip"\n')


@pytest.mark.parametrize("dwells", [0, 300])
def test_a_tool_length_taken_inside_the_box_is_tested(dwells):
    """Finding (refdiff36, a wrong ``safe``): the route tested the box again after a chunk only when the box or the
    set of tool lengths changed, but kept the walk's own set (which grows in place) as the one proved, so a chunk
    that added a tool length without widening the box was never tested at it.  Here the spindle stays at machine
    Z -50..0 throughout; before G43 the tip is the spindle (above the tip zone "table", Z below -100), after
    ``G43 H1`` (100 mm) the tip reaches Z -150.  With 300 dwells first (each a segment: the G43 moves come in a
    later chunk) the route answered ``safe``; the full path, and now the route, answer ``unsafe`` at both moves."""
    machine = mill(tables=_TIP_TABLE)
    text = ("O1\nG90 G21 G54 G00 X0. Y0. Z200.\nG01 Z150. F500.\n" + "G04 P1\n" * dwells
            + "G43 H1 Z50.\nG01 Z100.\nM30\n")
    lines = {4 + dwells, 5 + dwells}
    routed, _, _ = route_run(text, machine)
    full, _, _ = route_run(text, machine, route=False)
    for r in (routed, full):
        assert r.verdict.label == "unsafe"
        assert {v.span.line for v in r.violations if v.span is not None} == lines


# ------------------------------------------------------------------------------------------- mutations

def _mutate_r_arc_side(monkeypatch):
    """``columns.r_arc_box`` boxes the other arc of the circle through the ends (the minor and the major arc's side
    swapped: R negated with the direction, the same centre), in the lane (``BoxRows.add_arc``) and the reader."""
    from nczones.gcode.fanuc import columns

    real = columns.r_arc_box

    def broken(sa, sb, ea, eb, r, cw):
        return real(sa, sb, ea, eb, -r, not cw)

    monkeypatch.setattr(columns, "r_arc_box", broken)
    monkeypatch.setattr(boxrun, "r_arc_box", broken)


def _mutate_reader_offset(monkeypatch):
    """The box run reader widens the box by a straight move's end without the work offset (the program value; the
    position it keeps is right)."""

    def broken(line, words, p, lo, hi, off):
        for sl, m, i in words:
            v = int(line[sl]) * m
            p[i] = v + off[i]
            if v < lo[i]:
                lo[i] = v
            elif v > hi[i]:
                hi[i] = v

    monkeypatch.setattr(boxrun, "_straight", broken)


@pytest.mark.long
@pytest.mark.parametrize("mutation", [_mutate_r_arc_side, _mutate_reader_offset],
                         ids=["r-arc-box-side", "box-run-offset"])
def test_box_mutations_are_caught(monkeypatch, mutation):
    """Each mutation makes the CI-size differential (the same derandomized examples, no zones, no shrinking) fail."""
    mutation(monkeypatch)
    check, counts = _differential(EXAMPLES, zones=False, shrink=False)
    with pytest.raises(AssertionError):
        check()
        _not_vacuous(counts, EXAMPLES)
    print(f"{mutation.__name__}: {counts.get('failures', ['(the route no longer decides)'])[0]} {dict(counts)}")


# ------------------------------------------------------------------------------------------- short programs

def check_short(text: str, dpi: str, counts: dict) -> None:
    """A program of the reference differential's grammar (Macro B, calls, cycles: under 512 lines the route takes
    any Fanuc program): when the route proves it ``safe``, the reference's exact box lies inside the route's and
    every tool length it carries was tested.  Programs with a transform (the reference gives their arcs no
    circle) or that nczones does not read to the end are passed over (counted)."""
    try:
        motion, circles, lengths = reference_motion_with_circles(text, ref_machine(dpi))
    except (RefUnknown, RefError):
        counts["ref_skip"] += 1
        return
    ref = reference_box(motion, circles, ref_machine(dpi).start)
    if ref is None:
        counts["no_circle"] += 1
        return
    try:
        result, boxes, _ = route_run(text, _mill(dpi))
    except GcodeError:
        counts["rejected"] += 1
        return
    if not _decided(result) or result.verdict.label != "safe":
        counts["not_decided"] += 1
        return
    counts["decided"] += 1
    lo, hi, _tl = boxes[-1]
    outside = ref.contained_in(list(lo), list(hi))
    assert not outside, f"the route's box misses the reference's motion ({dpi}): {outside[:3]}\n{text}"
    assert set(lengths) <= {tl for _lo, _hi, tl in boxes}, f"a tool length never tested ({dpi})\n{text}"


def _short(n: int, seed: int | None = None):
    counts = _new_counts()

    @settings(max_examples=n, deadline=None, database=None, derandomize=seed is None,
              suppress_health_check=list(HealthCheck))
    @given(fanuc_programs(), st.sampled_from(["calculator", "increment"]))
    def check(text, dpi):
        check_short(text, dpi, counts)

    if seed is not None:
        from hypothesis import seed as hseed
        check = hseed(seed)(check)
    return check, counts


def test_the_box_route_holds_the_reference_motion_of_short_programs():
    check, counts = _short(SHORT)
    check()
    assert counts["decided"] >= 0.6 * SHORT, dict(counts)


@pytest.mark.long
def test_the_box_route_holds_the_reference_motion_of_short_programs_long():
    check, counts = _short(SHORT_LONG, seed=int(os.environ.get("FANUC_REF_SEED", "36")))
    check()
    print(f"fanuc box route, short programs: {dict(counts)}")
    assert counts["decided"] >= 0.6 * SHORT_LONG, dict(counts)
