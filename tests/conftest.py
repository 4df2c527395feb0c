"""Shared fixtures: the repository root and bundled files, the SK8-3,5-4000 unit, its machine, rod
string and pump built once, the CLI run in-process and as the real console script.

Constants and plain builders shared by the tests are in ``tests/helpers.py``.
"""

from __future__ import annotations

import io
import json
import os
import shutil
import subprocess
import sys
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

# One BLAS thread per process, set before numpy is first imported (here, and in the processes the
# tests start, which inherit it): one test's arrays are small, so OpenBLAS's own threads would only
# wait for work, spinning, and contend for the cores with those processes (the console script does
# the same, pumpjack_cli/__main__.py).
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from helpers import (LB_PER_FT, PSI, REPO_ROOT, RP11L_TABLE_4_1, SK8, SK8_API_YAML, SK8_CARD, SK8_FLUID_DENSITY,
                     SK8_PUMP_DEPTH, SK8_TOML, sample_card)


@pytest.fixture(scope="session")
def repo_root() -> Path:
    """The checkout: holds configs/, samples/ and pyproject.toml."""
    assert (REPO_ROOT / "pyproject.toml").is_file()
    return REPO_ROOT


@pytest.fixture(scope="session")
def sk8_toml() -> Path:
    """The bundled SK8-3,5-4000 unit (GOST names, every datum of [SK8Rotation2013])."""
    return SK8_TOML


@pytest.fixture(scope="session")
def sk8_card() -> Path:
    """The SK8-3,5-4000 sample card (``samples/make_cards.py``: elastic rods, damping 0.05, full pump)."""
    return SK8_CARD


@pytest.fixture(scope="session")
def sk8_api_yaml() -> Path:
    """The same SK8-3,5-4000 geometry written with API 11E letters, without [drive]."""
    return SK8_API_YAML


@pytest.fixture(scope="session")
def sk8_unit():
    """The bundled SK8-3,5-4000 as parsed (frozen: tests replace, never change it)."""
    from pumpjack_cli.config import load_unit

    return load_unit(SK8)


@pytest.fixture(scope="session")
def sk8_machine(sk8_unit):
    """Its machine of the equation of motion with the rigid-rod well model, as `pumpjack dynamics` builds it."""
    return sk8_unit.machine()


@pytest.fixture(scope="session")
def sk8_rods():
    """[SK8Rotation2013]'s rod string built by hand, not from the unit file: 1530 m of 25, 22 and
    19 mm rods over 23, 26 and 51 % from the top, API rods with couplings (the weights of the 1,
    7/8 and 3/4 in rods of RP 11L Table 4.1) and E = 30.5e6 psi."""
    from pumpjack_cli.core.rods.string import RodString

    diameter = np.array([25.0, 22.0, 19.0]) * 1e-3
    weight = np.array([RP11L_TABLE_4_1[size][0] for size in (1.0, 0.875, 0.75)])
    return RodString(SK8_PUMP_DEPTH * np.array([0.23, 0.26, 0.51]), np.pi * diameter**2 / 4,
                     np.full(3, 30.5e6 * PSI), weight * LB_PER_FT)


@pytest.fixture(scope="session")
def sk8_pump():
    """[SK8Rotation2013]'s 38 mm pump at 1530 m under 100 m of 820 kg/m³ fluid, full, anchored tubing
    (``dataclasses.replace`` it for fillage, gas or tubing stretch)."""
    from pumpjack_cli.core.rods.pump import Pump, pump_pressures

    discharge, intake = pump_pressures(SK8_PUMP_DEPTH, SK8_FLUID_DENSITY, submergence=100.0)
    return Pump(np.pi * 0.038**2 / 4, discharge, intake)


@pytest.fixture(scope="module")
def run_card_json(run_json):
    """``run_json(command, unit, "--card", CARD, ...)``, CARD the unit's sample card unless
    ``card_file`` is given."""

    def run(command: str, unit, *extra, card_file=None) -> dict:
        return run_json(command, unit, "--card", card_file or sample_card(unit), *extra)

    return run


