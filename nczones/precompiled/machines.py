"""Machine descriptions (TOML text) the start-up recordings (``python -m nczones.precompiled``) and the bench
scripts share: the package cannot import ``bench/``, so the scripts import them from here.  Not imported at
start-up."""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["box_machine", "peer_box"]


def box_machine(name: str, limit: str, settings: Sequence[str] = (), sections: Sequence[str] = (),
                rapid: str = "10000") -> str:
    """A three-axis mill ``name`` (X, Y, Z, each at ``rapid`` mm/min, reference 0) whose zone ``travel`` is the
    box of ``-limit`` to ``limit`` mm on every axis; ``settings``: more lines of its ``[machine]`` table,
    ``sections``: tables before the zone (more zones go after the text).

    >>> text = box_machine("m", "5", ['pulse = "0.001"'], ["[tool_lengths]", 'H1 = "100"'], rapid="60")
    >>> lines = text.splitlines()
    >>> lines[:4]
    ['[machine]', 'name = "m"', 'axes = ["X", "Y", "Z"]', 'pulse = "0.001"']
    >>> lines[5], lines[12:15], lines[-1]
    ('X = "60"', ['[tool_lengths]', 'H1 = "100"', '[[zones]]'], 'max = { X = "5", Y = "5", Z = "5" }')
    """
    lines = ["[machine]", f'name = "{name}"', 'axes = ["X", "Y", "Z"]', *settings,
             "[machine.rapid]", *(f'{a} = "{rapid}"' for a in "XYZ"),
             "[machine.reference]", *(f'{a} = "0"' for a in "XYZ"), *sections,
             "[[zones]]", 'name = "travel"', 'kind = "box"',
             "min = { " + ", ".join(f'{a} = "-{limit}"' for a in "XYZ") + " }",
             "max = { " + ", ".join(f'{a} = "{limit}"' for a in "XYZ") + " }"]
    return "\n".join(lines) + "\n"


def peer_box(dialect: str, limit: str = "100000") -> str:
    """The peer benchmarks' machine (``bench/bench_peers.py``; the box the instruction counts of
    ``specs/performance.md`` verify on): a mill of 0.0001 mm pulses in ``dialect`` with tool length H1 = 100 mm
    and the box ``travel`` of +-``limit`` mm."""
    return box_machine("peer bench", limit, ['pulse = "0.0001"', f'dialect = "{dialect}"'],
                       ["[tool_lengths]", 'H1 = "100"'])
