"""The loader at scale: what made it fast must not change what it accepts or reports.

* The simple-polygon check (a sweep over edges whose boxes overlap, exact in
  integers) gives the all-pairs check's answer, message included, on random
  small polygons full of touching, overlapping and crossing edges, on large
  coordinates (Python integers instead of ``int64``) and on mixed decimals:
  both of its sweeps, the Python one (few candidate pairs) and numpy's.
* Decimal text read on the fast path gives the ``Decimal`` path's value and
  diagnostics.
* Diagnostics in a long stepped table still point at the region's line.
"""

from __future__ import annotations

import decimal
from fractions import Fraction as F

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from nczones import machine
from nczones.errors import MachineFileError
from nczones.machine import (
    _Reader,
    _segments_intersect,
    parse_machine,
    polygon_problem,
    read_number,
)


def all_pairs_problem(vertices):
    """The reference: every pair of edges, exactly (the loader's rule before the sweep)."""
    from nczones.machine import _orient

    n = len(vertices)
    for i in range(n):
        if vertices[i] == vertices[(i + 1) % n]:
            return f"vertices {i + 1} and {(i + 1) % n + 1} are the same point"
    if all(_orient(vertices[0], vertices[1], v) == 0 for v in vertices[2:]):
        return "the vertices lie on one line and enclose no area"
    edges = [(vertices[i], vertices[(i + 1) % n]) for i in range(n)]
    for i in range(n):
        for j in range(i + 1, n):
            adjacent = j == i + 1 or (i == 0 and j == n - 1)
            if _segments_intersect(*edges[i], *edges[j], adjacent):
                return (f"edge {i + 1} (vertex {i + 1} to {(i + 1) % n + 1}) and edge {j + 1} "
                        f"(vertex {j + 1} to {(j + 1) % n + 1}) cross or overlap; "
                        "the polygon must not intersect itself")
    return None


coords = st.builds(F, st.integers(-3, 3), st.sampled_from([1, 2, 10]))


def both_sweeps(vertices):
    """``polygon_problem`` by the Python sweep and by numpy's (:data:`nczones.machine.PYTHON_PAIRS` set so)."""
    keep = machine.PYTHON_PAIRS
    try:
        machine.PYTHON_PAIRS = 10**9
        by_python = polygon_problem(vertices)
        machine.PYTHON_PAIRS = -(10**9)  # no pair allowed: numpy's
        by_numpy = polygon_problem(vertices)
    finally:
        machine.PYTHON_PAIRS = keep
    return by_python, by_numpy


@settings(max_examples=600, deadline=None)
@given(st.lists(st.tuples(coords, coords), min_size=3, max_size=9))
def test_sweep_agrees_with_all_pairs(vertices):
    want = all_pairs_problem(vertices)
    assert both_sweeps(vertices) == (want, want)


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 4), st.integers(0, 4)), min_size=3, max_size=8),
       st.sampled_from([F(10**12), F(1, 10**25), F(3, 8)]))
def test_sweep_agrees_on_large_and_fine_coordinates(points, unit):
    vertices = [(x * unit + F(10**5), y * unit) for x, y in points]  # 10**12 units: Python integers
    want = all_pairs_problem(vertices)
    assert both_sweeps(vertices) == (want, want)


def test_sweep_names_the_first_pair_of_many():
    # a comb whose teeth all cross one long edge: the first crossing pair in vertex order is named
    teeth = []
    for k in range(40):
        teeth += [(F(2 * k), F(0)), (F(2 * k), F(10)), (F(2 * k + 1), F(10)), (F(2 * k + 1), F(0))]
    vertices = [*teeth, (F(79), F(-5)), (F(0), F(5))]
    want = all_pairs_problem(vertices)
    assert want is not None
    assert both_sweeps(vertices) == (want, want)
    assert polygon_problem(vertices) == want


