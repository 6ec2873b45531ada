"""The tool solids on the path the machine moves (issue 39 × issue 35, nczones/prover/solids_blend.py).

The example mill (specs/machines/mill_solids.toml): the vise is the box X 100..250, Y 0..80, Z 0..60; tool 1
is a cutter Ø10 × 25, a shank Ø10 × 15 and a holder Ø63 (radius 31.5) at 40..100 above the tip, H1 = 100.
The tests put a right-angle corner outside the vise's corner (250, 80): the first motion runs along
Y = 80 + 31.5 + c towards X = 250 + 31.5 + c, the second down along that X, so on the programmed path the
holder clears the vise by exactly ``c`` on both motions (its axis is 31.5 + c from the vise's faces, and the
corner point itself is farther), and the vise lies inside the corner, where a blend cuts.  The tip is at
Z 10, so the holder (Z 50..110) overlaps the vise's heights (0..60).

* ``G64 P p`` (Q defaults to P): every real point lies within d = p + q of the programmed path
  (specs/path-modes.md §2), so the corner is ``safe`` when c > d and not ``safe`` when 0 < c < d.
* ``G64`` without P: the blend may use half of each motion; the corner region reaches the vise, and the
  independent model of LinuxCNC's planner (tests/oracles/blend.py) moves the holder into it.
"""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import solids_blend, verify_text
from nczones.solids import FixtureBox, FixtureCylinder, machine_solids
from tests.oracles.blend import blend_arc, parabolic_blend
from tests.oracles.solids import part_hits

ROOT = Path(__file__).resolve().parents[2]
TEXT = (ROOT / "specs/machines/mill_solids.toml").read_text(encoding="utf-8")
HEADER = "G21 G90 G17 G54\nT1 M6\nG43 H1\n"
HOLDER_R = Decimal("31.5")


def _machine(extra: str = "", fanuc: bool = False):
    text = TEXT.replace('path_mode = "G61"', 'path_mode = "G64"' + extra)
    if fanuc:
        text = text.replace('[machine]\n', '[machine]\ndialect = "fanuc"\n', 1)
    return parse_machine(text)


def _corner(c: Decimal, legs: int = 150) -> tuple[tuple[Decimal, Decimal], ...]:
    """(start, corner, end) of the two motions around the vise's corner with holder clearance ``c``."""
    cx, cy = 250 + HOLDER_R + c, 80 + HOLDER_R + c
    return (cx - legs, cy), (cx, cy), (cx, cy - legs)


def _program(mode: str, c: Decimal, legs: int = 150, *, before: str = "", feed: int = 6000,
             params: bool = False) -> str:
    (x0, y0), (cx, cy), (x1, y1) = _corner(c, legs)
    z = "#1" if params else "10"
    return (HEADER + ("#1 = 10\n" if params else "") + f"{mode}\n" + before + f"G0 X{x0} Y{y0} Z100\n"
            f"G1 Z{z} F{feed}\nG1 X{cx} Y{cy}\nG1 X{x1} Y{y1}\nG0 Z100\nM30\n")


def _long_prefix(n: int = 600) -> str:
    """More than 512 motions far from every fixture (the vectorized tier), a zig-zag at X -50..-40."""
    return "G0 X-50 Y0 Z100\nG1 Z10 F3000\n" + "".join(f"G1 X{-50 + (i % 2) * 10} Y{i % 50}\n" for i in range(n)) \
        + "G0 Z100\nG0 X-50 Y112.5\n"  # then along Y 112.5 (beside the vise) to the corner, in G64 too


def _codes(r) -> set[str]:
    return {x.code for x in r.reasons}


# ---------------------------------------------------------------------------------------- with a tolerance

@pytest.mark.parametrize("prefix", ["", "long"])
@pytest.mark.parametrize("params", [False, True])
@pytest.mark.parametrize("mode, expected", [
    ("G64 P0.4", "safe"),        # d = 0.4 + 0.4 = 0.8 < c = 1
    ("G64 P0.9 Q0", "safe"),     # d = 0.9 < 1 (no naive-CAM merging)
    ("G64 P0.6", "unknown"),     # d = 1.2 > 1: the holder may come within 1.2 of the path, the vise is 1 away
    ("G64 P0.5 Q0.6", "unknown"),  # d = 1.1 > 1
    ("G61", "safe"),
])
def test_tolerance_corner_clearance_against_the_bound(mode, expected, prefix, params):
    text = _program(mode, Decimal(1), before=_long_prefix() if prefix else "", params=params)
    r = verify_text(text, _machine())
    assert r.verdict.label == expected, r.reasons
    if expected == "unknown":
        assert _codes(r) == {"VF233"}, r.reasons
        assert any("holder" in x.message and "`vise`" in x.message for x in r.reasons)


