"""Spatial kinematics of the six-link lever mechanism (seed 000 eqs. 5-16).

Links (seed numbering): 1 double crank (arms OA and O1A1 on one shaft), 2 and 3
pitmans AB and A1B1, 4 equalizer B-D-B1, 5 walking beam with horsehead, 0 frame.
Frame: origin at the centre bearing C, x towards the well, y up, z along the crank
shaft (x, y, z right-handed); the beam moves in the plane z = 0. Pitman 2 is on the
+z side: crank pin A at z = +b (``crank_half_spacing``), equalizer pin B at z = +e
(``equalizer_half_length``); pitman 3 mirrors it at -z. The pin line B-B1 passes
through the equalizer bearing D, the rear-arm end of the beam.

With both sides equal the two pitmans move in mirror planes, so positions follow from
the planar closed form of :mod:`pumpjack_cli.core.linkage` applied to the projection
of the pitman on the beam plane, P_xy = sqrt(P^2 - (b - e)^2).

Angular velocities and accelerations come from the two closed vector loops
(seed 000 eqs. 5-6) differentiated with Bour's formula dl/dt = w x l:
``w1 x l1 + w2 x l2 + w4 x l4 + w5 x l5 = 0`` and
``w1 x l11 + w3 x l3 + w4 x l41 + w5 x l5 = 0`` (eqs. 7-10), and once more for the
accelerations (eqs. 11-12). Unknowns per crank angle: w2, w3 (3 each), the
equalizer's rotation relative to the beam d4 = w4 - w5 (3) and w5z (1): ten unknowns
for six loop equations. The rational mechanism has four idle freedoms (seed 000): the
spin of each pitman about its own axis, fixed here by w2 . e2 = 0 and w3 . e3 = 0,
and two rotations of the equalizer relative to the beam (about its pin line, and
about an axis along the pitmans). Those two are fixed by taking the minimum-norm
solution in d4, i.e. no idle relative motion: the 8 x 10 system is solved as
x = K^T (K K^T)^-1 b, one batched 8 x 8 inversion for the whole revolution, shared
by the velocity and the acceleration problem (same matrix).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .linkage import Linkage, motion

Z = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class SpatialLinkage:
    """The planar four-bar plus the spatial spacing of the two sides [m].

    ``planar`` holds the projected pitman length; :attr:`pitman` is the true one.
    """

    planar: Linkage
    crank_half_spacing: float
    equalizer_half_length: float

    @property
    def pitman(self) -> float:
        """True pitman length P [m] (the planar linkage holds its projection)."""
        return float(np.hypot(self.planar.pitman, self.crank_half_spacing - self.equalizer_half_length))

    @property
    def crank_spin(self) -> np.ndarray:
        """Unit vector of the crank angular velocity: clockwise seen from +z is -z."""
        return -self.planar.rotation * Z


@dataclass(frozen=True)
class SpatialMotion:
    """Points [m] (arrays (N, 3)) and link angular velocities [1/s] and accelerations [1/s^2].

    ``omega1``/``epsilon1`` are the crank's scalar speed and acceleration in the
    direction of rotation; the vectors ``w1``, ``e1`` point along the shaft.
    """

    crank_angle: np.ndarray
    omega1: np.ndarray
    epsilon1: np.ndarray
    crank_shaft: np.ndarray
    pin_a: np.ndarray
    pin_a1: np.ndarray
    pin_b: np.ndarray
    pin_b1: np.ndarray
    pin_d: np.ndarray
    beam_angle: np.ndarray
    w1: np.ndarray
    w2: np.ndarray
    w3: np.ndarray
    w4: np.ndarray
    w5: np.ndarray
    e1: np.ndarray
    e2: np.ndarray
    e3: np.ndarray
    e4: np.ndarray
    e5: np.ndarray


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a x b over the last axis (length 3); np.cross without its per-call overhead."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def _skew(v: np.ndarray) -> np.ndarray:
    """Cross-product matrices [v]x, shape (..., 3, 3), so that [v]x @ u = v x u."""
    out = np.zeros(v.shape[:-1] + (3, 3))
    out[..., 0, 1], out[..., 0, 2] = -v[..., 2], v[..., 1]
    out[..., 1, 0], out[..., 1, 2] = v[..., 2], -v[..., 0]
    out[..., 2, 0], out[..., 2, 1] = -v[..., 1], v[..., 0]
    return out


def _loop_matrix(l2: np.ndarray, l3: np.ndarray, l4: np.ndarray, l41: np.ndarray, l5: np.ndarray) -> np.ndarray:
    """The 8 x 10 coefficient matrix of (w2, w3, d4, w5z) for every crank angle.

    Rows 0-2: loop O-A-B-D-C; rows 3-5: loop O1-A1-B1-D-C; w x l = -[l]x w.
    Rows 6-7: no pitman spin, w2 . l2 = 0 and w3 . l3 = 0.
    """
    n = l2.shape[0]
    k = np.zeros((n, 8, 10))
    k[:, 0:3, 0:3] = -_skew(l2)
    k[:, 0:3, 6:9] = -_skew(l4)
    k[:, 0:3, 9] = cross(Z, l4 + l5)
    k[:, 3:6, 3:6] = -_skew(l3)
    k[:, 3:6, 6:9] = -_skew(l41)
    k[:, 3:6, 9] = cross(Z, l41 + l5)
    k[:, 6, 0:3] = l2
    k[:, 7, 3:6] = l3
    return k


def _min_norm_inverse(k: np.ndarray) -> np.ndarray:
    """K^+ = K^T (K K^T)^-1 for a stack of full-row-rank K (N, 8, 10): x = K^+ b is the
    minimum-norm solution of K x = b."""
    kt = np.swapaxes(k, 1, 2)
    return kt @ np.linalg.inv(k @ kt)


def spatial_motion(
    spatial: SpatialLinkage, crank_angle: np.ndarray, omega1: np.ndarray | float, epsilon1: np.ndarray | float = 0.0
) -> SpatialMotion:
    """Positions, angular velocities and accelerations of every link, whole revolution at once.

    ``omega1`` [1/s] and ``epsilon1`` [1/s^2] are the crank speed and acceleration in
    the direction of rotation (scalars or arrays like ``crank_angle``).
    """
    theta = np.asarray(crank_angle, dtype=float)
    n = theta.size
    omega1 = np.broadcast_to(np.asarray(omega1, dtype=float), (n,))
    epsilon1 = np.broadcast_to(np.asarray(epsilon1, dtype=float), (n,))
    planar = motion(spatial.planar, theta)
    b, e = spatial.crank_half_spacing, spatial.equalizer_half_length
    zeros = np.zeros(n)

    def lift(xy: np.ndarray, z: float) -> np.ndarray:
        return np.stack([xy[0], xy[1], np.full(n, z)], axis=-1)

    linkage = spatial.planar
    o = np.broadcast_to(np.array([*linkage.crank_shaft, 0.0]), (n, 3))
    pin_xy = np.stack(
        [linkage.crank_shaft[0] + linkage.rotation * linkage.crank_radius * np.sin(theta),
         linkage.crank_shaft[1] + linkage.crank_radius * np.cos(theta)]
    )
    d_xy = -linkage.rear_arm * np.stack([np.cos(planar.beam_angle), np.sin(planar.beam_angle)])
    a, a1 = lift(pin_xy, b), lift(pin_xy, -b)
    pb, pb1, d = lift(d_xy, e), lift(d_xy, -e), lift(d_xy, 0.0)
    l1, l11 = a - o - b * Z, a1 - o + b * Z
    l2, l3 = pb - a, pb1 - a1
    l4, l41 = d - pb, d - pb1
    l5 = -d
    spin = spatial.crank_spin
    w1 = omega1[:, None] * spin
    e1 = epsilon1[:, None] * spin
    k_plus = _min_norm_inverse(_loop_matrix(l2, l3, l4, l41, l5))

    rhs_v = np.concatenate([-cross(w1, l1), -cross(w1, l11), np.zeros((n, 2))], axis=1)
    x = (k_plus @ rhs_v[..., None])[..., 0]
    w2, w3, d4 = x[:, 0:3], x[:, 3:6], x[:, 6:9]
    w5 = np.stack([zeros, zeros, x[:, 9]], axis=-1)
    w4 = w5 + d4

    def centripetal(w: np.ndarray, vec: np.ndarray) -> np.ndarray:
        return cross(w, cross(w, vec))

    # Second derivative of each loop: sum(eps x l + w x (w x l)) = 0 (seed 000 eqs. 11-12).
    # With w4 = w5 + d4, eps4 = eps5 + dd4, where dd4 = d(d4)/dt; the w5z column of
    # the matrix multiplies eps5z, the d4 columns multiply dd4.
    loop1 = cross(e1, l1) + centripetal(w1, l1) + centripetal(w2, l2) + centripetal(w4, l4) + centripetal(w5, l5)
    loop2 = cross(e1, l11) + centripetal(w1, l11) + centripetal(w3, l3) + centripetal(w4, l41) + centripetal(w5, l5)
    rhs_a = np.concatenate([-loop1, -loop2, np.zeros((n, 2))], axis=1)
    y = (k_plus @ rhs_a[..., None])[..., 0]
    e5 = np.stack([zeros, zeros, y[:, 9]], axis=-1)
    return SpatialMotion(
        crank_angle=theta,
        omega1=omega1,
        epsilon1=epsilon1,
        crank_shaft=o,
        pin_a=a,
        pin_a1=a1,
        pin_b=pb,
        pin_b1=pb1,
        pin_d=d,
        beam_angle=planar.beam_angle,
        w1=w1,
        w2=w2,
        w3=w3,
        w4=w4,
        w5=w5,
        e1=e1,
        e2=y[:, 0:3],
        e3=y[:, 3:6],
        e4=e5 + y[:, 6:9],
        e5=e5,
    )
