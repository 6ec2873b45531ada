"""Runs of drilling-cycle hole lines (G81/G82) on the fast path give exactly the full interpreter's segments.

The fast path takes the X/Y-only lines after a cycle's first block in
columns (``fastpath._fast_cycle_run``); everything else in a drilling
program (the cycle's first block, R/Z/P/F changes, G91, L repeats, G80, G0)
stays on the full interpreter.  These tests hold both paths to identical
segments (kinds, exact points, feeds, dwell times, ``derived`` names, lines,
blocks, tool lengths), identical errors and identical final interpreter state.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import fastpath, interpret_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from tests.machines import machine_text
from tests.sizes import examples

MACHINE = parse_machine(machine_text("mill_offsets_h1_h2"))


def _key(s):
    return (s.kind, s.start, s.end, s.block, s.line, s.tool_length, s.feed_mm_min, s.plane, s.clockwise,
            s.centre, s.radius, s.turns, s.dwell_s, s.derived)


def _state(run):
    it = run.interpreter
    return (tuple(it.pos), it.motion, it.cycle_r, it.cycle_cc, it.cycle_p, it.last_cycle, it.cycle_il,
            it.absolute, it.inch, it.feed, it.blocks, it.segment_count, dict(it.kind_counts), dict(it.assumed),
            [str(u) for u in run.unsupported])


def _outcome(text, fast, block_bytes=None):
    run = interpret_text(text, MACHINE, fast=fast)
    try:
        if fast and block_bytes is not None:
            segs = [_key(s) for c in fastpath.run_with_fastpath(run, block_bytes=block_bytes) for s in c.segments()]
        else:
            segs = [_key(s) for s in run.segments()]
    except GcodeError as exc:
        d = exc.diagnostics[0]
        return ("error", d.code, d.span.line if d.span else None), run.fast_lines
    return (segs, _state(run)), run.fast_lines


def _num(draw, lo=-99999, hi=99999):
    """A decimal literal with 0-4 decimals (written exactly)."""
    k = draw(st.integers(lo, hi))
    d = draw(st.integers(0, 4))
    a = abs(k)
    text = str(a // 10**d) + (f".{a % 10**d:0{d}d}" if d else "")
    return ("-" if k < 0 else "") + text


@st.composite
def drilling_programs(draw, long_runs=True):
    lines = [draw(st.sampled_from(["G21", "G20"])) + " G90 G17 " + draw(st.sampled_from(["G54", "G55"]))]
    if draw(st.booleans()):
        lines.append(draw(st.sampled_from(["G43 H1", "G43 H2"])))
    lines.append(f"G0 Z{draw(st.sampled_from(['1', '5', '20', '0.5']))}")
    lines.append(f"G0 X{_num(draw)} Y{_num(draw)}")
    n_number = draw(st.booleans())
    for _ in range(draw(st.integers(1, 3))):
        cyc = draw(st.sampled_from(["G81", "G82"]))
        ret = draw(st.sampled_from(["G98", "G99"]))
        r = draw(st.sampled_from(["2", "0.5", "3.125", "10"]))
        z = draw(st.sampled_from(["-3", "-0.75", "-12.5", "1"]))
        head = f"{ret} {cyc} X{_num(draw)} Y{_num(draw)} Z{z} R{r}"
        if cyc == "G82":
            head += f" P{draw(st.sampled_from(['0.5', '1', '0.25', '2.125']))}"
        if draw(st.booleans()):
            head += f" F{draw(st.sampled_from(['300', '150.5', '12']))}"
        else:
            lines.append("F250")
        lines.append(head)
        if long_runs and draw(st.booleans()):
            nholes = draw(st.integers(fastpath.MIN_RUN + 1, fastpath.MIN_RUN + 40))
        else:
            nholes = draw(st.integers(0, 12))
        for k in range(nholes):
            what = draw(st.sampled_from(["xy"] * 12 + ["x", "y", "comment", "blank", "n", "interrupt"]))
            if what == "xy":
                line = f"X{_num(draw)} Y{_num(draw)}"
            elif what == "x":
                line = f"X{_num(draw)}"
            elif what == "y":
                line = f"Y{_num(draw)}"
            elif what == "comment":
                line = draw(st.sampled_from(["(hole)", "; next", "X1 Y2 (a hole)"]))
            elif what == "blank":
                line = ""
            elif what == "n":
                line = f"N{10 * k + 5}"
            else:
                line = draw(st.sampled_from([
                    "G91 X1.5 Y-0.25", "G90", "X1 Y2 L2", "X3 Y4 R4", "X5 Z-4", "X2 Y2 F400",
                    "G80", "G80\nG82 X1 Y1 Z-2 R3 P1", "G0 X0 Y0", "G81 X1 Y1 R2 Z-1", "X7 Y7 P0.75", "G1 X1 Y1", "G82 X2 Y3 Z-2 R1 P1",
                    "Z-1", "R5", "G98", "G99 X1", "G91", "G90 X1 Y1", "G20", "G21",
                ]))
            if n_number and line and not line.startswith(("N", "(", ";")) and draw(st.booleans()):
                line = f"N{100 + k} {line}"
            lines.append(line)
        if draw(st.booleans()):
            lines.append("G80")
        lines.append(draw(st.sampled_from(["G0 Z25", "G90", "G0 X0 Y0", ""])))
    lines.append("M30")
    return "\n".join(lines) + "\n"


@settings(max_examples=80, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(drilling_programs())
def test_fast_path_equals_full_interpreter_on_drilling_programs(text):
    want, _ = _outcome(text, fast=False)
    got, _ = _outcome(text, fast=True)
    assert got == want, text


@settings(max_examples=25, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(drilling_programs(), st.integers(1, 400))
def test_drilling_runs_cut_at_any_block_size(text, k):
    want, _ = _outcome(text, fast=False)
    got, _ = _outcome(text, fast=True, block_bytes=k)
    assert got == want, (k, text)


def _long_program(cycle="G82 P0.5", retract="G99", n=500, inch=False):
    lines = ["G20" if inch else "G21", "G90 G17 G54", "G43 H2", "G0 Z20", "G0 X0 Y0",
             f"{retract} {cycle} X1 Y1 Z-3.5 R2 F300".replace("G82 P0.5 X1 Y1", "G82 X1 Y1 P0.5")]
    for i in range(n):
        lines.append(f"N{i + 10} X{i % 97 * 1.25:.2f} Y{i // 97 * 0.5 + 0.001 * (i % 7):.3f}")
    lines += ["G80", "G0 Z50", "M30"]
    return "\n".join(lines) + "\n"


def test_long_drilling_run_takes_the_fast_path():
    for cycle in ("G81", "G82 P0.5"):
        for retract in ("G98", "G99"):
            for inch in (False, True):
                text = _long_program(cycle, retract, inch=inch)
                (want, _), (got, fast_lines) = _outcome(text, fast=False), _outcome(text, fast=True)
                assert got == want
                assert fast_lines >= 500  # every hole line after the cycle's first block
                segs, state = got
                # position, feed, retract; G82: a dwell; G98 (clear level above R): a rapid to R
                per_hole = 3 + (cycle != "G81") + (retract == "G98")
                # G0 Z20, G0 X0 Y0, the holes (the first from Z20 under G99: a rapid to R), G0 Z50
                assert len(segs) == 2 + 501 * per_hole + (retract == "G99") + 1


def test_cycle_rows_carry_dwell_times_and_names():
    run = interpret_text(_long_program("G82 P0.5", "G99", n=100), MACHINE)
    rows = [s for c in run if c.scale is not None for s in c.segments()]
    assert run.fast_lines >= 100
    dwells = [s for s in rows if s.kind is SegmentKind.DWELL]
    assert len(dwells) == 100 and all(s.dwell_s == Fraction(1, 2) and s.derived == "G82 dwell" for s in dwells)
    # G99 after the first hole: the clear level is R, so no separate rapid to R
    assert {s.derived for s in rows if s.derived} == {"G82 position", "G82 feed", "G82 dwell", "G82 retract"}


def test_initial_level_below_r_goes_up_to_r_every_hole():
    text = "G21 G90 G17 G54\nG0 Z1\nG0 X0 Y0\nG98 G81 X1 Y1 Z-3 R2 F100\n" + "".join(
        f"X{i} Y{i}.5\n" for i in range(100)) + "G80\nM30\n"
    (want, _), (got, fast_lines) = _outcome(text, fast=False), _outcome(text, fast=True)
    assert got == want and fast_lines >= 100
    assert sum(1 for k in got[0] if k[-1] == "G81 up to R") == 101


CLAMP_MACHINE = parse_machine(machine_text("dogleg_mill_clamp"))


def assert_same_proof_with_and_without_fast_path(text: str, machine) -> None:
    """The prover's verdict and violations (line, zone, point) through ``verify`` (fast path on) equal
    those from the full interpreter's segments."""
    from nczones.prover import verify_segments, verify_text

    fast = verify_text(text, machine, max_violations=1000)
    full = verify_segments(iter(list(interpret_text(text, machine, fast=False).segments())), machine,
                           max_violations=1000)
    assert fast.verdict == full.verdict
    assert [(v.span.line, v.zone, v.point) for v in fast.violations] == [
        (v.span.line, v.zone, v.point) for v in full.violations]


@settings(max_examples=examples(6, 12), deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(["G81", "G82 P0.5"]), st.sampled_from(["G98", "G99"]), st.sampled_from([5, 20, 31, 40]),
       st.sampled_from([1, 10, 25]), st.sampled_from([100, 32, 60]), st.integers(0, 3), st.randoms(use_true_random=False))
def test_prover_verdicts_and_violations_agree_on_drilling_columns(cycle, retract, z, dr, start_z, places, rnd):
    """Holes around a clamp: the prover gives the same verdict and the same violations (line, zone,
    point) whether the hole lines come as column rows (rapids, feeds, dwells) or as segments."""

    lines = ["G21 G90 G17 G54 F300", f"G0 Z{start_z}", f"{cycle} X10 Y10 Z{z} R{z + dr}", retract]
    lines += [f"X{rnd.uniform(60, 200):.{places}f} Y{rnd.uniform(20, 220):.2f}" for _ in range(90)]
    text = "\n".join([*lines, "G80", "M30"]) + "\n"
    assert_same_proof_with_and_without_fast_path(text, CLAMP_MACHINE)
    run = interpret_text(text, CLAMP_MACHINE)
    sum(len(c) for c in run)
    assert run.fast_lines >= 88  # the hole lines did take the fast path
