"""Spatial kinematics of the six-link lever mechanism ([Spatial7SK12] eqs. 5-16).

Links (numbered as in [Spatial7SK12]): 1 double crank (arms OA and O1A1 on one shaft), 2 and 3
pitmans AB and A1B1, 4 equalizer B-D-B1, 5 walking beam with horsehead, 0 frame.
Frame: origin at the centre bearing C, x towards the well, y up, z along the crank
shaft (x, y, z right-handed); the beam moves in the plane z = 0. Pitman 2 is on the
+z side: crank pin A at z = +b (``crank_half_spacing``), equalizer pin B at z = +e
(``equalizer_half_length``); pitman 3 mirrors it at -z. The pin line B-B1 passes
through the equalizer bearing D, the rear-arm end of the beam.

The rational mechanism has four idle freedoms ([Spatial7SK12]): the spin of each pitman
about its own axis, and two rotations of the equalizer relative to the beam (about
its pin line, and about an axis along the pitmans). They are fixed here as a real
unit's equalizer bearing does: the equalizer turns with the beam except for a roll
gamma about the beam's long axis l (which lets it share the load when the two sides
differ), and the pitmans do not spin.

Positions: with both sides equal the two pitmans move in mirror planes and the
planar closed form of :mod:`pumpjack_cli.core.beam.linkage` (applied to the projection of
the pitman on the beam plane, P_xy = sqrt(P^2 - (b - e)^2)) gives everything. With
deviations between the sides, the beam angle psi and the roll gamma solve
|B - A| = P2, |B1 - A1| = P3 with B, B1 = D +- e u, u = cos(gamma) z + sin(gamma) (z x l),
by Newton's method started from the planar solution, batched over all crank angles.

Angular velocities and accelerations come from the two closed vector loops
([Spatial7SK12] eqs. 5-6) differentiated with Bour's formula dl/dt = w x l:
``w1 x l1 + w2 x l2 + w4 x l4 + w5 x l5 = 0`` and
``w1 x l11 + w3 x l3 + w4 x l41 + w5 x l5 = 0`` (eqs. 7-10), and once more for the
accelerations (eqs. 11-12). Unknowns per crank angle: w2, w3 (3 each), the roll rate
k of the equalizer (w4 = w5 + k l) and w5z: eight, for the six loop equations and
w2 . l2 = 0, w3 . l3 = 0. One batched 8 x 8 solve for the whole revolution, the same
matrix for velocities and accelerations.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from ...errors import GeometryError
from .linkage import Linkage, check_assembly, motion

Z = np.array([0.0, 0.0, 1.0])
_NEWTON_ITERATIONS = 30


@dataclass(frozen=True)
class SpatialLinkage:
    """The planar four-bar plus the spatial spacing of the two sides.

    The deviations describe side 3 (crank pin A1, pitman A1B1) against side 2; all zero:
    both sides equal.

    Attributes
    ----------
    planar : Linkage
        The four-bar with the projected pitman length [m]; :attr:`pitman` is the true one.
    crank_half_spacing : float
        b, crank shaft mid-plane to each crank pin, along the shaft [m].
    equalizer_half_length : float
        e, equalizer bearing D to each equalizer pin [m].
    crank_phase_offset : float
        Crank pin A1 ahead of A in the direction of rotation [rad].
    crank_radius_offset, pitman_length_offset : float
        Crank radius of A1 and pitman A1B1 minus those of side 2 [m].
    arm_phase_offset : float
        Crank arm of side 3 with its counterweights turned ahead of side 2's in the
        direction of rotation [rad]: a crank-phase error of the whole arm (keyway play)
        rather than of pin A1's bore alone; it moves the arm's masses (their weight and
        inertia), while ``crank_phase_offset`` moves the pin.

    References
    ----------
    [Spatial7SK12] (the six-link mechanism and its errors).

    Examples
    --------
    A pitman projected to 4 m with its ends 3 m apart along the shaft is 5 m long:

    >>> from pumpjack_cli.core.beam.linkage import Linkage
    >>> SpatialLinkage(Linkage(3.5, 2.5, 1.01, 4.0, 2.195, 3.0), 1.0, 4.0).pitman
    5.0
    """

    planar: Linkage
    crank_half_spacing: float
    equalizer_half_length: float
    crank_phase_offset: float = 0.0
    crank_radius_offset: float = 0.0
    pitman_length_offset: float = 0.0
    arm_phase_offset: float = 0.0

    @property
    def pitman(self) -> float:
        """True length of pitman 2, P = sqrt(P_xy^2 + (b - e)^2) [m] (the planar linkage holds P_xy)."""
        return float(np.hypot(self.planar.pitman, self.crank_half_spacing - self.equalizer_half_length))

    @property
    def pitman3(self) -> float:
        """True length of pitman 3, P + pitman_length_offset [m]."""
        return self.pitman + self.pitman_length_offset

    @property
    def crank_spin(self) -> np.ndarray:
        """Unit vector of the crank angular velocity (dimensionless): clockwise seen from +z is -z."""
        return -self.planar.rotation * Z


@dataclass(frozen=True)
class SpatialMotion:
    """Positions, angular velocities and angular accelerations of every link at N crank angles.

    Attributes
    ----------
    crank_angle : numpy.ndarray
        theta, (N,) [rad].
    omega1, epsilon1 : numpy.ndarray
        The crank's scalar speed [1/s] and acceleration [1/s²] in the direction of
        rotation, (N,).
    crank_shaft, pin_a, pin_a1, pin_b, pin_b1, pin_d : numpy.ndarray
        Points O, A, A1, B, B1, D relative to the centre bearing C, (N, 3) [m].
    beam_angle : numpy.ndarray
        psi, (N,) [rad].
    w1, w2, w3, w4, w5 : numpy.ndarray
        Angular velocities of crank, pitmans, equalizer and beam, (N, 3) [1/s]; ``w1``
        points along the shaft.
    e1, e2, e3, e4, e5 : numpy.ndarray
        Their angular accelerations, (N, 3) [1/s²].
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


