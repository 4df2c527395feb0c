"""Exact planar kinematics of a conventional (class I) beam pumping unit.

The four-bar O-A-B-C: crank OA (radius R, API letter R; GOST r), pitman AB (P; l),
rear arm of the walking beam CB (C; k), frame OC from the crank shaft O to the centre
(saddle) bearing C (K; horizontal part I = l1, vertical part H - G = l2). The front
arm (A; k1) carries the horsehead, an arc of radius A about C from which the polished
rod hangs, so the polished rod moves by exactly A times the beam rotation.

Frame and conventions (used everywhere in the package):

* origin at the centre bearing C, x horizontal towards the well, y vertically up;
  the well is to the right and the crank shaft O = (-I, -(H - G)) is behind and
  below the centre bearing (API Spec 11E, 19th ed., fig. 1, conventional unit);
* crank angle theta is measured from the 12 o'clock position of the crank pin in the
  direction of rotation, as API Spec 11E does; rotation is *clockwise* or
  *counterclockwise* as seen with the well to the right;
* beam angle psi is the angle of the front arm above the horizontal;
* pitman angle chi is the direction of the vector A->B above the horizontal.

The closed form is the cosine rule on the triangle C-A-B (the closed-vector-loop
solution of seed 004, eqs. 2-6, written for the beam angle directly), its first and
second derivatives with respect to the crank angle come from differentiating the
loop constraint |B - A| = P twice (seed 000 eqs. 7-12 in planar form).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import GeometryError

CLOCKWISE = 1
COUNTERCLOCKWISE = -1


@dataclass(frozen=True)
class Linkage:
    """Geometry of the four-bar of a conventional pumping unit, SI.

    Parameters
    ----------
    front_arm : A, k1 [m], centre bearing to horsehead arc.
    rear_arm : C, k [m], centre bearing to equalizer bearing.
    crank_radius : R, r [m], crank shaft to crank pin.
    pitman : P, l [m], crank pin to equalizer bearing.
    horizontal_offset : I, l1 [m], horizontal distance crank shaft - centre bearing.
    vertical_offset : H - G, l2 [m], height of the centre bearing above the crank shaft.
    rotation : +1 clockwise, -1 counterclockwise, seen with the well to the right.
    """

    front_arm: float
    rear_arm: float
    crank_radius: float
    pitman: float
    horizontal_offset: float
    vertical_offset: float
    rotation: int = CLOCKWISE

    @property
    def crank_shaft(self) -> np.ndarray:
        """Position of the crank shaft O relative to the centre bearing [m]."""
        return np.array([-self.horizontal_offset, -self.vertical_offset])

    @property
    def frame_length(self) -> float:
        """K [m]: distance crank shaft - centre bearing (API Spec 11E letter K)."""
        return float(np.hypot(self.horizontal_offset, self.vertical_offset))


@dataclass(frozen=True)
class Motion:
    """Angles of the beam and pitman and their derivatives with respect to crank angle.

    All arrays share the shape of the crank angles they were computed for.
    ``beam_rate`` is dpsi/dtheta (the first transfer function of seed 004 eq. 6),
    ``beam_rate2`` is d2psi/dtheta2; likewise for the pitman angle chi. Angles in rad.
    """

    crank_angle: np.ndarray
    beam_angle: np.ndarray
    beam_rate: np.ndarray
    beam_rate2: np.ndarray
    pitman_angle: np.ndarray
    pitman_rate: np.ndarray
    pitman_rate2: np.ndarray


@dataclass(frozen=True)
class DeadPositions:
    """Crank and beam angles at the bottom and top of the stroke [rad].

    The beam stops when crank and pitman are in one line: stretched out (|OB| = P + R)
    or folded (|OB| = P - R). For a conventional unit the stretched position is the
    bottom of the stroke (seed 004: "crank and pitman stretched in one line").
    """

    crank_angle_bottom: float
    crank_angle_top: float
    beam_angle_bottom: float
    beam_angle_top: float


def check_assembly(linkage: Linkage) -> None:
    """Raise :class:`GeometryError` unless the crank turns through a full revolution.

    The crank pin's distance from the centre bearing runs over [K - R, K + R]; the
    pitman and rear arm reach it at every crank angle only if (Grashof crank-rocker
    condition, strict so that the unit never locks in a toggle)
    K + R < P + C and K - R > |P - C|.
    """
    lengths = {
        "front_arm": linkage.front_arm,
        "rear_arm": linkage.rear_arm,
        "crank_radius": linkage.crank_radius,
        "pitman": linkage.pitman,
        "horizontal_offset": linkage.horizontal_offset,
        "vertical_offset": linkage.vertical_offset,
    }
    for name, value in lengths.items():
        if not np.isfinite(value):
            raise GeometryError(f"{name} must be a finite length, got {value}")
        if name not in ("horizontal_offset", "vertical_offset") and not value > 0:
            raise GeometryError(f"{name} must be positive, got {value} m")
    k, r, p, c = linkage.frame_length, linkage.crank_radius, linkage.pitman, linkage.rear_arm
    if k + r >= p + c:
        raise GeometryError(
            f"the unit cannot assemble: with the crank pin farthest from the centre bearing "
            f"(K + R = {k:.4g} + {r:.4g} = {k + r:.4g} m) the pitman and rear arm "
            f"(P + C = {p:.4g} + {c:.4g} = {p + c:.4g} m) cannot reach it; "
            f"crank_radius or the offsets are too large, or pitman/rear_arm too short"
        )
    if k - r <= abs(p - c):
        raise GeometryError(
            f"the unit cannot assemble: with the crank pin nearest the centre bearing "
            f"(K - R = {k:.4g} - {r:.4g} = {k - r:.4g} m) the pitman and rear arm "
            f"(|P - C| = |{p:.4g} - {c:.4g}| = {abs(p - c):.4g} m) fold past each other; "
            f"crank_radius is too large or the offsets too small for this pitman/rear_arm"
        )


def _assembly_angle(point: np.ndarray, reach: np.ndarray | float, rear_arm: float) -> np.ndarray:
    """Beam angle psi that puts the rear-arm end B = -C e(psi) at distance ``reach`` from ``point``.

    Cosine rule: |B - X|^2 = C^2 + |X|^2 + 2 C |X| cos(psi - delta), delta = angle of X.
    The assembly branch keeps B on the side where (X x B)_z < 0, i.e. the equalizer
    bearing above and behind the crank pin as in every conventional unit; this branch
    cannot change during motion without passing a toggle, which :func:`check_assembly`
    excludes.
    """
    distance = np.hypot(point[0], point[1])
    delta = np.arctan2(point[1], point[0])
    cos_gamma = (reach**2 - rear_arm**2 - distance**2) / (2.0 * rear_arm * distance)
    psi = delta + np.arccos(cos_gamma)
    return (psi + np.pi) % (2.0 * np.pi) - np.pi


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
    Source: planar form of seed 000 eqs. 7-12 (Bour's formula) and seed 004 eq. 6.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> m = motion(sk8, np.radians([0.0, 90.0]))
    >>> bool(m.beam_rate[1] > 0)   # crank at 3 o'clock: polished rod rising
    True
    """
    theta = np.asarray(crank_angle, dtype=float)
    check_assembly(linkage)
    a = crank_pin(linkage, theta)
    o = linkage.crank_shaft[:, None] if a.ndim == 2 else linkage.crank_shaft
    psi = _assembly_angle(a, linkage.pitman, linkage.rear_arm)
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


