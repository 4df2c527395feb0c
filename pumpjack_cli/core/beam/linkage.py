"""Exact planar kinematics of a conventional (class I) beam pumping unit, for arrays of crank angles.

Geometry, conventions and dead positions are in :mod:`.geometry`. The closed form is
the cosine rule on the triangle C-A-B (the closed-vector-loop solution of
[SK8Rotation2013], eqs. 2-6, written for the beam angle directly); its first and second
derivatives with respect to the crank angle come from differentiating the loop
constraint |B - A| = P twice ([Spatial7SK12] eqs. 7-12 in planar form).
"""

from __future__ import annotations

import math

import numpy as np

from ..mechanism import ChordSliderCrank, JointRates, Motion
from .geometry import CLOCKWISE, COUNTERCLOCKWISE, DeadPositions, Linkage, assembly_angle, check_assembly, dead_positions

__all__ = ["CLOCKWISE", "COUNTERCLOCKWISE", "DeadPositions", "Linkage", "Motion", "check_assembly", "crank_pin",
           "chord_slider_crank", "dead_positions", "motion", "rod_motion", "joint_rates"]


def crank_pin(linkage: Linkage, crank_angle: np.ndarray) -> np.ndarray:
    """Position of the crank pin, A = O + R (s sin theta, cos theta), s = rotation.

    theta is measured from 12 o'clock in the direction of rotation ([API11E]).

    Parameters
    ----------
    linkage : Linkage
        The four-bar [m].
    crank_angle : numpy.ndarray
        theta, shape (N,) [rad].

    Returns
    -------
    numpy.ndarray
        A relative to the centre bearing, shape (2, N) [m].

    References
    ----------
    [API11E] (crank-angle convention).

    Examples
    --------
    SK8-3,5-4000, crank shaft at O = (-2.195, -3.0) m, R = 1.01 m, clockwise: at 12
    o'clock the pin is R above O, at 3 o'clock (90 degrees) R towards the well.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> np.round(crank_pin(sk8, np.radians([0.0, 90.0])), 6).tolist()
    [[-2.195, -1.185], [-1.99, -3.0]]
    """
    theta = np.asarray(crank_angle, dtype=float)
    o = linkage.crank_shaft
    return np.stack(
        [
            o[0] + linkage.rotation * linkage.crank_radius * np.sin(theta),
            o[1] + linkage.crank_radius * np.cos(theta),
        ]
    )


