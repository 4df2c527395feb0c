"""API 11E net torque, counterbalance from masses, CBE, permissible loads and the method
registry, checked against the spatial kinetostatics (an independent model: d'Alembert
equilibrium of every link, :mod:`pumpjack_cli.core.beam.kinetostatics`) and by hand.

Tolerances of 1e-9 relative are float round-off of two different computations of the
same exact quantity (the kinetostatics goes through a 3-D block elimination).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.counterbalance import (Counterbalance, counterbalance_effect,
                                                   counterbalance_from_masses, upstroke_mask)
from pumpjack_cli.core.beam.kinetostatics import rational_mechanism
from pumpjack_cli.core.beam.masses import MassModel
from pumpjack_cli.core.beam.torque import (api_net_torque, compare_methods, exact_net_torque, net_torque,
                                           permissible_load, torque_methods)
from pumpjack_cli.core.constants import STANDARD_GRAVITY as G
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.errors import TorqueError

from helpers import BEAM_UNITS, KILOGRAM_FORCE

ZERO = MassModel(*[0.0] * 18)
THETA = crank_grid(720)


def unit(name: str):
    config = load_unit(name)
    return config.geometry.spatial(name), config.masses.model()


def card_like(theta: np.ndarray) -> np.ndarray:
    """A smooth card-like polished-rod load [N]: 50 kN mean, first and second harmonics."""
    return 50e3 + 15e3 * np.sin(theta) + 5e3 * np.cos(2 * theta)


def static_exact(spatial, masses, load) -> np.ndarray:
    """Balancing torque of the rational mechanism with weights and no inertia."""
    _, reactions = rational_mechanism(spatial, masses, THETA, 0.0, 0.0, load, inertia=False)
    return reactions.net_torque


def crank_only(masses: MassModel, phase: float) -> MassModel:
    return dataclasses.replace(ZERO, crank_arm_mass=masses.crank_arm_mass, crank_arm_cg=masses.crank_arm_cg,
                               counterweight_mass=masses.counterweight_mass,
                               counterweight_radius=masses.counterweight_radius, counterweight_phase=phase)


@pytest.mark.parametrize("name", BEAM_UNITS)
@pytest.mark.parametrize("phase", [0.0, 0.4, -0.3])
def test_counterbalance_moment_equals_kinetostatic_gravity_of_crank_group(name, phase):
    """M, tau from counterbalance_from_masses reproduce the balancing torque of crank arms
    and counterweights alone (rod load 0, inertia off) at every crank angle, 1e-9
    relative to M. With phase 0 (conventional) the term is -M sin(theta): the
    counterweights, in line with the pin, help the gearbox while the pin descends."""
    spatial, masses = unit(name)
    crank = crank_only(masses, phase)
    b, m, tau, _ = counterbalance_from_masses(spatial.planar, crank)
    assert b == 0.0
    exact = static_exact(spatial, crank, np.zeros_like(THETA))
    assert np.max(np.abs(exact - (-m * np.sin(THETA + tau)))) <= 1e-9 * m
    if phase == 0.0:
        assert tau == 0.0
        assert m == pytest.approx(G * (2 * masses.crank_arm_mass * masses.crank_arm_cg
                                       + masses.counterweight_mass * masses.counterweight_radius), rel=1e-15)


def test_crank_offset_sign_is_the_lead_of_the_counterweights():
    """Counterweights alone at phase phi ahead of the pin give tau = phi (a lag is negative)."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    masses = dataclasses.replace(ZERO, counterweight_mass=1000.0, counterweight_radius=1.0, counterweight_phase=0.25)
    _, m, tau, _ = counterbalance_from_masses(lk, masses)
    assert tau == pytest.approx(0.25, abs=1e-15) and m == pytest.approx(1000.0 * G, rel=1e-15)


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_structural_unbalance_is_the_level_beam_gravity_of_the_kinetostatics(name):
    """Beam body, horsehead and equalizer only (pitmans massless): the exact gravity
    torque is -TF B cos(psi) with B from the masses, i.e. B is the polished-rod force
    of the beam group when the beam is level (psi = 0). 1e-9 relative to the peak."""
    spatial, masses = unit(name)
    beam = dataclasses.replace(masses, crank_arm_mass=0.0, counterweight_mass=0.0, pitman_mass=0.0)
    b = counterbalance_from_masses(spatial.planar, beam).structural_unbalance
    exact = static_exact(spatial, beam, np.zeros_like(THETA))
    m = spatial.planar.motion(THETA)
    expected = -spatial.planar.front_arm * m.beam_rate * b * np.cos(m.beam_angle)
    assert np.max(np.abs(exact - expected)) <= 1e-9 * np.max(np.abs(expected))


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_exact_minus_api_is_beam_tilt_and_pitman_share(name):
    """With every mass of the bundled unit (static, inertia off), exact - API is exactly
    the two simplifications of the API method, computed here independently:
    (1) the beam group's weight acts through cos(psi), not at a level beam:
        (TF/A) g (m_b x_b + m_h x_h - m_eq C)(cos psi - 1);
    (2) each pitman's weight is shared between crank pin and equalizer pin by its centre
        of mass (f = AS/P), where B hangs it whole on the equalizer:
        2 m_p g [(1 - f) dy_A/dtheta + f dy_B/dtheta] + 2 m_p g C psi'.
    1e-9 relative to the peak torque."""
    spatial, masses = unit(name)
    lk = spatial.planar
    load = card_like(THETA)
    api = net_torque("api", spatial, masses, THETA, load)
    exact = static_exact(spatial, masses, load)
    m = lk.motion(THETA)
    moment = masses.beam_mass * masses.beam_cg + masses.horsehead_mass * masses.horsehead_cg \
        - masses.equalizer_mass * lk.rear_arm
    tilt = m.beam_rate * G * moment * (np.cos(m.beam_angle) - 1.0)
    f = masses.pitman_cg / spatial.pitman
    dy_a = -lk.crank_radius * np.sin(THETA)
    dy_b = -lk.rear_arm * np.cos(m.beam_angle) * m.beam_rate
    pitmans = 2 * masses.pitman_mass * G * ((1 - f) * dy_a + f * dy_b + lk.rear_arm * m.beam_rate)
    assert np.max(np.abs(exact - api - tilt - pitmans)) <= 1e-9 * np.max(np.abs(exact))


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_exact_equals_api_without_masses(name):
    """All masses zero: B = M = 0 and both methods give TF W (1e-9 of the peak), also
    with a crank speed (no mass, no inertia)."""
    spatial, _ = unit(name)
    load = card_like(THETA)
    assert counterbalance_from_masses(spatial.planar, ZERO) == (0.0, 0.0, 0.0, False)
    both = compare_methods(spatial, ZERO, THETA, load, crank_speed=1.2, crank_acceleration=0.05)
    peak = np.max(np.abs(both.api))
    assert np.max(np.abs(both.api - both.exact)) <= 1e-9 * peak
    assert np.max(np.abs(both.api - spatial.planar.torque_factor(THETA) * load)) <= 1e-12 * peak


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_exact_equals_api_with_counterweights_only(name):
    """Crank arms and counterweights only, static: the API counterbalance term from the
    masses is the whole difference to TF W, in both methods (1e-9 of the peak)."""
    spatial, masses = unit(name)
    crank = crank_only(masses, 0.0)
    load = card_like(THETA)
    api = net_torque("api", spatial, crank, THETA, load)
    exact = exact_net_torque(spatial, crank, THETA, load)
    assert np.max(np.abs(api - exact)) <= 1e-9 * np.max(np.abs(exact))


