"""Crank-angle grids and the extremes of periodic sampled curves, for every model.

Every summary extreme in the package (peak rod load, max torque and the crank angle
where it occurs) is computed here, so that the rule is stated once.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Extreme:
    """An extreme value and the crank angle where it occurs.

    Attributes
    ----------
    value : float
        The extreme, in the unit of the sampled curve.
    crank_angle : float
        Crank angle of the extreme [rad].
    """

    value: float
    crank_angle: float


def crank_grid(steps: int) -> np.ndarray:
    """Equally spaced crank angles over one revolution, from 0, endpoint excluded.

    theta_k = 2 pi k / steps, k = 0 .. steps - 1.

    Parameters
    ----------
    steps : int
        Number of crank positions per revolution (dimensionless).

    Returns
    -------
    numpy.ndarray
        Crank angles, shape (steps,) [rad].

    Examples
    --------
    >>> crank_grid(4).tolist() == [0.0, np.pi / 2, np.pi, 3 * np.pi / 2]
    True

    The grid is made once per size and shared, read-only (the run layer asks for the same
    grids for every card).
    """
    return _grid(int(steps))


@functools.lru_cache(maxsize=32)
def _grid(steps: int) -> np.ndarray:
    grid = np.linspace(0.0, 2.0 * np.pi, steps, endpoint=False)
    grid.flags.writeable = False
    return grid


def wrapped(angle) -> np.ndarray:
    """Angles [rad] taken modulo 2 pi, into [0, 2 pi): the array itself when it already lies
    there (a crank grid, a card's placed angles), for ``numpy.mod`` of floats is costly.

    >>> wrapped(np.array([-0.5, 7.0])).round(4).tolist(), wrapped(crank_grid(4)) is crank_grid(4)
    ([5.7832, 0.7168], True)
    """
    angle = np.asarray(angle, dtype=float)
    if angle.size and angle.min() >= 0.0 and angle.max() < 2.0 * np.pi:
        return angle
    return angle % (2.0 * np.pi)


def ahead(values: np.ndarray) -> np.ndarray:
    """Each sample's successor around a cycle, along the last axis: ``numpy.roll(values, -1, axis=-1)``
    without its cost.

    >>> ahead(np.arange(4)).tolist(), behind(np.arange(4)).tolist()
    ([1, 2, 3, 0], [3, 0, 1, 2])
    """
    return np.concatenate((values[..., 1:], values[..., :1]), axis=-1)


def behind(values: np.ndarray) -> np.ndarray:
    """Each sample's predecessor around a cycle, along the last axis: ``numpy.roll(values, 1, axis=-1)``."""
    return np.concatenate((values[..., -1:], values[..., :-1]), axis=-1)


def extremes(theta: np.ndarray, values: np.ndarray) -> tuple[Extreme, Extreme]:
    """Maximum and minimum of a periodic curve sampled on a uniform crank-angle grid.

    Each is refined by the parabola through the extreme sample y1 and its two
    neighbours y0, y2 (the grid is periodic, so the last sample neighbours the first):
    shift s = (y0 - y2) / (2 (y0 - 2 y1 + y2)) steps, value y1 - (y0 - y2) s / 4. For a
    smooth curve the error of the located angle is O(h^3) and of the value O(h^4), h
    the step.

    Parameters
    ----------
    theta : numpy.ndarray
        Uniform grid over one revolution, as :func:`crank_grid` makes it [rad].
    values : numpy.ndarray
        The curve on that grid, shape like ``theta`` (any unit).

    Returns
    -------
    tuple of Extreme
        (maximum, minimum), values in the unit of ``values``, crank angles in
        [0, 2 pi) [rad].

    Examples
    --------
    The extremes of cos(theta - 0.1), sampled every 10 degrees, are +-1 at 0.1 rad:

    >>> theta = crank_grid(36)
    >>> top, bottom = extremes(theta, np.cos(theta - 0.1))
    >>> round(top.value, 4), round(top.crank_angle, 3), round(bottom.value, 4)
    (1.0, 0.1, -1.0)
    """
    (top, top_angle), (bottom, bottom_angle) = extremes_of(theta, np.asarray(values)[None])
    return Extreme(float(top[0]), float(top_angle[0])), Extreme(float(bottom[0]), float(bottom_angle[0]))


def extremes_of(theta: np.ndarray, values: np.ndarray) -> tuple[tuple[np.ndarray, np.ndarray], ...]:
    """:func:`extremes` of K curves at once, ``values`` shape (K, N) on the grid ``theta`` (N,):
    ((maxima, their angles), (minima, their angles)), arrays (K,)."""
    values = np.asarray(values, dtype=float)
    return _refined(theta, values, 1.0), _refined(theta, values, -1.0)


def _refined(theta: np.ndarray, values: np.ndarray, sign: float) -> tuple[np.ndarray, np.ndarray]:
    """The maxima (``sign`` 1) or minima (-1) of K curves (K, N) refined by the parabola through
    the extreme sample and its neighbours (:func:`extremes`), and their crank angles."""
    rows = np.arange(values.shape[0])
    size = values.shape[-1]
    h = theta[1] - theta[0]
    i = np.argmax(sign * values, axis=-1)
    y0, y1, y2 = (values[rows, (i + k) % size] for k in (-1, 0, 1))
    curvature = y0 - 2.0 * y1 + y2
    with np.errstate(divide="ignore", invalid="ignore"):
        shift = np.where(curvature != 0.0, 0.5 * (y0 - y2) / np.where(curvature != 0.0, curvature, 1.0), 0.0)
    return y1 - 0.25 * (y0 - y2) * shift, (theta[i] + shift * h) % (2.0 * np.pi)


def largest_magnitude(theta: np.ndarray, values: np.ndarray) -> Extreme:
    """The sample of largest magnitude and its crank angle, on the given grid (no refinement).

    Parameters
    ----------
    theta : numpy.ndarray
        Crank angles, shape (N,) [rad].
    values : numpy.ndarray
        A series (N,), whose magnitude is |v|, or a series of vectors (N, k), whose
        magnitude is the Euclidean norm (any unit).

    Returns
    -------
    Extreme
        The largest magnitude (unit of ``values``) and its crank angle [rad].

    Examples
    --------
    >>> largest_magnitude(np.array([0.0, 1.0, 2.0]), np.array([1.0, -3.0, 2.0]))
    Extreme(value=3.0, crank_angle=1.0)
    >>> largest_magnitude(np.array([0.0, 1.0]), np.array([[3.0, 4.0], [1.0, 1.0]])).value
    5.0
    """
    magnitude = np.abs(values) if np.ndim(values) == 1 else np.linalg.norm(values, axis=-1)
    i = int(np.argmax(magnitude))
    return Extreme(float(magnitude[i]), float(theta[i]))


def signed_extremes(theta: np.ndarray, values: np.ndarray) -> tuple[Extreme, Extreme]:
    """The largest and the smallest sample and their crank angles, on the given grid (no refinement).

    Parameters
    ----------
    theta : numpy.ndarray
        Crank angles, shape (N,) [rad].
    values : numpy.ndarray
        The series, shape (N,) (any unit).

    Returns
    -------
    tuple of Extreme
        (largest, smallest) sample with its crank angle [rad].

    Examples
    --------
    >>> signed_extremes(np.array([0.0, 1.0, 2.0]), np.array([1.0, -3.0, 2.0]))
    (Extreme(value=2.0, crank_angle=2.0), Extreme(value=-3.0, crank_angle=1.0))
    """
    top, bottom = int(np.argmax(values)), int(np.argmin(values))
    return Extreme(float(values[top]), float(theta[top])), Extreme(float(values[bottom]), float(theta[bottom]))


def uniform_time(crank_angle: np.ndarray, crank_speed: float) -> np.ndarray:
    """Time from crank angle 0 at uniform rotation, t = theta / omega.

    Parameters
    ----------
    crank_angle : numpy.ndarray
        theta [rad].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    numpy.ndarray
        t [s].

    Examples
    --------
    >>> uniform_time(np.array([0.0, np.pi]), np.pi / 3).tolist()   # half a 6 s cycle
    [0.0, 3.0]
    """
    return crank_angle / crank_speed


def cycle_period(crank_speed: float) -> float:
    """Time of one crank revolution, T = 2 pi / omega.

    Parameters
    ----------
    crank_speed : float
        Mean crank speed [1/s].

    Returns
    -------
    float
        T [s].

    Examples
    --------
    >>> round(cycle_period(2 * np.pi / 6), 12)   # 10 strokes per minute
    6.0
    """
    return 2.0 * np.pi / crank_speed


def peak(theta: np.ndarray, values: np.ndarray) -> Extreme:
    """The largest magnitude of a periodic curve on the uniform grid ``theta`` [rad] and
    its crank angle, refined as :func:`extremes` does.

    ``values`` is a series (N,) (magnitude |v|) or a series of vectors (N, k) (length).

    >>> theta = crank_grid(36)
    >>> found = peak(theta, -2.0 * np.cos(theta - 0.1))   # largest |v| = 2 at theta = 0.1
    >>> round(found.value, 4), round(found.crank_angle, 3)
    (2.0, 0.1)
    """
    magnitude = np.abs(values) if np.ndim(values) == 1 else np.linalg.norm(values, axis=-1)
    return extremes(theta, magnitude)[0]


def peaks_of(theta: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`peak` of K series at once, ``values`` (K, N): the largest magnitudes and their
    crank angles, arrays (K,)."""
    return _refined(theta, np.abs(np.asarray(values, dtype=float)), 1.0)