def cross(a: np.ndarray, b: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """Cross product a x b over the last axis (length 3), np.cross without its per-call overhead.

    Each component is written into one output array (no stacking of three temporaries):
    each component is still a_i b_j - a_j b_i, so the bits are those of np.cross.

    Parameters
    ----------
    a, b : numpy.ndarray
        Vectors, shape (..., 3) (any units).
    out : numpy.ndarray, optional
        Where to write a x b, of the broadcast shape (a view into a larger array will do).

    Returns
    -------
    numpy.ndarray
        a x b, shape (..., 3) (product of the units).

    Examples
    --------
    >>> cross(np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])).tolist()
    [0.0, 0.0, 1.0]
    """
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    if out is None:
        out = np.empty(np.broadcast_shapes(np.shape(a), np.shape(b)), dtype=np.result_type(a, b))
    c0, c1, c2 = out[..., 0], out[..., 1], out[..., 2]
    np.multiply(a1, b2, out=c0)
    c0 -= a2 * b1
    np.multiply(a2, b0, out=c1)
    c1 -= a0 * b2
    np.multiply(a0, b1, out=c2)
    c2 -= a1 * b0
    return out


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Dot product a . b over the last axis, np.sum(a * b, axis=-1) term by term.

    numpy adds a reduction over a short axis in order, 0.0 + a_0 b_0 + a_1 b_1 + ...; the
    same additions on whole component arrays give the same bits (the sign of a zero
    included) without the reduction's per-row overhead.

    Parameters
    ----------
    a, b : numpy.ndarray
        Vectors, shape (..., k) (any units).

    Returns
    -------
    numpy.ndarray
        a . b, shape (...) (product of the units).

    Examples
    --------
    >>> dot(np.array([[1.0, 2.0, 3.0]]), np.array([[4.0, 5.0, 6.0]])).tolist()
    [32.0]
    """
    return ordered_sum(a[..., i] * b[..., i] for i in range(a.shape[-1]))


def ordered_sum(terms: Iterable[np.ndarray]) -> np.ndarray:
    """0.0 + t_0 + t_1 + ... of a few arrays, in that order: the additions numpy's reduction
    over a short axis makes (the same bits, the sign of a zero included), whole arrays at a
    time instead of row by row (:func:`dot`; a link's points in the kinetostatics).

    Examples
    --------
    >>> ordered_sum(np.array([[1.0, -0.0], [2.0, -0.0]])).tolist()
    [3.0, 0.0]
    """
    iterator = iter(terms)
    total = 0.0 + next(iterator)
    for term in iterator:
        total += term
    return total


def norm(a: np.ndarray) -> np.ndarray:
    """Length |a| over the last axis as np.linalg.norm computes it, sqrt(:func:`dot` (a, a)).

    Parameters
    ----------
    a : numpy.ndarray
        Vectors, shape (..., k) (any unit).

    Returns
    -------
    numpy.ndarray
        |a|, shape (...) (the same unit).

    Examples
    --------
    >>> norm(np.array([[3.0, 4.0, 0.0]])).tolist()
    [5.0]
    """
    return np.sqrt(dot(a, a))


def skew(v: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """Cross-product matrices [v]x, so that [v]x @ u = v x u.

    Parameters
    ----------
    v : numpy.ndarray
        Vectors, shape (..., 3).
    out : numpy.ndarray, optional
        Where to write them, shape (..., 3, 3) (a view into a larger array will do).

    Returns
    -------
    numpy.ndarray
        Skew-symmetric matrices, shape (..., 3, 3).

    Examples
    --------
    >>> v, u = np.array([1.0, 2.0, 3.0]), np.array([-1.0, 0.5, 2.0])
    >>> bool(np.allclose(skew(v) @ u, np.cross(v, u)))
    True
    """
    if out is None:
        out = np.zeros(v.shape[:-1] + (3, 3))
    else:
        out[..., 0, 0] = out[..., 1, 1] = out[..., 2, 2] = 0.0
    out[..., 0, 1], out[..., 0, 2] = -v[..., 2], v[..., 1]
    out[..., 1, 0], out[..., 1, 2] = v[..., 2], -v[..., 0]
    out[..., 2, 0], out[..., 2, 1] = -v[..., 1], v[..., 0]
    return out


def _loop_matrix(l2: np.ndarray, l3: np.ndarray, l4: np.ndarray, l41: np.ndarray, l5: np.ndarray,
                 line: np.ndarray) -> np.ndarray:
    """The 8 x 8 coefficient matrix of (w2, w3, k, w5z) for every crank angle.

    Rows 0-2: loop O-A-B-D-C; rows 3-5: loop O1-A1-B1-D-C; w x l = -[l]x w, and the
    equalizer's w4 = w5z z + k l. Rows 6-7: no pitman spin, w2 . l2 = 0, w3 . l3 = 0.
    The blocks -[l]x are :func:`skew` written in place and negated there.
    """
    n = l2.shape[0]
    k = np.zeros((n, 8, 8))
    for row, vec in ((0, l2), (3, l3)):
        block = k[:, row:row + 3, row:row + 3]
        np.negative(skew(vec, out=block), out=block)
    cross(line, l4, out=k[:, 0:3, 6])
    cross(Z, l4 + l5, out=k[:, 0:3, 7])
    cross(line, l41, out=k[:, 3:6, 6])
    cross(Z, l41 + l5, out=k[:, 3:6, 7])
    k[:, 6, 0:3] = l2
    k[:, 7, 3:6] = l3
    return k


@dataclass(frozen=True)
class _Pose:
    crank_pin: np.ndarray
    crank_pin1: np.ndarray
    beam_angle: np.ndarray
    roll: np.ndarray


def _pose(spatial: SpatialLinkage, theta: np.ndarray) -> _Pose:
    """Crank pins, beam angle and equalizer roll for every crank angle (see module doc)."""
    linkage = spatial.planar
    n = theta.size
    b, e = spatial.crank_half_spacing, spatial.equalizer_half_length
    o = np.array([*linkage.crank_shaft, 0.0])

    def pin(radius: float, angle: np.ndarray, z: float) -> np.ndarray:
        return o + np.stack([linkage.rotation * radius * np.sin(angle), radius * np.cos(angle), np.full(n, z)], axis=-1)

    a = pin(linkage.crank_radius, theta, b)
    a1 = pin(linkage.crank_radius + spatial.crank_radius_offset, theta + spatial.crank_phase_offset, -b)
    psi = motion(linkage, theta).beam_angle
    gamma = np.zeros(n)
    if spatial.crank_phase_offset or spatial.crank_radius_offset or spatial.pitman_length_offset:
        side3 = dataclasses.replace(
            linkage, crank_radius=linkage.crank_radius + spatial.crank_radius_offset,
            pitman=float(np.sqrt(spatial.pitman3**2 - (b - e) ** 2)))
        try:
            check_assembly(side3)
        except GeometryError as exc:
            raise GeometryError(f"with the deviations of side 3 (crank radius {side3.crank_radius:.4g} m, "
                                f"pitman {spatial.pitman3:.4g} m): {exc}") from None
        lengths = (spatial.pitman, spatial.pitman3)
        for _ in range(_NEWTON_ITERATIONS):
            c, s_, cg, sg = np.cos(psi), np.sin(psi), np.cos(gamma), np.sin(gamma)
            d = -linkage.rear_arm * np.stack([c, s_, np.zeros(n)], axis=-1)
            d_psi = linkage.rear_arm * np.stack([s_, -c, np.zeros(n)], axis=-1)
            h = np.stack([-s_, c, np.zeros(n)], axis=-1)
            h_psi = np.stack([-c, -s_, np.zeros(n)], axis=-1)
            u = cg[:, None] * Z + sg[:, None] * h
            u_psi = sg[:, None] * h_psi
            u_gamma = -sg[:, None] * Z + cg[:, None] * h
            residual, jac = np.empty((n, 2)), np.empty((n, 2, 2))
            for row, (sign, crank_pin, length) in enumerate(((1.0, a, lengths[0]), (-1.0, a1, lengths[1]))):
                w = d + sign * e * u - crank_pin
                residual[:, row] = dot(w, w) - length**2
                jac[:, row, 0] = 2.0 * dot(w, d_psi + sign * e * u_psi)
                jac[:, row, 1] = 2.0 * dot(w, sign * e * u_gamma)
            step = np.linalg.solve(jac, residual[..., None])[..., 0]
            psi, gamma = psi - step[:, 0], gamma - step[:, 1]
            if np.max(np.abs(step)) < 1e-14:
                break
        else:
            raise GeometryError("the two sides cannot be assembled with these deviations: "
                                f"no beam position closes both loops after {_NEWTON_ITERATIONS} Newton steps")
        if not np.all(np.isfinite(psi)) or np.max(np.abs(gamma)) > 0.5:
            raise GeometryError("the two sides cannot be assembled with these deviations: the equalizer "
                                "would have to roll by more than 0.5 rad")
    return _Pose(a, a1, psi, gamma)


def spatial_motion(
    spatial: SpatialLinkage, crank_angle: np.ndarray, crank_speed: np.ndarray | float, crank_acceleration: np.ndarray | float = 0.0
) -> SpatialMotion:
    """Positions, angular velocities and accelerations of every link, whole revolution at once.

    Velocities from the two closed loops differentiated with Bour's formula,
    sum w_i x l_i = 0, plus w2 . l2 = w3 . l3 = 0 (no pitman spin): one 8 x 8 system per
    crank angle in (w2, w3, the equalizer's roll rate, w5z); accelerations from the
    loops differentiated again, sum (eps_i x l_i + w_i x (w_i x l_i)) = 0, with the same
    matrix.

    Parameters
    ----------
    spatial : SpatialLinkage
        The mechanism [m, rad].
    crank_angle : numpy.ndarray
        theta, (N,) [rad].
    crank_speed : float or numpy.ndarray
        Crank speed in the direction of rotation [1/s].
    crank_acceleration : float or numpy.ndarray
        Crank acceleration in the direction of rotation [1/s²].

    Returns
    -------
    SpatialMotion
        Points [m], angular velocities [1/s], angular accelerations [1/s²].

    Raises
    ------
    GeometryError
        The two sides cannot be assembled with the deviations.

    References
    ----------
    [Spatial7SK12] eqs. 5-16.

    Examples
    --------
    With equal sides the beam turns as in the planar closed form, w5z = psi' omega1:

    >>> from pumpjack_cli.core.beam.linkage import Linkage
    >>> sk8 = SpatialLinkage(Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0), 0.8, 0.8)
    >>> theta = np.radians([30.0, 90.0])
    >>> sm = spatial_motion(sk8, theta, 1.2)
    >>> bool(np.allclose(sm.w5[:, 2], motion(sk8.planar, theta).beam_rate * 1.2, rtol=1e-12))
    True
    """
    theta = np.asarray(crank_angle, dtype=float)
    n = theta.size
    crank_speed = np.broadcast_to(np.asarray(crank_speed, dtype=float), (n,))
    crank_acceleration = np.broadcast_to(np.asarray(crank_acceleration, dtype=float), (n,))
    pose = _pose(spatial, theta)
    b, e = spatial.crank_half_spacing, spatial.equalizer_half_length
    zeros = np.zeros(n)
    o = np.broadcast_to(np.array([*spatial.planar.crank_shaft, 0.0]), (n, 3))
    line = np.stack([np.cos(pose.beam_angle), np.sin(pose.beam_angle), zeros], axis=-1)
    normal = cross(Z, line)
    u = np.cos(pose.roll)[:, None] * Z + np.sin(pose.roll)[:, None] * normal
    d = -spatial.planar.rear_arm * line
    a, a1 = pose.crank_pin, pose.crank_pin1
    pb, pb1 = d + e * u, d - e * u
    l1, l11 = a - o - b * Z, a1 - o + b * Z
    l2, l3 = pb - a, pb1 - a1
    l4, l41 = d - pb, d - pb1
    l5 = -d
    spin = spatial.crank_spin
    w1 = crank_speed[:, None] * spin
    e1 = crank_acceleration[:, None] * spin
    k = _loop_matrix(l2, l3, l4, l41, l5, line)

    rhs_v = np.zeros((n, 8))
    cross(w1, l1, out=rhs_v[:, 0:3])
    cross(w1, l11, out=rhs_v[:, 3:6])
    np.negative(rhs_v[:, 0:6], out=rhs_v[:, 0:6])
    x = np.linalg.solve(k, rhs_v[..., None])[..., 0]
    w2, w3, roll_rate = x[:, 0:3], x[:, 3:6], x[:, 6]
    w5 = np.stack([zeros, zeros, x[:, 7]], axis=-1)
    w4 = w5 + roll_rate[:, None] * line

    def centripetal(w: np.ndarray, vec: np.ndarray) -> np.ndarray:
        return cross(w, cross(w, vec))

    # Second derivative of each loop: sum(eps x l + w x (w x l)) = 0 ([Spatial7SK12] eqs. 11-12).
    # eps4 = eps5z z + k' l + k w5z (z x l): the last term is known and goes to the right side.
    # The beam's term w5 x (w5 x l5) is common to both loops.
    known4 = (roll_rate * x[:, 7])[:, None] * normal
    beam_term = centripetal(w5, l5)
    loop1 = (cross(e1, l1) + centripetal(w1, l1) + centripetal(w2, l2) + centripetal(w4, l4)
             + cross(known4, l4) + beam_term)
    loop2 = (cross(e1, l11) + centripetal(w1, l11) + centripetal(w3, l3) + centripetal(w4, l41)
             + cross(known4, l41) + beam_term)
    rhs_a = np.zeros((n, 8))
    np.negative(loop1, out=rhs_a[:, 0:3])
    np.negative(loop2, out=rhs_a[:, 3:6])
    y = np.linalg.solve(k, rhs_a[..., None])[..., 0]
    e5 = np.stack([zeros, zeros, y[:, 7]], axis=-1)
    return SpatialMotion(
        crank_angle=theta,
        omega1=crank_speed,
        epsilon1=crank_acceleration,
        crank_shaft=o,
        pin_a=a,
        pin_a1=a1,
        pin_b=pb,
        pin_b1=pb1,
        pin_d=d,
        beam_angle=pose.beam_angle,
        w1=w1,
        w2=w2,
        w3=w3,
        w4=w4,
        w5=w5,
        e1=e1,
        e2=y[:, 0:3],
        e3=y[:, 3:6],
        e4=e5 + y[:, 6:7] * line + known4,
        e5=e5,
    )
