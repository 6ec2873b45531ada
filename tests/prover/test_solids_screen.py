"""The vectorized screen of the solids proof (nczones/prover/solids_screen.py) against the exact proof of every
motion: the same verdict, violations, reasons and least clearances (issue 39, speed).

``nczones.prover.solids.SCREEN = False`` makes the checker prove every motion exactly (the behaviour before the
screen).  Short programs go through the segment batches (the full interpreter); programs of more than 512
lines through the column chunks of the vectorized fast path (the rows screened straight from the columns, in
integers on the columns' grid, or in floats with a margin when a fixture is off that grid)."""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.prover.solids as solids_mod
from nczones.gcode import interpret_text, segments_text
from nczones.machine import parse_machine
from nczones.motion import MotionChunk
from nczones.prover import verify_text
from tests.prover.test_solids import ORACLE_MACHINE, programs

#: the oracle machine of tests/prover/test_solids.py runs the exact path (G61: the solids are proved, not unknown)
assert 'path_mode = "G61"' in ORACLE_MACHINE

#: the oracle machine with a third fixture whose sides are off a 4-decimal grid (the float screen)
OFF_GRID = ORACLE_MACHINE + """[[fixtures]]
name = "stop"
kind = "box"
min = { X = "60.0000001", Y = "-20", Z = "0" }
max = { X = "70", Y = "20.0000003", Z = "30" }
"""


def _facts(r):
    return (r.verdict.label,
            [(v.block, v.line, v.zone, v.zones, v.point, v.path_point, v.parameter) for v in r.violations],
            [(x.code, x.span.line if x.span is not None else None) for x in r.reasons],
            {(p, f): c for p, f, c, _line in r.extra.get("clearance", ())})


def _both(text, machine_text, monkeypatch):
    machine = parse_machine(machine_text, "m.toml")
    monkeypatch.setattr(solids_mod, "SCREEN", False)
    exact = verify_text(text, machine)
    monkeypatch.setattr(solids_mod, "SCREEN", True)
    screened = verify_text(text, machine)
    return exact, screened


def _walk(seed: int, n: int) -> str:
    """``n`` short moves (a CAM-like walk on a 0.5 mm grid) around the jaw (X 0..40, Y 0..30, Z up to 25) and
    the post (about X-30 Y40), tool 1 then 2 half way, retracts, a few rapids and one G49 stretch."""
    rnd = random.Random(seed)
    h = rnd.choice([1, 2])
    out = [f"G21 G90 G17 G54\nT{h} M6\nG43 H{h}\nG0 X-60 Y-60 Z120"]
    x, y, z = Fraction(-60), Fraction(-60), Fraction(120)
    for i in range(n):
        if i == n // 2:
            h = 3 - h
            out.append(f"G0 Z150\nT{h} M6\nG43 H{h}")
        if i == 3 * n // 4:
            out.append("G49")  # which assembly is in the spindle is not known: VF211 for these moves
        if i == 3 * n // 4 + 5:
            out.append(f"G43 H{h}")
        x = max(Fraction(-80), min(Fraction(80), x + Fraction(rnd.randint(-8, 8), 2)))
        y = max(Fraction(-80), min(Fraction(80), y + Fraction(rnd.randint(-8, 8), 2)))
        z = max(Fraction(5, 2), min(Fraction(160), z + Fraction(rnd.randint(-12, 10), 2)))
        word = "G0" if rnd.random() < 0.05 else "G1"
        out.append(f"{word} X{float(x)} Y{float(y)} Z{float(z)}" + (" F500" if word == "G1" else ""))
    return "\n".join(out) + "\nM30\n"


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(text=programs())
def test_screen_agrees_with_the_exact_proof_short(text, monkeypatch):
    exact, screened = _both(text, OFF_GRID, monkeypatch)
    assert _facts(screened) == _facts(exact), text


@pytest.mark.parametrize("seed, machine", [(2, ORACLE_MACHINE), (3, OFF_GRID)])
def test_screen_agrees_with_the_exact_proof_columns(seed, machine, monkeypatch):
    text = _walk(seed, 700)  # > 512 lines: the vectorized fast path's column chunks
    exact, screened = _both(text, machine, monkeypatch)
    assert _facts(screened) == _facts(exact)
    assert exact.extra.get("clearance")  # the walk passes near the fixtures: something to agree on


@pytest.mark.long
@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 10**9), machine=st.sampled_from([ORACLE_MACHINE, OFF_GRID]))
def test_screen_agrees_with_the_exact_proof_long(seed, machine, monkeypatch):
    exact, screened = _both(_walk(seed, 700), machine, monkeypatch)
    assert _facts(screened) == _facts(exact)


def test_the_screen_leaves_most_motions_to_numpy(monkeypatch):
    """On a walk far from every fixture after its first moves, almost no motion is proved exactly."""
    made = []
    init = solids_mod.SolidsChecker.__post_init__

    def keep(self):
        init(self)
        made.append(self)

    monkeypatch.setattr(solids_mod.SolidsChecker, "__post_init__", keep)
    text = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X150 Y150 Z100\n" + "".join(
        f"G1 X{150 + (i % 7)} Y{150 + (i % 5)} Z{40 + (i % 3)} F500\n" for i in range(800)) + "M30\n"
    r = verify_text(text, parse_machine(ORACLE_MACHINE, "m.toml"))
    assert r.verdict.label == "safe", r.reasons
    checker = made[-1]
    assert checker.column_rows >= 780  # the fast path's columns, screened as they are
    assert checker.screened_out >= 780 and checker.screened_exact + checker.screened_pairs <= 20


def test_the_fast_path_records_the_tool_register():
    """A run of simple lines has no H or T word (gcode/codes.py: the fast path declines G43, G49, M6 and T),
    so its column chunk has one tool register: the one the full interpreter gives every segment of it."""
    text = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X150 Y150 Z100\n" + "".join(
        f"G1 X{150 + (i % 7)} Y{150 + (i % 5)} F500\n" for i in range(2500)) + "G0 Z200\nT2 M6\nG43 H2\n" + "".join(
        f"G1 X{150 + (i % 3)} Y{150 + (i % 4)}\n" for i in range(2500)) + "M30\n"
    machine = parse_machine(ORACLE_MACHINE, "m.toml")
    fast = segments_text(text, machine)
    full = segments_text(text, machine, fast=False)
    assert [(s.block, s.tool_register) for s in fast] == [(s.block, s.tool_register) for s in full]
    chunks = [c for c in interpret_text(text, machine) if isinstance(c, MotionChunk) and c.scale is not None]
    assert chunks and all(c.tools_known for c in chunks)
    assert 2 in {c.tool_register for c in chunks}
