"""Time-stamped cards: the time column is the speed; the loop's orientation; --spm against the card.

Truth in these tests comes from how a card was made (the sample script's crank grid
and speed, seed 004's crank speed, synthetic crank motions with known parameters),
never from the reader's own output.
"""

from __future__ import annotations

import dataclasses
import io
import math

import numpy as np
import pytest

from pumpjack_cli.analysis.card_runs import SPEED_TOLERANCE, check_speed, place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import fit_rotation, loop_work
from pumpjack_cli.core import cards as placement
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.core.cards import place_card
from pumpjack_cli.core.dynamics.periodic import steady_state
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.errors import CardError
from pumpjack_cli.readers.cards import read_card

from helpers import SK8_CARD, sample_card

SK8 = load_unit("sk8-3.5-4000").geometry.mechanism()
CCW = dataclasses.replace(SK8, rotation=-SK8.rotation)
TIME, POSITION, LOAD_KN = np.loadtxt(SK8_CARD, delimiter=",", comments="#", skiprows=4, unpack=True)
#: Seed 004's uniform crank speed: pi n_nom / (30 u_gearbox u_belt) = pi 1460 / (30 * 37.18 * 900/250) [1/s].
SEED_OMEGA = math.pi * 1460 / (30 * 37.18 * 900 / 250)


def read(path, linkage=SK8):
    """A card file read without a unit, then placed on ``linkage``'s crank-angle axis."""
    return place(read_card(path), linkage)


def read_text(text: str, linkage=SK8):
    return place(read_card("-", stream=io.StringIO(text)), linkage)


def text_of(header: str, *columns: np.ndarray) -> str:
    return header + "\n" + "\n".join(",".join(repr(float(v)) for v in row) for row in zip(*columns)) + "\n"


def rod_position(linkage, theta):
    """Exact polished-rod position [m] from the bottom and its crank-angle rate, via Linkage.motion."""
    m = linkage.motion(theta)
    return linkage.front_arm * (m.beam_angle - linkage.dead_positions().beam_angle_bottom), m.beam_rate


def synthetic(theta: np.ndarray, time: np.ndarray, linkage=SK8) -> str:
    """A time card of exact positions with 52 kN on the rising and 40 kN on the falling rod (positive work)."""
    s, rate = rod_position(linkage, theta)
    return text_of("time_s,position_m,load_n", time, s, np.where(rate > 0, 52e3, 40e3))


def circular(a, b):
    return np.abs((np.asarray(a) - np.asarray(b) + np.pi) % (2 * np.pi) - np.pi)


def test_sample_card_runs_at_the_seed_speed():
    """The SK8 sample was made at the unit's rated speed, seed 004's 1.1422 1/s (10.91 strokes/min).
    Time stamps are rounded to 0.1 ms over a 5.5 s cycle (2e-5), positions to 10 um: 1e-4 covers both."""
    reading = read(SK8_CARD)
    assert reading.speed == pytest.approx(SEED_OMEGA, rel=1e-4)
    assert reading.strokes_per_minute == pytest.approx(30 * SEED_OMEGA / math.pi, rel=1e-4)
    assert reading.fit_rms < 1e-4 and reading.fit_rms_relative < 1e-4


def test_sample_restamped_to_6_spm_runs_at_6_spm():
    """The same positions stamped 10 s / 180 apart: one cycle in 10 s is 6 strokes/min, omega = 0.6283 1/s."""
    restamped = text_of("time_s,position_m,load_kN", np.arange(TIME.size) * 10.0 / TIME.size, POSITION, LOAD_KN)
    reading = read_text(restamped)
    assert reading.speed == pytest.approx(0.2 * math.pi, rel=1e-4)
    assert reading.strokes_per_minute == pytest.approx(6.0, rel=1e-4)


def test_fitted_angles_are_those_the_sample_was_made_at():
    """samples/make_cards.py takes the 180-point crank grid from the lowest point on; the fit must
    find those angles (time stamps to 0.1 ms at 1.14 rad/s: 6e-5 rad; 2e-4 rad allows for positions
    rounded to 10 um near the dead positions)."""
    grid = uniform_kinematics(SK8, SEED_OMEGA, TIME.size)
    start = int(np.argmin(grid.rod.position))
    made_at = np.roll(grid.crank_angle, -start)
    reading = read(SK8_CARD)
    assert np.max(circular(reading.crank_angle, made_at)) < 2e-4


