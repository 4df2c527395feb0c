"""The machine and the elastic rods solved together (pumpjack_cli.core.dynamics.coupled).

Independent references:
* a stiff motor (slip 0.5 rpm instead of 40) holds the crank speed: the coupled cards
  must tend to the uniform-rotation cards of pumpjack_cli.core.rods.predict at the same
  mean speed, a separate solver with the polished-rod motion prescribed;
* the motor's linear characteristic M = a u + b u^2 omega: its work per revolution over
  2 pi is the crank-angle mean of M, a u + b u^2 <omega>_theta, with
  <omega>_theta = int omega dtheta / 2 pi = int omega^2 dt / 2 pi;
* energy: over a periodic cycle the links' kinetic energy and the weights' potential
  energy return, so the motor's work equals the polished-rod work, and at every sample
  the torques balance;
* the SK8-3,5-4000 data of [SK8Rotation2013], built from configs/ as `pumpjack dynamics`
  does, with the well's rods 25/22/19 mm (23/26/51 %, largest at the top).

The SK8 well's rods and pump are the shared fixtures of tests/conftest.py (API rods with
couplings, RP 11L Table 4.1 weights, E = 30.5e6 psi).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from pumpjack_cli.core.dynamics.coupled import predict_coupled
from pumpjack_cli.core.dynamics.drive import motor_characteristic
from pumpjack_cli.core.rods.predict import predict
from pumpjack_cli.errors import PredictionError

from helpers import RPM, SK8_FLUID_DENSITY, polished_rod_position


@pytest.fixture(scope="module")
def coupled(sk8_machine, sk8_rods, sk8_pump):
    return predict_coupled(sk8_machine, sk8_rods, sk8_pump, damping=0.1, fluid_density=SK8_FLUID_DENSITY, samples=512,
                           resolution=512)   # the march's own steps (the tests below count them)


def test_stiff_motor_gives_the_uniform_rotation_cards(sk8_machine, sk8_rods, sk8_pump):
    # Slip 0.5 rpm: b u^2 = 4.3e7 N m s, so the torque swing of ~50 kN m moves the crank speed
    # by ~1e-3 of its mean (measured 1.3e-3). The cards then match the uniform-rotation
    # prediction at the same mean speed: measured 2.2e-3 of the load range, net stroke 1.2e-4.
    stiff = dataclasses.replace(sk8_machine, motor=motor_characteristic(30e3, 1500 * RPM, 1499.5 * RPM, 2.0, 2.2))
    samples = 512
    coupled = predict_coupled(stiff, sk8_rods, sk8_pump, damping=0.1, fluid_density=SK8_FLUID_DENSITY, samples=samples,
                              resolution=samples)   # on the grid of the uniform prediction it is compared with
    s = coupled.summary
    assert s.speed_fluctuation < 3e-3
    position = polished_rod_position(stiff.linkage, np.arange(samples) * 2 * np.pi / samples)
    uniform = predict(sk8_rods, sk8_pump, position, s.period, damping=0.1, fluid_density=SK8_FLUID_DENSITY)
    span = np.ptp(uniform.polished_rod_load)
    assert np.max(np.abs(coupled.cards.polished_rod_load - uniform.polished_rod_load)) < 5e-3 * span
    assert coupled.cards.summary.net_plunger_stroke == pytest.approx(uniform.summary.net_plunger_stroke, rel=1e-3)


def test_mean_motor_torque_fixes_the_mean_speed(sk8_machine, coupled):
    # Motor work per revolution / 2 pi = a u + b u^2 <omega>_theta, <omega>_theta = sum omega^2 h / 2 pi
    # (measured 1.3e-10; the same sums on both sides, so only the bookkeeping is tested to 1e-8).
    s = coupled.summary
    h = s.period / 512
    a_u, b_u2 = sk8_machine.motor.a * sk8_machine.drive_ratio, sk8_machine.motor.b * sk8_machine.drive_ratio**2
    angle_mean = float(np.sum(coupled.crank_speed**2) * h / (2 * np.pi))
    assert s.motor_work / (2 * np.pi) == pytest.approx(a_u + b_u2 * angle_mean, rel=1e-8)
    assert s.mean_speed == pytest.approx(2 * np.pi / s.period, rel=1e-14)
    # The crank starts the reported revolution at crank angle 0 and ends it at 2 pi.
    assert coupled.cards.crank_angle[0] == pytest.approx(0.0, abs=1e-9) or \
        coupled.cards.crank_angle[0] == pytest.approx(2 * np.pi, abs=1e-9)
    # This well overloads the 30 kW motor of [SK8Rotation2013] when the rods are elastic (docs/predict.md).
    assert s.breakdown_torque_margin < 1.0


def test_coupled_motor_work_is_polished_rod_work(coupled):
    # Measured 6e-7 at 512 samples per revolution (trapezoidal rule on the machine).
    s = coupled.summary
    assert s.motor_work == pytest.approx(s.polished_rod_work, rel=1e-4)
    # The cards' surface work leaves out W_rf x (sum of the velocity samples x h), ~2e-6 m over a cycle.
    assert s.polished_rod_work == pytest.approx(coupled.cards.summary.surface_card_work, rel=1e-5)
    cards = coupled.cards.summary
    assert cards.surface_card_work == pytest.approx(cards.pump_card_work + cards.damping_dissipation, rel=1e-4)


def test_coupled_torques_balance_at_every_sample(sk8_machine, coupled):
    # M_drive = I eps + 1/2 I' omega^2 + M_gravity + P TF, sample by sample, from the reported
    # columns (gearbox torque = M_drive - I_drive eps; load torque P TF; polished-rod velocity TF omega).
    machine = sk8_machine
    drive = coupled.motor_torque * machine.drive_ratio
    balance = coupled.inertia_torque + coupled.gravity_torque + coupled.rod_load_torque
    assert np.max(np.abs(drive - balance)) < 1e-6 * np.max(np.abs(drive))
    assert np.allclose(coupled.net_torque, drive - machine.drive_inertia * coupled.crank_acceleration, rtol=1e-12)
    tf = coupled.rod_load_torque / coupled.cards.polished_rod_load
    assert np.allclose(coupled.cards.polished_rod_velocity, tf * coupled.crank_speed, rtol=1e-9, atol=1e-12)


def test_a_motor_too_weak_for_the_well_stalls_the_crank(sk8_machine, sk8_rods, sk8_pump):
    # 0.6 kW instead of 30 kW: the linear characteristic still turns the crank on average, but the
    # upstroke's torque stops it within the first revolution; the solver says so in one line.
    weak = dataclasses.replace(sk8_machine, motor=motor_characteristic(600.0, 1500 * RPM, 1460 * RPM, 2.0, 2.2))
    with pytest.raises(PredictionError, match="the crank stalls"):
        predict_coupled(weak, sk8_rods, sk8_pump, damping=0.1, fluid_density=SK8_FLUID_DENSITY, samples=256)
