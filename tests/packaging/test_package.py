"""The package's own checks stay complete (issue 20): mypy covers every module of ``nczones``."""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_mypy_checks_every_nczones_module():
    """No module of the package is exempt from type checking (the list of exemptions is gone, not growing)."""
    mypy = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["mypy"]
    assert mypy["files"] == ["nczones"]
    assert mypy["check_untyped_defs"] and mypy["strict_optional"] and mypy["warn_return_any"]
    exempt = [o["module"] for o in mypy.get("overrides", ())
              if o.get("ignore_errors") or o.get("follow_imports") == "skip"]
    assert exempt == []
    for override in mypy.get("overrides", ()):
        modules = override["module"] if isinstance(override["module"], list) else [override["module"]]
        assert not [m for m in modules if m == "nczones" or m.startswith("nczones.")], override
