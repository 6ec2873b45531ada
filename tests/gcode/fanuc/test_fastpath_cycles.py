"""Fanuc hole lines (G73, G74, G81-G86, G89) on the vectorized fast path give exactly the full interpreter's segments.

After a cycle's first block a Fanuc drilling program is mostly lines of X and Y words (CAM hole lists); the
fast path takes them in columns (``fastpath._fast_cycle_run`` with ``fastpath._fanuc_holes``, the template of
``FanucInterpreter._fanuc_cycle`` for such a block: a rapid at the current level, a rapid to R when that is not
R, G73/G83's pecks, the feed, a dwell, the retract to the initial level or R, or a feed out and a return).  Everything else (the cycle's first block, R,
Z, P, F, K changes, G91, G80, G98/G99, a G0, a line with a comment) stays on the full interpreter.  Both paths
must give identical segments (kinds, exact points, feeds, dwell times, ``derived`` names, lines, blocks, tool
lengths), identical errors and the same final state (position, cycle data, counts, the last N for #4114).
The test mill (tests/gcode/fanuc/helpers.py): G54 = (100, 50, -200), G55 = (300, 50, -200), H1 = 100.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import fastpath, interpret_text
from tests.gcode.fanuc.helpers import mill

MACHINE = mill()


def _key(s):
    return (s.kind, s.start, s.end, s.block, s.line, s.tool_length, s.feed_mm_min, s.plane, s.clockwise,
            s.centre, s.radius, s.turns, s.dwell_s, s.derived)


def _state(run):
    it = run.interpreter
    return (tuple(it.pos), it.cycle, dict(it.cycle_data), it.initial_level, it.retract_r, it.absolute, it.inch,
            it.feed, it.blocks, it.segment_count, dict(it.kind_counts), dict(it.assumed), dict(it.last),
            [str(u) for u in run.unsupported])


def _outcome(text, fast):
    run = interpret_text(text, MACHINE, fast=fast, file="t.nc")
    try:
        segs = [_key(s) for s in run.segments()]
    except GcodeError as exc:
        d = exc.diagnostics[0]
        return ("error", d.code, d.span.line if d.span else None), run.fast_lines
    return (segs, _state(run)), run.fast_lines


def _num(draw, lo=-99999, hi=99999):
    """A length with a decimal point and 0-3 decimals (IS-B)."""
    k = draw(st.integers(lo, hi))
    d = draw(st.integers(0, 3))
    a = abs(k)
    return ("-" if k < 0 else "") + str(a // 10**d) + "." + (f"{a % 10**d:0{d}d}" if d else "")


_INTERRUPTIONS = ["G91 X1.5 Y-0.25", "G90", "X1. Y2. K2", "X3. Y4. R4.", "X5. Z-4.", "X2. Y2. F400.", "G80",
                  "G80\nG82 X1. Y1. Z-2. R3. P1000", "G00 X0. Y0.", "G81 X1. Y1. R2. Z-1.", "X7. Y7. P750",
                  "G01 X1. Y1.", "Z-1.", "R5.", "G98", "G99 X1.", "G91", "G90 X1. Y1.", "M08", "X1 Y2",
                  "X1.2345 Y1.", "(HOLE)", "X4. Y4. (HOLE)", "G55", "G54"]


@st.composite
def drilling_programs(draw, long_runs=True):
    lines = ["O1000", draw(st.sampled_from(["G21", "G20"])) + " G90 G17 " + draw(st.sampled_from(["G54", "G55"]))]
    if draw(st.booleans()):
        lines.append("G43 H1 Z50.")
    lines.append(f"G00 Z{draw(st.sampled_from(['1.', '5.', '20.', '0.5', '2.']))}")
    lines.append(f"G00 X{_num(draw)} Y{_num(draw)}")
    numbered = draw(st.booleans())
    for _ in range(draw(st.integers(1, 3))):
        cyc = draw(st.sampled_from(["G81", "G82", "G73", "G83", "G85", "G89", "G84", "G74", "G86"]))
        r = draw(st.sampled_from(["2.", "0.5", "3.125", "10."]))
        z = draw(st.sampled_from(["-3.", "-0.75", "-12.5", "1."]))
        if cyc in ("G84", "G86"):
            lines.append("M03 S500")
        elif cyc == "G74":
            lines.append("M04 S500")
        head = f"{draw(st.sampled_from(['G98', 'G99']))} {cyc} X{_num(draw)} Y{_num(draw)} Z{z} R{r}"
        if cyc in ("G82", "G89", "G84", "G74") and draw(st.booleans()):
            head += f" P{draw(st.sampled_from(['500', '1000', '250', '0']))}"
        if cyc in ("G73", "G83") and draw(st.integers(0, 5)):
            head += f" Q{draw(st.sampled_from(['1.', '0.75', '2.5', '0.3']))}"
        if draw(st.booleans()):
            head += f" F{draw(st.sampled_from(['300.', '150.5', '12.']))}"
        else:
            lines.append("F250.")
        lines.append(head)
        nholes = draw(st.integers(fastpath.MIN_RUN + 1, fastpath.MIN_RUN + 40)) if long_runs and draw(
            st.booleans()) else draw(st.integers(0, 12))
        for k in range(nholes):
            what = draw(st.sampled_from(["xy"] * 14 + ["x", "y", "n", "interrupt"]))
            if what == "xy":
                line = f"X{_num(draw)} Y{_num(draw)}"
            elif what in ("x", "y"):
                line = f"{what.upper()}{_num(draw)}"
            elif what == "n":
                line = f"N{10 * k + 5}"
            else:
                line = draw(st.sampled_from(_INTERRUPTIONS))
            if numbered and not line.startswith(("N", "(")) and draw(st.booleans()):
                line = f"N{100 + k} {line}"
            lines.append(line)
        if draw(st.booleans()):
            lines.append("G80")
        lines.append(draw(st.sampled_from(["G00 Z25.", "G90", "G00 X0. Y0.", ""])))
    lines.append("M30")
    return "\n".join(lines) + "\n"


@settings(max_examples=60, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(drilling_programs())
def test_fast_path_equals_full_interpreter_on_fanuc_drilling(text):
    want, _ = _outcome(text, fast=False)
    got, _ = _outcome(text, fast=True)
    assert got == want, text


def _hole_list(cycle: str, retract: str, n: int = 600, z0: str = "20.", inch: bool = False) -> str:
    lines = ["O1000", f"{'G20' if inch else 'G21'} G90 G17 G54", "G43 H1 Z50.", f"G00 Z{z0}", "G00 X0. Y0.",
             f"{retract} {cycle} X1. Y1. Z-3.5 R2. F300."]
    lines += [f"N{i + 10} X{i % 97 * 1.25:.2f} Y{i // 97 * 0.5 + 0.001 * (i % 7):.3f}" for i in range(n)]
    return "\n".join(lines + ["G80", "G00 Z50.", "M30"]) + "\n"


_WORDS = {"G73": " Q1.5", "G83": " Q1.5", "G82": " P500", "G89": " P250", "G84": " P100", "G74": " P100"}
_SPINDLE = {"G84": "M03 S500\n", "G86": "M03 S500\n", "G74": "M04 S500\n"}


def test_a_hole_list_takes_the_fast_path():
    """Every hole line after the cycle's first block is the fast path's, for every cycle it takes (with its Q,
    P, spindle), G98/G99, an initial level above and below R, metric and inch; the segments and state are the
    full path's."""
    for cycle in ("G81", "G82", "G73", "G83", "G85", "G89", "G84", "G74", "G86"):
        for retract, z0, inch in (("G98", "20.", False), ("G99", "20.", False), ("G98", "1.", False),
                                  ("G99", "20.", True)):
            text = _hole_list(cycle, retract, n=100, z0=z0, inch=inch).replace(
                "F300.", _WORDS.get(cycle, "") + " F300.").replace(f"{retract} {cycle}",
                                                                   _SPINDLE.get(cycle, "") + f"{retract} {cycle}")
            (want, _), (got, fast_lines) = _outcome(text, fast=False), _outcome(text, fast=True)
            assert got == want, (cycle, retract, z0, inch)
            assert fast_lines >= 99, (cycle, retract, z0, inch)


