"""Dynamometer cards on the crank-angle axis.

A card is the polished-rod load over one pumping cycle. Measured cards come as load
against polished-rod position (or position and time); the calculator needs load
against crank angle. Two ways onto the crank-angle axis, both through the exact
kinematics of :mod:`.linkage` (no approximation):

* **position only.** Each position occurs once on the upstroke and once on the
  downstroke, so each point is mapped on the branch of its own stroke direction:
  upstroke points on the exact position curve between the bottom and top dead
  positions, downstroke points on the curve from top back to bottom
  (:func:`crank_angle_from_position`).
* **time and position.** The time stamps say how fast the crank turned: for uniform
  rotation theta_i = theta_0 + omega t_i, and theta_0 and omega are fitted by least
  squares to the measured positions (:func:`fit_uniform_rotation`). The fitted
  omega is the card's pumping speed, and the residual says how well the card fits
  this unit turning uniformly. [Takacs2016] derive the crank angle against time from
  dynamometer data iteratively for non-uniform speed; here the speed is one number.

Orientation: over a steady pumping cycle the unit does positive work on the rods,
W = closed integral of F ds > 0 (the card's area, the polished-rod work per stroke of
[Gibbs1963]): the rods go up on the high load and down on the low load. The sign of
:func:`loop_work` in the order listed tells a card stored in reverse.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ...errors import CardError
from .linkage import Linkage

#: Crank positions per stroke branch used to invert position -> crank angle.
_BRANCH_STEPS = 8192
#: Gauss-Newton iterations of the time fit at most (exact data converge in under ten).
_FIT_ITERATIONS = 50
#: Step-halvings tried before a Gauss-Newton step is taken as converged.
_LINE_SEARCH = 40
#: A Gauss-Newton step below this many radians (start angle, and speed times the half
#: time span) ends the fit: far below any measured position's resolution.
_FIT_TOLERANCE = 1e-12


@dataclass(frozen=True)
class Card:
    """Polished-rod load [N] at crank angles [rad], increasing, within [0, 2 pi)."""

    crank_angle: np.ndarray
    load: np.ndarray


@dataclass(frozen=True)
class RotationFit:
    """Uniform crank rotation fitted to time-stamped polished-rod positions.

    ``crank_angle`` [rad] of every sample (not wrapped, increasing with time),
    ``start_angle`` [rad] the crank angle at the first sample, ``speed`` omega [rad/s],
    ``rms`` the root-mean-square position residual [m].
    """

    crank_angle: np.ndarray
    start_angle: float
    speed: float
    rms: float


def card_load(card: Card, crank_angle: np.ndarray) -> np.ndarray:
    """Load [N] at any crank angles [rad]: periodic linear interpolation of the card."""
    return np.interp(np.asarray(crank_angle, dtype=float) % (2.0 * np.pi), card.crank_angle, card.load,
                     period=2.0 * np.pi)


def upstroke_points(position: np.ndarray) -> np.ndarray:
    """True where the card's polished rod is moving up, from the neighbours of each point.

    The card is periodic, so the first and last points are neighbours; the sign of
    s[i+1] - s[i-1] decides (at the dead positions either branch gives the same angle).
    """
    return (np.roll(position, -1) - np.roll(position, 1)) > 0


def _rod(linkage: Linkage, crank_angle: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Polished-rod position s = A (psi - psi_bottom) [m] and ds/dtheta = A psi' [m/rad]."""
    m = linkage.motion(crank_angle)
    bottom = linkage.dead_positions().beam_angle_bottom
    return linkage.front_arm * (m.beam_angle - bottom), linkage.front_arm * m.beam_rate