def test_time_fit_and_position_map_agree():
    """Two independent routes onto the crank-angle axis (time fit; branch inversion of positions).
    The branch map shifts the card so that its lowest sample (0.15 mm above the bottom) sits at the
    bottom dead position, which moves that sample by sqrt(2 * 0.15 mm / s'') = 0.69 deg
    (s'' = A psi'' = 2.09 m/rad^2 there); 5 deg or more from the dead positions, where
    |ds/dtheta| >= 0.086 m/rad, the same 0.15 mm shift moves an angle by at most 0.1 deg."""
    timed = read(SK8_CARD)
    untimed = read_text(text_of("position_m,load_kN", POSITION, LOAD_KN))
    difference = circular(timed.crank_angle, untimed.crank_angle)
    dead = SK8.dead_positions()
    away = np.all([circular(timed.crank_angle, d) > np.radians(5) for d in (dead.crank_angle_bottom, dead.crank_angle_top)],
                  axis=0)
    assert np.max(difference) < np.radians(0.75) and np.max(difference[away]) < np.radians(0.1)


def test_periodic_speed_variation_is_recovered():
    """A crank turning at 6 spm on average with +-13 % speed variation (two harmonics), sampled at
    uneven times: mean speed, speed and acceleration at every sample and angles come back to round-off."""
    omega = 0.2 * math.pi
    time = np.sort(np.random.default_rng(7).uniform(0.0, 10.0, 240))
    phi = omega * time
    theta = 0.7 + phi + 0.08 * np.sin(phi + 0.5) + 0.03 * np.sin(2 * phi)
    speed = omega * (1 + 0.08 * np.cos(phi + 0.5) + 0.06 * np.cos(2 * phi))
    acceleration = -omega**2 * (0.08 * np.sin(phi + 0.5) + 0.12 * np.sin(2 * phi))
    reading = read_text(synthetic(theta, time))
    assert reading.warnings == ()
    assert reading.speed == pytest.approx(omega, rel=1e-9)
    assert np.allclose(reading.crank_speed, speed, rtol=1e-8)
    assert np.allclose(reading.crank_acceleration, acceleration, rtol=0, atol=1e-7 * omega**2)
    assert np.max(circular(reading.crank_angle, theta)) < 1e-8


#: Harmonics of the crank speed over its mean in the machine's periodic motion under the SK8
#: sample card (halved swing; docs/cards.md), with phases chosen at will: the variation the
#: placement's fit is sized for.
SPEED_HARMONICS = (0.017, 0.019, 0.0065, 0.0061, 0.0032, 0.0031)


def test_speed_variation_of_the_equation_of_motion_is_recovered():
    """A crank whose speed varies by the six harmonics of the equation of motion's periodic
    solution, at the SK8 sample's speed and on 180 uneven samples of one cycle: the motion lies
    in the fitted model (theta = theta_0 + phi + sum_j (a_j cos j phi + b_j sin j phi)), so least
    squares leaves no residual and omega = dtheta/dt, alpha = d2theta/dt2 come back exactly but
    for the fit's stopping step (1e-10 rad, times j^2 <= 36 for alpha): 1e-8 of omega and of
    omega^2."""
    omega = SEED_OMEGA
    period = 2 * math.pi / omega
    u = np.linspace(0.0, 1.0, 180, endpoint=False)
    time = period * (u + 0.1 * u * (1 - u))
    phi = omega * time
    j = np.arange(1, len(SPEED_HARMONICS) + 1)[:, None]
    amplitude, phase = np.array(SPEED_HARMONICS)[:, None], 0.7 * j
    theta = 0.4 + phi + np.sum(amplitude / j * np.sin(j * phi + phase), axis=0)
    speed = omega * (1 + np.sum(amplitude * np.cos(j * phi + phase), axis=0))
    acceleration = -omega**2 * np.sum(amplitude * j * np.sin(j * phi + phase), axis=0)
    reading = read_text(synthetic(theta, time))
    assert reading.warnings == () and reading.fit_rms < 1e-9
    assert reading.speed == pytest.approx(omega, rel=1e-9)
    assert np.max(np.abs(reading.crank_speed - speed)) < 1e-8 * omega
    assert np.max(np.abs(reading.crank_acceleration - acceleration)) < 1e-8 * omega**2


