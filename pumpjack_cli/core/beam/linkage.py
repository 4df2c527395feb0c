"""Exact planar kinematics of a conventional (class I) beam pumping unit, for arrays of crank angles.

Geometry, conventions and dead positions are in :mod:`.geometry`. The closed form is
the cosine rule on the triangle C-A-B (the closed-vector-loop solution of
[SK8Rotation2013], eqs. 2-6, written for the beam angle directly); its first and second
derivatives with respect to the crank angle come from differentiating the loop
constraint |B - A| = P twice ([Spatial7SK12] eqs. 7-12 in planar form).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .geometry import CLOCKWISE, COUNTERCLOCKWISE, DeadPositions, Linkage, assembly_angle, check_assembly, dead_positions

__all__ = ["CLOCKWISE", "COUNTERCLOCKWISE", "DeadPositions", "Linkage", "Motion", "check_assembly", "crank_pin",
           "dead_positions", "motion", "pin_rates"]


@dataclass(frozen=True)
class Motion:
    """Angles of the beam and pitman and their derivatives with respect to crank angle.

    All arrays share the shape of the crank angles they were computed for.
    ``beam_rate`` is dpsi/dtheta (the first transfer function of [SK8Rotation2013] eq. 6),
    ``beam_rate2`` is d2psi/dtheta2; likewise for the pitman angle chi. Angles in rad.
    """

    crank_angle: np.ndarray
    beam_angle: np.ndarray
    beam_rate: np.ndarray
    beam_rate2: np.ndarray
    pitman_angle: np.ndarray
    pitman_rate: np.ndarray
    pitman_rate2: np.ndarray


def crank_pin(linkage: Linkage, crank_angle: np.ndarray) -> np.ndarray:
    """Crank pin A, shape (2, N) [m]: A = O + R (s sin theta, cos theta), s = rotation."""
    theta = np.asarray(crank_angle, dtype=float)
    o = linkage.crank_shaft
    return np.stack(
        [
            o[0] + linkage.rotation * linkage.crank_radius * np.sin(theta),
            o[1] + linkage.crank_radius * np.cos(theta),
        ]
    )


def motion(linkage: Linkage, crank_angle: np.ndarray) -> Motion:
    """Beam and pitman angles and their first two derivatives for whole arrays of crank angles.

    With w = B - A the pitman vector, the constraint |w| = P differentiated once gives
    psi' = (w . A') / (w . B_psi) and twice
    psi'' = [w . A'' - w . B_psipsi psi'^2 - |B_psi psi' - A'|^2] / (w . B_psi),
    where B_psi = dB/dpsi, B_psipsi = -B, A' = dA/dtheta, A'' = -(A - O). The pitman
    angle follows from chi' = (w x w')/P^2 and chi'' = (w x w'')/P^2.

    References
    ----------
    Planar form of [Spatial7SK12] eqs. 7-12 (Bour's formula) and [SK8Rotation2013] eq. 6.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> m = motion(sk8, np.radians([0.0, 90.0]))
    >>> bool(m.beam_rate[1] > 0)   # crank at 3 o'clock: polished rod rising
    True
    """
    theta = np.asarray(crank_angle, dtype=float)
    check_assembly(linkage)
    a = crank_pin(linkage, theta)
    o = linkage.crank_shaft[:, None] if a.ndim == 2 else linkage.crank_shaft
    psi = assembly_angle(a[0], a[1], linkage.pitman, linkage.rear_arm, np)
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
    return Motion(
        crank_angle=theta,
        beam_angle=psi,
        beam_rate=psi_1,
        beam_rate2=psi_2,
        pitman_angle=np.arctan2(w[1], w[0]),
        pitman_rate=(w[0] * w_1[1] - w[1] * w_1[0]) / p2,
        pitman_rate2=(w[0] * w_2[1] - w[1] * w_2[0]) / p2,
    )




def pin_rates(linkage: Linkage, m: Motion) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """dA/dtheta, d2A/dtheta2, dB/dtheta, d2B/dtheta2 of the crank pin A and the equalizer bearing B.

    A = O + R (s sin theta, cos theta), s = rotation; B = -C (cos psi, sin psi) with
    psi(theta) from :func:`motion` (chain rule). Shape (2, N) each [m/rad, m/rad^2].
    """
    theta, psi, d1, d2 = m.crank_angle, m.beam_angle, m.beam_rate, m.beam_rate2
    r, c, s = linkage.crank_radius, linkage.rear_arm, linkage.rotation
    across = np.stack([np.sin(psi), -np.cos(psi)])
    along = np.stack([np.cos(psi), np.sin(psi)])
    return (r * np.stack([s * np.cos(theta), -np.sin(theta)]), -r * np.stack([s * np.sin(theta), np.cos(theta)]),
            c * d1 * across, c * (d2 * across + d1**2 * along))
