"""Geometry of a slider-crank: dimensions, the turning condition, dead centres and stroke.

Scalar geometry only, with :mod:`math` (no numpy), so that configs and ``pumpjack
units`` can use it at no start-up cost. Frame and symbols: :mod:`.mechanism`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import GeometryError


@dataclass(frozen=True)
class SliderCrank:
    """Geometry of a slider-crank, SI.

    Parameters
    ----------
    crank_radius : r [m], crank shaft O to crank pin A.
    rod_length : l (seed 001: l2) [m], crank pin A to slider pin B.
    offset : e [m], distance of the line of stroke from O, on the side the crank pin
        swings into first (see the module docstring); 0 for a centric mechanism.
    """

    crank_radius: float
    rod_length: float
    offset: float = 0.0

    def check(self) -> None:
        """Raise :class:`GeometryError` unless the crank turns through a full revolution."""
        check_slider_crank(self)

    def dead_positions(self) -> DeadCentres:
        """The dead centres (outer: largest slider distance from the crank shaft)."""
        return dead_centres(self)

    @property
    def stroke(self) -> float:
        """Exact stroke [m]."""
        return stroke(self)

    @property
    def crank_ratio(self) -> float:
        """lambda = r / l (seed 001: lambda_1 = r / l2)."""
        return self.crank_radius / self.rod_length


@dataclass(frozen=True)
class DeadCentres:
    """Crank angles [rad] and slider positions [m] of the outer and inner dead centres."""

    crank_angle_outer: float
    crank_angle_inner: float
    position_outer: float
    position_inner: float

    @property
    def stroke(self) -> float:
        """Exact stroke [m]: sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2); 2r for e = 0."""
        return self.position_outer - self.position_inner


def check_slider_crank(mechanism: SliderCrank) -> None:
    """Raise :class:`GeometryError` unless the crank turns through a full revolution.

    The rod reaches the line of stroke at every crank angle only if |r sin phi - e| < l
    for all phi, i.e. l > r + |e| (strict, so that the rod never lies across the line).
    """
    r, l, e = mechanism.crank_radius, mechanism.rod_length, mechanism.offset
    if not r > 0:
        raise GeometryError(f"crank_radius must be positive, got {r} m")
    if not l > r + abs(e):
        raise GeometryError(
            f"the crank cannot turn: rod_length l = {l:.4g} m must exceed crank_radius + |offset| "
            f"= {r:.4g} + {abs(e):.4g} = {r + abs(e):.4g} m"
        )


def dead_centres(mechanism: SliderCrank) -> DeadCentres:
    """Exact dead centres: crank and rod in one line through O.

    Outer: B = (l + r) n, A = r n, n the unit vector O->B with n_y = e/(l + r), so
    phi = arcsin(e/(l + r)) and x = sqrt((l + r)^2 - e^2). Inner: B = (l - r) n,
    A = -r n, phi = pi + arcsin(e/(l - r)), x = sqrt((l - r)^2 - e^2).
    """
    check_slider_crank(mechanism)
    r, l, e = mechanism.crank_radius, mechanism.rod_length, mechanism.offset
    return DeadCentres(
        crank_angle_outer=math.asin(e / (l + r)) % (2.0 * math.pi),
        crank_angle_inner=math.pi + math.asin(e / (l - r)),
        position_outer=math.sqrt((l + r) ** 2 - e * e),
        position_inner=math.sqrt((l - r) ** 2 - e * e),
    )


def stroke(mechanism: SliderCrank) -> float:
    """Exact stroke [m]: sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2); 2r for e = 0.

    >>> round(stroke(SliderCrank(0.2, 1.19)), 12)
    0.4
    """
    return dead_centres(mechanism).stroke
