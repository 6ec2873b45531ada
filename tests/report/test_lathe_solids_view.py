"""Pictures match the proof for a lathe's turret tool solids (issue 39), and ``nczones replay`` confirms them.

The machine specs/machines/lathe_solids.toml: tool 1's offsets X 100, Z 150 (the tip is the controlled point
minus them), its parts relative to the tip: insert X -4..0 Z 0..5 (5 thick), bar X -17..-1 Z 5..35, bar
holder X -30..45 Z 35..95, 40 thick (the proof grows it by 20 on both X sides: X -50..65); the chuck a ring
of radii 25..100 over Z 0..60, the jaws a ring of radii 30..70 over Z 60..90 (machine X is a radius).

specs/examples/programs/boring_bar_hits_chuck.nc, line 7 ``Z-80.`` from ``X30. Z1.`` with G54 Z130 and the
tool offsets: the controlled point runs at X 15 + 100 = 115 from Z 1 + 130 + 150 = 281 to Z 200.  The holder
meets the jaws for controlled Z in the open interval (60 - 95 + 150, 90 - 35 + 150) = (115, 205) (and X:
the holder's -35..80 meets the ring's 30..70), i.e. for ``t`` in (76/81, 1] of ``281 - 81 t``; the prover
reports the middle t = 157/162, Z = 202.5.  There the tip is at X 15, Z 52.5: the holder spans X -35..80,
Z 87.5..147.5, and its overlap with the jaws' +X section is X 30..70 × Z 87.5..90, whose centre is the
witness X 50 Z 88.75."""

from __future__ import annotations

import json
import subprocess
import sys
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from nczones.replay import replay_report  # noqa: E402
from nczones.report.figure import plot_program  # noqa: E402
from nczones.report.html import render_html  # noqa: E402
from nczones.report.solids_view import contact_solids  # noqa: E402

from .helpers import EX, ROOT, run_example  # noqa: E402

HITS = "programs/boring_bar_hits_chuck.nc"
CLEARS = "programs/boring_bar_clears_chuck.nc"
MACHINE = "lathe_solids.toml"


@pytest.fixture(scope="module")
def hits():
    return run_example(HITS, MACHINE)


def _drawn(patch):
    return patch.get_patch_transform().transform_path(patch.get_path())


def test_the_drawn_turret_tool_is_the_machine_files_at_the_path_point(hits):
    result, _m = hits
    contacts = contact_solids(result)
    assert [v.line for _, v, _, _ in contacts] == [7, 8, 9]
    _i, v, parts, fx = contacts[0]
    assert dict(v.path_point) == {"X": 115, "Z": Fraction(405, 2)}  # the module docstring
    assert dict(v.point) == {"X": 50, "Z": Fraction(355, 4)}
    tx, tz = Fraction(15), Fraction(105, 2)  # the tip: the path point minus the offsets X 100, Z 150
    want = [("insert", (tx - 4 - Fraction(5, 2), tx + Fraction(5, 2)), (tz, tz + 5), False),
            ("bar", (tx - 17, tx - 1), (tz + 5, tz + 35), False),
            ("bar holder", (tx - 50, tx + 65), (tz + 35, tz + 95), True)]
    assert [(s.name, s.span("X"), s.span("Z"), hit) for s, hit in parts] == want
    assert (fx.name, fx.span("X"), fx.span("Z")) == ("jaws", (30, 70), (60, 90))  # the +X section entered
    for _i, v, parts, fx in contacts:  # every witness inside the entering part (closed) and the fixture (open)
        q = dict(v.point)
        s = next(s for s, hit in parts if hit)
        assert all(s.span(a)[0] <= q[a] <= s.span(a)[1] for a in "XZ")
        assert all(fx.span(a)[0] < q[a] < fx.span(a)[1] for a in "XZ")


