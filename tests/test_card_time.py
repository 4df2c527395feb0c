"""Time-stamped cards: the time column is the speed; the loop's orientation; --spm against the card.

Truth in these tests comes from how a card was made (the sample script's crank grid
and speed, seed 004's crank speed, synthetic crank motions with known parameters),
never from the reader's own output.
"""

from __future__ import annotations

import dataclasses
import io
import math
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.card_files import SPEED_TOLERANCE, check_speed, read_card
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import fit_rotation, loop_work
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.errors import CardError

ROOT = Path(__file__).resolve().parent.parent
SAMPLE = ROOT / "samples" / "sk8-3.5-4000-card.csv"
SK8 = load_unit("sk8-3.5-4000").geometry.mechanism()
CCW = dataclasses.replace(SK8, rotation=-SK8.rotation)
TIME, POSITION, LOAD_KN = np.loadtxt(SAMPLE, delimiter=",", comments="#", skiprows=4, unpack=True)
#: Seed 004's uniform crank speed: pi n_nom / (30 u_gearbox u_belt) = pi 1460 / (30 * 37.18 * 900/250) [1/s].
SEED_OMEGA = math.pi * 1460 / (30 * 37.18 * 900 / 250)


def read_text(text: str, linkage=SK8):
    return read_card("-", linkage, stream=io.StringIO(text))


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
    reading = read_card(SAMPLE, SK8)
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
    reading = read_card(SAMPLE, SK8)
    assert np.max(circular(reading.crank_angle, made_at)) < 2e-4


def test_time_fit_and_position_map_agree():
    """Two independent routes onto the crank-angle axis (time fit; branch inversion of positions).
    The branch map shifts the card so that its lowest sample (0.15 mm above the bottom) sits at the
    bottom dead position, which moves that sample by sqrt(2 * 0.15 mm / s'') = 0.69 deg
    (s'' = A psi'' = 2.09 m/rad^2 there); 5 deg or more from the dead positions, where
    |ds/dtheta| >= 0.086 m/rad, the same 0.15 mm shift moves an angle by at most 0.1 deg."""
    timed = read_card(SAMPLE, SK8)
    untimed = read_text(text_of("position_m,load_kN", POSITION, LOAD_KN))
    difference = circular(timed.crank_angle, untimed.crank_angle)
    dead = SK8.dead_positions()
    away = np.all([circular(timed.crank_angle, d) > np.radians(5) for d in (dead.crank_angle_bottom, dead.crank_angle_top)],
                  axis=0)
    assert np.max(difference) < np.radians(0.75) and np.max(difference[away]) < np.radians(0.1)


def test_periodic_speed_variation_is_recovered():
    """A crank turning at 6 spm on average with +-13 % speed variation (two harmonics), sampled at
    uneven times: mean speed, speed at every sample and angles come back to round-off."""
    omega = 0.2 * math.pi
    time = np.sort(np.random.default_rng(7).uniform(0.0, 10.0, 240))
    phi = omega * time
    theta = 0.7 + phi + 0.08 * np.sin(phi + 0.5) + 0.03 * np.sin(2 * phi)
    speed = omega * (1 + 0.08 * np.cos(phi + 0.5) + 0.06 * np.cos(2 * phi))
    reading = read_text(synthetic(theta, time))
    assert reading.warnings == ()
    assert reading.speed == pytest.approx(omega, rel=1e-9)
    assert np.allclose(reading.crank_speed, speed, rtol=1e-8)
    assert np.max(circular(reading.crank_angle, theta)) < 1e-8


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
    lines = SAMPLE.read_text(encoding="utf-8").splitlines()
    reading = read_text("\n".join(lines[:4] + lines[4:][::-1]))
    assert reading.speed == read_card(SAMPLE, SK8).speed


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
        reading = read_card(ROOT / "samples" / f"{name}-card.csv", load_unit(name).geometry.mechanism())
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
