"""Fixtures shared by every test folder (issue 34).  The test machines live in tests/machines/ (one TOML file
each, see tests/machines/__init__.py); a test that needs one as a file on disk asks for ``machine_file``."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from tests.machines import machine_text


@pytest.fixture
def machine_file(tmp_path: Path) -> Callable[..., Path]:
    """``machine_file(name, set=..., extra=...)``: the machine written to ``tmp_path/<name>.toml`` (a variant
    keeps the name: one variant per test)."""

    def write(name: str, *, set: dict[str, object] | None = None, extra: str = "") -> Path:  # noqa: A002
        path = tmp_path / f"{name}.toml"
        path.write_text(machine_text(name, set=set, extra=extra), encoding="utf-8")
        return path

    return write
