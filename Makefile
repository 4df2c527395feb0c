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

# The whole test suite (unit, validation, CLI, doctests).
test: $(STAMP)
	$(VENV)/bin/python -m pytest -q

# Every benchmark in benchmarks/; each prints its throughput.
bench: $(STAMP)
	for script in benchmarks/bench_*.py; do PATH="$(CURDIR)/$(VENV)/bin:$$PATH" $(VENV)/bin/python $$script || exit 1; done