def test_noise_in_the_rates_is_what_least_squares_predicts():
    """Gaussian position noise sigma = 1e-4 of the stroke on a uniformly turning crank (180
    samples of one cycle): the fitted speed and acceleration scatter as linear least squares
    says, the covariance sigma^2 (J^T J)^-1 of the parameters (angle start, mean speed, a_j, b_j,
    the position's offset and scale; J_i = ds/dtheta (1, t_i, cos j phi_i, sin j phi_i), 1, s_i)
    carried to omega_i and alpha_i by their derivatives (omega j (-sin, cos) and omega^2 j^2
    (-cos, -sin) per harmonic). Over 40 noise draws the RMS scatter matches the prediction
    within 15 % (the sampling spread of 40 draws); the prediction is the noise gain that
    docs/cards.md quotes for six harmonics: 5.5 sigma/S in omega and 24 sigma/S omega^2 in
    alpha."""
    omega, stroke, harmonics = SEED_OMEGA, SK8.dead_positions().stroke, placement.HARMONICS
    time = np.arange(180) * (2 * math.pi / omega) / 180
    theta = 0.3 + omega * time
    s, tf = SK8.rod_position(theta), SK8.torque_factor(theta)
    centred = time - 0.5 * (time[0] + time[-1])
    j = np.arange(1, harmonics + 1)
    cos, sin = np.cos(np.outer(omega * centred, j)), np.sin(np.outer(omega * centred, j))

    def interleaved(a, b):
        """Columns a_1, b_1, a_2, b_2, ... in the order of the fit's parameters."""
        both = np.empty((a.shape[0], 2 * a.shape[1]))
        both[:, 0::2], both[:, 1::2] = a, b
        return both

    jacobian = np.column_stack([tf, tf * centred, tf[:, None] * interleaved(cos, sin), np.ones_like(s), s])
    covariance = np.linalg.inv(jacobian.T @ jacobian)
    zero, one = np.zeros((time.size, 1)), np.ones((time.size, 1))
    d_speed = np.hstack([zero, one, omega * interleaved(-j * sin, j * cos), zero, zero])
    d_acceleration = np.hstack([zero, zero, -omega**2 * interleaved(j**2 * cos, j**2 * sin), zero, zero])
    sigma = 1e-4 * stroke
    predicted = [sigma * math.sqrt(np.mean(np.einsum("ip,pq,iq->i", d, covariance, d)))
                 for d in (d_speed, d_acceleration)]
    found_speed, found_acceleration = [], []
    for seed in range(40):
        noisy = s + np.random.default_rng(seed).normal(0.0, sigma, s.size)
        reading = place_card(SK8, np.where(tf > 0, 52e3, 40e3), position=noisy, time=time)
        found_speed.append(reading.crank_speed - omega)
        found_acceleration.append(reading.crank_acceleration)
    scatter = [math.sqrt(np.mean(np.square(found))) for found in (found_speed, found_acceleration)]
    assert scatter[0] == pytest.approx(predicted[0], rel=0.15)
    assert scatter[1] == pytest.approx(predicted[1], rel=0.15)
    assert predicted[0] / omega / 1e-4 == pytest.approx(5.5, rel=0.05)
    assert predicted[1] / omega**2 / 1e-4 == pytest.approx(24, rel=0.05)


def test_uniform_fit_residual_grows_with_the_speed_variation():
    """Limit and scaling: exact uniform rotation fits to round-off; a small speed variation of
    amplitude e leaves a residual proportional to e (doubling e doubles it within 5 %)."""
    time = np.linspace(0.0, 10.0, 200, endpoint=False)
    phi = 0.2 * math.pi * time

    def residual(e):
        return fit_rotation(SK8, time, rod_position(SK8, 1.0 + phi + e * np.sin(phi))[0]).rms

    assert residual(0.0) < 1e-9
    assert residual(0.02) / residual(0.01) == pytest.approx(2.0, rel=0.05)


def test_rotation_of_the_unit_is_told_by_the_time_stamps():
    """A card made by the counterclockwise twin of SK8 (PR_ccw(theta) = PR_cw(-theta)): read for the
    clockwise unit it fits counterclockwise rotation clearly better (one warning); read for the
    counterclockwise unit it fits exactly, silently."""
    time = np.arange(180) * 0.05
    theta = 0.3 + 0.7 * time
    text = synthetic(theta, time, CCW)
    as_ccw = read_text(text, CCW)
    assert as_ccw.warnings == () and as_ccw.fit_rms < 1e-8
    as_cw = read_text(text, SK8)
    assert len(as_cw.warnings) == 1 and "fit counterclockwise rotation better" in as_cw.warnings[0]


def test_reversed_rows_keep_the_speed():
    lines = SK8_CARD.read_text(encoding="utf-8").splitlines()
    reading = read_text("\n".join(lines[:4] + lines[4:][::-1]))
    assert reading.speed == read(SK8_CARD).speed


