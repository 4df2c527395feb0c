"""The air-balanced counterbalance (``core/beam/air_balanced.py``) against the gas's own energy.

Independent check: a polytropic gas p V^n = C stores, against the atmosphere it pushes back,
the potential U(V) = C V^(1-n) / (n - 1) + p_a V (the work the piston must do to compress it
from any volume, up to a constant), so the gearbox torque that holds the beam against it is
dU/dtheta, computed here by central differences of U along the crank angle from the unit's
beam angle alone. The cylinder's torque then has zero work over a turn (a conservative
force), and the mean net torque equals the polished-rod work per radian whatever the pressure.
The balance of the air pressure against a brute-force scan is in ``test_unit_kinds.py``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.air_balanced import ATMOSPHERE, AirCylinder
from pumpjack_cli.core.beam.class_three import ClassThreeLinkage
from pumpjack_cli.core.beam.geometry import COUNTERCLOCKWISE
from pumpjack_cli.core.sampling import crank_grid

from helpers import INCH, POUND_FORCE

UNIT = ClassThreeLinkage(120 * INCH, 70 * INCH, 24.5 * INCH, 100 * INCH, 70 * INCH, 95 * INCH, COUNTERCLOCKWISE)
H = 1e-5


def _cylinder(pressure=230 * POUND_FORCE / INCH**2, reference=None, exponent=1.4):
    dead = UNIT.dead_positions()
    return AirCylinder(-500 * POUND_FORCE, pressure, dead.beam_angle_bottom if reference is None else reference,
                       math.pi * (12 * INCH) ** 2 / 4, 0.2, dead.beam_angle_bottom, 50 * INCH, UNIT.front_arm, exponent)


def _potential(air: AirCylinder, theta: np.ndarray) -> np.ndarray:
    """U [J] of the gas and the atmosphere, by the closed form, at crank angles theta."""
    volume = air.volume(UNIT.motion(theta).beam_angle)
    reference = air.volume(np.asarray(air.reference_beam_angle))
    c = (air.pressure + ATMOSPHERE) * reference**air.exponent
    if air.exponent == 1.0:
        return -c * np.log(volume) + ATMOSPHERE * volume
    return c * volume ** (1 - air.exponent) / (air.exponent - 1) + ATMOSPHERE * volume


@pytest.mark.parametrize("exponent", [1.0, 1.2, 1.4])
def test_cylinder_torque_is_the_derivative_of_the_gas_energy(exponent):
    air = _cylinder(exponent=exponent)
    theta = np.linspace(0.0, 2 * np.pi, 721)
    torque = air.counterbalance_torque(UNIT.motion(theta))
    fd = (_potential(air, theta + H) - _potential(air, theta - H)) / (2 * H)
    assert np.abs(torque - fd).max() < 1e-6 * np.abs(torque).max()
    # it holds the beam up: on the upstroke (TF > 0) it drives the crank forward
    assert np.all(torque[UNIT.torque_factor(theta) > 0.05] < 0)


@pytest.mark.parametrize("pressure_psi", [150.0, 230.0, 320.0])
def test_the_cylinder_does_no_net_work_and_the_mean_torque_is_the_card_work(pressure_psi):
    air = _cylinder(pressure=pressure_psi * POUND_FORCE / INCH**2)
    theta = crank_grid(20_000)
    m = UNIT.motion(theta)
    load = 40e3 + 15e3 * (UNIT.torque_factor(theta) > 0)
    net = m.torque_factor * load + air.structural_torque(m) + air.counterbalance_torque(m)
    step = 2 * np.pi / theta.size
    # a periodic smooth integrand: the rectangle rule is spectrally accurate
    assert abs(np.sum(air.counterbalance_torque(m)) * step) < 1e-9 * np.abs(air.counterbalance_torque(m)).max()
    card_work = np.sum(m.torque_factor * load) * step
    assert np.mean(net) * 2 * np.pi == pytest.approx(card_work, rel=1e-9)


def test_the_stated_pressure_holds_at_its_position_and_the_gas_follows_the_polytrope():
    dead = UNIT.dead_positions()
    middle = 0.5 * (dead.beam_angle_bottom + dead.beam_angle_top)
    air = _cylinder(reference=middle)
    assert air.force(np.array(middle)) == pytest.approx(air.pressure * air.piston_area, rel=1e-12)
    top, bottom = air.force(np.array(dead.beam_angle_top)), air.force(np.array(dead.beam_angle_bottom))
    assert bottom > air.force(np.array(middle)) > top
    v_b, v_t = air.volume(np.array(dead.beam_angle_bottom)), air.volume(np.array(dead.beam_angle_top))
    p_b, p_t = bottom / air.piston_area + ATMOSPHERE, top / air.piston_area + ATMOSPHERE
    assert p_b * v_b**1.4 == pytest.approx(p_t * v_t**1.4, rel=1e-12)


def test_the_bundled_unit_builds_its_cylinder_from_the_clearance():
    unit = load_unit("a-228d-246-86")
    air, known = unit.counterbalance_model()
    dead = unit.geometry.mechanism().dead_positions()
    swept = air.piston_area * air.lever * (math.sin(dead.beam_angle_top) - math.sin(dead.beam_angle_bottom))
    assert known and air.bottom_volume == pytest.approx(3.0 * swept, rel=1e-12)
    assert air.pressure == pytest.approx(150 * POUND_FORCE / INCH**2, rel=1e-12)
    assert air.piston_area == pytest.approx(math.pi * (12 * INCH) ** 2 / 4, rel=1e-12)
