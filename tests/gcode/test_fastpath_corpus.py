"""Fast path == full interpreter on the corpus (differential test).

``test_fast_equals_full`` is the differential test: on every program where
the fast path handled lines, the segments equal the full interpreter's
(everything but the span text and the H register number, which column chunks
do not carry).  Programs over :data:`DIFF_MAX_LINES` lines run only under
``-m long``.  The corpus outcome/coverage test is in
``tests/gcode/test_corpus_coverage.py``.
"""

from __future__ import annotations

import pytest

from nczones.errors import GcodeError
from nczones.gcode import interpret
from nczones.machine import parse_machine
from tests.corpus import CORPUS, corpus_programs

MANIFEST = CORPUS / "MANIFEST.tsv"
pytestmark = [pytest.mark.corpus, pytest.mark.skipif(not MANIFEST.is_file(), reason="corpus not available")]
DIFF_MAX_LINES = 1_500

_AXES = ["X", "Y", "Z", "A", "B", "C", "U", "V", "W"]
MACHINE = parse_machine(
    "[machine]\naxes = " + str(_AXES).replace("'", '"') + '\npulse = "0.0001"\n'
    + "[machine.rapid]\n" + "\n".join(f'{a} = "1000"' for a in _AXES) + "\n"
    + "[machine.reference]\n" + "\n".join(f'{a} = "0"' for a in _AXES) + "\n"
    + "[tool_lengths]\n" + "\n".join(f'H{i} = "0"' for i in range(1, 100)) + "\n"
)



def _segment_key(s):
    return (s.kind, s.start, s.end, s.axes, s.block, s.line, s.tool_length, s.feed_mm_min, s.plane,
            s.clockwise, s.centre, s.radius, s.turns, s.dwell_s, s.derived)


def _diff_cases(long: bool):
    out = []
    for rel, _ in corpus_programs():
        path = CORPUS / rel
        try:
            nlines = path.read_bytes().count(b"\n")
        except OSError:
            continue
        if (nlines > DIFF_MAX_LINES) == long:
            out.append(rel)
    return out


def _check_same(rel: str):
    path = CORPUS / rel
    fast = interpret(path, MACHINE)
    try:
        a = [_segment_key(s) for s in fast.segments()]
    except GcodeError as exc:
        a = ("error", exc.diagnostics[0].code, str(exc.diagnostics[0].span))
    if fast.fast_lines == 0:
        return None
    full = interpret(path, MACHINE, fast=False)
    try:
        b = [_segment_key(s) for s in full.segments()]
    except GcodeError as exc:
        b = ("error", exc.diagnostics[0].code, str(exc.diagnostics[0].span))
    assert a == b, rel
    assert [str(u) for u in fast.unsupported] == [str(u) for u in full.unsupported]
    return fast.fast_lines


def test_fast_equals_full(capsys):
    used = 0
    lines = 0
    for rel in _diff_cases(long=False):
        got = _check_same(rel)
        if got:
            used += 1
            lines += got
    with capsys.disabled():
        print(f"\nfast path used on {used} corpus programs ({lines} lines), identical to the full path")
    assert used >= 10


@pytest.mark.long
@pytest.mark.parametrize("rel", _diff_cases(long=True))
def test_fast_equals_full_large(rel):
    _check_same(rel)
