"""What every pumping-unit mechanism provides, whatever its linkage.

A conventional (class I) crank-balanced unit is :class:`~.beam.geometry.Linkage`
today; a Mark II, an air-balanced or a phased-crank unit is one more class that
satisfies :class:`Mechanism` (see ``docs/architecture.md``). The run layer and every
model above the linkage use only this protocol: the crank angle goes in, the
polished-rod motion, the torque factor and the link kinematics come out, and the
stroke and the crank travel of each stroke are properties of the dead positions,
defined once here.

This module imports nothing heavy, so configs can use it at start-up.
"""

from __future__ import annotations

from typing import Any, Protocol


class DeadPositions(Protocol):
    """The two positions where the polished rod stops (bottom and top of the stroke).

    ``crank_angle_bottom``, ``crank_angle_top`` [rad] in the unit's crank-angle
    convention; ``stroke`` [m]; ``upstroke_crank_travel`` [rad], the crank rotation
    from bottom to top in the direction of rotation, and ``downstroke_crank_travel``
    = 2 pi - upstroke_crank_travel.
    """

    crank_angle_bottom: float
    crank_angle_top: float

    @property
    def stroke(self) -> float: ...

    @property
    def upstroke_crank_travel(self) -> float: ...

    @property
    def downstroke_crank_travel(self) -> float: ...


class Mechanism(Protocol):
    """A pumping unit's linkage from the crank to the polished rod.

    ``rotation`` is +1 (clockwise) or -1 (counterclockwise) seen with the well to
    the right; ``front_arm`` [m] is the radius of the horsehead arc, so the polished
    rod moves front_arm times the beam rotation. ``motion`` evaluates the link
    angles and their first two derivatives with respect to the crank angle for a
    whole array of crank angles at once (a :class:`~.beam.linkage.Motion`), and
    ``check`` raises :class:`~pumpjack_cli.errors.GeometryError` when the linkage
    cannot turn through a revolution.
    """

    rotation: int
    front_arm: float

    def check(self) -> None: ...

    def dead_positions(self) -> DeadPositions: ...

    def motion(self, crank_angle: Any) -> Any: ...
