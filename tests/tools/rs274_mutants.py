"""Mutation check of the rs274 differential: break nczones's LinuxCNC interpreter in three places and show
that the CI-size differential (``tests/gcode/test_rs274_grammar.py``'s seeds) fails on each.

    python -m tests.tools.rs274_mutants            # all three, prints the mismatches each one causes

The mutants (monkeypatched, nothing is written):

* ``offset-g92``: G92 forgets the work offset (``g92 = pos - tool - value`` instead of
  ``pos - G5x - tool - value``): one offset rule;
* ``restore-distance``: M72/M73's restore keeps the current distance mode (G90/G91) instead of the saved
  one: one modal restore;
* ``pecks-round``: the G73/G83 peck count rounds to the nearest whole number of pecks instead of
  LinuxCNC's loop (``for (d = r - q; d > bottom; d -= q)``, one peck per started ``q``): one count rounding.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager

from nczones.exact import to_float
from nczones.gcode import interpreter as interp_mod

Interpreter = interp_mod.Interpreter


@contextmanager
def _patched(name: str, make: Callable) -> Iterator[None]:
    original = getattr(Interpreter, name)
    setattr(Interpreter, name, make(original))
    try:
        yield
    finally:
        setattr(Interpreter, name, original)


def _offset_g92(original):
    def g92(self, axis_words, w):
        original(self, axis_words, w)
        for i, _aw in axis_words:  # add the work offset back: G92 computed as if G54.. were zero
            self.g92[i] += self.g5x[self.wcs][i]
        self.g92_params = list(self.g92)
        self.recompute_offsets()
    return g92


def _restore_distance(original):
    def restore(self, snap, *rest):  # _restore_modal(snap, w) since M73's return was modelled
        keep = self.absolute
        original(self, snap, *rest)
        self.absolute = keep
    return restore


def _pecks_round(original):
    def pecks(self, rprog, cprog, old_prog_mm):
        # the same doubles as the interpreter's loop; t = (r - bottom) / q pecks of depth
        q = to_float(self.cycle_q or 0)
        if self.absolute:
            r, bottom = to_float(rprog), to_float(cprog)
        else:
            old = to_float(old_prog_mm / interp_mod.INCH if self.inch else old_prog_mm)
            r = to_float(rprog) + old
            bottom = r + to_float(cprog)
        if q <= 0 or r <= bottom:
            return original(self, rprog, cprog, old_prog_mm)
        # LinuxCNC's loop makes ceil(t) - 1 pecks before the last plunge; the mutant rounds t to the nearest
        return max(0, math.floor((r - bottom) / q + 0.5) - 1)
    return pecks


MUTANTS: dict[str, tuple[str, Callable]] = {
    "offset-g92": ("_g92", _offset_g92),
    "restore-distance": ("_restore_modal", _restore_distance),
    "pecks-round": ("_linuxcnc_pecks", _pecks_round),
}


@contextmanager
def mutant(name: str) -> Iterator[None]:
    method, make = MUTANTS[name]
    with _patched(method, make):
        yield


def main() -> int:
    from tests.gcode.test_rs274_grammar import CI_SEEDS, differential

    failed_all = True
    for name in MUTANTS:
        with mutant(name):
            counts, bad = differential(CI_SEEDS)
        print(f"{name}: {len(bad)} mismatches in {len(CI_SEEDS)} programs {dict(counts)}; first: {bad[:2]}")
        failed_all &= bool(bad)
    return 0 if failed_all else 1


if __name__ == "__main__":
    sys.exit(main())
