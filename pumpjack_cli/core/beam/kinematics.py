"""Polished-rod kinematics: exact motion and the classical textbook approximations.

The exact motion comes from the unit's mechanism (:class:`~pumpjack_cli.core.mechanism.Mechanism`):
the polished-rod position s(theta) and the torque factor of [API11E] TF = ds/dtheta
(torque on the crank shaft per unit polished-rod load), so velocity v = TF omega and
acceleration a = TF' omega^2 + TF epsilon; on a beam unit the horsehead is an arc of
radius A about the centre bearing and s = A (psi - psi_bottom) ([SK8Rotation2013]: "the
speed of the suspension point equals the speed of the beam end").

The approximations are the "elementary" and "refined" theories of Soviet textbooks
([Aliverdizade1951], ref. 1 of [SK8Rotation2013]; restated in the oil-production
textbook [NUNG], eqs. 5.12-5.18), with phi the crank angle travelled from the bottom
dead position and amplitude R A/C:

* elementary (harmonic): s = R (A/C)(1 - cos phi), v = R (A/C) omega sin phi,
  a = R (A/C) omega^2 cos phi;
* refined (two-term, lambda = R/P): s = R (A/C)[(1 - cos phi) + (lambda/2) sin^2 phi],
  v = R (A/C) omega [sin phi + (lambda/2) sin 2 phi], a = R (A/C) omega^2 [cos phi + lambda cos 2 phi].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..mechanism import DeadPositions, Mechanism, Motion
from ..sampling import Extreme, crank_grid, cycle_period, extremes, uniform_time
from .geometry import Linkage  # noqa: F401 (the docstrings' examples build one)

#: Crank positions used to locate extremes, independent of the output resolution.
_DENSE_STEPS = 7200


@dataclass(frozen=True)
class RodMotion:
    """Polished-rod motion, positive upwards.

    Attributes
    ----------
    position : numpy.ndarray
        s, from the bottom of the stroke [m].
    velocity : numpy.ndarray
        v [m/s].
    acceleration : numpy.ndarray
        a [m/s²].
    """

    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray


def rod_motion(m: Motion, crank_speed: np.ndarray | float, crank_acceleration: np.ndarray | float = 0.0) -> RodMotion:
    """Exact polished-rod motion for any crank speed and acceleration.

    The chain rule on s(theta(t)):

        v = (ds/dtheta) omega = TF omega,  a = TF' omega^2 + TF epsilon.

    Parameters
    ----------
    m : Motion
        The mechanism's motion at the crank angles (position s [m], TF [m], TF' [m/rad]).
    crank_speed : float or numpy.ndarray
        Crank speed [1/s].
    crank_acceleration : float or numpy.ndarray
        Crank acceleration [1/s²]; 0 for uniform rotation.

    Returns
    -------
    RodMotion
        s [m], v [m/s], a [m/s²].

    References
    ----------
    [SK8Rotation2013] eqs. 6-8.

    Examples
    --------
    C-114D-133-54 at theta = 90 degrees: the velocity is TF omega, and [Guo2007] prints
    TF = 26.45 in there.

    >>> inch = 0.0254
    >>> c114 = Linkage(72 * inch, 64 * inch, 24 * inch, 74.5 * inch, 64 * inch, 75 * inch)
    >>> rod = rod_motion(c114.motion(np.radians([90.0])), crank_speed=1.0)
    >>> round(float(rod.velocity[0]) / inch, 2)   # in/s at 1 rad/s
    26.45
    """
    return RodMotion(
        position=m.rod_position,
        velocity=m.torque_factor * crank_speed,
        acceleration=m.torque_factor_rate * crank_speed**2 + m.torque_factor * crank_acceleration,
    )


def harmonic_motion(amplitude: float, crank_from_bottom: np.ndarray, crank_speed: float) -> RodMotion:
    """Elementary theory: simple harmonic motion of the polished rod.

        s = r_e (1 - cos phi),  v = r_e omega sin phi,  a = r_e omega^2 cos phi,

    with r_e = R A / C and phi the crank travel from the bottom dead position.

    Parameters
    ----------
    amplitude : float
        r_e = R A / C [m].
    crank_from_bottom : numpy.ndarray
        phi [rad].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    RodMotion
        s [m], v [m/s], a [m/s²].

    References
    ----------
    [NUNG] eqs. 5.16-5.18; [Aliverdizade1951].

    Examples
    --------
    >>> m = harmonic_motion(1.0, np.array([0.0, np.pi]), 2.0)
    >>> m.position.tolist(), m.acceleration.tolist()
    ([0.0, 2.0], [4.0, -4.0])
    """
    phi = np.asarray(crank_from_bottom, dtype=float)
    return RodMotion(
        position=amplitude * (1.0 - np.cos(phi)),
        velocity=amplitude * crank_speed * np.sin(phi),
        acceleration=amplitude * crank_speed**2 * np.cos(phi),
    )


def two_term_motion(amplitude: float, crank_ratio: float, crank_from_bottom: np.ndarray, crank_speed: float) -> RodMotion:
    """Refined theory: harmonic motion plus the second harmonic of a slider-crank.

        s = r_e [(1 - cos phi) + (lambda/2) sin^2 phi],
        v = r_e omega [sin phi + (lambda/2) sin 2phi],
        a = r_e omega^2 [cos phi + lambda cos 2phi],

    r_e = R A / C, lambda = R/P: the two-term series of the slider-crank.

    Parameters
    ----------
    amplitude : float
        r_e = R A / C [m].
    crank_ratio : float
        lambda = R / P (dimensionless).
    crank_from_bottom : numpy.ndarray
        phi, crank travel from the bottom dead position [rad].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    RodMotion
        s [m], v [m/s], a [m/s²].

    References
    ----------
    [NUNG] eqs. 5.12-5.13; [Aliverdizade1951].

    Examples
    --------
    At phi = 0 the acceleration is r_e omega^2 (1 + lambda), at phi = pi
    -r_e omega^2 (1 - lambda):

    >>> m = two_term_motion(1.0, 0.25, np.array([0.0, np.pi]), 1.0)
    >>> m.position.tolist(), m.acceleration.tolist()
    ([0.0, 2.0], [1.25, -0.75])
    """
    phi = np.asarray(crank_from_bottom, dtype=float)
    return RodMotion(
        position=amplitude * ((1.0 - np.cos(phi)) + 0.5 * crank_ratio * np.sin(phi) ** 2),
        velocity=amplitude * crank_speed * (np.sin(phi) + 0.5 * crank_ratio * np.sin(2.0 * phi)),
        acceleration=amplitude * crank_speed**2 * (np.cos(phi) + crank_ratio * np.cos(2.0 * phi)),
    )


def approximate_motion(method: str, mechanism: Mechanism, crank_from_bottom: np.ndarray, crank_speed: float) -> RodMotion:
    """Polished-rod motion by one of the textbook approximations of :data:`APPROXIMATIONS`.

    The amplitude is r_e = R A / C and, for ``"two_term"``, lambda = R / P
    (:func:`harmonic_motion`, :func:`two_term_motion`), the unit's
    :meth:`~pumpjack_cli.core.mechanism.Mechanism.equivalent_crank`.

    Parameters
    ----------
    method : str
        ``"harmonic"`` (elementary theory) or ``"two_term"`` (refined theory).
    mechanism : Mechanism
        The unit [m].
    crank_from_bottom : numpy.ndarray
        phi, crank travel from the bottom dead position [rad].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    RodMotion
        s [m], v [m/s], a [m/s²].

    Raises
    ------
    ValueError
        Unknown ``method``.

    References
    ----------
    [Aliverdizade1951], [NUNG] eqs. 5.12-5.18.

    Examples
    --------
    The elementary stroke of SK8-3,5-4000 is 2 R A / C = 2 x 1.01 x 3.5 / 2.5 = 2.828 m,
    against the exact 2.913 m:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> round(float(approximate_motion("harmonic", sk8, np.array([np.pi]), 1.0).position[0]), 3)
    2.828
    """
    crank = mechanism.equivalent_crank()
    if method == "harmonic":
        return harmonic_motion(crank.amplitude, crank_from_bottom, crank_speed)
    if method == "two_term":
        return two_term_motion(crank.amplitude, crank.crank_ratio, crank_from_bottom, crank_speed)
    raise ValueError(f"unknown approximation {method!r}; use one of {', '.join(APPROXIMATIONS)}")


#: Textbook approximations of the polished-rod motion, by name.
APPROXIMATIONS = ("harmonic", "two_term")


@dataclass(frozen=True)
class ApproximationError:
    """Error of an approximate law against the exact motion over one revolution.

    Attributes
    ----------
    position : float
        max |s_approx - s| / stroke (dimensionless fraction).
    velocity : float
        max |v_approx - v| / max |v| (dimensionless).
    acceleration : float
        max |a_approx - a| / max |a| (dimensionless).
    peak_acceleration : float
        max |a_approx| / max |a| - 1 (dimensionless, signed: negative means the law
        underestimates the peak; the definition of [InertiaUNB600A] at the maximum).
    """

    position: float
    velocity: float
    acceleration: float
    peak_acceleration: float


@dataclass(frozen=True)
class KinematicsSummary:
    """Scalar results of a uniform-rotation kinematics run.

    Attributes
    ----------
    crank_speed : float
        omega [1/s].
    period : float
        2 pi / omega [s].
    stroke : float
        Exact stroke [m].
    crank_angle_bottom, crank_angle_top : float
        Dead positions [rad].
    upstroke_crank_travel, downstroke_crank_travel : float
        Crank rotation during each stroke [rad].
    max_velocity, min_velocity : Extreme
        [m/s] at [rad].
    max_acceleration, min_acceleration : Extreme
        [m/s²] at [rad].
    max_torque_factor, min_torque_factor : Extreme
        TF = A psi' [m] at [rad] ([API11E]).
    approximation_errors : dict of str to ApproximationError
        By name of :data:`APPROXIMATIONS` (dimensionless fractions).
    """

    crank_speed: float
    period: float
    stroke: float
    crank_angle_bottom: float
    crank_angle_top: float
    upstroke_crank_travel: float
    downstroke_crank_travel: float
    max_velocity: Extreme
    min_velocity: Extreme
    max_acceleration: Extreme
    min_acceleration: Extreme
    max_torque_factor: Extreme
    min_torque_factor: Extreme
    approximation_errors: dict[str, ApproximationError]


@dataclass(frozen=True)
class KinematicsResult:
    """Per-crank-angle kinematics of the unit for uniform crank rotation.

    Attributes
    ----------
    crank_angle : numpy.ndarray
        theta [rad].
    time : numpy.ndarray
        theta / omega [s].
    rod : RodMotion
        Exact polished-rod motion [m, m/s, m/s²].
    torque_factor : numpy.ndarray
        TF = A psi' [m] ([API11E]).
    beam_angle, beam_angular_velocity, beam_angular_acceleration : numpy.ndarray
        psi [rad], dpsi/dt [1/s], d2psi/dt2 [1/s²].
    pitman_angle, pitman_angular_velocity, pitman_angular_acceleration : numpy.ndarray
        chi [rad], dchi/dt [1/s], d2chi/dt2 [1/s²].
    approximations : dict of str to RodMotion
        The textbook laws of :data:`APPROXIMATIONS`.
    summary : KinematicsSummary
        Extremes and errors, located on a fixed dense grid.
    """

    crank_angle: np.ndarray
    time: np.ndarray
    rod: RodMotion
    torque_factor: np.ndarray
    beam_angle: np.ndarray
    beam_angular_velocity: np.ndarray
    beam_angular_acceleration: np.ndarray
    pitman_angle: np.ndarray
    pitman_angular_velocity: np.ndarray
    pitman_angular_acceleration: np.ndarray
    approximations: dict[str, RodMotion]
    summary: KinematicsSummary


def _approximation_error(exact: RodMotion, approx: RodMotion, stroke: float) -> ApproximationError:
    peak_a = np.max(np.abs(exact.acceleration))
    return ApproximationError(
        position=float(np.max(np.abs(approx.position - exact.position)) / stroke),
        velocity=float(np.max(np.abs(approx.velocity - exact.velocity)) / np.max(np.abs(exact.velocity))),
        acceleration=float(np.max(np.abs(approx.acceleration - exact.acceleration)) / peak_a),
        peak_acceleration=float(np.max(np.abs(approx.acceleration)) / peak_a - 1.0),
    )


def _summary(linkage: Mechanism, dead: DeadPositions, crank_speed: float) -> KinematicsSummary:
    theta = crank_grid(_DENSE_STEPS)
    m = linkage.motion(theta)
    exact = rod_motion(m, crank_speed)
    stroke = dead.stroke
    from_bottom = theta - dead.crank_angle_bottom
    v_max, v_min = extremes(theta, exact.velocity)
    a_max, a_min = extremes(theta, exact.acceleration)
    tf_max, tf_min = extremes(theta, m.torque_factor)
    return KinematicsSummary(
        crank_speed=crank_speed,
        period=cycle_period(crank_speed),
        stroke=stroke,
        crank_angle_bottom=dead.crank_angle_bottom,
        crank_angle_top=dead.crank_angle_top,
        upstroke_crank_travel=dead.upstroke_crank_travel,
        downstroke_crank_travel=dead.downstroke_crank_travel,
        max_velocity=v_max,
        min_velocity=v_min,
        max_acceleration=a_max,
        min_acceleration=a_min,
        max_torque_factor=tf_max,
        min_torque_factor=tf_min,
        approximation_errors={
            name: _approximation_error(exact, approximate_motion(name, linkage, from_bottom, crank_speed), stroke)
            for name in APPROXIMATIONS
        },
    )


def uniform_kinematics(linkage: Mechanism, crank_speed: float, steps: int = 360) -> KinematicsResult:
    """Kinematics of every link for uniform crank rotation.

    One array computation over ``steps`` crank angles (see :func:`crank_grid`); time is
    measured from crank angle 0 (crank pin at 12 o'clock). Beam and pitman rates are
    dpsi/dt = psi' omega, d2psi/dt2 = psi'' omega^2 (likewise chi). The summary's extremes
    are located on a fixed dense grid of 7200 positions, so they do not depend on
    ``steps``.

    Parameters
    ----------
    linkage : Mechanism
        The unit [m].
    crank_speed : float
        Crank speed [1/s], positive.
    steps : int
        Crank positions per revolution of the output (dimensionless).

    Returns
    -------
    KinematicsResult
        Per-angle arrays and the summary (SI, angles in rad).

    Raises
    ------
    ValueError
        ``omega`` is not positive.

    References
    ----------
    [SK8Rotation2013] eqs. 2-8; [API11E] (torque factor); [Aliverdizade1951], [NUNG]
    (approximations).

    Examples
    --------
    SK8-3,5-4000 at the rated crank speed 1.1422 1/s of [SK8Rotation2013]: the cycle
    takes 2 pi / 1.1422 = 5.501 s.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> result = uniform_kinematics(sk8, 1.1422)
    >>> round(result.summary.stroke, 4), round(result.summary.period, 3)
    (2.9128, 5.501)
    """
    if not crank_speed > 0:
        raise ValueError(f"crank speed must be positive, got {crank_speed} 1/s")
    dead = linkage.dead_positions()
    theta = crank_grid(steps)
    m = linkage.motion(theta)
    rod = rod_motion(m, crank_speed)
    from_bottom = theta - dead.crank_angle_bottom
    return KinematicsResult(
        crank_angle=theta,
        time=uniform_time(theta, crank_speed),
        rod=rod,
        torque_factor=m.torque_factor,
        beam_angle=m.beam_angle,
        beam_angular_velocity=m.beam_rate * crank_speed,
        beam_angular_acceleration=m.beam_rate2 * crank_speed**2,
        pitman_angle=m.pitman_angle,
        pitman_angular_velocity=m.pitman_rate * crank_speed,
        pitman_angular_acceleration=m.pitman_rate2 * crank_speed**2,
        approximations={name: approximate_motion(name, linkage, from_bottom, crank_speed) for name in APPROXIMATIONS},
        summary=_summary(linkage, dead, crank_speed),
    )
