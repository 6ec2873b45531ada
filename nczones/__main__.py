"""``python -m nczones`` runs the command line."""

from .cli import run

run()
