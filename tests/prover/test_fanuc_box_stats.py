"""The Fanuc box route's stats are the full path's (codes36, item 3).

The route (:mod:`nczones.prover.fanucboxes`) proves a program by one box and decides no motion on its own; its
report must still count what the full path counts for the same program: the blocks executed, the motions, the
motions by kind (``stats.profile``), and the interpretation's counts.  ``slowest`` is there, empty: no motion
was decided one by one (as on the double pass).  Helices are left out here: the route counts them among the
arcs (as the vectorized screen does), the per-motion proof labels them ``helix``.
"""

from __future__ import annotations

import pytest

from nczones.prover import fanucboxes, verify_text
from tests.gcode.fanuc.helpers import mill

MACHINE = mill()
#: straight moves, R and I/J arcs, a rapid, a dwell, non-motion blocks after the last motion
PROGRAM = ("O1\nG90 G17 G21 G54 G00 X0. Y0. Z0.\nG01 F500.\nG1 X10. Y5.\nG2 X14. Y5. R2.5\nG3 X10. Y5. I-2.\n"
           "G0 Z5.\nG4 X1.\nG18 G2 Z2. X14. R3.\nM5\nM9\nM30\n")
LOOP = "O1\nG90 G17 G21 G54 G00 X0. Y0. Z0.\nG01 F500.\n#1 = 0\nWHILE [#1 LT 40] DO1\nG1 X[#1] Y5.\n" \
       "G2 X[#1 + 4] Y5. R2.\n#1 = #1 + 1\nEND1\nM5\nM30\n"


def _stats(text: str, route: bool) -> tuple:
    saved = fanucboxes.ROUTE
    fanucboxes.ROUTE = route
    try:
        r = verify_text(text, MACHINE)
    finally:
        fanucboxes.ROUTE = saved
    prof = r.profile
    kinds = {k: v["motions"] for k, v in prof["kinds"].items()}
    return (r.verdict.label, prof["blocks"], prof["motions"], kinds, r.extra["counts"], dict(r.stats)["segments"],
            "slowest" in prof, "fanuc_boxes" in dict(r.stats))


@pytest.mark.parametrize("text", [PROGRAM, LOOP, PROGRAM.replace("M30\n", "") + "G1 X1.\nM30\n"],
                         ids=["plain", "loop", "ends-moving"])
def test_the_route_counts_what_the_full_path_counts(text):
    routed, full = _stats(text, True), _stats(text, False)
    assert routed[-1] and not full[-1]  # the route proved it; the full path ran without it
    assert routed[:-1] == full[:-1]
    assert routed[1] == routed[4]["blocks"] and routed[3], routed  # every block executed; kinds counted
