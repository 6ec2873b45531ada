"""Every teaching notebook runs top to bottom (issue 11), offline, from notebooks/."""

from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

NOTEBOOKS = sorted((Path(__file__).parents[2] / "notebooks").glob("*.ipynb"))


def _shown(nb):
    """What a reader sees of each code cell: its printed text, text results and the number of images."""
    out = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        texts, images = [], 0
        for o in cell.get("outputs", []):
            if o.get("output_type") == "stream":
                texts.append(o.get("text", ""))
            data = o.get("data", {})
            if "image/png" in data:
                images += 1
            elif "text/plain" in data:
                texts.append(data["text/plain"])
        out.append(("".join(texts), images))
    return out


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path):
    nb = nbformat.read(path, as_version=4)
    saved = _shown(nb)
    # saved with their outputs (issue 37: a notebook without them teaches nothing until run); `make notebooks`
    # (tests/tools/run_notebooks.py) rewrites them
    assert any(images for _, images in saved), f"{path.name} is saved without its plots: run `make notebooks`"
    client = NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    errors = [
        out
        for cell in nb.cells
        if cell.cell_type == "code"
        for out in cell.get("outputs", [])
        if out.get("output_type") == "error"
    ]
    assert not errors
    assert _shown(nb) == saved, f"{path.name}'s saved outputs are not current: run `make notebooks`"
    # each notebook teaches with at least one plot
    assert any(
        "image/png" in out.get("data", {})
        for cell in nb.cells
        if cell.cell_type == "code"
        for out in cell.get("outputs", [])
    )


def test_notebooks_use_only_the_public_api():
    for path in NOTEBOOKS:
        nb = nbformat.read(path, as_version=4)
        for cell in nb.cells:
            if cell.cell_type == "code":
                assert "._" not in cell.source and "import _" not in cell.source, path.name