@pytest.fixture(scope="module")
def run_json():
    """Run a command in-process with ``-f json`` once per argument list in a module; return its
    document (a cache: several tests read the same run)."""
    from pumpjack_cli.cli import main

    cache = {}

    def run(*argv) -> dict:
        key = tuple(str(a) for a in argv)
        if key not in cache:
            out, err = io.StringIO(), io.StringIO()
            with redirect_stdout(out), redirect_stderr(err):
                code = main([*key, "-f", "json"])
            assert code == 0, err.getvalue()
            cache[key] = json.loads(out.getvalue())
        return cache[key]

    return run


@pytest.fixture
def run_cli(capsys):
    """Run ``pumpjack_cli.cli.main(argv)`` in-process; return (exit code, stdout, stderr).

    Output captured before the call is discarded, so each call sees only its own output.
    capsys' stdout is not a terminal, as in a pipe.
    """
    from pumpjack_cli.cli import main

    def run(*argv: str) -> tuple[int, str, str]:
        capsys.readouterr()
        code = main([str(a) for a in argv])
        captured = capsys.readouterr()
        return code, captured.out, captured.err

    return run


def _console_script() -> str:
    """The installed ``pumpjack`` script of the interpreter running the tests."""
    beside = Path(sys.executable).parent / "pumpjack"
    if beside.is_file():
        return str(beside)
    found = shutil.which("pumpjack")
    if found is None:
        pytest.skip("the pumpjack console script is not installed")
    return found


@pytest.fixture(scope="session")
def pumpjack_script() -> str:
    """Path of the real console script (the package must be installed)."""
    return _console_script()


@pytest.fixture
def run_script(pumpjack_script, repo_root):
    """Run the real console script in a subprocess from the repository root.

    Returns the CompletedProcess with text stdout/stderr. ``environment`` sets variables
    (None: unset). The timeout only guards against a hang; no assertion depends on how
    long a run takes.
    """

    def run(*argv: str, environment: dict[str, str | None] | None = None, **kwargs) -> subprocess.CompletedProcess:
        env = dict(os.environ)
        env.pop("COLUMNS", None)
        for name, value in (environment or {}).items():
            env.pop(name, None)
            if value is not None:
                env[name] = value
        return subprocess.run(
            [pumpjack_script, *map(str, argv)],
            cwd=repo_root,
            capture_output=True,
            text=True,
            timeout=120,
            env=env,
            **kwargs,
        )

    return run


@pytest.fixture(scope="session")
def sk8_drivable_card(tmp_path_factory) -> Path:
    """The SK8-3,5-4000 sample card with its load swing halved about its mean.

    The sample card (elastic rods, `samples/make_cards.py`) asks the SK8's motor, with the
    counterbalance of [SK8Rotation2013], for more than its pull-out torque, so the
    equation of motion under it is refused ("the motor is too weak"); tests of identities
    that need the machine driven by a card use this lighter card of the same shape."""
    lines = SK8_CARD.read_text(encoding="utf-8").splitlines()
    body = [line for line in lines if not line.startswith("#")]
    rows = np.array([[float(x) for x in line.split(",")] for line in body[1:]])
    rows[:, 2] = rows[:, 2].mean() + 0.5 * (rows[:, 2] - rows[:, 2].mean())
    path = tmp_path_factory.mktemp("cards") / "sk8-drivable-card.csv"
    path.write_text("\n".join([body[0]] + [",".join(repr(float(x)) for x in row) for row in rows]) + "\n",
                    encoding="utf-8")
    return path


@pytest.fixture(scope="session")
def deviated_sample():
    """samples/make_deviated.py as a module, and its prediction of the SK8 rods in the J-shaped hole
    (cards, crank speed, unit), computed once: (module, (prediction, omega, unit))."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_deviated", REPO_ROOT / "samples" / "make_deviated.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module, module.prediction()
