"""import-machine reads the INI's maximum accelerations into ``[machine.acceleration]`` (issue 35).

LinuxCNC 2.9 (``src/emc/ini/iniaxis.cc``, ``inijoint.cc``, ``initraj.cc``): ``[AXIS_<L>] MAX_ACCELERATION``
(default ``DEFAULT_AXIS_MAX_ACCELERATION`` = 1 unit/s^2), ``[JOINT_<n>] MAX_ACCELERATION`` (the joint's
limit; with identity kinematics the axis cannot accelerate faster than its joint), ``[TRAJ]
MAX_LINEAR_ACCELERATION`` (2.7: ``MAX_ACCELERATION``; default 1e99), the cap of coordinated linear moves.
The machine file takes the smallest, in mm/s^2 (inch x 25.4).
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest

from nczones.controller.blending import blends
from nczones.errors import MachineImportError
from nczones.imports import import_machine
from nczones.machine import parse_machine

F = Fraction
BASE = "[TRAJ]\nCOORDINATES = X Y Z\nLINEAR_UNITS = mm\n"


def _ini(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "m.ini"
    p.write_text(text)
    return p


def test_acceleration_is_the_smallest_of_axis_joint_and_trajectory_limits(tmp_path):
    p = _ini(tmp_path, BASE.replace("mm\n", "mm\nMAX_LINEAR_ACCELERATION = 400\n")
             + "[AXIS_X]\nMAX_ACCELERATION = 800\n[JOINT_0]\nMAX_ACCELERATION = 600\n"
             "[AXIS_Y]\nMAX_ACCELERATION = 300\n[JOINT_1]\nMAX_ACCELERATION = 350\n")
    r = import_machine(p)
    m = r.machine
    assert [m.axis(a).accel_mm_s2 for a in "XYZ"] == [F(400), F(300), F(1)]  # Z: LinuxCNC's default 1 mm/s^2
    assert any(n.code == "IM203" and "MAX_ACCELERATION" in n.message for n in r.notes)
    # the written machine file reads back with the same values
    again = parse_machine(r.text)
    assert [again.axis(a).accel_mm_s2 for a in "XYZ"] == [F(400), F(300), F(1)]


def test_inch_acceleration_converts_exactly(tmp_path):
    p = _ini(tmp_path, "[TRAJ]\nCOORDINATES = X Z\nLINEAR_UNITS = inch\n[AXIS_X]\nMAX_ACCELERATION = 20.5\n"
             "[AXIS_Z]\nMAX_ACCELERATION = 30\n")
    m = import_machine(p).machine
    assert (m.axis("X").accel_mm_s2, m.axis("Z").accel_mm_s2) == (F("520.7"), F(762))


@pytest.mark.parametrize("value", ["0", "-5"])
def test_a_non_positive_acceleration_is_refused(tmp_path, value):
    p = _ini(tmp_path, BASE + f"[AXIS_X]\nMAX_ACCELERATION = {value}\n")
    with pytest.raises(MachineImportError) as e:
        import_machine(p)
    assert "IM108" in [d.code for d in e.value.diagnostics]


def test_an_imported_machine_in_g64_blends_in_the_controller(tmp_path):
    p = _ini(tmp_path, BASE + "[AXIS_X]\nMAX_ACCELERATION = 500\n[AXIS_Y]\nMAX_ACCELERATION = 500\n"
             "[AXIS_Z]\nMAX_ACCELERATION = 500\n")
    assert blends(import_machine(p).machine, "auto")
    p = _ini(tmp_path, BASE + "[RS274NGC]\nRS274NGC_STARTUP_CODE = G21 G61\n")
    assert not blends(import_machine(p).machine, "auto")
