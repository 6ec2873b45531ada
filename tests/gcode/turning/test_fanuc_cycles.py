"""Golden passes of the Fanuc lathe cycles, each derived by hand beside the test.

Points are ``(label, Z, X)`` in machine coordinates with no offsets, so Z is the program Z and X the
radius (half the programmed diameter).  The algorithms are written down in ``specs/turning.md``.
"""

from __future__ import annotations

import pytest

from nczones.gcode import interpret_text
from tests.gcode.turning.helpers import F, lathe, moves, unknown_reason

R, L = "RAPID", "LINE"


def kinds(program: str, machine) -> list[str]:
    return [s.kind.name for s in interpret_text(program, machine).segments()]


# ----------------------------------------------------------------------------------- G90 G92 G94

def test_g90_turning_cycle_and_its_modal_repeat():
    # A = (Z5, r30).  G90 X40. Z-20.: (1) rapid to r20 at Z5, (2) feed to Z-20, (3) feed out to r30,
    # (4) rapid back to Z5.  "X30." repeats it with r15 and the modal Z-20.
    m = lathe()
    got = moves("G00 X60. Z5.\nG90 X40. Z-20. F0.2\nX30.\nG00 X100.\n", m)
    cycle = [("G90 (1) infeed", F(5), F(20)), ("G90 (2) cut", F(-20), F(20)), ("G90 (3) out", F(-20), F(30)),
             ("G90 (4) return", F(5), F(30))]
    again = [(a, z, F(15) if x == 20 else x) for a, z, x in cycle]
    assert got == [("", F(5), F(30))] + cycle + again + [("", F(5), F(50))]
    assert kinds("G00 X60. Z5.\nG90 X40. Z-20. F0.2\n", m)[1:] == [R, L, L, R]


def test_g90_taper():
    # R-2.: the cut starts 2 mm (radius) below its end: (1) goes to r18, (2) from (Z5, r18) to (Z-20, r20).
    m = lathe()
    got = moves("G00 X60. Z5.\nG90 X40. Z-20. R-2. F0.2\n", m)
    assert got[1:3] == [("G90 (1) infeed", F(5), F(18)), ("G90 (2) cut", F(-20), F(20))]


def test_g94_facing_cycle():
    # A = (Z5, r30).  G94 X10. Z-2.: (1) rapid along Z to Z-2, (2) feed along X to r5, (3) feed back to Z5,
    # (4) rapid along X back to r30.
    m = lathe()
    got = moves("G00 X60. Z5.\nG94 X10. Z-2. F0.2\n", m)
    assert got[1:] == [("G94 (1) infeed", F(-2), F(30)), ("G94 (2) cut", F(-2), F(5)),
                       ("G94 (3) out", F(5), F(5)), ("G94 (4) return", F(5), F(30))]


def test_g92_thread_cycle_with_and_without_chamfer():
    # A = (Z5, r15).  G92 X28. Z-20. F1.5: (1) rapid to r14, (2) thread to Z-20 (no feed rate of its own),
    # (3) rapid out to r15, (4) rapid back.  A chamfer of 0.5 leads (0.75 mm) at 45 degrees: the thread
    # ends at Z-19.25 and pulls out to (Z-20, r14.75).
    m = lathe(fanuc='thread_chamfer = "0"')
    segs = list(interpret_text("G00 X30. Z5.\nG92 X28. Z-20. F1.5\n", m).segments())
    assert [(s.derived, s.end[1], s.end[0]) for s in segs[1:]] == [
        ("G92 (1) infeed", F(5), F(14)), ("G92 (2) thread", F(-20), F(14)), ("G92 (3) out", F(-20), F(15)),
        ("G92 (4) return", F(5), F(15))]
    assert segs[2].feed_mm_min is None
    m2 = lathe(fanuc='thread_chamfer = "0.5"')
    got = moves("G00 X30. Z5.\nG92 X28. Z-20. F1.5\n", m2)
    assert got[2:4] == [("G92 (2) thread", F(-77, 4), F(14)), ("G92 (2) thread chamfer", F(-20), F(59, 4))]


def test_g92_needs_the_chamfer_parameter():
    assert "thread_chamfer" in unknown_reason("G00 X30. Z5.\nG92 X28. Z-20. F1.5\n", lathe())


# ----------------------------------------------------------------------------------- G71 G72

G71_SHAPE = "N10 G00 X20.\nG01 Z-20.\nX40. Z-30.\nN20 Z-40.\n"


