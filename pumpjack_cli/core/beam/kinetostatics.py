"""Kinetostatics of the rational spatial mechanism: joint reactions and balancing torque.

d'Alembert's principle ([Spatial7SK12] eqs. 17-48, [PopovychSenchishak] eqs. 1-9): every link is in
equilibrium under its weight, its inertia force -m a_S at the centre of mass, its
inertia moment -J eps - w x (J w), the joint reactions and, on the beam, the
polished-rod load at E. Friction is neglected.

The rational mechanism has spherical pairs at A, A1, B, B1 and D and revolute pairs
at C (beam) and O (crank). As [Spatial7SK12] itself does in the end (its eqs. 38-39),
the structural group 2-3-4-5 is solved as one linear system: 24 equilibrium equations
(forces and moments about C for pitmans 2, 3, equalizer 4 and beam 5) in 20 unknowns
R12, R13, R24, R34, R45, R05 (3 components each) and the bearing moment M_R05 (2
components across the beam axis z). The matrix has full column rank (the rational
mechanism is statically determinate) and four dependent rows, one per idle freedom
(pitman spins, equalizer spin about its pin line and rotation about an axis along
the pitmans); loads are consistent with those freedoms when they do no work on them,
which the solver checks through the equilibrium residual. The system is solved in the
least-squares sense by its normal equations, one batched 20 x 20 solve for all crank
angles; the residual max |E x - f| is reported relative to the largest load.

The equalizer's inertia moment about its own pin line would act on an idle freedom:
the equalizer is taken to turn with the beam (kinematics, :mod:`.spatial`) and that
component is carried by the beam. Its power is unchanged because the equalizer does
not turn relative to the beam about the pin line.

Then the crank ([PopovychSenchishak] eqs. 8-9): forces give R01, moments about the shaft centre
give the balancing torque M_z along the shaft (the gearbox output torque, reported
positive when it drives the crank in its direction of rotation) and the bearing
moment M_R01 across the shaft.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from ..constants import STANDARD_GRAVITY
from .masses import MassModel
from .spatial import Z, SpatialLinkage, SpatialMotion, cross, dot, norm, ordered_sum, spatial_motion



@dataclass(frozen=True)
class LinkLoads:
    """Applied loads on one link at N crank angles: k point forces and a couple.

    Attributes
    ----------
    forces : numpy.ndarray
        Forces, shape (N, k, 3) [N].
    points : numpy.ndarray
        Their points of application relative to the centre bearing C, shape (N, k, 3) [m].
    moment : numpy.ndarray
        A couple on the link, shape (N, 3) [N·m].
    """

    forces: np.ndarray
    points: np.ndarray
    moment: np.ndarray

    def resultant(self) -> np.ndarray:
        """Sum of the forces, shape (N, 3) [N]."""
        return ordered_sum(self.forces.swapaxes(0, 1))

    def moment_about_origin(self) -> np.ndarray:
        """Moment about the centre bearing C, sum p x F + couple, shape (N, 3) [N·m]."""
        return ordered_sum(cross(self.points.swapaxes(0, 1), self.forces.swapaxes(0, 1))) + self.moment


@dataclass(frozen=True)
class AppliedLoads:
    """Weights, inertia forces and moments and the rod load, per link.

    Links numbered as in [Spatial7SK12].

    Attributes
    ----------
    crank : LinkLoads
        Link 1: both crank arms and the counterweights [N, m, N·m].
    pitman2, pitman3 : LinkLoads
        Links 2 and 3.
    equalizer : LinkLoads
        Link 4.
    beam : LinkLoads
        Link 5: beam body, horsehead and the polished-rod load at E.
    """

    crank: LinkLoads
    pitman2: LinkLoads
    pitman3: LinkLoads
    equalizer: LinkLoads
    beam: LinkLoads


@dataclass(frozen=True)
class Reactions:
    """Joint reactions and moments of the mechanism at N crank angles.

    Rij acts from link i on link j (links numbered as in [Spatial7SK12]; 0 the frame).

    Attributes
    ----------
    r12, r13, r24, r34, r45, r05, r01 : numpy.ndarray
        Reaction forces, shape (N, 3) [N].
    m05, m01 : numpy.ndarray
        Bearing moments of the beam (C) and the crank shaft (O) across their axes, shape
        (N, 3) [N·m].
    net_torque : numpy.ndarray
        M_z [N·m], the gearbox output torque on the crank, positive when it drives the
        crank in its direction of rotation ([PopovychSenchishak] eqs. 8-9).
    residual : numpy.ndarray
        Equilibrium residual of the group 2-3-4-5 relative to the largest applied load
        (dimensionless), per crank angle.

    References
    ----------
    [Spatial7SK12], [PopovychSenchishak].
    """

    r12: np.ndarray
    r13: np.ndarray
    r24: np.ndarray
    r34: np.ndarray
    r45: np.ndarray
    r05: np.ndarray
    m05: np.ndarray
    r01: np.ndarray
    m01: np.ndarray
    net_torque: np.ndarray
    residual: np.ndarray


def _point_acceleration(eps: np.ndarray, w: np.ndarray, rel: np.ndarray, base: np.ndarray | float = 0.0) -> np.ndarray:
    """a = a_base + eps x r + w x (w x r) for a point at r from a base point of the same body."""
    return base + cross(eps, rel) + cross(w, cross(w, rel))


def applied_loads(
    spatial: SpatialLinkage,
    masses: MassModel,
    sm: SpatialMotion,
    rod_load: np.ndarray,
    *,
    weights: bool = True,
    inertia: bool = True,
    gravity: float = STANDARD_GRAVITY,
) -> AppliedLoads:
    """Weights, d'Alembert inertia forces and moments and the polished-rod load on every link.

    Every centre of mass S carries m g and the inertia force -m a_S; every link the
    inertia moment -J eps (the equalizer also -(J - J_t)(w . u) w x u, u its pin line).
    Counterweights are point masses, half on each crank arm. The polished-rod load acts
    downwards on the horsehead along the vertical tangent x = A, i.e. at E = (A, 0, 0).

    Parameters
    ----------
    spatial : SpatialLinkage
        The mechanism [m].
    masses : MassModel
        Masses [kg], centres of mass [m], inertias [kg·m²].
    sm : SpatialMotion
        Positions [m], angular velocities [1/s] and accelerations [1/s²].
    rod_load : numpy.ndarray
        Polished-rod load at each crank angle [N] (dynamometer card).
    weights, inertia : bool
        Include the weights, the inertia forces and moments.
    gravity : float
        g [m/s²] ([BIPM2019]).

    Returns
    -------
    AppliedLoads
        Forces [N] at points [m] and couples [N·m], per link.

    References
    ----------
    [Spatial7SK12] eqs. 17-48; [PopovychSenchishak] eqs. 1-9.
    """
    n = sm.crank_angle.size
    g = np.array([0.0, -gravity, 0.0]) if weights else np.zeros(3)
    k_in = 1.0 if inertia else 0.0
    linkage = spatial.planar
    b = spatial.crank_half_spacing

    # A link's k points are held point by point, arrays (k, N, 3), while they are computed
    # (the per-angle vectors then broadcast over the points at full speed) and handed on as
    # the views (N, k, 3) that LinkLoads documents: the same numbers, element by element.
    def body(link_masses, points, accelerations, moment) -> LinkLoads:
        m = np.array(link_masses)[:, None, None]
        forces = m * g - k_in * m * accelerations
        return LinkLoads(forces=forces.swapaxes(0, 1), points=points.swapaxes(0, 1), moment=k_in * moment)

    # Crank: two arms and the counterweights (half on each arm), points in the arm planes.
    theta = sm.crank_angle
    sigma = linkage.rotation

    def along(angle: np.ndarray) -> np.ndarray:
        return np.stack([sigma * np.sin(angle), np.cos(angle), np.zeros(n)], axis=-1)

    arm3 = theta + spatial.arm_phase_offset  # side 3's arm (at -b), turned with its blocks by a whole-arm error
    rel = np.stack([masses.crank_arm_cg * along(theta), masses.crank_arm_cg * along(arm3),
                    masses.counterweight_radius * along(theta + masses.counterweight_phase),
                    masses.counterweight_radius * along(arm3 + masses.counterweight_phase)])
    offsets = np.array([b, -b, b, -b])[:, None, None] * Z
    acc = _point_acceleration(sm.e1, sm.w1, rel)
    half_cw = 0.5 * masses.counterweight_mass
    crank = body([masses.crank_arm_mass] * 2 + [half_cw] * 2, sm.crank_shaft + offsets + rel,
                 acc, -2.0 * masses.crank_arm_inertia * sm.e1)

    def pitman(pin: np.ndarray, top: np.ndarray, w: np.ndarray, eps: np.ndarray) -> LinkLoads:
        axis = top - pin
        rel_s = masses.pitman_cg / norm(axis)[:, None] * axis
        a_pin = _point_acceleration(sm.e1, sm.w1, pin - sm.crank_shaft)  # w1, e1 along z: z offset drops out
        a_s = _point_acceleration(eps, w, rel_s, a_pin)
        return body([masses.pitman_mass], (pin + rel_s)[None], a_s[None], -masses.pitman_inertia * eps)

    pitman2 = pitman(sm.pin_a, sm.pin_b, sm.w2, sm.e2)
    pitman3 = pitman(sm.pin_a1, sm.pin_b1, sm.w3, sm.e3)

    # Equalizer: centre of mass at D on the beam; inertia about its pin line u goes to the beam.
    u = sm.pin_b - sm.pin_b1
    u = u / norm(u)[:, None]
    spin = dot(sm.e4, u)[:, None] * u
    axial_moment = -masses.equalizer_inertia * spin
    gyro = (masses.equalizer_inertia - masses.equalizer_transverse_inertia) * dot(sm.w4, u)[:, None] * cross(sm.w4, u)
    a_d = _point_acceleration(sm.e5, sm.w5, sm.pin_d)
    equalizer = body([masses.equalizer_mass], sm.pin_d[None], a_d[None],
                     -masses.equalizer_transverse_inertia * (sm.e4 - spin) - gyro)

    # Beam body and horsehead on the beam line; rod load at the horsehead tangent point E.
    line = np.stack([np.cos(sm.beam_angle), np.sin(sm.beam_angle), np.zeros(n)], axis=-1)
    parts = np.stack([masses.beam_cg * line, masses.horsehead_cg * line])
    acc_parts = _point_acceleration(sm.e5, sm.w5, parts)
    m = np.array([masses.beam_mass, masses.horsehead_mass])[:, None, None]
    forces = np.empty((3, n, 3))
    np.subtract(m * g, k_in * m * acc_parts, out=forces[0:2])
    forces[2, :, 0], forces[2, :, 2] = 0.0, 0.0
    np.negative(np.asarray(rod_load, dtype=float), out=forces[2, :, 1])
    points = np.zeros((3, n, 3))
    points[0:2] = parts
    points[2, :, 0] = linkage.front_arm
    beam = LinkLoads(forces=forces.swapaxes(0, 1), points=points.swapaxes(0, 1),
                     moment=k_in * (-(masses.beam_inertia + masses.horsehead_inertia) * sm.e5 + axial_moment))
    return AppliedLoads(crank=crank, pitman2=pitman2, pitman3=pitman3, equalizer=equalizer, beam=beam)


def _moment_about(moment: np.ndarray, resultant: np.ndarray, point: np.ndarray) -> np.ndarray:
    """Moment of a link's loads about ``point`` from their moment about C and resultant: M_C - P x F."""
    return moment - cross(point, resultant)


