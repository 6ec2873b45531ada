"""The nose radius's module is imported for a lathe only (issue 36, boot44): the pipeline's stand-in gives what
:func:`nczones.prover.nose.nose_zones` gives on every test machine and every machine of specs/machines."""

from __future__ import annotations

from pathlib import Path

import pytest

from nczones.machine import load_machine
from nczones.pipeline.verification import _nose_zones
from nczones.prover.nose import nose_zones
from tests.machines import machine_path, names

ROOT = Path(__file__).resolve().parents[2]
FILES = [machine_path(n) for n in names()] + sorted((ROOT / "specs" / "machines").glob("*.toml"))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_the_stand_in_is_nose_zones(path):
    try:
        machine = load_machine(str(path))
    except Exception:  # noqa: BLE001 - a machine file that does not load (a test of its errors): nothing to compare
        pytest.skip("not a loadable machine")
    ours, theirs = _nose_zones(machine), nose_zones(machine)
    assert ours == theirs
    if not machine.is_lathe:
        assert ours[0] is machine and ours[1:] == (None, None)


def test_a_lathe_with_a_nose_radius_is_among_them():
    # the comparison above reaches nose_zones' own work: some machine is a lathe whose tip zones it enlarges
    grown = [p for p in FILES if (m := _try(p)) is not None and m.is_lathe and nose_zones(m)[1] is not None]
    assert grown


def _try(path: Path):
    try:
        return load_machine(str(path))
    except Exception:  # noqa: BLE001
        return None
