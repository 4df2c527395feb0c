"""Limits of the predictive solver that hand calculations and the rigid-rod seed model fix.

* static card: a full pump at very low speed gives the textbook card, loads W_rf + F_o
  and W_rf, picked up and released over the static rod stretch F_o sum L_i/(E_i A_i)
  (plus F_o / k_t with unanchored tubing: RP 11L's Sp = S - F_o (1/k_r + 1/k_t));
* rigid, massless rods reproduce the rigid-rod well model of [SK8Rotation2013]
  (pumpjack_cli.core.well, friction set to zero): W' + P_f up, W' down;
* zero fillage: no liquid ever enters, so the column never leaves the plunger and the
  polished-rod card is the card of an open pump (no fluid load) plus F_o, exactly
  (the rods are linear);
* buoyancy: the datum W_rf = g sum m_i L_i (1 - rho_f / rho_r), Archimedes.

The SK8 well's rods and pump are the shared fixtures of tests/conftest.py (API rods with
couplings, RP 11L Table 4.1 weights, E = 30.5e6 psi).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from pumpjack_cli.core.constants import STANDARD_GRAVITY
from pumpjack_cli.core.rods.predict import predict
from pumpjack_cli.core.rods.pump import tubing_stiffness
from pumpjack_cli.core.rods.string import RodString
from pumpjack_cli.core.well import WellLoad, buoyant_weight, fluid_load

from helpers import SK8_CRANK_SPEED, SK8_FLUID_DENSITY, SK8_PUMP_DEPTH, sk8_rod_position


@pytest.mark.parametrize("anchored", [True, False])
def test_full_pump_at_very_low_speed_gives_the_static_card(sk8_rods, sk8_pump, anchored):
    # 0.0006 strokes/min, nu = 0.02: inertia and damping forces (c m v, v < 0.1 mm/s) are
    # below 0.05 N, and so is the rods' ringing at the kinks of the sampled load (a few N at
    # a ten times shorter cycle); loads asserted to 1 N.
    rods = sk8_rods
    stiffness = math.inf if anchored else tubing_stiffness("2-7/8", SK8_PUMP_DEPTH)
    pump = dataclasses.replace(sk8_pump, tubing_stiffness=stiffness)
    position = sk8_rod_position(1024)
    result = predict(rods, pump, position, 1e5, damping=0.02, fluid_density=SK8_FLUID_DENSITY)
    s = result.summary
    f_o, w_rf = pump.fluid_load, s.buoyant_rod_weight
    stretch = f_o * (float(np.sum(rods.length / (rods.youngs_modulus * rods.area))) + 1 / stiffness)
    assert s.static_stretch == pytest.approx(stretch, rel=1e-12)
    assert s.peak_polished_rod_load.value == pytest.approx(w_rf + f_o, abs=1.0)
    assert s.minimum_polished_rod_load.value == pytest.approx(w_rf, abs=1.0)
    # Held still at the bottom, the plunger takes the load as the rods stretch: F = F_o s / stretch
    # from the bottom of the stroke; held at the top it gives it up over the same stretch.
    # Every sample of both transfers (about 90 here), to 1 N: the held plunger slides by a
    # second-order amount, worth 0.41-0.57 N of load at 1024 samples (1.4-2.0 N at 512, 0.11-0.15 N
    # at 2048, measured).
    up = result.polished_rod_velocity > 0
    moving = (result.pump_load > 0) & (result.pump_load < f_o)
    bottom, top = position.min(), position.max()
    pickup, release = moving & up, moving & ~up
    assert pickup.sum() > 20 and release.sum() > 20
    assert np.allclose(result.pump_load[pickup], f_o * (position[pickup] - bottom) / stretch, rtol=0, atol=1.0)
    assert np.allclose(result.pump_load[release], f_o * (1 - (top - position[release]) / stretch), rtol=0, atol=1.0)
    assert np.allclose(result.polished_rod_load, w_rf + result.pump_load, rtol=0, atol=0.1)
    # RP 11L's static plunger stroke Sp = S - F_o (1/k_r + 1/k_t); the pump card is F_o x Sp.
    # The pump's liquid count is second order in the step: 0.12 mm short at 1024 samples.
    assert s.net_plunger_stroke == pytest.approx(np.ptp(position) - stretch, abs=3e-4)
    assert s.pump_card_work == pytest.approx(f_o * s.net_plunger_stroke, rel=1e-4)


def test_rigid_massless_rods_give_the_rigid_well_model_loads(sk8_rods, sk8_pump):
    # E x 1e4 and mass / 1e4: the rods' stretch and inertia vanish, and the pump card is the
    # polished-rod card less W_rf. core.well's WellLoad with its friction forces set to zero
    # is W' + P_f on the upstroke and W' on the downstroke ([SK8Rotation2013] eqs. 19-23).
    # Gibbs' damping force c m v = (pi nu / 2L) sqrt(E A m) v does not vanish with the rods'
    # inertia (sqrt(E A m) is unchanged), so nu goes to 1e-4 as well: c m v < 5 N.
    rods = sk8_rods
    light = RodString(rods.length, rods.area, rods.youngs_modulus * 1e4, rods.mass_per_length * 1e-4)
    pump = sk8_pump
    position = sk8_rod_position(512)
    result = predict(light, pump, position, 2 * np.pi / SK8_CRANK_SPEED, damping=1e-4, fluid_density=SK8_FLUID_DENSITY)
    mass = float(np.sum(light.mass_per_length * light.length))
    seed = WellLoad(rod_weight=buoyant_weight(mass, 7850.0, SK8_FLUID_DENSITY, STANDARD_GRAVITY),
                    fluid_load=fluid_load(0.038, SK8_PUMP_DEPTH - 100.0, SK8_FLUID_DENSITY, STANDARD_GRAVITY),
                    plunger_friction=0.0, tubing_friction=0.0, rod_friction=0.0, rod_mass=mass, fluid_mass=0.0)
    assert result.summary.fluid_load == pytest.approx(seed.fluid_load, rel=1e-12)
    upstroke = result.polished_rod_velocity > 0
    expected = seed.force(None, upstroke)
    # Away from the two instants of load transfer (each shorter than one sample here):
    settled = np.abs(result.pump_load - np.where(upstroke, seed.fluid_load, 0.0)) < 1.0
    assert settled.mean() > 0.98
    assert np.max(np.abs(result.polished_rod_load - expected)[settled]) < 1e-3 * seed.fluid_load  # measured 3.5e-4


def test_zero_fillage_leaves_the_fluid_load_on_the_plunger(sk8_rods, sk8_pump):
    rods, position, period = sk8_rods, sk8_rod_position(512), 2 * np.pi / SK8_CRANK_SPEED
    pump = dataclasses.replace(sk8_pump, fillage=0.0)
    empty = predict(rods, pump, position, period, damping=0.1, fluid_density=SK8_FLUID_DENSITY)
    open_pump = predict(rods, dataclasses.replace(sk8_pump, discharge_pressure=pump.intake_pressure), position, period, damping=0.1,
                        fluid_density=SK8_FLUID_DENSITY)
    assert np.all(empty.pump_load == pump.fluid_load)
    assert np.allclose(empty.polished_rod_load, open_pump.polished_rod_load + pump.fluid_load, rtol=0, atol=1e-6)
    assert empty.summary.pump_displacement == 0.0
    assert empty.summary.pump_card_work == pytest.approx(0.0, abs=1e-6)


def test_fluid_pound_displaces_the_fillage_share_of_the_stroke(sk8_rods, sk8_pump):
    # With fillage f the liquid fills f of the volume swept while the standing valve is open,
    # so the liquid discharged per cycle is f A_p times that travel (steady state: in = out),
    # and the pump card's work is F_o times that stroke. The plunger meets the liquid at
    # about 1.5 m/s inside a time step: the card work is first order in the step there,
    # 0.47 % high at 512 samples per cycle (0.25 % at 1024, 0.06 % at 4096): asserted to 1 %.
    rods, position, period = sk8_rods, sk8_rod_position(512), 2 * np.pi / SK8_CRANK_SPEED
    result = predict(rods, dataclasses.replace(sk8_pump, fillage=0.6), position, period, damping=0.1, fluid_density=SK8_FLUID_DENSITY)
    s = result.summary
    lifting = result.pump_load >= sk8_pump.fluid_load
    rising = np.diff(result.plunger_position, append=result.plunger_position[0]) > 0
    travel = float(np.sum(np.diff(result.plunger_position, append=result.plunger_position[0])[lifting & rising]))
    assert s.net_plunger_stroke == pytest.approx(0.6 * travel, rel=1e-3)  # measured 3.5e-4
    assert s.pump_card_work == pytest.approx(s.fluid_load * s.net_plunger_stroke, rel=1e-2)
    assert s.net_plunger_stroke < 0.65 * s.gross_plunger_stroke


def test_buoyant_rod_weight_is_archimedes(sk8_rods, sk8_pump):
    rods = sk8_rods
    result = predict(rods, sk8_pump, sk8_rod_position(512), 1e4, damping=0.1, fluid_density=SK8_FLUID_DENSITY)
    mass = float(np.sum(rods.mass_per_length * rods.length))
    assert result.summary.buoyant_rod_weight == pytest.approx(
        mass * STANDARD_GRAVITY * (1 - SK8_FLUID_DENSITY / 7850.0), rel=1e-12)
    # The taper loads hang from the datum: at very low speed on the downstroke (pump load 0)
    # the top of each taper carries the buoyant weight of the rods below it.
    down = int(np.argmax(result.pump_load == 0.0))
    below = np.cumsum((rods.mass_per_length * rods.length)[::-1])[::-1] * STANDARD_GRAVITY * (1 - SK8_FLUID_DENSITY / 7850.0)
    assert np.allclose(result.taper_top_load[:, down], below, rtol=0, atol=2.0)