def _cross_z(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The z component of a x b alone, as :func:`.spatial.cross` computes it."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _max_abs(v: np.ndarray) -> np.ndarray:
    """max |v_i| over the last axis (three components), exact in any order."""
    mag = np.abs(v)
    return np.maximum(np.maximum(mag[..., 0], mag[..., 1]), mag[..., 2])


def rational_reactions(spatial: SpatialLinkage, sm: SpatialMotion, loads: AppliedLoads) -> Reactions:
    """Reactions in every joint and the balancing torque of the rational mechanism.

    Parameters
    ----------
    spatial : SpatialLinkage
        The mechanism [m].
    sm : SpatialMotion
        Its motion (:func:`.spatial.spatial_motion`).
    loads : AppliedLoads
        The applied loads (:func:`applied_loads`) [N, m, N·m].

    Returns
    -------
    Reactions
        Reactions [N], bearing moments and balancing torque [N·m], residual
        (dimensionless).

    Notes
    -----
    The 24 equilibrium equations of the group 2-3-4-5 in its 20 unknowns are solved by
    block elimination along the structure of the group (all crank angles at once,
    closed form, no per-angle matrices):

    1. pitman 2, moments about A: w2 x R24 = M_A2, so R24 = (M_A2 x w2)/|w2|^2 + t2 e2
       with the axial force t2 unknown (w2 = AB); the component w2 . M_A2 = 0 is the
       idle-spin condition. Likewise R34 with t3 for pitman 3.
    2. equalizer forces give R45 = R24 + R34 + F4; equalizer moments about D (three
       equations) and the beam's moment about its axis z (one equation) are linear in
       (t2, t3): four equations, two unknowns, the two surplus ones being the idle
       spin and rotation of the equalizer. Solved by 2 x 2 normal equations.
    3. beam forces give R05, beam moments across z give M_R05; pitman forces give R12, R13.

    The residual of all 24 equations is then evaluated link by link and reported:
    max(|sum F| / F_ref, |sum M| / (F_ref L_ref)) with F_ref the largest applied force
    and L_ref = K + A the size of the unit. ``tests/core/beam/test_kinetostatics.py`` assembles the
    full 24 x 20 matrix independently, checks its rank (20) and this solution against it.

    References
    ----------
    [Spatial7SK12] eqs. 17-48 (closed by eqs. 38-39 for the whole group);
    [PopovychSenchishak] eqs. 1-9.
    """
    n = sm.pin_d.shape[0]
    # Each link's resultant and moment about C, once (they serve the solution and the residual).
    links = (loads.pitman2, loads.pitman3, loads.equalizer, loads.beam)
    (f2, m2), (f3, m3), (f4, m4), (f5, beam_moment) = ((link.resultant(), link.moment_about_origin()) for link in links)
    w2, w3 = sm.pin_b - sm.pin_a, sm.pin_b1 - sm.pin_a1
    n2 = w2 / norm(w2)[:, None]
    n3 = w3 / norm(w3)[:, None]
    r24_perp = cross(_moment_about(m2, f2, sm.pin_a), w2) / dot(w2, w2)[:, None]
    r34_perp = cross(_moment_about(m3, f3, sm.pin_a1), w3) / dot(w3, w3)[:, None]
    d = sm.pin_d
    arm2, arm3 = sm.pin_b - d, sm.pin_b1 - d
    q = np.empty((n, 4))
    np.negative(_moment_about(m4, f4, d) + cross(arm2, r24_perp) + cross(arm3, r34_perp), out=q[:, 0:3])
    np.negative(beam_moment[:, 2] + _cross_z(d, r24_perp + r34_perp + f4), out=q[:, 3])
    # The columns of g (N, 4, 2), one per axial force: rows of the equalizer's moments and the beam's.
    g2, g3 = np.empty((n, 4)), np.empty((n, 4))
    for column, arm, axis in ((g2, arm2, n2), (g3, arm3, n3)):
        cross(arm, axis, out=column[:, 0:3])
        column[:, 3] = _cross_z(d, axis)
    gtg00, gtg01, gtg11 = dot(g2, g2), dot(g2, g3), dot(g3, g3)
    gtq0, gtq1 = dot(g2, q), dot(g3, q)
    det = gtg00 * gtg11 - gtg01 ** 2
    t2 = (gtg11 * gtq0 - gtg01 * gtq1) / det
    t3 = (gtg00 * gtq1 - gtg01 * gtq0) / det
    r24 = r24_perp + t2[:, None] * n2
    r34 = r34_perp + t3[:, None] * n3
    r45 = r24 + r34 + f4
    r05 = -r45 - f5
    across = cross(d, r45) + beam_moment
    m05 = np.empty((n, 3))
    np.negative(across[:, 0:2], out=m05[:, 0:2])
    m05[:, 2] = -0.0  # M_R05 = -(D x R45 + M) across z only: the negated zero along it
    r12 = r24 - f2
    r13 = r34 - f3

    origin = np.zeros_like(d)
    equations = (
        (f2, m2, ((r12, sm.pin_a), (-r24, sm.pin_b)), 0.0),
        (f3, m3, ((r13, sm.pin_a1), (-r34, sm.pin_b1)), 0.0),
        (f4, m4, ((r24, sm.pin_b), (r34, sm.pin_b1), (-r45, d)), 0.0),
        (f5, beam_moment, ((r45, d), (r05, origin)), m05),
    )
    force_ref = max(float(np.max(np.abs(link.forces))) for link in links)
    force_ref = force_ref if force_ref > 0 else 1.0
    size = spatial.planar.frame_length + spatial.planar.front_arm
    residual = np.zeros(n)
    for resultant, moment_c, reactions, couple in equations:
        force = resultant + sum(f for f, _ in reactions)
        moment = moment_c + sum(cross(p, f) for f, p in reactions) + couple
        residual = np.maximum(residual, _max_abs(force) / force_ref)
        residual = np.maximum(residual, _max_abs(moment) / (force_ref * size))

    r01, m01, torque = crank_reactions(spatial, sm, loads.crank, r12, r13)
    return Reactions(
        r12=r12, r13=r13, r24=r24, r34=r34, r45=r45, r05=r05,
        m05=m05, r01=r01, m01=m01, net_torque=torque, residual=residual,
    )


def crank_reactions(
    spatial: SpatialLinkage, sm: SpatialMotion, crank: LinkLoads, r12: np.ndarray, r13: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Crank equilibrium: the shaft bearing reaction R01, its moment M_R01 and the balancing torque M_z.

        R01 + R21 + R31 + F_crank = 0,  R21 = -R12, R31 = -R13;

    about the shaft centre O, the drive couple M1 = M_z + M_R01 balances the moments of
    R21, R31 and the crank's own loads; M_z is its component along the direction of
    rotation (positive driving), M_R01 the rest (across the shaft).

    Parameters
    ----------
    spatial : SpatialLinkage
        The mechanism [m].
    sm : SpatialMotion
        Its motion.
    crank : LinkLoads
        Weights and inertia of crank arms and counterweights [N, m, N·m].
    r12, r13 : numpy.ndarray
        Forces of the crank on the pitmans, shape (N, 3) [N].

    Returns
    -------
    tuple of numpy.ndarray
        R01 (N, 3) [N], M_R01 (N, 3) [N·m], M_z (N,) [N·m].

    References
    ----------
    [PopovychSenchishak] eqs. 8-9.
    """
    resultant = crank.resultant()
    r01 = r12 + r13 - resultant
    o = sm.crank_shaft
    moment = (cross(sm.pin_a - o, -r12) + cross(sm.pin_a1 - o, -r13)
              + _moment_about(crank.moment_about_origin(), resultant, o))
    drive = -moment
    spin = spatial.crank_spin
    torque = drive @ spin
    return r01, drive - torque[:, None] * spin, torque


def rational_mechanism(
    spatial: SpatialLinkage,
    masses: MassModel,
    crank_angle: np.ndarray,
    crank_speed: np.ndarray | float,
    crank_acceleration: np.ndarray | float,
    rod_load: np.ndarray,
    *,
    weights: bool = True,
    inertia: bool = True,
) -> tuple[SpatialMotion, Reactions]:
    """Kinematics and reactions of the rational mechanism over the given crank angles.

    :func:`.spatial.spatial_motion`, then :func:`applied_loads`, then
    :func:`rational_reactions`.

    Parameters
    ----------
    spatial : SpatialLinkage
        The mechanism [m].
    masses : MassModel
        Link masses [kg], centres [m], inertias [kg·m²].
    crank_angle : numpy.ndarray
        theta [rad].
    crank_speed : float or numpy.ndarray
        Crank speed in the direction of rotation [1/s].
    crank_acceleration : float or numpy.ndarray
        Crank acceleration in the direction of rotation [1/s²].
    rod_load : numpy.ndarray
        Polished-rod load at each crank angle [N].
    weights, inertia : bool
        Include the links' weights, their inertia forces and moments.

    Returns
    -------
    tuple
        (:class:`~.spatial.SpatialMotion`, :class:`Reactions`).

    References
    ----------
    [Spatial7SK12], [PopovychSenchishak]; torque factor [API11E].

    Examples
    --------
    With massless links the balancing torque is the torque factor times the rod load
    (the torque-factor method of [API11E]). C-114D-133-54 at 90 degrees, where
    [Guo2007] prints TF = 26.45 in, under 10 000 lbf:

    >>> from pumpjack_cli.core.beam.linkage import Linkage
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> c114 = Linkage(72 * inch, 64 * inch, 24 * inch, 74.5 * inch, 64 * inch, 75 * inch)
    >>> massless = MassModel(*[0.0] * 18)
    >>> _, r = rational_mechanism(SpatialLinkage(c114, 0.6, 0.6), massless, np.radians([90.0]), 1.0, 0.0,
    ...                           np.array([10000 * lbf]))
    >>> round(float(r.net_torque[0]) / (lbf * inch) / 10000, 2)   # M_z / F = TF [in]
    26.45

    The weight of 5200 kg of counterweights at 0.83 m ([SK8Rotation2013]), crank at
    3 o'clock: M_z = -m g r = -5200 x 9.80665 x 0.83 = -42 325.5 N·m.

    >>> import dataclasses
    >>> blocks = dataclasses.replace(massless, counterweight_mass=5200.0, counterweight_radius=0.83)
    >>> sk8 = SpatialLinkage(Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0), 0.8, 0.8)
    >>> _, r = rational_mechanism(sk8, blocks, np.radians([90.0]), 1.0, 0.0, np.array([0.0]))
    >>> round(float(r.net_torque[0]), 1)
    -42325.5
    """
    theta = np.asarray(crank_angle, dtype=float)
    if theta.ndim != 1 or theta.size <= BLOCK:
        sm = spatial_motion(spatial, crank_angle, crank_speed, crank_acceleration)
        loads = applied_loads(spatial, masses, sm, rod_load, weights=weights, inertia=inertia)
        return sm, rational_reactions(spatial, sm, loads)
    omega, epsilon, load = (np.broadcast_to(np.asarray(v, dtype=float), theta.shape) for v in (crank_speed, crank_acceleration, rod_load))
    starts = range(0, theta.size, BLOCK)
    parts = [rational_mechanism(spatial, masses, theta[s:s + BLOCK], omega[s:s + BLOCK], epsilon[s:s + BLOCK],
                                load[s:s + BLOCK], weights=weights, inertia=inertia) for s in starts]
    lengths = [min(BLOCK, theta.size - s) for s in starts]
    return _joined([motion for motion, _ in parts], lengths), _joined([r for _, r in parts], lengths)


#: Crank angles solved in one batch by :func:`rational_mechanism`: the batched
#: kinetostatics holds about 2 kB per angle while it works, so a longer grid is solved
#: block by block (the motion and the reactions are the same to the bit; the residual is
#: relative to the largest load of its block).
BLOCK = 65536


def _joined(parts: list, lengths: list[int]):
    """Dataclass results of consecutive blocks of crank angles as one: the per-angle arrays
    (leading dimension the block's length in every block) joined, anything else kept."""
    joined = {}
    for field in dataclasses.fields(parts[0]):
        items = [getattr(part, field.name) for part in parts]
        per_angle = all(isinstance(item, np.ndarray) and item.ndim and item.shape[0] == n
                        for item, n in zip(items, lengths))
        joined[field.name] = np.concatenate(items) if per_angle else items[0]
    return dataclasses.replace(parts[0], **joined)
