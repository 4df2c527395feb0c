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
from ..beam.geometry import Linkage  # noqa: F401 (the docstrings' examples build one)
from ..mechanism import Mechanism, Motion
from ..beam.masses import MassModel
from ..constants import STANDARD_GRAVITY
from .drive import MotorCharacteristic, rated_crank_speed


class RodLoad(Protocol):
    """Polished-rod load by crank angle and stroke direction, and the masses moving with the polished rod.

    Attributes
    ----------
    mass_upstroke, mass_downstroke : float
        Masses that move with the polished rod on each stroke [kg]; they enter the
        reduced inertia ([SK8Rotation2013] eq. 9).

    Methods
    -------
    force(crank_angle, upstroke)
        Polished-rod load [N] at crank angles [rad], given the upstroke mask.
    """

    mass_upstroke: float
    mass_downstroke: float

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray: ...


@dataclass(frozen=True)
class CardLoad:
    """Polished-rod load from a dynamometer card.

    A measured card already holds the weights of rods and fluid, friction and the rods'
    inertia, so no mass moves with the polished rod in the reduced inertia.

    Attributes
    ----------
    card : Card
        Load [N] on the crank-angle axis [rad].
    mass_upstroke, mass_downstroke : float
        0 [kg].
    """

    card: Card
    mass_upstroke: float = 0.0
    mass_downstroke: float = 0.0

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
        """The card's load [N] at crank angles [rad] (:func:`~pumpjack_cli.core.beam.card.card_load`)."""
        return card_load(self.card, crank_angle)


@dataclass(frozen=True)
class Machine:
    """Everything the equation of motion needs, SI.

    Attributes
    ----------
    linkage : Linkage
        The planar four-bar [m].
    masses : MassModel
        The moving links, per arm and per pitman [kg, m, kg·m², rad].
    drive_inertia : float
        Rotor, sheaves and gearbox reduced to the crank shaft [kg·m²]
        (:func:`~.drive.drive_inertia`).
    drive_ratio : float
        u, motor speed / crank speed (dimensionless).
    motor : MotorCharacteristic
        The motor's characteristic at the motor shaft [N·m, rad/s].
    rod_load : RodLoad
        The polished-rod load model (:class:`~pumpjack_cli.core.well.WellLoad` or
        :class:`CardLoad`) [N, kg].
    gravity : float
        g [m/s²] ([BIPM2019]).

    References
    ----------
    [SK8Rotation2013] eqs. 1, 9, 18-26.

    Examples
    --------
    SK8-3,5-4000 ([SK8Rotation2013]): crank arms 2 x 1373 kg, counterweights 5200 kg at
    0.83 m; the drive inertias are the estimates of ``configs/sk8-3.5-4000.toml``, chosen
    to close the paper's constant part of the reduced inertia, 66 798.5 kg·m². The crank
    part by hand: 2 (257 + 1373 x 0.45²) + 5200 x 0.83² = 4652.3 kg·m².

    >>> import dataclasses
    >>> from pumpjack_cli.core.beam.card import Card
    >>> from pumpjack_cli.core.dynamics.drive import drive_inertia, motor_characteristic
    >>> rpm = np.pi / 30
    >>> masses = dataclasses.replace(MassModel(*[0.0] * 18), crank_arm_mass=1373.0, crank_arm_cg=0.45,
    ...                              crank_arm_inertia=257.0, counterweight_mass=5200.0, counterweight_radius=0.83)
    >>> sk8 = Machine(Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0), masses,
    ...               drive_inertia(0.232 + 0.1, 0.5 + 40.154, 0.0, 3.6, 37.18), 37.18 * 3.6,
    ...               motor_characteristic(30e3, 1500 * rpm, 1460 * rpm, 2.0, 2.2),
    ...               CardLoad(Card(np.array([0.0]), np.array([0.0]))))
    >>> round(sk8.crank_inertia, 1), round(sk8.constant_inertia)
    (4652.3, 66798)
    >>> round(sk8.rated_crank_speed, 4)
    1.1423

    At the rated crank speed the motor gives its rated torque, 196.22 N·m x u = 26 263 N·m
    at the crank:

    >>> round(sk8.drive_torque(sk8.rated_crank_speed))
    26263
    """

    linkage: Mechanism
    masses: MassModel
    drive_inertia: float
    drive_ratio: float
    motor: MotorCharacteristic
    rod_load: RodLoad
    gravity: float = STANDARD_GRAVITY

    @property
    def crank_inertia(self) -> float:
        """Crank arms and counterweights about the shaft, 2 (J_1 + m_1 r_1^2) + m_cw r_cw^2 [kg·m²] (parallel axes)."""
        m = self.masses
        return 2.0 * (m.crank_arm_inertia + m.crank_arm_mass * m.crank_arm_cg**2) + \
            m.counterweight_mass * m.counterweight_radius**2

    @property
    def constant_inertia(self) -> float:
        """The constant part of the reduced inertia, I_0 + I_dr + m_pr r_pr^2 of [SK8Rotation2013] eq. 9 [kg·m²]."""
        return self.drive_inertia + self.crank_inertia

    @property
    def rated_crank_speed(self) -> float:
        """Crank speed at the motor's rated speed, omega_1 = omega_n / u [1/s] (:func:`.drive.rated_crank_speed`)."""
        return rated_crank_speed(self.motor.rated_speed, self.drive_ratio)

    def drive_torque(self, crank_speed: np.ndarray | float) -> np.ndarray | float:
        """Motor torque reduced to the crank, M_drive = (a + b u omega) u.

        Parameters
        ----------
        crank_speed : float or numpy.ndarray
            Crank speed [1/s].

        Returns
        -------
        float or numpy.ndarray
            M_drive [N·m].

        References
        ----------
        [SK8Rotation2013] eq. 26.
        """
        return self.motor.torque(self.drive_ratio * crank_speed) * self.drive_ratio