def test_the_section_figure_draws_the_witness_inside_the_part_and_the_fixture(hits):
    result, m = hits
    fig = plot_program(str(EX / HITS), m, ("Z", "X"), result)
    patches = {p.get_gid(): p for p in fig.axes[0].patches if p.get_gid()}
    # the fixtures of revolution, both signs of X: the jaws' ring 30..70 and its mirror -70..-30
    for name, (lo, hi) in (("chuck", (25, 100)), ("jaws", (30, 70))):
        plus, minus = _drawn(patches[f"fixture-{name}"]).get_extents(), _drawn(
            patches[f"fixture-{name}-mirror"]).get_extents()
        assert (plus.y0, plus.y1) == pytest.approx((lo, hi)) and (minus.y0, minus.y1) == pytest.approx((-hi, -lo))
    assert {"tool-part-1-1", "tool-part-1-2"} <= set(patches)
    for i, v, parts, _fx in contact_solids(result):
        q = dict(v.point)
        zx = (float(q["Z"]), float(q["X"]))
        part, fixture = _drawn(patches[f"contact-part-{i}"]), _drawn(patches[f"contact-fixture-{i}"])
        assert part.contains_point(zx) and fixture.contains_point(zx), (i, zx)
        s = next(s for s, hit in parts if hit)
        ext = part.get_extents()
        assert (ext.x0, ext.x1) == pytest.approx([float(x) for x in s.span("Z")])
        assert (ext.y0, ext.y1) == pytest.approx([float(x) for x in s.span("X")])
    plt.close(fig)


def test_the_html_report_of_a_lathe_with_solids_renders():
    # it stopped with an AttributeError (a LatheFixture drawn as a box) before the lathe was drawn
    for program, unsafe in ((HITS, True), (CLEARS, False)):
        result, m = run_example(program, MACHINE)
        assert result.verdict.label == ("unsafe" if unsafe else "safe")
        page = render_html(result, m, str(EX / program), deterministic=True)
        assert 'fixture-jaws-mirror"' in page
        assert ('contact-part-1"' in page) == unsafe
        assert (contact_solids(result) != []) == unsafe


GOLDEN = EX / "reports" / "boring_bar_hits_chuck.json"  # tests/report/test_replay.py keeps it current


def _doc(hits):
    return json.loads(GOLDEN.read_text())


def test_the_lathe_report_replays_confirmed():
    # it stopped with RP104 (a witness without Y) before a lathe's solid violation was replayed
    r = subprocess.run([sys.executable, "-m", "nczones", "replay", str(GOLDEN)], capture_output=True, text=True,
                       cwd=ROOT)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.splitlines()[0] == (
        "specs/examples/programs/boring_bar_hits_chuck.nc:7: confirmed: the point X50 Z88.75 is inside the bar holder (X -30..45, Z 35..95 "
        "from the tip, 40 thick) of tool 1 placed at the path point X115 Z202.5 and inside fixture 'jaws' "
        "(exact, in the section through the spindle axis), and the path point lies on the line of block 4 "
        "exactly")
    assert r.stdout.splitlines()[-1] == "replay: 3 of 3 counterexamples confirmed"


@pytest.mark.parametrize("point, why", [
    # in the holder (X -35..80, Z 87.5..147.5) above the jaws' top Z 90
    ({"X": "50", "Z": "91"}, "but not inside fixture 'jaws'"),
    # in the holder, in the jaws' bore (radius < 30)
    ({"X": "29", "Z": "88"}, "but not inside fixture 'jaws'"),
    # in the jaws' ring, below the holder's bottom Z 87.5
    ({"X": "50", "Z": "87"}, "is not inside the part 'bar holder'"),
    # in the jaws' mirrored section (-70..-30), left of the holder's X -35
    ({"X": "-36", "Z": "88"}, "is not inside the part 'bar holder'"),
])
def test_a_moved_lathe_witness_is_not_reproduced(hits, point, why):
    doc = _doc(hits)
    doc["violations"] = doc["violations"][:1]
    doc["violations"][0]["point_exact"] = point
    (check,) = replay_report(doc, base=str(ROOT))
    assert not check.confirmed and why in check.message, check.message


def test_a_witness_in_the_mirrored_section_is_confirmed(hits):
    # X -33 is in the holder (-35..80) and in the jaws' -X section (-70..-30): a true contact too
    doc = _doc(hits)
    doc["violations"] = doc["violations"][:1]
    doc["violations"][0]["point_exact"] = {"X": "-33", "Z": "88"}
    (check,) = replay_report(doc, base=str(ROOT))
    assert check.confirmed, check.message
