"""Energy per cycle of the predicted cards, and of the machine solved with the rods.

Over a periodic cycle the kinetic and strain energy of the rods return, so the work the
polished rod does on the rods (the surface card's area) equals the work the rods do on
the plunger (the pump card's area: for a full pump with incompressible liquid, the fluid
load times the net plunger stroke, F_o S_p) plus the energy the damping dissipates,
int int c m u_t^2 dx dt ([Gibbs1963]). The three are computed independently: the
surface work from the polished-rod load and velocity, the pump work from the pump load
and the plunger's motion (or from the liquid the pump discharged), the dissipation
from the modal velocities along the whole string.

The machine's energy closure (motor work = polished-rod work) is in test_predict_coupled.py.

The SK8 well's rods and pump are the shared fixtures of tests/conftest.py (API rods with
couplings, RP 11L Table 4.1 weights, E = 30.5e6 psi).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from pumpjack_cli.core.rods.predict import predict
from pumpjack_cli.core.rods.pump import tubing_stiffness

from helpers import SK8_CRANK_SPEED, SK8_FLUID_DENSITY, SK8_PUMP_DEPTH, sk8_rod_position

PERIOD = 2 * np.pi / SK8_CRANK_SPEED


@pytest.mark.parametrize("anchored", [True, False])
def test_surface_work_is_fluid_load_times_net_stroke_plus_damping(sk8_rods, sk8_pump, anchored):
    # Full pump: work on the fluid = F_o x net plunger stroke (liquid discharged / A_p).
    # Measured closure 2.5e-6 (anchored) and 3e-6 (unanchored) at 1024 samples; asserted 1e-4.
    stiffness = np.inf if anchored else tubing_stiffness("2-7/8", SK8_PUMP_DEPTH)
    pump = dataclasses.replace(sk8_pump, tubing_stiffness=stiffness)
    s = predict(sk8_rods, pump, sk8_rod_position(1024), PERIOD, damping=0.1, fluid_density=SK8_FLUID_DENSITY).summary
    fluid_work = pump.fluid_load * s.net_plunger_stroke
    assert s.surface_card_work == pytest.approx(fluid_work + s.damping_dissipation, rel=1e-4)
    assert s.pump_card_work == pytest.approx(fluid_work, rel=1e-4)
    # The damping takes a large share at nu = 0.1 in this well: a non-trivial check.
    assert 0.2 < s.damping_dissipation / s.surface_card_work < 0.5
    assert s.polished_rod_power == pytest.approx(s.surface_card_work / PERIOD, rel=1e-12)
    assert s.pump_rate == pytest.approx(s.pump_displacement / PERIOD, rel=1e-12)


@pytest.mark.parametrize("samples, changes", [
    (1024, dict(fillage=0.5, tubing_stiffness=tubing_stiffness("2-7/8", SK8_PUMP_DEPTH))),
    (1024, dict(fillage=0.6, gas_exponent=1.2)),
    # The plunger hits the liquid within a time step: first order there, 1.2e-4 at 1024
    # samples and 6.6e-5 at 2048 (measured), so this one runs at 2048.
    (2048, dict(fillage=0.6)),
])
def test_surface_work_is_pump_card_work_plus_damping(sk8_rods, sk8_pump, samples, changes):
    # Fluid pound, gas, unanchored tubing: the pump card's area (the p-V loop of the chamber)
    # replaces F_o S_p. With gas it exceeds F_o S_p by the gas compression work.
    s = predict(sk8_rods, dataclasses.replace(sk8_pump, **changes), sk8_rod_position(samples), PERIOD, damping=0.1,
                fluid_density=SK8_FLUID_DENSITY).summary
    assert s.surface_card_work == pytest.approx(s.pump_card_work + s.damping_dissipation, rel=1e-4)
    if "gas_exponent" in changes:
        assert s.pump_card_work > 1.1 * s.fluid_load * s.net_plunger_stroke
