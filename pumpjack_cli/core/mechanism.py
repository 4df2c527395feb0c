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

    Attributes
    ----------
    crank_angle_bottom, crank_angle_top : float
        Crank angles of the bottom and the top of the stroke [rad], in the unit's
        crank-angle convention (from 12 o'clock in the direction of rotation, [API11E]).
    stroke : float
        Polished-rod travel from bottom to top [m].
    upstroke_crank_travel : float
        Crank rotation from bottom to top in the direction of rotation [rad].
    downstroke_crank_travel : float
        2 pi - upstroke_crank_travel [rad].

    References
    ----------
    [API11E] (crank-angle convention).
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

    ``motion`` evaluates the link angles and their first two derivatives with respect
    to the crank angle for a whole array of crank angles at once (a
    :class:`~.beam.linkage.Motion`), ``dead_positions`` gives the ends of the stroke
    (:class:`DeadPositions`), and ``check`` raises
    :class:`~pumpjack_cli.errors.GeometryError` when the linkage cannot turn through a
    revolution.

    Attributes
    ----------
    rotation : int
        +1 (clockwise) or -1 (counterclockwise), seen with the well to the right.
    front_arm : float
        Radius of the horsehead arc [m]: the polished rod moves front_arm times the
        beam rotation [rad], and the torque factor is TF = front_arm dpsi/dtheta [m].

    References
    ----------
    [API11E] (torque factor, crank-angle convention).
    """

    rotation: int
    front_arm: float

    def check(self) -> None:
        """Raise :class:`~pumpjack_cli.errors.GeometryError` unless the crank turns through a revolution."""
        ...

    def dead_positions(self) -> DeadPositions:
        """The bottom and top of the stroke (crank angles [rad], stroke [m])."""
        ...

    def motion(self, crank_angle: Any) -> Any:
        """Link angles [rad] and their first two crank-angle derivatives at crank angles [rad], arrays."""
        ...

    def rod_position(self, crank_angle: Any) -> Any:
        """Polished-rod position above the bottom of the stroke [m] at crank angles [rad], arrays."""
        ...
