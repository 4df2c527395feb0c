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

import numpy as np
import pytest

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.balance import balance_criteria, recommend_counterbalance
from pumpjack_cli.core.beam.card import card_load
from pumpjack_cli.core.beam.counterbalance import Counterbalance, counterbalance_from_masses, upstroke_mask
from pumpjack_cli.core.beam.loading import card_work
from pumpjack_cli.core.beam.torque import api_net_torque
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.readers.cards import read_card

from helpers import sample_card, zoom_scan

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
    reading = place(read_card(sample_card(name), units=CARDS[name][0]), linkage)
    return linkage, config.masses.model(), reading.card


def torques(base: np.ndarray, sine: np.ndarray, moments: np.ndarray) -> np.ndarray:
    return base[None, :] - moments[:, None] * sine[None, :]


def balance_of(name: str):
    """Linkage, B M tau and card of a bundled unit: from the masses, or from the
    [counterbalance] of a unit described without them (C-80D-133-48)."""
    config = load_unit(name)
    linkage = config.geometry.mechanism()
    units = CARDS.get(name, ("field",))[0]
    card = place(read_card(sample_card(name), units=units), linkage).card
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
        assert result.value == pytest.approx(scanned, rel=1e-6), criterion
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
    """The cards were made at uniform crank speed 2 pi spm / 60: the speed fitted to the
    time stamps stays within 2e-4 of it and the acceleration below 1e-3 omega^2 at every
    sample (six harmonics fitted to a uniform motion). The limits come from the files'
    rounding: time to 1e-4 s is an angle error of RMS omega 1e-4 / sqrt(12) = 3.3e-5
    rad at 1.14 1/s; least squares over 180 samples gives each harmonic's coefficient to
    that times sqrt(2 / 180), 3.5e-6 rad, and harmonic j puts j times it into omega /
    omega_m and j^2 times it into alpha / omega_m^2: RMS 2.4e-5 and 1.2e-4 over six
    harmonics, so the limits leave a factor of about 3 over the largest samples (the
    positions' rounding to 1e-5 m adds less)."""
    linkage, _, _ = bundled(name)
    reading = place(read_card(sample_card(name), units=CARDS[name][0]), linkage)
    uniform = 2 * math.pi * CARDS[name][1] / 60
    assert np.max(np.abs(reading.crank_speed / uniform - 1)) < 2e-4
    assert np.max(np.abs(reading.crank_acceleration)) < 1e-3 * uniform**2
