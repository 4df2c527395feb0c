"""Coefficients of the equation of motion of a beam pumping unit reduced to the crank shaft.

[SK8Rotation2013] eq. 1 (Lagrange's equation of a one-degree-of-freedom machine, with the
crank angle theta as generalised coordinate; [Artobolevsky1951]):

    I(theta) d(omega)/dt + 1/2 omega^2 dI/dtheta = M_drive(omega) - M_load(theta) - M_gravity(theta)

* I, the reduced moment of inertia (kinetic energy T = 1/2 I omega^2), [SK8Rotation2013] eq. 9:
  the drive (motor rotor, sheaves, gearbox) and the crank with its counterweights
  (constant), the pitmans, the beam with horsehead and equalizer, and the masses moving
  with the polished rod (rods, and the fluid on the upstroke only);
* M_drive = (a + b u omega) u, the motor's linear working characteristic reduced to
  the crank through the total ratio u ([SK8Rotation2013] eqs. 25-26; :mod:`.drive`);
* M_load = P(theta) TF(theta): polished-rod load times the torque factor A psi'
  ([SK8Rotation2013] eqs. 19-23; P from :mod:`pumpjack_cli.core.well` or a dynamometer card);
* M_gravity = dV/dtheta: derivative of the potential energy of crank arms,
  counterweights, pitmans, beam, horsehead and equalizer ([SK8Rotation2013] eq. 18).

The positions and transfer functions (psi', psi'', chi', chi'') come from the
mechanism (:class:`pumpjack_cli.core.mechanism.Mechanism`), for whole arrays of crank
angles. The periodic solution is :mod:`.periodic`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from ..beam.card import Card, card_load
from ..beam.linkage import Linkage, Motion
from ..beam.masses import MassModel
from ..constants import STANDARD_GRAVITY
from .drive import MotorCharacteristic, rated_crank_speed


class RodLoad(Protocol):
    """Polished-rod load [N] by crank angle and stroke direction, and the masses [kg]
    that move with the polished rod on each stroke (they enter the reduced inertia)."""

    mass_upstroke: float
    mass_downstroke: float

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray: ...


@dataclass(frozen=True)
class CardLoad:
    """Polished-rod load from a dynamometer card.

    A measured card already holds the weights of rods and fluid, friction and the rods'
    inertia, so no mass moves with the polished rod in the reduced inertia.
    """

    card: Card
    mass_upstroke: float = 0.0
    mass_downstroke: float = 0.0

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
        return card_load(self.card, crank_angle)


@dataclass(frozen=True)
class Machine:
    """Everything the equation of motion needs, SI.

    linkage: the planar four-bar; masses: the moving links (per arm / per pitman, as
    :class:`~.kinetostatics.MassModel`); drive_inertia [kg·m^2]: rotor, sheaves and
    gearbox reduced to the crank shaft (:func:`drive_inertia`); drive_ratio u: motor
    speed / crank speed; motor: its characteristic at the motor shaft; rod_load: the
    polished-rod load model (:class:`~.well.WellLoad` or :class:`CardLoad`).
    """

    linkage: Linkage
    masses: MassModel
    drive_inertia: float
    drive_ratio: float
    motor: MotorCharacteristic
    rod_load: RodLoad
    gravity: float = STANDARD_GRAVITY

    @property
    def crank_inertia(self) -> float:
        """Both crank arms and all counterweights about the shaft [kg·m^2] (parallel axes)."""
        m = self.masses
        return 2.0 * (m.crank_arm_inertia + m.crank_arm_mass * m.crank_arm_cg**2) + \
            m.counterweight_mass * m.counterweight_radius**2

    @property
    def constant_inertia(self) -> float:
        """The constant part of the reduced inertia, I_0 + I_dr + m_pr r_pr^2 of seed 004 eq. 9 [kg·m^2]."""
        return self.drive_inertia + self.crank_inertia

    @property
    def rated_crank_speed(self) -> float:
        """omega_1 = omega_n / u [1/s] (:func:`.drive.rated_crank_speed`)."""
        return rated_crank_speed(self.motor.rated_speed, self.drive_ratio)

    def drive_torque(self, omega: np.ndarray | float) -> np.ndarray | float:
        """Motor torque reduced to the crank, (a + b u omega) u [N·m] (seed 004 eq. 26)."""
        return self.motor.torque(self.drive_ratio * omega) * self.drive_ratio


@dataclass(frozen=True)
class Coefficients:
    """The coefficients of the equation of motion at given crank angles (arrays).

    inertia I [kg·m^2] and inertia_rate dI/dtheta [kg·m^2/rad]; gravity_torque
    M_gravity, load_torque M_load = P TF [N·m]; rod_load P [N]; torque_factor TF [m];
    upstroke mask; the four-bar motion.
    """

    inertia: np.ndarray
    inertia_rate: np.ndarray
    gravity_torque: np.ndarray
    load_torque: np.ndarray
    rod_load: np.ndarray
    torque_factor: np.ndarray
    upstroke: np.ndarray
    motion: Motion


def _pitman_cg_derivatives(linkage: Linkage, masses: MassModel, m: Motion) -> tuple[np.ndarray, np.ndarray]:
    """dS/dtheta and d2S/dtheta2 of the pitman's centre of mass S = (1 - f) A + f B, f = AS / P.

    A the crank pin and B the equalizer bearing, their derivatives from the mechanism
    (:meth:`~pumpjack_cli.core.beam.geometry.Linkage.pin_rates`). Shape (2, N) each [m/rad, m/rad^2].
    """
    f = masses.pitman_cg / linkage.pitman
    a1, a2, b1, b2 = linkage.pin_rates(m)
    return (1.0 - f) * a1 + f * b1, (1.0 - f) * a2 + f * b2


def reduced_inertia(linkage: Linkage, masses: MassModel, m: Motion, rod_mass: np.ndarray | float,
                    constant: float) -> tuple[np.ndarray, np.ndarray]:
    """Reduced moment of inertia I(theta) [kg·m^2] and dI/dtheta (seed 004 eq. 9).

    I = constant + 2 [m_2 |dS_2/dtheta|^2 + J_2 chi'^2] + I_C psi'^2 + m_rod (A psi')^2,
    with the two pitmans (mass m_2, centroidal inertia J_2, centre S_2), the beam group
    about the centre bearing I_C = J_beam + m_beam x_beam^2 + J_head + m_head x_head^2
    + J_eq + m_eq C^2 (equalizer at D, turning with the beam), and rod_mass [kg] the
    mass moving with the polished rod. constant [kg·m^2]: drive, crank arms and
    counterweights. dI/dtheta differentiates each square: d(x^2)/dtheta = 2 x x'.
    """
    s1, s2 = _pitman_cg_derivatives(linkage, masses, m)
    beam = (masses.beam_inertia + masses.beam_mass * masses.beam_cg**2
            + masses.horsehead_inertia + masses.horsehead_mass * masses.horsehead_cg**2
            + masses.equalizer_inertia + masses.equalizer_mass * linkage.rear_arm**2)
    rod = rod_mass * linkage.front_arm**2
    inertia = (constant + 2.0 * (masses.pitman_mass * np.sum(s1 * s1, axis=0) + masses.pitman_inertia * m.pitman_rate**2)
               + (beam + rod) * m.beam_rate**2)
    rate = (4.0 * (masses.pitman_mass * np.sum(s1 * s2, axis=0) + masses.pitman_inertia * m.pitman_rate * m.pitman_rate2)
            + 2.0 * (beam + rod) * m.beam_rate * m.beam_rate2)
    return inertia, rate


def gravity_torque(linkage: Linkage, masses: MassModel, m: Motion, gravity: float = STANDARD_GRAVITY) -> np.ndarray:
    """M_gravity = dV/dtheta [N·m] of all links (seed 004 eq. 18).

    V = g [2 m_1 r_1 cos theta + m_cw r_cw cos(theta + phase) + 2 m_2 y_S2
    + (m_beam x_beam + m_head x_head - m_eq C) sin psi]: crank arms and counterweights at
    their radii (heights from the shaft), pitmans at their centres, the beam group on
    the beam line (equalizer at D, a distance C behind the centre bearing).
    """
    theta = m.crank_angle
    s1, _ = _pitman_cg_derivatives(linkage, masses, m)
    beam_moment = (masses.beam_mass * masses.beam_cg + masses.horsehead_mass * masses.horsehead_cg
                   - masses.equalizer_mass * linkage.rear_arm)
    return gravity * (
        -2.0 * masses.crank_arm_mass * masses.crank_arm_cg * np.sin(theta)
        - masses.counterweight_mass * masses.counterweight_radius * np.sin(theta + masses.counterweight_phase)
        + 2.0 * masses.pitman_mass * s1[1]
        + beam_moment * np.cos(m.beam_angle) * m.beam_rate
    )


def coefficients(machine: Machine, crank_angle: np.ndarray, upstroke: np.ndarray) -> Coefficients:
    """All coefficients of the equation of motion at the given crank angles [rad], one array pass."""
    theta = np.asarray(crank_angle, dtype=float)
    up = np.asarray(upstroke, dtype=bool)
    m = machine.linkage.motion(theta)
    load = machine.rod_load
    rod_mass = np.where(up, load.mass_upstroke, load.mass_downstroke)
    inertia, rate = reduced_inertia(machine.linkage, machine.masses, m, rod_mass, machine.constant_inertia)
    tf = machine.linkage.front_arm * m.beam_rate
    force = np.asarray(load.force(theta, up), dtype=float)
    return Coefficients(
        inertia=inertia,
        inertia_rate=rate,
        gravity_torque=gravity_torque(machine.linkage, machine.masses, m, machine.gravity),
        load_torque=force * tf,
        rod_load=force,
        torque_factor=tf,
        upstroke=up,
        motion=m,
    )


def mean_rod_speeds(linkage: Linkage, omega: float) -> tuple[float, float]:
    """Mean polished-rod speeds [m/s] of the upstroke and the downstroke at uniform crank speed omega [1/s]:
    stroke / time of the stroke, the time being the stroke's crank travel / omega."""
    dead = linkage.dead_positions()
    return dead.stroke * omega / dead.upstroke_crank_travel, dead.stroke * omega / dead.downstroke_crank_travel
