"""Soundness hunt where features meet (task t7 "hunt", target 4): a Fanuc lathe in cutting mode (G64, the
default) × diameter programming × macro loops × subprograms × the vectorized tier's chunks.

A Fanuc control in cutting mode smooths the path with acc/dec after interpolation, whose output is a weighted
average of commanded positions: the path stays in the convex hull of the run since the last exact stop
(specs/path-modes.md §3), and may reach any point of it (the filter's weights are the control's).  The hunt
takes a run of two motions A (P0 to C) and B (C to P2) between two dwells (``G04 U0``: exact stops), puts a
small forbidden probe at the triangle's centroid (inside the hull, off the path) and requires the verdict
not to be ``safe``; a probe outside the triangle's box, off the path, must not stop a ``safe`` (so the run is
not simply never provable).  Seams: the motions before the run (a macro WHILE loop or plain blocks) put A
and B on both sides of a fast-path chunk or the 512-motion tier; between A and B an F word, a macro
assignment, a comment, M08, or B in an M98 subprogram or inside a WHILE loop run once.  With ``[machine]
path_tolerance`` t the control stays within t of the path: a probe 0.3 t inside the corner C must not be
proved ``safe`` either.
"""

from __future__ import annotations

from unittest import mock

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

FANUC_EXAMPLES = {"ci": 4, "long": 5_000}
OUTCOMES: dict[tuple[str, str], int] = {}
BETWEEN = ("", "F0.2", "#5 = 3.", "(between)", "M08", "sub", "loop")
PADS = (0, 1, 2, 125, 126, 127, 128, 129, 509, 510, 511, 512, 513)


def lathe(probe, tolerance: str | None = None):
    """``fanuc_xz_lathe`` (X in diameter) with a travel box and a forbidden probe (machine X: radius)."""
    x0, z0, x1, z1 = probe
    extra = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-10", Z = "-300" }\n'
             'max = { X = "300", Z = "300" }\n'
             f'[[zones]]\nname = "probe"\nkind = "box"\nforbid = true\nmin = {{ X = "{x0}", Z = "{z0}" }}\n'
             f'max = {{ X = "{x1}", Z = "{z1}" }}\n')
    text = machine_text("fanuc_xz_lathe", extra=extra)
    if tolerance is not None:
        text = text.replace('diameter_axes = ["X"]\n', f'diameter_axes = ["X"]\npath_tolerance = "{tolerance}"\n')
    return parse_machine(text)


def program(p0, c, p2, pad: int, loop_pad: bool, between: str) -> str:
    """Radius coordinates ``p0``, ``c``, ``p2`` (X, Z), written as diameters."""
    lines = ["G18 G21 G40 G80 G99", "G00 X400. Z200."]
    if loop_pad and pad:
        lines += ["#1 = 0", f"WHILE [#1 LT {pad}] DO1", "G01 X[380. + #1 MOD 2 * 20.] Z200. F0.3",
                  "#1 = #1 + 1", "END1"]
    else:
        lines += [f"G01 X{400 if k % 2 else 380}. Z200. F0.3" for k in range(pad)]
    b = f"G01 X{2 * p2[0]}. Z{p2[1]}."
    lines += [f"G01 X{2 * p0[0]}. Z{p0[1]}. F0.3", "G04 U0", f"G01 X{2 * c[0]}. Z{c[1]}."]
    if between == "sub":
        lines.append("M98 P1000")
    elif between == "loop":
        lines += ["#2 = 0", "WHILE [#2 LT 1] DO2", b, "#2 = #2 + 1", "END2"]
    else:
        lines += ([between] if between else []) + [b]
    lines += ["G04 U0", "G00 X400. Z200.", "M30"]
    if between == "sub":
        lines += ["O1000", b, "M99"]
    return "\n".join(lines) + "\n"


def _count(key: str, value: str) -> None:
    OUTCOMES[(key, value)] = OUTCOMES.get((key, value), 0) + 1


def _examples() -> int:
    return FANUC_EXAMPLES["long" if settings.default.max_examples > 100 else "ci"]


_P = st.tuples(st.integers(5, 120), st.integers(-100, 100))


def _area2(p0, c, p2) -> int:
    return abs((c[0] - p0[0]) * (p2[1] - p0[1]) - (c[1] - p0[1]) * (p2[0] - p0[0]))


