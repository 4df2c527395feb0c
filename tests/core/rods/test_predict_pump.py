"""The pump as a boundary condition (pumpjack_cli.core.rods.pump), step by step, and bad inputs.

The chamber is driven here by hand: each step gives the affine relation
zeta = known - compliance F of the rods, and the valve laws must pick F and zeta:
* liquid-locked: F = clip((known - zeta_last) / compliance, 0, F_o) (a stop operator);
* vapour (fluid pound): F = F_o until the plunger has come down by the vapour volume / A_p;
* polytropic gas: p V^n constant between the valves, the travelling valve opening at p_d.
RP 11L's tubing stretch constants are checked in tests/validation/test_api_rp11l.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.core.rods.predict import predict
from pumpjack_cli.core.rods.pump import Pump, PumpChamber, pump_pressures, tubing_stiffness
from pumpjack_cli.core.rods.string import RodString
from pumpjack_cli.core.well import fluid_load
from pumpjack_cli.errors import PredictionError, PumpjackError

from pumpjack_cli.core.constants import STANDARD_GRAVITY

AREA = 1e-3
P_D, P_I = 12e6, 1e6
F_O = (P_D - P_I) * AREA
C0 = 1e-6  # m/N


def test_liquid_locked_chamber_is_a_stop_operator():
    chamber = PumpChamber(Pump(AREA, P_D, P_I), C0, 0.0)
    # Rods pull up by 5 mm: the plunger stays while the load rises by 5e-3 / 1e-6 = 5000 N.
    assert chamber.step(5e-3) == (pytest.approx(5000.0), 0.0)
    # Further: the load passes F_o = 11 kN, the standing valve opens, the plunger rises.
    load, position = chamber.step(0.02)
    assert load == F_O and position == pytest.approx(0.02 - C0 * F_O)
    assert chamber.intake == pytest.approx(AREA * position)
    # Reversal: held again while the load falls, then the travelling valve opens at zero load.
    held = chamber.step(position + 3e-3)
    assert held[1] == position and held[0] == pytest.approx(3e-3 / C0)
    load, down = chamber.step(position - 0.05)
    assert load == 0.0 and down == position - 0.05
    assert chamber.discharge == pytest.approx(AREA * 0.05)


def test_vapour_keeps_the_full_load_until_the_plunger_meets_the_liquid():
    chamber = PumpChamber(Pump(AREA, P_D, P_I, fillage=0.4), C0, 0.0)
    top = 1.0 + C0 * F_O
    chamber.step(top)  # up 1 m: 0.4 l of liquid, 0.6 l of vapour per litre swept
    assert chamber.volume - chamber.liquid == pytest.approx(0.6 * AREA * 1.0)
    # Down by 0.5 m: still in the vapour, full load.
    assert chamber.step(top - 0.5)[0] == F_O
    # The vapour ends 0.1 m lower, at 0.4 m: rods pushing to 0.405 - C0 F_o = 0.394 m put the
    # plunger on the liquid, which holds it at 0.4 m with (0.405 - 0.4) / C0 = 5000 N left on it.
    load, position = chamber.step(0.405)
    assert position == pytest.approx(0.4) and load == pytest.approx(5000.0)
    # Rods pushing on to 0.3 m: the travelling valve opens and the liquid goes up the tubing.
    assert chamber.step(0.3) == (0.0, 0.3)
    assert chamber.discharge == pytest.approx(AREA * 0.1)


def test_polytropic_gas_opens_the_travelling_valve_at_the_discharge_pressure():
    n = 1.3
    chamber = PumpChamber(Pump(AREA, P_D, P_I, fillage=0.5, gas_exponent=n), C0, 0.0)
    chamber.step(1.0 + C0 * F_O)  # 0.5 l of gas at p_i per litre swept; it must shrink to (1/12)^(1/1.3)
    gas, start = chamber.volume - chamber.liquid, chamber.position
    # Push down in small steps: between the valves p V^n = p_i gas^n, F = (p_d - p) A.
    for k in range(1, 600):
        load, position = chamber.step(start - 1e-3 * k)
        volume = gas + AREA * (position - start)
        if load == 0.0:
            # Open: the gas was compressed to p_d at V = gas (p_i / p_d)^(1/n).
            assert volume <= gas * (P_I / P_D) ** (1 / n) + AREA * 1e-3
            break
        pressure = P_D - load / AREA
        assert pressure * volume**n == pytest.approx(P_I * gas**n, rel=1e-9)
    else:
        pytest.fail("the travelling valve never opened")


def test_fluid_load_from_the_pressures_is_the_seed_well_models():
    pd, pi = pump_pressures(1530.0, 820.0, submergence=100.0)
    assert Pump(np.pi * 0.038**2 / 4, pd, pi).fluid_load == pytest.approx(fluid_load(0.038, 1430.0, 820.0), rel=1e-12)
    pd2, pi2 = pump_pressures(1530.0, 820.0, intake_pressure=2e6, tubing_head_pressure=1e6)
    assert (pd2, pi2) == (pytest.approx(1e6 + 820.0 * STANDARD_GRAVITY * 1530.0), 2e6)


def _rods():
    return RodString(np.array([1000.0]), np.array([2.85e-4]), np.array([2.1e11]), np.array([2.43]))


def _position(n=64):
    return 1.0 - np.cos(np.arange(n) * 2 * np.pi / n)


@pytest.mark.parametrize("call, message", [
    (lambda: Pump(AREA, P_D, P_I, fillage=1.5).check(), "fillage must lie between 0 and 1"),
    (lambda: Pump(AREA, P_I, P_D).check(), "the well would flow"),
    (lambda: Pump(-AREA, P_D, P_I).check(), "plunger area must be positive"),
    (lambda: Pump(AREA, P_D, P_I, gas_exponent=0.5).check(), "polytropic gas exponent must be >= 1"),
    (lambda: Pump(AREA, P_D, P_I, tubing_stiffness=0.0).check(), "tubing stiffness must be positive"),
    (lambda: tubing_stiffness("2-1/2", 1000.0), "unknown tubing size"),
    (lambda: pump_pressures(1000.0, 800.0), "either the pump submergence or the pump intake pressure"),
    (lambda: pump_pressures(1000.0, 800.0, submergence=1200.0), "submergence 1200 m must lie between 0"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(), -1.0, damping=0.1, fluid_density=800.0),
     "period must be positive"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(8), 5.0, damping=0.1, fluid_density=800.0),
     "at least 16 samples"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), np.full(64, np.nan), 5.0, damping=0.1, fluid_density=800.0),
     "non-finite"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(), 5.0, damping=0.0, fluid_density=800.0),
     "damping factor must be positive"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(), 5.0, damping=3.0, fluid_density=800.0),
     "overdamped"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(), 5.0, damping=0.1, fluid_density=9000.0),
     "fluid density 9000"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(40000), 5.0, damping=0.1, fluid_density=800.0),
     "use fewer samples per cycle"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(), 5.0, damping=0.1, fluid_density=800.0,
                     crank_angle=np.zeros(3)), "one value per position sample"),
    (lambda: predict(_rods(), Pump(AREA, P_D, P_I), _position(), 5.0, damping=0.1, fluid_density=800.0,
                     max_cycles=1), "at least 2 cycles"),
])
def test_bad_input_is_a_one_line_user_error(call, message):
    with pytest.raises(PredictionError, match=message) as caught:
        call()
    assert isinstance(caught.value, PumpjackError) and "\n" not in str(caught.value)


def test_rod_sections_given_as_lists_work():
    rods = RodString([1000.0], [2.85e-4], [2.1e11], [2.43])
    result = predict(rods, Pump(AREA, P_D, P_I), _position(), 5.0, damping=0.1, fluid_density=800.0)
    assert result.summary.fluid_load == pytest.approx(F_O)


def test_anchored_tubing_is_infinite_stiffness():
    assert Pump(AREA, P_D, P_I).tubing_stiffness == math.inf
