"""Regenerate the README's report images: ``python docs/make_images.py`` (from the repository root).

docs/images/notch_dip.png is ``nczones plot specs/examples/programs/notch_dip.ngc
--machine specs/machines/grinder.toml`` with the verification's violation marked;
docs/images/notch_dip.txt is the text report printed by ``nczones verify`` (without
the timing), shown in the README next to it.
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from nczones.machine import load_machine  # noqa: E402
from nczones.prover import verify  # noqa: E402
from nczones.report import plot_program  # noqa: E402
from nczones.report.text import render_text  # noqa: E402


def main() -> None:
    out = ROOT / "docs" / "images"
    out.mkdir(parents=True, exist_ok=True)
    program = "specs/examples/programs/notch_dip.ngc"
    machine = load_machine(ROOT / "specs" / "machines" / "grinder.toml")
    result = verify(str(ROOT / program), machine, file=program)
    fig = plot_program(str(ROOT / program), machine, result=result)
    fig.savefig(out / "notch_dip.png", dpi=100, metadata={"Software": None})
    (out / "notch_dip.txt").write_text(render_text(result, deterministic=True), encoding="utf-8")
    print(f"wrote {out / 'notch_dip.png'} and {out / 'notch_dip.txt'}")


if __name__ == "__main__":
    main()
