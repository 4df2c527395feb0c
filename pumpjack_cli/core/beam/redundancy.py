"""The real mechanism: redundant constraints and elastic pitmans ([Spatial7SK12] eqs. 17-39).

In the real unit the pitmans are joined to the crank pins A, A1 and to the equalizer
pins B, B1 by revolute pairs (class V). Against the rational mechanism (spherical
pairs there) this adds four constraints that the motion does not need ([Spatial7SK12]:
W = -3 for a unit that moves with one degree of freedom), so the mechanism is
statically indeterminate of degree 4. An ideal unit assembles without stress; a unit
with manufacturing or wear errors (crank arms out of phase, unequal crank radii or
pitman lengths, pin bores not parallel) forces the pitmans to twist and bend, and
their elastic moments load the joints unevenly.

Compatibility model (derived here; [Spatial7SK12] takes its twist and bending angles from
a companion paper, [Popovych2014], that is not available): the force method. Linear elasticity about
the configuration of the rational mechanism with the same errors (positions and
motion from :mod:`.spatial`); all links rigid except the pitmans, each a straight
prismatic bar of length l between its joints with axial stiffness E A, torsional
G J_t, bending E J_c about the pin direction (bending in the plane of motion; J_z of
[Spatial7SK12]) and E J_n across it (out of that plane); shear deformation neglected.

1. Unknowns (28, [Spatial7SK12]): R12, R13, R24, R34, R45, R05 (3 each), M_R05 (2, across z)
   and the joint moments M_R12, M_R13, M_R24, M_R34 (2 each, across their pin axes:
   a revolute pair transmits no moment about its own axis).
2. Equilibrium: the 24 equations of links 2, 3, 4, 5 (forces, moments about C),
   E X = f. Their rank is 24, or 23 when the equalizer's spin about its pin line is
   free (parallel pins, spherical D); the null space of E holds the self-stress states
   (redundancy 4 to 5), found per crank angle by singular value decomposition.
3. Misfit: in the frame of each pitman chord (n along A->B, c the shaft direction
   projected across n, t = n x c) the pin axes of the error-free unit have fixed
   components a0, u0; with errors the pins are a, u, and the pitman ends must turn
   with them by mu_A = a0 x a, mu_B = u0 x u relative to the chord (small rotations).
4. Complementary energy of the pitmans, with the internal axial force N, torque T
   and bending moments M_c, M_t at a section x from A following from the end-A loads
   and the pitman's own weight and inertia (a point load at its centre of mass):
   U* = sum over pitmans of integral (N^2/EA + T^2/G J_t + M_c^2/E J_c + M_t^2/E J_n) dx / 2
   (piecewise linear moments, integrated exactly by Simpson's rule on each piece).
5. Castigliano-Menabrea with initial misfit: X = X_p + S y minimises
   U*(X) - sum(joint moment on a pitman end . mu of that end) over the self-stress
   amplitudes y: (S^T Q S) y = S^T (w - q - Q X_p). With no errors and symmetric loads
   y = 0 and the real mechanism equals the rational one.

[Spatial7SK12] writes the torsion as G J_p phi / l_AB along e_AB (eqs. 18-19) and the
bending as 3 E J_z sin(dbeta23) / (2 l_AB) along e_BD (eqs. 20-21), a bar clamped at
one end and free to turn at the other. Here both ends are held by their pins and the
whole statically indeterminate group is solved at once; about the pin direction a
revolute pair turns freely, so bending in the plane of motion is not forced by the
joints.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .kinetostatics import LinkLoads, Reactions, applied_loads, crank_reactions
from .masses import MassModel
from .spatial import Z, SpatialLinkage, SpatialMotion, skew, cross, spatial_motion


@dataclass(frozen=True)
class PitmanSection:
    """Elastic properties of a pitman, a straight prismatic bar.

    Attributes
    ----------
    youngs_modulus : float
        E [Pa] (2.1e11 Pa in [Spatial7SK12]).
    shear_modulus : float
        G [Pa].
    area : float
        Cross-section area A [m²].
    inplane_inertia : float
        J_c, second moment about the pin direction (bending in the plane of motion;
        J_z = 17.61e-6 m⁴ in [Spatial7SK12]) [m⁴].
    outofplane_inertia : float
        J_n, second moment across the pin direction [m⁴].
    torsion_constant : float
        J_t, the polar moment J_p for a tube [m⁴].

    References
    ----------
    [Spatial7SK12] eqs. 18-21.
    """

    youngs_modulus: float
    shear_modulus: float
    area: float
    inplane_inertia: float
    outofplane_inertia: float
    torsion_constant: float


@dataclass(frozen=True)
class PinTilts:
    """Pin bores not parallel to the crank shaft: small rotations of the pin axes of side 3.

    Side 2 is the reference.

    Attributes
    ----------
    crank_pin_radial : float
        Crank pin A1 turned about the crank arm's radial line (the pin leans along the
        path of the pin) [rad].
    crank_pin_tangential : float
        Crank pin A1 turned about the arm's tangent (the pin leans outwards) [rad].
    equalizer_pin_roll : float
        Equalizer pin B1 turned about the beam's long axis [rad].
    equalizer_pin_yaw : float
        Equalizer pin B1 turned about the vertical across the beam [rad].
    """

    crank_pin_radial: float = 0.0
    crank_pin_tangential: float = 0.0
    equalizer_pin_roll: float = 0.0
    equalizer_pin_yaw: float = 0.0


@dataclass(frozen=True)
class JointCompliance:
    """Rotational stiffness and clearance of the revolute pairs across their pin axes.

    Each pin is a rotational spring in series with the pitman (complementary energy
    M²/(2k) per moment component), with a dead band: the joint turns freely through
    +-clearance (radial clearance over bearing width, e.g. 0.1 mm / 100 mm = 1 mrad)
    before it carries a moment. Each of the two moment components across a pin axis has
    its own dead band (a square band: exact when one component acts, conservative when
    both do). Infinite stiffness and zero clearance: the rigid pins of [Spatial7SK12].

    Attributes
    ----------
    crank_pin_stiffness, equalizer_pin_stiffness : float
        k [N·m/rad] of the crank pins A, A1 and of the equalizer pins B, B1.
    crank_pin_clearance, equalizer_pin_clearance : float
        Free rotation delta [rad] of each pin's pair before contact.
    """

    crank_pin_stiffness: float = np.inf
    equalizer_pin_stiffness: float = np.inf
    crank_pin_clearance: float = 0.0
    equalizer_pin_clearance: float = 0.0


#: Crank angles solved at once by :func:`real_mechanism` (longer grids go in chunks).
CHUNK = 1024

#: Iterations of the active-set solution of the joints' dead bands at most.
MAX_CONTACT_ITERATIONS = 50
#: Weights of the moment in the primal-dual active-set update lambda + step M / max h_ii,
#: tried in turn at the crank angles where the previous one cycled.
CONTACT_STEPS = (0.01, 1.0, 0.1, 10.0)


@dataclass(frozen=True)
class ContactCheck:
    """How the joints' dead-band problem was solved at each crank angle: active-set
    iterations, and the largest violations of compatibility (stationarity of the
    complementary energy, relative to the misfit work's scale) and of the contact
    conditions (|lambda| <= delta where a moment is zero, lambda = delta sign(M) where it
    is not; relative to delta) [-]."""

    iterations: np.ndarray
    compatibility_residual: np.ndarray
    contact_residual: np.ndarray


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.sum(a * b, axis=-1)


def _chord_frame(head: np.ndarray, tail: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(n, c, t): chord, shaft direction projected across it, and n x c."""
    n = _unit(head - tail)
    c = _unit(Z - _dot(Z, n)[:, None] * n)
    return n, c, cross(n, c)


def _local(v: np.ndarray, frame: tuple[np.ndarray, ...]) -> np.ndarray:
    return np.stack([_dot(v, axis) for axis in frame], axis=-1)


def _global(v: np.ndarray, frame: tuple[np.ndarray, ...]) -> np.ndarray:
    return sum(v[:, i:i + 1] * axis for i, axis in enumerate(frame))


def _rotate(v: np.ndarray, rotation: np.ndarray) -> np.ndarray:
    """Rodrigues' rotation of vectors v (N, 3) by rotation vectors (N, 3)."""
    angle = np.linalg.norm(rotation, axis=-1, keepdims=True)
    axis = np.divide(rotation, angle, out=np.zeros_like(rotation), where=angle > 0)
    return (v * np.cos(angle) + cross(axis, v) * np.sin(angle)
            + axis * _dot(axis, v)[:, None] * (1.0 - np.cos(angle)))


def pin_axes(spatial: SpatialLinkage, sm: SpatialMotion, tilts: PinTilts) -> tuple[np.ndarray, ...]:
    """Axes of the four pins, crank pins A, A1 and equalizer pins B, B1.

    Crank pins turn with the crank: their axes are the shaft direction, pin A1's tilted
    in the arm frame (radial line r, tangent s = z x r). Equalizer pins lie along the
    pin line B1->B, pin B1's tilted about the beam axis and about z x beam axis. Tilts
    are applied as finite rotations (Rodrigues' formula).

    Parameters
    ----------
    spatial : SpatialLinkage
        The unit [m].
    sm : SpatialMotion
        Its motion.
    tilts : PinTilts
        Pin-bore errors of side 3 [rad].

    Returns
    -------
    tuple of numpy.ndarray
        (a2, u2, a3, u3): unit vectors (N, 3) of pins A, B, A1, B1 (dimensionless).
    """
    n = sm.crank_angle.size
    shaft = np.broadcast_to(Z, (n, 3))
    radial = _unit(sm.pin_a1 - sm.crank_shaft - _dot(sm.pin_a1 - sm.crank_shaft, Z)[:, None] * Z)
    tangent = cross(Z, radial)
    a3 = _rotate(shaft, tilts.crank_pin_radial * radial + tilts.crank_pin_tangential * tangent)
    line = _unit(sm.pin_b - sm.pin_b1)
    beam = np.stack([np.cos(sm.beam_angle), np.sin(sm.beam_angle), np.zeros(n)], axis=-1)
    u3 = _rotate(line, tilts.equalizer_pin_roll * beam + tilts.equalizer_pin_yaw * cross(Z, beam))
    return shaft, line, a3, u3


@dataclass(frozen=True)
class JointMoments:
    """Reaction moments of the revolute pairs of the real mechanism.

    Attributes
    ----------
    m12, m13 : numpy.ndarray
        Moments of the crank on pitman 2 at A and on pitman 3 at A1, (N, 3) [N·m].
    m24, m34 : numpy.ndarray
        Moments of pitman 2 on the equalizer at B and of pitman 3 at B1, (N, 3) [N·m].
    torsion2, torsion3 : numpy.ndarray
        The pitman torques about their axes, (N,) [N·m].

    References
    ----------
    [Spatial7SK12] eqs. 18-21 (the pitmans' elastic moments).
    """

    m12: np.ndarray
    m13: np.ndarray
    m24: np.ndarray
    m34: np.ndarray
    torsion2: np.ndarray
    torsion3: np.ndarray
    contact: ContactCheck | None = None


_FORCES = ("r12", "r13", "r24", "r34", "r45", "r05")
_MOMENTS = ("m12", "m13", "m24", "m34")
_N_UNKNOWNS = 28


def _column(name: str) -> int:
    """First column of an unknown: forces 0-17, M_R05 18-19, joint moments 20-27."""
    if name in _FORCES:
        return 3 * _FORCES.index(name)
    return 18 if name == "m05" else 20 + 2 * _MOMENTS.index(name)


def _moment_basis(axis: np.ndarray) -> np.ndarray:
    """Two unit vectors across a pin axis, (N, 3, 2): a moment there is basis @ (m1, m2)."""
    p = _unit(cross(axis, np.broadcast_to(np.array([0.0, 1.0, 0.0]), axis.shape)))
    return np.stack([p, cross(axis, p)], axis=-1)


def _equilibrium(sm: SpatialMotion, bases: dict[str, np.ndarray]) -> np.ndarray:
    """E (N, 24, 28): forces and moments about C of pitman 2, pitman 3, equalizer, beam."""
    n = sm.crank_angle.size
    e = np.zeros((n, 24, _N_UNKNOWNS))
    origin = np.zeros((n, 3))

    def force(link: int, name: str, sign: float, point: np.ndarray) -> None:
        c = _column(name)
        e[:, 6 * link:6 * link + 3, c:c + 3] += sign * np.eye(3)
        e[:, 6 * link + 3:6 * link + 6, c:c + 3] += sign * skew(point)

    def couple(link: int, name: str, sign: float) -> None:
        c = _column(name)
        e[:, 6 * link + 3:6 * link + 6, c:c + 2] += sign * bases[name]

    force(0, "r12", 1.0, sm.pin_a)
    force(0, "r24", -1.0, sm.pin_b)
    couple(0, "m12", 1.0)
    couple(0, "m24", -1.0)
    force(1, "r13", 1.0, sm.pin_a1)
    force(1, "r34", -1.0, sm.pin_b1)
    couple(1, "m13", 1.0)
    couple(1, "m34", -1.0)
    for name, point in (("r24", sm.pin_b), ("r34", sm.pin_b1)):
        force(2, name, 1.0, point)
    force(2, "r45", -1.0, sm.pin_d)
    couple(2, "m24", 1.0)
    couple(2, "m34", 1.0)
    force(3, "r45", 1.0, sm.pin_d)
    force(3, "r05", 1.0, origin)
    e[:, 21, 18] = e[:, 22, 19] = 1.0
    return e


def _self_stress(e: np.ndarray, f: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A particular solution of E X = f (N, 28) and the self-stress states, an orthonormal basis
    of the null space of E (N, 28, 28 - rank).

    QR of E^T (rows of E taken in order): E^T = Q R, so with rank 24 the null space is
    spanned by the last four columns of Q and X = Q_1 R_1^-T f. A row of E that depends
    on the rows before it shows as a vanishing diagonal element of R (the equalizer's
    spin about its pin line with parallel pins, rank 23); found at the first crank angle,
    it is dropped (the system is consistent, so the row adds nothing) before the batched
    QR. If any crank angle then still shows a vanishing pivot, the singular value
    decomposition serves instead.
    """
    rows = np.arange(e.shape[1])
    first = np.abs(np.diag(np.linalg.qr(e[0].T, mode="r")))
    weak = np.flatnonzero(first < 1e-10 * first.max())
    rows = np.delete(rows, weak)
    q, r = np.linalg.qr(np.swapaxes(e[:, rows, :], 1, 2), mode="complete")
    rank = rows.size
    pivots = np.abs(np.einsum("nii->ni", r[:, :rank, :rank]))
    if np.any(pivots < 1e-10 * np.max(pivots, axis=-1, keepdims=True)):
        u_svd, sing, vh = np.linalg.svd(e)
        rank = int(np.max(np.sum(sing > 1e-10 * sing[:, :1], axis=-1)))
        x_p = np.einsum("nji,nj->ni", vh[:, :rank], np.einsum("nji,nj->ni", u_svd[:, :, :rank], f) / sing[:, :rank])
        return x_p, np.swapaxes(vh[:, rank:], 1, 2)
    z = np.linalg.solve(np.swapaxes(r[:, :rank, :rank], 1, 2), f[:, rows][..., None])[..., 0]
    return np.einsum("nij,nj->ni", q[:, :, :rank], z), q[:, :, rank:]


def _pitman_energy(
    sm: SpatialMotion, pin: str, top: str, force_name: str, moment_name: str, loads: LinkLoads,
    bases: dict[str, np.ndarray], section: PitmanSection,
) -> tuple[np.ndarray, np.ndarray]:
    """Q (N, 5, 5) and q (N, 5) of one pitman's complementary energy U* = X.QX/2 + q.X + c in the
    five unknowns it depends on: the force at its crank pin (3) and the joint moment there (2)."""
    n_pts = sm.crank_angle.size
    a, b = getattr(sm, pin), getattr(sm, top)
    axis, c_dir, t_dir = _chord_frame(b, a)
    length = np.linalg.norm(b - a, axis=-1)
    load_force, load_point, load_moment = loads.forces[:, 0], loads.points[:, 0], loads.moment
    x_s = _dot(load_point - a, axis)
    compliance = np.array([1 / (section.youngs_modulus * section.area), 1 / (section.shear_modulus * section.torsion_constant),
                           1 / (section.youngs_modulus * section.inplane_inertia),
                           1 / (section.youngs_modulus * section.outofplane_inertia)])
    directions = np.stack([axis, axis, c_dir, t_dir], axis=1)  # (N, 4, 3): N, T, M_c, M_t
    q_mat = np.zeros((n_pts, 5, 5))
    q_vec = np.zeros((n_pts, 5))
    for start, stop, loaded in ((np.zeros(n_pts), x_s, 0.0), (x_s, length, 1.0)):
        for weight, where in ((1 / 6, start), (4 / 6, 0.5 * (start + stop)), (1 / 6, stop)):
            p = a + where[:, None] * axis
            # cut face of the piece [0, x]: F = -F_A - loaded F_s; M = -M_A - (A - P) x F_A - loaded (M_s + (S - P) x F_s)
            g_force = np.zeros((n_pts, 3, 5))
            g_force[:, :, :3] = -np.eye(3)
            g_moment = np.zeros((n_pts, 3, 5))
            g_moment[:, :, 3:] = -bases[moment_name]
            g_moment[:, :, :3] = -skew(a - p)
            h_force = -loaded * load_force
            h_moment = -loaded * (load_moment + cross(load_point - p, load_force))
            g = np.concatenate([np.einsum("nk,nkj->nj", directions[:, 0], g_force)[:, None],
                                np.einsum("nik,nkj->nij", directions[:, 1:], g_moment)], axis=1)
            h = np.concatenate([_dot(directions[:, 0], h_force)[:, None],
                                np.einsum("nik,nk->ni", directions[:, 1:], h_moment)], axis=1)
            scale = (weight * (stop - start))[:, None] * compliance
            q_mat += np.einsum("nij,ni,nik->njk", g, scale, g)
            q_vec += np.einsum("nij,ni,ni->nj", g, scale, h)
    return q_mat, q_vec


def _misfit(ideal: SpatialMotion, actual: SpatialMotion, pin: str, top: str,
            a_axis: np.ndarray, u_axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rotations the pitman ends must make relative to their chord: (mu_A, mu_B)."""
    n_pts = actual.crank_angle.size
    frame0 = _chord_frame(getattr(ideal, top), getattr(ideal, pin))
    frame = _chord_frame(getattr(actual, top), getattr(actual, pin))
    a0 = _global(_local(np.broadcast_to(Z, (n_pts, 3)), frame0), frame)
    u0 = _global(_local(_unit(ideal.pin_b - ideal.pin_b1), frame0), frame)
    return cross(a0, a_axis), cross(u0, u_axis)


def real_mechanism(
    ideal: SpatialLinkage,
    actual: SpatialLinkage,
    tilts: PinTilts,
    section: PitmanSection,
    masses: MassModel,
    crank_angle: np.ndarray,
    crank_speed: np.ndarray | float,
    crank_acceleration: np.ndarray | float,
    rod_load: np.ndarray,
    *,
    weights: bool = True,
    inertia: bool = True,
    joints: JointCompliance = JointCompliance(),
) -> tuple[SpatialMotion, JointMoments, Reactions]:
    """Kinematics, joint moments and reactions of the real mechanism.

    The force method of the module docstring: the 24 equilibrium equations E X = f in
    28 unknowns, a particular solution X_p and the self-stress states S (null space of
    E, per crank angle by SVD), then Menabrea's condition with misfit,
    (S^T Q S) y = S^T (w - q - Q X_p), X = X_p + S y; the crank follows as in the
    rational mechanism, with the joint moments at A and A1 acting on it.

    Parameters
    ----------
    ideal : SpatialLinkage
        The error-free unit [m].
    actual : SpatialLinkage
        The same with the side-3 deviations (crank phase [rad], crank radius and pitman
        length [m]).
    tilts : PinTilts
        Pin-bore errors [rad].
    section : PitmanSection
        The pitmans' elastic section [Pa, m², m⁴].
    masses : MassModel
        Masses [kg], centres [m], inertias [kg·m²].
    crank_angle : numpy.ndarray
        theta [rad].
    crank_speed, crank_acceleration : float or numpy.ndarray
        Crank speed [1/s] and acceleration [1/s²] in the direction of rotation.
    rod_load : numpy.ndarray
        Polished-rod load at each crank angle [N].
    weights, inertia : bool
        Include the links' weights, their inertia forces and moments.
    joints : JointCompliance
        Rotational stiffness [N·m/rad] and clearance [rad] of the pins (default: rigid,
        no clearance). Stiffness adds 1/k to the complementary energy of each joint
        moment component; a clearance delta makes it delta |M| + M²/(2k) (a dead band),
        and Menabrea's condition becomes the convex problem min over y of
        1/2 y.Ay - b.y + sum delta_i |M_i(y)|, solved per crank angle by an active-set
        method (:func:`_dead_band`) whose residuals come back in ``contact``.

    Returns
    -------
    tuple
        (:class:`SpatialMotion` of ``actual``, :class:`JointMoments` [N·m] with the
        :class:`ContactCheck`, :class:`~.kinetostatics.Reactions` [N, N·m]).

    References
    ----------
    [Spatial7SK12] eqs. 17-39.

    Examples
    --------
    Without deviations the unit assembles free of stress, so the real mechanism gives
    the rational mechanism's reactions and no joint moments:

    >>> import dataclasses
    >>> from pumpjack_cli.core.beam.linkage import Linkage
    >>> from pumpjack_cli.core.beam.kinetostatics import rational_mechanism
    >>> sk8 = SpatialLinkage(Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0), 0.8, 0.8)
    >>> masses = dataclasses.replace(MassModel(*[0.0] * 18), pitman_mass=130.0, pitman_cg=1.5)
    >>> tube = PitmanSection(2.1e11, 8.08e10, 56.5e-4, 17.61e-6, 17.61e-6, 35.22e-6)
    >>> theta, load = np.radians([0.0, 90.0, 180.0]), np.full(3, 50e3)
    >>> _, moments, real = real_mechanism(sk8, sk8, PinTilts(), tube, masses, theta, 1.14, 0.0, load)
    >>> _, rational = rational_mechanism(sk8, masses, theta, 1.14, 0.0, load)
    >>> bool(np.allclose(real.r12, rational.r12, atol=1e-6) and np.allclose(moments.m12, 0.0, atol=1e-6))
    True
    """
    theta = np.asarray(crank_angle, dtype=float)
    if theta.size > CHUNK:  # bounded memory: about 50 kB per crank angle while it is solved
        per = [np.broadcast_to(np.asarray(v, dtype=float), theta.shape) for v in (crank_speed, crank_acceleration, rod_load)]
        parts = [real_mechanism(ideal, actual, tilts, section, masses, theta[k:k + CHUNK],
                                *(v[k:k + CHUNK] for v in per), weights=weights, inertia=inertia, joints=joints)
                 for k in range(0, theta.size, CHUNK)]
        return tuple(_joined([part[i] for part in parts]) for i in range(3))
    ideal_motion = spatial_motion(ideal, crank_angle, crank_speed, crank_acceleration)
    sm = spatial_motion(actual, crank_angle, crank_speed, crank_acceleration)
    loads = applied_loads(actual, masses, sm, rod_load, weights=weights, inertia=inertia)
    a2, u2, a3, u3 = pin_axes(actual, sm, tilts)
    bases = {"m12": _moment_basis(a2), "m24": _moment_basis(u2), "m13": _moment_basis(a3), "m34": _moment_basis(u3)}
    e = _equilibrium(sm, bases)
    f = -np.concatenate([np.concatenate([link.resultant(), link.moment_about_origin()], axis=-1)
                         for link in (loads.pitman2, loads.pitman3, loads.equalizer, loads.beam)], axis=-1)
    x_p, null = _self_stress(e, f)

    q_mat, q_vec = np.zeros((crank_angle.size, _N_UNKNOWNS, _N_UNKNOWNS)), np.zeros((crank_angle.size, _N_UNKNOWNS))
    work = np.zeros((crank_angle.size, _N_UNKNOWNS))
    for pin, top, force_name, m_pin, m_top, link, axes in (
        ("pin_a", "pin_b", "r12", "m12", "m24", loads.pitman2, (a2, u2)),
        ("pin_a1", "pin_b1", "r13", "m13", "m34", loads.pitman3, (a3, u3)),
    ):
        qm, qv = _pitman_energy(sm, pin, top, force_name, m_pin, link, bases, section)
        used = np.r_[_column(force_name):_column(force_name) + 3, _column(m_pin):_column(m_pin) + 2]
        q_mat[:, used[:, None], used[None, :]] += qm
        q_vec[:, used] += qv
        mu_a, mu_b = _misfit(ideal_motion, sm, pin, top, *axes)
        # work of the joint moments on the pitman ends through the misfit: +M_pin at A, -M_top at B
        work[:, _column(m_pin):_column(m_pin) + 2] = np.einsum("nki,nk->ni", bases[m_pin], mu_a)
        work[:, _column(m_top):_column(m_top) + 2] = -np.einsum("nki,nk->ni", bases[m_top], mu_b)
    index = np.concatenate([_column(name) + np.arange(2) for name in _MOMENTS])
    stiffness = np.repeat([joints.crank_pin_stiffness, joints.crank_pin_stiffness, joints.equalizer_pin_stiffness,
                           joints.equalizer_pin_stiffness], 2)
    q_mat[:, index, index] += 1.0 / stiffness
    st = np.swapaxes(null, 1, 2)
    a_mat = st @ q_mat @ null
    rhs = np.einsum("nij,nj->ni", st, work - q_vec - np.einsum("nij,nj->ni", q_mat, x_p))
    clearance = np.repeat([joints.crank_pin_clearance, joints.crank_pin_clearance, joints.equalizer_pin_clearance,
                           joints.equalizer_pin_clearance], 2)
    y, contact = _dead_band(a_mat, rhs, null[:, index, :], x_p[:, index], clearance)
    x = x_p + np.einsum("nij,nj->ni", null, y)

    scale = np.max(np.abs(f), axis=-1)
    residual = np.max(np.abs(np.einsum("nij,nj->ni", e, x) - f), axis=-1) / np.where(scale > 0, scale, 1.0)
    r = {name: x[:, _column(name):_column(name) + 3] for name in _FORCES}
    joint = {name: np.einsum("nki,ni->nk", bases[name], x[:, _column(name):_column(name) + 2]) for name in _MOMENTS}
    crank = dataclasses.replace(loads.crank, moment=loads.crank.moment - joint["m12"] - joint["m13"])
    r01, m01, torque = crank_reactions(actual, sm, crank, r["r12"], r["r13"])
    n2, n3 = _unit(sm.pin_b - sm.pin_a), _unit(sm.pin_b1 - sm.pin_a1)
    moments = JointMoments(
        m12=joint["m12"], m13=joint["m13"], m24=joint["m24"], m34=joint["m34"],
        torsion2=_dot(joint["m24"], n2), torsion3=_dot(joint["m34"], n3), contact=contact,
    )
    n = crank_angle.size
    reactions = Reactions(
        r12=r["r12"], r13=r["r13"], r24=r["r24"], r34=r["r34"], r45=r["r45"], r05=r["r05"],
        m05=np.stack([x[:, 18], x[:, 19], np.zeros(n)], axis=-1), r01=r01, m01=m01,
        net_torque=torque, residual=residual,
    )
    return sm, moments, reactions


def _dead_band(a_mat: np.ndarray, rhs: np.ndarray, g: np.ndarray, m0: np.ndarray,
               clearance: np.ndarray) -> tuple[np.ndarray, ContactCheck]:
    """Self-stress amplitudes y (N, r) minimising 1/2 y.A y - b.y + sum_i delta_i |m0_i + g_i.y|.

    The joint moments are M = m0 + g y. By convex duality (the dead band's term is
    max over |lambda_i| <= delta_i of lambda.M) the problem is the box-constrained
    quadratic programme min over |lambda| <= delta of 1/2 lambda.H lambda - c.lambda,
    H = g A^-1 g^T, c = m0 + g A^-1 b, and then y = A^-1 (b - g^T lambda), M = c - H lambda.
    Its KKT conditions are the contact conditions: |lambda_i| < delta_i where M_i = 0
    (the joint within its play) and lambda_i = delta_i sign(M_i) where M_i != 0 (in
    contact). H has the rank of the self-stress states; a Tikhonov term of 1e-9 of its
    largest diagonal makes it definite (of the lambdas that give the same moments it
    picks the smallest; the moments change by that fraction). Solved per crank angle,
    all angles at once, by the primal-dual active-set method for bounds
    (:func:`_active_set`): lambda_i goes to +-delta_i where lambda_i + gamma M_i leaves
    the band, the free components solve H_FF lambda_F = c_F - H_F,B lambda_B, until the
    sets repeat; crank angles where one gamma cycles are solved again with the next of
    :data:`CONTACT_STEPS`. Without clearance lambda = 0 and this is one linear solve.
    """
    n, r = rhs.shape
    k = m0.shape[1]
    inverse = np.linalg.inv(a_mat)
    if not np.any(clearance > 0):
        y = np.einsum("nij,nj->ni", inverse, rhs)
        return y, ContactCheck(np.ones(n, dtype=int), _stationarity(a_mat, rhs, y, g, np.zeros((n, k))),
                               np.zeros(n))
    gi = g @ inverse
    h = gi @ np.swapaxes(g, 1, 2)
    c = m0 + np.einsum("nkr,nr->nk", gi, rhs)
    top = np.max(np.einsum("nkk->nk", h), axis=-1)
    # H has the rank of the self-stress states: a tiny Tikhonov term makes it definite and
    # picks, of the lambdas that give the same moments, the smallest; the moments are unchanged
    regular = h + (1e-9 * top)[:, None, None] * np.eye(k)
    scale = np.maximum(np.max(np.abs(c), axis=-1), np.max(np.abs(m0), axis=-1)) + 1.0
    lam = np.zeros((n, k))
    iterations = np.full(n, MAX_CONTACT_ITERATIONS + 1)
    todo = np.arange(n)
    for step in CONTACT_STEPS:  # the update's weight: where one cycles, the next usually settles
        found, spent, settled = _active_set(regular[todo], c[todo], clearance, step / top[todo])
        lam[todo] = found
        iterations[todo[settled]] = spent[settled]
        todo = todo[~settled]
        if todo.size == 0:
            break
    for i in todo:  # where every gamma cycled: a bounded quasi-Newton descent, then its sets solved exactly
        lam[i], iterations[i] = _bounded_descent(h[i], regular[i], c[i], clearance)
    y = np.einsum("nij,nj->ni", inverse, rhs - np.einsum("nkr,nk->nr", g, lam))
    moment = m0 + np.einsum("nkr,nr->nk", g, y)
    contact = ContactCheck(iterations, _stationarity(a_mat, rhs, y, g, lam),
                           _contact_violation(moment, lam, clearance) / scale)
    return y, contact


def _active_set(h: np.ndarray, c: np.ndarray, clearance: np.ndarray, gamma: np.ndarray):
    """Primal-dual active set for min over |lambda| <= delta of 1/2 lambda.H lambda - c.lambda
    (H definite), all rows at once: (lambda, iterations, settled) per row."""
    n, k = c.shape
    lam = np.zeros((n, k))
    moment = c.copy()
    state = np.full((n, k), 2.0)  # no set yet
    iterations = np.zeros(n, dtype=int)
    active = np.ones(n, dtype=bool)
    eye = np.eye(k)
    for _ in range(MAX_CONTACT_ITERATIONS):
        trial = lam + gamma[:, None] * moment
        new_state = np.where(trial > clearance, 1.0, np.where(trial < -clearance, -1.0, 0.0))
        free = new_state == 0
        system = np.where(free[:, :, None] & free[:, None, :], h, 0.0) + np.where(free[:, :, None], 0.0, eye)
        bound = clearance * new_state
        right = np.where(free, c - np.einsum("nij,nj->ni", h, bound), bound)
        solved = np.linalg.solve(system, right[..., None])[..., 0]
        lam = np.where(active[:, None], solved, lam)
        moment = c - np.einsum("nij,nj->ni", h, lam)
        iterations += active
        settled = np.all(new_state == state, axis=-1)
        state = np.where(active[:, None], new_state, state)
        active = active & ~settled
        if not active.any():
            break
    return lam, iterations, ~active


def _contact_violation(moment: np.ndarray, lam: np.ndarray, clearance: np.ndarray) -> np.ndarray:
    """Largest violation of the contact conditions per crank angle [N·m]: a moment where the
    joint is within its play (|lambda| < delta), or a moment against the side in contact."""
    inside = np.abs(lam) < clearance * (1.0 - 1e-9)
    against = np.where(lam > 0, np.maximum(-moment, 0.0), np.maximum(moment, 0.0))
    return np.max(np.where(inside | (clearance == 0), np.abs(moment) * (clearance > 0), against), axis=-1)


def _stationarity(a_mat, rhs, y, g, lam) -> np.ndarray:
    """|A y - b + g^T lambda| relative to |b| (plus one), per crank angle: Menabrea's compatibility."""
    residual = np.einsum("nij,nj->ni", a_mat, y) - rhs + np.einsum("nkr,nk->nr", g, lam)
    return np.max(np.abs(residual), axis=-1) / (np.max(np.abs(rhs), axis=-1) + 1.0)


def _bounded_descent(h: np.ndarray, regular: np.ndarray, c: np.ndarray, clearance: np.ndarray) -> tuple[np.ndarray, int]:
    """One crank angle's box QP by L-BFGS-B (scipy), then its sets made exact: (lambda, iterations).

    From the quasi-Newton solution the components at their bounds are fixed there and the
    others solved exactly; a free component that leaves the band is fixed at it and a
    fixed one whose moment turns against it is freed, until the sets repeat (warm-started
    active set); the most exact lambda found is kept."""
    from scipy.optimize import minimize

    found = minimize(lambda lam: 0.5 * lam @ h @ lam - c @ lam, np.zeros(c.size), jac=lambda lam: h @ lam - c,
                     bounds=list(zip(-clearance, clearance)), method="L-BFGS-B",
                     options={"ftol": 1e-30, "gtol": 1e-14, "maxiter": 10_000})
    best, best_violation = found.x, float(_contact_violation((c - h @ found.x)[None], found.x[None], clearance)[0])
    state = np.where(found.x >= clearance * (1 - 1e-7), 1.0, np.where(found.x <= -clearance * (1 - 1e-7), -1.0, 0.0))
    for _ in range(MAX_CONTACT_ITERATIONS):
        free = state == 0
        system = np.where(free[:, None] & free[None, :], regular, 0.0) + np.diag(np.where(free, 0.0, 1.0))
        bound = clearance * state
        lam = np.linalg.solve(system, np.where(free, c - regular @ bound, bound))
        moment = c - h @ lam
        violation = float(_contact_violation(moment[None], np.clip(lam, -clearance, clearance)[None], clearance)[0])
        if violation < best_violation and np.all(np.abs(lam) <= clearance * (1 + 1e-9)):
            best, best_violation = lam, violation
        new_state = np.where(free & (lam > clearance), 1.0, np.where(free & (lam < -clearance), -1.0, state))
        new_state = np.where(~free & (moment * state < 0), 0.0, new_state)
        if np.array_equal(new_state, state):
            break
        state = new_state
    return best, MAX_CONTACT_ITERATIONS + int(found.nit)


def _joined(parts: list):
    """Results of consecutive chunks of crank angles as one: arrays joined along the crank
    angles, nested results joined field by field, anything else taken from the first."""
    first = parts[0]
    if dataclasses.is_dataclass(first) and not isinstance(first, type):
        return dataclasses.replace(first, **{f.name: _joined([getattr(p, f.name) for p in parts])
                                             for f in dataclasses.fields(first)})
    if isinstance(first, np.ndarray) and first.ndim >= 1:
        return np.concatenate(parts, axis=0)
    return first

