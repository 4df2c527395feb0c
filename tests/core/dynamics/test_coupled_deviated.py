"""The machine and a deviated well's rods in one march (core/dynamics/coupled_deviated.py): in a vertical hole
it is the coupled solution of core/dynamics/coupled.py (exact modal steps), a solver it shares no rod code with;
the motor's work per cycle is the polished rod's."""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.dynamics.coupled import predict_coupled
from pumpjack_cli.core.dynamics.coupled_deviated import predict_coupled_deviated
from pumpjack_cli.core.rods.path import VerticalPath


def test_a_vertical_hole_gives_the_modal_coupled_solution(sk8_unit):
    machine, rods, pump = sk8_unit.machine(elastic_rods=True), sk8_unit.rods(), sk8_unit.pump()
    modal = predict_coupled(machine, rods, pump, damping=0.1, fluid_density=820.0, samples=256)
    both, deviated = predict_coupled_deviated(machine, rods, VerticalPath(), pump, damping=0.1, fluid_density=820.0,
                                              friction_coefficient=0.2, samples=256)
    a, b = modal.summary, both.summary
    assert b.mean_speed == pytest.approx(a.mean_speed, rel=1e-4)
    assert b.speed_fluctuation == pytest.approx(a.speed_fluctuation, abs=0.003)  # of 9.6 %
    assert b.peak_motor_torque.value == pytest.approx(a.peak_motor_torque.value, rel=0.02)
    assert both.cards.summary.peak_polished_rod_load.value == pytest.approx(
        modal.cards.summary.peak_polished_rod_load.value, rel=0.01)
    assert np.sqrt(np.mean((both.crank_speed - modal.crank_speed) ** 2)) < 1e-3 * a.mean_speed
    assert abs(b.energy_residual) < 1e-4 and deviated.friction_work == 0.0
