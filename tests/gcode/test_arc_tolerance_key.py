"""``[machine] arc_tolerance`` and Grbl's arc rule (issue 38).

Grbl's gcode.c (gnea/grbl, the I/J branch of the arc checks), in mm after unit conversion::

    delta_r = fabs(target_r - gc_block.values.r);
    if (delta_r > 0.005) {
      if (delta_r > 0.5) FAIL(...);                       // [Arc definition error] > 0.5mm
      if (delta_r > (0.001*gc_block.values.r)) FAIL(...); // > 0.005mm AND 0.1% radius
    }

and for R arcs ``h_x2_div_d = 4*r*r - x*x - y*y; if (h_x2_div_d < 0) FAIL(...)``: no tolerance.  nczones's
``"grbl"`` rule accepts the 0.005 mm part (bounding the gap between Grbl's path and the spiral it proves)
and refuses more.  The Grbl import writes it, so Grbl's own HelloWorld.nc (CamBam, 4-decimal inches whose
arcs are off by up to 0.0021 mm, more than nczones's default 0.002 mm) is read.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nczones.errors import GcodeError
from nczones.imports import import_machine
from nczones.machine import parse_machine
from nczones.prover import verify, verify_text
from nczones.prover.core import Verdict

ROOT = Path(__file__).resolve().parents[2]
HELLO = Path("/work/shared/corpus/grbl/sim/HelloWorld.nc")


def _machine(rule: str | None) -> object:
    key = "" if rule is None else f"arc_tolerance = {rule}\n"
    return parse_machine(f"""
[machine]
axes = ["X", "Y", "Z"]
pulse = "0.001"
{key}[machine.rapid]
X = "5000"
Y = "5000"
Z = "5000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "-100", Y = "-100", Z = "-100" }}
max = {{ X = "100", Y = "100", Z = "100" }}
""")


def _program(arc: str, filler: int = 0, hash_: bool = False) -> str:
    # start (0, 0); I/J arcs with centre (10, 0): the start radius is 10 mm
    fill = "".join(f"G1 X{(k % 5) / 10} Y0\n" for k in range(filler)) + ("G1 X0 Y0\n" if filler else "")
    head = "#1 = 0\nG0 X#1 Y0\n" if hash_ else "G0 X0 Y0\n"
    return "G21 G90 G17 G54 F600\n" + head + fill + arc + "\nM2\n"


# G2 X20.004 Y0 I10 J0: end radius 10.004, 0.004 mm off: Grbl accepts (delta_r <= 0.005)
OFF_4 = "G2 X20.004 Y0 I10 J0"
# 0.02 mm off at radius 10: > 0.005 and > 0.1 % of 10 mm (0.01): Grbl refuses too
OFF_20 = "G2 X20.02 Y0 I10 J0"
# R9.9995 for a 20 mm chord: 4r^2 - 400 < 0, Grbl refuses; nczones's default (0.002 mm) takes it as a half circle
R_SHORT = "G2 X20 Y0 R9.9995"


@pytest.mark.parametrize("filler, hash_", [(0, False), (600, False), (0, True)])
def test_grbl_rule_accepts_what_grbl_accepts_in_every_lane(filler, hash_):
    text = _program(OFF_4, filler, hash_)
    with pytest.raises(GcodeError) as e:  # the default 0.002 mm refuses it
        verify_text(text, _machine(None))
    assert e.value.diagnostics[0].code == "GC301"
    r = verify_text(text, _machine('"grbl"'))
    assert r.verdict == Verdict.SAFE, r.reasons
    assert dict(r.settings)["arc_tolerance"] == "grbl"
    r = verify_text(text, _machine('"0.005"'))  # a length in the machine file works the same
    assert r.verdict == Verdict.SAFE


@pytest.mark.parametrize("arc, code", [(OFF_20, "GC301"), (R_SHORT, "GC302")])
def test_grbl_rule_refuses_what_grbl_refuses(arc, code):
    with pytest.raises(GcodeError) as e:
        verify_text(_program(arc), _machine('"grbl"'))
    assert e.value.diagnostics[0].code == code


def test_the_command_line_tolerance_overrides_the_machine_file():
    text = _program(OFF_4)
    with pytest.raises(GcodeError):
        verify_text(text, _machine('"grbl"'), arc_tolerance="0.002")
    assert verify_text(_program(R_SHORT), _machine(None)).verdict == Verdict.SAFE  # the default: 0.002 mm


def test_a_bad_arc_tolerance_is_zn114():
    from nczones.errors import MachineFileError

    with pytest.raises(MachineFileError) as e:
        _machine('"fanuc"')
    assert e.value.diagnostics[0].code == "ZN114"


@pytest.mark.skipif(not HELLO.exists(), reason="the corpus is not here")
def test_grbls_hello_world_is_read_with_the_imported_machine(tmp_path):
    im = import_machine(ROOT / "tests" / "golden" / "import" / "grbl" / "router_grbl11.settings")
    assert 'arc_tolerance = "grbl"' in im.text and im.machine.arc_tolerance == "grbl"
    r = verify(HELLO, im.machine)
    assert r.verdict == Verdict.SAFE, r.reasons  # read to the end (the router's travel holds it), not refused
