"""Loading against the ratings, card work, polished-rod power, CLF and motor power: hand
arithmetic on cards and torque curves whose integrals are known in closed form."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import Card
from pumpjack_cli.core.beam.loading import card_work, cyclic_load_factor, loading
from pumpjack_cli.core.designations import parse_designation
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.errors import TorqueError

STEPS = 3600


def square_card(linkage, w_up: float, w_down: float) -> Card:
    """W_up while the polished rod rises, W_down while it falls, on a dense grid."""
    theta = crank_grid(STEPS)
    return Card(theta, np.where(linkage.motion(theta).beam_rate > 0, w_up, w_down))


def test_square_card_work_is_load_difference_times_stroke():
    """Work of a square card = (W_up - W_down) S. 1e-5 relative: the trapezoid rule
    averages the two loads on the two segments that cross the dead positions, where
    ds is O(dtheta^2) = (2 pi / 3600)^2 of the stroke."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    work = card_work(lk, square_card(lk, 70e3, 40e3))
    assert work == pytest.approx(30e3 * lk.stroke, rel=1e-5)


def test_loading_percentages_and_power_by_hand():
    """SK8-3,5-4000 rated by its designation (39 226.6 N·m, 78 453.2 N, 3.5 m), a square
    card 70/40 kN at 6 strokes/min and a torque curve T = 20 + 12 sin(theta) kN·m:
    gearbox 100 x 32 000 / 39 226.6 = 81.577 %; structure 100 x 70 000 / 78 453.2 =
    89.225 %; stroke 100 S / 3.5; P_pr = 30 kN x S x 0.1 1/s; CLF = sqrt(400 + 72)/20 =
    1.086 278; motor power T_rms omega / eta = 21 725.56 N·m x 0.628 319 1/s / 0.9."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    rating = parse_designation("SK8-3,5-4000")
    theta = crank_grid(STEPS)
    result = loading(20e3 + 12e3 * np.sin(theta), square_card(lk, 70e3, 40e3), lk, 6 / 60,
                     gearbox_rating=rating.gearbox_torque, structure_rating=rating.structure_load,
                     max_stroke=rating.max_stroke, drive_efficiency=0.9)
    assert result.peak_net_torque == pytest.approx(32e3, rel=1e-12)
    assert result.peak_net_torque_angle == pytest.approx(math.pi / 2, abs=1e-12)
    assert result.gearbox_loading_percent == pytest.approx(81.577, abs=1e-3)
    assert result.structure_loading_percent == pytest.approx(89.225, abs=1e-3)
    assert result.stroke_percent == pytest.approx(100 * lk.stroke / 3.5, rel=1e-12)
    assert result.polished_rod_power == pytest.approx(30e3 * lk.stroke * 0.1, rel=1e-5)
    assert result.mean_torque == pytest.approx(20e3, rel=1e-12)
    assert result.cyclic_load_factor == pytest.approx(math.sqrt(472) / 20, rel=1e-12)
    assert result.rms_torque == pytest.approx(1e3 * math.sqrt(472), rel=1e-12)
    assert result.motor_power == pytest.approx(1e3 * math.sqrt(472) * 2 * math.pi * 0.1 / 0.9, rel=1e-12)


def test_motor_power_is_clf_times_polished_rod_power_at_uniform_speed():
    """When T_mean = work / 2 pi (the API torque of the card), the RMS rule gives
    P_motor = CLF P_pr / eta."""
    lk = load_unit("7sk12-2.5-5600").geometry.mechanism()
    card = square_card(lk, 80e3, 45e3)
    theta = crank_grid(STEPS)
    torque = lk.front_arm * lk.motion(theta).beam_rate * card.load - 70e3 * np.sin(theta)
    result = loading(torque, card, lk, 8 / 60, gearbox_rating=60e3, structure_rating=120e3, max_stroke=2.5)
    assert result.motor_power == pytest.approx(result.cyclic_load_factor * result.polished_rod_power, rel=1e-5)


def test_cyclic_load_factor_of_constant_torque_is_one():
    assert cyclic_load_factor(np.full(100, 5e3)) == pytest.approx(1.0, rel=1e-15)


@pytest.mark.parametrize("torque, message", [
    (np.sin(crank_grid(360)), "mean net torque"),
    (np.array([1.0, np.nan]), "not finite"),
])
def test_cyclic_load_factor_undefined(torque, message):
    with pytest.raises(TorqueError, match=message):
        cyclic_load_factor(torque)


@pytest.mark.parametrize("field, value, message", [
    ("gearbox_rating", 0.0, "gearbox rating is 0.0"),
    ("structure_rating", -1.0, "structure rating is -1.0"),
    ("max_stroke", float("nan"), "maximum stroke is nan"),
    ("drive_efficiency", 1.5, "drive efficiency is 1.5"),
])
def test_loading_rejects_bad_ratings(field, value, message):
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    kwargs = dict(gearbox_rating=40e3, structure_rating=80e3, max_stroke=3.5)
    kwargs[field] = value
    with pytest.raises(TorqueError, match=message):
        loading(np.full(STEPS, 1e3), square_card(lk, 70e3, 40e3), lk, 0.1, **kwargs)
