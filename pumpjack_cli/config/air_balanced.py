"""Schema of the ``[geometry]`` of an air-balanced unit: the class III lever counterbalanced by an air cylinder.

The four-bar is that of the Mark II (:class:`~pumpjack_cli.core.beam.class_three.ClassThreeLinkage`,
either rotation); the counterbalance is the air cylinder of ``air_cylinder``
(:class:`~pumpjack_cli.core.beam.air_balanced.AirCylinder`): its piston, the gas volume at
the bottom of the stroke (or the clearance as a share of the piston's swept volume), the
polytropic exponent, the lever of its pin on the beam and the gauge pressure at a stated
polished-rod position. B comes from ``[counterbalance] structural_unbalance``.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, model_validator

from ..core.beam.class_three import ClassThreeLinkage
from ..errors import ConfigError
from .geometry_names import ROTATION_SIGNS
from .letters import BeamLetters
from .quantities import Area, Fraction, Length, Number, Pressure, Section, Volume, at_least

if TYPE_CHECKING:
    from ..core.beam.air_balanced import AirCylinder
    from ..core.beam.masses import MassModel
    from .beam_unit import CounterbalanceConfig


class AirCylinderConfig(Section):
    """The air-balance cylinder ([API11E] class III counterbalance; ``docs/units.md``)."""

    piston_area: Area | None = Field(default=None, gt=0, le=2.0, description="piston area A_c [m²]")
    piston_diameter: Annotated[Length, at_least(0.05, "50 mm")] | None = Field(
        default=None, gt=0, le=1.5, description="piston diameter, for A_c = pi D² / 4 [m]")
    bottom_volume: Volume | None = Field(
        default=None, gt=0, le=20.0, description="gas volume at the bottom of the stroke, clearance and tank [m³]")
    clearance: Fraction | None = Field(
        default=None, gt=0, le=100.0, description="gas volume at the bottom of the stroke as a share of the "
        "piston's swept volume")
    exponent: Number = Field(default=1.4, ge=1.0, le=1.67, description="polytropic exponent n (1.4 isentropic air, "
                             "1 isothermal)")
    lever: Annotated[Length, at_least(0.1, "100 mm")] = Field(
        gt=0, le=20, description="the piston rod's pin on the beam, from the centre bearing towards the horsehead [m]")
    pressure: Pressure | None = Field(
        default=None, ge=0, le=5e7, description="present gauge pressure at pressure_position (the balancing variable) [Pa]")
    pressure_position: Length = Field(
        default=0.0, ge=0, le=20, description="polished-rod position above the bottom of the stroke where pressure "
        "is stated [m]")

    @model_validator(mode="after")
    def _one_of_each(self) -> "AirCylinderConfig":
        for first, second in (("piston_area", "piston_diameter"), ("bottom_volume", "clearance")):
            if (getattr(self, first) is None) == (getattr(self, second) is None):
                raise ValueError(f"give one of {first} and {second}")
        return self

    def area(self) -> float:
        """A_c [m²]."""
        return self.piston_area if self.piston_area is not None else math.pi * self.piston_diameter**2 / 4.0


class AirBalancedGeometry(BeamLetters):
    """Four-bar of an air-balanced unit (API letters of the class III unit) and its air cylinder."""

    unit_class: Literal["air-balanced"] = Field(
        alias="class", description="kind of unit (config/unit_classes.py): air-balanced, the class III lever "
        "counterbalanced by an air cylinder")
    air_cylinder: AirCylinderConfig = Field(description="the air-balance cylinder")

    def mechanism(self) -> ClassThreeLinkage:
        """The class III four-bar."""
        return ClassThreeLinkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                                 self.vertical_offset, ROTATION_SIGNS[self.rotation])

    def counterbalance(self, given: CounterbalanceConfig | None, masses: MassModel | None) -> tuple[AirCylinder, bool]:
        """The air cylinder with B of ``[counterbalance]``, and whether the present pressure is known."""
        from ..core.beam.air_balanced import AirCylinder

        if given is None or given.moment is not None or given.phase != 0.0:
            raise ConfigError("an air-balanced unit needs [counterbalance] structural_unbalance, without moment or "
                              "phase (its counterbalance is [geometry] air_cylinder)")
        mechanism = self.mechanism()
        dead = mechanism.dead_positions()
        air = self.air_cylinder
        if air.lever > self.front_arm:
            raise ConfigError(f"geometry.air_cylinder.lever {air.lever:.4g} m is beyond the beam's front arm A "
                              f"{self.front_arm:.4g} m: the piston rod's pin is on the beam")
        if air.pressure_position > dead.stroke:
            raise ConfigError(f"geometry.air_cylinder.pressure_position {air.pressure_position:.4g} m is beyond the "
                              f"stroke {dead.stroke:.4g} m")
        area = air.area()
        swept = area * air.lever * (math.sin(dead.beam_angle_top) - math.sin(dead.beam_angle_bottom))
        volume = air.bottom_volume if air.bottom_volume is not None else air.clearance * swept
        reference = dead.beam_angle_bottom + air.pressure_position / mechanism.horsehead_arm
        cylinder = AirCylinder(given.structural_unbalance, air.pressure or 0.0, reference, area, volume,
                               dead.beam_angle_bottom, air.lever, mechanism.horsehead_arm, air.exponent)
        return cylinder, air.pressure is not None
