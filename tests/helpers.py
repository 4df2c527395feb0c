"""Constants and small builders shared by the tests (importable: ``pythonpath`` in pyproject.toml).

Conversion factors are the package's own (:mod:`pumpjack_cli.quantities`); their values are
checked once, against the published definitions, in ``tests/validation/test_nist811.py``.
Fixtures live in ``tests/conftest.py``.
"""

from __future__ import annotations

import ast
import functools
import math
import os
import sqlite3
import time
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.core.beam.geometry import Linkage
# The package's conversion factors, re-exported so that a test takes every constant from here.
from pumpjack_cli.quantities import BARREL, FOOT, HORSEPOWER, INCH, KILOGRAM_FORCE, POUND_FORCE, POUND_MASS

#: The checkout: holds configs/, samples/, docs/ and pyproject.toml.
REPO_ROOT = Path(__file__).resolve().parents[1]

#: Pa per psi (lbf/in²).
PSI = POUND_FORCE / INCH**2
#: kg/m per lb/ft (a rod table's weight per foot as a mass per metre).
LB_PER_FT = POUND_MASS / FOOT
#: rad/s per rev/min, by definition.
RPM = 2 * math.pi / 60

#: API RP 11L, 4th ed., Table 4.1, columns 3-4 ([API11L]), restated from the source, not from the
#: package: rod size [in] -> (weight with couplings [lb/ft], elastic constant E_r [1e-6 in/(lb ft)]).
RP11L_TABLE_4_1 = {0.625: (1.135, 1.270), 0.750: (1.634, 0.883), 0.875: (2.224, 0.649),
                   1.000: (2.904, 0.497), 1.125: (3.676, 0.393)}

#: The bundled beam units with link masses (the spatial kinetostatics needs them).
BEAM_UNITS = ("sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54")
#: The bundled beam units with a sample card and a [well].
CARD_UNITS = ("sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54", "c-80d-133-48")

#: The bundled SK8-3,5-4000 of [SK8Rotation2013].
SK8 = "sk8-3.5-4000"
#: Its unit file (GOST names, every datum of the paper) and the same geometry in API letters, without [drive].
SK8_TOML = REPO_ROOT / "configs" / "sk8-3.5-4000.toml"
SK8_API_YAML = REPO_ROOT / "samples" / "sk8-3.5-4000-api.yaml"
#: Its linkage as the paper prints it: k1, k, r, l, l1, l2 = A, C, R, P, I, H - G [m], clockwise.
SK8_LINKAGE = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
#: Its crank speed at the motor's rated 1460 rpm as the paper prints it, pi 1460 / (30 37.18 900/250) [1/s].
SK8_CRANK_SPEED = 1.1422
#: Its well: pump depth [m] and produced-fluid density [kg/m³].
SK8_PUMP_DEPTH, SK8_FLUID_DENSITY = 1530.0, 820.0

#: The UNB-600A drill pump of [InertiaUNB600A]: crank radius r and connecting rod l2 [m].
UNB600A_CRANK_RADIUS, UNB600A_ROD_LENGTH = 0.2, 1.19


@functools.cache
def syntax_tree(path: Path) -> ast.Module:
    """A Python file's syntax tree, parsed once for every check that reads it."""
    return ast.parse(path.read_text(encoding="utf-8"))


def sample_card(unit: str) -> Path:
    """The bundled sample card of a unit (``samples/<unit>-card.csv``, made by ``samples/make_cards.py``)."""
    return REPO_ROOT / "samples" / f"{unit}-card.csv"


SK8_CARD = sample_card(SK8)


def series(doc: dict, name: str) -> np.ndarray:
    """A column of a command's JSON document as an array."""
    return np.array(doc["series"][name])


def polished_rod_position(linkage, theta: np.ndarray) -> np.ndarray:
    """Exact polished-rod position [m] above the bottom of the stroke at crank angles ``theta``."""
    m = linkage.motion(theta)
    return linkage.front_arm * (m.beam_angle - linkage.dead_positions().beam_angle_bottom)


def sk8_rod_position(samples: int) -> np.ndarray:
    """SK8-3,5-4000's polished-rod position at ``samples`` equal crank steps from crank angle 0."""
    return polished_rod_position(SK8_LINKAGE, np.arange(samples) * 2 * np.pi / samples)


def zoom_scan(objective, lo: float, hi: float, rounds: int = 12, points: int = 401) -> float:
    """Brute force: evaluate on a dense grid of the balancing variable, keep +-2 steps around the best, repeat.

    For a function that is unimodal near its minimum every window holds the minimiser,
    and each round shrinks the window 100-fold."""
    for _ in range(rounds):
        grid = np.linspace(lo, hi, points)
        k = int(np.argmin(objective(grid)))
        lo, hi = grid[max(k - 2, 0)], grid[min(k + 2, points - 1)]
    return float(grid[k])


def assert_same_summary(found: dict, expected: dict, rel: float, absolute: float, *where) -> int:
    """Every value of the summary ``expected`` in ``found``: a text label equal, a number within
    ``rel`` and ``absolute``; ``where`` heads the failure message. Returns how many were compared."""
    for name, value in expected.items():
        if isinstance(value, str):
            assert found[name] == value, (*where, name)
        else:
            assert found[name] == pytest.approx(value, rel=rel, abs=absolute), (*where, name)
    return len(expected)


