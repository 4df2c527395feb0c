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
    crank_radius : float
        r [m], crank shaft O to crank pin A.
    rod_length : float
        l ([InertiaUNB600A]: l2) [m], crank pin A to slider pin B.
    offset : float
        e [m], distance of the line of stroke from O, on the side the crank pin swings
        into first (see :mod:`.mechanism`); 0 for a centric mechanism.

    References
    ----------
    [InertiaUNB600A] (symbols; the UNB-600A drill pump, r = 0.2 m, l2 = 1.19 m).

    Examples
    --------
    >>> unb600a = SliderCrank(0.2, 1.19)
    >>> round(unb600a.crank_ratio, 6), round(unb600a.stroke, 12)
    (0.168067, 0.4)
    """

    crank_radius: float
    rod_length: float
    offset: float = 0.0

    def check(self) -> None:
        """Raise :class:`GeometryError` unless the crank turns through a revolution (:func:`check_slider_crank`)."""
        check_slider_crank(self)

    def dead_positions(self) -> DeadCentres:
        """The dead centres (outer: largest slider distance from the crank shaft; :func:`dead_centres`) [rad, m]."""
        return dead_centres(self)

    @property
    def stroke(self) -> float:
        """Exact stroke [m] (:func:`stroke`)."""
        return stroke(self)

    @property
    def crank_ratio(self) -> float:
        """Crank ratio lambda = r / l ([InertiaUNB600A]: lambda_1 = r / l2), dimensionless."""
        return self.crank_radius / self.rod_length


@dataclass(frozen=True)
class DeadCentres:
    """Crank angles and slider positions of the outer and inner dead centres.

    Attributes
    ----------
    crank_angle_outer, crank_angle_inner : float
        phi at the outer and inner dead centre [rad].
    position_outer, position_inner : float
        Slider distance x from the crank shaft there [m].
    """

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

    Parameters
    ----------
    mechanism : SliderCrank
        r, l, e [m].

    Raises
    ------
    GeometryError
        r is not positive, or l <= r + |e|.

    Examples
    --------
    >>> check_slider_crank(SliderCrank(0.2, 0.25, 0.1))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pumpjack_cli.errors.GeometryError: the crank cannot turn: ... = 0.2 + 0.1 = 0.3 m
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

    Parameters
    ----------
    mechanism : SliderCrank
        r, l, e [m].

    Returns
    -------
    DeadCentres
        Crank angles [rad] and slider positions [m].

    Raises
    ------
    GeometryError
        The crank cannot turn (:func:`check_slider_crank`).

    Examples
    --------
    r = 0.2 m, l = 1 m, e = 0.1 m: x_outer = sqrt(1.2² - 0.1²) = 1.19583 m,
    x_inner = sqrt(0.8² - 0.1²) = 0.79373 m.

    >>> d = dead_centres(SliderCrank(0.2, 1.0, 0.1))
    >>> round(d.position_outer, 5), round(d.position_inner, 5)
    (1.19583, 0.79373)
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
    """Exact stroke, sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2); 2r for e = 0.

    Parameters
    ----------
    mechanism : SliderCrank
        r, l, e [m].

    Returns
    -------
    float
        Stroke [m].

    Examples
    --------
    The centric UNB-600A drill pump of [InertiaUNB600A], r = 0.2 m: 2r = 0.4 m; with an offset the
    stroke is longer than 2r.

    >>> round(stroke(SliderCrank(0.2, 1.19)), 12)
    0.4
    >>> round(stroke(SliderCrank(0.2, 1.0, 0.1)), 5)   # 1.19583 - 0.79373
    0.4021
    """
    return dead_centres(mechanism).stroke