def test_tolerance_fanuc_path_tolerance():
    """A Fanuc control in cutting mode with [machine] path_tolerance t: within t of the path.  (Fanuc's G43
    without an axis word applies the offset on the next Z motion; the header gives one.)"""
    text = _program("G64", Decimal(1)).replace(HEADER, "G21 G90 G17 G54\nT1 M6\nG0 G43 H1 Z100\n")
    assert verify_text(text, _machine('\npath_tolerance = "0.9"', fanuc=True)).verdict.label == "safe"
    r = verify_text(text, _machine('\npath_tolerance = "1.5"', fanuc=True))
    assert r.verdict.label == "unknown" and "VF233" in _codes(r), r.reasons
    r = verify_text(text, _machine(fanuc=True))  # no tolerance: the run's hull, not modelled for the solids
    assert r.verdict.label == "unknown" and "VF235" in _codes(r), r.reasons


def test_programmed_path_hit_stays_unsafe():
    """The holder enters the vise on the programmed path itself (c = -1): unsafe in every mode, and no corner
    reason names the violating motions."""
    for mode in ("G64", "G64 P0.6", "G61"):
        r = verify_text(_program(mode, Decimal(-1)), _machine())
        assert r.verdict.label == "unsafe", (mode, r.reasons)
        bad = {v.block for v in r.violations}
        assert not any(x.block in bad for x in r.reasons if x.code in ("VF233", "VF234"))


# ---------------------------------------------------------------------------------------- without tolerance

@pytest.mark.parametrize("prefix", ["", "long"])
@pytest.mark.parametrize("params", [False, True])
def test_no_tolerance_corner_region(prefix, params):
    """``G64``: long motions (150) let the blend cut 1/2 of each, into the vise: unknown, the corner named;
    short ones (20: the region reaches (Cx - 10, Cy - 10), 10·√2 + 1·√2 ... at least 31.5 + 13.5·√2 - 10·√2
    from the vise's corner) clear it."""
    before = _long_prefix() if prefix else ""
    r = verify_text(_program("G64", Decimal(1), before=before, params=params), _machine())
    # the tip's own corner region reaches the vise too (VF208, the point's corner proof)
    assert r.verdict.label == "unknown" and "VF234" in _codes(r) <= {"VF208", "VF234"}, r.reasons
    assert any("`vise`" in x.message and "holder" in x.message and "blend between line" in x.message
               for x in r.reasons), r.reasons
    r = verify_text(_program("G64", Decimal(1), legs=20, before=before, params=params), _machine())
    assert r.verdict.label == "safe", r.reasons


def test_no_tolerance_long_program_uses_the_column_screen(monkeypatch):
    """The > 512-motion program's corners are screened on the column chunks (not one motion at a time)."""
    seen = []
    screen = solids_blend.SolidsCornerCheck._screen_corners

    def spy(self, chunk, *args):
        got = screen(self, chunk, *args)
        seen.append((len(chunk), got))
        return got

    monkeypatch.setattr(solids_blend.SolidsCornerCheck, "_screen_corners", spy)
    r = verify_text(_program("G64", Decimal(1), before=_long_prefix()), _machine())
    assert r.verdict.label == "unknown" and "VF234" in _codes(r)
    assert any(n > 512 and got for n, got in seen), seen


# ---------------------------------------------------------------------------------------- the oracle

