"""``python -m nczones`` runs the command line."""

import gc

# the collector's threshold of the nczones program, set before the command line's modules are imported (see
# nczones.cli.run, which sets it too for the console script)
gc.set_threshold(50_000, *gc.get_threshold()[1:])

from .cli import run  # noqa: E402

run()