def test_g71_type_one_with_allowance():
    # A = (Z2, r25); U5. R1.: depth 5, escape 1; allowance U2. (r1) W0.5: the shape moves by (0.5, 1):
    # A'' (2.5, 11), (-19.5, 11), (-29.5, 21), B'' (-39.5, 21).  Levels 25 - 5k above the lowest point 11:
    # 20, 15.  r20 meets the moved taper at Z = -19.5 - (20 - 11) = -28.5; r15 at -23.5.
    m = lathe()
    got = moves("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 U2. W0.5 F0.2\n" + G71_SHAPE + "G00 X100.\n", m)
    assert got == [
        ("", F(2), F(25)),
        ("G71 roughing pass 1: infeed", F(2), F(20)), ("G71 roughing pass 1: cut", F(-57, 2), F(20)),
        ("G71 roughing pass 1: escape", F(-55, 2), F(21)), ("G71 roughing pass 1: return", F(2), F(21)),
        ("G71 roughing pass 2: infeed", F(2), F(15)), ("G71 roughing pass 2: cut", F(-47, 2), F(15)),
        ("G71 roughing pass 2: escape", F(-45, 2), F(16)), ("G71 roughing pass 2: return", F(2), F(16)),
        ("G71 finishing allowance pass", F(5, 2), F(11)), ("G71 finishing allowance pass", F(-39, 2), F(11)),
        ("G71 finishing allowance pass", F(-59, 2), F(21)), ("G71 finishing allowance pass", F(-79, 2), F(21)),
        ("G71 finishing allowance pass: return to the start point", F(2), F(25)),
        # after the cycle the program goes on after N20: the shape's blocks do not run again
        ("", F(2), F(50)),
    ]
    # infeeds at rapid (the first shape block is G00), cuts at feed, escapes and returns at rapid
    assert kinds("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 U2. W0.5 F0.2\n" + G71_SHAPE, m)[1:5] == [R, L, R, R]


