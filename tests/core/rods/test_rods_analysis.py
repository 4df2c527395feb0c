"""Pump-card figures, card work, rates and pressures, taper loads and Goodman loading."""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.rods.analysis import (
    card_work,
    displacement_rate,
    goodman_allowable_stress,
    goodman_loading,
    intake_pressure,
    series_work,
    summarise_pump_card,
    taper_loads,
)
from pumpjack_cli.core.rods.downhole import pump_card, surface_card
from pumpjack_cli.core.rods.string import RodString
from pumpjack_cli.core.rods.tables import RodSection, rod_string, tensile_strength
from pumpjack_cli.errors import DownholeError
from pumpjack_cli.core.constants import STANDARD_GRAVITY as G


def rectangle_card(samples=400, stroke=2.0, fluid_load=10e3, unload_fraction=1.0, pickup=0.02):
    """Harmonic plunger p = S/2 (1 - cos theta); load F_o from theta = 2 pi pickup until the
    plunger has come down to `unload_fraction` of the stroke (fluid pound below 1)."""
    theta = 2 * np.pi * np.arange(samples) / samples
    position = stroke / 2 * (1 - np.cos(theta))
    unload = 2 * np.pi - np.arccos(1 - 2 * unload_fraction)
    load = np.where((theta >= 2 * np.pi * pickup) & (theta < unload), fluid_load, 0.0)
    return position, load


def test_card_work_of_an_elliptic_card_is_pi_a_b():
    # p = a (1 - cos), F = F0 + b sin: the loop integral of F dp is pi a b, exactly
    theta = 2 * np.pi * np.arange(64) / 64
    assert card_work(1.5 * (1 - np.cos(theta)), 3e4 + 2e3 * np.sin(theta)) == pytest.approx(np.pi * 1.5 * 2e3,
                                                                                           rel=1e-13)
    # clockwise (load higher on the way down) is negative work
    assert card_work(1 - np.cos(theta), -np.sin(theta)) == pytest.approx(-np.pi, rel=1e-13)


def test_card_work_matches_the_polygon_area_of_a_smooth_card():
    theta = 2 * np.pi * np.arange(200) / 200
    position = 1 - np.cos(theta) + 0.2 * np.sin(theta) ** 2
    load = 5.0 + np.tanh(3 * np.sin(theta))
    polygon = np.sum(0.5 * (load + np.roll(load, -1)) * (np.roll(position, -1) - position))
    # trapezoid and trigonometric interpolants differ by O(1/N^2): 1e-3 at N = 200
    assert card_work(position, load) == pytest.approx(polygon, rel=1e-3)
    assert card_work(np.stack([position, position]), np.stack([load, 2 * load])) == pytest.approx(
        [polygon, 2 * polygon], rel=1e-3)


def test_full_card_has_full_fillage_and_the_fluid_load():
    position, load = rectangle_card()
    summary = summarise_pump_card(position, load)
    assert summary.gross_stroke == pytest.approx(2.0)
    assert summary.upstroke_load == pytest.approx(10e3) and summary.downstroke_load == pytest.approx(0.0)
    assert summary.fluid_load == pytest.approx(10e3)
    # unloading at the top of the stroke: the net stroke is the gross one, within a sample
    assert summary.fillage == pytest.approx(1.0, abs=1e-3)
    assert summary.peak_load == 10e3 and summary.minimum_load == 0.0


@pytest.mark.parametrize("fillage", [0.35, 0.6, 0.85])
def test_fluid_pound_fillage_is_the_unloading_point(fillage):
    # the load drops when the plunger reaches `fillage` of the stroke on the way down;
    # the crossing is interpolated between two samples, so within one sample's travel
    # (S pi / N = 0.8 % of the stroke at N = 400)
    position, load = rectangle_card(unload_fraction=fillage)
    summary = summarise_pump_card(position, load)
    assert summary.fillage == pytest.approx(fillage, abs=0.008)
    assert summary.net_stroke == pytest.approx(2.0 * summary.fillage)
    assert summary.fluid_load == pytest.approx(10e3)


def test_summary_of_a_batch_and_of_a_card_shifted_in_time():
    position, load = rectangle_card(unload_fraction=0.6)
    one = summarise_pump_card(position, load)
    batch = summarise_pump_card(np.stack([position, np.roll(position, 57)]), np.stack([load, np.roll(load, 57)]))
    # the figures do not depend on where the record starts
    for name, value in vars(one).items():
        assert getattr(batch, name) == pytest.approx([value, value]), name