def test_methods_registry():
    assert torque_methods() == ("api", "exact")
    spatial, masses = unit("sk8-3.5-4000")
    with pytest.raises(TorqueError, match="unknown torque method 'rp11l'; use one of api, exact"):
        net_torque("rp11l", spatial, masses, THETA, card_like(THETA))


def test_api_net_torque_by_hand():
    """T = TF (W - B) - M sin(theta + tau) at three positions, evaluated here by hand (tau = -10 deg,
    a lag of 10 deg as a reverse-mark's catalogue prints it)."""
    theta = np.radians([30.0, 90.0, 200.0])
    tf = np.array([0.8, 1.3, -1.1])
    w = np.array([60e3, 55e3, 30e3])
    bal = Counterbalance(500.0, 45e3, math.radians(-10.0))
    expected = [0.8 * 59_500 - 45e3 * math.sin(math.radians(20)),
                1.3 * 54_500 - 45e3 * math.sin(math.radians(80)),
                -1.1 * 29_500 - 45e3 * math.sin(math.radians(190))]
    assert api_net_torque(theta, tf, w, bal) == pytest.approx(expected, rel=1e-14)


def test_api_net_torque_rejects_nan():
    with pytest.raises(TorqueError, match="not finite"):
        api_net_torque(THETA[:2], np.array([1.0, np.nan]), np.ones(2), Counterbalance(0.0, 0.0))