@lru_cache(maxsize=16)
def _branches(linkage: Linkage) -> tuple[tuple[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]:
    """(position, crank angle) tables of the upstroke and the downstroke, position increasing."""
    dead = linkage.dead_positions()
    up = dead.crank_angle_bottom + np.linspace(0.0, dead.upstroke_crank_travel, _BRANCH_STEPS)
    down = (dead.crank_angle_top + np.linspace(0.0, dead.downstroke_crank_travel, _BRANCH_STEPS))[::-1]
    return (_rod(linkage, up)[0], up), (_rod(linkage, down)[0], down)


def crank_angle_from_position(linkage: Linkage, position: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
    """Crank angle [rad] of each polished-rod position [m, from the bottom] on its stroke branch.

    Positions must lie within [0, stroke]; the exact position is monotonic between the
    dead positions, so each branch is inverted by interpolation on a fine grid.
    """
    position = np.asarray(position, dtype=float)
    theta = np.empty_like(position)
    for (s, branch), mask in zip(_branches(linkage), (upstroke, ~upstroke)):
        theta[mask] = np.interp(position[mask], s, branch)
    return theta % (2.0 * np.pi)


def card_from_angles(crank_angle: np.ndarray, load: np.ndarray) -> Card:
    """A card from points in any order: angles wrapped to [0, 2 pi), sorted, repeats averaged."""
    theta = np.asarray(crank_angle, dtype=float) % (2.0 * np.pi)
    unique, inverse = np.unique(theta, return_inverse=True)
    sums = np.bincount(inverse, weights=np.asarray(load, dtype=float))
    return Card(crank_angle=unique, load=sums / np.bincount(inverse))


def loop_work(position: np.ndarray, load: np.ndarray) -> float:
    """Work done on the rods around the closed card in the order listed [J].

    W = closed integral of F ds, by the trapezoidal rule over the polygon of the points
    closed from the last back to the first: the signed area of the card in the
    position-load plane. Positive when the rods rise on the high load and fall on the
    low load, as a pumping unit drives them ([Gibbs1963]: the card area is the
    polished-rod work per stroke).

    Parameters
    ----------
    position : numpy.ndarray
        Polished-rod position [m], in cycle order.
    load : numpy.ndarray
        Polished-rod load [N] at those positions.

    Returns
    -------
    float
        Work per cycle [J]; negative for a card listed in reverse.

    References
    ----------
    [Gibbs1963]

    A rectangle 1 m by 1 N, up at 2 N and down at 1 N (hand calculation: 2 - 1 = 1 J):

    >>> loop_work(np.array([0.0, 1.0, 1.0, 0.0]), np.array([2.0, 2.0, 1.0, 1.0]))
    1.0
    >>> loop_work(np.array([0.0, 1.0, 1.0, 0.0])[::-1], np.array([2.0, 2.0, 1.0, 1.0])[::-1])
    -1.0
    """
    s = np.asarray(position, dtype=float)
    f = np.asarray(load, dtype=float)
    return float(np.sum(0.5 * (f + np.roll(f, -1)) * (np.roll(s, -1) - s)))


def largest_gap(crank_angle: np.ndarray) -> float:
    """Largest crank rotation [rad] between neighbouring angles of a card, around the circle.

    >>> round(float(np.degrees(largest_gap(np.radians([0.0, 90.0, 180.0])))), 6)
    180.0
    >>> round(float(np.degrees(largest_gap(np.radians([350.0, 10.0])))), 6)
    340.0
    """
    theta = np.sort(np.asarray(crank_angle, dtype=float) % (2.0 * np.pi))
    return float(np.max(np.diff(theta, append=theta[0] + 2.0 * np.pi)))


def fit_uniform_rotation(linkage: Linkage, time: np.ndarray, position: np.ndarray) -> RotationFit:
    """Start angle and speed of uniform crank rotation that best explain a time-stamped card.

    Model: the polished rod is at s(theta_i) with theta_i = theta_0 + omega t_i, s the
    exact position curve of ``linkage`` (A (psi - psi_bottom)); theta_0 and omega
    minimise sum (s(theta_i) - position_i)^2. The start comes from the stroke-branch
    map of :func:`crank_angle_from_position`, unwrapped along time and fitted by a
    straight line (which makes no assumption on how many cycles the card holds); then
    Gauss-Newton with the exact Jacobian ds/dtheta (1, t_i), halving a step that does
    not lower the sum of squares.

    Parameters
    ----------
    linkage : Linkage
        The unit, with its rotation direction.
    time : numpy.ndarray
        Sample times [s], strictly increasing.
    position : numpy.ndarray
        Polished-rod positions [m] from the bottom of the stroke, within [0, stroke].

    Returns
    -------
    RotationFit
        Crank angle of every sample [rad], start angle [rad], speed omega [rad/s] and
        the RMS position residual [m].

    References
    ----------
    [Takacs2016] (the crank angle against time from dynamometer data); exact
    kinematics of [SK8Rotation2013] eq. 6.

    Positions of SK8-3,5-4000 at omega = 0.6283 rad/s (6 strokes/min) from a crank
    angle of 1 rad, sampled at uneven times, give those numbers back:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> t = np.sort(np.random.default_rng(1).uniform(0.0, 10.0, 150))
    >>> theta = 1.0 + 0.2 * np.pi * t
    >>> fit = fit_uniform_rotation(sk8, t, _rod(sk8, theta)[0])
    >>> abs(fit.speed / (0.2 * np.pi) - 1.0) < 1e-9
    True
    >>> bool(np.max(np.abs(np.sin(0.5 * (fit.crank_angle - theta)))) < 1e-9)   # same angles, modulo 2 pi
    True
    >>> fit.rms < 1e-9
    True
    """
    t = np.asarray(time, dtype=float)
    p = np.asarray(position, dtype=float)
    if t.ndim != 1 or t.shape != p.shape or t.size < 3:
        raise CardError(f"time fit: needs matching 1-D arrays of at least 3 samples, got {t.shape} and {p.shape}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(p))):
        raise CardError("time fit: time and position must be finite numbers")
    if np.any(np.diff(t) <= 0):
        raise CardError("time fit: time must increase strictly")
    centre = 0.5 * (t[0] + t[-1])
    tc = t - centre
    unwrapped = np.unwrap(crank_angle_from_position(linkage, p, upstroke_points(p)))
    omega = float(np.sum(tc * (unwrapped - unwrapped.mean())) / np.sum(tc * tc))
    params = np.array([unwrapped.mean() - omega * tc.mean(), omega])
    s, ds = _rod(linkage, params[0] + params[1] * tc)
    residual = s - p
    cost = float(residual @ residual)
    scale = np.array([1.0, 0.5 * (t[-1] - t[0])])
    for _ in range(_FIT_ITERATIONS):
        step = np.linalg.lstsq(np.column_stack([ds, ds * tc]), -residual, rcond=None)[0]
        for _ in range(_LINE_SEARCH):
            trial = params + step
            s, ds_trial = _rod(linkage, trial[0] + trial[1] * tc)
            trial_residual = s - p
            trial_cost = float(trial_residual @ trial_residual)
            if trial_cost <= cost:
                break
            step = 0.5 * step
        else:
            break
        params, residual, ds, cost = trial, trial_residual, ds_trial, trial_cost
        if np.all(np.abs(step) * scale <= _FIT_TOLERANCE):
            break
    theta = params[0] + params[1] * tc
    return RotationFit(crank_angle=theta, start_angle=float(theta[0]), speed=float(params[1]),
                       rms=float(np.sqrt(cost / t.size)))
