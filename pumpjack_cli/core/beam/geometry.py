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

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from ...errors import GeometryError

CLOCKWISE = 1
COUNTERCLOCKWISE = -1


@dataclass(frozen=True)
class DeadPositions:
    """Crank and beam angles at the bottom and top of the stroke [rad], and the stroke.

    The beam stops when crank and pitman are in one line: stretched out (|OB| = P + R)
    or folded (|OB| = P - R). For a conventional unit the stretched position is the
    bottom of the stroke ([SK8Rotation2013]: "crank and pitman stretched in one line").
    ``front_arm`` [m] turns beam rotation into polished-rod travel.
    """

    crank_angle_bottom: float
    crank_angle_top: float
    beam_angle_bottom: float
    beam_angle_top: float
    front_arm: float

    @property
    def stroke(self) -> float:
        """Exact polished-rod stroke S = A (psi_top - psi_bottom) [m]."""
        return self.front_arm * (self.beam_angle_top - self.beam_angle_bottom)

    @property
    def upstroke_crank_travel(self) -> float:
        """Crank rotation from the bottom to the top of the stroke [rad]."""
        return (self.crank_angle_top - self.crank_angle_bottom) % (2.0 * math.pi)

    @property
    def downstroke_crank_travel(self) -> float:
        """Crank rotation from the top back to the bottom of the stroke [rad]."""
        return 2.0 * math.pi - self.upstroke_crank_travel


@dataclass(frozen=True)
class Linkage:
    """Geometry of the four-bar of a conventional pumping unit, SI.

    Implements :class:`pumpjack_cli.core.mechanism.Mechanism`.

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
        +1 clockwise, -1 counterclockwise, seen with the well to the right.
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
        """Position of the crank shaft O relative to the centre bearing, numpy array (2,) [m]."""
        import numpy as np

        return np.array([-self.horizontal_offset, -self.vertical_offset])

    @property
    def frame_length(self) -> float:
        """K [m]: distance crank shaft - centre bearing (API Spec 11E letter K)."""
        return math.hypot(self.horizontal_offset, self.vertical_offset)

    def check(self) -> None:
        """Raise :class:`GeometryError` unless the crank turns through a full revolution."""
        check_assembly(self)

    @cached_property
    def _dead(self) -> DeadPositions:
        return dead_positions(self)

    def dead_positions(self) -> DeadPositions:
        """The exact dead positions (computed once per linkage)."""
        return self._dead

    @property
    def stroke(self) -> float:
        """Exact polished-rod stroke [m]."""
        return self._dead.stroke

    def motion(self, crank_angle: Any):
        """Link angles and their crank-angle derivatives, arrays (:func:`.linkage.motion`)."""
        from .linkage import motion

        return motion(self, crank_angle)

    def pin_rates(self, motion: Any):
        """Crank-angle derivatives of the crank pin and the equalizer bearing (:func:`.linkage.pin_rates`)."""
        from .linkage import pin_rates

        return pin_rates(self, motion)


def check_assembly(linkage: Linkage) -> None:
    """Raise :class:`GeometryError` unless the crank turns through a full revolution.

    The crank pin's distance from the centre bearing runs over [K - R, K + R]; the
    pitman and rear arm reach it at every crank angle only if (Grashof crank-rocker
    condition, strict so that the unit never locks in a toggle)
    K + R < P + C and K - R > |P - C| ([Artobolevsky1951]).
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


def assembly_angle(x: Any, y: Any, reach: Any, rear_arm: float, xp: Any = math) -> Any:
    """Beam angle psi [rad] that puts the rear-arm end B = -C e(psi) at distance ``reach`` from X = (x, y).

    Cosine rule: |B - X|^2 = C^2 + |X|^2 + 2 C |X| cos(psi - delta), delta = angle of X.
    The assembly branch keeps B on the side where (X x B)_z < 0, i.e. the equalizer
    bearing above and behind the crank pin as in every conventional unit; this branch
    cannot change during motion without passing a toggle, which :func:`check_assembly`
    excludes. ``xp`` is :mod:`math` for scalars or numpy for arrays.

    SK8-3,5-4000 at its stretched (bottom) dead position, where the beam swings to
    -23.8 degrees ([SK8Rotation2013] data, l1 horizontal, l2 vertical):

    >>> round(math.degrees(assembly_angle(-2.195, -3.0, 3.0 + 1.01, 2.5)), 1)
    -23.8
    """
    distance = xp.hypot(x, y)
    delta = xp.atan2(y, x)
    cos_gamma = (reach**2 - rear_arm**2 - distance**2) / (2.0 * rear_arm * distance)
    psi = delta + xp.acos(cos_gamma)
    return (psi + math.pi) % (2.0 * math.pi) - math.pi


def dead_positions(linkage: Linkage) -> DeadPositions:
    """Exact crank and beam angles at the ends of the stroke.

    At a dead position O, A and B are collinear, so B is at distance P + R (stretched)
    or P - R (folded) from O; the beam angle follows from the cosine rule of
    :func:`assembly_angle` applied to the triangle C-O-B, and the crank pin lies on the
    line OB (stretched: A = O + R u, folded: A = O - R u, u the unit vector O->B).

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> round(dead_positions(sk8).stroke, 4)   # seed unit SK8-3,5-4000, r = 1010 mm hole
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
    """H - G [m]: the centre bearing's height above the crank shaft from the API 11E letters
    H (centre bearing above the base) and G (crank shaft above the base) [API11E]."""
    return centre_bearing_height - crank_shaft_height


def vertical_offset_from_frame(frame_length: float, horizontal_offset: float) -> float:
    """sqrt(K^2 - I^2) [m]: the vertical offset from the API 11E letters K (straight
    distance crank shaft - centre bearing) and I (its horizontal part) [API11E].

    >>> vertical_offset_from_frame(5.0, 3.0)
    4.0
    """
    if not frame_length > horizontal_offset:
        raise GeometryError(f"K = {frame_length:.4g} m must exceed I = {horizontal_offset:.4g} m")
    return math.sqrt(frame_length * frame_length - horizontal_offset * horizontal_offset)


def pitman_lean(crank_half_spacing: float | None, equalizer_half_length: float | None) -> float:
    """|b - e| [m]: offset of the pitman's ends along the crank shaft (0 without spatial data)."""
    if crank_half_spacing is None or equalizer_half_length is None:
        return 0.0
    return abs(crank_half_spacing - equalizer_half_length)


def beam_linkage(front_arm: float, rear_arm: float, crank_radius: float, pitman: float, horizontal_offset: float,
                 vertical_offset: float, rotation: int, crank_half_spacing: float | None = None,
                 equalizer_half_length: float | None = None) -> Linkage:
    """The planar four-bar of a unit [m]; the pitman is projected on the beam plane,
    sqrt(P^2 - (b - e)^2), when the crank pins (half spacing b) and the equalizer pins
    (half length e) are spaced differently along the shaft.

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