def test_counterbalance_effect_balances_the_torque_at_the_test_angle():
    """CBE is the load that makes T = 0 at theta_t = 90 deg (cranks horizontal)."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    bal = Counterbalance(-800.0, 60e3, 0.0)
    test = np.array([math.pi / 2])
    cbe = counterbalance_effect(lk.motion(test), bal)
    assert api_net_torque(test, lk.torque_factor(test), np.array([cbe]), bal)[0] == pytest.approx(0.0, abs=1e-9)
    with pytest.raises(TorqueError, match="test angle"):
        counterbalance_effect(dataclasses.replace(lk.motion(test), torque_factor=np.zeros(1)), bal)


def test_permissible_load_by_hand():
    """Gault's bounds at several positions: the formula evaluated here for TF > 0 and
    TF < 0 (bounds swapped), and loads on the bounds give |T| = T_r exactly."""
    lk = load_unit("7sk12-2.5-5600").geometry.mechanism()
    theta = np.radians([40.0, 90.0, 150.0, 230.0, 300.0])
    tf = lk.torque_factor(theta)
    bal = Counterbalance(700.0, 80e3, 0.0)
    rating = 5600 * KILOGRAM_FORCE
    low, high = permissible_load(tf, -tf * 700.0 - 80e3 * np.sin(theta), rating)
    for k in range(theta.size):
        cb = 80e3 * math.sin(theta[k])
        a, b = 700.0 + (cb - rating) / tf[k], 700.0 + (cb + rating) / tf[k]
        assert (low[k], high[k]) == pytest.approx((min(a, b), max(a, b)), rel=1e-14)
    assert np.all(tf[:3] > 0) and np.all(tf[3:] < 0)
    edges = np.abs(api_net_torque(np.concatenate([theta, theta]), np.concatenate([tf, tf]),
                                  np.concatenate([low, high]), bal))
    assert edges == pytest.approx(rating, rel=1e-12)


def test_permissible_load_where_the_torque_factor_vanishes():
    """TF = 0: any load if the counterbalance alone is within the rating, none otherwise."""
    theta = np.radians([0.0, 90.0])
    low, high = permissible_load(np.zeros(2), -50e3 * np.sin(theta), 40e3)
    assert (low[0], high[0]) == (-np.inf, np.inf)      # |50e3 sin 0| = 0 <= 40e3
    assert (low[1], high[1]) == (np.inf, -np.inf)      # |50e3 sin 90| = 50e3 > 40e3: empty
    with pytest.raises(TorqueError, match="gearbox rating"):
        permissible_load(np.ones(2), np.zeros(2), 0.0)


def test_upstroke_mask_matches_rising_polished_rod():
    """On the upstroke the polished rod rises: TF > 0 there and < 0 on the downstroke."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    up = upstroke_mask(lk, THETA)
    tf = lk.torque_factor(THETA)
    dead = lk.dead_positions()
    near = np.minimum(np.abs((THETA - dead.crank_angle_bottom + np.pi) % (2 * np.pi) - np.pi),
                      np.abs((THETA - dead.crank_angle_top + np.pi) % (2 * np.pi) - np.pi)) < 1e-9
    assert np.all(tf[up & ~near] > 0) and np.all(tf[~up & ~near] < 0)
