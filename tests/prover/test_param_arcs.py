"""An arc whose start and end depend on different parameters is decided (issue 19).

The first motion of a program starts at the machine's start position; with
``--param start.X=LO..HI`` its start moves with the parameter while its
programmed end does not.  Such an arc used to be ``unknown`` whatever it
did, and the summary's "first at line N" then named a later block.
"""

from fractions import Fraction as F

from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from nczones.errors import InputError
from nczones.exact import format_exact
from nczones.machine import parse_machine
from nczones.prover import Verdict, verify_text
from tests.oracles.concrete import machine_at


def machine(top: str, start_x: str = "50", g54_x: str = "0", more_zones: str = ""):
    """Travel box X 0..100, Y 0..top; the start at (start_x, 50); G54 at (g54_x, 0)."""
    return parse_machine(f"""
[machine]
axes = ["X", "Y"]
[machine.rapid]
X = "1000"
Y = "1000"
[machine.reference]
X = "{start_x}"
Y = "50"
[offsets]
G54 = {{ X = "{g54_x}", Y = "0" }}
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "0", Y = "0" }}
max = {{ X = "100", Y = "{top}" }}
{more_zones}""")


#: a half circle clockwise from the start (50, 50) over (55, 55) to (60, 50), then a line up to Y60
PROGRAM = "G17 G90 G54\nG2 X60 Y50 I5 J0 F100\nG1 Y60\nM2\n"


def test_arc_from_a_start_range_that_violates_at_every_value_is_unsafe_with_its_values():
    m = machine("53")
    r = verify_text(PROGRAM, m, params=["start.X=-2..2"])
    assert r.verdict is Verdict.UNSAFE
    first = r.violations[0]
    assert first.line == 2 and first.segment_kind == "arc"
    dev = dict(first.params)["start.X"]
    assert -2 <= dev <= 2
    assert m.allowed.violated_zones(dict(first.point), F(0))
    assert not any("different parameters" in x.message for x in r.reasons)
    # replayed at its value (the machine starting there), the same block is unsafe
    at_value = verify_text(PROGRAM, machine("53", format_exact(50 + dev)))
    assert at_value.violations[0].line == 2


def test_arc_from_a_start_range_that_stays_inside_is_safe():
    r = verify_text("G17 G90 G54\nG2 X60 Y50 I5 J0 F100\nM2\n", machine("70"), params=["start.X=-2..2"])
    assert r.verdict is Verdict.SAFE, r.reasons


#: an R-format arc from the start (50, 50) to G54 X60 Y50: its start moves with start.X, its end with
#: G54.X; the chord is 6..14 mm over the ranges, the bulge above Y50 0.58..4.13 mm (R8); then a line up
TWO_RANGES = "G17 G90 G54\nG2 X60 Y50 R8 F100\nG1 Y60\nM2\n"


def test_arc_whose_ends_move_with_different_ranges_is_unsafe_at_its_line_and_the_summary_names_it():
    from nczones.report.text import summary_line

    m = machine("50.5")  # below the smallest bulge: every value of both ranges violates at line 2
    params = ["start.X=-2..2", "G54.X=-2..2"]
    r = verify_text(TWO_RANGES, m, params=params)
    assert r.verdict is Verdict.UNSAFE, r.reasons
    assert [v.line for v in r.violations] == [2, 3]
    first = r.violations[0]
    assert first.segment_kind == "arc" and first.zone == "travel"
    assert m.allowed.violated_zones(dict(first.point), F(0))
    values = dict(first.params)
    assert set(values) == {"start.X", "G54.X"} and all(-2 <= x <= 2 for x in values.values())
    assert "the first at line 2;" in summary_line(r, "p.ngc")
    # replayed at its values (the machine starting and its G54 offset there), line 2 is unsafe
    replay = verify_text(TWO_RANGES, machine("50.5", format_exact(50 + values["start.X"]),
                                                      format_exact(values["G54.X"])))
    assert replay.violations[0].line == 2



def test_arc_whose_ends_move_with_different_ranges_and_stays_below_the_top_is_proved():
    # the bulge is at most 4.13 mm over the ranges (the largest chord, 14 mm, with R8): below Y56 the arc
    # is proved for every value by its chord and sagitta; the line after it leaves the box
    r = verify_text(TWO_RANGES, machine("56"), params=["start.X=-2..2", "G54.X=-2..2"])
    assert [v.line for v in r.violations] == [3] and not r.reasons
    # with the top at Y54 the arc violates at its largest chords only (start.X=-2, G54.X=2)
    r = verify_text(TWO_RANGES, machine("54"), params=["start.X=-2..2", "G54.X=-2..2"])
    assert r.violations[0].line == 2