def test_the_rows_carry_the_cycles_names_and_dwells():
    run = interpret_text(_hole_list("G82", "G98").replace("F300.", "P500 F300."), MACHINE, file="t.nc")
    rows = [s for c in run if c.scale is not None for s in c.segments()]
    assert len({s.line for s in rows}) >= 599
    assert {s.derived for s in rows if s.derived} == {"G82 position", "G82 to R", "G82 feed", "G82 dwell", "G82 retract"}
    assert all(s.dwell_s == 0.5 for s in rows if s.derived == "G82 dwell")


_ZONES = ('\n[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\n'
          'min = { X = "150", Y = "50", Z = "-1000" }\nmax = { X = "160", Y = "60", Z = "-204" }\n'
          '\n[[zones]]\nname = "roof"\nkind = "box"\nforbid = true\n'
          'min = { X = "110", Y = "45", Z = "{roof}" }\nmax = { X = "175", Y = "100", Z = "1000" }\n')


def test_prover_verdicts_agree_on_fanuc_hole_columns():
    """A hole list over a clamp (program X 50..60, Y 0..10, below Z -4: the feed of a hole there reaches it) and
    under a forbidden roof at, below or above the retract level (machine Z -179: EXT Z is 1): ``verify`` (rows as
    columns) gives the full path's verdict and violations (line, zone, point)."""
    from tests.gcode.test_fastpath_cycles import assert_same_proof_with_and_without_fast_path

    holes = "".join(f"X{20 + 3 * (i % 17)}. Y{(i // 17) * 5}.\n" for i in range(150))
    for roof, depth in (("-178.999", "-3.5"), ("-178.999", "-5.5"), ("-179", "-3.5"), ("-179.001", "-3.5")):
        machine = mill(tables=_ZONES.replace("{roof}", roof))
        text = (f"O1000\nG21 G90 G17 G54 G61\nG00 Z20.\nG00 X0. Y0.\nG98 G81 X1. Y1. Z{depth} R2. F300.\n" + holes
                + "G80\nM30\n")
        assert_same_proof_with_and_without_fast_path(text, machine)
