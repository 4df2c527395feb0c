"""The drive of a pumping unit: induction motor characteristic and the reduced inertia of
the motor, V-belt and gearbox ([SK8Rotation2013] eqs. 25-26; [Artobolevsky1951]).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import DynamicsError


@dataclass(frozen=True)
class MotorCharacteristic:
    """Linear working branch M = a + b omega of an induction motor, at the motor shaft.

    a [N·m], b [N·m·s]; torques [N·m] and speeds [rad/s] of the nameplate.
    """

    a: float
    b: float
    rated_torque: float
    starting_torque: float
    breakdown_torque: float
    synchronous_speed: float
    rated_speed: float

    def torque(self, speed: np.ndarray | float) -> np.ndarray | float:
        """Motor torque [N·m] at motor speed [rad/s] on the linear branch."""
        return self.a + self.b * speed


def motor_characteristic(rated_power: float, synchronous_speed: float, rated_speed: float,
                         starting_torque_ratio: float, breakdown_torque_ratio: float) -> MotorCharacteristic:
    """The straight line through (synchronous speed, 0) and (rated speed, rated torque).

    Seed 004 eq. 25 with speeds n in rpm: a = M_n n_s / (n_s - n_n),
    b = -30 M_n / (pi (n_s - n_n)), M_n = P / omega_n; in rad/s the same line is
    a = M_n w_s / (w_s - w_n), b = -M_n / (w_s - w_n). rated_power P [W]; speeds [rad/s].

    Motor 4AR180M4U3 of seed 004 (30 kW, 1500/1460 rpm): M_n = 30000 / (1460 pi/30)
    = 196.22 N·m, a = 196.22 · 1500/40 = 7358.2 N·m, b = -30 · 196.22 / (40 pi) = -46.84 N·m·s.

    >>> rpm = np.pi / 30
    >>> m = motor_characteristic(30e3, 1500 * rpm, 1460 * rpm, 2.0, 2.2)
    >>> round(m.rated_torque, 2), round(m.a, 1), round(m.b, 2)
    (196.22, 7358.2, -46.84)
    """
    if not 0 < rated_speed < synchronous_speed:
        raise DynamicsError(f"motor rated speed {rated_speed:.6g} rad/s must lie between 0 and the "
                            f"synchronous speed {synchronous_speed:.6g} rad/s")
    rated_torque = rated_power / rated_speed
    slip_speed = synchronous_speed - rated_speed
    return MotorCharacteristic(
        a=rated_torque * synchronous_speed / slip_speed,
        b=-rated_torque / slip_speed,
        rated_torque=rated_torque,
        starting_torque=starting_torque_ratio * rated_torque,
        breakdown_torque=breakdown_torque_ratio * rated_torque,
        synchronous_speed=synchronous_speed,
        rated_speed=rated_speed,
    )


def drive_inertia(motor_shaft: float, gearbox_input: float, crank_shaft: float,
                  belt_ratio: float, gearbox_ratio: float) -> float:
    """Moment of inertia of the drive reduced to the crank shaft [kg·m^2].

    Equal kinetic energy (Artobolevsky 1951, reduction of masses): a part turning u_k
    times faster than the crank counts u_k^2 times, so
    I = J_motor (u_b u_r)^2 + J_gearbox_input u_r^2 + J_crank_shaft, with J_motor the
    rotor and motor sheave, J_gearbox_input the driven sheave and the gearbox parts
    referred to its input shaft, belt_ratio u_b, gearbox_ratio u_r.

    Seed 004's rotor alone (0.232 kg·m^2, u = 37.18 · 900/250):

    >>> round(drive_inertia(0.232, 0.0, 0.0, 3.6, 37.18), 1)
    4156.3
    """
    return motor_shaft * (belt_ratio * gearbox_ratio) ** 2 + gearbox_input * gearbox_ratio**2 + crank_shaft


def belt_ratio(motor_sheave_diameter: float, gearbox_sheave_diameter: float) -> float:
    """V-belt reduction u_belt = d_2 / d_1 of the driving sheave d_1 and the driven sheave d_2 [m]
    (belt slip neglected; [SK8Rotation2013]).

    >>> belt_ratio(0.25, 0.9)
    3.6
    """
    return gearbox_sheave_diameter / motor_sheave_diameter


def total_ratio(gearbox_ratio: float, belt_reduction: float) -> float:
    """Motor speed / crank speed, u = u_r u_belt, of the gearbox and the V-belt reductions."""
    return gearbox_ratio * belt_reduction


def rated_crank_speed(motor_rated_speed: float, drive_ratio: float) -> float:
    """Crank speed at the motor's rated speed, omega_1 = omega_n / u [1/s] ([SK8Rotation2013]:
    pi n_n / (30 u_r u_belt) = 1.1422 1/s for SK8-3,5-4000).

    >>> round(rated_crank_speed(1460 * 3.141592653589793 / 30, total_ratio(37.18, belt_ratio(0.25, 0.9))), 4)
    1.1423
    """
    return motor_rated_speed / drive_ratio
