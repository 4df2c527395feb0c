"""Schema of the ``[geometry]`` of a reverse-mark (phased-crank) unit: a class I lever with phased counterweights.

Conventional geometry with the rear working centre shifted forward ([LufkinRM]: the
equalizer bearing towards the well from above the crank shaft, C < I in every reverse-mark row
of [UnitDatabase2018], which makes the clockwise upstroke take more than half a turn), the
counterweights offset from the crank pin by the crank offset angle tau (negative in
catalogues: a lag), turning clockwise with the well to the right only ([LufkinRM]); the
four-bar is :class:`~pumpjack_cli.core.beam.geometry.Linkage`.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from ..core.beam.geometry import Linkage
from .conventional import PhasedCrankGeometry
from .geometry_names import ROTATION_SIGNS


class ReverseMarkGeometry(PhasedCrankGeometry):
    """Four-bar of a reverse-mark unit (API letters of the class I unit)."""

    unit_class: Literal["reverse-mark"] = Field(
        alias="class", description="kind of unit (config/unit_classes.py): reverse-mark, the phased-crank class I lever")
    rotation: Literal["clockwise"] = Field(
        default="clockwise", description="a reverse-mark unit turns clockwise with the well to the right")

    def mechanism(self) -> Linkage:
        """The class I four-bar."""
        return Linkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                       self.vertical_offset, ROTATION_SIGNS[self.rotation])
