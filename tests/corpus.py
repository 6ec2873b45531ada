"""Where the external corpus lives: ``shared/corpus`` beside the repository.

That is where the workspace and CI put it; tests that need it skip when it
is missing.
"""

from pathlib import Path

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus"