def _oracle_hits(mode_tol: float, c: Decimal, legs: int, a: float, v: float) -> bool:
    """Does LinuxCNC's planner (tests/oracles/blend.py: blend arc and parabolic blend) move a part of tool 1
    into a fixture at the corner?  Floats, the tip at Z 10 (machine Z 110, tool length 100)."""
    m = _machine()
    s = machine_solids(m)
    parts = s.parts_for(1)
    p0, corner, p1 = (tuple(float(x) for x in p) for p in _corner(c, legs))
    pts = (blend_arc(p0, corner, p1, a_max=a, v_goal=v, tolerance=mode_tol)
           + parabolic_blend(p0, corner, p1, a1=a, a2=a, v1=v, v2=v, tolerance=mode_tol))
    fparts = [type(p)(p.name, float(p.radius), float(p.z0), float(p.z1), p.spindle) for p in parts]
    return any(part_hits(p, fx, x, y, 110.0, 100.0) for x, y in pts for p in fparts for fx in _float_fixtures(s))


def _float_fixtures(s):
    def f(v):
        return None if v is None else float(v)

    out = []
    for fx in s.fixtures:
        if isinstance(fx, FixtureCylinder):
            out.append(FixtureCylinder(fx.name, f(fx.cx), f(fx.cy), f(fx.radius), f(fx.z0), f(fx.z1)))
        else:
            assert isinstance(fx, FixtureBox)
            out.append(FixtureBox(fx.name, *(f(v) for v in (fx.x0, fx.x1, fx.y0, fx.y1, fx.z0, fx.z1))))
    return out


def test_oracle_blends_reach_the_vise_and_the_prover_is_not_safe(monkeypatch):
    """The planner's model moves the holder into the vise at these corners (tolerance 20 and no tolerance,
    1000 mm/s² ... 200 mm/s², F6000 = 100 mm/s): the prover must not say safe.  Mutations: the parts grown by
    a hundredth of the bound, or a corner region of no extent, prove them safe (so the tests hold them)."""
    cases = [("G64 P20", 20.0), ("G64", 0.0)]
    for mode, tol in cases:
        assert _oracle_hits(tol, Decimal(1), 150, 200.0, 100.0), mode
        r = verify_text(_program(mode, Decimal(1)), _machine())
        assert r.verdict.label == "unknown" and {"VF233", "VF234"} & _codes(r), (mode, r.reasons)
    # (the tip is 32.5 from the vise, inside the point's own corner enclosures too: VF208 stays; the solids'
    # reasons are what the mutations remove)
    original = solids_blend.grown_solids
    monkeypatch.setattr(solids_blend, "grown_solids", lambda s, d: original(s, d / 100))
    assert "VF233" not in _codes(verify_text(_program("G64 P20", Decimal(1)), _machine()))
    monkeypatch.setattr(solids_blend, "_HALF", Fraction(0))
    assert "VF234" not in _codes(verify_text(_program("G64", Decimal(1)), _machine()))


@settings(max_examples=12, deadline=None)
@given(st.sampled_from([("G64", 0.0), ("G64 P2", 2.0), ("G64 P10", 10.0), ("G64 P20 Q0", 20.0), ("G64 P20", 20.0)]),
       st.integers(0, 12).map(lambda k: Decimal(k) / 4), st.integers(20, 160),
       st.floats(100, 1000), st.floats(40, 200))
def test_oracle_never_a_wrong_safe(mode, c, legs, a, v):
    """Generated corners around the vise: where the planner's model moves a part into a fixture, the prover
    is not ``safe`` (the programmed path clears by c >= 0, so the verdict is safe or unknown).  The ranges
    are biased to corners the planner rounds deeply (clearance up to 3, slow acceleration, fast feeds): a
    sample of 30 such corners (clearance 0..2, legs 60..160, 100..600 mm/s², 60..200 mm/s) had 18 where the
    model's blend puts the holder into the vise; with clearance up to 10 and 100..3000 mm/s², none of 30."""
    code, tol = mode
    r = verify_text(_program(code, c, legs, feed=int(v * 60)), _machine())
    assert r.verdict.label != "unsafe" or c == 0, r.violations
    if _oracle_hits(tol, c, legs, a, v):
        assert r.verdict.label != "safe", (code, c, legs, a, v)
    if r.verdict.label == "unknown":
        assert _codes(r) <= {"VF208", "VF233", "VF234"}, r.reasons


def test_holder_corner_unknown_names_the_lines():
    r = verify_text(_program("G64", Decimal(1)), _machine())
    msg = next(x.message for x in r.reasons if x.code == "VF234")
    # lines: 1-3 header, 4 the mode, 5 G0, 6 G1 Z10, 7 the first motion, 8 the second
    assert "between line 7 and line 8" in msg and "holder" in msg


