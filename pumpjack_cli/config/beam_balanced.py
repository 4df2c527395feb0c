"""Schema of the ``[geometry]`` of a beam-balanced unit: the class I lever with a counterweight on the beam.

The four-bar is the conventional one (:class:`~pumpjack_cli.core.beam.geometry.Linkage`,
either rotation); the counterweight hangs on the beam's rear arm
(:class:`~pumpjack_cli.core.beam.beam_balanced.BeamCounterweight`). B comes from
``[counterbalance] structural_unbalance`` (the beam without its counterweight).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field

from ..core.beam.geometry import Linkage
from ..errors import ConfigError
from .geometry_names import ROTATION_SIGNS
from .letters import BeamLetters
from .quantities import Force, Length, at_least

if TYPE_CHECKING:
    from ..core.beam.beam_balanced import BeamCounterweight
    from ..core.beam.masses import MassModel
    from .beam_unit import CounterbalanceConfig


class BeamBalancedGeometry(BeamLetters):
    """Four-bar of a beam-balanced unit (API letters of the class I unit) and its beam counterweight."""

    unit_class: Literal["beam-balanced"] = Field(
        alias="class", description="kind of unit (config/unit_classes.py): beam-balanced, the class I lever with "
        "a counterweight on the beam")
    beam_counterweight: Force | None = Field(
        default=None, ge=0, le=1e6, description="present weight of the beam counterweight (the balancing variable) [N]")
    beam_counterweight_arm: Annotated[Length, at_least(0.1, "100 mm")] = Field(
        gt=0, le=20, description="distance of the counterweight's centre behind the centre bearing, along the beam [m]")

    def mechanism(self) -> Linkage:
        """The class I four-bar."""
        return Linkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                       self.vertical_offset, ROTATION_SIGNS[self.rotation])

    def counterbalance(self, given: CounterbalanceConfig | None,
                       masses: MassModel | None) -> tuple[BeamCounterweight, bool]:
        """The beam counterweight with B of ``[counterbalance]``, and whether its present weight is known."""
        from ..core.beam.beam_balanced import BeamCounterweight

        if given is None or given.moment is not None or given.phase != 0.0:
            raise ConfigError("a beam-balanced unit needs [counterbalance] structural_unbalance, without moment or "
                              "phase (its counterbalance is [geometry] beam_counterweight)")
        return (BeamCounterweight(given.structural_unbalance, self.beam_counterweight or 0.0,
                                  -self.beam_counterweight_arm, self.front_arm),
                self.beam_counterweight is not None)
