"""Schema of the ``[geometry]`` of a Mark II unit: the class III lever with phased crank counterweights.

The equalizer bearing between the centre bearing and the horsehead, the crank shaft ahead
of the centre bearing (:class:`~pumpjack_cli.core.beam.class_three.ClassThreeLinkage`), the
counterweights on the crank's tail, offset by the crank offset angle tau, turning
counterclockwise with the well to the right ([LufkinMarkII]; ``docs/units.md``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pydantic import Field

from ..core.beam.class_three import ClassThreeLinkage
from .conventional import crank_counterweights
from .geometry_names import ROTATION_SIGNS
from .letters import BeamLetters
from .quantities import Angle

if TYPE_CHECKING:
    from ..core.beam.counterbalance import Counterbalance
    from ..core.beam.masses import MassModel
    from .beam_unit import CounterbalanceConfig


class MarkIIGeometry(BeamLetters):
    """Four-bar of a Mark II unit (API letters; C on the horsehead side, I ahead of the centre bearing)."""

    unit_class: Literal["mark-ii"] = Field(
        alias="class", description="kind of unit (config/unit_classes.py): mark-ii, the class III crank-balanced lever")
    rotation: Literal["counterclockwise"] = Field(
        default="counterclockwise", description="a Mark II turns counterclockwise with the well to the right")
    crank_offset: Angle = Field(
        ge=-1.0, le=1.0, description="tau: lead of the counterweights ahead of the crank's tail, in the direction of "
        "rotation, as catalogues print it (docs/conventions.md) [rad]")

    def mechanism(self) -> ClassThreeLinkage:
        """The class III four-bar."""
        return ClassThreeLinkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                                 self.vertical_offset, ROTATION_SIGNS[self.rotation])

    def counterbalance(self, given: CounterbalanceConfig | None, masses: MassModel | None) -> tuple[Counterbalance, bool]:
        """Crank counterweights on the tail with the crank offset (:func:`.conventional.crank_counterweights`)."""
        return crank_counterweights(self.mechanism(), given, masses, self.crank_offset)