@dataclass(frozen=True)
class Coefficients:
    """The coefficients of the equation of motion at given crank angles (arrays).

    Attributes
    ----------
    inertia : numpy.ndarray
        Reduced moment of inertia I [kg·m²].
    inertia_rate : numpy.ndarray
        dI/dtheta [kg·m²/rad].
    gravity_torque : numpy.ndarray
        M_gravity = dV/dtheta [N·m].
    rod_load_torque : numpy.ndarray
        M_load = P TF [N·m].
    rod_load : numpy.ndarray
        P [N].
    torque_factor : numpy.ndarray
        TF = A psi' [m] ([API11E]).
    upstroke : numpy.ndarray
        Boolean mask of the upstroke.
    motion : Motion
        The four-bar motion at these angles.
    """

    inertia: np.ndarray
    inertia_rate: np.ndarray
    gravity_torque: np.ndarray
    rod_load_torque: np.ndarray
    rod_load: np.ndarray
    torque_factor: np.ndarray
    upstroke: np.ndarray
    motion: Motion


def _pitman_cg_derivatives(linkage: Mechanism, masses: MassModel, m: Motion) -> tuple[np.ndarray, np.ndarray]:
    """dS/dtheta [m/rad] and d2S/dtheta2 [m/rad²] of the pitman's centre of mass S = (1 - f) A + f B, f = AS / P.

    A the crank pin and B the equalizer bearing, their derivatives from the mechanism
    (:meth:`~pumpjack_cli.core.mechanism.Mechanism.joint_rates`). Shape (2, N) each [m/rad, m/rad^2].
    """
    f = masses.pitman_cg / linkage.pitman_length
    j = linkage.joint_rates(m)
    return (1.0 - f) * j.crank_pin_rate + f * j.equalizer_rate, (1.0 - f) * j.crank_pin_rate2 + f * j.equalizer_rate2


