"""The well's path along the rod string: the seam of well geometries.

The rod-string models see the hole only through :class:`WellPath`: at a measured depth s
(along the rods, from the polished rod down) its true vertical depth, inclination phi from
the vertical and azimuth psi, and their rates per measured depth going down (for the side
load of the soft-string model and the gravity component along the string). A vertical
well is :class:`VerticalPath`; a deviation survey is one more module implementing the
protocol (``docs/architecture.md``: adding a well geometry). Measured depths are those of
the unit's ``[well]`` (the pump's depth is its measured depth: the rods are that long);
heads of fluid use the true vertical depth.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np


class WellPath(Protocol):
    """A well's path: functions of measured depth s [m] (arrays in, arrays out)."""

    def vertical_depth(self, measured_depth: Any) -> np.ndarray:
        """True vertical depth [m] below the wellhead."""
        ...

    def inclination(self, measured_depth: Any) -> np.ndarray:
        """phi [rad]: 0 vertical, pi/2 horizontal."""
        ...

    def azimuth(self, measured_depth: Any) -> np.ndarray:
        """psi [rad], clockwise from north."""
        ...

    def inclination_rate(self, measured_depth: Any) -> np.ndarray:
        """dphi/ds [rad/m], going down."""
        ...

    def azimuth_rate(self, measured_depth: Any) -> np.ndarray:
        """dpsi/ds [rad/m], going down."""
        ...

    def north_east(self, measured_depth: Any) -> np.ndarray:
        """Horizontal displacement (north, east) [m] from the wellhead, shape (..., 2)."""
        ...


@dataclass(frozen=True)
class VerticalPath:
    """A vertical hole: the vertical depth is the measured depth, every angle and rate is 0.

    >>> VerticalPath().vertical_depth(np.array([0.0, 1530.0])).tolist()
    [0.0, 1530.0]
    """

    def vertical_depth(self, measured_depth: Any) -> np.ndarray:
        return np.asarray(measured_depth, dtype=float)

    def _zero(self, measured_depth: Any) -> np.ndarray:
        return np.zeros_like(np.asarray(measured_depth, dtype=float))

    inclination = azimuth = inclination_rate = azimuth_rate = _zero

    def north_east(self, measured_depth: Any) -> np.ndarray:
        return np.zeros((*np.shape(measured_depth), 2))
