"""A deviation survey as a well path: minimum curvature between the stations.

The stations (measured depth s_j, inclination phi_j from the vertical, azimuth psi_j
clockwise from north) give unit tangents t_j = (sin phi cos psi, sin phi sin psi, cos phi)
in (north, east, down). Between two stations the hole is the circular arc in the plane of
t_j and t_j+1 (the minimum-curvature method of Mason & Taylor and Zaremba, 1971, the
industry standard, [SawarynThorogood2005]): with the dogleg
beta = arccos(t_j . t_j+1) and f in [0, 1] the share of the interval's length D,

    t(f) = (sin((1 - f) beta) t_j + sin(f beta) t_j+1) / sin(beta),
    r(f) = r_j + D / (beta sin beta) ((cos((1 - f) beta) - cos(beta)) t_j + (1 - cos(f beta)) t_j+1),

so that r(1) - r_j = D/2 (t_j + t_j+1) RF with the ratio factor RF = (2 / beta) tan(beta / 2)
([SawarynThorogood2005] eq. 3); straight lines (beta -> 0) as the limit. The curvature
is constant on each arc, beta / D (the dogleg severity), and jumps at the stations.
Below the last station the path goes on straight.

Implements :class:`~pumpjack_cli.core.rods.path.WellPath`; the rates phi' and psi' of the
tangent, t' = phi' e_phi + psi' sin(phi) e_psi, follow from t' = beta / D (cos(f beta)
t_j+1 - cos((1 - f) beta) t_j) / sin(beta). At a vertical point psi is undefined: the
azimuth is then that of the direction the hole leaves the vertical in (psi' = 0 and
phi' = |t'| there, the limits along the arc).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...errors import DownholeError

#: Below this dogleg [rad] an interval is a straight line (its series terms are below rounding).
STRAIGHT = 1e-9
#: Largest dogleg between two stations [rad]: the arc's plane is undefined at 180 degrees.
LARGEST_DOGLEG = np.pi - 1e-6
#: Largest dogleg severity a survey may give [rad/m], 10 deg/m (300 deg/30 m): beyond the sharpest
#: (short-radius) drilled builds, about 3 deg/ft; sharper is a survey slip (stations out of order,
#: angles in the wrong unit), and a string through it would carry side loads without bound.
LARGEST_SEVERITY = np.radians(10.0)


def tangent(inclination, azimuth) -> np.ndarray:
    """Unit tangent (north, east, down) of a hole going down at inclination phi, azimuth psi [rad]; shape (..., 3)."""
    phi, psi = np.asarray(inclination, dtype=float), np.asarray(azimuth, dtype=float)
    return np.stack([np.sin(phi) * np.cos(psi), np.sin(phi) * np.sin(psi), np.cos(phi)], axis=-1)


def _sinc_ratio(beta: np.ndarray, f: np.ndarray) -> np.ndarray:
    """sin(f beta) / sin(beta), with its limit f at beta -> 0."""
    small = beta < STRAIGHT
    safe = np.where(small, 1.0, beta)
    return np.where(small, f, np.sin(f * safe) / np.sin(safe))


def _arc_weights(beta: np.ndarray, f: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(cos((1 - f) beta) - cos beta) / (beta sin beta) and (1 - cos(f beta)) / (beta sin beta):
    the weights of t_j and t_j+1 in (r - r_j) / D; limits f - f^2/2 and f^2/2 for a straight line."""
    small = beta < STRAIGHT
    b = np.where(small, 1.0, beta)
    denominator = b * np.sin(b)
    # cos(a) - cos(b) = 2 sin((a + b)/2) sin((b - a)/2), free of cancellation for small angles
    first = 2.0 * np.sin((2.0 - f) * b / 2.0) * np.sin(f * b / 2.0) / denominator
    second = 2.0 * np.sin(f * b / 2.0) ** 2 / denominator
    return np.where(small, f - 0.5 * f * f, first), np.where(small, 0.5 * f * f, second)