def reduced_inertia(linkage: Mechanism, masses: MassModel, m: Motion, rod_mass: np.ndarray | float,
                    constant: float) -> tuple[np.ndarray, np.ndarray]:
    """Reduced moment of inertia I(theta) and dI/dtheta, from the kinetic energy T = I omega^2 / 2.

        I = constant + 2 [m_2 |dS_2/dtheta|^2 + J_2 chi'^2] + I_C psi'^2 + m_rod TF^2,

    with the two pitmans (mass m_2, centroidal inertia J_2, centre S_2), the beam group
    about the centre bearing I_C = J_beam + m_beam x_beam^2 + J_head + m_head x_head^2
    + J_eq + m_eq x_eq^2 (equalizer at D, a distance |x_eq| from the centre bearing,
    turning with the beam), and m_rod the mass moving with the polished rod (TF = ds/dtheta).
    dI/dtheta differentiates each square: d(x^2)/dtheta = 2 x x'.

    Parameters
    ----------
    linkage : Mechanism
        The unit [m].
    masses : MassModel
        The moving links [kg, m, kg·m²].
    m : Motion
        The four-bar motion at the crank angles of interest.
    rod_mass : float or numpy.ndarray
        m_rod, mass moving with the polished rod [kg].
    constant : float
        Constant part: drive, crank arms and counterweights [kg·m²].

    Returns
    -------
    tuple of numpy.ndarray
        I [kg·m²] and dI/dtheta [kg·m²/rad].

    References
    ----------
    [SK8Rotation2013] eq. 9; [Artobolevsky1951] (reduction of masses).

    Examples
    --------
    A mass alone on the polished rod counts m TF^2: 1000 kg on C-114D-133-54 at 90
    degrees, where TF = 26.45 in = 0.672 m ([Guo2007]), gives about 451 kg·m².

    >>> from pumpjack_cli.core.beam.linkage import motion
    >>> inch = 0.0254
    >>> c114 = Linkage(72 * inch, 64 * inch, 24 * inch, 74.5 * inch, 64 * inch, 75 * inch)
    >>> inertia, _ = reduced_inertia(c114, MassModel(*[0.0] * 18), motion(c114, np.radians([90.0])), 1000.0, 0.0)
    >>> round(float(inertia[0]))
    451
    """
    s1, s2 = _pitman_cg_derivatives(linkage, masses, m)
    beam = (masses.beam_inertia + masses.beam_mass * masses.beam_cg**2
            + masses.horsehead_inertia + masses.horsehead_mass * masses.horsehead_cg**2
            + masses.equalizer_inertia + masses.equalizer_mass * linkage.equalizer_arm**2)
    inertia = (constant + 2.0 * (masses.pitman_mass * np.sum(s1 * s1, axis=0) + masses.pitman_inertia * m.pitman_rate**2)
               + beam * m.beam_rate**2 + rod_mass * m.torque_factor**2)
    rate = (4.0 * (masses.pitman_mass * np.sum(s1 * s2, axis=0) + masses.pitman_inertia * m.pitman_rate * m.pitman_rate2)
            + 2.0 * (beam * m.beam_rate * m.beam_rate2 + rod_mass * m.torque_factor * m.torque_factor_rate))
    return inertia, rate


