"""Shared fixtures: the repository root, the CLI run in-process and as the real console script."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="session")
def repo_root() -> Path:
    """The checkout: holds configs/, samples/ and pyproject.toml."""
    assert (REPO_ROOT / "pyproject.toml").is_file()
    return REPO_ROOT


@pytest.fixture(scope="session")
def sk8_toml(repo_root) -> Path:
    """The bundled SK8-3,5-4000 unit (GOST names, every datum of [SK8Rotation2013])."""
    return repo_root / "configs" / "sk8-3.5-4000.toml"


@pytest.fixture(scope="session")
def sk8_api_yaml(repo_root) -> Path:
    """The same SK8-3,5-4000 geometry written with API 11E letters, without [drive]."""
    return repo_root / "samples" / "sk8-3.5-4000-api.yaml"


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

    Returns the CompletedProcess with text stdout/stderr. The timeout only guards
    against a hang; no assertion depends on how long a run takes.
    """

    def run(*argv: str, **kwargs) -> subprocess.CompletedProcess:
        env = dict(os.environ)
        env.pop("COLUMNS", None)
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
def sk8_drivable_card(repo_root, tmp_path_factory) -> Path:
    """The SK8-3,5-4000 sample card with its load swing halved about its mean.

    The sample card (elastic rods, `samples/make_cards.py`) asks the SK8's motor, with the
    counterbalance of [SK8Rotation2013], for more than its pull-out torque, so the
    equation of motion under it is refused ("the motor is too weak"); tests of identities
    that need the machine driven by a card use this lighter card of the same shape."""
    import numpy as np

    lines = (repo_root / "samples" / "sk8-3.5-4000-card.csv").read_text(encoding="utf-8").splitlines()
    body = [line for line in lines if not line.startswith("#")]
    rows = np.array([[float(x) for x in line.split(",")] for line in body[1:]])
    rows[:, 2] = rows[:, 2].mean() + 0.5 * (rows[:, 2] - rows[:, 2].mean())
    path = tmp_path_factory.mktemp("cards") / "sk8-drivable-card.csv"
    path.write_text("\n".join([body[0]] + [",".join(repr(float(x)) for x in row) for row in rows]) + "\n",
                    encoding="utf-8")
    return path
