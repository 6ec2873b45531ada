"""The double pass imports cutter compensation only for a program or machine that compensates (issue 36, boot44).

``nczones.gcode.linuxcnc.doubles`` stands for :mod:`~nczones.gcode.linuxcnc.double_comp`'s functions until a block
writes G40/G41/G42 or the machine compensates: the stand-ins give what the module's functions give (they are
asked with no compensation state, ``cc`` None), and a plain program's pass leaves the module unimported.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import double_comp, doubles

ROOT = Path(__file__).resolve().parents[2]


class _State:
    cc = None


groups = st.dictionaries(st.sampled_from(["comp", "motion", "plane", "units", "tool"]),
                         st.sampled_from([0, 1, 17, 20, 40, 41, 42, -411, -421]), max_size=4)
others = st.lists(st.sampled_from(["D", "P", "Q", "R", "I", "J", "K", "L", "S"]), max_size=5)


def _outcome(f, *args):
    try:
        return "value", f(*args)
    except doubles.Declined as exc:
        return "declined", str(exc)


@settings(max_examples=300, deadline=None)
@given(groups, others, st.lists(st.sampled_from([3, 5, 6, 61]), max_size=2), st.lists(st.integers(0, 9), max_size=1))
def test_the_stand_ins_give_what_the_module_gives_without_compensation(g, words, ms, ts):
    assert doubles.comp_others(g, words) == double_comp.comp_others(g, words)
    assert _outcome(doubles.comp_body, _State(), g, ms, ts, [], words, doubles.Declined) == \
        _outcome(double_comp.comp_body, _State(), g, ms, ts, [], words, doubles.Declined)


@pytest.mark.parametrize("text, loaded", [
    ("G21 G90 G17 F100\n" + "".join(f"G1 X{k} Y{k % 7}\n" for k in range(40)) + "G2 X50 Y0 R30\nM2\n", False),
    ("G21 G90 G17 F100\nG40\nG1 X1 Y1\nM2\n", True),  # a compensation code: the module's own answer
])
def test_a_plain_pass_does_not_import_compensation(text, loaded):
    code = ("import sys\nfrom nczones.machine import load_machine\n"
            "from nczones.gcode.linuxcnc.doubles import double_pass\n"
            "m = load_machine('specs/machines/mill.toml')\n"
            f"path = double_pass({text!r}, m, max_iterations=1000)\n"
            "print(path.motions, 'nczones.gcode.linuxcnc.double_comp' in sys.modules,"
            " 'nczones.gcode.linuxcnc.comp_floats' in sys.modules)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    motions, comp, floats = r.stdout.split()
    assert int(motions) >= 1 and comp == floats == str(loaded)
