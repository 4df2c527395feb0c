"""The equation of motion (pumpjack_cli.core.dynamics): invariants and hand values on SK8-3,5-4000.

The numbers [SK8Rotation2013] prints (motor line, rated crank speed, constant inertia) are
checked in tests/validation/test_sk8rotation2013.py. Independent references used here:
* the drive reduction by hand;
* the rational-mechanism kinetostatics of issue 3 (pumpjack_cli.core.beam.kinetostatics),
  a separate spatial d'Alembert solution: by virtual work its balancing torque equals
  the gravity torque dV/dtheta (weights only) and I epsilon + 1/2 I' omega^2 (inertia only);
* energy and periodicity: over a periodic cycle kinetic and potential energy return, so
  the motor's energy equals the work of the polished-rod load, stroke x (P_up - P_down)
  for the well model; and with M = a u + b u^2 omega the cycle mean of M over the crank
  angle is E / 2 pi, which fixes the angle-mean of omega.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from pumpjack_cli.core.beam.card import Card
from pumpjack_cli.core.dynamics.coefficients import CardLoad, coefficients
from pumpjack_cli.core.dynamics.drive import drive_inertia, motor_characteristic
from pumpjack_cli.core.dynamics.periodic import steady_state
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.beam.kinetostatics import rational_mechanism
from pumpjack_cli.core.beam.geometry import dead_positions
from pumpjack_cli.core.beam.linkage import crank_pin, motion
from pumpjack_cli.errors import DynamicsError

from helpers import RPM


@pytest.fixture(scope="module")
def solution(sk8_machine):
    return steady_state(sk8_machine, crank_grid(720))


def _stroke(linkage) -> float:
    dead = dead_positions(linkage)
    return linkage.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom)


# --- the drive by hand -----------------------------------------------------------------------


def test_drive_reduction_counts_each_inertia_by_its_speed_ratio_squared():
    assert drive_inertia(1.0, 0.0, 0.0, 3.6, 37.18) == pytest.approx((3.6 * 37.18) ** 2)
    assert drive_inertia(0.0, 1.0, 0.0, 3.6, 37.18) == pytest.approx(37.18**2)
    assert drive_inertia(0.0, 0.0, 5.0, 3.6, 37.18) == 5.0
    # [SK8Rotation2013]'s rotor alone: 0.232 kg m^2 x (37.18 x 3.6)^2 = 4156 kg m^2.
    assert drive_inertia(0.232, 0.0, 0.0, 3.6, 37.18) == pytest.approx(4156.35, abs=0.01)


# --- the coefficients against the independent spatial kinetostatics -------------------


def test_gravity_torque_equals_the_kinetostatic_net_torque_of_the_weights(sk8_unit, sk8_machine):
    theta = crank_grid(72)
    r = coefficients(sk8_machine, theta, np.zeros(theta.size, bool))
    _, reactions = rational_mechanism(sk8_unit.geometry.spatial(), sk8_machine.masses, theta, 1.0, 0.0,
                                      np.zeros(theta.size), weights=True, inertia=False)
    scale = np.max(np.abs(r.gravity_torque))
    np.testing.assert_allclose(r.gravity_torque, reactions.net_torque, rtol=0, atol=1e-12 * scale)


def test_link_inertia_torque_equals_the_kinetostatic_net_torque_of_the_inertia_forces(sk8_unit, sk8_machine):
    # Virtual work: with weights and rod load off, the torque that keeps the links moving
    # is d/dt(dT/d omega) - dT/d theta = I eps + 1/2 I' omega^2 over the links alone
    # (no drive, no rods: the kinetostatics has neither).
    theta = crank_grid(72)
    omega, eps = 1.0 + 0.1 * np.sin(theta), 0.3 * np.cos(theta)
    links = dataclasses.replace(sk8_machine, drive_inertia=0.0, rod_load=CardLoad(Card(np.array([0.0, 1.0]), np.zeros(2))))
    r = coefficients(links, theta, np.zeros(theta.size, bool))
    _, reactions = rational_mechanism(sk8_unit.geometry.spatial(), sk8_machine.masses, theta, omega, eps,
                                      np.zeros(theta.size), weights=False, inertia=True)
    mine = r.inertia * eps + 0.5 * r.inertia_rate * omega**2
    np.testing.assert_allclose(mine, reactions.net_torque, rtol=0, atol=1e-12 * np.max(np.abs(mine)))


def test_reduced_inertia_is_twice_the_kinetic_energy_at_unit_speed(sk8_machine):
    # Finite differences of the link positions (not the transfer functions): pitman
    # centres S = A + f (B - A), beam group turning with psi, rods moving A psi.
    linkage, masses = sk8_machine.linkage, sk8_machine.masses
    theta = crank_grid(36)
    h = 1e-6

    def points(t):
        mo = motion(linkage, t)
        a = crank_pin(linkage, t)
        b = -linkage.rear_arm * np.stack([np.cos(mo.beam_angle), np.sin(mo.beam_angle)])
        return a + masses.pitman_cg / linkage.pitman * (b - a), mo.pitman_angle, mo.beam_angle

    (s_p, chi_p, psi_p), (s_m, chi_m, psi_m) = points(theta + h), points(theta - h)
    v_s = (s_p - s_m) / (2 * h)
    chi_rate = (chi_p - chi_m) / (2 * h)
    psi_rate = (psi_p - psi_m) / (2 * h)
    beam = (masses.beam_inertia + masses.beam_mass * masses.beam_cg**2 + masses.horsehead_inertia
            + masses.horsehead_mass * masses.horsehead_cg**2 + masses.equalizer_inertia
            + masses.equalizer_mass * linkage.rear_arm**2)
    rods = sk8_machine.rod_load.mass_downstroke
    two_t = (sk8_machine.constant_inertia + 2 * (masses.pitman_mass * np.sum(v_s**2, axis=0) + masses.pitman_inertia * chi_rate**2)
             + beam * psi_rate**2 + rods * (linkage.front_arm * psi_rate) ** 2)
    r = coefficients(sk8_machine, theta, np.zeros(theta.size, bool))
    np.testing.assert_allclose(r.inertia, two_t, rtol=1e-8)
    i_p = coefficients(sk8_machine, theta + h, np.zeros(theta.size, bool)).inertia
    i_m = coefficients(sk8_machine, theta - h, np.zeros(theta.size, bool)).inertia
    np.testing.assert_allclose(r.inertia_rate, (i_p - i_m) / (2 * h), rtol=0, atol=1e-5 * np.max(r.inertia))


def test_fluid_mass_counts_only_on_the_upstroke(sk8_machine):
    theta = np.radians([60.0])
    up = coefficients(sk8_machine, theta, np.array([True]))
    down = coefficients(sk8_machine, theta, np.array([False]))
    fluid = sk8_machine.rod_load.fluid_mass
    assert fluid > 0
    assert up.inertia[0] - down.inertia[0] == pytest.approx(fluid * up.torque_factor[0] ** 2, rel=1e-10)
    assert up.rod_load[0] - down.rod_load[0] == pytest.approx(sk8_machine.rod_load.upstroke - sk8_machine.rod_load.downstroke)


# --- the periodic solution ------------------------------------------------------------


def test_periodic_solution_ends_at_its_start_speed(sk8_machine, solution):
    dead = dead_positions(sk8_machine.linkage)
    # Just after the bottom dead position the upstroke starts at omega_0; just before
    # it, the downstroke ends: both must agree to 1e-9 (plus the tiny slope over 1e-9 rad).
    ends = steady_state(sk8_machine, np.array([dead.crank_angle_bottom, dead.crank_angle_bottom - 1e-9]))
    assert ends.crank_speed[0] == pytest.approx(solution.summary.start_speed, rel=1e-12)
    assert ends.crank_speed[1] == pytest.approx(ends.crank_speed[0], rel=1e-9)
    assert solution.summary.convergence.periodicity_error <= 1e-9


def test_energy_closure_motor_energy_equals_friction_plus_work_on_the_fluid(sk8_machine, solution):
    # Over one periodic cycle T and V return, so int M_drive dtheta = cycle integral of P ds.
    # P is P_up on the way up and P_down on the way down: S (P_up - P_down), and
    # P_up - P_down = P_fluid + 2 F_plunger + F_tubing + F_rods (rod weight cancels):
    # work on the fluid plus energy dissipated by friction.
    w = sk8_machine.rod_load
    stroke = _stroke(sk8_machine.linkage)
    dissipated = stroke * (2 * w.plunger_friction + w.tubing_friction + w.rod_friction)
    lifted = stroke * w.fluid_load
    energy = solution.summary.energy_per_cycle
    assert energy == pytest.approx(dissipated + lifted, rel=1e-9)
    assert solution.summary.rod_work_per_cycle == pytest.approx(dissipated + lifted, rel=1e-9)
    assert 0 < dissipated < lifted


def test_angle_mean_speed_follows_from_the_energy_balance(sk8_machine):
    # (1/2pi) int (a u + b u^2 omega) dtheta = E / 2pi  =>  <omega>_theta = (E/2pi - a u) / (b u^2).
    theta = crank_grid(4096)
    r = steady_state(sk8_machine, theta)
    u, motor = sk8_machine.drive_ratio, sk8_machine.motor
    expected = (r.summary.energy_per_cycle / (2 * math.pi) - motor.a * u) / (motor.b * u**2)
    assert np.mean(r.crank_speed) == pytest.approx(expected, rel=1e-7)


def test_epsilon_is_the_time_derivative_of_omega_and_time_integrates_dtheta_over_omega(sk8_machine):
    theta = crank_grid(7200)
    r = steady_state(sk8_machine, theta)
    h = theta[1] - theta[0]
    domega = (np.roll(r.crank_speed, -1) - np.roll(r.crank_speed, 1)) / (2 * h)
    # epsilon has a kink at the dead positions (the load changes there), where central
    # differences are only first order: leave those neighbourhoods out.
    dead = dead_positions(sk8_machine.linkage)
    far = np.ones(theta.size, bool)
    for angle in (dead.crank_angle_bottom, dead.crank_angle_top):
        far &= np.abs((theta - angle + math.pi) % (2 * math.pi) - math.pi) > 3 * h
    np.testing.assert_allclose(r.crank_acceleration[far], (r.crank_speed * domega)[far], rtol=0, atol=1e-5 * np.max(np.abs(r.crank_acceleration)))
    period = np.sum(h / r.crank_speed)  # periodic trapezoid
    assert period == pytest.approx(r.summary.period, rel=1e-9)
    assert r.summary.mean_speed == pytest.approx(2 * math.pi / period, rel=1e-9)
    assert r.time[0] == 0.0 and np.all(np.diff(r.time) > 0)


def test_results_converge_as_the_tolerance_tightens(sk8_machine):
    theta = crank_grid(36)
    reference = steady_state(sk8_machine, theta, rtol=1e-12)
    errors = []
    for rtol in (1e-5, 1e-7, 1e-9):
        r = steady_state(sk8_machine, theta, rtol=rtol)
        error = np.max(np.abs(r.crank_speed - reference.crank_speed)) / np.max(reference.crank_speed)
        errors.append(error)
        assert error <= 100 * rtol
        assert abs(r.summary.energy_per_cycle / reference.summary.energy_per_cycle - 1) <= 100 * rtol
    assert errors[0] > errors[1] > errors[2]


def test_huge_drive_inertia_makes_the_rotation_uniform(sk8_machine):
    # With I -> infinity the crank turns at its mean speed and the polished rod moves as
    # with uniform rotation at that speed; the fluctuation falls like 1 / I.
    fluctuations = []
    for inertia in (1e7, 1e8, 1e9):
        r = steady_state(dataclasses.replace(sk8_machine, drive_inertia=inertia), crank_grid(90))
        fluctuations.append(r.summary.speed_fluctuation)
        uniform = sk8_machine.linkage.front_arm * motion(sk8_machine.linkage, r.crank_angle).beam_rate * r.summary.mean_speed
        assert np.max(np.abs(r.rod.velocity - uniform)) <= 2 * r.summary.speed_fluctuation * np.max(np.abs(uniform))
    assert fluctuations[2] < 2e-4
    assert fluctuations[0] / fluctuations[1] == pytest.approx(10, rel=0.1)
    assert fluctuations[1] / fluctuations[2] == pytest.approx(10, rel=0.1)


def test_uniform_columns_are_the_kinematics_at_the_rated_speed(sk8_machine, solution):
    m = motion(sk8_machine.linkage, solution.crank_angle)
    np.testing.assert_allclose(solution.rod_uniform.velocity,
                               sk8_machine.linkage.front_arm * m.beam_rate * sk8_machine.rated_crank_speed, rtol=1e-14)


def test_motor_columns_and_inertia_torque_are_consistent(sk8_machine, solution):
    u = sk8_machine.drive_ratio
    np.testing.assert_allclose(solution.motor_speed, u * solution.crank_speed, rtol=1e-15)
    np.testing.assert_allclose(solution.power, solution.motor_torque * solution.motor_speed, rtol=1e-15)
    # Crank-shaft balance at every angle: drive torque = load + gravity + inertia torque.
    balance = solution.motor_torque * u - solution.rod_load_torque - solution.gravity_torque - solution.inertia_torque
    assert np.max(np.abs(balance)) <= 1e-9 * np.max(np.abs(solution.rod_load_torque))
    np.testing.assert_allclose(solution.constant_inertia_torque, sk8_machine.constant_inertia * solution.crank_acceleration)


# --- dynamometer cards ----------------------------------------------------------------


def _card(loads: np.ndarray, sk8_machine) -> Card:
    theta = crank_grid(loads.size)
    return Card(crank_angle=theta, load=loads)


def test_card_energy_closure(sk8_machine):
    # A smooth card: its cycle work int P TF dtheta evaluated independently by a dense sum.
    theta = crank_grid(72)
    card = Card(theta, 45_000 + 8_000 * np.sin(theta) + 2_000 * np.cos(2 * theta))
    driven = dataclasses.replace(sk8_machine, rod_load=CardLoad(card))
    r = steady_state(driven, crank_grid(36))
    dense = crank_grid(400_000)
    work = np.sum(np.interp(dense, theta, card.load, period=2 * math.pi)
                  * sk8_machine.linkage.front_arm * motion(sk8_machine.linkage, dense).beam_rate) * (dense[1] - dense[0])
    # The card's kinks (linear interpolation) cost the integrator many steps, each within its
    # tolerance (rtol / 100): the global error of the energy is then some 1e-10 here, and the
    # dense sum's own error on the kinks about 1e-9; 1e-6 bounds both with room.
    assert r.summary.energy_per_cycle == pytest.approx(work, rel=1e-6)
    assert r.summary.energy_per_cycle == pytest.approx(r.summary.rod_work_per_cycle, rel=1e-6)


def test_card_that_returns_energy_does_not_fit(sk8_machine):
    # Loads of the downstroke on the upstroke and vice versa: the card would drive the motor.
    theta = crank_grid(180)
    upstroke = motion(sk8_machine.linkage, theta).beam_rate > 0
    card = Card(theta, np.where(upstroke, 37_000.0, 51_000.0))
    with pytest.raises(DynamicsError, match="does not fit this unit"):
        steady_state(dataclasses.replace(sk8_machine, rod_load=CardLoad(card)))


# --- bad input --------------------------------------------------------------------------


def _massless(sk8_machine):
    zero = {f.name: 0.0 for f in dataclasses.fields(sk8_machine.masses)}
    return dataclasses.replace(sk8_machine, masses=dataclasses.replace(sk8_machine.masses, **zero))


@pytest.mark.parametrize("inertia", [0.0, -1e5])
def test_zero_or_negative_inertia_is_refused(sk8_machine, inertia):
    with pytest.raises(DynamicsError, match="reduced moment of inertia"):
        steady_state(dataclasses.replace(_massless(sk8_machine), drive_inertia=inertia))


def test_motor_too_weak_for_the_load_names_the_torques(sk8_machine):
    weak = motor_characteristic(5e3, 1500 * RPM, 1460 * RPM, 2.0, 2.2)
    with pytest.raises(DynamicsError, match=r"motor is too weak: the load needs [0-9.]+ N·m .* pull-out torque 71\.9 N·m"):
        steady_state(dataclasses.replace(sk8_machine, motor=weak))


def test_motor_that_cannot_turn_the_unit_stalls_with_a_message(sk8_machine):
    tiny = motor_characteristic(300.0, 1500 * RPM, 1460 * RPM, 2.0, 2.2)
    with pytest.raises(DynamicsError, match="stalls"):
        steady_state(dataclasses.replace(sk8_machine, motor=tiny))


def test_non_converging_shooting_reports_what_it_tried(sk8_machine):
    with pytest.raises(DynamicsError, match=r"did not converge in 1 secant iterations.*last start speeds 1\.16"):
        steady_state(sk8_machine, max_iterations=1)


@pytest.mark.parametrize("rtol", [0.0, 1e-2])
def test_tolerance_out_of_range(sk8_machine, rtol):
    with pytest.raises(DynamicsError, match="rtol"):
        steady_state(sk8_machine, rtol=rtol)


def test_a_strokes_spline_at_one_angle_is_scipys_spline():
    """The integration's right-hand side reads the coefficient splines one angle at a time
    from their own cubic pieces (``_Stroke.at``): the same polynomials as scipy's
    CubicSpline, to rounding, inside the stroke and at its ends."""
    from scipy.interpolate import CubicSpline

    from pumpjack_cli.core.dynamics.periodic import _Stroke

    theta = np.linspace(0.3, 3.5, 257)
    table = np.stack([np.sin(theta) + 2.0, np.cos(3 * theta), theta**2], axis=1)
    stroke = _Stroke(0.3, 3.2, CubicSpline(theta, table))
    at = stroke.at
    angles = np.concatenate([[0.3, 3.5, theta[100]], np.random.default_rng(5).uniform(0.3, 3.5, 2000)])
    found = np.array([at(float(a)) for a in angles])
    np.testing.assert_allclose(found, stroke.spline(angles), rtol=0, atol=1e-14 * np.max(np.abs(table)))


def test_a_cards_kinks_do_not_keep_the_shooting_going(sk8_unit, sk8_drivable_card):
    """On a card (linear between its points) the integration's error on omega_end is some
    10 x its tolerance; integrated to rtol / 100, the secant iteration reaches
    |omega_end - omega_0| <= rtol omega_0 in a few shots instead of following that noise."""
    from pumpjack_cli.analysis.card_runs import place
    from pumpjack_cli.readers.cards import read_card

    machine = sk8_unit.machine(place(read_card(sk8_drivable_card), sk8_unit.geometry.mechanism()).card)
    convergence = steady_state(machine, crank_grid(36)).summary.convergence
    assert len(convergence.start_speeds) <= 4
    assert abs(convergence.residuals[-1]) <= convergence.rtol * convergence.start_speeds[-1]
