# Two commands do all the set-up on a fresh machine (Python 3.11 + pip):
#   make demo   create .venv, install nczones, verify the bundled example
#   make test   create .venv, install nczones with its test extras, run every test
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
PYTEST_ARGS ?=

.PHONY: demo test bench clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/nczones check-machine specs/machines/grinder.toml
	$(BIN)/nczones verify specs/examples/programs/notch_over.ngc --machine specs/machines/grinder.toml
	$(BIN)/nczones verify specs/examples/programs/notch_dip.ngc --machine specs/machines/grinder.toml; \
	  test $$? -eq 1  # intentionally unsafe: the line dips into the work-head notch

test: $(STAMP)
	-bash .ci/install-chromium.sh
	$(BIN)/python -m pytest -q -n 2 $(PYTEST_ARGS)

clean:
	rm -rf $(VENV) build *.egg-info