def gravity_torque(linkage: Mechanism, masses: MassModel, m: Motion, gravity: float = STANDARD_GRAVITY) -> np.ndarray:
    """Gravity torque of all links reduced to the crank, M_gravity = dV/dtheta.

        V = g [2 m_1 r_1 cos theta + m_cw r_cw cos(theta + phase) + 2 m_2 y_S2
               + (m_beam x_beam + m_head x_head + m_eq x_eq) sin psi]:

    crank arms and counterweights at their radii (heights from the shaft), pitmans at
    their centres, the beam group on the beam line (equalizer at D, x_eq from the centre
    bearing towards the well: -C on a class I unit).

    Parameters
    ----------
    linkage : Mechanism
        The unit [m].
    masses : MassModel
        The moving links [kg, m, rad].
    m : Motion
        The four-bar motion at the crank angles of interest.
    gravity : float
        g [m/s²] ([BIPM2019]).

    Returns
    -------
    numpy.ndarray
        M_gravity [N·m], the torque the weights resist the crank with.

    References
    ----------
    [SK8Rotation2013] eq. 18.

    Examples
    --------
    SK8-3,5-4000 crank arms (2 x 1373 kg at 0.45 m) and counterweights (5200 kg at
    0.83 m) of [SK8Rotation2013], crank at 3 o'clock: dV/dtheta = -g (2 m_1 r_1 + m_cw r_cw)
    = -9.80665 x 5551.7 = -54 443.6 N·m.

    >>> import dataclasses
    >>> from pumpjack_cli.core.beam.linkage import motion
    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> masses = dataclasses.replace(MassModel(*[0.0] * 18), crank_arm_mass=1373.0, crank_arm_cg=0.45,
    ...                              counterweight_mass=5200.0, counterweight_radius=0.83)
    >>> round(float(gravity_torque(sk8, masses, motion(sk8, np.radians([90.0])))[0]), 1)
    -54443.6
    """
    theta = m.crank_angle
    s1, _ = _pitman_cg_derivatives(linkage, masses, m)
    beam_moment = (masses.beam_mass * masses.beam_cg + masses.horsehead_mass * masses.horsehead_cg
                   + masses.equalizer_mass * linkage.equalizer_arm)
    return gravity * (
        -2.0 * masses.crank_arm_mass * masses.crank_arm_cg * np.sin(theta)
        - masses.counterweight_mass * masses.counterweight_radius * np.sin(theta + masses.counterweight_phase)
        + 2.0 * masses.pitman_mass * s1[1]
        + beam_moment * np.cos(m.beam_angle) * m.beam_rate
    )


def coefficients(machine: Machine, crank_angle: np.ndarray, upstroke: np.ndarray) -> Coefficients:
    """All coefficients of the equation of motion at the given crank angles, one array pass.

    I and dI/dtheta (:func:`reduced_inertia`, with the rod load's mass of the stroke),
    M_gravity (:func:`gravity_torque`), P from the rod-load model, TF = A psi' and
    M_load = P TF.

    Parameters
    ----------
    machine : Machine
        The unit, its drive and its rod load (SI).
    crank_angle : numpy.ndarray
        theta [rad].
    upstroke : numpy.ndarray
        Boolean mask of the points on the upstroke.

    Returns
    -------
    Coefficients
        I [kg·m²], dI/dtheta [kg·m²/rad], torques [N·m], P [N], TF [m].

    References
    ----------
    [SK8Rotation2013] eqs. 9, 18-23; [API11E] (torque factor).
    """
    theta = np.asarray(crank_angle, dtype=float)
    up = np.asarray(upstroke, dtype=bool)
    m = machine.linkage.motion(theta)
    load = machine.rod_load
    rod_mass = np.where(up, load.mass_upstroke, load.mass_downstroke)
    inertia, rate = reduced_inertia(machine.linkage, machine.masses, m, rod_mass, machine.constant_inertia)
    tf = m.torque_factor
    force = np.asarray(load.force(theta, up), dtype=float)
    return Coefficients(
        inertia=inertia,
        inertia_rate=rate,
        gravity_torque=gravity_torque(machine.linkage, machine.masses, m, machine.gravity),
        rod_load_torque=force * tf,
        rod_load=force,
        torque_factor=tf,
        upstroke=up,
        motion=m,
    )


def mean_rod_speeds(linkage: Mechanism, crank_speed: float) -> tuple[float, float]:
    """Mean polished-rod speeds of the upstroke and the downstroke at uniform crank speed.

    v = S / t, with t = (crank travel of the stroke) / omega.

    Parameters
    ----------
    linkage : Linkage
        The four-bar [m].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    tuple of float
        Upstroke and downstroke mean speeds [m/s].

    References
    ----------
    [SK8Rotation2013] ("v_cp, mean velocity").

    Examples
    --------
    The two strokes take one revolution together, S/v_up + S/v_down = 2 pi / omega:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> up, down = mean_rod_speeds(sk8, 1.0)
    >>> round(sk8.stroke / up + sk8.stroke / down, 12) == round(2 * np.pi, 12)
    True
    """
    dead = linkage.dead_positions()
    return dead.stroke * crank_speed / dead.upstroke_crank_travel, dead.stroke * crank_speed / dead.downstroke_crank_travel
