"""Schema of a unit file's ``[well]``: pump, rods, fluid, tubing and pressures."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .quantities import (Density, Fraction, KinematicViscosity, Length, Number, Pressure, Section, WeightPerLength,
                         at_least)


class RodSection(Section):
    """One section of a tapered rod string, by length or by share of the pump depth.

    The weight per length (couplings included) and the modulus come from the API rod
    and sinker-bar tables by diameter ([API11L], [API11B]) unless given; a fibreglass
    section (API 11C) must give both."""

    diameter: Annotated[Length, at_least(0.005, "5 mm")] = Field(gt=0, le=0.06, description="rod diameter [m]")
    fraction: Fraction | None = Field(default=None, gt=0, le=1,
                                      description="share of the pump depth (0..1, or '51 %'), instead of length")
    length: Annotated[Length, at_least(0.1, "0.1 m")] | None = Field(default=None, gt=0, le=6000,
                                                                      description="section length [m]")
    kind: Literal["steel", "sinker", "fibreglass"] | None = Field(
        default=None, description="steel rod, sinker bar or fibreglass rod [default: by the tables, steel rod "
        "if the diameter is an API rod size, else sinker bar]")
    grade: str | None = Field(default=None, description="API 11B grade (K, C, D, ...) for the tensile strength")
    youngs_modulus: Annotated[Pressure, at_least(1e9, "1 GPa")] | None = Field(
        default=None, gt=0, le=1e12, description="E [Pa] [default: the table's]")
    weight_per_length: WeightPerLength | None = Field(
        default=None, gt=0, le=2000, description="weight per length with couplings [N/m] [default: the table's]")
    tensile_strength: Annotated[Pressure, at_least(1e7, "10 MPa")] | None = Field(
        default=None, gt=0, le=1e10, description="minimum tensile strength [Pa], instead of grade")

    @model_validator(mode="after")
    def _length_or_fraction(self) -> "RodSection":
        if (self.fraction is None) == (self.length is None):
            raise ValueError("give the section's length or its fraction of the pump depth (one of them)")
        return self


class Well(Section):
    """Downhole data of the well the unit pumps: pump, rods, fluid, tubing, pressures."""

    pump_depth: Annotated[Length, at_least(1.0, "1 m")] = Field(gt=0, le=5000, description="pump setting depth [m]")
    plunger_diameter: Annotated[Length, at_least(0.005, "5 mm")] = Field(gt=0, le=0.15, description="pump plunger diameter [m]")
    rod_string: tuple[RodSection, ...] = Field(min_length=1, max_length=20, description="rod sections from the top down")
    fluid_density: Density = Field(gt=100, le=2000, description="produced fluid density [kg/m³]")
    fluid_kinematic_viscosity: KinematicViscosity | None = Field(
        default=None, gt=0, le=1e-2, description="produced fluid kinematic viscosity [m²/s] (rigid-rod well model)"
    )
    tubing_inner_diameter: Annotated[Length, at_least(0.01, "10 mm")] | None = Field(
        default=None, gt=0, le=0.2, description="tubing inner diameter [m] (rigid-rod well model)")
    tubing_size: Literal["2-3/8", "2-7/8", "3-1/2"] | None = Field(
        default=None, description="API tubing size, for the tubing stretch of an unanchored tubing")
    tubing_anchored: bool = Field(default=True, description="true: anchored tubing (no stretch)")
    tubing_head_pressure: Pressure = Field(default=0.0, ge=0, le=1e8, description="tubing (wellhead) pressure [Pa]")
    casing_head_pressure: Pressure = Field(default=0.0, ge=0, le=1e8, description="casing head pressure [Pa]")
    plunger_clearance: Annotated[Length, at_least(1e-6, "1 um")] | None = Field(
        default=None, gt=0, le=1e-3, description="clearance between plunger and barrel, for the plunger friction [m]"
    )
    pump_submergence: Length | None = Field(
        default=None, ge=0, le=5000, description="depth of the pump below the dynamic fluid level, h [m]"
    )
    pump_intake_pressure: Pressure | None = Field(
        default=None, ge=0, le=1e8, description="pressure at the pump intake [Pa], instead of the submergence")
    pump_fillage: Fraction = Field(default=1.0, ge=0, le=1, description="share of the pump barrel filled with liquid")
    gas_exponent: Number | None = Field(
        default=None, ge=1.0, le=1.4, description="polytropic exponent of free gas in the pump chamber (1: "
        "isothermal); none: the unfilled part is vapour at intake pressure")
    damping_factor: Number | None = Field(
        default=None, ge=0, le=2, description="Gibbs' dimensionless damping factor nu of the rods [default: from "
        "the energy balance of the card and the fluid load]")
    rod_density: Density = Field(default=7850.0, gt=1000, le=10000,
                                 description="rod material density (steel) of the rigid-rod well model [kg/m³]")

    @model_validator(mode="after")
    def _taper(self) -> "Well":
        total = sum(s.fraction if s.fraction is not None else s.length / self.pump_depth for s in self.rod_string)
        if abs(total - 1.0) > 0.005:
            raise ValueError(f"rod_string fractions add up to {total:.3f}, not 1 (lengths count as their share "
                             f"of the pump depth {self.pump_depth:.6g} m)")
        if self.pump_submergence is not None and self.pump_intake_pressure is not None:
            raise ValueError("give pump_submergence or pump_intake_pressure, not both")
        return self
