"""Grbl import: negative machine space, the homed position on the step grid, layouts, $# lines."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import MachineImportError
from nczones.exact import format_decimal
from nczones.imports import import_text
from nczones.testing import decimals

F = Fraction


def _dump(values: dict[int, object]) -> str:
    return "".join(f"${n}={v}\n" for n, v in sorted(values.items()))


def _grbl_homed_position(travel: F, pulloff: F, steps: F, inverted: bool) -> F:
    """Grbl 1.1's limits_go_home, in steps then back to mm (max_travel is stored negated)."""
    max_travel = -travel
    target = (max_travel + pulloff) if inverted else -pulloff
    scaled = target * steps
    n = math.floor(abs(scaled) + F(1, 2))  # lround: halves away from zero
    return F(n if scaled >= 0 else -n) / steps


@settings(max_examples=60, deadline=None)
@given(
    travel=st.lists(decimals(min_value=10, max_value=2000, places=3), min_size=3, max_size=3),
    steps=st.lists(st.sampled_from([F(80), F(250), F("87.489"), F(400), F("3.2"), F(1280)]), min_size=3, max_size=3),
    mask=st.integers(0, 7),
    pulloff=decimals(min_value=F(1, 2), max_value=5, places=3),  # more than a step, less than the travel
    soft=st.booleans(),
)
def test_negative_space_box_and_homed_position(travel, steps, mask, pulloff, soft):
    values = {20: int(soft), 22: 1, 23: mask, 27: format_decimal(pulloff)}
    for i in range(3):
        values[100 + i] = format_decimal(steps[i])
        values[110 + i] = "1000"
        values[130 + i] = format_decimal(travel[i])
    r = import_text(_dump(values), "dump.txt")
    m = r.machine
    box = m.allowed.bounding_box()
    for i, a in enumerate("XYZ"):
        assert box[a] == (-travel[i], F(0))
        expected = _grbl_homed_position(travel[i], pulloff, steps[i], bool(mask >> i & 1))
        start = m.start[i]
        # written exactly, or rounded to 1e-9 with a note when it is not a finite decimal
        assert abs(start - expected) <= F(1, 2 * 10**9)
        if start != expected:
            assert any(n.code == "IM202" and f"axis {a}" in n.message for n in r.notes)
    assert m.reference == (0, 0, 0)  # no $# output: machine zero, Grbl's default G28 position
    assert m.zones[0].name == ("soft limits" if soft else "travel")


def test_offsets_and_g28_from_hash_output_in_inches():
    text = _dump({13: 1, 22: 1, 100: 250, 101: 250, 102: 250, 110: 500, 111: 500, 112: 500,
                  130: 200, 131: 200, 132: 100})
    text += "[G54:-1.000,-2.000,-0.500]\n[G55:0.000,0.000,0.000]\n[G28:-7.000,-0.100,-0.010]\n[TLO:0.000]\nok\n"
    m = import_text(text, "dump.txt").machine
    assert m.offsets == {"G54": (F("-25.4"), F("-50.8"), F("-12.7"))}
    assert m.reference == (F("-177.8"), F("-2.54"), F("-0.254"))


def test_settings_are_mm_even_when_reports_are_inches():
    text = _dump({13: 1, 100: 250, 101: 250, 102: 250, 110: 500, 111: 500, 112: 500, 130: 200, 131: 200, 132: 100})
    assert import_text(text, "dump.txt").machine.allowed.bounding_box()["X"] == (F(-200), F(0))


def test_four_axis_fork_numbering_and_startup_modal():
    values = {100 + i: 100 for i in range(4)} | {110 + i: 600 for i in range(4)} | {130 + i: 90 for i in range(4)}
    text = _dump(values) + "$N0=G20 G91 M3\n$N1=\n"
    r = import_text(text, "dump.txt")
    assert r.machine.axis_names == ("X", "Y", "Z", "A")
    assert {"G20", "G91"} <= set(r.machine.modal)
    assert any("M3 not taken" in n.message for n in r.notes)


def test_legacy_layout_is_told_by_its_comments():
    text = ("$0=80.000 (x, step/mm)\n$1=80.000 (y, step/mm)\n$2=400.000 (z, step/mm)\n"
            "$3=500.000 (x max rate, mm/min)\n$4=500.000 (y max rate, mm/min)\n$5=300.000 (z max rate, mm/min)\n"
            "$9=300.000 (x max travel, mm)\n$10=200.000 (y max travel, mm)\n$11=50.000 (z max travel, mm)\n"
            "$25=1 (homing cycle, bool)\n$26=4 (homing dir invert mask:00000100)\n$30=1.000 (homing pull-off, mm)\n")
    m = import_text(text, "old.settings").machine
    assert m.allowed.bounding_box()["Y"] == (F(-200), F(0))
    assert m.start == (F(-1), F(-1), F(-49))  # Z homes towards minus: -travel + pull-off


def test_without_newer_settings_or_comments_the_layout_is_an_error():
    with pytest.raises(MachineImportError) as e:
        import_text("$0=10\n$9=100\n$10=100\n$11=100\n", "dump.txt", "grbl")
    assert [d.code for d in e.value.diagnostics] == ["IM107"]


def test_status_lines_and_banners_are_ignored_but_junk_is_not():
    base = _dump({100: 250, 110: 500, 130: 200})
    noisy = "Grbl 1.1h ['$' for help]\n>>> $$\n" + base + "ok\n<Idle|MPos:0.000,0.000,0.000|FS:0,0>\n[MSG:'$H'|'$X' to unlock]\n"
    assert import_text(noisy, "d.txt").machine.axis_names == ("X",)
    with pytest.raises(MachineImportError) as e:
        import_text(base + "hello\n", "d.txt", "grbl")
    assert e.value.diagnostics[0].code == "IM102" and e.value.diagnostics[0].span.line == 4


def test_pull_off_beyond_the_travel_is_refused_at_the_pull_off():
    with pytest.raises(MachineImportError) as e:
        import_text(_dump({22: 1, 27: 12, 100: 250, 110: 500, 130: 10}), "d.txt")
    d = e.value.diagnostics[0]
    assert d.code == "IM110" and d.span.text == "$27=12"