def test_g71_without_the_final_pass_and_with_g01_infeeds():
    m = lathe(fanuc="roughing_final_pass = false")
    shape = G71_SHAPE.replace("N10 G00", "N10 G01")
    got = moves("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m)
    assert got[-1] == ("G71 return to the start point", F(2), F(25))
    assert not any("finishing" in g[0] for g in got)
    assert kinds("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m)[1] == L


def test_g71_one_block_form_of_haas():
    # G71 P Q U W D F: D is the depth, the escape e comes from g71_retract (Haas setting 73).
    m = lathe(fanuc='g71_retract = "1"')
    two = moves("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + G71_SHAPE, m)
    one = moves("G00 X50. Z2.\nG71 P10 Q20 D5. F0.2\n" + G71_SHAPE, m)
    assert one == two
    assert "g71_retract" in unknown_reason("G00 X50. Z2.\nG71 P10 Q20 D5. F0.2\n" + G71_SHAPE, lathe())


def test_g71_type_two_with_a_face():
    # The first block moves X and Z: type II.  A = (Z2, r25); shape A'(1, 20) (0, 20) (0, 5) (-10, 5)
    # (-20, 15) B(-30, 15); depth 5, escape 1.  Levels 20, 15, 10 (above the lowest point 5).  The material
    # at each level lies between the face Z0 and: the line up from B (Z-30) at r20 (the shape is below),
    # the taper at r15 (Z-20) and at r10 (Z-15).
    m = lathe()
    shape = "N10 G00 X40. Z1.\nG01 Z0\nX10.\nZ-10.\nX30. Z-20.\nN20 Z-30.\n"
    got = moves("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m)
    cuts = [(a, z, x) for a, z, x in got if a.endswith(": cut")]
    assert cuts == [("G71 roughing pass 1: cut", F(-30), F(20)), ("G71 roughing pass 2: cut", F(-20), F(15)),
                    ("G71 roughing pass 3: cut", F(-15), F(10))]
    final = [(z, x) for a, z, x in got if a == "G71 finishing allowance pass"]
    assert final == [(F(1), F(20)), (F(0), F(20)), (F(0), F(5)), (F(-10), F(5)), (F(-20), F(15)),
                     (F(-30), F(15))]


def test_g71_type_one_must_be_monotonic():
    # the same face shape with an X-only first block is type I, and it turns back in X: the control alarms
    m = lathe()
    shape = "N10 G00 X40.\nG01 Z0\nX10.\nZ-10.\nX30. Z-20.\nN20 Z-30.\n"
    assert "PS0064" in unknown_reason("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m)


def test_g71_pocket_is_unknown():
    # type II with a groove: level r15 meets two stretches of material
    m = lathe()
    shape = "N10 G00 X20. Z1.\nG01 Z-10.\nX40.\nZ-15.\nX20.\nZ-25.\nN20 X50. Z-30.\n"
    assert "pocket" in unknown_reason("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m)


def test_g71_arc_shape_rounds_the_level_crossing():
    # A = (Z2, r25), shape A'(2, 10) -> (-10, 10) -> G03 to (-20, 20) around (-20, 10) (a quarter circle of
    # radius 10, convex: counter-clockwise in the (Z, X) plane seen from +Y), B = (-30, 20).  Levels 20, 15 (depth 5).  r15 meets the arc where
    # (z + 20)^2 + 5^2 = 100, z = -20 + sqrt(75) = -11.339746...: rounded to the increment 0.001: -11.340.
    m = lathe()
    shape = "N10 G00 X20.\nG01 Z-10.\nG03 X40. Z-20. I0 K-10.\nN20 G01 Z-30.\n"
    got = moves("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m)
    cuts = [(a, z, x) for a, z, x in got if a.endswith(": cut")]
    assert cuts == [("G71 roughing pass 1: cut", F(-20), F(20)), ("G71 roughing pass 2: cut", F(-1134, 100), F(15))]
    arcs = [s for s in interpret_text("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m).segments()
            if s.kind.name == "ARC"]
    assert len(arcs) == 1 and arcs[0].centre == (F(-20), F(10)) and not arcs[0].clockwise
    # the same arc as G02 is the long way round (270 degrees): it turns back along Z, the control alarms
    assert "PS0064" in unknown_reason("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape.replace("G03", "G02"), m)


def test_g72_type_one():
    # G72: depth along Z, cut along X.  A = (Z2, r30); W2. R0.5; shape A'(-6, 30) -> (-6, 20) -> (-2, 10)
    # -> B(-2, 0).  Levels Z 0, -2, -4 (above the lowest Z -6).  Z0 is above the whole shape: the cut runs to
    # B's X (r0); Z-2 meets the taper at r10; Z-4 meets it at r15.  Escapes (+0.5, +0.5), returns to r30.
    m = lathe()
    shape = "N10 G00 Z-6.\nG01 X40.\nX20. Z-2.\nN20 X0\n"
    got = moves("G00 X60. Z2.\nG72 W2. R0.5\nG72 P10 Q20 F0.2\n" + shape, m)
    assert got[1:13] == [
        ("G72 roughing pass 1: infeed", F(0), F(30)), ("G72 roughing pass 1: cut", F(0), F(0)),
        ("G72 roughing pass 1: escape", F(1, 2), F(1, 2)), ("G72 roughing pass 1: return", F(1, 2), F(30)),
        ("G72 roughing pass 2: infeed", F(-2), F(30)), ("G72 roughing pass 2: cut", F(-2), F(10)),
        ("G72 roughing pass 2: escape", F(-3, 2), F(21, 2)), ("G72 roughing pass 2: return", F(-3, 2), F(30)),
        ("G72 roughing pass 3: infeed", F(-4), F(30)), ("G72 roughing pass 3: cut", F(-4), F(15)),
        ("G72 roughing pass 3: escape", F(-7, 2), F(31, 2)), ("G72 roughing pass 3: return", F(-7, 2), F(30)),
    ]


# ----------------------------------------------------------------------------------- G73 G70

G73_SHAPE = "N10 G00 X20. Z0\nG01 X40. Z-10.\nN20 Z-20.\n"


def test_g73_pattern_repeating():
    # A = (Z5, r30); U4. W0 R3: the relief 4 (radius) in 3 divisions: pass j moves the shape by 4 (3 - j) / 2
    # in X: 4, 2, 0.  Each pass: to the moved A', along the moved shape, back to A at rapid.
    m = lathe()
    got = moves("G00 X60. Z5.\nG73 U4. W0 R3\nG73 P10 Q20 U0 W0 F0.2\n" + G73_SHAPE, m)
    exp = [("", F(5), F(30))]
    for j, dx in ((1, 4), (2, 2), (3, 0)):
        p = f"G73 pattern pass {j}"
        exp += [(f"{p}: approach", F(0), F(10 + dx)), (p, F(-10), F(20 + dx)), (p, F(-20), F(20 + dx)),
                (f"{p}: return", F(5), F(30))]
    assert got == exp


def test_g73_needs_its_data():
    assert "g73_divisions" in unknown_reason("G00 X60. Z5.\nG73 P10 Q20 F0.2\n" + G73_SHAPE, lathe())


def test_g70_follows_the_shape_and_returns():
    # the shape as programmed, then back to A at rapid; the shape may be anywhere in the program, and the
    # program goes on after the G70 block
    m = lathe()
    prog = "G00 X60. Z5.\nG70 P10 Q20 F0.1\nG00 X100.\nM30\n" + G73_SHAPE
    got = moves(prog, m)
    assert got == [("", F(5), F(30)), ("G70 finishing pass", F(0), F(10)), ("G70 finishing pass", F(-10), F(20)),
                   ("G70 finishing pass", F(-20), F(20)), ("G70 finishing pass: return to the start point", F(5), F(30)),
                   ("", F(5), F(50))]


def test_g70_with_u_w_proves_both_readings():
    # The manuals define no U/W on G70 (Haas programs carry G71's words over).  Zero words change nothing;
    # non-zero ones: the shape as programmed, then the shape moved by (W, U/2) = (0.2, 0.5) as G71 would leave
    # the allowance, each from A and back to A; a control that ignores the words runs the first, one that
    # applies them the second, so proving both covers either.
    m = lathe()
    prog = "G00 X60. Z5.\nG70 P10 Q20 U0 W0 D0.01 F0.1\nM30\n" + G73_SHAPE
    assert len(moves(prog, m)) == 5
    got = moves(prog.replace("U0 W0", "U1. W0.2"), m)
    first = [("G70 finishing pass", F(0), F(10)), ("G70 finishing pass", F(-10), F(20)),
             ("G70 finishing pass", F(-20), F(20)), ("G70 finishing pass: return to the start point", F(5), F(30))]
    moved = "G70 finishing pass moved by U/W"
    second = [(moved, F(1, 5), F(21, 2)), (moved, F(-49, 5), F(41, 2)), (moved, F(-99, 5), F(41, 2)),
              (f"{moved}: return to the start point", F(5), F(30))]
    assert got == [("", F(5), F(30))] + first + second


# ----------------------------------------------------------------------------------- G74 G75 G76

def test_g74_end_face_peck_drilling():
    # A = (Z1, r0); e = 0.5; Q2000: 2 mm pecks (least increments) to Z-4: -1, back to -0.5, -3, back -2.5,
    # -4, then back to Z1.
    m = lathe()
    got = moves("G00 X0 Z1.\nG74 R0.5\nG74 Z-4. Q2000 F0.1\n", m)
    assert got[1:] == [("G74 position 1: peck 1", F(-1), F(0)), ("G74 position 1: back off", F(-1, 2), F(0)),
                       ("G74 position 1: peck 2", F(-3), F(0)), ("G74 position 1: back off", F(-5, 2), F(0)),
                       ("G74 position 1: peck 3", F(-4), F(0)), ("G74 position 1: return", F(1), F(0))]


def test_g75_grooving_shifts_along_z():
    # A = (Z-10, r25); e = 0.5; X40. Z-12. P2000 Q1000: pecks of 2 mm (radius) along X to r20 (23, 21, 20)
    # at Z -10, -11, -12 (shifts of 1 mm), then back to A.
    m = lathe()
    got = moves("G00 X50. Z-10.\nG75 R0.5\nG75 X40. Z-12. P2000 Q1000 F0.1\n", m)
    one = [("peck 1", 23), ("back off", F(47, 2)), ("peck 2", 21), ("back off", F(43, 2)), ("peck 3", 20),
           ("return", 25)]
    exp = []
    for j, z in ((1, -10), (2, -11), (3, -12)):
        if j > 1:
            exp.append((f"G75 position {j}: shift", F(z), F(25)))
        exp += [(f"G75 position {j}: {a}", F(z), F(x)) for a, x in one]
    exp.append(("G75 back to the start point", F(-10), F(25)))
    assert got[1:] == exp


def test_g76_depths_are_root_n_rounded_to_the_increment():
    # A = (Z5, r16); P010060: m = 1, no chamfer, a = 60 degrees; Q100: minimum depth 0.1; R0: no allowance.
    # X27.4: root r13.7; P1300: height 1.3, so the crest is r15; Q500: first depth 0.5.
    # Depths 0.5 sqrt(n) rounded to the X increment 0.0005: 0.5, 0.707, 0.866, 1.0, 1.118, 1.2245 (sqrt 6 /
    # 2 = 1.224745: 1.2245 is nearer than 1.2250), then sqrt 7 / 2 = 1.3229 >= 1.3 stops: the final pass at 1.3.
    # Flank shifts depth * tan 30 rounded to 0.001: 0.289, 0.408, 0.5 (0.499985), 0.577, 0.645, 0.707, 0.751.
    m = lathe()
    got = moves("G00 X32. Z5.\nG76 P010060 Q100 R0\nG76 X27.4 Z-20. P1300 Q500 F2.\n", m)
    infeeds = [(z, x) for a, z, x in got if a.endswith(": infeed")]
    depths = ["0.5", "0.707", "0.866", "1", "1.118", "1.2245", "1.3"]
    shifts = ["0.289", "0.408", "0.5", "0.577", "0.645", "0.707", "0.751"]
    assert infeeds == [(5 + F(s), 15 - F(d)) for d, s in zip(depths, shifts)]
    threads = [(a, z, x) for a, z, x in got if a.endswith(": thread")]
    assert threads[-1] == ("G76 thread pass 7 (finishing): thread", F(-20), F(137, 10))
    assert got[-1] == ("G76 thread pass 7 (finishing): return", F(5), F(16))


def test_g76_tool_angle_with_an_irrational_shift_is_unknown():
    assert "tool angle" in unknown_reason("G00 X32. Z5.\nG76 P010055 Q100 R0\nG76 X27.4 Z-20. P1300 Q500 F2.\n",
                                          lathe())


@pytest.mark.parametrize("shape, why", [
    ("N10 G02 X20. Z0 R5.\nN20 G01 Z-10.\n", "G00 or G01"),
    ("N10 G00 X20.\nG01 Z-10. ,C1.\nN20 X30.\n", None),
    ("N10 G00 X20.\n#1 = 2\nN20 G01 Z-10.\n", "macro statement"),
])
def test_shapes_the_manuals_do_not_allow(shape, why):
    from nczones.errors import GcodeError

    m = lathe()
    try:
        reason = unknown_reason("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 F0.2\n" + shape, m)
    except GcodeError:
        assert why is None
        return
    assert why is not None and why in reason


def test_missing_shape_block_is_an_error():
    from nczones.errors import GcodeError

    with pytest.raises(GcodeError) as e:
        moves("G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q30 F0.2\n" + G71_SHAPE, lathe())
    assert e.value.diagnostics[0].code == "GC314" and "N30" in e.value.diagnostics[0].message


# ----------------------------------------------------------------------------------- the mode after G70-G73

def test_the_motion_mode_after_a_shape_cycle_is_unknown_when_it_changes_the_path():
    # G70-G76 are one-shot (group 00, [0i-T] "G code list"); the finishing shape's blocks set group 01 (G01,
    # G02) when the control runs them, and the manuals do not say which mode is in effect after the cycle.
    # A bare move after it is unknown unless every candidate moves on the same path.
    arc_shape = "N10 G00 X20. Z0\nG01 X30. Z-5.\nN20 G02 X40. Z-10. R5.\n"
    why = unknown_reason("G00 X60. Z5.\nG70 P10 Q20 F0.1\nX100. Z20.\nM30\n" + arc_shape, lathe())
    assert "motion mode after a G70-G73 cycle" in why and "G2" in why
    # with a G code the move is modelled
    got = moves("G00 X60. Z5.\nG70 P10 Q20 F0.1\nG00 X100. Z20.\nM30\n" + arc_shape, lathe())
    assert got[-1] == ("", F(20), F(50))
    # G00 before, G01 last: both straight with rapid_mode = "linear" (the helper's lathe): modelled
    got = moves("G00 X60. Z5.\nG70 P10 Q20 F0.1\nX100. Z20.\nM30\n" + G73_SHAPE, lathe())
    assert got[-1] == ("", F(20), F(50))
    # ... but not with a dogleg rapid
    why = unknown_reason("G00 X60. Z5.\nG70 P10 Q20 F0.1\nX100. Z20.\nM30\n" + G73_SHAPE,
                         lathe('rapid_mode = "dogleg"\n'))
    assert "motion mode after" in why