# ---------------------------------------------------------------------------------------- a lathe

def test_lathe_solids_with_a_path_tolerance():
    """A lathe's turret tool (specs/machines/lathe_solids.toml, Fanuc): the boring example moved out to X40
    brings the insert 9.013 mm from the jaws (the least clearance the G61 proof prints, a lower bound).  In
    cutting mode with path_tolerance 3 the parts grown by 3 on every side still clear them (safe); with 10
    (more than the clearance) the verdict is not safe (VF233).  Without path_tolerance the corners are unknown
    (VF235), as before (VF210)."""
    text = (ROOT / "specs/examples/programs/boring_bar_clears_chuck.nc").read_text(encoding="utf-8")
    text = text.replace("X30. Z1.", "X40. Z1.")
    lathe = (ROOT / "specs/machines/lathe_solids.toml").read_text(encoding="utf-8")
    exact = verify_text(text, parse_machine(lathe))
    assert exact.verdict.label == "safe"
    assert any("insert" in n and "9.013 mm from `jaws`" in n for n in exact.notes), exact.notes

    def run(extra: str):
        return verify_text(text, parse_machine(lathe.replace('path_mode = "G61"', 'path_mode = "G64"' + extra)))

    assert run('\npath_tolerance = "3"').verdict.label == "safe"
    r = run('\npath_tolerance = "10"')
    assert r.verdict.label == "unknown" and _codes(r) == {"VF233"}, r.reasons
    assert any("insert" in x.message and "`jaws`" in x.message for x in r.reasons)
    r = run("")
    assert r.verdict.label == "unknown" and _codes(r) == {"VF235"}, r.reasons


def test_reference_controller_blending_agrees():
    """The reference controller rounds the corner with LinuxCNC's blend arcs (`simulate`, blending where the
    machine starts in G64 and gives its accelerations: 200 mm/s² here, F6000) and checks the solids pulse by
    pulse, independently of the prover: in G64 and G64 P20 its holder alarms on the blend arc (line 7, Y below
    the programmed 112.5) and the prover is not safe; in G64 P0.4 neither alarms nor doubts (safe)."""
    from nczones.controller import simulate
    from nczones.gcode import interpret_text

    m = parse_machine(TEXT.replace('path_mode = "G61"', 'path_mode = "G64"')
                      + '\n[machine.acceleration]\nX = "200"\nY = "200"\nZ = "200"\n')
    for mode, alarm in (("G64", True), ("G64 P20", True), ("G64 P0.4", False)):
        text = _program(mode, Decimal(1))
        sim = simulate(interpret_text(text, m, fast=False), m)
        assert bool(sim.alarms) is alarm, (mode, sim.alarms)
        if alarm:
            a = sim.alarms[0]
            assert a.line == 7 and a.zone == "vise" and a.position[1] < Fraction(225, 2), a
        assert verify_text(text, m).verdict.label == ("unknown" if alarm else "safe"), mode


def test_tolerance_long_program_grown_parts_on_the_columns(monkeypatch):
    """In G64 P the > 512-motion program's motions reach the grown parts' checker as column chunks (its numpy
    screen on the columns), not one segment at a time."""
    rows = []
    checker = solids_blend.SolidsCornerCheck._checker

    def spy(self, d):
        got = checker(self, d)
        rows.append(got)
        return got

    monkeypatch.setattr(solids_blend.SolidsCornerCheck, "_checker", spy)
    r = verify_text(_program("G64 P0.6", Decimal(1), before=_long_prefix()), _machine())
    assert r.verdict.label == "unknown" and _codes(r) == {"VF233"}
    assert rows and max(c.column_rows for c in rows) > 512


def test_fanuc_without_tolerance_long_program_counts_its_corners():
    """A Fanuc control in cutting mode without path_tolerance, > 512 motions: the corners are unknown (VF235),
    the first ones named and the rest counted under the same code."""
    text = _program("G64", Decimal(1), before=_long_prefix()).replace(HEADER, "G21 G90 G17 G54\nT1 M6\nG0 G43 H1 Z100\n")
    r = verify_text(text, _machine(fanuc=True))
    assert r.verdict.label == "unknown" and "VF235" in _codes(r) <= {"VF208", "VF235"}, r.reasons
    assert any(x.code == "VF235" and "more blended corner" in x.message for x in r.reasons), r.reasons


