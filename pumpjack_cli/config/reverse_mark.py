"""Schema of the ``[geometry]`` of a reverse-mark (phased-crank) unit: a class I lever with phased counterweights.

Conventional geometry with the rear working centre shifted forward ([LufkinRM]: the crank
shaft towards the well from under the equalizer, I < C, which makes the clockwise upstroke
take less than half a turn; ``docs/units.md`` says what could not be checked), the
counterweights offset from the crank pin by the crank offset angle tau, turning clockwise
with the well to the right only ([LufkinRM]); the four-bar is
:class:`~pumpjack_cli.core.beam.geometry.Linkage`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pydantic import Field

from ..core.beam.geometry import Linkage
from .conventional import crank_counterweights
from .geometry_names import ROTATION_SIGNS
from .letters import BeamLetters
from .quantities import Angle

if TYPE_CHECKING:
    from ..core.beam.counterbalance import Counterbalance
    from ..core.beam.masses import MassModel
    from .beam_unit import CounterbalanceConfig


class ReverseMarkGeometry(BeamLetters):
    """Four-bar of a reverse-mark unit (API letters of the class I unit)."""

    unit_class: Literal["reverse-mark"] = Field(
        alias="class", description="kind of unit (config/unit_classes.py): reverse-mark, the phased-crank class I lever")
    rotation: Literal["clockwise"] = Field(
        default="clockwise", description="a reverse-mark unit turns clockwise with the well to the right")
    crank_offset: Angle = Field(
        ge=-1.0, le=1.0, description="tau: lag of the counterweights behind the crank pin in T = TF (W - B) - "
        "M sin(theta - tau), negative when they lead (docs/conventions.md) [rad]")

    def mechanism(self) -> Linkage:
        """The class I four-bar."""
        return Linkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                       self.vertical_offset, ROTATION_SIGNS[self.rotation])

    def counterbalance(self, given: CounterbalanceConfig | None, masses: MassModel | None) -> tuple[Counterbalance, bool]:
        """Crank counterweights with the crank offset (:func:`.conventional.crank_counterweights`)."""
        return crank_counterweights(self.mechanism(), given, masses, self.crank_offset)
