"""The vectorized fast path gives exactly the full interpreter's segments on generated programs.

The corpus differential (test_fastpath_corpus.py) covers real programs; this
one covers what nczones.testing generates: boundary-biased moves, arcs,
G90/G91 switches, work offsets, 3 axes with tool lengths, M98 subprograms.
"""

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.testing import machines, programs


def _run(text, machine, fast):
    run = interpret_text(text, machine, fast=fast)
    try:
        segs = [(s.kind, s.start, s.end, s.block, s.centre, s.clockwise, s.turns, s.line, s.tool_length)
                for chunk in run for s in chunk.segments()]
    except GcodeError as exc:
        d = exc.diagnostics[0]
        return "error", d.code, d.span.line if d.span else None
    return "ok", segs, run.status


@settings(max_examples=120, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(st.data())
def test_fast_path_equals_full_interpreter_on_generated_programs(data):
    axes = data.draw(st.sampled_from([("X", "Y"), ("X", "Y", "Z")]))
    machine = data.draw(machines(axes=axes))
    text = data.draw(programs(machine, max_blocks=12, subprograms=data.draw(st.booleans())))
    assert _run(text, machine, fast=True) == _run(text, machine, fast=False), text
