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

    Attributes
    ----------
    a : float
        Torque intercept [N·m].
    b : float
        Slope [N·m·s] (negative).
    rated_torque, starting_torque, breakdown_torque : float
        M_n, starting and pull-out (maximum) torque [N·m].
    synchronous_speed, rated_speed : float
        omega_s, omega_n [rad/s].

    References
    ----------
    [SK8Rotation2013] eq. 25.
    """

    a: float
    b: float
    rated_torque: float
    starting_torque: float
    breakdown_torque: float
    synchronous_speed: float
    rated_speed: float

    def torque(self, speed: np.ndarray | float) -> np.ndarray | float:
        """Motor torque on the linear branch, M = a + b omega.

        Parameters
        ----------
        speed : float or numpy.ndarray
            omega, motor speed [rad/s].

        Returns
        -------
        float or numpy.ndarray
            M [N·m].

        Examples
        --------
        The line passes through the rated point and through zero at synchronous speed
        (4AR180M4U3, [SK8Rotation2013]):

        >>> rpm = np.pi / 30
        >>> m = motor_characteristic(30e3, 1500 * rpm, 1460 * rpm, 2.0, 2.2)
        >>> round(m.torque(1460 * rpm), 2), round(m.torque(1500 * rpm), 9)
        (196.22, 0.0)
        """
        return self.a + self.b * speed


def motor_characteristic(rated_power: float, synchronous_speed: float, rated_speed: float,
                         starting_torque_ratio: float, breakdown_torque_ratio: float) -> MotorCharacteristic:
    """The straight line through (synchronous speed, 0) and (rated speed, rated torque).

    [SK8Rotation2013] eq. 25 with speeds n in rpm:

        a = M_n n_s / (n_s - n_n),  b = -30 M_n / (pi (n_s - n_n)),  M_n = P / omega_n;

    in rad/s the same line is a = M_n w_s / (w_s - w_n), b = -M_n / (w_s - w_n).

    Parameters
    ----------
    rated_power : float
        P, rated shaft power [W].
    synchronous_speed : float
        w_s [rad/s].
    rated_speed : float
        w_n [rad/s], 0 < w_n < w_s.
    starting_torque_ratio, breakdown_torque_ratio : float
        Starting and pull-out torque over rated torque (dimensionless).

    Returns
    -------
    MotorCharacteristic
        a [N·m], b [N·m·s], torques [N·m], speeds [rad/s].

    Raises
    ------
    DynamicsError
        The rated speed is not between 0 and the synchronous speed.

    References
    ----------
    [SK8Rotation2013] eq. 25.

    Examples
    --------
    Motor 4AR180M4U3 of [SK8Rotation2013] (30 kW, 1500/1460 rpm): M_n = 30000 / (1460 pi/30)
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
    """Moment of inertia of the drive reduced to the crank shaft.

    Equal kinetic energy (reduction of masses, [Artobolevsky1951]): a part turning u_k
    times faster than the crank counts u_k^2 times, so

        I = J_motor (u_b u_r)^2 + J_gearbox_input u_r^2 + J_crank_shaft.

    Parameters
    ----------
    motor_shaft : float
        J_motor, rotor and motor sheave [kg·m²].
    gearbox_input : float
        J_gearbox_input, driven sheave and gearbox parts referred to its input shaft
        [kg·m²].
    crank_shaft : float
        Parts on the crank shaft [kg·m²].
    belt_ratio, gearbox_ratio : float
        u_b, u_r (dimensionless).

    Returns
    -------
    float
        I [kg·m²].

    References
    ----------
    [Artobolevsky1951]; [SK8Rotation2013] eq. 9 (I_dr).

    Examples
    --------
    The rotor of [SK8Rotation2013] alone (0.232 kg·m², u = 37.18 · 900/250):
    0.232 x 133.848² = 4156.3 kg·m².

    >>> round(drive_inertia(0.232, 0.0, 0.0, 3.6, 37.18), 1)
    4156.3
    """
    return motor_shaft * (belt_ratio * gearbox_ratio) ** 2 + gearbox_input * gearbox_ratio**2 + crank_shaft


def belt_ratio(motor_sheave_diameter: float, gearbox_sheave_diameter: float) -> float:
    """V-belt reduction u_belt = d_2 / d_1, belt slip neglected.

    Parameters
    ----------
    motor_sheave_diameter : float
        d_1, driving sheave [m].
    gearbox_sheave_diameter : float
        d_2, driven sheave [m].

    Returns
    -------
    float
        u_belt (dimensionless).

    References
    ----------
    [SK8Rotation2013] (sheaves 250 and 900 mm).

    Examples
    --------
    >>> belt_ratio(0.25, 0.9)
    3.6
    """
    return gearbox_sheave_diameter / motor_sheave_diameter


def total_ratio(gearbox_ratio: float, belt_reduction: float) -> float:
    """Total drive ratio, motor speed / crank speed, u = u_r u_belt.

    Parameters
    ----------
    gearbox_ratio : float
        u_r (dimensionless).
    belt_reduction : float
        u_belt (dimensionless).

    Returns
    -------
    float
        u (dimensionless).

    References
    ----------
    [SK8Rotation2013] (gearbox Ts2NSh-750B, u_r = 37.18).

    Examples
    --------
    SK8-3,5-4000: 37.18 x 900/250 = 133.848.

    >>> round(total_ratio(37.18, 3.6), 6)
    133.848
    """
    return gearbox_ratio * belt_reduction


def rated_crank_speed(motor_rated_speed: float, drive_ratio: float) -> float:
    """Crank speed at the motor's rated speed, omega_1 = omega_n / u.

    Parameters
    ----------
    motor_rated_speed : float
        omega_n [rad/s].
    drive_ratio : float
        u, motor speed / crank speed (dimensionless).

    Returns
    -------
    float
        omega_1 [1/s].

    References
    ----------
    [SK8Rotation2013]: pi n_n / (30 u_r u_belt) = 1.1422 1/s for SK8-3,5-4000.

    Examples
    --------
    pi 1460 / (30 x 37.18 x 3.6) = 1.14227 1/s, printed as 1.1422 in [SK8Rotation2013]:

    >>> round(rated_crank_speed(1460 * 3.141592653589793 / 30, total_ratio(37.18, belt_ratio(0.25, 0.9))), 4)
    1.1423
    """
    return motor_rated_speed / drive_ratio