def test_every_start_of_the_record_gives_the_same_figures_exactly():
    # the figures are read around the cycle from the bottom without rolling the card: wherever the
    # record starts (the top before the bottom, either at the record's end), the same samples make
    # the same figures, to the last bit; a noisy pounding card, so the medians and the crossing
    # interpolate between unequal samples
    position, load = rectangle_card(samples=120, unload_fraction=0.55)
    load = load + 150.0 * np.random.default_rng(7).standard_normal(load.size)
    one = summarise_pump_card(position, load)
    shifts = np.arange(position.size)
    every = summarise_pump_card(np.array([np.roll(position, s) for s in shifts]),
                                np.array([np.roll(load, s) for s in shifts]))
    for name, value in vars(one).items():
        assert np.array_equal(getattr(every, name), np.full(shifts.size, value)), name


def test_card_work_from_the_series_of_a_card():
    # the work of a card given by its Fourier coefficients is the work of its samples; harmonics
    # left out of a band-limited card's series change nothing
    theta = 2 * np.pi * np.arange(90) / 90
    position = np.stack([1 - np.cos(theta), 0.5 * (1 - np.cos(theta)) + 0.1 * np.sin(2 * theta)])
    load = np.stack([2e3 * np.sin(theta) + 300 * np.cos(3 * theta), 1e3 * np.sin(theta - 0.3)])
    spectra = np.fft.rfft(position, axis=-1), np.fft.rfft(load, axis=-1)
    assert series_work(*spectra, 90) == pytest.approx(card_work(position, load), rel=1e-13)
    assert series_work(spectra[0][:, :4], spectra[1][:, :4], 90) == pytest.approx(card_work(position, load),
                                                                                   rel=1e-13)


def test_a_card_without_stroke_or_samples_is_refused():
    with pytest.raises(DownholeError, match="pump card 1 has no plunger stroke"):
        summarise_pump_card(np.zeros(20), np.ones(20))
    theta = 2 * np.pi * np.arange(8) / 8
    with pytest.raises(DownholeError, match="no sample on the upstroke between 60% and 90%"):
        summarise_pump_card(np.where(theta < np.pi, 0.0, 1.0) + 0.01 * np.sin(theta), np.ones(8))


def test_seed_well_pump_card_figures():
    # seed 004 well: 38 mm plunger, 820 kg/m^3 lifted 1530 m. A synthetic full pump card
    # (2.5 m stroke, F_o = rho g H A_p) pushed to the surface and diagnosed again:
    # the figures come back, and with the discharge pressure rho g H (no tubing-head
    # pressure) the intake pressure is ~0 (fluid level at the pump).
    depth, density, plunger = 1530.0, 820.0, 0.038
    area = np.pi * plunger**2 / 4
    fluid_load = density * G * depth * area
    string = rod_string([RodSection(0.025, 0.23 * depth, grade="D"), RodSection(0.022, 0.26 * depth, grade="D"),
                         RodSection(0.019, 0.51 * depth, grade="D")])
    period = 60 / 10.9
    theta = 2 * np.pi * np.arange(240) / 240
    position = 1.25 * (1 - np.cos(theta))
    n = np.arange(1, 25)
    # upstroke window from theta = 0.2 to pi + 0.2 as a smoothed Fourier series
    coefficient = (np.exp(-1j * n * 0.2) - np.exp(-1j * n * (np.pi + 0.2))) / (2j * np.pi * n)
    load = fluid_load * (0.5 + 2 * np.real(np.exp(1j * np.outer(theta, n)) @ (np.sinc(n / 25) ** 2 * coefficient)))
    surface = surface_card(string, period, position, load, fluid_density=density)
    card = pump_card(string, period, surface.surface_position, surface.surface_load, fluid_density=density)
    summary = summarise_pump_card(card.pump_position, card.pump_load)
    assert summary.gross_stroke == pytest.approx(2.5, abs=1e-9)
    assert summary.fluid_load == pytest.approx(fluid_load, rel=0.01)
    assert summary.fillage > 0.95
    assert float(intake_pressure(summary.fluid_load, plunger, density * G * depth)) == pytest.approx(
        0.0, abs=0.01 * density * G * depth)
    # hand value: 1.1341e-3 m^2 * 2.5 m / 5.5046 s = 5.151e-4 m^3/s (44.5 m^3/day)
    assert float(displacement_rate(summary.gross_stroke, period, plunger)) == pytest.approx(5.151e-4, rel=1e-3)
    # the rods' Goodman loading is below 1 and the top taper is the most loaded section
    loading = goodman_loading(string, taper_loads(string, card.joint_load))
    assert (loading > 0).all() and (loading < 1).all()
    loads = taper_loads(string, card.joint_load)
    assert loads.top_max_load[0] == pytest.approx(surface.surface_load.max())
    assert loads.bottom_min_load[-1] == pytest.approx(summary.minimum_load)


