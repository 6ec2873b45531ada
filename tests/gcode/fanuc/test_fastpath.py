"""The vectorized fast path in the Fanuc dialect gives the full interpreter's segments, notes and errors."""

from __future__ import annotations

from dataclasses import replace

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.gcode.fastpath import MIN_RUN
from tests.sizes import examples

from .helpers import mill


def _run(text, machine, fast):
    run = interpret_text(text, machine, fast=fast)
    try:
        segs = [(s.kind, s.start, s.end, s.centre, s.clockwise, s.span.line if s.span else None, s.block)
                for s in run.segments()]
    except GcodeError as e:
        return ("error", e.diagnostics[0].code, e.diagnostics[0].span.line), run
    return (segs, run.status, run.notes()), run


_literal = st.one_of(
    st.integers(-500, 500).map(lambda n: f"{n}."),                      # a point, no decimals
    st.integers(-500000, 500000).map(lambda n: f"{n / 1000:.3f}"),      # three decimals
    st.integers(-5000000, 5000000).map(lambda n: f"{n / 10000:.4f}"),   # beyond the increment: rounded
    st.integers(-500, 500).map(str),                                     # no point: the DPI rule
    st.just("0"),
)


@st.composite
def fanuc_cam(draw):
    lines = ["%", "O1000 (CAM)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0."]
    for k in range(draw(st.integers(MIN_RUN, 2 * MIN_RUN + 20))):
        words = [f"{a}{draw(_literal)}" for a in draw(st.sets(st.sampled_from("XYZ"), min_size=1))]
        head = draw(st.sampled_from(["", "", "", "G01 ", "G00 ", "N%d " % (k + 1)]))
        tail = draw(st.sampled_from(["", "", " F500.", " ;", " (NOTE)"]))
        lines.append(head + " ".join(words) + tail)
    lines += ["M30", "%"]
    return "\n".join(lines) + "\n"


@settings(max_examples=examples(20, 40), deadline=None)
@given(fanuc_cam(), st.sampled_from(["calculator", "increment"]))
def test_fast_path_agrees_with_the_full_interpreter(text, dpi):
    m = mill()
    m = replace(m, fanuc=replace(m.fanuc, decimal_point_input=dpi))
    fast, run = _run(text, m, True)
    full, _ = _run(text, m, False)
    assert fast == full


def test_cam_runs_take_the_fast_path():
    body = "\n".join(f"X{i % 97}.{i % 10}5 Y-{i % 31}.25" for i in range(5 * MIN_RUN))
    text = "%\nO2000\nG00 G17 G40 G49 G80 G90\nG54 G01 F800.\n" + body + "\nM30\n%\n"
    run = interpret_text(text, mill())
    n = sum(len(chunk) for chunk in run)
    assert n == 5 * MIN_RUN and run.counts["fast_lines"] >= 4 * MIN_RUN
