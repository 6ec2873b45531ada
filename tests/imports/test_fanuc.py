"""Fanuc import: the punch format, increment systems, the stroke checks as zones."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import MachineImportError
from nczones.imports import detect_kind, import_text
from nczones.imports.fanuc import parse_listing
from nczones.imports.model import Collector

F = Fraction


def _axes(n: int, values) -> str:
    return "".join(f"A{k}P{v}" for k, v in zip(range(1, n + 1), values))


def _listing(*blocks: str) -> str:
    return "%\n" + "\n".join(blocks) + "\n%\n"


BASE = ("N01020" + _axes(3, (88, 89, 90)), "N01420" + _axes(3, (10000, 10000, 5000)), "N01401P00000010")


def test_bits_are_written_bit_seven_first():
    c = Collector()
    ps = parse_listing("p", "N01300P00000101\nN1006 A1 P00100000 A2 P00000001 ;\n", c)
    assert c.errors == []
    from nczones.imports.fanuc import _Listing

    ls = _Listing("p", ps, c)
    assert [ls.bit(1300, b)[0] for b in range(8)] == [True, False, True, False, False, False, False, False]
    assert ls.bit(1006, 5, 1)[0] and ls.bit(1006, 0, 2)[0] and not ls.bit(1006, 5, 2)[0]


def test_both_punch_formats_and_comments():
    old = "N01320A1P500000A2P400000A3P0"
    new = "N01320Q1A1P500.000A2P400.000A3P0.000; (STROKE 1 PLUS)"
    for block in (old, new):
        m = import_text(_listing(*BASE, block, "N01321" + _axes(3, ("-1000", "-1000", "-300000"))), "p.prm").machine
        assert m.allowed.bounding_box()["X"] == (F(-1), F(500))
    assert detect_kind(_listing(new)) == "fanuc"


@settings(max_examples=40, deadline=None)
@given(
    system=st.sampled_from([("00000001", F(1, 100)), ("00000000", F(1, 1000)), ("00000010", F(1, 10000)),
                            ("00000100", F(1, 100000)), ("00001000", F(1, 1000000))]),
    inch=st.booleans(),
    counts=st.lists(st.integers(-10**8 + 1, 10**8 - 1), min_size=2, max_size=2, unique=True),
)
def test_integer_lengths_count_the_least_command_increment(system, inch, counts):
    bits, metric = system
    unit = metric / 10 * F(254, 10) if inch else metric
    lo, hi = sorted(counts)
    if abs(hi * unit) > 10**6 or abs(lo * unit) > 10**6 or not lo <= 0 <= hi:
        return
    text = _listing("N01020A1P88", "N01001P0000000" + ("1" if inch else "0"), f"N01013A1P{bits}",
                    "N01420A1P1000", f"N01320A1P{hi}", f"N01321A1P{lo}")
    m = import_text(text, "p.prm").machine
    assert m.allowed.bounding_box()["X"] == (lo * unit, hi * unit)
    assert m.axis("X").rapid_mm_min == (F(100) * F(254, 10) if inch else 1000)  # 0.1 in/min on an inch machine


def test_stroke_check_two_inside_or_outside_and_three_inside():
    common = (*BASE, "N01320" + _axes(3, (1000000,) * 3), "N01321" + _axes(3, (-1000000,) * 3),
              "N01322" + _axes(3, (200000, 200000, 0)), "N01323" + _axes(3, (100000, 100000, -50000)),
              "N01324" + _axes(3, (-100000, -100000, 0)), "N01325" + _axes(3, (-200000, -200000, -10000)))
    inside = import_text(_listing(*common), "p.prm").machine
    outside = import_text(_listing(*common, "N01300P00000001", "N01240" + _axes(3, (150000, 150000, -20000))),
                          "p.prm").machine
    p = {"X": F(150), "Y": F(150), "Z": F(-20)}  # inside stroke check 2's box
    q = {"X": F(0), "Y": F(0), "Z": F(-20)}  # outside both
    r = {"X": F(-150), "Y": F(-150), "Z": F(-5)}  # inside stroke check 3's box
    assert (inside.allowed.contains(p), inside.allowed.contains(q), inside.allowed.contains(r)) == (False, True, False)
    assert (outside.allowed.contains(p), outside.allowed.contains(q), outside.allowed.contains(r)) == (True, False, False)
    # the forbidden area's boundary may be touched, as on the control
    assert inside.allowed.contains({"X": F(100), "Y": F(150), "Z": F(-20)})


def test_stroke_check_axes_switched_off_in_1310_are_free():
    text = _listing(*BASE, "N01310" + _axes(3, ("00000001", "00000001", "00000000")),
                    "N01322" + _axes(3, (200000, 200000, 0)), "N01323" + _axes(3, (100000, 100000, -50000)))
    m = import_text(text, "p.prm").machine
    (zone,) = m.zones
    assert zone.forbid and set(zone.axes) == {"X", "Y"}


def test_infinite_stroke_and_the_exlm_limits():
    text = _listing(*BASE, "N01300P00000100", "N01320" + _axes(3, (500000, -1, 0)), "N01321" + _axes(3, (0, 1, -100000)),
                    "N01326" + _axes(3, (400000, -1, 0)), "N01327" + _axes(3, (0, 1, -100000)))
    r = import_text(text, "p.prm")
    box = r.machine.allowed.bounding_box()
    assert box["X"] == (0, 400) and "Y" not in box  # Y: 1320 < 1321, no stored stroke check
    assert any("infinite" in n.message for n in r.notes)
    lms_off = import_text(text.replace("N01300P00000100", "N01300P00000000"), "p.prm").machine
    assert lms_off.allowed.bounding_box()["X"] == (0, 500)


def test_reference_positions_and_inch_input_and_g91():
    text = _listing(*BASE, "N00000P00000100", "N03402P00001000", "N01240" + _axes(3, (100000, 0, -5000)),
                    "N01241" + _axes(3, (0, 0, 0)), "N01320" + _axes(3, (200000,) * 3), "N01321" + _axes(3, (-200000,) * 3))
    r = import_text(text, "p.prm")
    assert r.machine.reference == (100, 0, -5)
    assert {"G20", "G91"} <= set(r.machine.modal)
    assert r.machine.dialect == "fanuc"
    assert dict(r.machine.fanuc.references) == {2: (0, 0, 0)}  # G30 P2


def test_the_fanuc_dialects_settings():
    text = _listing(*BASE, "N03401P00000000", "N01004P00000010", "N05114P2500", "N05101P00110000",
                    "N05400P00000000", "N06050P801", "N06080P88", "N06071P0", "N01320" + _axes(3, (200000,) * 3),
                    "N01321" + _axes(3, (-200000,) * 3))
    f = import_text(text, "p.prm").machine.fanuc
    assert (f.decimal_point_input, f.increment_system, f.g73_retract) == ("increment", "IS-C", F("0.25"))
    assert (f.boring_shift, f.scaling_unit, f.rotation_incremental) == ("-Y", F(1, 100000), False)
    assert dict(f.macros) == {"G801": (9010, "macro"), "M88": (9020, "macro")}


@pytest.mark.parametrize("blocks,code", [
    (("N01320A1P1", "N01420A1P10"), None),
    (("N01020A1P88A2P89", "N01420A1P10"), "IM107"),  # axis 2 has no rapid rate
    (("N01020A1P72", "N01420A1P10"), "IM105"),  # 'H' is no axis
    (("N01020A1P88", "N01420A1P10", "N01013A1P00000011"), "IM105"),
    (("N01020A1P88", "N01420A1P0"), "IM108"),
    (("N01020A1P88", "N01420A1P10", "N01820A1P99", "N01850A1P5"), "IM104"),
])
def test_refused_listings(blocks, code):
    if code is None:
        assert import_text(_listing(*blocks), "p.prm").machine.axis_names == ("X",)
        return
    with pytest.raises(MachineImportError) as e:
        import_text(_listing(*blocks), "p.prm")
    assert e.value.diagnostics[0].code == code