def test_goodman_loading_hand_calculation():
    # one 7/8 in grade D taper, stresses 200/60 MPa at the top and 120/-10 MPa at the bottom.
    # S_A = T/4 + 0.5625 S_min with T = 115 000 psi = 792.9 MPa:
    # top: 198.22 + 33.75 = 231.97 MPa, loading 140 / 171.97 = 0.8141
    # bottom: 198.22 - 5.63 = 192.60 MPa, loading 130 / 202.60 = 0.6417
    area = np.pi * 0.022225**2 / 4
    string = RodString([500.0], [area], [2.1e11], [3.31], tensile_strength=[tensile_strength("D")])
    t = np.linspace(0, 2 * np.pi, 40, endpoint=False)   # hits sin = +-1
    top = (130 + 70 * np.sin(t)) * 1e6 * area
    bottom = (55 + 65 * np.sin(t)) * 1e6 * area
    loads = taper_loads(string, np.stack([top, bottom]))
    assert loads.top_max_stress == pytest.approx([200e6]) and loads.bottom_min_stress == pytest.approx([-10e6])
    strength = tensile_strength("D")
    assert goodman_allowable_stress(strength, 60e6) == pytest.approx(strength / 4 + 0.5625 * 60e6)
    assert goodman_loading(string, loads) == pytest.approx([140e6 / (strength / 4 - 0.4375 * 60e6)])
    assert goodman_loading(string, loads)[0] == pytest.approx(0.8141, abs=1e-4)
    # a service factor below 1 (corrosive fluid) shrinks the allowable range
    assert goodman_loading(string, loads, service_factor=0.9)[0] > 0.8141


def test_goodman_needs_a_grade():
    string = RodString([500.0], [3.9e-4], [2.1e11], [3.31])
    loads = taper_loads(string, np.ones((2, 10)))
    with pytest.raises(DownholeError, match="taper 1 has no rod grade or tensile strength"):
        goodman_loading(string, loads)
    with pytest.raises(DownholeError, match="joint loads have 3 section ends for 1 tapers"):
        taper_loads(string, np.ones((3, 10)))


@pytest.mark.parametrize("call, message", [
    (lambda: card_work(np.arange(10.0), np.where(np.arange(10) == 3, np.inf, 1.0)),
     "card: load is not finite at sample 3"),
    (lambda: summarise_pump_card(np.ones((2, 10)), np.full((2, 10), np.nan)), "pump card 1: load is not finite"),
    (lambda: summarise_pump_card(np.ones(10), np.ones(11)), "must both have shape"),
    (lambda: displacement_rate(np.nan, 5.0, 0.038), "stroke must be finite"),
    (lambda: intake_pressure(1e4, 0.038, np.nan), "discharge pressure must be finite"),
    (lambda: displacement_rate(1.0, 0.0, 0.038), "period must be finite and positive"),
    (lambda: displacement_rate(np.ones(3), np.array([5.0, -2.0, np.inf]), 0.038),
     "period must be finite and positive, got -2 s"),
    (lambda: displacement_rate(1.0, 5.0, -0.038), "plunger diameter must be finite and positive"),
    (lambda: intake_pressure(1e4, np.nan, 1e7), "plunger diameter must be finite and positive"),
])
def test_bad_pump_data(call, message):
    with pytest.raises(DownholeError, match=message):
        call()


def test_displacement_rates_of_k_cards_are_each_cards():
    """Strokes and periods of K cards: each card's Q = A_p S / T as alone, to the bit."""
    strokes, periods = np.array([2.5, 1.0, 0.0]), np.array([5.5, 7.25, 6.0])
    rates = displacement_rate(strokes, periods, 0.038)
    assert rates.tolist() == [float(displacement_rate(s, t, 0.038)) for s, t in zip(strokes, periods)]
