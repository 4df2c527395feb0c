"""The torque analysis on every bundled beam unit with its sample card
(samples/<unit>-card.csv, read as the CLI reads it; the C-114D card is in field units).

* every balance optimiser agrees with a brute-force scan of M (1e-6 relative);
* the mean API net torque over a revolution is the card work / 2 pi (the
  counterbalance and the structure do no net work over a cycle);
* the crank speed recovered from the cards' time stamps is the uniform speed the
  cards were made with (samples/make_cards.py).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.card_files import read_card
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.balance import balance_criteria, recommend_counterbalance
from pumpjack_cli.core.beam.card import card_load, crank_angle_from_position, upstroke_points
from pumpjack_cli.core.beam.counterbalance import Counterbalance, counterbalance_from_masses, upstroke_mask
from pumpjack_cli.core.beam.loading import card_work
from pumpjack_cli.core.beam.torque import api_net_torque, crank_rates_from_time
from pumpjack_cli.core.sampling import crank_grid

REPO = Path(__file__).resolve().parents[1]
#: unit -> (card units, strokes per minute the card was made at: samples/make_cards.py;
#: SK8 runs at the motor's rated speed, pi 1460 / (30 x 37.18 x 3.6) = 1.1422 1/s)
CARDS = {
    "sk8-3.5-4000": ("si", 1460 / (37.18 * 900 / 250)),
    "7sk12-2.5-5600": ("si", 8.0),
    "c-114d-133-54": ("field", 10.0),
}
THETA = crank_grid(1800)


def bundled(name: str):
    """Linkage, masses and card of a bundled unit."""
    config = load_unit(name)
    linkage = config.geometry.mechanism()
    reading = read_card(REPO / "samples" / f"{name}-card.csv", linkage, CARDS[name][0])
    return linkage, config.masses.model(), reading.card


def zoom_scan(objective, lo: float, hi: float, rounds: int = 12, points: int = 401) -> float:
    """Brute force: evaluate on a dense grid of M, keep +-2 steps around the best, repeat.

    For a function that is unimodal near its minimum every window holds the minimiser,
    and each round shrinks the window 100-fold."""
    for _ in range(rounds):
        grid = np.linspace(lo, hi, points)
        k = int(np.argmin(objective(grid)))
        lo, hi = grid[max(k - 2, 0)], grid[min(k + 2, points - 1)]
    return float(grid[k])


def torques(base: np.ndarray, sine: np.ndarray, moments: np.ndarray) -> np.ndarray:
    return base[None, :] - moments[:, None] * sine[None, :]


def balance_of(name: str):
    """Linkage, B M tau and card of a bundled unit: from the masses, or from the
    [counterbalance] of a unit described without them (C-80D-133-48)."""
    config = load_unit(name)
    linkage = config.geometry.mechanism()
    units = CARDS.get(name, ("field",))[0]
    card = read_card(REPO / "samples" / f"{name}-card.csv", linkage, units).card
    if config.masses is not None:
        return linkage, counterbalance_from_masses(linkage, config.masses.model()), card
    given = config.counterbalance
    return linkage, Counterbalance(given.structural_unbalance, given.moment, given.phase), card


@pytest.mark.parametrize("name", [*CARDS, "c-80d-133-48"])
def test_optimisers_agree_with_brute_force_scans(name):
    """Each criterion's M and peak torque equal those of a scan of the same objective
    on the same crank grid to 1e-6 relative (the scan's final window is ~1e-20 of the
    range, so the tolerance checks the optimiser, not the scan)."""
    linkage, bal, card = balance_of(name)
    w = card_load(card, THETA)
    base = linkage.torque_factor(THETA) * (w - bal.structural_unbalance)
    sine = np.sin(THETA - bal.offset)
    up = upstroke_mask(linkage, THETA)
    hi = 2 * np.max(np.abs(base)) / np.max(np.abs(sine))
    objectives = {
        "min-peak": lambda m: np.max(np.abs(torques(base, sine, m)), axis=1),
        "min-rms": lambda m: np.mean(torques(base, sine, m) ** 2, axis=1),
        "equal-peaks": lambda m: np.abs(np.max(np.where(up, torques(base, sine, m), -np.inf), axis=1)
                                        - np.max(np.where(up, -np.inf, torques(base, sine, m)), axis=1)),
    }
    for criterion in balance_criteria():
        result = recommend_counterbalance(criterion, linkage, THETA, w, bal)
        scanned = zoom_scan(objectives[criterion], 0.0, hi)
        assert result.moment == pytest.approx(scanned, rel=1e-6), criterion
        peak = float(np.max(np.abs(base - scanned * sine)))
        assert result.peak_net_torque == pytest.approx(peak, rel=1e-6), criterion
    equal = recommend_counterbalance("equal-peaks", linkage, THETA, w, bal)
    assert equal.upstroke_peak == pytest.approx(equal.downstroke_peak, rel=1e-9)


@pytest.mark.parametrize("name", CARDS)
def test_mean_net_torque_is_card_work_over_two_pi(name):
    """Integral of T over a revolution = closed integral of W ds (TF = ds/dtheta; the
    structural and counterbalance terms integrate to zero). 2e-4 relative: the card is
    interpolated linearly in crank angle for T and in position for the work (180
    points, 2 deg apart), which differ at second order in the point spacing."""
    linkage, masses, card = bundled(name)
    bal = counterbalance_from_masses(linkage, masses)
    t = api_net_torque(THETA, linkage.torque_factor(THETA), card_load(card, THETA), bal)
    assert np.mean(t) == pytest.approx(card_work(linkage, card) / (2 * np.pi), rel=2e-4)


@pytest.mark.parametrize("name", CARDS)
def test_crank_speed_from_the_cards_time_stamps(name):
    """The cards were made at uniform crank speed 2 pi spm / 60: the recovered speed is
    within 0.1 % of it and the acceleration below 0.2 % of omega^2 (4 harmonics). The
    limits come from the files' rounding: positions to 1e-5 m (or in), which near the
    dead positions moves the angle by up to sqrt(2e-5 / A psi'') ~ 3e-3 rad, and time
    to 1e-4 s, 0.3 % of the 0.03 s step."""
    config = load_unit(name)
    linkage = config.geometry.mechanism()
    data = np.loadtxt(REPO / "samples" / f"{name}-card.csv", delimiter=",", comments="#", skiprows=4)
    time = data[:, 0]
    position = data[:, 1] * (0.0254 if CARDS[name][0] == "field" else 1.0)
    position = (position - position.min()) * linkage.stroke / np.ptp(position)
    theta = crank_angle_from_position(linkage, position, upstroke_points(position))
    omega, alpha = crank_rates_from_time(linkage, time, theta)
    uniform = 2 * math.pi * CARDS[name][1] / 60
    assert np.max(np.abs(omega / uniform - 1)) < 1e-3
    assert np.max(np.abs(alpha)) < 2e-3 * uniform**2