def dead_positions(linkage: Linkage) -> DeadPositions:
    """Exact crank and beam angles at the ends of the stroke.

    At a dead position O, A and B are collinear, so B is at distance P + R (stretched)
    or P - R (folded) from O; the beam angle follows from the same cosine rule as
    :func:`motion` applied to the triangle C-O-B, and the crank pin lies on the line
    OB (stretched: A = O + R u, folded: A = O - R u, u the unit vector O->B).
    """
    check_assembly(linkage)
    o = linkage.crank_shaft
    result = {}
    for label, reach, side in (("stretched", linkage.pitman + linkage.crank_radius, 1.0),
                               ("folded", linkage.pitman - linkage.crank_radius, -1.0)):
        psi = float(_assembly_angle(o, reach, linkage.rear_arm))
        b = -linkage.rear_arm * np.array([np.cos(psi), np.sin(psi)])
        pin = side * (b - o) / np.hypot(*(b - o))
        theta = float(np.arctan2(linkage.rotation * pin[0], pin[1]) % (2.0 * np.pi))
        result[label] = (theta, psi)
    (theta_s, psi_s), (theta_f, psi_f) = result["stretched"], result["folded"]
    if psi_s < psi_f:
        return DeadPositions(theta_s, theta_f, psi_s, psi_f)
    return DeadPositions(theta_f, theta_s, psi_f, psi_s)