def test_card_speed_wins_within_2_percent():
    card = 0.2 * math.pi
    assert check_speed(card, card * (1 + 0.9 * SPEED_TOLERANCE)) == card
    assert check_speed(card, card * (1 - 0.9 * SPEED_TOLERANCE)) == card
    assert check_speed(card, None) == card and check_speed(None, 1.1) == 1.1 and check_speed(None, None) is None


@pytest.mark.parametrize("factor", [1.025, 0.97, 2.0])
def test_spm_disagreeing_with_the_card_is_an_error_printing_both(factor):
    card = 0.2 * math.pi  # 6 strokes/min
    with pytest.raises(CardError) as info:
        check_speed(card, card * factor, "card.csv")
    message = str(info.value)
    assert "\n" not in message and "card.csv" in message
    assert f"--spm {6 * factor:.4g}" in message and "(6 strokes/min)" in message


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf])
def test_check_speed_refuses_impossible_speeds(bad):
    with pytest.raises(CardError, match="not a positive speed"):
        check_speed(bad, 1.0)


def test_loop_work_is_the_enclosed_area():
    """Points on an ellipse traversed clockwise in the position-load plane (up on the high load):
    their polygon is the affine image of a regular N-gon, of area (N/2) a b sin(2 pi/N) (-> pi a b);
    reversed, the sign flips."""
    n, a, b = 400, 1.5, 6e3
    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    position, load = a * (1 - np.cos(phi)), 45e3 + b * np.sin(phi)
    area = 0.5 * n * a * b * math.sin(2 * math.pi / n)
    assert loop_work(position, load) == pytest.approx(area, rel=1e-12)
    assert loop_work(position[::-1], load[::-1]) == pytest.approx(-area, rel=1e-12)


def test_sample_cards_do_positive_work():
    """The sample cards lift the fluid on the upstroke, so the rods take work from the unit."""
    for name in ("sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54"):
        reading = read(sample_card(name), load_unit(name).geometry.mechanism())
        assert not reading.reversed and loop_work(reading.position, reading.load) > 0


@pytest.mark.parametrize(("time", "position", "fragment"), [
    (np.arange(3.0), np.zeros(4), "matching 1-D arrays"),
    (np.arange(2.0), np.zeros(2), "at least 3 samples"),
    (np.array([0.0, 1.0, np.nan]), np.zeros(3), "finite"),
    (np.array([0.0, 1.0, 1.0]), np.zeros(3), "increase strictly"),
])
def test_fit_rotation_refuses_bad_input(time, position, fragment):
    with pytest.raises(CardError, match=fragment):
        fit_rotation(SK8, time, position)


def test_fit_rotation_needs_samples_for_its_harmonics():
    with pytest.raises(CardError, match="2 harmonics need at least 7 samples"):
        fit_rotation(SK8, np.arange(6.0), np.linspace(0.0, 1.0, 6), harmonics=2)


def test_six_harmonics_hold_the_speed_variation_of_the_equation_of_motion(sk8_drivable_card):
    """Why HARMONICS is 6: the machine's periodic motion under the SK8 card (its load swing
    halved so that the motor drives it) has a crank speed whose first six harmonics in time
    are each above 0.3 % of the mean speed, the 7th is near 0.13 % and every higher one (the
    rod string's stress waves in the card) below 0.07 %; the six leave under 0.15 % RMS of
    the speed unfitted. The harmonics come from least squares on 720 crank angles of the motion
    (uneven in time) with 20 harmonics, far more than the motion holds above the 1e-5 level."""
    config = load_unit("sk8-3.5-4000")
    state = steady_state(config.machine(place(read_card(sk8_drivable_card), SK8).card), crank_grid(720),
                         rtol=1e-10)
    phi = 2 * math.pi * state.time / state.summary.period
    j = np.arange(1, 21)
    basis = np.column_stack([np.ones_like(phi), np.cos(np.outer(phi, j)), np.sin(np.outer(phi, j))])
    coefficients = np.linalg.lstsq(basis, state.crank_speed, rcond=None)[0]
    amplitude = np.hypot(coefficients[1:21], coefficients[21:]) / coefficients[0]
    assert np.all(amplitude[:6] > 3e-3) and 1e-3 < amplitude[6] < 1.5e-3 and np.all(amplitude[7:] < 7e-4)
    assert math.sqrt(0.5 * np.sum(amplitude[6:] ** 2)) < 1.5e-3
