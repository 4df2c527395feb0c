"""Torque components with non-uniform crank speed (Takacs, Kis & Koncz 2016).

The components are checked against the spatial kinetostatics with inertia (an
independent model: d'Alembert forces and moments of every link) and the
articulating-inertia term against the rate of change of the beam group's kinetic
energy by finite differences.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.counterbalance import Counterbalance, counterbalance_from_masses
from pumpjack_cli.core.beam.torque import (api_net_torque, beam_group_inertia, crank_group_inertia, exact_net_torque,
                                           torque_components)
from pumpjack_cli.core.sampling import crank_grid

from helpers import BEAM_UNITS

THETA = crank_grid(720)


def load(theta: np.ndarray) -> np.ndarray:
    """A smooth card-like polished-rod load [N]."""
    return 50e3 + 15e3 * np.sin(theta) + 5e3 * np.cos(2 * theta)


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_components_reproduce_kinetostatics_with_non_uniform_speed(name):
    """Beam group balanced about the saddle bearing (horsehead centre moved so that
    m_b x_b + m_h x_h = m_eq C, hence B = 0 and no beam gravity torque at any beam
    angle) and massless pitmans: the five components of Takacs et al. add up to the
    exact balancing torque with inertia, at a crank speed and acceleration that vary
    along the cycle. 1e-9 relative to the peak (round-off)."""
    config = load_unit(name)
    spatial, masses = config.geometry.spatial(name), config.masses.model()
    lk = spatial.planar
    balanced_cg = (masses.equalizer_mass * lk.rear_arm - masses.beam_mass * masses.beam_cg) / masses.horsehead_mass
    m = dataclasses.replace(masses, pitman_mass=0.0, pitman_inertia=0.0, horsehead_cg=balanced_cg)
    bal = counterbalance_from_masses(lk, m)
    assert bal.structural_unbalance == pytest.approx(0.0, abs=1e-9)
    omega = 1.1 * (1.0 + 0.1 * np.sin(2 * THETA))
    alpha = 0.3 * np.cos(THETA) - 0.2 * np.sin(2 * THETA)
    parts = torque_components(lk, THETA, load(THETA), bal, beam_inertia=beam_group_inertia(lk, m),
                              rotary_inertia=crank_group_inertia(m), crank_speed=omega, crank_acceleration=alpha)
    exact = exact_net_torque(spatial, m, THETA, load(THETA), omega, alpha)
    assert np.max(np.abs(parts.net - exact)) <= 1e-9 * np.max(np.abs(exact))
    assert np.max(np.abs(parts.articulating_inertia)) > 1e-3 * np.max(np.abs(exact))  # the term matters here


def test_components_sum_and_static_limit():
    """net is the sum of the five arrays; at omega = alpha = 0 the inertia terms vanish
    and net is the API torque; rod-load, structural and counterbalance terms are the
    API formula's three terms."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    bal = Counterbalance(-800.0, 60e3, 0.1)
    parts = torque_components(lk, THETA, load(THETA), bal, beam_inertia=5e3, rotary_inertia=3e4)
    tf = lk.torque_factor(THETA)
    assert np.all(parts.articulating_inertia == 0.0) and np.all(parts.rotary_inertia == 0.0)
    assert parts.net == pytest.approx(api_net_torque(THETA, tf, load(THETA), bal), rel=1e-13, abs=1e-9)
    assert parts.rod_load == pytest.approx(tf * load(THETA), rel=1e-15)
    assert parts.structural == pytest.approx(800.0 * tf, rel=1e-15)
    assert parts.counterbalance == pytest.approx(-60e3 * np.sin(THETA + 0.1), rel=1e-15, abs=1e-9)


def test_articulating_inertia_is_the_rate_of_beam_kinetic_energy():
    """Along a motion theta(t) = w0 t + 0.1 sin(w0 t), the power of the articulating
    term, T_a omega, equals d/dt of (1/2) I_b psi_dot^2 computed by central differences
    of psi(theta(t)) in time. Tolerance 1e-6 relative: the O(h^2) difference error with
    h = 1e-4 s on the second derivative of psi."""
    lk = load_unit("7sk12-2.5-5600").geometry.mechanism()
    w0, ib, h = 0.9, 4000.0, 1e-4
    t = np.linspace(0.0, 2 * np.pi / w0, 50, endpoint=False)

    def theta(time):
        return w0 * time + 0.1 * np.sin(w0 * time)

    def kinetic(time):
        psi = lambda x: lk.motion(theta(x)).beam_angle  # noqa: E731
        psi_dot = (psi(time + h) - psi(time - h)) / (2 * h)
        return 0.5 * ib * psi_dot**2

    power = (kinetic(t + h) - kinetic(t - h)) / (2 * h)
    omega = w0 * (1 + 0.1 * np.cos(w0 * t))
    alpha = -0.1 * w0**2 * np.sin(w0 * t)
    parts = torque_components(lk, theta(t) % (2 * np.pi), np.zeros_like(t), Counterbalance(0.0, 0.0),
                              beam_inertia=ib, crank_speed=omega, crank_acceleration=alpha)
    assert parts.articulating_inertia * omega == pytest.approx(power, rel=1e-6, abs=1e-6 * np.max(np.abs(power)))


@pytest.mark.parametrize("name", ["sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54"])
def test_exact_torque_is_affine_in_load_speed_squared_and_acceleration(name):
    """The basis of four kinetostatic solutions (ExactTorqueBasis) reproduces the direct
    solution for arbitrary loads, speeds and accelerations at every angle: the rational
    mechanism is linear in its loads and its inertia terms scale with omega^2 and eps
    ([Spatial7SK12]); 1e-10 of the peak torque (round-off of the differences)."""
    from pumpjack_cli.core.beam.torque import exact_net_torque, exact_torque_basis

    unit = load_unit(name)
    spatial, masses = unit.geometry.spatial(), unit.mass_model()
    theta = crank_grid(97)
    basis = exact_torque_basis(spatial, masses, theta)
    rng = np.random.default_rng(7)
    for _ in range(3):
        w, omega, alpha = rng.uniform(1e4, 9e4, theta.size), rng.uniform(0.3, 2.0, theta.size), rng.uniform(-1, 1, 97)
        direct = exact_net_torque(spatial, masses, theta, w, omega, alpha)
        assert np.max(np.abs(basis.torque(w, omega, alpha) - direct)) < 1e-10 * np.max(np.abs(direct))


def test_exact_torque_basis_in_blocks_is_the_whole_grid(monkeypatch):
    """A grid longer than a quarter of the kinetostatics' BLOCK is solved block by block
    (only the torques kept: bounded memory); the responses are those of one batch, to the bit."""
    from pumpjack_cli.core.beam import kinetostatics
    from pumpjack_cli.core.beam.torque import exact_torque_basis

    unit = load_unit("sk8-3.5-4000")
    spatial, masses = unit.geometry.spatial(), unit.mass_model()
    theta = crank_grid(1000)
    whole = exact_torque_basis(spatial, masses, theta)
    monkeypatch.setattr(kinetostatics, "BLOCK", 64)
    blocks = exact_torque_basis(spatial, masses, theta)
    for name in ("static", "per_load", "per_speed_squared", "per_acceleration"):
        assert np.array_equal(getattr(blocks, name), getattr(whole, name)), name
