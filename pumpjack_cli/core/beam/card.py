"""Dynamometer cards on the crank-angle axis.

A card is the polished-rod load over one pumping cycle. Measured cards come as load
against polished-rod position (or time); the calculator needs load against crank
angle. Position alone is ambiguous (each position occurs once on the upstroke and
once on the downstroke), so each point is mapped on the branch of its own stroke
direction: upstroke points on the exact position curve between the bottom and top
dead positions, downstroke points on the curve from top back to bottom. The map uses
the exact kinematics of :mod:`.linkage` (no approximation).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .linkage import Linkage

#: Crank positions per stroke branch used to invert position -> crank angle.
_BRANCH_STEPS = 8192


@dataclass(frozen=True)
class Card:
    """A dynamometer card on the crank-angle axis.

    Attributes
    ----------
    crank_angle : numpy.ndarray
        Crank angles, increasing, within [0, 2 pi) [rad].
    load : numpy.ndarray
        Polished-rod load at those angles [N].
    """

    crank_angle: np.ndarray
    load: np.ndarray


def card_load(card: Card, crank_angle: np.ndarray) -> np.ndarray:
    """Polished-rod load at any crank angles: periodic linear interpolation of the card.

    Parameters
    ----------
    card : Card
        The card [rad, N].
    crank_angle : numpy.ndarray
        Crank angles, any values (taken modulo 2 pi) [rad].

    Returns
    -------
    numpy.ndarray
        Load [N].

    Examples
    --------
    A two-point card, 1 N at 0 and 3 N at pi, is 2 N half way on either side:

    >>> card = Card(np.array([0.0, np.pi]), np.array([1.0, 3.0]))
    >>> card_load(card, np.array([np.pi / 2, 3 * np.pi / 2, 2 * np.pi])).tolist()
    [2.0, 2.0, 1.0]
    """
    return np.interp(np.asarray(crank_angle, dtype=float) % (2.0 * np.pi), card.crank_angle, card.load,
                     period=2.0 * np.pi)


def upstroke_points(position: np.ndarray) -> np.ndarray:
    """True where the card's polished rod is moving up, from the neighbours of each point.

    The card is periodic, so the first and last points are neighbours; the sign of
    s[i+1] - s[i-1] decides (at the dead positions either branch gives the same angle).

    Parameters
    ----------
    position : numpy.ndarray
        Polished-rod positions of the card in the order measured [m] (any length unit).

    Returns
    -------
    numpy.ndarray
        Boolean mask, True on the upstroke.

    Examples
    --------
    >>> upstroke_points(np.array([0.0, 1.0, 2.0, 1.0])).tolist()
    [False, True, False, False]
    """
    return (np.roll(position, -1) - np.roll(position, 1)) > 0


def crank_angle_from_position(linkage: Linkage, position: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
    """Crank angle of each polished-rod position on the branch of its stroke.

    Positions must lie within [0, stroke]; the exact position s = A (psi - psi_bottom) is
    monotonic between the dead positions, so each branch (bottom -> top on the upstroke,
    top -> bottom on the downstroke) is inverted by linear interpolation on 8192 points.

    Parameters
    ----------
    linkage : Linkage
        The four-bar [m].
    position : numpy.ndarray
        Polished-rod positions from the bottom of the stroke [m].
    upstroke : numpy.ndarray
        Boolean mask of the points on the upstroke (:func:`upstroke_points`).

    Returns
    -------
    numpy.ndarray
        Crank angles in [0, 2 pi) [rad].

    Examples
    --------
    The bottom and the top of the stroke map to the dead positions:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> dead = sk8.dead_positions()
    >>> theta = crank_angle_from_position(sk8, np.array([0.0, dead.stroke]), np.array([True, True]))
    >>> bool(np.allclose(theta, [dead.crank_angle_bottom, dead.crank_angle_top], atol=1e-9))
    True
    """
    dead = linkage.dead_positions()
    theta = np.empty_like(np.asarray(position, dtype=float))
    for start, travel, mask, rising in (
        (dead.crank_angle_bottom, dead.upstroke_crank_travel, upstroke, True),
        (dead.crank_angle_top, dead.downstroke_crank_travel, ~upstroke, False),
    ):
        branch = start + np.linspace(0.0, travel, _BRANCH_STEPS)
        s = linkage.front_arm * (linkage.motion(branch).beam_angle - dead.beam_angle_bottom)
        if not rising:
            branch, s = branch[::-1], s[::-1]
        theta[mask] = np.interp(position[mask], s, branch)
    return theta % (2.0 * np.pi)


def card_from_angles(crank_angle: np.ndarray, load: np.ndarray) -> Card:
    """A card from points in any order: angles wrapped to [0, 2 pi), sorted, repeats averaged.

    Parameters
    ----------
    crank_angle : numpy.ndarray
        Crank angles of the points [rad].
    load : numpy.ndarray
        Polished-rod loads [N].

    Returns
    -------
    Card
        Sorted, unique crank angles [rad] and their mean loads [N].

    Examples
    --------
    >>> card = card_from_angles(np.array([0.5, 0.1, 0.5]), np.array([10.0, 5.0, 20.0]))
    >>> card.crank_angle.tolist(), card.load.tolist()
    ([0.1, 0.5], [5.0, 15.0])
    """
    theta = np.asarray(crank_angle, dtype=float) % (2.0 * np.pi)
    unique, inverse = np.unique(theta, return_inverse=True)
    sums = np.bincount(inverse, weights=np.asarray(load, dtype=float))
    return Card(crank_angle=unique, load=sums / np.bincount(inverse))