def test_an_outline_is_checked_without_numpy():
    # a 200-vertex outline has a few candidate pairs an edge: the Python sweep decides it and numpy is not
    # imported (tests/cli/test_startup.py); a zigzag whose 300 edges all overlap in X: numpy's sweep
    import subprocess
    import sys

    code = """import math, sys
from fractions import Fraction as F
from nczones.machine import polygon_problem
outline = [(F(round(100 * math.cos(2 * math.pi * i / 200) * 10**4), 10**4),
            F(round(100 * math.sin(2 * math.pi * i / 200) * 10**4), 10**4)) for i in range(200)]
zigzag = [(F(100 * (k % 2)), F(k)) for k in range(300)] + [(F(-1), F(299)), (F(-1), F(0))]
print(polygon_problem(outline), 'numpy' in sys.modules, polygon_problem(zigzag), 'numpy' in sys.modules)
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["None", "False", "None", "True"]


texts = st.one_of(
    st.from_regex(r"[+-]?[0-9]{1,12}(\.[0-9]{0,32})?", fullmatch=True),
    st.sampled_from(["0", "-0", "+0.0", "1000000", "1000000.0000001", "-1000000", "0.000", "12."]),
)


@settings(max_examples=400, deadline=None)
@given(texts, st.sampled_from([{}, {"positive": True}, {"nonnegative": True}, {"limit": F(10**9)}]))
def test_fast_decimal_text_agrees_with_decimal(text, flags):
    fast, slow = _Reader("m", ""), _Reader("m", "")
    got = read_number(fast, text, "v", None, **flags)
    want = read_number(slow, decimal.Decimal(text), "v", None, **flags)
    assert got == want
    assert [d.code for d in fast.diagnostics] == [d.code for d in slow.diagnostics]


def test_region_diagnostics_point_at_their_lines():
    rows = [f'  {{upto = "{i + 1}", max = "5"}},' for i in range(3000)]
    rows[2500] = '  {upto = "2501", min = "7", max = "5"},'
    text = ('[machine]\naxes = ["X", "Y"]\n[machine.rapid]\nX = "1"\nY = "1"\n[machine.reference]\nX = "0"\nY = "0"\n'
            '[[zones]]\nname = "t"\nkind = "stepped"\nreference_axis = "X"\nlimited_axis = "Y"\nfrom = "0"\n'
            'regions = [\n' + "\n".join(rows) + "\n]\n")
    with pytest.raises(MachineFileError) as err:
        parse_machine(text, "m.toml")
    (d,) = err.value.diagnostics
    assert d.code == "ZN122" and "region 2501" in d.message
    assert d.span is not None and d.span.line == 15 + 2501 and d.span.text.strip().startswith('{upto = "2501", min')


# --------------------------------------------------------------------------- a table's regions in the common form

_region_numbers = st.one_of(
    st.sampled_from(["0", "-0", "1", "2", "2.0", "-1", "5", "10", "10.5", "1000000", "1000000.0000001", "-1000000.5",
                     "12.", "+3", "1e3", " 1", "1_0", "inf", "", "٣", "0.1000000000000000000000000000001"]),
    st.from_regex(r"-?[0-9]{1,3}(\.[0-9]{0,3})?", fullmatch=True),
    st.integers(-3, 20).map(str),
)


@st.composite
def region_rows(draw) -> list[str]:
    """Inline tables of a table's regions, mostly well formed (increasing uptos, min <= max), with the odd
    number, key, order or unquoted value that the readers must report alike."""
    rows = []
    upto = 0
    for _ in range(draw(st.integers(1, 6))):
        upto += draw(st.integers(0, 3))
        parts = [f'upto = "{draw(_region_numbers) if draw(st.integers(0, 9)) == 0 else upto}"']
        lo = draw(st.none() | st.integers(-5, 5))
        hi = draw(st.none() | st.integers(-5, 5))
        if lo is not None:
            parts.append(f'min = "{draw(_region_numbers) if draw(st.integers(0, 9)) == 0 else lo}"')
        if hi is not None:
            parts.append(f'max = "{draw(_region_numbers) if draw(st.integers(0, 9)) == 0 else hi}"')
        odd = draw(st.integers(0, 19))
        if odd == 0:
            parts.append('mni = "1"')
        elif odd == 1:
            parts = parts[1:]
        elif odd == 2:
            parts = [p.replace('"', "") for p in parts]  # TOML numbers: Decimal and int values
        elif odd == 3:
            parts.reverse()
        elif odd == 5:
            parts.append('min = ["1"]' if lo is None else 'max = { a = "1" }')
        elif odd == 6:
            parts[0] = f'upto = "{upto}\\n{upto + 1}"'  # a TOML escape: a newline in the text
        elif odd == 7:
            parts.append("max = true" if hi is None else "min = 2")
        rows.append("{ " + ", ".join(parts) + " }" if odd != 4 else '"5"')
    return rows


def _table_text(rows: list[str], start: str = '"0"') -> str:
    return ('[machine]\naxes = ["X", "Y"]\n[machine.rapid]\nX = "1"\nY = "1"\n[machine.reference]\nX = "0"\nY = "0"\n'
            '[[zones]]\nname = "t"\nkind = "stepped"\nreference_axis = "X"\nlimited_axis = "Y"\nfrom = ' + start + '\n'
            'regions = [\n' + ",\n".join(rows) + "\n]\n")


def _outcome(text: str):
    try:
        m = parse_machine(text, "m.toml")
    except MachineFileError as err:
        return [(d.code, d.message, d.span) for d in err.diagnostics]
    return m.allowed.zones


@settings(max_examples=300, deadline=None)
@given(region_rows(), st.sampled_from(['"0"', '"-1"', '"1"', "0", '"x"']))
@example(['{ upto = "1", max = "1000000.0000001" }'], '"0"')
@example(['{ upto = "1", min = "-1000000.5" }'], '"0"')
@example(['{ upto = "1000000.0000001" }'], '"0"')
@example(['{ upto = "1", min = "2", max = "1" }'], '"0"')
@example(['{ upto = "1" }', '{ upto = "1.0" }'], '"0"')
@example(['{ upto = "0" }'], '"0"')
@example(['{ upto = "1\\n2" }'], '"0"')
@example(['{ upto = "1" }', '{ upto = "2", min = ["1"] }'], '"0"')
@example(['{ upto = "1", min = "1", max = "1" }', '{ upto = "2", min = "-0", max = "0.000" }'], '"-0"')
def test_common_form_regions_read_as_the_region_loop_reads_them(rows, start):
    """The regions read by ``_plain_table`` (the common form) against the loop that reads any form and reports
    each problem: the same zones, or the same diagnostics (code, message, span) -- the loop alone decides those."""
    import nczones.machine as machine

    text = _table_text(rows, start)
    got = _outcome(text)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(machine, "_plain_table", lambda raw, start: None)
        want = _outcome(text)
    assert got == want
    if isinstance(got, tuple):
        zone = got[0]
        assert all(type(v) is F for r in zone.regions for v in (r.upto, r.min, r.max) if v is not None)


def test_a_table_of_4096_regions_takes_the_common_form(monkeypatch):
    import nczones.machine as machine

    rows = [f'{{upto = "{(k + 1) * 0.976562:.6f}", min = "{-1 - k % 7}", max = "{300 + k % 5}"}}' for k in range(4096)]
    calls = []
    plain = machine._plain_table
    monkeypatch.setattr(machine, "_plain_table", lambda raw, start: calls.append(plain(raw, start)) or calls[-1])
    (zone,) = parse_machine(_table_text(rows), "m.toml").allowed.zones
    assert calls[0] is not None and len(zone.regions) == 4096
    assert zone.regions[4095] == machine.Region(F("3999.997952"), F(-1 - 4095 % 7), F(300 + 4095 % 5))
