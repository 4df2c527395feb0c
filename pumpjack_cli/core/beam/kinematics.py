"""Polished-rod kinematics: exact motion and the classical textbook approximations.

The exact motion comes from :mod:`pumpjack_cli.core.linkage`. The horsehead is an arc
of radius A about the centre bearing, so the polished rod moves by A times the beam
rotation (seed 004: "the speed of the suspension point equals the speed of the beam
end"): position s = A (psi - psi_bottom), velocity v = A psi' omega,
acceleration a = A (psi'' omega^2 + psi' epsilon), and the API Spec 11E torque factor
TF = ds/dtheta = A psi' (torque on the crank shaft per unit polished-rod load).

The approximations are the "elementary" and "refined" theories of Soviet textbooks
(Aliverdizade 1951, ref. [1] of seed 004; restated in the NUNG oil-production
textbook, eqs. 5.12-5.18), with phi the crank angle travelled from the bottom dead
position and amplitude R A/C:

* elementary (harmonic): s = R (A/C)(1 - cos phi), v = R (A/C) omega sin phi,
  a = R (A/C) omega^2 cos phi;
* refined (two-term, lambda = R/P): s = R (A/C)[(1 - cos phi) + (lambda/2) sin^2 phi],
  v = R (A/C) omega [sin phi + (lambda/2) sin 2 phi], a = R (A/C) omega^2 [cos phi + lambda cos 2 phi].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..sampling import Extreme, crank_grid, cycle_period, extremes, uniform_time
from .linkage import DeadPositions, Linkage, dead_positions, motion

#: Crank positions used to locate extremes, independent of the output resolution.
_DENSE_STEPS = 7200


@dataclass(frozen=True)
class RodMotion:
    """Polished-rod position [m] from the bottom of the stroke, velocity [m/s],
    acceleration [m/s^2] (positive upwards)."""

    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray


def rod_motion(
    linkage: Linkage, beam_angle: np.ndarray, beam_rate: np.ndarray, beam_rate2: np.ndarray,
    beam_angle_bottom: float, omega: np.ndarray | float, epsilon: np.ndarray | float = 0.0,
) -> RodMotion:
    """Exact polished-rod motion for crank speed ``omega`` [1/s] and acceleration ``epsilon`` [1/s^2].

    s = A (psi - psi_bottom); v = A psi' omega; a = A (psi'' omega^2 + psi' epsilon)
    (chain rule on s(theta(t)); seed 004 eqs. 6-8).
    """
    a = linkage.front_arm
    return RodMotion(
        position=a * (beam_angle - beam_angle_bottom),
        velocity=a * beam_rate * omega,
        acceleration=a * (beam_rate2 * omega**2 + beam_rate * epsilon),
    )


def harmonic_motion(amplitude: float, crank_from_bottom: np.ndarray, omega: float) -> RodMotion:
    """Elementary theory: simple harmonic motion of the polished rod.

    s = r_e (1 - cos phi), v = r_e omega sin phi, a = r_e omega^2 cos phi, with
    r_e = R A / C [m] and phi [rad] the crank travel from the bottom dead position
    (NUNG textbook eqs. 5.16-5.18).

    >>> m = harmonic_motion(1.0, np.array([0.0, np.pi]), 2.0)
    >>> m.position.tolist(), m.acceleration.tolist()
    ([0.0, 2.0], [4.0, -4.0])
    """
    phi = np.asarray(crank_from_bottom, dtype=float)
    return RodMotion(
        position=amplitude * (1.0 - np.cos(phi)),
        velocity=amplitude * omega * np.sin(phi),
        acceleration=amplitude * omega**2 * np.cos(phi),
    )


def two_term_motion(amplitude: float, crank_ratio: float, crank_from_bottom: np.ndarray, omega: float) -> RodMotion:
    """Refined theory: harmonic motion plus the second harmonic of a slider-crank.

    s = r_e [(1 - cos phi) + (lambda/2) sin^2 phi], v = r_e omega [sin phi + (lambda/2) sin 2phi],
    a = r_e omega^2 [cos phi + lambda cos 2phi], r_e = R A / C [m], lambda = R/P
    (NUNG textbook eqs. 5.12-5.13; the two-term series of the slider-crank).

    >>> m = two_term_motion(1.0, 0.25, np.array([0.0, np.pi]), 1.0)
    >>> m.position.tolist(), m.acceleration.tolist()
    ([0.0, 2.0], [1.25, -0.75])
    """
    phi = np.asarray(crank_from_bottom, dtype=float)
    return RodMotion(
        position=amplitude * ((1.0 - np.cos(phi)) + 0.5 * crank_ratio * np.sin(phi) ** 2),
        velocity=amplitude * omega * (np.sin(phi) + 0.5 * crank_ratio * np.sin(2.0 * phi)),
        acceleration=amplitude * omega**2 * (np.cos(phi) + crank_ratio * np.cos(2.0 * phi)),
    )


def approximate_motion(method: str, linkage: Linkage, crank_from_bottom: np.ndarray, omega: float) -> RodMotion:
    """Polished-rod motion by one of :data:`APPROXIMATIONS` (``"harmonic"``, ``"two_term"``)."""
    amplitude = linkage.crank_radius * linkage.front_arm / linkage.rear_arm
    if method == "harmonic":
        return harmonic_motion(amplitude, crank_from_bottom, omega)
    if method == "two_term":
        return two_term_motion(amplitude, linkage.crank_radius / linkage.pitman, crank_from_bottom, omega)
    raise ValueError(f"unknown approximation {method!r}; use one of {', '.join(APPROXIMATIONS)}")


#: Textbook approximations of the polished-rod motion, by name.
APPROXIMATIONS = ("harmonic", "two_term")


@dataclass(frozen=True)
class ApproximationError:
    """Error of an approximate law against the exact motion, as fractions.

    position: max |s_approx - s| / stroke; velocity: max |v_approx - v| / max |v|;
    acceleration: max |a_approx - a| / max |a|; peak_acceleration:
    max |a_approx| / max |a| - 1 (signed: negative means the law underestimates).
    """

    position: float
    velocity: float
    acceleration: float
    peak_acceleration: float


@dataclass(frozen=True)
class KinematicsSummary:
    """Scalar results of a uniform-rotation kinematics run (SI, angles in rad)."""

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
    """Per-crank-angle kinematics of the unit for uniform crank rotation (SI, rad)."""

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


def _summary(linkage: Linkage, dead: DeadPositions, omega: float) -> KinematicsSummary:
    theta = crank_grid(_DENSE_STEPS)
    m = linkage.motion(theta)
    exact = rod_motion(linkage, m.beam_angle, m.beam_rate, m.beam_rate2, dead.beam_angle_bottom, omega)
    stroke = dead.stroke
    from_bottom = theta - dead.crank_angle_bottom
    v_max, v_min = extremes(theta, exact.velocity)
    a_max, a_min = extremes(theta, exact.acceleration)
    tf_max, tf_min = extremes(theta, linkage.front_arm * m.beam_rate)
    return KinematicsSummary(
        crank_speed=omega,
        period=cycle_period(omega),
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
            name: _approximation_error(exact, approximate_motion(name, linkage, from_bottom, omega), stroke)
            for name in APPROXIMATIONS
        },
    )


def uniform_kinematics(linkage: Linkage, omega: float, steps: int = 360) -> KinematicsResult:
    """Kinematics of every link for uniform crank rotation at ``omega`` [1/s].

    One array computation over ``steps`` crank angles (see :func:`crank_grid`); time is
    measured from crank angle 0 (crank pin at 12 o'clock). The summary's extremes are
    located on a fixed dense grid, so they do not depend on ``steps``.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> round(uniform_kinematics(sk8, 1.1422).summary.stroke, 4)
    2.9128
    """
    if not omega > 0:
        raise ValueError(f"crank speed must be positive, got {omega} 1/s")
    dead = linkage.dead_positions()
    theta = crank_grid(steps)
    m = linkage.motion(theta)
    rod = rod_motion(linkage, m.beam_angle, m.beam_rate, m.beam_rate2, dead.beam_angle_bottom, omega)
    from_bottom = theta - dead.crank_angle_bottom
    return KinematicsResult(
        crank_angle=theta,
        time=uniform_time(theta, omega),
        rod=rod,
        torque_factor=linkage.front_arm * m.beam_rate,
        beam_angle=m.beam_angle,
        beam_angular_velocity=m.beam_rate * omega,
        beam_angular_acceleration=m.beam_rate2 * omega**2,
        pitman_angle=m.pitman_angle,
        pitman_angular_velocity=m.pitman_rate * omega,
        pitman_angular_acceleration=m.pitman_rate2 * omega**2,
        approximations={name: approximate_motion(name, linkage, from_bottom, omega) for name in APPROXIMATIONS},
        summary=_summary(linkage, dead, omega),
    )
