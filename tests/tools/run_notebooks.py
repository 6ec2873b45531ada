"""Run the teaching notebooks and save them with their outputs (``make notebooks``).

Each notebook is first written again from its source, ``docs/make_notebook_0N.py``
(the README: the notebooks' sources are there), then executed top to bottom
from ``notebooks/`` (as ``tests/notebooks/test_notebooks.py`` does) and
written back with its outputs, so a reader sees the plots without running
anything.  Cell ids are made deterministic (a hash of the cell's position and
source: the generators' nbformat ids are random) and execution counts are
cleared, so a re-run changes only what the code prints or draws.

    python -m tests.tools.run_notebooks [NOTEBOOK ...]
"""

from __future__ import annotations

import hashlib
import subprocess
import sys
from pathlib import Path

import nbformat
from nbclient import NotebookClient

ROOT = Path(__file__).resolve().parents[2]


def regenerate(path: Path) -> None:
    """Write ``path`` again from its generator ``docs/make_notebook_NN.py`` (NN: the notebook's number)."""
    source = ROOT / "docs" / f"make_notebook_{path.name[:2]}.py"
    if source.is_file():
        subprocess.run([sys.executable, str(source)], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)


def run(path: Path) -> nbformat.NotebookNode:
    """Execute one notebook; returns it with its outputs (execution counts cleared)."""
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": str(path.parent)}}).execute()
    for i, cell in enumerate(nb.cells):
        cell.id = hashlib.sha256(f"{i}\0{cell.source}".encode()).hexdigest()[:8]
        if cell.cell_type == "code":
            # consecutive writes to one stream are split where the kernel happened to flush: join them
            merged: list = []
            for out in cell.get("outputs", []):
                if (out.get("output_type") == "stream" and merged and merged[-1].get("output_type") == "stream"
                        and merged[-1].get("name") == out.get("name")):
                    merged[-1]["text"] += out["text"]
                else:
                    merged.append(out)
            cell.outputs = merged
            cell.execution_count = None
            cell.metadata.pop("execution", None)
            for out in cell.get("outputs", []):
                if "execution_count" in out:
                    out["execution_count"] = None
    nb.metadata.pop("widgets", None)
    return nb


def main(argv: list[str]) -> int:
    paths = [Path(a) for a in argv] or sorted((ROOT / "notebooks").glob("*.ipynb"))
    for path in paths:
        regenerate(path.resolve())
        nb = run(path.resolve())
        nbformat.write(nb, path)
        print(f"{path}: saved with outputs", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
