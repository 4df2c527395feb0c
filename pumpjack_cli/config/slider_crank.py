"""Schema of a slider-crank machine file (kind ``slider-crank``: drill pumps,
compressors; [InertiaUNB600A]): crank, connecting rod, line of stroke, the
reciprocating mass and, optionally, a stepped slider on redundant supports.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from ..core.slider_crank.geometry import SliderCrank, check_slider_crank
from ..core.slider_crank.support_friction import slider_length
from ..errors import GeometryError
from .geometry_names import slider_crank_of
from .quantities import Angle, Length, Mass, Number, Pressure, RotationalSpeed, Section, Text


class SliderCrankGeometry(Section):
    """Crank, connecting rod and line of stroke of a slider-crank (symbols of [InertiaUNB600A])."""

    crank_radius: Length = Field(gt=0, le=5, description="r: crank shaft to crank pin [m]")
    rod_length: Length = Field(gt=0, le=20, description="l2: connecting rod, crank pin to crosshead (slider) pin [m]")
    offset: Length = Field(
        default=0.0, ge=-5, le=5,
        description="e: line of stroke above the crank shaft, drawn with the slider to the right [m]; 0 for a centric drive",
    )
    rotation: Literal["clockwise", "counterclockwise"] = Field(
        default="counterclockwise", description="crank rotation seen with the slider to the right (matters only with an offset)"
    )

    @model_validator(mode="after")
    def _turns(self) -> "SliderCrankGeometry":
        try:
            check_slider_crank(self.slider_crank())
        except GeometryError as exc:
            raise ValueError(str(exc)) from None
        return self

    def slider_crank(self) -> SliderCrank:
        """The numerical core's view (:func:`.geometry_names.slider_crank_of`)."""
        return slider_crank_of(self.crank_radius, self.rod_length, self.offset, self.rotation)



#: The largest reciprocating mass of a slider-crank machine [kg] (the file's and --mass's limit).
MASS_LIMIT = 1e5


class Reciprocating(Section):
    """The parts moving with the slider, and the crank speed."""

    mass: Mass = Field(gt=0, le=MASS_LIMIT, description="m: piston (plunger), rod and crosshead together [kg]")
    crank_speed: RotationalSpeed = Field(
        gt=0, le=400, description="omega: crank speed, e.g. '65 rpm' = 65 double strokes per minute [rad/s]"
    )


class SliderSection(Section):
    """One section of a stepped slider, a solid round bar."""

    length: Length = Field(gt=0, le=20, description="l_i: section length along the slider [m]")
    # at least 1 mm: far below it the section's bending stiffness (d^4) makes the support problem singular
    diameter: Length = Field(ge=1e-3, le=2, description="d_i: section diameter [m]")



class IntermediateSupport(Section):
    """A redundant support fixed to the frame between the ends of the slider ([InertiaUNB600A] fig. 4)."""

    position: Length = Field(
        gt=0, le=20, description="z_C0: distance from the clamped end A along the slider at the outer dead centre [m]"
    )
    offset: Length = Field(ge=-0.01, le=0.01, description="delta_C: height of the support off the axis of A [m]")


class SteppedSlider(Section):
    """Stepped slider on redundant supports ([InertiaUNB600A], second part): clamped at A (the
    piston end), held by guide B (the crosshead guide) that has settled and turned."""

    sections: tuple[SliderSection, ...] = Field(
        min_length=1, description="sections from the clamped end A to the guide B (crosshead)"
    )
    # at least 10 mm: the edge forces of guide B grow as 1/l_n, without bound for a shoe of no length
    guide_length: Length = Field(ge=0.01, le=5, description="l_n: distance between the edge contacts of guide B [m]")
    settlement: Length = Field(
        ge=-0.01, le=0.01, description="Delta_B: guide B's axis off the axis of A at the outer dead centre [m]"
    )
    turn: Angle = Field(ge=-0.05, le=0.05, description="theta_B: angle of guide B's axis to the axis of A [rad]")
    intermediate_support: IntermediateSupport | None = None
    friction_coefficient: Number = Field(gt=0, le=1, description="f: sliding friction coefficient in the guides")
    elastic_modulus: Pressure = Field(gt=0, le=1e12, description="E: Young's modulus of the slider [Pa]")

    @property
    def length(self) -> float:
        """L: clamped end A to guide B [m] (:func:`~pumpjack_cli.core.slider_crank.support_friction.slider_length`)."""
        return slider_length([section.length for section in self.sections])


class SliderCrankConfig(Section):
    """A reciprocating machine with a slider-crank drive (drill pump, compressor; [InertiaUNB600A])."""

    kind: Literal["slider-crank"] = Field(default="slider-crank", description="machine kind (see UNIT_KINDS)")
    name: Text = Field(min_length=1, description="designation, e.g. UNB-600A")
    description: Text = Field(default="", description="one line shown by `pumpjack units`")
    sources: tuple[str, ...] = Field(default=(), description="where the data come from")
    geometry: SliderCrankGeometry
    reciprocating: Reciprocating
    stepped_slider: SteppedSlider | None = None

    @model_validator(mode="after")
    def _support_on_slider(self) -> "SliderCrankConfig":
        support = self.stepped_slider.intermediate_support if self.stepped_slider else None
        if support is not None:
            travel, length = self.stroke(), self.stepped_slider.length
            if not travel < support.position < length:
                raise ValueError(
                    f"stepped_slider.intermediate_support.position = {support.position:.4g} m: the support must stay "
                    f"on the slider over the stroke, so it must lie between the stroke {travel:.4g} m "
                    f"and the slider length {length:.4g} m"
                )
        return self

    def stroke(self) -> float:
        """Exact piston stroke [m] of the slider-crank."""
        return self.geometry.slider_crank().stroke