def command_result(*argv):
    """The result a command run in-process with ``argv`` hands to the renderer, and what it wrote
    (``-f json`` in SI): the unit systems and text formats differ in the writing only, so one run
    serves them all (:func:`written`)."""
    import io
    from contextlib import redirect_stderr, redirect_stdout
    from unittest import mock

    from pumpjack_cli.cli import main
    from pumpjack_cli.render import Outputs

    emitted, emit = [], Outputs.emit

    def kept(self, result) -> None:
        emitted.append(result)
        emit(self, result)

    out, err = io.StringIO(), io.StringIO()
    with mock.patch.object(Outputs, "emit", kept), redirect_stdout(out), redirect_stderr(err):
        code = main([str(a) for a in argv] + ["-f", "json", "--units", "si"])
    assert code == 0 and len(emitted) == 1, err.getvalue()
    return emitted[0], out.getvalue()


def written(result, system: str, file_format: str = "json") -> str:
    """A result as ``-f FORMAT --units SYSTEM`` writes it to standard output."""
    import io

    from pumpjack_cli.render.delimited import write_csv, write_json

    stream = io.StringIO()
    {"json": write_json, "csv": write_csv}[file_format](result, system, stream)
    return stream.getvalue()


def one_line_error(code: int, out: str, err: str, *fragments: str) -> None:
    """A refusal as the CLI prints it: exit code 2, nothing on stdout, one line on stderr
    holding every fragment, no traceback."""
    assert code == 2, (code, err)
    assert out == ""
    assert err.startswith("pumpjack: error: ") and err.count("\n") == 1, err
    assert "Traceback" not in err
    for fragment in fragments:
        assert fragment in err, (fragment, err)


# --- `pumpjack batch`: fields of cards, manifests, stores, processes -----------------------

def field_cards(folder: Path, count: int, seed: int = 3, start: int = 0,
                units: tuple[str, ...] = CARD_UNITS) -> list[tuple[str, str, str, str]]:
    """``count`` cards of the bundled ``units`` (sample cards with scaled swing, noise and speed)
    written to ``folder``: (well, unit, card file name, timestamp) rows."""
    rng = np.random.default_rng(seed)
    rows = []
    for k in range(start, start + count):
        unit = units[k % len(units)]
        lines = sample_card(unit).read_text(encoding="utf-8").splitlines()
        body = [line for line in lines if not line.startswith("#")]
        data = np.array([[float(x) for x in line.split(",")] for line in body[1:]])
        mean = data[:, 2].mean()
        data[:, 2] = mean + rng.uniform(0.95, 1.05) * (data[:, 2] - mean) + rng.normal(0, 1e-3 * np.ptp(data[:, 2]),
                                                                                      len(data))
        data[:, 0] /= rng.uniform(0.97, 1.03)
        name = f"card-{k:04d}.csv"
        (folder / name).write_text(body[0] + "\n" + "".join(f"{t:.4f},{s:.5f},{w:.4f}\n" for t, s, w in data))
        rows.append((f"well-{k % 5}", unit, name, f"2026-11-{1 + k // 5:02d}T00:00"))
    return rows


def field_manifest(folder: Path, rows, name: str = "manifest.csv") -> Path:
    """A CSV manifest of (well, unit, card, timestamp) rows."""
    path = folder / name
    path.write_text("well,unit,card,timestamp\n" + "".join(",".join(row) + "\n" for row in rows))
    return path


def stored_results(store: Path) -> dict[tuple[str, str], dict]:
    """(card file name, analysis) -> the stored row."""
    db = sqlite3.connect(store)
    db.row_factory = sqlite3.Row
    rows = {(Path(r["card"]).name, r["analysis"]): dict(r) for r in db.execute("SELECT * FROM results")}
    db.close()
    return rows


def stored_count(store: Path) -> int:
    """Rows in a results store, 0 while it is missing or cannot be read."""
    try:
        db = sqlite3.connect(f"file:{store}?mode=ro", uri=True, timeout=5)
        try:
            return db.execute("SELECT COUNT(*) FROM results").fetchone()[0]
        finally:
            db.close()
    except sqlite3.Error:
        return 0


def wait_for_rows(store: Path, count: int, process=None, timeout: float = 120.0) -> int:
    """Wait until the store holds at least ``count`` rows (or ``process`` has ended); the
    rows found. The timeout only guards a hang."""
    deadline = time.monotonic() + timeout
    found = stored_count(store)
    while found < count and time.monotonic() < deadline and (process is None or process.poll() is None):
        time.sleep(0.02)
        found = stored_count(store)
    return found


def children_of(pid: int) -> list[int]:
    """The live processes whose parent is ``pid``, from the process table (/proc)."""
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat", encoding="ascii", errors="replace") as handle:
                    fields = handle.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == pid and fields[0] != "Z":
                found.append(int(entry))
    return found


def alive(pid: int) -> bool:
    """Whether the process ``pid`` exists and is not a zombie (from /proc)."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as handle:
            return handle.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def gone(pids, timeout: float = 60.0) -> bool:
    """Whether every process of ``pids`` has ended within ``timeout`` seconds (a guard against a hang)."""
    deadline = time.monotonic() + timeout
    while any(alive(pid) for pid in pids) and time.monotonic() < deadline:
        time.sleep(0.05)
    return not any(alive(pid) for pid in pids)
