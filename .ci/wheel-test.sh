#!/usr/bin/env bash
# Build the wheel with `python -m build`, install it into a fresh venv (the core: no extras)
# and run the installed nczones outside the source tree: the package must stand on its own
# (py.typed and the license in the wheel, the console script, nczones.testing asking for its extra).
# The core install is light: no Dask, matplotlib or Shapely, and `nczones verify` works without them
# while a command that needs an extra says which one (PK101, exit 2).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
PY=${PYTHON:-.venv/bin/python}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
"$PY" -m build --wheel --outdir "$WORK/dist" . >"$WORK/build.log" 2>&1 || { cat "$WORK/build.log"; exit 1; }
WHEEL=$(ls "$WORK"/dist/nczones-*.whl)
python3 -m venv "$WORK/venv"
"$WORK/venv/bin/python" -m pip install --quiet "$WHEEL"
"$PY" - "$WHEEL" <<'PY'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
for wanted in ("nczones/py.typed", "licenses/LICENSE", "nczones/gcode/source.py"):
    assert any(n.endswith(wanted) for n in names), f"wheel-test: {wanted} missing from {sys.argv[1]}"
assert not any(n.startswith(("tests/", "specs/", "bench/")) for n in names), "wheel-test: the wheel ships tests"
PY
for heavy in dask distributed matplotlib shapely; do
  if "$WORK/venv/bin/python" -c "import importlib.util, sys; sys.exit(importlib.util.find_spec('$heavy') is None)"; then
    echo "wheel-test: the core install pulled $heavy (an extra's package)"; exit 1
  fi
done
cd "$WORK"  # away from the source tree: the installed package, not ./nczones
status=0
"$WORK/venv/bin/nczones" plot "$ROOT/specs/examples/programs/notch_dip.ngc" \
  --machine "$ROOT/specs/machines/grinder.toml" --output "$WORK/p.png" 2>"$WORK/plot.txt" || status=$?
if [ "$status" -ne 2 ] || ! grep -q "error\[PK101\].*pip install 'nczones\[plot\]'" "$WORK/plot.txt"; then
  echo "wheel-test: nczones plot without the [plot] extra gave exit $status:"; cat "$WORK/plot.txt"; exit 1
fi
status=0
"$WORK/venv/bin/nczones" verify "$ROOT/specs/examples/programs/notch_dip.ngc" \
  --machine "$ROOT/specs/machines/grinder.toml" >"$WORK/out.txt" || status=$?
if [ "$status" -ne 1 ] || ! grep -q 'notch_dip.ngc: unsafe: 1 violating block' "$WORK/out.txt"; then
  echo "wheel-test: the installed nczones verify gave exit $status:"; cat "$WORK/out.txt"; exit 1
fi
"$WORK/venv/bin/nczones" verify "$ROOT/specs/examples/programs/notch_over.ngc" \
  --machine "$ROOT/specs/machines/grinder.toml" --format json >"$WORK/out.json"
"$WORK/venv/bin/python" - "$WORK/out.json" <<'PY'
import json, sys
import nczones
doc = json.load(open(sys.argv[1]))
assert doc["verdict"] == "safe" and doc["nczones_version"] == nczones.__version__, doc
assert "site-packages" in nczones.__file__, nczones.__file__
try:
    import nczones.testing  # noqa: F401
except ModuleNotFoundError as exc:
    assert "pip install 'nczones[testing]'" in str(exc), exc
else:
    raise AssertionError("nczones.testing imported without hypothesis installed")
PY
echo "wheel-test: $(basename "$WHEEL") installs and verifies in a fresh venv"