@dataclass(frozen=True)
class SurveyPath:
    """A well path through survey stations by minimum curvature (module docstring).

    Parameters
    ----------
    station_depth : numpy.ndarray
        Measured depths s_j [m] from the wellhead, strictly increasing, the first 0 (the wellhead).
    station_inclination : numpy.ndarray
        phi_j [rad] in [0, pi].
    station_azimuth : numpy.ndarray
        psi_j [rad], clockwise from north.

    Raises
    ------
    DownholeError
        Stations that are not increasing from 0, an inclination outside [0, 180] degrees, a
        value that is not finite, a dogleg of 180 degrees between two stations, or a dogleg
        severity above :data:`LARGEST_SEVERITY`.

    Examples
    --------
    A hole built from vertical at 3 degrees per 30 m to 45 degrees: the arc's radius is
    R = 30 / (3 pi / 180) = 572.96 m, so at the end of the build the true vertical depth has
    grown by R sin 45 deg = 405.14 m over 450 m of hole.

    >>> path = SurveyPath(np.array([0.0, 450.0]), np.radians([0.0, 45.0]), np.radians([0.0, 0.0]))
    >>> round(float(path.vertical_depth(450.0)), 2), round(float(np.degrees(path.inclination(225.0))), 6)
    (405.14, 22.5)
    """

    station_depth: np.ndarray
    station_inclination: np.ndarray
    station_azimuth: np.ndarray
    _tangents: np.ndarray = field(init=False, repr=False)
    _dogleg: np.ndarray = field(init=False, repr=False)
    _positions: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        s = np.atleast_1d(np.asarray(self.station_depth, dtype=float))
        phi = np.atleast_1d(np.asarray(self.station_inclination, dtype=float))
        psi = np.atleast_1d(np.asarray(self.station_azimuth, dtype=float))
        if not (s.ndim == phi.ndim == psi.ndim == 1 and s.size == phi.size == psi.size and s.size >= 1):
            raise DownholeError("a survey needs one measured depth, inclination and azimuth per station")
        if not (np.isfinite(s).all() and np.isfinite(phi).all() and np.isfinite(psi).all()):
            raise DownholeError("survey stations must be finite")
        if s[0] != 0.0 or (s.size > 1 and not np.all(np.diff(s) > 0)):
            raise DownholeError("survey stations must start at the wellhead (measured depth 0) and go down")
        if not np.all((phi >= 0) & (phi <= np.pi)):
            raise DownholeError("survey inclinations must lie between 0 and 180 degrees")
        t = tangent(phi, psi)
        # the angle between the tangents, accurate for small angles too (arccos of the dot product is not)
        beta = np.arctan2(np.linalg.norm(np.cross(t[:-1], t[1:]), axis=-1), np.sum(t[:-1] * t[1:], axis=-1))
        if np.any(beta > LARGEST_DOGLEG):
            j = int(np.flatnonzero(beta > LARGEST_DOGLEG)[0])
            raise DownholeError(f"the survey turns by 180 degrees between {s[j]:g} m and {s[j + 1]:g} m")
        length = np.diff(s)
        sharp = np.flatnonzero(beta > LARGEST_SEVERITY * length)
        if sharp.size:
            j = int(sharp[0])
            raise DownholeError(f"the survey turns by {np.degrees(beta[j]):.4g} degrees over {length[j]:.4g} m between "
                                f"{s[j]:g} m and {s[j + 1]:g} m: {np.degrees(beta[j] / length[j]):.4g} deg/m, above the "
                                f"{np.degrees(LARGEST_SEVERITY):g} deg/m of the sharpest drilled builds")
        first, second = _arc_weights(beta, np.ones_like(beta))
        steps = length[:, None] * (first[:, None] * t[:-1] + second[:, None] * t[1:])
        positions = np.vstack([np.zeros((1, 3)), np.cumsum(steps, axis=0)])
        for name, value in (("station_depth", s), ("station_inclination", phi), ("station_azimuth", psi), ("_tangents", t),
                            ("_dogleg", beta), ("_positions", positions)):
            object.__setattr__(self, name, value)

    # --- where a measured depth lies ---------------------------------------------------

    def _locate(self, measured_depth: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Interval index j, share f of it, its dogleg beta and length D for each depth; past the
        last station, f counts along a straight continuation of length D = 1 m per unit f."""
        s = np.clip(np.asarray(measured_depth, dtype=float), 0.0, None)
        stations = self.station_depth
        if stations.size == 1:
            j = np.zeros(s.shape, dtype=int)
            return j, s, np.zeros(s.shape), np.ones(s.shape)
        j = np.clip(np.searchsorted(stations, s, side="right") - 1, 0, stations.size - 2)
        length = stations[j + 1] - stations[j]
        beyond = s > stations[-1]
        f = np.where(beyond, 1.0, (s - stations[j]) / length)
        return j, f, self._dogleg[j], length

    def _beyond(self, measured_depth: Any) -> np.ndarray:
        """Distance below the last station [m] (0 above it)."""
        return np.clip(np.asarray(measured_depth, dtype=float) - self.station_depth[-1], 0.0, None)

    def tangent(self, measured_depth: Any) -> np.ndarray:
        """Unit tangent (north, east, down) going down, shape (..., 3)."""
        j, f, beta, _ = self._locate(measured_depth)
        t = self._tangents
        if t.shape[0] == 1:
            return np.broadcast_to(t[0], (*np.shape(measured_depth), 3)).copy()
        return _sinc_ratio(beta, 1.0 - f)[..., None] * t[j] + _sinc_ratio(beta, f)[..., None] * t[j + 1]

    def tangent_rate(self, measured_depth: Any) -> np.ndarray:
        """dt/ds [1/m] going down, shape (..., 3): beta / D times the arc's unit normal (0 on straight parts)."""
        j, f, beta, length = self._locate(measured_depth)
        t = self._tangents
        if t.shape[0] == 1:
            return np.zeros((*np.shape(measured_depth), 3))
        small = beta < STRAIGHT
        b = np.where(small, 1.0, beta)
        scale = np.where(small | (self._beyond(measured_depth) > 0), 0.0, b / (length * np.sin(b)))
        return scale[..., None] * (np.cos(f * b)[..., None] * t[j + 1] - np.cos((1.0 - f) * b)[..., None] * t[j])

    def position(self, measured_depth: Any) -> np.ndarray:
        """(north, east, true vertical depth) [m] of each measured depth, shape (..., 3)."""
        j, f, beta, length = self._locate(measured_depth)
        t, r = self._tangents, self._positions
        if t.shape[0] == 1:
            return np.asarray(measured_depth, dtype=float)[..., None] * t[0]
        first, second = _arc_weights(beta, f)
        along = length[..., None] * (first[..., None] * t[j] + second[..., None] * t[j + 1])
        return r[j] + along + self._beyond(measured_depth)[..., None] * t[-1]

    # --- the WellPath protocol ---------------------------------------------------------

    def vertical_depth(self, measured_depth: Any) -> np.ndarray:
        """True vertical depth [m] below the wellhead."""
        return self.position(measured_depth)[..., 2]

    def north_east(self, measured_depth: Any) -> np.ndarray:
        """Horizontal position (north, east) [m] from the wellhead, shape (..., 2)."""
        return self.position(measured_depth)[..., :2]

    def inclination(self, measured_depth: Any) -> np.ndarray:
        """phi [rad]: 0 vertical, pi/2 horizontal."""
        return self._angles(measured_depth)[2]

    def azimuth(self, measured_depth: Any) -> np.ndarray:
        """psi [rad] in [0, 2 pi), clockwise from north."""
        return self._angles(measured_depth)[3]

    def _angles(self, measured_depth: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        t, rate = self.tangent(measured_depth), self.tangent_rate(measured_depth)
        horizontal = np.hypot(t[..., 0], t[..., 1])
        phi = np.arctan2(horizontal, t[..., 2])
        leaving = np.where(horizontal[..., None] > 1e-12, t, rate)  # the direction the hole leaves the vertical in
        psi = np.mod(np.arctan2(leaving[..., 1], leaving[..., 0]), 2.0 * np.pi)
        return t, rate, phi, psi

    def inclination_rate(self, measured_depth: Any) -> np.ndarray:
        """dphi/ds [rad/m] going down."""
        t, rate, phi, _ = self._angles(measured_depth)
        horizontal = np.hypot(t[..., 0], t[..., 1])
        # d(sin phi)/ds = cos(phi) phi' = (h . h') / |h|, and -sin(phi) phi' = t_down'; whichever is better conditioned
        along = np.where(horizontal > 1e-12, (t[..., 0] * rate[..., 0] + t[..., 1] * rate[..., 1])
                         / np.where(horizontal > 1e-12, horizontal, 1.0), np.hypot(rate[..., 0], rate[..., 1]))
        return np.where(np.abs(np.cos(phi)) > 0.5, along / np.where(np.abs(np.cos(phi)) > 0.5, np.cos(phi), 1.0),
                        -rate[..., 2] / np.where(np.abs(np.cos(phi)) > 0.5, 1.0, np.sin(phi)))

    def azimuth_rate(self, measured_depth: Any) -> np.ndarray:
        """dpsi/ds [rad/m] going down (0 where the hole is vertical)."""
        t, rate, _, _ = self._angles(measured_depth)
        horizontal2 = t[..., 0] ** 2 + t[..., 1] ** 2
        return np.where(horizontal2 > 1e-24, (t[..., 0] * rate[..., 1] - t[..., 1] * rate[..., 0])
                        / np.where(horizontal2 > 1e-24, horizontal2, 1.0), 0.0)

    def dogleg_severity(self, measured_depth: Any) -> np.ndarray:
        """Curvature |dt/ds| [rad/m]: the dogleg per measured length."""
        return np.linalg.norm(self.tangent_rate(measured_depth), axis=-1)

    @property
    def depth(self) -> float:
        """Measured depth of the last station [m]."""
        return float(self.station_depth[-1])

    @property
    def vertical(self) -> bool:
        """True when every station is vertical: the path is the vertical hole."""
        return bool(np.all(self.station_inclination == 0.0))