# --------------------------------------------------------------------------- a range verdict vs its values


def _grid(n: int, d: int = 2) -> st.SearchStrategy[F]:
    return st.integers(-n * d, n * d).map(lambda k: F(k, d))


@st.composite
def varying_arc_cases(draw):
    """A machine (travel box, maybe a forbid post), a program whose first move is an arc from the start
    position (I/J or R), and ranges that move its start (start.*) and its end (G54.*) differently."""
    top = 50 + draw(st.integers(1, 16))
    post = ""
    if draw(st.booleans()):
        x0, y0 = 40 + draw(st.integers(0, 25)), 40 + draw(st.integers(0, 20))
        post = (f'[[zones]]\nname = "post"\nkind = "box"\nforbid = true\nmin = {{ X = "{x0}", Y = "{y0}" }}\n'
                f'max = {{ X = "{x0 + draw(st.integers(1, 6))}", Y = "{y0 + draw(st.integers(1, 6))}" }}\n')
    m = machine(str(top), more_zones=post)
    end = (50 + draw(_grid(12)), 50 + draw(_grid(12)))
    if end == (50, 50):
        end = (60, 50)
    g = draw(st.sampled_from(("G2", "G3")))
    if draw(st.booleans()):
        chord2 = (end[0] - 50) ** 2 + (end[1] - 50) ** 2
        r = draw(st.integers(1, 20))
        if 4 * r * r < chord2:
            r = int(chord2 ** 0.5) // 2 + 1 + draw(st.integers(0, 5))
        words = f"R{r if draw(st.booleans()) else -r}"
    else:  # the centre on the perpendicular bisector: (end - start)/2 + k * perp
        k = draw(_grid(4))
        cx = F(end[0] - 50, 2) - k * (end[1] - 50)
        cy = F(end[1] - 50, 2) + k * (end[0] - 50)
        words = f"I{format_exact(cx)} J{format_exact(cy)}"
    text = (f"G17 G21 G90 G54\n{g} X{format_exact(F(end[0]))} Y{format_exact(F(end[1]))} {words} F100\n"
            "G1 X50 Y50\nM2\n")
    names = draw(st.lists(st.sampled_from(("start.X", "start.Y", "G54.X", "G54.Y")), min_size=1, max_size=3,
                          unique=True))
    ranges = []
    for name in names:
        lo = draw(st.sampled_from((F(-2), F(-1, 2), F(0), F(1, 4))))  # mostly holding the file's value
        hi = max(lo, F(0)) + draw(st.sampled_from((F(1, 4), F(1), F(2))))
        ranges.append(f"{name}={format_exact(lo)}..{format_exact(hi)}")
    return m, text, tuple(ranges)


def _concrete(text, machine):
    try:
        return verify_text(text, machine)
    except InputError:  # the controller refuses the arc at these values (its end is off its circle)
        return None


@settings(max_examples=25, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(varying_arc_cases())
def test_arcs_whose_ends_move_differently_agree_with_their_concrete_values(case):
    """`safe` over the ranges holds at the corners and the middle; a witness replays at its values."""
    m, text, params = case
    try:
        r = verify_text(text, m, params=list(params))
    except InputError:  # the arc is refused at the values the ranges are interpreted with
        assume(False)
        raise
    ranges = [(p.split("=")[0], *(F(x) for x in p.split("=")[1].split(".."))) for p in params]
    samples = [{n: lo for n, lo, _ in ranges}, {n: hi for n, _, hi in ranges},
               {n: (lo + hi) / 2 for n, lo, hi in ranges}]
    arc_excused = any(x.span is not None and x.span.line <= 2 for x in r.reasons)
    for values in samples:
        at = _concrete(text, machine_at(m, values))
        if at is None:
            continue
        if any(v.line == 2 for v in at.violations):
            assert any(v.line == 2 for v in r.violations) or arc_excused, (values, r.verdict, r.reasons)
    for v in r.violations:
        if v.line != 2:
            continue
        values = dict(v.params)
        assert all(lo <= values[n] <= hi for n, lo, hi in ranges if n in values)
        replay = _concrete(text, machine_at(m, values))
        assert replay is not None and any(w.line == 2 for w in replay.violations), (values, replay)
