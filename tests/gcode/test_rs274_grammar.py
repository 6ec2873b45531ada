"""The grammar-driven differential against LinuxCNC's ``rs274 -g`` (issue 33).

``tests/tools/rs274_diff.py`` generates LinuxCNC programs from named productions; each names the rows of
``specs/gcode-support.md``'s tables (codes, state parameters, O-word constructs) it writes.  Here:

* every row the spec marks modelled has a production (or a reason in ``NOT_GENERATED``), and every
  production fires on the CI seeds;
* the CI-size differential: fixed seeds through ``rs274`` and nczones, motion by motion, errors on the same
  line (``tests/oracles/rs274.py``).  In CI (``CI=true``) a missing ``rs274`` fails the test; locally it skips;
* the long profile (``-m long``, ``NCZONES_RS274_PROGRAMS``, default 50,000): the same over more seeds.

The numbers of the runs are in ``specs/contract.md`` ("rs274 grammar differential").
"""

from __future__ import annotations

import os
import re
import tempfile
from collections import Counter
from pathlib import Path

import pytest

from tests.tools import rs274_diff
from tests.tools.rs274_diff import NOT_GENERATED, PRODUCTIONS, RS274, Generator, generate, outcome

SPEC = Path(__file__).resolve().parents[2] / "specs" / "gcode-support.md"
#: CI size: 300 programs (about 10 s of CPU with rs274), seeds fixed
CI_SEEDS = range(7000, 7300)
IN_CI = os.environ.get("CI", "").lower() == "true"


def _tables(text: str) -> dict[str, str]:
    """First cell -> treatment of every row of the spec's code, parameter and O-word tables."""
    rows: dict[str, str] = {}
    heads = ("| Code | Treatment |", "| parameters | value |", "| O-word construct | Treatment |")
    lines = text.splitlines()
    for k, line in enumerate(lines):
        if line.strip() not in heads:
            continue
        for row in lines[k + 2:]:
            if not row.startswith("|"):
                break
            cells = [c.strip() for c in row.strip().strip("|").split("|")]
            rows[cells[0]] = cells[1] if len(cells) > 1 else ""
    return rows


def modelled_rows() -> list[str]:
    rows = _tables(SPEC.read_text())
    return [k for k, v in rows.items() if not re.match(r"\**unknown", v.strip(), re.I)]


def test_the_spec_tables_are_read():
    rows = modelled_rows()
    assert "G0 G1" in rows and "`#5220`, `#<_coord_system>`" in rows and "o-word do/while" in rows
    assert not any(r.startswith("G76") for r in rows)  # an "unknown" row is not modelled
    assert len(rows) >= 50


def test_every_modelled_row_has_a_production():
    covered = {row for rows in PRODUCTIONS.values() for row in rows}
    missing = [r for r in modelled_rows() if r not in covered and r not in NOT_GENERATED]
    assert not missing, f"modelled rows of specs/gcode-support.md without a generator production: {missing}"
    stale = [r for r in covered | set(NOT_GENERATED) if r not in _tables(SPEC.read_text())]
    assert not stale, f"productions name rows the spec no longer has: {stale}"


def test_every_production_fires_on_the_ci_seeds():
    used: Counter = Counter()
    for seed in CI_SEEDS:
        g = Generator(seed)
        g.program()
        used.update(g.used)
    names = {n for n, _ in Generator.WEIGHTS}
    assert names | {"program"} == set(PRODUCTIONS)
    assert not names - set(used), f"productions never used on the CI seeds: {names - set(used)}"


def test_generated_programs_are_deterministic():
    assert generate(7001) == generate(7001)
    assert generate(7001)[0] != generate(7002)[0]


def _rs274_or_skip() -> None:
    if Path(RS274).exists():
        return
    if IN_CI:
        pytest.fail(f"{RS274} is missing in CI: .ci/install-rs274.sh installs LinuxCNC's interpreter")
    pytest.skip(f"{RS274} not installed (LinuxCNC's standalone interpreter; .ci/install-rs274.sh)")


def differential(seeds) -> tuple[Counter, list[tuple[int, str, str]]]:
    """Outcome counts and the mismatches (seed, status, detail) of ``seeds``."""
    counts: Counter = Counter()
    bad = []
    with tempfile.TemporaryDirectory() as tmp:
        for seed in seeds:
            text, setup = generate(seed)
            o = outcome(text, setup, Path(tmp))
            counts[o.status] += 1
            if o.status not in ("match", "unknown"):
                bad.append((seed, o.status, o.detail))
    return counts, bad


@pytest.mark.parametrize("block", range(6))
def test_ci_differential_against_rs274(block):
    """50 programs per block, 300 in all: every one matches rs274 (or is nczones ``unknown``)."""
    _rs274_or_skip()
    seeds = CI_SEEDS[block * 50:(block + 1) * 50]
    counts, bad = differential(seeds)
    assert counts["match"] >= 40, counts  # programs that exercise the comparison, not only unknowns
    assert not bad, f"rs274 differential mismatches (python -m tests.tools.rs274_diff run --seed S --count 1): {bad}"


@pytest.mark.long
def test_long_differential_against_rs274():
    """The long profile: NCZONES_RS274_PROGRAMS programs (default 50,000) from seed 100000; the chunked runner
    ``python -m tests.tools.rs274_long`` is the same with kept results."""
    _rs274_or_skip()
    n = int(os.environ.get("NCZONES_RS274_PROGRAMS", "50000"))
    counts, bad = differential(range(100000, 100000 + n))
    assert not bad, f"{len(bad)} mismatches, first {bad[:5]} ({dict(counts)})"


def test_ci_seeds_do_not_use_a_filtered_class_by_accident():
    """The known-class filters are on by default (the lead drops them when the fixes are merged)."""
    assert set(rs274_diff.KNOWN_CLASSES) <= Generator(1).exclude


@pytest.mark.long
@pytest.mark.parametrize("name", ["offset-g92", "restore-distance", "pecks-round"])
def test_a_broken_interpreter_fails_the_ci_differential(name):
    """Mutation check (``tests/tools/rs274_mutants.py``): one offset rule, one modal restore and one count
    rounding broken in nczones's LinuxCNC interpreter each make the CI-size differential find mismatches."""
    from tests.tools.rs274_mutants import mutant

    _rs274_or_skip()
    with mutant(name):
        _counts, bad = differential(CI_SEEDS)
    assert bad, f"the CI-size differential did not notice the mutant {name}"
