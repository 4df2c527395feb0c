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
    """Polished-rod load [N] at crank angles [rad], increasing, within [0, 2 pi)."""

    crank_angle: np.ndarray
    load: np.ndarray


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


def crank_angle_from_position(linkage: Linkage, position: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
    """Crank angle [rad] of each polished-rod position [m, from the bottom] on its stroke branch.

    Positions must lie within [0, stroke]; the exact position is monotonic between the
    dead positions, so each branch is inverted by interpolation on a fine grid.
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
    """A card from points in any order: angles wrapped to [0, 2 pi), sorted, repeats averaged."""
    theta = np.asarray(crank_angle, dtype=float) % (2.0 * np.pi)
    unique, inverse = np.unique(theta, return_inverse=True)
    sums = np.bincount(inverse, weights=np.asarray(load, dtype=float))
    return Card(crank_angle=unique, load=sums / np.bincount(inverse))
