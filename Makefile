# Two commands do all the set-up on a fresh machine (Python 3.11 + pip):
#   make demo   create .venv, install nczones (the core: Z3 and numpy, all verify needs), verify the examples
#   make test   create .venv, install nczones with its test extras, run every test
# CI runs .ci/run: make test, then ruff and lint-imports (make lint), mypy and the wheel test (and it
# installs chromium for the browser tests; make test never installs system packages: without chromium
# those tests skip).
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
RUNTIME := $(VENV)/.installed-runtime
PYTEST_ARGS ?=

.PHONY: demo test lint typecheck bench clean notebooks

$(VENV)/bin/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(RUNTIME): pyproject.toml | $(VENV)/bin/python
	$(BIN)/python -m pip install --quiet -e .
	touch $(RUNTIME)

$(STAMP): pyproject.toml | $(VENV)/bin/python
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP) $(RUNTIME)

demo: $(RUNTIME)
	$(BIN)/nczones check-machine specs/machines/grinder.toml
	$(BIN)/nczones verify specs/examples/programs/notch_over.ngc --machine specs/machines/grinder.toml
	$(BIN)/nczones verify specs/examples/programs/notch_dip.ngc --machine specs/machines/grinder.toml; \
	  test $$? -eq 1  # intentionally unsafe: the line dips into the work-head notch
	$(BIN)/nczones verify specs/examples/programs/fanuc_slots_safe.nc --machine specs/machines/fanuc_mill.toml
	$(BIN)/nczones verify specs/examples/programs/fanuc_slots_clamp.nc --machine specs/machines/fanuc_mill.toml; \
	  test $$? -eq 1  # intentionally unsafe: the Macro B loop's fourth slot runs into the clamp
	$(BIN)/nczones verify specs/examples/programs/g71_clear.nc --machine specs/machines/fanuc_lathe.toml
	$(BIN)/nczones verify specs/examples/programs/g71_jaws.nc --machine specs/machines/fanuc_lathe.toml; \
	  test $$? -eq 1  # intentionally unsafe: the G71 cycle's third roughing pass runs into the chuck jaws
	$(BIN)/nczones verify specs/examples/programs/polar_face.nc --machine specs/examples/machines/turning_centre.toml
	$(BIN)/nczones verify specs/examples/programs/polar_face.nc --machine specs/examples/machines/turning_centre_clamp_near.toml; \
	  test $$? -eq 1  # intentionally unsafe: in G12.1 the profile's corner near C135 reaches the clamp
	$(BIN)/nczones verify specs/examples/programs/holder_clears_vise.ngc --machine specs/machines/mill_solids.toml
	$(BIN)/nczones verify specs/examples/programs/holder_hits_vise.ngc --machine specs/machines/mill_solids.toml; \
	  test $$? -eq 1  # intentionally unsafe: the cutter clears the vise jaw, its Ø63 holder does not
	$(BIN)/nczones verify specs/examples/programs/boring_bar_clears_chuck.nc --machine specs/machines/lathe_solids.toml
	$(BIN)/nczones verify specs/examples/programs/boring_bar_hits_chuck.nc --machine specs/machines/lathe_solids.toml; \
	  test $$? -eq 1  # intentionally unsafe: the boring bar's tip clears the jaws, its holder does not

test: $(STAMP)
	$(BIN)/python -m pytest -q -n 2 $(PYTEST_ARGS)

lint: $(STAMP)
	$(BIN)/ruff check nczones bench tests docs
	$(BIN)/lint-imports

typecheck: $(STAMP)
	$(BIN)/mypy

notebooks: $(STAMP)  # run the teaching notebooks and save them with their outputs
	$(BIN)/python -m tests.tools.run_notebooks

clean:
	rm -rf $(VENV) build dist *.egg-info
