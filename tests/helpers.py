"""Constants and small builders shared by the tests (importable: ``pythonpath`` in pyproject.toml).

Conversion factors are the package's own (:mod:`pumpjack_cli.quantities`); their values are
checked once, against the published definitions, in ``tests/validation/test_nist811.py``.
Fixtures live in ``tests/conftest.py``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

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