def _beam_angle(linkage: Linkage, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The beam angle psi [rad] with the crank pin at (x, y) [m]: :func:`assembly_angle` for arrays,
    to the bit, its wrap to [-pi, pi) one subtraction.

    psi = delta + arccos(...) with delta = atan2(y, x) in [-pi, pi] and the arccos in [0, pi], so
    psi + pi lies in [0, 3 pi]: (psi + pi) mod 2 pi is psi + pi itself below 2 pi and
    psi + pi - 2 pi above, a difference that is exact (the two within a factor of two, Sterbenz's
    lemma), as ``numpy.mod``, which costs ten times more, computes it.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> pin = crank_pin(sk8, np.linspace(-7.0, 7.0, 1001))
    >>> bool(np.array_equal(_beam_angle(sk8, *pin), assembly_angle(*pin, sk8.pitman, sk8.rear_arm, np)))
    True
    """
    c = linkage.rear_arm
    distance = np.hypot(x, y)
    shifted = np.arctan2(y, x) + np.arccos((linkage.pitman**2 - c**2 - distance**2) / (2.0 * c * distance)) + math.pi
    return shifted - (shifted >= 2.0 * math.pi) * (2.0 * math.pi) - math.pi


def motion(linkage: Linkage, crank_angle: np.ndarray) -> Motion:
    """Beam and pitman angles and their first two derivatives for whole arrays of crank angles.

    The beam angle psi comes from the cosine rule on C-A-B (:func:`assembly_angle`, as
    :func:`_beam_angle` computes it for arrays).
    With w = B - A the pitman vector, the constraint |w| = P differentiated once gives

        psi' = (w . A') / (w . B_psi)

    and twice

        psi'' = [w . A'' - w . B_psipsi psi'^2 - |B_psi psi' - A'|^2] / (w . B_psi),

    where B_psi = dB/dpsi, B_psipsi = -B, A' = dA/dtheta, A'' = -(A - O). The pitman
    angle follows from chi' = (w x w')/P^2 and chi'' = (w x w'')/P^2. The torque factor
    of [API11E] is TF = A psi' [m].

    Parameters
    ----------
    linkage : Linkage
        The four-bar [m].
    crank_angle : numpy.ndarray
        theta, any shape [rad].

    Returns
    -------
    Motion
        psi, chi [rad], their first derivatives (dimensionless) and second derivatives
        [1/rad]; s [m], TF [m], dTF/dtheta [m/rad]; arrays shaped like ``crank_angle``.

    Raises
    ------
    GeometryError
        The crank cannot turn (:func:`check_assembly`).

    References
    ----------
    Planar form of [Spatial7SK12] eqs. 7-12 (Bour's formula) and [SK8Rotation2013] eq. 6;
    torque factor [API11E].

    Examples
    --------
    C-114D-133-54 (A = 72, C = 64, R = 24, P = 74.5, I = 64, H - G = 116 - 41 in),
    clockwise: [Guo2007], Table 12.1, prints the torque factor 26.45 in at theta = 90
    degrees.

    >>> inch = 0.0254
    >>> c114 = Linkage(72 * inch, 64 * inch, 24 * inch, 74.5 * inch, 64 * inch, 75 * inch)
    >>> m = motion(c114, np.radians([90.0]))
    >>> round(float(m.torque_factor[0] / inch), 2)
    26.45

    At a dead position the beam stops, psi' = 0:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> bottom = sk8.dead_positions().crank_angle_bottom
    >>> bool(abs(motion(sk8, np.array([bottom])).beam_rate[0]) < 1e-12)
    True
    """
    theta = np.asarray(crank_angle, dtype=float)
    check_assembly(linkage)
    a = crank_pin(linkage, theta)
    o = linkage.crank_shaft[:, None] if a.ndim == 2 else linkage.crank_shaft
    psi = _beam_angle(linkage, a[0], a[1])
    c = linkage.rear_arm
    b = -c * np.stack([np.cos(psi), np.sin(psi)])
    b_psi = c * np.stack([np.sin(psi), -np.cos(psi)])
    a_1 = linkage.crank_radius * np.stack([linkage.rotation * np.cos(theta), -np.sin(theta)])
    a_2 = -(a - o)
    w = b - a
    w_dot_bpsi = np.sum(w * b_psi, axis=0)
    psi_1 = np.sum(w * a_1, axis=0) / w_dot_bpsi
    w_1 = b_psi * psi_1 - a_1
    psi_2 = (np.sum(w * a_2, axis=0) + np.sum(w * b, axis=0) * psi_1**2 - np.sum(w_1 * w_1, axis=0)) / w_dot_bpsi
    w_2 = -b * psi_1**2 + b_psi * psi_2 - a_2
    p2 = linkage.pitman**2
    front = linkage.front_arm
    return Motion(
        crank_angle=theta,
        rod_position=front * (psi - linkage.dead_positions().beam_angle_bottom),
        torque_factor=front * psi_1,
        torque_factor_rate=front * psi_2,
        beam_angle=psi,
        beam_rate=psi_1,
        beam_rate2=psi_2,
        pitman_angle=np.arctan2(w[1], w[0]),
        pitman_rate=(w[0] * w_1[1] - w[1] * w_1[0]) / p2,
        pitman_rate2=(w[0] * w_2[1] - w[1] * w_2[0]) / p2,
    )


def rod_motion(linkage: Linkage, crank_angle: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The polished rod's position s [m] and torque factor TF = A psi' [m] alone, as :func:`motion`
    computes them (to the bit) without the rest of the motion.

    With u = (C cos psi + A_x, C sin psi + A_y) = A - B = -w, the quotient of :func:`motion` is
    psi' = (w . A') / (w . B_psi) = (u_y R sin theta - u_x sigma R cos theta) / (u_y C cos psi - u_x C sin psi),
    sigma = rotation: the same products and sums rounded the same way (a negation is exact,
    a - (-b) is a + b, and (sigma R) x = sigma (R x) for sigma = +-1), with R sin theta,
    R cos theta, C cos psi and C sin psi each made once.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> theta = np.linspace(0.0, 6.0, 7)
    >>> s, tf = rod_motion(sk8, theta)
    >>> m = motion(sk8, theta)
    >>> bool(np.array_equal(s, m.rod_position) and np.array_equal(tf, m.torque_factor))
    True
    """
    theta = np.asarray(crank_angle, dtype=float)
    check_assembly(linkage)
    o, r, c, rotation = linkage.crank_shaft, linkage.crank_radius, linkage.rear_arm, linkage.rotation
    across, along = r * np.sin(theta), r * np.cos(theta)
    ax, ay = o[0] + rotation * across, o[1] + along
    psi = _beam_angle(linkage, ax, ay)
    cc, cs = c * np.cos(psi), c * np.sin(psi)
    ux, uy = cc + ax, cs + ay
    rate = (uy * across - ux * (rotation * along)) / (uy * cc - ux * cs)
    front = linkage.front_arm
    return front * (psi - linkage.dead_positions().beam_angle_bottom), front * rate


def joint_rates(linkage: Linkage, m: Motion) -> JointRates:
    """Crank-angle derivatives of the crank pin A and the equalizer bearing B.

    A = O + R (s sin theta, cos theta), s = rotation, so A' = R (s cos theta, -sin theta)
    and A'' = -R (s sin theta, cos theta); B = -C (cos psi, sin psi) with psi(theta) from
    :func:`motion`, so by the chain rule B' = C psi' (sin psi, -cos psi) and
    B'' = C [psi'' (sin psi, -cos psi) + psi'^2 (cos psi, sin psi)].

    Parameters
    ----------
    linkage : Linkage
        The four-bar [m].
    m : Motion
        The motion at the crank angles of interest.

    Returns
    -------
    JointRates
        dA/dtheta, d2A/dtheta2 [m/rad, m/rad²], dB/dtheta, d2B/dtheta2 [m/rad, m/rad²],
        each of shape (2, N).

    Examples
    --------
    At 90 degrees the pin of a clockwise crank moves straight down at R per radian:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> rates = joint_rates(sk8, motion(sk8, np.radians([90.0])))
    >>> np.round(rates.crank_pin_rate[:, 0], 6).tolist()
    [0.0, -1.01]
    """
    theta, psi, d1, d2 = m.crank_angle, m.beam_angle, m.beam_rate, m.beam_rate2
    r, c, s = linkage.crank_radius, linkage.rear_arm, linkage.rotation
    across = np.stack([np.sin(psi), -np.cos(psi)])
    along = np.stack([np.cos(psi), np.sin(psi)])
    return JointRates(r * np.stack([s * np.cos(theta), -np.sin(theta)]), -r * np.stack([s * np.sin(theta), np.cos(theta)]),
                      c * d1 * across, c * (d2 * across + d1**2 * along))


def chord_slider_crank(linkage: Linkage) -> ChordSliderCrank:
    """The offset slider-crank of the chord law.

    The chord runs through the equalizer-bearing positions B_bottom and B_top of the two
    dead positions (|OB| = P + R and P - R). Its axis n is the chord direction signed so
    that (B_bottom - O) . n > 0 (the slider-crank branch with the rod pointing along n).
    The crank pin direction in the frame is pi/2 - rotation * theta (theta: the unit's
    crank angle from 12 o'clock, :mod:`pumpjack_cli.core.beam.linkage`), so in the chord
    frame it is gamma = pi/2 - rotation * theta - angle(n); mirroring the frame across n
    by m = -rotation makes phi = m gamma = phase + theta grow with time, with the offset
    e = m (B_bottom - O) . n_perp.

    Parameters
    ----------
    linkage : Linkage
        The four-bar [m].

    Returns
    -------
    ChordSliderCrank
        The :class:`SliderCrank` with r = R, l = P and the offset e [m]; the phase [rad],
        with phi = phase + theta; the scale d A / C, d = +1 if n points from B_bottom to
        B_top (the polished rod rises as B moves along n), else -1 (dimensionless).

    References
    ----------
    [InertiaUNB600A] eq. 7 (the assumption; the formula is reconstructed here).

    Examples
    --------
    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> chord = chord_slider_crank(sk8)
    >>> chord.slider.crank_radius, chord.slider.rod_length, abs(chord.scale)   # R and P of the unit, A/C
    (1.01, 3.0, 1.4)
    """
    from ..slider_crank.geometry import SliderCrank

    dead = linkage.dead_positions()
    o = linkage.crank_shaft
    b_bottom, b_top = (-linkage.rear_arm * np.array([np.cos(psi), np.sin(psi)])
                       for psi in (dead.beam_angle_bottom, dead.beam_angle_top))
    chord = (b_top - b_bottom) / np.hypot(*(b_top - b_bottom))
    direction = 1.0 if np.dot(b_bottom - o, chord) > 0 else -1.0
    axis = direction * chord
    across = np.array([-axis[1], axis[0]])
    mirror = -linkage.rotation
    axis_angle = float(np.arctan2(axis[1], axis[0]))
    offset = mirror * float(np.dot(b_bottom - o, across))
    phase = mirror * (0.5 * np.pi - axis_angle)
    return ChordSliderCrank(SliderCrank(linkage.crank_radius, linkage.pitman, offset), phase,
                            direction * linkage.front_arm / linkage.rear_arm)
