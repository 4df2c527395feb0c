"""The predictive solver against an independent exact method: Gibbs' frequency-domain solution.

Gibbs (1963) solves the damped wave equation of a tapered string per harmonic: with
beta = sqrt(-omega^2 + i omega c) / a_i, each taper carries the displacement U (down) and
the force F = EA U' by

    [U, F]_bottom = [[cosh beta l, sinh beta l / (EA beta)], [EA beta sinh beta l, cosh beta l]] [U, F]_top,

exact for the periodic steady state, with no modes, no time steps and no pump model.
The helpers below (a few lines of transfer matrices) are that independent method; the
predictive solver (modes, exact hat-input steps, quasi-static residual modes, a pump
marched in time) must agree with it:

* open pump (no fluid load): the polished-rod load for a prescribed polished-rod motion;
* the bottom-end dynamic compliance of the modal model against B / D of the chain;
* round trip: the downhole card computed from the predicted surface card by the chain
  (what a diagnostic program does, [Gibbs1963]) against the predicted pump card.

The SK8 well's rods and pump are the shared fixtures of tests/conftest.py (API rods with
couplings, RP 11L Table 4.1 weights, E = 30.5e6 psi).
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.rods.predict import predict, well_model
from pumpjack_cli.core.rods.predict_modes import damping_coefficient
from pumpjack_cli.core.rods.pump import Pump
from pumpjack_cli.core.rods.string import RodString

from helpers import SK8_CRANK_SPEED, SK8_FLUID_DENSITY, sk8_rod_position


def _chain(rods: RodString, omega: np.ndarray, c: float):
    """Gibbs' transfer matrix (A, B; C, D) of the whole string per angular frequency (arrays)."""
    a_, b_, c_, d_ = (np.ones_like(omega, dtype=complex), np.zeros_like(omega, dtype=complex),
                      np.zeros_like(omega, dtype=complex), np.ones_like(omega, dtype=complex))
    for length, ea, speed in zip(rods.length, rods.youngs_modulus * rods.area, rods.wave_speed):
        beta = np.sqrt(-omega**2 + 1j * omega * c + 0j) / speed
        bl = beta * length
        with np.errstate(invalid="ignore", divide="ignore"):
            sinc = np.where(np.abs(bl) > 0, np.sinh(bl) / np.where(bl == 0, 1, bl), 1.0)
        t11, t12, t21 = np.cosh(bl), sinc * length / ea, ea * beta * np.sinh(bl)
        a_, b_, c_, d_ = t11 * a_ + t12 * c_, t11 * b_ + t12 * d_, t21 * a_ + t11 * c_, t21 * b_ + t11 * d_
    return a_, b_, c_, d_


def test_open_pump_load_is_gibbs_harmonic_solution(sk8_rods):
    # No fluid load (p_d = p_i): the pump end is free, F_L = 0. Polished rod moving with
    # two harmonics; the dynamic polished-rod load must be F_0 = (C/D) S per harmonic
    # (S up, U_0 = -S). Tolerance 1e-4 of the load range: modal truncation at twice
    # the Nyquist frequency and the linear interpolation of the top acceleration, both
    # O((omega h)^2); measured 1.6e-5.
    rods, samples, period = sk8_rods, 512, 5.5
    t = np.arange(samples) * period / samples
    w = 2 * np.pi / period
    s = 1.2 * (1 - np.cos(w * t)) + 0.2 * np.sin(2 * w * t)
    pump = Pump(1e-3, 1e6, 1e6)
    result = predict(rods, pump, s, period, damping=0.15, fluid_density=SK8_FLUID_DENSITY)
    c = damping_coefficient(rods, 0.15)
    spectrum = np.fft.rfft(s)
    _, _, c_, d_ = _chain(rods, w * np.arange(spectrum.size), c)
    exact = np.fft.irfft(c_ / d_ * spectrum, samples)
    dynamic = result.polished_rod_load - result.summary.buoyant_rod_weight
    assert np.max(np.abs(dynamic - exact)) < 1e-4 * np.ptp(exact)
    assert np.all(result.pump_load == 0.0)


def test_bottom_compliance_of_the_modes_is_gibbs_b_over_d(sk8_rods):
    # Dynamic compliance of the rod end to a harmonic pump force, top held: modal sum
    # sum b_k^2 / (omega_k^2 - w^2 + i c w) + C_rem against the chain's B / D. The
    # residual is quasi-static, so the error grows as (w / omega_cut)^2: 1e-10 at 0.3 rad/s,
    # 1.1e-4 at 60 rad/s (measured).
    rods = sk8_rods
    model = well_model(rods, Pump(1e-3, 2e7, 1e6), damping=0.1, step=5.5 / 1024, samples=8,
                       fluid_density=SK8_FLUID_DENSITY)
    m = model.modes
    w = np.array([0.3, 2.0, 7.0, 20.0, 60.0])
    modal = np.sum(m.bottom[:, None]**2 / (m.frequency[:, None]**2 - w**2 + 1j * m.damping * w), axis=0)
    modal += m.residual_compliance
    _, b_, _, d_ = _chain(rods, w, m.damping)
    assert np.allclose(modal, b_ / d_, rtol=2e-4, atol=0)
    assert m.static_compliance == pytest.approx(float(np.sum(rods.length / (rods.youngs_modulus * rods.area))))


def test_round_trip_gibbs_diagnostic_recovers_the_pump_card(sk8_rods, sk8_pump):
    # Predict the SK8 well's cards (full pump), then compute the downhole card from the
    # surface card alone with the chain: U_L = A U_0 + B F_0, F_L = C U_0 + D F_0.
    # The diagnostic reads the sampled surface card as a trigonometric polynomial, the
    # prediction drives the rods with linear pieces and keeps modes up to twice the
    # Nyquist frequency: they differ only near the sharp load transfers. Measured: pump
    # load RMS 2.8e-4 F_o (largest 2.2e-3 F_o), plunger 9 um, card work 4e-6; asserted
    # with a margin of about 3.
    rods, pump, samples = sk8_rods, sk8_pump, 1024
    period = 2 * np.pi / SK8_CRANK_SPEED
    s = sk8_rod_position(samples)
    result = predict(rods, pump, s, period, damping=0.1, fluid_density=SK8_FLUID_DENSITY)
    c = damping_coefficient(rods, 0.1)
    w = 2 * np.pi / period * np.arange(samples // 2 + 1)
    a_, b_, c_, d_ = _chain(rods, w, c)
    u0 = np.fft.rfft(-s)
    f0 = np.fft.rfft(result.polished_rod_load - result.summary.buoyant_rod_weight)
    load = np.fft.irfft(c_ * u0 + d_ * f0, samples)
    plunger = -np.fft.irfft(a_ * u0 + b_ * f0, samples)
    f_o = pump.fluid_load
    assert np.sqrt(np.mean((load - result.pump_load) ** 2)) < 1e-3 * f_o
    assert np.max(np.abs(load - result.pump_load)) < 6e-3 * f_o
    assert np.max(np.abs(plunger - result.plunger_position)) < 3e-5
    work = np.sum(0.5 * (load + np.roll(load, -1)) * (np.roll(plunger, -1) - plunger))
    assert work == pytest.approx(result.summary.pump_card_work, rel=2e-5)
