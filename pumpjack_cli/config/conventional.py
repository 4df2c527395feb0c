"""Schema of the ``[geometry]`` of a conventional (class I, crank-balanced) unit, and its mechanism.

The four-bar of :class:`~pumpjack_cli.core.beam.geometry.Linkage`, written with the GOST
names or the API Spec 11E letters ([API11E]; :mod:`.geometry_names`); the spatial model
of the six-link mechanism ([Spatial7SK12]) when the pin spacings are given.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Field, model_validator

from ..core.beam.geometry import Linkage, beam_linkage, check_assembly
from ..errors import ConfigError, GeometryError
from .geometry_names import ROTATION_SIGNS, canonical_geometry
from .quantities import Length, Section, at_least

if TYPE_CHECKING:  # the core's models are imported when a command uses them
    from ..core.beam.counterbalance import Counterbalance
    from ..core.beam.masses import MassModel
    from ..core.beam.spatial import SpatialLinkage
    from .beam_unit import CounterbalanceConfig


class ConventionalGeometry(Section):
    """Four-bar geometry of a conventional (class I) unit, rotation direction included."""

    unit_class: Literal["conventional"] = Field(
        default="conventional", alias="class",
        description="kind of unit (config/unit_classes.py): conventional, the crank-balanced class I lever")

    front_arm: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=20, description="k1 / A: centre bearing to horsehead arc [m]")
    rear_arm: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=20, description="k / C: centre bearing to equalizer bearing [m]")
    crank_radius: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=5, description="r / R: crank shaft to crank pin [m]")
    pitman: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=20, description="l / P: crank pin to equalizer bearing [m]")
    horizontal_offset: Length = Field(
        ge=0, le=20, description="l1 / I: horizontal distance crank shaft - centre bearing [m]"
    )
    vertical_offset: Annotated[Length, at_least(0.01, "10 mm")] = Field(
        gt=0, le=20, description="l2 / H-G: height of the centre bearing above the crank shaft [m]"
    )
    rotation: Literal["clockwise", "counterclockwise"] = Field(
        description="crank rotation seen with the well to the right"
    )
    crank_half_spacing: Annotated[Length, at_least(0.01, "10 mm")] | None = Field(
        default=None, gt=0, le=5,
        description="spatial model: crank shaft mid-plane to each crank pin, along the shaft [m]",
    )
    equalizer_half_length: Annotated[Length, at_least(0.01, "10 mm")] | None = Field(
        default=None, gt=0, le=5, description="spatial model: equalizer bearing D to each pin, BD = DB1 [m]"
    )

    @model_validator(mode="before")
    @classmethod
    def _names(cls, data: Any) -> Any:
        """Map GOST names and API letters to field names; reject double definitions."""
        return canonical_geometry(data) if isinstance(data, dict) else data

    @model_validator(mode="after")
    def _assembles(self) -> "ConventionalGeometry":
        try:
            check_assembly(self.mechanism())
        except GeometryError as exc:
            raise ValueError(str(exc)) from None
        return self

    def mechanism(self) -> Linkage:
        """The numerical core's planar four-bar (:func:`~pumpjack_cli.core.beam.geometry.beam_linkage`)."""
        return beam_linkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                            self.vertical_offset, ROTATION_SIGNS[self.rotation], self.crank_half_spacing,
                            self.equalizer_half_length)

    def counterbalance(self, given: CounterbalanceConfig | None, masses: MassModel | None) -> tuple[Counterbalance, bool]:
        """Crank counterweights (B, M, tau of the API method) and whether M is known: the unit
        file's ``[counterbalance]`` if given, else from the link masses
        (:func:`~pumpjack_cli.core.beam.counterbalance.counterbalance_from_masses`)."""
        from ..core.beam.counterbalance import Counterbalance, counterbalance_from_masses

        if given is not None:
            return Counterbalance(given.structural_unbalance, given.moment or 0.0, given.phase), given.moment is not None
        if masses is not None:
            return counterbalance_from_masses(self.mechanism(), masses), True
        raise ConfigError("neither [counterbalance] nor [masses]: give at least [counterbalance] structural_unbalance "
                          "(and moment for the present net torque)")

    def spatial(self, source: str = "unit") -> SpatialLinkage:
        """The spatial model; needs crank_half_spacing and equalizer_half_length."""
        if self.crank_half_spacing is None or self.equalizer_half_length is None:
            raise ConfigError(
                f"{source}: geometry: the spatial model needs crank_half_spacing and equalizer_half_length"
            )
        from ..core.beam.spatial import SpatialLinkage

        return SpatialLinkage(self.mechanism(), self.crank_half_spacing, self.equalizer_half_length)
