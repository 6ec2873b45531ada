"""Soundness hunt where features meet (hunt38): ``--param`` ranges × ``--library`` subprograms × the witness
replay.

The ranged programs of ``tests/contract/test_range_seams.py`` (arcs, canned cycles, G90/G91, work offsets,
G43 H, frames) with their last blocks moved into a library subprogram (LinuxCNC ``o<seam> call`` of
``seam.ngc``; Fanuc ``M98 P1234`` of ``O1234.nc``); modal state flows into a subprogram and back in both
dialects, so the path is the same.  Relation: **the called program proves as the inline one** -- the same
verdict, and the same violating lines, a line moved into the library named by the library file and its line
there (a witness dropped by the replay on one side and not the other shows as a difference).  With the
probe zone of ``test_range_seams`` beside the path, where the ranges decide.

CI: ``EXAMPLES["ci"]`` examples per dialect (derandomized).  ``-m long``: ``NCZONES_LIBRARY_SEAMS`` (default
150) per dialect, randomized, counts printed (specs/contract.md, "Where features meet: hunt38").
"""

from __future__ import annotations

import os
import random
import tempfile
from collections import Counter
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.contract.test_range_seams import (
    _label,
    _probe,
    _same,
    _verify,
    dec,
    machine_for,
    programs,
    ranges,
    setups,
)

EXAMPLES = {"ci": 2, "long": int(os.environ.get("NCZONES_LIBRARY_SEAMS", "150"))}
OUTCOMES: Counter = Counter()
_SUB = {"linuxcnc": ("seam.ngc", "o<seam> sub", "o<seam> endsub\nM2", "o<seam> call"),
        "fanuc": ("O1234.nc", "O1234", "M99", "M98 P1234")}


def split(text: str, dialect: str, at: int) -> tuple[str, str, int]:
    """``text`` (a header line, blocks, ``M30``) with its blocks from the ``at``-th on moved into the library
    subprogram: (main text, library text, how many lines earlier a moved block sits in the library)."""
    lines = text.rstrip("\n").split("\n")
    assert lines[-1] == "M30"
    body = lines[1:-1]
    at = max(1, min(at, len(body)))
    _name, head, tail, call = _SUB[dialect]
    main = "\n".join([lines[0], *body[:at - 1], call, "M30"]) + "\n"
    library = "\n".join([head, *body[at - 1:], tail]) + "\n"
    # inline line of body[k] is k + 2; in the library it is k - (at - 1) + 2
    return main, library, at - 1


def _inline_lines(result, shift: int, name: str) -> set:
    """The violating (file, line) pairs of the inline run, as the split places them (None: the main text)."""
    return {(name, v.line - shift) if v.line >= shift + 2 else (None, v.line) for v in result.violations}


def _called_lines(result, name: str) -> set:
    return {(name if v.span.file.endswith(name) else None, v.line) for v in result.violations}


def _backstop(*results) -> bool:
    """A result with a motion the solver's wall-time backstop left undecided (under load, one run of two)."""
    return any(r.code == "VF202" for res in results for r in res.reasons)


def check(text: str, setup, rngs, at: int, rnd: random.Random) -> None:
    dialect = setup.dialect
    setup = _probe(text, setup, rnd)
    base = machine_for(setup)
    params = [f"{n}={dec(lo).rstrip('.')}..{dec(hi).rstrip('.')}" for n, lo, hi in rngs]
    inline = _verify(text, base, params=params)
    main, library, shift = split(text, dialect, at)
    name = _SUB[dialect][0]
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / name).write_text(library)
        called = _verify(main, base, params=params, library=folder)
    a, b = _label(inline), _label(called)
    OUTCOMES[(f"inline/called {dialect}", f"{a}/{b}")] += 1
    if a.startswith("error:") or b.startswith("error:"):
        assert a == b, f"inline {a}, called {b}, ranges {params}:\n{text}\n---\n{main}---\n{library}"
        return
    assert _same(inline, called), f"inline {a}, called {b}, ranges {params}:\n{text}\n---\n{main}---\n{library}"
    if a == b == "unsafe" and _backstop(inline, called):
        OUTCOMES[("violating lines", "solver time backstop (not compared)")] += 1
    elif a == b == "unsafe":
        want, got = _inline_lines(inline, shift, name), _called_lines(called, name)
        assert want == got, f"violating lines inline {want}, called {got}, ranges {params}:\n{text}"


def _run(dialect: str, n: int, derandomize: bool) -> None:
    @settings(max_examples=n, deadline=None, derandomize=derandomize, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(programs(dialect), setups(dialect), ranges(), st.integers(1, 9), st.integers(0, 2 ** 32))
    def run(text, setup, rngs, at, seed):
        check(text, setup, rngs, at, random.Random(seed))

    run()


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_library_seams(dialect):
    _run(dialect, EXAMPLES["ci"], True)


@pytest.mark.long
@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_library_seams_long(dialect):
    OUTCOMES.clear()
    _run(dialect, EXAMPLES["long"], False)
    print(f"\nlibrary seams, {dialect}:", dict(sorted(OUTCOMES.items())))
