"""Numbers people read (issue 37): short exact decimals, rounded values to the machine's resolution marked ≈,
depths to the pulse length, the "Checked" row in words; JSON keeps the exact values."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest

from nczones import load_machine
from nczones.prover import verify
from nczones.report import render_report
from nczones.report.numbers import checked_in_words, coord, depth

from .helpers import EX, MACHINES

HELIX = str(EX / "programs/helix_into_vise_corner.ngc")


@pytest.fixture(scope="module")
def helix():
    m = load_machine(MACHINES / "mill.toml")  # pulse 0.001 on every axis
    return verify(HELIX, m, file="helix_into_vise_corner.ngc"), m


def test_helix_witness_reads_rounded_to_the_pulse(helix):
    """The helix's exit is irrational: the reported rational enclosure point is within 1e-20 of X110 Y60 (the
    vise corner, specs/machines/mill.toml: vise X 100..110 Y 60..100 as the tip sees it) and its point has
    Z = 48419331058796533806597/200000000000000000000 = 242.0966552939826...; on a 0.001 mm machine these read
    X≈110 Y≈60 and Z≈242.097.  The depth is a lower bound 6.786885245901...: floored to 0.001, 6.786."""
    result, m = helix
    v = result.violations[0]
    assert not v.depth_exact
    text = render_report(result, "text", machine=m, deterministic=True)
    assert "Z≈242.097 " in text and "first exit at X≈110 Y≈60 Z≈248 " in text
    assert "at least 6.786 mm deep" in text and "0000000" not in text
    page = render_report(result, "html", machine=m, deterministic=True)
    assert "X≈110 Y≈60" in page and "≥ 6.786 mm" in page
    sarif = render_report(result, "sarif", machine=m, deterministic=True)
    assert "X≈110 Y≈60" in sarif and "at least 6.786 mm" in sarif
    # the exact values stay in JSON
    doc = json.loads(render_report(result, "json", machine=m, deterministic=True))
    assert doc["violations"][0]["point_exact"]["Z"] == "48419331058796533806597/200000000000000000000"


def test_checked_row_in_words(helix):
    result, m = helix
    page = render_report(result, "html", machine=m, deterministic=True)
    row = page.split("<th>Checked</th><td>", 1)[1].split("</td>", 1)[0]
    assert "_" not in row and "exact_decided" not in row and row.startswith("2 motion segments checked")


def test_number_rules():
    F = Fraction
    assert coord(F("60.000")) == "60" and coord(F("-0.5")) == "-0.5"  # as short as exact allows
    assert coord(F(1, 3), F("0.0005")) == "≈0.3333"  # the places of a 0.0005 pulse
    assert coord(F(1, 3)) == "≈0.333333"  # no machine: 6 places
    assert depth(F(19, 10), False, F("0.001")) == "1.9"  # a short lower bound is written as it is
    assert depth(F(6789, 1000) - F(1, 10**9), False, F("0.001")) == "6.788"  # floor keeps "at least" true
    assert checked_in_words({"segments": 1, "z3_queries": 1}) == "1 motion segment checked: 1 solver query"
