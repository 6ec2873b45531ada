"""``python -m nczones`` runs the command line."""

import gc

# the collector's threshold of the nczones program, set before the command line's modules are imported (see
# nczones.cli.run, which sets it too for the console script)
_first, _second, _third = gc.get_threshold()
if 0 < _first < 50_000:  # raised, never lowered; 0 (collection off) stays 0
    gc.set_threshold(50_000, _second, _third)

from .cli import run  # noqa: E402

run()
