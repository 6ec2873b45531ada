"""Where the external corpus lives: ``shared/corpus`` beside the repository.

That is where the workspace and CI put it (``NCZONES_CORPUS`` names another
place, for a checkout elsewhere); tests that need it skip when it is missing.
A git worktree elsewhere finds it beside its main checkout too.
"""

import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _beside_main_checkout(root: Path) -> Path | None:
    """``shared/corpus`` beside the main checkout of the worktree at ``root`` (whose ``.git`` is a file naming
    ``<main>/.git/worktrees/<name>``), or None for a plain checkout.

    >>> _beside_main_checkout(ROOT / "no such folder") is None
    True
    """
    marker = root / ".git"
    if not marker.is_file():
        return None
    text = marker.read_text(encoding="utf-8", errors="replace").strip()
    if not text.startswith("gitdir:"):
        return None
    gitdir = Path(text.removeprefix("gitdir:").strip())
    main_git = (root / gitdir).resolve().parents[1]  # <main>/.git/worktrees/<name> -> <main>/.git
    return main_git.parent.parent / "shared" / "corpus"


def _corpus() -> Path:
    if os.environ.get("NCZONES_CORPUS"):
        return Path(os.environ["NCZONES_CORPUS"])
    beside = ROOT.parent / "shared" / "corpus"
    if beside.is_dir():
        return beside
    return _beside_main_checkout(ROOT) or beside


CORPUS = _corpus()
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