@pytest.mark.parametrize("long", [False, True])
def test_through_verify_on_a_file(tmp_path, long):
    """The same corner through `nczones.prover.verify` on a program file (verify_text shares its pipeline)."""
    from nczones.prover import verify

    before = _long_prefix() if long else ""
    for mode, expected in (("G64 P0.4", "safe"), ("G64 P0.6", "unknown"), ("G64", "unknown")):
        path = tmp_path / "corner.ngc"
        path.write_text(_program(mode, Decimal(1), before=before), encoding="utf-8")
        r = verify(str(path), _machine())
        assert r.verdict.label == expected, (mode, r.reasons)
        assert expected == "safe" or {"VF233", "VF234"} & _codes(r)


@pytest.mark.parametrize("prefix", ["", "long"])
def test_a_move_linuxcnc_drops_at_the_corner_does_not_hide_the_corner(prefix):
    """A straight move shorter than 3e-7 mm (``nczones.motion.DROPPED_BELOW``) at the corner: LinuxCNC's canonical
    layer drops it (CART_FUZZ) and blends the two long motions around it, whose corner region reaches the vise
    (the ``G64`` long-legs case above: VF234).  Taken as a real move, the corners on either side of it are
    slivers along each motion, which clear the vise by c = 1: the solids' reason was lost (found at review,
    where the point's corner proof already handled dropped moves and the solids' did not)."""
    (x0, y0), (cx, cy), (x1, y1) = _corner(Decimal(1))
    text = (HEADER + "G64\n" + (_long_prefix() if prefix else "") + f"G0 X{x0} Y{y0} Z100\nG1 Z10 F6000\n"
            f"G1 X{cx} Y{cy}\nG1 X{cx + Decimal('0.0000002')}\nG1 X{x1} Y{y1}\nG0 Z100\nM30\n")
    r = verify_text(text, _machine())
    assert r.verdict.label == "unknown" and "VF234" in _codes(r), r.reasons
    # a move LinuxCNC keeps (1e-3 mm) splits the corner in two, each blend using at most half of that move:
    # both regions are slivers along the legs, and the tool clears the vise there
    kept = text.replace(f"X{cx + Decimal('0.0000002')}", f"X{cx + Decimal('0.001')}")
    assert verify_text(kept, _machine()).verdict.label == "safe"


def test_a_tool_change_at_a_rounded_corner_is_not_proved():
    """A turret index inside a run in cutting mode with path_tolerance (a second tool, the same assembly, Z
    offset 140 against 150): the grown parts' checker proves each motion with its own tool, while the blend
    near the corner may carry either tool near either motion.  Before, ``safe``; now ``unknown`` (VF233)
    naming the corner; the same program without the index stays ``safe``."""
    text = (ROOT / "specs/examples/programs/boring_bar_clears_chuck.nc").read_text(encoding="utf-8")
    text = text.replace("X30. Z1.", "X40. Z1.")
    lathe = (ROOT / "specs/machines/lathe_solids.toml").read_text(encoding="utf-8")
    lathe = lathe.replace('1 = { X = "100", Z = "150", R = "0.4", tip = 2 }',
                          '1 = { X = "100", Z = "150", R = "0.4", tip = 2 }\n'
                          '2 = { X = "100", Z = "140", R = "0.4", tip = 2 }')
    start = lathe.index("[[tools]]")
    tool = lathe[start:lathe.index("[[fixtures]]")].replace("number = 1", "number = 2", 1)
    lathe = lathe.replace("[[fixtures]]", tool + "[[fixtures]]", 1)
    lathe = lathe.replace('path_mode = "G61"', 'path_mode = "G64"\npath_tolerance = "3"')
    assert verify_text(text, parse_machine(lathe)).verdict.label == "safe"
    r = verify_text(text.replace("Z-35.", "T0202 Z-35."), parse_machine(lathe))
    assert r.verdict.label == "unknown" and _codes(r) == {"VF233"}, r.reasons
    assert any("between line 6 and line 7" in x.message and "tool length or frame changes" in x.message
               for x in r.reasons), r.reasons