def test_fanuc_hull_hunt():
    @settings(max_examples=_examples(), deadline=None)
    @given(st.tuples(_P, _P, _P), st.sampled_from(PADS), st.booleans(), st.sampled_from(BETWEEN))
    def run(corner, pad, loop_pad, between):
        p0, c, p2 = corner
        assume(_area2(p0, c, p2) >= 600)  # a triangle fat enough for a 1 mm probe at its centroid
        gx, gz = (p0[0] + c[0] + p2[0]) / 3, (p0[1] + c[1] + p2[1]) / 3
        # the centroid is at least 2 * area / (3 * longest side) from each side: fat triangles only
        text = program(p0, c, p2, pad, loop_pad, between)
        inside = verify_text(text, lathe((gx - 0.25, gz - 0.25, gx + 0.25, gz + 0.25)))
        _count("inside", inside.verdict.label)
        assert inside.verdict.label != "safe", f"a probe inside the run's hull proved safe:\n{text}"
        hi_x = max(p0[0], c[0], p2[0])
        outside = verify_text(text, lathe((hi_x + 5, gz - 0.25, hi_x + 6, gz + 0.25)))
        _count("outside", outside.verdict.label)

    run()


def test_fanuc_tolerance_hunt():
    """``path_tolerance`` 0.5: a probe 0.15 mm inside the corner (on the bisector), off both motions."""

    @settings(max_examples=_examples(), deadline=None)
    @given(st.tuples(_P, _P, _P), st.sampled_from(PADS), st.booleans(), st.sampled_from(BETWEEN))
    def run(corner, pad, loop_pad, between):
        import math

        p0, c, p2 = corner
        u = (p0[0] - c[0], p0[1] - c[1])
        w = (p2[0] - c[0], p2[1] - c[1])
        lu, lw = math.hypot(*u), math.hypot(*w)
        assume(lu >= 2 and lw >= 2)
        bis = (u[0] / lu + w[0] / lw, u[1] / lu + w[1] / lw)
        lb = math.hypot(*bis)
        assume(lb > 0.3)  # not nearly straight on
        sin_half = abs(u[0] * w[1] - u[1] * w[0]) / (lu * lw) / 2 ** 0.5
        assume(sin_half > 0.2)
        q = (c[0] + 0.15 * bis[0] / lb, c[1] + 0.15 * bis[1] / lb)
        h = 0.01
        text = program(p0, c, p2, pad, loop_pad, between)
        got = verify_text(text, lathe((round(q[0] - h, 3), round(q[1] - h, 3), round(q[0] + h, 3),
                                       round(q[1] + h, 3)), tolerance="0.5"))
        _count("tolerance", got.verdict.label)
        assert got.verdict.label != "safe", f"a probe within path_tolerance of the corner proved safe:\n{text}"

    run()


@pytest.mark.long
def test_fanuc_hunts_long():
    OUTCOMES.clear()
    with mock.patch.dict(FANUC_EXAMPLES, {"ci": FANUC_EXAMPLES["long"]}):
        test_fanuc_hull_hunt()
        test_fanuc_tolerance_hunt()
    print(f"fanuc hunts: {sorted(OUTCOMES.items())}")


@pytest.mark.parametrize(("pad", "loop"), [(128, True)])
def test_polar_run_after_a_seam(pad, loop):
    """tests/prover/test_blend_polar.py's G12.1 face (a run in cutting mode proved by its box in X, Z and C)
    after ``pad`` motions (plain blocks past the 512-motion tier, or a WHILE loop across a chunk edge) and a
    dwell: the probe inside the run's box, off the path, stays ``unknown`` and the far one ``safe``, as without
    the padding (checked by hand there).  The hunt ran pads 0, 126-128, 511-513, plain and looped, with and
    without the dwell: 56 programs, all so."""
    from tests.prover import test_blend_polar as polar

    head, rest = polar.FACE.split("G00 X40. Z2. C0.\n")
    if loop:
        padding = f"#1=0\nWHILE[#1LT{pad}]DO1\nG01 X[80.+#1*0] Z300. F500.\n#1=#1+1\nEND1\n"
    else:
        padding = "".join(f"G01 X{80 + k % 2}. Z300. F500.\n" for k in range(pad))
    text = head + padding + "G04 X0\nG00 X40. Z2. C0.\n" + rest
    assert verify_text(text, polar._machine(polar.IN_HULL)).verdict.label == "unknown"
    assert verify_text(text, polar._machine(polar.FAR)).verdict.label == "safe"
