"""Where the external corpus lives: ``shared/corpus`` beside the repository.

That is where the workspace and CI put it (``NCZONES_CORPUS`` names another
place, for a checkout elsewhere); tests that need it skip when it is missing.
"""

import os
from pathlib import Path

CORPUS = Path(os.environ.get("NCZONES_CORPUS") or Path(__file__).resolve().parents[2] / "shared" / "corpus")
#: Real Fanuc and Haas programs (``fanuc/README.md``, ``fanuc/MANIFEST.tsv``).
FANUC = CORPUS / "fanuc"

MANIFEST = CORPUS / "MANIFEST.tsv"


def corpus_programs() -> list[tuple[str, str]]:
    """(path relative to the corpus, dialect) of every MANIFEST row with role ``program``; empty without
    the corpus."""
    if not MANIFEST.is_file():
        return []
    out = []
    for row in MANIFEST.read_text().splitlines()[1:]:
        cols = row.split("\t")
        if len(cols) > 6 and cols[4] == "program":
            out.append((cols[0], cols[6]))
    return out
