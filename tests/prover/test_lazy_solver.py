"""Z3 is loaded at the first solver query: a program the exact tiers decide never loads it.

The report still names the Z3 version (from the METADATA of the z3-solver wheel beside the ``z3`` package
until Z3 is loaded, without importing ``importlib.metadata``), the same string Z3 gives.
"""

from __future__ import annotations

import subprocess
import sys

from hypothesis import given, settings
from hypothesis import strategies as st

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
    # issue 36: solver_version.find_spec stands for importlib.util.find_spec (not imported by a small verify)
    import importlib.util

    from nczones.prover.solver_version import find_spec

    for name in ("z3", "fractions", "nczones", "no_such_module_for_nczones"):
        ours, theirs = find_spec(name), importlib.util.find_spec(name)
        assert (ours is None) == (theirs is None), name
        assert ours is None or (ours.name, ours.origin) == (theirs.name, theirs.origin), name


def test_only_a_name_that_starts_with_z3_lowers_to_the_wheels_prefix():
    # issue 36 (boot44): wheel_infos lowers only the names that start with "z3" or "Z3": no other character's
    # lower case starts with "z" or "3" (so no other name's lower case starts with "z3_solver-")
    others = [c for c in map(chr, range(0x110000)) if c not in "zZ3" and c.lower()[:1] in ("z", "3")]
    assert others == []


@settings(max_examples=300, deadline=None)
@given(st.lists(st.text(st.sampled_from("zZ3_sSoOlLvVeErR-.distnfoſKİ"), max_size=20) | st.sampled_from(
    ["z3_solver-4.12.2.0.dist-info", "Z3_SOLVER-4.dist-info", "z3_solver-4.dist-INFO", "z3-4.dist-info"]), max_size=8))
def test_the_wheel_s_folders_are_those_the_whole_rule_finds(names):
    from nczones.prover.solver_version import wheel_infos

    assert wheel_infos(names) == [n for n in names if n.lower().startswith("z3_solver-") and n.endswith(".dist-info")]


def test_the_double_pass_names_the_solver_without_the_smt_module():
    # issue 36 (boot44): a program the double pass proves names Z3's version without importing nczones.prover.smt
    code = ("import sys\nfrom nczones.machine import load_machine\nfrom nczones.prover import verify_text\n"
            "m = load_machine('specs/machines/mill.toml')\n"
            "r = verify_text('G21 G90 G54 F100\\n#1 = 2\\nG1 X[#1 * 5] Y10\\nM2\\n', m)\n"
            "print(r.verdict.label, r.solver_version, dict(r.profile).get('double_pass') is not None, "
            "'nczones.prover.smt' in sys.modules)\nimport z3\nprint(z3.get_version_string())")
    first, second = _run(code)[:2]
    assert first.split() == ["safe", second, "True", "False"]
