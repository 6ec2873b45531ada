"""A small program is verified without numpy: the full interpreter alone, every motion decided exactly.

Below ``FAST_PATH_MIN_LINES`` lines ``verify`` does not take the vectorized fast path, and a run that has
met fewer than ``SCREEN_MIN_SEGMENTS`` motions decides them one by one on the exact path (Fractions, then
Z3) instead of the integer column screen, so a small verify never loads numpy (``tests/cli/test_startup.py``
checks that in a fresh interpreter).  The two paths must give the same answer: on generated programs
(lines, rapids, arcs, expressions) against travel boxes, forbid boxes, stepped tables, tool-tip zones and
allow and forbid polygons, with margins and ``--param`` ranges, the verdict and the violating blocks are
the same on the numpy-free path, on the vectorized path (fast path and column screen forced for any size)
and, where Z3 decides, with Z3 sent every motion.
"""

from __future__ import annotations

import os
from fractions import Fraction as F

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.pipeline.verification as prover_api
import nczones.prover.core as core
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.prover.test_segment_batches import MACHINE as BATCH_MACHINE
from tests.prover.test_segment_batches import by_columns, dec, t

#: test_segment_batches' machine (travel box, forbid box, stepped table, tool-tip floor) with a rapid mode to draw.
MACHINE = BATCH_MACHINE.replace("[machine.rapid]", 'rapid_mode = "{rapid}"\n[machine.rapid]', 1)

ALLOW_POLYGON = """
[[zones]]
name = "outline"
kind = "polygon"
plane = ["X", "Y"]
vertices = [["0", "0"], ["{xmax}", "0"], ["{xmax}", "{ymax}"], ["{nx1}", "{ymax}"], ["{nmid}", "{ny}"],
            ["{nx0}", "{ymax}"], ["0", "{ymax}"]]
"""

FORBID_POLYGON = """
[[zones]]
name = "fixture"
kind = "polygon"
forbid = true
plane = ["X", "Y"]
vertices = [["{px}", "{py}"], ["{px2}", "{py}"], ["{pmx}", "{py2}"]]
"""


@st.composite
def machines(draw):
    """Boxes, a forbid box, a stepped table and a tool-tip floor; an allow polygon with a notch in its top
    edge and a forbid triangle, each present or not."""
    xmax, ymax = dec(draw, 60, 90, 1), dec(draw, 60, 90, 1)
    cx0, cy0 = dec(draw, 10, 70, 1), dec(draw, 10, 70, 1)
    v = dict(dialect="linuxcnc", rapid=draw(st.sampled_from(["linear", "dogleg"])), xmax=xmax, ymax=ymax, cx0=cx0, cy0=cy0,
             cx1=cx0 + dec(draw, 1, 15, 1), cy1=cy0 + dec(draw, 1, 15, 1), step=dec(draw, 30, 80, 1),
             ystep=ymax - dec(draw, 0, 10, 1), g55x=dec(draw, -5, 5, 2), g55y=dec(draw, -5, 5, 2),
             h1=dec(draw, 10, 30, 2), floor=dec(draw, -80, -20, 1))
    text = MACHINE
    if draw(st.booleans()):
        nx0 = dec(draw, 10, 40, 1)
        v.update(nx0=nx0, nx1=nx0 + dec(draw, 4, 20, 1), nmid=nx0 + 2, ny=ymax - dec(draw, 5, 40, 1))
        text += ALLOW_POLYGON
    if draw(st.booleans()):
        px, py = dec(draw, 5, 60, 1), dec(draw, 5, 60, 1)
        v.update(px=px, py=py, px2=px + dec(draw, 3, 20, 1), pmx=px + 1, py2=py + dec(draw, 3, 20, 1))
        text += FORBID_POLYGON
    return parse_machine(text.format(**{k: x if isinstance(x, str) else t(x) for k, x in v.items()}))


def coord(draw):
    return t(dec(draw, 0, 62, 2))


@st.composite
def motions(draw):
    """One motion: a rapid or a line (literals or expressions), or an arc (I/J, exact, quarter to full)."""
    kind = draw(st.sampled_from(["G0", "G1", "G1", "expr", "arc"]))
    if kind == "expr":
        return [f"#1 = [SIN[{draw(st.integers(0, 90))}] * {draw(st.integers(0, 4))}]",
                f"G1 X[#1 + {coord(draw)}] Y[{coord(draw)} - #1]"]
    if kind == "arc":
        cx, cy, r = dec(draw, 12, 50, 1), dec(draw, 12, 50, 1), dec(draw, 1, 12, 1)
        turn = draw(st.sampled_from([(1, 0), (0, 1), (-1, 0), (0, -1)]))
        g = draw(st.sampled_from(["G2", "G3"]))
        return [f"G1 X{t(cx + r)} Y{t(cy)}",
                f"{g} X{t(cx + r * turn[0])} Y{t(cy + r * turn[1])} I{t(-r)} J0"]
    z = f" Z{t(dec(draw, -40, 30, 1))}" if draw(st.booleans()) else ""
    return [f"{kind} X{coord(draw)} Y{coord(draw)}{z}"]


