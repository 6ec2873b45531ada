"""Fixtures shared by every test folder (issue 34).  The test machines live in tests/machines/ (one TOML file
each, see tests/machines/__init__.py); a test that needs one as a file on disk asks for ``machine_file``."""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile
from collections.abc import Callable
from pathlib import Path

import pytest

from tests.machines import machine_text

# cli/linuxcnc/frontend.py runs under LinuxCNC's system Python with its `linuxcnc` module
# (tests/cli/test_linuxcnc_filter.py starts it through the linuxcnc launcher); it is not a module of the test
# suite.  (It had a conftest.py of its own, whose module name "conftest" clashed with this file's: the folders
# without __init__.py share one module namespace.)
collect_ignore = ["cli/linuxcnc/frontend.py"]


def pytest_configure(config: pytest.Config) -> None:
    """The machine-file parse cache (nczones/machine_cache.py) of this test process and the programs it starts:
    a fresh folder, removed at exit, never the user's ~/.cache (each xdist worker makes its own)."""
    folder = tempfile.mkdtemp(prefix="nczones-cache-")
    os.environ["NCZONES_CACHE_DIR"] = folder
    atexit.register(shutil.rmtree, folder, True)


@pytest.fixture
def machine_file(tmp_path: Path) -> Callable[..., Path]:
    """``machine_file(name, set=..., extra=...)``: the machine written to ``tmp_path/<name>.toml`` (a variant
    keeps the name: one variant per test)."""

    def write(name: str, *, set: dict[str, object] | None = None, extra: str = "") -> Path:  # noqa: A002
        path = tmp_path / f"{name}.toml"
        path.write_text(machine_text(name, set=set, extra=extra), encoding="utf-8")
        return path

    return write
