"""Soundness hunt (hunt36b): a lathe's tool solids over two parameter ranges at once, against concrete values.

tests/prover/test_lathe_solids_ranges.py holds one range (``G54.X`` or ``G54.Z``) against its ends and
middle.  Here one or two ranges at once among ``G54.X``, ``G54.Z``, ``start.X``, ``start.Z`` (a work offset
moves the path and the program's frame; the start position moves the first rapid's start), on the same
generated Fanuc lathe programs (lines, rapids and arcs around the chuck, the jaws and the tailstock quill,
tool 1 or 2 and a change between them; tests/prover/test_lathe_solids.py ``programs``), and the values
checked are every corner of the box of ranges, its centre and two drawn points inside (multiples of 1/64 of
each range): a range ``safe`` must be ``safe`` there and the independent sampled oracle
(tests/oracles/lathe_solids.py) must find no tool part in a fixture there; a concrete ``safe`` must have no
oracle hit.  CI 2 examples; ``-m long``: the count in specs/contract.md "Where features meet: hunt36b".
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.oracles.concrete import machine_at
from tests.prover.test_lathe_solids import ORACLE, programs
from tests.prover.test_lathe_solids_ranges import _oracle_hit
from tests.prover.test_solids_ranges import _fmt

_MACHINE = parse_machine(ORACLE, "oracle.toml")
_HALF = st.integers(-16, 16).map(lambda v: Fraction(v, 2))


@st.composite
def _ranges(draw) -> list[tuple[str, Fraction, Fraction]]:
    names = draw(st.lists(st.sampled_from(["G54.X", "G54.Z", "start.X", "start.Z"]), min_size=1, max_size=2,
                          unique=True))
    return [(n, *sorted((draw(_HALF), draw(_HALF)))) for n in names]


def _values(rngs, rnd: random.Random) -> list[dict[str, Fraction]]:
    corners = [{n: (a if (k >> i) & 1 == 0 else b) for i, (n, a, b) in enumerate(rngs)}
               for k in range(1 << len(rngs))]
    inside = [{n: a + (b - a) * Fraction(rnd.randint(0, 64), 64) for n, a, b in rngs} for _ in range(2)]
    return [*corners, {n: (a + b) / 2 for n, a, b in rngs}, *inside]


def _range_against_values(text: str, rngs, rnd: random.Random) -> str:
    r = verify_text(text, _MACHINE, params=[f"{n}={_fmt(a)}..{_fmt(b)}" for n, a, b in rngs])
    for values in _values(rngs, rnd):
        at = machine_at(_MACHINE, values)
        concrete = verify_text(text, at)
        hit = _oracle_hit(text, at, concrete)
        if concrete.verdict.label == "safe":
            assert hit is None, f"safe at {values}, the oracle finds {hit[0].name} in {hit[1].name}"
        if r.verdict.label == "safe":
            assert concrete.verdict.label == "safe" and hit is None, f"safe over {rngs}, not at {values}"
    return r.verdict.label


_SETTINGS = dict(deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])


@settings(max_examples=2, **_SETTINGS)  # type: ignore[arg-type]
@given(programs(), _ranges(), st.randoms(use_true_random=False))
def test_two_ranges_against_the_corners_and_inside(text, rngs, rnd):
    _range_against_values(text, rngs, rnd)


OUTCOMES: dict[str, int] = {}


@pytest.mark.long
@settings(max_examples=400, **_SETTINGS)  # type: ignore[arg-type]
@given(programs(), _ranges(), st.randoms(use_true_random=False))
def test_two_ranges_against_the_corners_and_inside_long(text, rngs, rnd):
    label = _range_against_values(text, rngs, rnd)
    OUTCOMES[label] = OUTCOMES.get(label, 0) + 1


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    if OUTCOMES:
        print("\nhunt36b lathe ranges:", dict(sorted(OUTCOMES.items())))
