# A virtual environment in .venv, installed once per change of pyproject.toml.
PYTHON ?= python3
VENV := .venv
STAMP := $(VENV)/.installed-stamp

.PHONY: demo test bench

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(VENV)/bin/python -m pip install --quiet --upgrade pip
	$(VENV)/bin/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

# The main job on a bundled unit: exact kinematics of SK8-3,5-4000 ([SK8Rotation2013]).
demo: $(STAMP)
	$(VENV)/bin/pumpjack kinematics sk8-3.5-4000 --format table

# The whole test suite (unit, validation, CLI, doctests). The package's bytecode is compiled
# first, as pip compiles a regular install: the suite starts some hundred interpreters (the
# console script, batch pools, xdist workers), and where PYTHONDONTWRITEBYTECODE is set each of
# them would otherwise compile every module it imports from source again.
test: $(STAMP)
	$(VENV)/bin/python -m compileall -q pumpjack_cli tests
	$(VENV)/bin/python -m pytest -q

# Every benchmark in benchmarks/; each prints its throughput.
bench: $(STAMP)
	for script in benchmarks/bench_*.py; do PATH="$(CURDIR)/$(VENV)/bin:$$PATH" $(VENV)/bin/python $$script || exit 1; done
