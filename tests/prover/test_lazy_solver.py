"""Z3 is loaded at the first solver query: a program the exact tiers decide never loads it.

The report still names the Z3 version (from the METADATA of the z3-solver wheel beside the ``z3`` package
until Z3 is loaded, without importing ``importlib.metadata``), the same string Z3 gives.
"""

from __future__ import annotations

import subprocess
import sys

SAFE_RUN = """
import sys
from nczones.machine import load_machine
from nczones.prover import verify_text
m = load_machine("specs/machines/mill.toml")
r = verify_text("G21 G90 G54\\nG0 X10 Y10 Z20\\nG1 X20 Y15 F300\\nM2\\n", m)
print(r.verdict.label, r.solver_version, "z3" in sys.modules or "importlib.metadata" in sys.modules)
import z3
print(z3.get_version_string())
"""

UNSAFE_RUN = """
import sys
from nczones.machine import load_machine
from nczones.prover import verify_text
m = load_machine("specs/machines/mill.toml")
r = verify_text("G21 G90 G54\\nG0 X10 Y10 Z20\\nG1 X900 F300\\nM2\\n", m)
print(r.verdict.label, "z3" in sys.modules, dict(r.stats)["z3_queries"])
"""


def _run(code: str) -> list[str]:
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return out.stdout.split("\n")


def test_a_program_the_exact_tiers_prove_does_not_load_z3():
    first, second = _run(SAFE_RUN)[:2]
    label, version, loaded = first.split()
    assert (label, loaded) == ("safe", "False")
    assert version == second  # the wheel's version is the library's


def test_a_query_loads_it():
    label, loaded, queries = _run(UNSAFE_RUN)[0].split()
    assert label == "unsafe" and int(queries) > 0 and loaded == "True"


def test_the_wheel_is_looked_for_where_an_import_would_find_z3():
    # issue 36: smt._find_spec stands for importlib.util.find_spec (not imported by a small verify)
    import importlib.util

    from nczones.prover.smt import _find_spec

    for name in ("z3", "fractions", "nczones", "no_such_module_for_nczones"):
        ours, theirs = _find_spec(name), importlib.util.find_spec(name)
        assert (ours is None) == (theirs is None), name
        assert ours is None or (ours.name, ours.origin) == (theirs.name, theirs.origin), name
