# A virtual environment in .venv, installed once per change of pyproject.toml.
PYTHON ?= python3
VENV := .venv
STAMP := $(VENV)/.installed-stamp

.PHONY: demo test bench

# The package's bytecode is compiled as `pip install` (not editable) compiles an installed
# package's: every interpreter then reads it instead of compiling the modules it imports, which
# an environment with PYTHONDONTWRITEBYTECODE would do in every process (the test suite starts
# some sixty; docs/performance.md). A module edited later is compiled again where it is imported.
$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(VENV)/bin/python -m pip install --quiet --upgrade pip
	$(VENV)/bin/python -m pip install --quiet -e '.[test]'
	$(VENV)/bin/python -m compileall -q pumpjack_cli
	touch $(STAMP)

# The main job on a bundled unit: exact kinematics of SK8-3,5-4000 ([SK8Rotation2013]).
demo: $(STAMP)
	$(VENV)/bin/pumpjack kinematics sk8-3.5-4000 --format table

# The whole test suite (unit, validation, CLI, doctests).
test: $(STAMP)
	$(VENV)/bin/python -m pytest -q

# Every benchmark in benchmarks/; each prints its throughput.
bench: $(STAMP)
	for script in benchmarks/bench_*.py; do PATH="$(CURDIR)/$(VENV)/bin:$$PATH" $(VENV)/bin/python $$script || exit 1; done