@st.composite
def programs(draw):
    lines = ["G21 G90 G17 G54 F500"] + (["G43 H1"] if draw(st.booleans()) else [])
    for _ in range(draw(st.integers(1, 5))):
        if draw(st.integers(0, 5)) == 0:
            lines.append(draw(st.sampled_from(["G55", "G54"])))
        lines += draw(motions())
    return "\n".join(lines + ["M2"]) + "\n"


params = st.sampled_from([(), ("G55.X", F(1, 2)), ("G55.Y", F(2)), ("H1", F(1)), ("start.Z", F(3, 2))])


def blocks(r):
    return [v.block for v in r.violations]


#: 12 fixed draws in the default run (25 random ones took about 40 s of it); a hunt:
#: NCZONES_SMALL_PROGRAM_EXAMPLES=500 (randomized above 25)
SMALL_EXAMPLES = int(os.environ.get("NCZONES_SMALL_PROGRAM_EXAMPLES", "12"))


@settings(max_examples=SMALL_EXAMPLES, deadline=None, derandomize=SMALL_EXAMPLES <= 25,
          suppress_health_check=[HealthCheck.too_slow])
@given(machines(), programs(), st.sampled_from([F(0), F(0), F(1, 2), F(13, 10)]), params)
def test_the_numpy_free_path_agrees_with_the_vectorized_path_and_z3(machine, program, margin, param):
    if param:
        name, width = param
        if name == "H1":
            h = machine.tool_length(1)
            ranges = [f"H1={t(h - width)}..{t(h + width)}"]
        else:
            ranges = [f"{name}={t(-width)}..{t(width)}"]
    else:
        ranges = []
    options = dict(margin=margin, params=ranges, max_violations=4)
    small = verify_text(program, machine, **options)
    assert small.extra["counts"]["fast_lines"] == 0 and small.profile["motions_screened_vectorized"] == 0
    with by_columns():
        columns = verify_text(program, machine, **options)
    assert (small.verdict, blocks(small)) == (columns.verdict, blocks(columns)), (program, ranges)
    assert sorted(r.code for r in small.reasons) == sorted(r.code for r in columns.reasons)
    z3 = verify_text(program, machine, engine="z3", **options)
    if "unknown" not in (z3.verdict.label, small.verdict.label):
        assert (small.verdict, blocks(small)) == (z3.verdict, blocks(z3)), (program, ranges)


def test_the_thresholds_choose_the_path(monkeypatch):
    machine = parse_machine(MACHINE.format(dialect="linuxcnc", rapid="linear", xmax="80", ymax="80", cx0="70", cy0="70", cx1="75",
                                           cy1="75", step="60", ystep="80", g55x="0", g55y="0", h1="20",
                                           floor="-50"))
    lines = [f"G1 X{10 + k % 7}.{k % 10} Y{20 + k % 5}.5" for k in range(600)]
    head = "G21 G90 G17 G54 F500\n"

    def run(n: int):
        return verify_text(head + "\n".join(lines[:n]) + "\nM2\n", machine)

    small = run(prover_api.FAST_PATH_MIN_LINES - 10)
    large = run(prover_api.FAST_PATH_MIN_LINES + 10)
    assert small.verdict.label == large.verdict.label == "safe"
    assert small.extra["counts"]["fast_lines"] == 0 and small.profile["motions_screened_vectorized"] == 0
    assert "double_pass" not in small.profile
    # a plain LinuxCNC program of FAST_PATH_MIN_LINES lines up to PLAIN_PASS_SIZE: the double pass first (issue 36)
    assert large.profile["double_pass"]["motions"] == large.profile["motions"] == prover_api.FAST_PATH_MIN_LINES + 10
    from nczones.pipeline import verification

    monkeypatch.setattr(verification, "PLAIN_PASS_SIZE", prover_api.FAST_PATH_MIN_LINES)  # larger: the fast path
    large = run(prover_api.FAST_PATH_MIN_LINES + 10)
    assert large.extra["counts"]["fast_lines"] > 0 and large.profile["motions_screened_vectorized"] > 0
    assert core.SCREEN_MIN_SEGMENTS <= prover_api.FAST_PATH_MIN_LINES  # a program read fast is screened too
