"""Schema of the ``[geometry]`` of a Mark II unit: the class III lever with phased crank counterweights.

The equalizer bearing between the centre bearing and the horsehead, the crank shaft ahead
of the centre bearing (:class:`~pumpjack_cli.core.beam.class_three.ClassThreeLinkage`), the
counterweights on the crank's tail, offset by the crank offset angle tau, turning
counterclockwise with the well to the right ([LufkinMarkII]; ``docs/units.md``).
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from ..core.beam.class_three import ClassThreeLinkage
from .conventional import PhasedCrankGeometry
from .geometry_names import ROTATION_SIGNS


class MarkIIGeometry(PhasedCrankGeometry):
    """Four-bar of a Mark II unit (API letters; C on the horsehead side, I ahead of the centre bearing)."""

    unit_class: Literal["mark-ii"] = Field(
        alias="class", description="kind of unit (config/unit_classes.py): mark-ii, the class III crank-balanced lever")
    rotation: Literal["counterclockwise"] = Field(
        default="counterclockwise", description="a Mark II turns counterclockwise with the well to the right")

    def mechanism(self) -> ClassThreeLinkage:
        """The class III four-bar."""
        return ClassThreeLinkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                                 self.vertical_offset, ROTATION_SIGNS[self.rotation])
