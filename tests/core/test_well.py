"""The well model of [SK8Rotation2013] (pumpjack_cli.core.well): every force against a hand calculation.

Reference data: [SK8Rotation2013]'s well (pump at 1530 m, plunger 38 mm, rods 19/22/25 mm for
51/26/23 % of the length, fluid 820 kg/m^3 and 3e-6 m^2/s, tubing 62 mm), with the
ESTIMATED plunger clearance 0.1 mm and submergence 100 m of configs/sk8-3.5-4000.toml.
Each expected value is written out from its textbook formula here, not taken from the code.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.core.well import annulus_drag_factor, buoyant_weight, darcy_friction_factor, fluid_kinetic_mass, fluid_load, plunger_friction, rod_friction, rod_string_mass, tubing_friction, well_load
from pumpjack_cli.errors import DynamicsError, PumpjackError
from pumpjack_cli.core.constants import STANDARD_GRAVITY as G

RODS = np.array([0.019, 0.022, 0.025])
SHARES = np.array([0.51, 0.26, 0.23])
SEED_WELL = dict(
    pump_depth=1530.0, submergence=100.0, plunger_diameter=0.038, plunger_clearance=1e-4,
    rod_diameters=RODS, rod_fractions=SHARES, rod_density=7850.0, fluid_density=820.0,
    kinematic_viscosity=3e-6, tubing_diameter=0.062, upstroke_speed=1.1, downstroke_speed=1.0,
)


def test_rod_string_mass_and_weight_in_fluid_by_hand():
    # 7850 kg/m^3 x pi/4 x (0.019^2 x 0.51 + 0.022^2 x 0.26 + 0.025^2 x 0.23) m^2 x 1530 m
    area = math.pi / 4 * (0.019**2 * 0.51 + 0.022**2 * 0.26 + 0.025**2 * 0.23)
    mass = 7850 * area * 1530
    assert rod_string_mass(RODS, 1530 * SHARES, 7850) == pytest.approx(mass, rel=1e-14)
    # Archimedes: the rods displace 820/7850 of their weight.
    assert buoyant_weight(mass, 7850, 820, G) == pytest.approx(mass * G * (7850 - 820) / 7850, rel=1e-14)


def test_fluid_load_is_the_column_above_the_dynamic_level_on_the_plunger():
    # rho g (H - h) pi D^2 / 4 = 820 x 9.80665 x 1430 x pi 0.038^2 / 4
    expected = 820 * G * 1430 * math.pi * 0.038**2 / 4
    assert fluid_load(0.038, 1430.0, 820.0, G) == pytest.approx(expected, rel=1e-14)
    assert expected == pytest.approx(13041.5, abs=0.1)


def test_plunger_friction_serdyuk_formula():
    # F = 1.84 D / delta - 137 N with D = 38 mm, delta = 0.1 mm: 1.84 x 380 - 137 = 562.2 N
    assert plunger_friction(0.038, 1e-4) == pytest.approx(562.2, rel=1e-12)
    with pytest.raises(DynamicsError, match="too large for the plunger friction formula"):
        plunger_friction(0.038, 0.6e-3)  # 1.84 x 38 / 0.6 = 116.5 < 137


def test_darcy_friction_factor_laminar_and_blasius():
    assert darcy_friction_factor(1000.0) == pytest.approx(0.064)        # 64 / Re
    assert darcy_friction_factor(2299.0) == pytest.approx(64 / 2299)
    assert darcy_friction_factor(1e4) == pytest.approx(0.3164 / 10)     # 0.3164 / Re^(1/4)
    assert darcy_friction_factor(1e5) == pytest.approx(0.3164 / 1e5**0.25)


def _annulus_drag_numerically(m: float) -> float:
    """Drag of a rod (radius 1, speed -1) in a tube of radius m, fluid displaced up the annulus.

    u(r) = -G r^2 / 4 + C1 ln r + C2 (mu = 1) with u(1) = -1, u(m) = 0 and a flux
    int 2 pi r u dr = +pi (the rod's own volume per unit time): three linear equations
    for G, C1, C2, solved numerically. Drag per unit length = 2 pi r mu du/dr at r = 1,
    divided by 2 pi mu V = 2 pi.
    """
    def flux(f):  # integral of 2 pi r f(r) over (1, m) for f = r^2, ln r, 1
        return {
            "r2": 2 * math.pi * (m**4 - 1) / 4,
            "ln": 2 * math.pi * (m**2 * math.log(m) / 2 - (m**2 - 1) / 4),
            "1": math.pi * (m**2 - 1),
        }[f]

    matrix = np.array([
        [-1 / 4, 0.0, 1.0],
        [-(m**2) / 4, math.log(m), 1.0],
        [-flux("r2") / 4, flux("ln"), flux("1")],
    ])
    g, c1, _ = np.linalg.solve(matrix, [-1.0, 0.0, math.pi])
    shear = -g / 2 + c1  # du/dr at r = 1
    return 2 * math.pi * shear / (2 * math.pi)


@pytest.mark.parametrize("ratio", [62 / 19, 62 / 25, 1.2, 5.0])
def test_annulus_drag_factor_matches_the_flow_solved_numerically(ratio):
    assert annulus_drag_factor(ratio) == pytest.approx(_annulus_drag_numerically(ratio), rel=1e-10)


def test_rod_friction_sums_the_sections():
    mu, v = 820 * 3e-6, 1.0
    expected = sum(2 * math.pi * mu * v * 1530 * share * _annulus_drag_numerically(0.062 / d)
                   for d, share in zip(RODS, SHARES))
    assert rod_friction(RODS, 1530 * SHARES, 0.062, mu, v) == pytest.approx(expected, rel=1e-10)


def test_tubing_friction_laminar_is_hagen_poiseuille_on_the_annulus_gap():
    # One section, viscous fluid (Re < 2300): dp = 32 mu L v_f / d_h^2 (lambda = 64/Re),
    # v_f = v (A_p - A_r)/(A_t - A_r), force = dp (A_p - A_r).
    a_p, a_r, a_t = (math.pi * d**2 / 4 for d in (0.038, 0.019, 0.062))
    v = 1.0
    v_f = v * (a_p - a_r) / (a_t - a_r)
    nu, rho, length = 1e-3, 900.0, 1000.0
    d_h = 0.062 - 0.019
    assert v_f * d_h / nu < 2300
    dp = 32 * rho * nu * length * v_f / d_h**2
    assert tubing_friction(0.038, [0.019], [length], 0.062, rho, nu, v) == pytest.approx(dp * (a_p - a_r), rel=1e-12)


def test_tubing_friction_turbulent_uses_blasius():
    a_p, a_r, a_t = (math.pi * d**2 / 4 for d in (0.038, 0.019, 0.062))
    v_f = 1.5 * (a_p - a_r) / (a_t - a_r)
    d_h = 0.043
    re = v_f * d_h / 3e-6
    assert re > 4000
    dp = 0.3164 / re**0.25 * 1000 / d_h * 820 * v_f**2 / 2
    assert tubing_friction(0.038, [0.019], [1000.0], 0.062, 820, 3e-6, 1.5) == pytest.approx(dp * (a_p - a_r), rel=1e-12)


def test_fluid_kinetic_mass_by_hand():
    a_p, a_r, a_t = (math.pi * d**2 / 4 for d in (0.038, 0.022, 0.062))
    expected = 820 * 500 * (a_p - a_r) ** 2 / (a_t - a_r)
    assert fluid_kinetic_mass(0.038, [0.022], [500.0], 0.062, 820) == pytest.approx(expected, rel=1e-14)


def test_stroke_loads_of_the_seed_well():
    w = well_load(**SEED_WELL)
    assert w.upstroke == pytest.approx(w.rod_weight + w.fluid_load + w.plunger_friction + w.tubing_friction, rel=1e-15)
    assert w.downstroke == pytest.approx(w.rod_weight - w.plunger_friction - w.rod_friction, rel=1e-15)
    assert w.mass_upstroke == w.rod_mass + w.fluid_mass
    assert w.mass_downstroke == w.rod_mass
    # The fluid moves only on the upstroke; the load depends only on the stroke direction.
    np.testing.assert_array_equal(w.force(np.zeros(3), np.array([True, False, True])),
                                  [w.upstroke, w.downstroke, w.upstroke])
    # Orders of magnitude of this light, thin oil: friction small against the weights.
    assert 37_000 < w.rod_weight < 38_000 and 13_000 < w.fluid_load < 13_100
    assert w.tubing_friction < 100 and w.rod_friction < 100


@pytest.mark.parametrize(
    "change, message",
    [
        ({"tubing_diameter": 0.024}, "does not clear"),
        ({"plunger_diameter": 0.02}, "must exceed the rod diameters"),
        ({"submergence": 1530.0}, "submergence"),
        ({"plunger_clearance": 1e-3}, "plunger clearance"),
    ],
)
def test_impossible_wells_are_refused(change, message):
    with pytest.raises(PumpjackError, match=message):
        well_load(**(SEED_WELL | change))
