"""Geometry of a conventional (class I) beam pumping unit: dimensions, assembly, dead positions.

The four-bar O-A-B-C: crank OA (radius R, API letter R; GOST r), pitman AB (P; l),
rear arm of the walking beam CB (C; k), frame OC from the crank shaft O to the centre
(saddle) bearing C (K; horizontal part I = l1, vertical part H - G = l2). The front
arm (A; k1) carries the horsehead, an arc of radius A about C from which the polished
rod hangs, so the polished rod moves by exactly A times the beam rotation.

Frame and conventions (used everywhere in the package):

* origin at the centre bearing C, x horizontal towards the well, y vertically up;
  the well is to the right and the crank shaft O = (-I, -(H - G)) is behind and
  below the centre bearing ([API11E], fig. 1, conventional unit);
* crank angle theta is measured from the 12 o'clock position of the crank pin in the
  direction of rotation, as [API11E] does; rotation is *clockwise* or
  *counterclockwise* as seen with the well to the right;
* beam angle psi is the angle of the front arm above the horizontal;
* pitman angle chi is the direction of the vector A->B above the horizontal.

This module holds only scalar geometry and imports neither numpy nor anything heavy:
the dead positions and the stroke are computed with :mod:`math`, which lets
``pumpjack units`` list strokes at no start-up cost. The cosine rule
:func:`assembly_angle` is written once for both :mod:`math` scalars and numpy arrays;
the array kinematics is :mod:`.linkage`.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from ...errors import GeometryError

CLOCKWISE = 1
COUNTERCLOCKWISE = -1


@dataclass(frozen=True)
class DeadPositions:
    """Crank and beam angles at the bottom and top of the stroke, and the stroke.

    The beam stops when crank and pitman are in one line: stretched out (|OB| = P + R)
    or folded (|OB| = P - R). For a conventional unit the stretched position is the
    bottom of the stroke ([SK8Rotation2013]: "crank and pitman stretched in one line").

    Attributes
    ----------
    crank_angle_bottom, crank_angle_top : float
        Crank angles theta of the bottom and top of the stroke, from 12 o'clock in the
        direction of rotation ([API11E]) [rad].
    beam_angle_bottom, beam_angle_top : float
        Beam angles psi there, front arm above horizontal [rad].
    front_arm : float
        A [m]: turns beam rotation into polished-rod travel.

    References
    ----------
    [SK8Rotation2013] (start of the upstroke), [API11E] (angle convention).
    """

    crank_angle_bottom: float
    crank_angle_top: float
    beam_angle_bottom: float
    beam_angle_top: float
    front_arm: float

    @property
    def stroke(self) -> float:
        """Exact polished-rod stroke S = A (psi_top - psi_bottom) [m] (the horsehead is an arc of radius A)."""
        return self.front_arm * (self.beam_angle_top - self.beam_angle_bottom)

    @property
    def upstroke_crank_travel(self) -> float:
        """Crank rotation from the bottom to the top of the stroke, (theta_top - theta_bottom) mod 2 pi [rad]."""
        return (self.crank_angle_top - self.crank_angle_bottom) % (2.0 * math.pi)

    @property
    def downstroke_crank_travel(self) -> float:
        """Crank rotation from the top back to the bottom of the stroke, 2 pi - upstroke travel [rad]."""
        return 2.0 * math.pi - self.upstroke_crank_travel


@dataclass(frozen=True)
class Linkage:
    """Geometry of the four-bar O-A-B-C of a conventional (class I) pumping unit, SI.

    Implements :class:`pumpjack_cli.core.mechanism.Mechanism` for class I units. The letters are those of
    [API11E], the second names those of GOST 5866-76 units and [SK8Rotation2013].

    Parameters
    ----------
    front_arm : float
        A, k1 [m]: centre bearing to horsehead arc.
    rear_arm : float
        C, k [m]: centre bearing to equalizer bearing.
    crank_radius : float
        R, r [m]: crank shaft to crank pin.
    pitman : float
        P, l [m]: crank pin to equalizer bearing.
    horizontal_offset : float
        I, l1 [m]: horizontal distance crank shaft - centre bearing.
    vertical_offset : float
        H - G, l2 [m]: height of the centre bearing above the crank shaft.
    rotation : int
        +1 clockwise, -1 counterclockwise, seen with the well to the right
        (dimensionless).

    References
    ----------
    [API11E] (letters, conventional unit), [SK8Rotation2013] (GOST names, SK8-3,5-4000).

    Examples
    --------
    SK8-3,5-4000 with the 1010 mm crank hole ([SK8Rotation2013]); K = sqrt(2.195² + 3²):

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> round(sk8.frame_length, 4)
    3.7173
    """

    front_arm: float
    rear_arm: float
    crank_radius: float
    pitman: float
    horizontal_offset: float
    vertical_offset: float
    rotation: int = CLOCKWISE

    @property
    def crank_shaft(self):
        """Position of the crank shaft O relative to the centre bearing, (-I, -(H - G)), numpy array (2,) [m]."""
        import numpy as np

        return np.array([-self.horizontal_offset, -self.vertical_offset])

    @property
    def frame_length(self) -> float:
        """K = sqrt(I^2 + (H - G)^2) [m]: distance crank shaft - centre bearing ([API11E] letter K)."""
        return math.hypot(self.horizontal_offset, self.vertical_offset)

    def check(self) -> None:
        """Raise :class:`GeometryError` unless the crank turns through a full revolution."""
        check_assembly(self)

    @cached_property
    def _dead(self) -> DeadPositions:
        return dead_positions(self)

    def dead_positions(self) -> DeadPositions:
        """The exact dead positions (:func:`dead_positions`, computed once per linkage)."""
        return self._dead

    @property
    def stroke(self) -> float:
        """Exact polished-rod stroke S = A (psi_top - psi_bottom) [m]."""
        return self._dead.stroke

    def motion(self, crank_angle: Any):
        """Link angles [rad] and their crank-angle derivatives at crank angles [rad] (:func:`.linkage.motion`).

        The motion on a shared grid (a read-only array of at least :data:`CACHED_GRID` angles,
        as :func:`~pumpjack_cli.core.sampling.crank_grid` makes them) is kept (read-only) for
        the next call with the same angles: the run layer asks for the same summary grid many
        times per card, and a batch for every card of a unit. Other arrays (a card's own
        angles, the time fit's iterates) are asked for once and are not kept."""
        from .linkage import motion

        if _shared(crank_angle):
            return _cached_motion(self, crank_angle.tobytes())
        return motion(self, crank_angle)

    def rod_position(self, crank_angle: Any):
        """Polished-rod position above the bottom of the stroke, s = A (psi - psi_bottom) [m],
        at crank angles [rad] ([SK8Rotation2013] eq. 6 integrated: the horsehead arc)."""
        return self.motion(crank_angle).rod_position if _shared(crank_angle) else self.rod_motion(crank_angle)[0]

    def rod_motion(self, crank_angle: Any):
        """The polished-rod position [m] and torque factor [m] alone (:func:`.linkage.rod_motion`)."""
        from .linkage import rod_motion

        return rod_motion(self, crank_angle)

    def torque_factor(self, crank_angle: Any):
        """TF = ds/dtheta = A psi' [m] at crank angles [rad] ([API11E]; [KretzerSWPSC])."""
        return self.motion(crank_angle).torque_factor

    def turned(self) -> Linkage:
        """The same four-bar turning the other way."""
        return dataclasses.replace(self, rotation=-self.rotation)

    def joint_rates(self, motion: Any):
        """Crank-angle derivatives of crank pin and equalizer bearing [m/rad, m/rad²] (:func:`.linkage.joint_rates`)."""
        from .linkage import joint_rates

        return joint_rates(self, motion)

    @property
    def lever_class(self) -> str:
        """``"I"``: the equalizer bearing behind the centre bearing ([API11E])."""
        return "I"

    @property
    def horsehead_arm(self) -> float:
        """A [m]: radius of the horsehead arc."""
        return self.front_arm

    @property
    def equalizer_arm(self) -> float:
        """-C [m]: the equalizer bearing a rear-arm length behind the centre bearing."""
        return -self.rear_arm

    @property
    def pitman_length(self) -> float:
        """P [m] (the planar pitman)."""
        return self.pitman

    def equivalent_crank(self):
        """Amplitude R A / C [m] and crank ratio R / P of the textbook laws ([Aliverdizade1951])."""
        from ..mechanism import EquivalentCrank

        return EquivalentCrank(self.crank_radius * self.front_arm / self.rear_arm, self.crank_radius / self.pitman)

    def chord_slider_crank(self):
        """The chord law's slider-crank (:func:`.linkage.chord_slider_crank`)."""
        from .linkage import chord_slider_crank

        return chord_slider_crank(self)


#: Shared grids of at least this many crank angles have their motion cached (:meth:`Linkage.motion`).
CACHED_GRID = 360


def _shared(theta: Any) -> bool:
    """Whether crank angles are a shared grid whose motion is kept (:meth:`Linkage.motion`)."""
    return (getattr(getattr(theta, "flags", None), "writeable", True) is False
            and getattr(theta, "size", 0) >= CACHED_GRID and getattr(theta, "dtype", None) == float)


@functools.lru_cache(maxsize=64)
def _cached_motion(linkage: Linkage, crank_angle: bytes):
    import numpy as np

    from .linkage import motion

    found = motion(linkage, np.frombuffer(crank_angle))
    for value in vars(found).values():
        value.flags.writeable = False
    return found


#: The transmission angle between pitman and rear arm may come no nearer a line than this [deg]:
#: at a toggle the beam's acceleration has no bound (the bundled and catalogue units keep 35-90 deg).
MIN_TRANSMISSION_ANGLE = 10.0


def check_assembly(linkage: Linkage) -> None:
    """Raise :class:`GeometryError` unless the crank turns through a full revolution.

    The crank pin's distance from the centre bearing runs over [K - R, K + R]; the
    pitman and rear arm reach it at every crank angle only if (Grashof crank-rocker
    condition, strict so that the unit never locks in a toggle)

        K + R < P + C  and  K - R > |P - C|;

    and the transmission angle mu between pitman and rear arm, cos mu = (P^2 + C^2 - d^2) / (2 P C)
    at the crank pin's distance d = K -+ R from the centre bearing, stays at least
    :data:`MIN_TRANSMISSION_ANGLE` from 0 and 180 deg (near a toggle the motion has no bound).

    Every length must be finite and, except the two offsets, positive.

    Parameters
    ----------
    linkage : Linkage
        The four-bar, lengths [m].

    Raises
    ------
    GeometryError
        A length is not finite or not positive, or the crank cannot turn.

    References
    ----------
    [Artobolevsky1951] (Grashof's condition).

    Examples
    --------
    A 2 m crank on SK8-3,5-4000: K + R = 3.717 + 2 = 5.717 m > P + C = 5.5 m.

    >>> check_assembly(Linkage(3.5, 2.5, 2.0, 3.0, 2.195, 3.0))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pumpjack_cli.errors.GeometryError: the unit cannot assemble: ... (K + R = 3.717 + 2 = 5.717 m) ... (P + C = 3 + 2.5 = 5.5 m) ...
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
        if not math.isfinite(value):
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
    for reach, where in ((k - r, "nearest"), (k + r, "farthest from")):
        cosine = (p * p + c * c - reach * reach) / (2.0 * p * c)
        angle = math.degrees(math.acos(max(-1.0, min(1.0, cosine))))
        if min(angle, 180.0 - angle) < MIN_TRANSMISSION_ANGLE:
            raise GeometryError(
                f"the unit is near a toggle: with the crank pin {where} the centre bearing the pitman and rear arm "
                f"stand {angle:.4g} deg apart, within {MIN_TRANSMISSION_ANGLE:g} deg of a line (pumping units keep "
                f"30 deg and more); the motion there has no bound: check crank_radius, pitman, rear_arm and the offsets"
            )


def assembly_angle(x: Any, y: Any, reach: Any, rear_arm: float, xp: Any = math) -> Any:
    """Beam angle that puts the rear-arm end B = -C e(psi) at distance ``reach`` from X = (x, y).

    Cosine rule on the triangle C-X-B:

        |B - X|^2 = C^2 + |X|^2 + 2 C |X| cos(psi - delta),  delta = angle of X,

    so psi = delta + arccos((reach^2 - C^2 - |X|^2) / (2 C |X|)), wrapped to [-pi, pi).
    The assembly branch keeps B on the side where (X x B)_z < 0, i.e. the equalizer
    bearing above and behind the crank pin as in every conventional unit; this branch
    cannot change during motion without passing a toggle, which :func:`check_assembly`
    excludes. This is the closed-vector-loop solution of [SK8Rotation2013] eqs. 2-6
    written for the beam angle directly.

    Parameters
    ----------
    x, y : float or numpy.ndarray
        Point X relative to the centre bearing [m] (the crank pin, or the crank shaft at
        a dead position).
    reach : float or numpy.ndarray
        Required distance |B - X| [m] (the pitman P, or P +- R at a dead position).
    rear_arm : float
        C [m].
    xp : module
        :mod:`math` for scalars or :mod:`numpy` for arrays.

    Returns
    -------
    float or numpy.ndarray
        psi, front arm above horizontal [rad].

    References
    ----------
    [SK8Rotation2013] eqs. 2-6.

    Examples
    --------
    SK8-3,5-4000 at its stretched (bottom) and folded (top) dead positions: the beam
    swings from -23.8 to +23.9 degrees ([SK8Rotation2013] data, l1 horizontal, l2
    vertical, as ``configs/sk8-3.5-4000.toml`` states):

    >>> round(math.degrees(assembly_angle(-2.195, -3.0, 3.0 + 1.01, 2.5)), 1)
    -23.8
    >>> round(math.degrees(assembly_angle(-2.195, -3.0, 3.0 - 1.01, 2.5)), 1)
    23.9
    """
    distance = xp.hypot(x, y)
    delta = xp.atan2(y, x)
    cos_gamma = (reach**2 - rear_arm**2 - distance**2) / (2.0 * rear_arm * distance)
    psi = delta + xp.acos(cos_gamma)
    return (psi + math.pi) % (2.0 * math.pi) - math.pi


def dead_positions(linkage: Linkage) -> DeadPositions:
    """Exact crank and beam angles at the ends of the stroke, in closed form.

    At a dead position O, A and B are collinear, so B is at distance P + R (stretched)
    or P - R (folded) from O; the beam angle follows from the cosine rule of
    :func:`assembly_angle` applied to the triangle C-O-B, and the crank pin lies on the
    line OB (stretched: A = O + R u, folded: A = O - R u, u the unit vector O->B), so
    theta = atan2(s u_x, u_y) for the stretched and atan2(-s u_x, -u_y) for the folded
    position, s the rotation. The lower beam angle is the bottom of the stroke.

    Parameters
    ----------
    linkage : Linkage
        The four-bar, lengths [m].

    Returns
    -------
    DeadPositions
        Crank and beam angles of bottom and top [rad]; ``stroke`` [m].

    Raises
    ------
    GeometryError
        The crank cannot turn (:func:`check_assembly`).

    References
    ----------
    [SK8Rotation2013] (the upstroke starts with crank and pitman stretched in one line).

    Examples
    --------
    SK8-3,5-4000 with the 1010 mm crank hole of [SK8Rotation2013]: the beam swings
    -23.80 to +23.88 degrees (:func:`assembly_angle`), so the stroke is
    3.5 m x 47.68 degrees x pi/180 = 2.913 m:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> dead = dead_positions(sk8)
    >>> round(math.degrees(dead.beam_angle_bottom), 2), round(math.degrees(dead.beam_angle_top), 2)
    (-23.8, 23.88)
    >>> round(dead.stroke, 4)
    2.9128
    """
    check_assembly(linkage)
    ox, oy = -linkage.horizontal_offset, -linkage.vertical_offset
    found = []
    for reach, side in ((linkage.pitman + linkage.crank_radius, 1.0), (linkage.pitman - linkage.crank_radius, -1.0)):
        psi = assembly_angle(ox, oy, reach, linkage.rear_arm)
        bx, by = -linkage.rear_arm * math.cos(psi) - ox, -linkage.rear_arm * math.sin(psi) - oy
        length = math.hypot(bx, by)
        theta = math.atan2(linkage.rotation * side * bx / length, side * by / length) % (2.0 * math.pi)
        found.append((theta, psi))
    (theta_s, psi_s), (theta_f, psi_f) = found
    if psi_s < psi_f:
        return DeadPositions(theta_s, theta_f, psi_s, psi_f, linkage.front_arm)
    return DeadPositions(theta_f, theta_s, psi_f, psi_s, linkage.front_arm)


def vertical_offset_from_heights(centre_bearing_height: float, crank_shaft_height: float) -> float:
    """The centre bearing's height above the crank shaft, H - G, from the [API11E] letters.

    Parameters
    ----------
    centre_bearing_height : float
        H, centre bearing above the base [m].
    crank_shaft_height : float
        G, crank shaft above the base [m].

    Returns
    -------
    float
        H - G [m].

    References
    ----------
    [API11E].

    Examples
    --------
    C-114D-133-54 of [Guo2007], Table 12.1: H = 116 in, G = 41 in.

    >>> round(vertical_offset_from_heights(116 * 0.0254, 41 * 0.0254) / 0.0254, 9)
    75.0
    """
    return centre_bearing_height - crank_shaft_height


def vertical_offset_from_frame(frame_length: float, horizontal_offset: float) -> float:
    """The vertical offset sqrt(K^2 - I^2) from the [API11E] letters K and I.

    Parameters
    ----------
    frame_length : float
        K, straight distance crank shaft - centre bearing [m].
    horizontal_offset : float
        I, its horizontal part [m].

    Returns
    -------
    float
        H - G [m].

    Raises
    ------
    GeometryError
        K does not exceed I.

    References
    ----------
    [API11E].

    Examples
    --------
    >>> vertical_offset_from_frame(5.0, 3.0)
    4.0
    """
    if not frame_length > horizontal_offset:
        raise GeometryError(f"K = {frame_length:.4g} m must exceed I = {horizontal_offset:.4g} m")
    return math.sqrt(frame_length * frame_length - horizontal_offset * horizontal_offset)


def pitman_lean(crank_half_spacing: float | None, equalizer_half_length: float | None) -> float:
    """Offset |b - e| of the pitman's ends along the crank shaft (0 without spatial data).

    Parameters
    ----------
    crank_half_spacing : float or None
        b, crank shaft mid-plane to each crank pin [m].
    equalizer_half_length : float or None
        e, equalizer bearing D to each equalizer pin [m].

    Returns
    -------
    float
        |b - e| [m], 0 when either is None.

    Examples
    --------
    >>> pitman_lean(1.0, 0.6), pitman_lean(None, 0.6)
    (0.4, 0.0)
    """
    if crank_half_spacing is None or equalizer_half_length is None:
        return 0.0
    return abs(crank_half_spacing - equalizer_half_length)


def beam_linkage(front_arm: float, rear_arm: float, crank_radius: float, pitman: float, horizontal_offset: float,
                 vertical_offset: float, rotation: int, crank_half_spacing: float | None = None,
                 equalizer_half_length: float | None = None) -> Linkage:
    """The planar four-bar of a unit, with the pitman projected on the beam plane.

    When the crank pins (half spacing b) and the equalizer pins (half length e) are
    spaced differently along the shaft, the pitman leans and its projection on the beam
    plane, P_xy = sqrt(P^2 - (b - e)^2), is the planar pitman.

    Parameters
    ----------
    front_arm, rear_arm, crank_radius, pitman, horizontal_offset, vertical_offset : float
        A, C, R, P, I, H - G [m] as in :class:`Linkage`; ``pitman`` is the true length.
    rotation : int
        +1 clockwise, -1 counterclockwise, seen with the well to the right.
    crank_half_spacing, equalizer_half_length : float or None
        b and e [m] of the spatial model, or None.

    Returns
    -------
    Linkage
        The planar four-bar [m].

    Raises
    ------
    GeometryError
        The pitman is not longer than |b - e|.

    Examples
    --------
    A 5 m pitman leaning by |1 - 4| = 3 m projects to 4 m (a 3-4-5 triangle):

    >>> beam_linkage(3.5, 2.5, 1.01, 5.0, 2.195, 3.0, CLOCKWISE, 1.0, 4.0).pitman
    4.0
    """
    lean = pitman_lean(crank_half_spacing, equalizer_half_length)
    if lean >= pitman:
        raise GeometryError(
            f"pitman ({pitman:.4g} m) is shorter than the offset of its ends along the crank shaft "
            f"|crank_half_spacing - equalizer_half_length| = {lean:.4g} m"
        )
    return Linkage(front_arm, rear_arm, crank_radius, math.sqrt(pitman**2 - lean**2), horizontal_offset,
                   vertical_offset, rotation)
