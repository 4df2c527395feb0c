"""Inferred production, slippage, intake pressure, fluid level and energy per day, by hand.

Every expected value is worked out here from the formula's published field form or by
arithmetic in the comment, not taken from the code's output.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.core.rods.production import (energy_per_day, fluid_above_pump, inferred_production,
                                               intake_pressure_from_load, slippage_rate)
from pumpjack_cli.core.rods.pump import discharge_pressure
from pumpjack_cli.errors import DownholeError

from helpers import BARREL, FOOT, INCH, PSI

DAY = 86400.0


def test_inferred_production_is_the_field_formula():
    # BFPD = 0.1166 d^2 SPM S_n eta %runtime (d, S_n in inches) [field reference]: the constant is
    # pi/4 in^2 x 1440 min/d / 9702 in^3/bbl = 0.11657; 2 in plunger, 8.5 SPM, 64 in, 100 %, 20 h
    expected = math.pi / 4 * 1440 / 9702 * 2.0**2 * 8.5 * 64 * (20 / 24)
    q = inferred_production(64 * INCH, math.pi * (2 * INCH)**2 / 4, 60 / 8.5, 20 / 24)
    assert float(q) * DAY / BARREL == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(0.1166 * 4 * 8.5 * 64 * 20 / 24, rel=3e-4)   # 211.4 bbl/d


def test_inferred_production_deducts_the_slippage_while_loaded():
    # 1e-3 m^2 x 2 m per 6 s = 3.333e-4 m^3/s; slippage 1e-4 m^3/s for half the cycle: 2.833e-4;
    # 12 h of 24: 1.4167e-4 m^3/s
    q = inferred_production(2.0, 1e-3, 6.0, 0.5, slippage=1e-4, loaded_share=0.5)
    assert float(q) == pytest.approx((2e-3 / 6 - 0.5e-4) * 0.5, rel=1e-12)
    assert float(inferred_production(2.0, 1e-3, 6.0, 1.0, slippage=1.0)) == 0.0   # never negative


def test_slippage_is_laminar_flow_through_the_plunger_clearance():
    # q = pi D (c/2)^3 dp / (12 mu L) [Wang2019]: 1.75 in plunger, 0.004 in fit, 5 ft long,
    # 2 cP, 1500 psi: pi 0.04445 (5.08e-5)^3 1.0342e7 / (12 2e-3 1.524) = 1.8933e-7 / 0.036576
    # = 5.176e-6 m^3/s (0.447 m^3/d)
    d, c, length, mu, dp = 1.75 * INCH, 0.004 * INCH, 5 * FOOT, 2e-3, 1500 * PSI
    by_hand = math.pi * 0.04445 * (0.0000508**3) * 1.0342136e7 / (12 * 2e-3 * 1.524)
    assert float(slippage_rate(d, c, length, mu, dp)) == pytest.approx(by_hand, rel=1e-4)
    assert by_hand == pytest.approx(5.176e-6, rel=1e-3)
    # cubic in the clearance, linear in the pressure difference, inverse in viscosity and length
    base = float(slippage_rate(d, c, length, mu, dp))
    assert float(slippage_rate(d, 2 * c, length, mu, dp)) == pytest.approx(8 * base, rel=1e-12)
    assert float(slippage_rate(d, c, 2 * length, 2 * mu, 4 * dp)) == pytest.approx(base, rel=1e-12)


def test_intake_pressure_and_fluid_level_of_the_published_design_well():
    # SWPSC design well of the field reference: 4 200 ft, 1.25 in plunger, SG 0.85, fluid level
    # 4 300 ft (at the pump: pumped off), tubing 150 psi, casing 25 psi. F_o = 0.340 G D^2 H
    # counts the fluid column only: 0.340 0.85 1.5625 4200 = 1897 lb; with the tubing pressure
    # on the plunger, 150 psi x 1.2272 in^2 = 184 lb more (the 184 lbf an open tool missed).
    area = math.pi * (1.25 * INCH)**2 / 4
    density = 0.85 * 999.0
    p_d = discharge_pressure(4200 * FOOT, density, 150 * PSI)
    # the pump's intake at the casing pressure (no liquid above the pump): F_o = (p_d - p_c) A_p
    fluid_load = (p_d - 25 * PSI) * area
    assert fluid_load / 4.4482216152605 == pytest.approx(1897 + (150 - 25) * 1.2272, rel=3e-3)
    intake = float(intake_pressure_from_load(fluid_load, area, p_d))
    assert intake == pytest.approx(25 * PSI, rel=1e-12)
    assert float(fluid_above_pump(intake, 25 * PSI, density)) == pytest.approx(0.0, abs=1e-9)
    # 100 ft of liquid above the pump: the intake 0.85 x 0.433 x 100 = 36.8 psi above the casing's
    lighter = fluid_load - 0.85 * 999.0 * 9.80665 * 100 * FOOT * area
    h = float(fluid_above_pump(float(intake_pressure_from_load(lighter, area, p_d)), 25 * PSI, density))
    assert h / FOOT == pytest.approx(100.0, rel=1e-9)


def test_energy_per_day_is_the_drive_power_over_the_running_hours():
    # PRHP 10 hp, drive 0.55 efficient, 18 h a day: 7.457 kW / 0.55 x 18 h = 244.0 kWh/d
    energy = float(energy_per_day(10 * 745.69987158227022, 0.55, 0.75))
    assert energy / 3.6e6 == pytest.approx(7.4569987 / 0.55 * 18, rel=1e-7)


@pytest.mark.parametrize("call, words", [
    (lambda: inferred_production(1.0, 1e-3, 6.0, 0.0), "runtime must lie in"),
    (lambda: inferred_production(1.0, 1e-3, 6.0, 1.2), "runtime must lie in"),
    (lambda: inferred_production(1.0, 1e-3, 6.0, 1.0, pump_efficiency=0.0), "pump efficiency"),
    (lambda: slippage_rate(0.04, -1e-4, 1.0, 1e-3, 1e6), "plunger clearance must be positive"),
    (lambda: energy_per_day(np.nan, 0.8, 1.0), "polished-rod power"),
])
def test_bad_inputs_are_refused_in_one_line(call, words):
    with pytest.raises(DownholeError, match=words) as error:
        call()
    assert "\n" not in str(error.value)
