"""Schema of a unit file's ``[well]``: pump, rods, fluid, tubing and pressures, and the core's
rod string and pump built from them.

Rod sections are given by length or by share of the pump depth; their weight with couplings
and modulus come from the API tables by diameter unless given ([API11L], [API11B]); steel
displaces the fluid with the well's ``rod_density``, as in the rigid-rod well model. A
section whose diameter is an API rod size is a steel rod, any other a sinker bar, unless
its ``kind`` says otherwise.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, ValidationInfo, field_validator, model_validator

from ..errors import ConfigError, DownholeError

if TYPE_CHECKING:  # the rod models are imported when a command uses them
    from ..core.rods.path import WellPath
    from ..core.rods.survey_path import SurveyPath
    from ..core.rods.pump import Pump
    from ..core.rods.string import RodString
from .quantities import (Density, Force, Fraction, KinematicViscosity, Length, Number, Pressure, Section,
                         WeightPerLength, at_least)


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

    def rod_kind(self) -> str:
        """steel, sinker or fibreglass: the ``kind`` given, else steel for an API rod size."""
        from ..core.rods.tables import steel_rod

        if self.kind is not None:
            return self.kind
        try:
            steel_rod(self.diameter)
        except DownholeError:
            return "sinker"
        return "steel"


#: The side load one coupling or rod guide may carry [N]: at least 10 N (2.2 lbf; a guide that
#: carries less is none, and the number of guides it would ask for has no bound), at most 1 MN.
GUIDE_LIMIT_RANGE = (10.0, 1e6)


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
        default=None, gt=0, le=1e-3, description="diametral clearance (fit) between plunger and barrel, for the "
        "plunger friction and the slippage [m]"
    )
    plunger_length: Annotated[Length, at_least(0.1, "0.1 m")] | None = Field(
        default=None, gt=0, le=15, description="length of the plunger, for the slippage past it [m]")
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
    survey: str | None = Field(
        default=None, min_length=1, description="deviation survey file (CSV: measured_depth_m or _ft, inclination_deg, "
        "azimuth_deg), relative to the unit file; none: a vertical hole (docs/deviated.md)")
    rod_friction_coefficient: Number | None = Field(
        default=None, ge=0, le=1, description="Coulomb friction coefficient of rods and couplings on the tubing "
        "[default: 0.2, docs/deviated.md]")
    rod_guide_side_load_limit: Force | None = Field(
        default=None, ge=GUIDE_LIMIT_RANGE[0], le=GUIDE_LIMIT_RANGE[1],
        description="side load one coupling or rod guide may carry [N], for the rod-guide "
        "advice (no published limit was found: docs/deviated.md)")
    rod_joint_length: Annotated[Length, at_least(1.0, "1 m")] = Field(
        default=7.62, le=20, description="length of one rod between couplings [m] (API 11B: 25 or 30 ft)")

    @field_validator("survey")
    @classmethod
    def _survey_file(cls, value: str | None, info: ValidationInfo) -> str | None:
        """The survey file relative to the unit file's folder (the validation context's ``folder``)."""
        from pathlib import Path

        folder = (info.context or {}).get("folder") if info.context else None
        if value is None or folder is None or Path(value).is_absolute():
            return value
        return str(Path(folder) / value)

    @model_validator(mode="after")
    def _taper(self) -> "Well":
        total = sum(s.fraction if s.fraction is not None else s.length / self.pump_depth for s in self.rod_string)
        if abs(total - 1.0) > 0.005:
            raise ValueError(f"rod_string fractions add up to {total:.3f}, not 1 (lengths count as their share "
                             f"of the pump depth {self.pump_depth:.6g} m)")
        if self.pump_submergence is not None and self.pump_intake_pressure is not None:
            raise ValueError("give pump_submergence or pump_intake_pressure, not both")
        if self.pump_submergence is not None and self.pump_submergence > self.pump_depth:
            raise ValueError(f"pump_submergence {self.pump_submergence:.6g} m is more than the pump depth "
                             f"{self.pump_depth:.6g} m: the fluid level would stand above the wellhead")
        from ..core.rods.pump import TUBING

        for name, inner in (("tubing_inner_diameter", self.tubing_inner_diameter),
                            ("tubing_size", TUBING[self.tubing_size][1] if self.tubing_size else None)):
            if inner is not None and self.plunger_diameter >= inner:
                raise ValueError(f"plunger_diameter {self.plunger_diameter * 1e3:.4g} mm does not pass through the "
                                 f"tubing of {name} (inner diameter {inner * 1e3:.4g} mm)")
        return self

    def rods(self) -> RodString:
        """The core's tapered rod string of ``rod_string``, top section first ([API11L], [API11B] tables),
        built once per well: kept with the fields it is built from (a copy whose ``rod_string``,
        ``pump_depth`` or ``rod_density`` differ, ``model_copy(update=...)``, builds its own)."""
        key = (self.rod_string, self.pump_depth, self.rod_density)
        kept = self.__dict__.get("_built_rods")
        if kept is None or kept[0] != key:
            kept = self.__dict__["_built_rods"] = (key, self._build_rods())
        return kept[1]

    def _build_rods(self) -> RodString:
        from ..core.constants import STANDARD_GRAVITY
        from ..core.rods.tables import RodSection as CoreSection
        from ..core.rods.tables import rod_string

        sections = []
        for section in self.rod_string:
            kind = section.rod_kind()
            sections.append(CoreSection(
                section.diameter, section.length if section.length is not None else section.fraction * self.pump_depth,
                kind=kind, grade=section.grade, youngs_modulus=section.youngs_modulus,
                mass_per_length=None if section.weight_per_length is None else section.weight_per_length / STANDARD_GRAVITY,
                tensile_strength=section.tensile_strength,
                material_density=None if kind == "fibreglass" else self.rod_density))
        try:
            return rod_string(sections)
        except DownholeError as exc:
            raise ConfigError(f"well.rod_string: {exc}") from None

    def path(self) -> WellPath:
        """The well's path along the rods (:mod:`~pumpjack_cli.core.rods.path`): the ``survey`` by
        minimum curvature (:mod:`~pumpjack_cli.core.rods.survey_path`), else a vertical hole. A
        survey that does not reach the pump is refused naming the file."""
        if self.survey is None:
            from ..core.rods.path import VerticalPath

            return VerticalPath()
        return _survey_path(self.survey, self.pump_depth)

    def friction_coefficient(self) -> float:
        """mu of rods and couplings on the tubing: the file's, else the default
        (:data:`~pumpjack_cli.core.rods.deviated.DEFAULT_FRICTION_COEFFICIENT`)."""
        from ..core.rods.deviated import DEFAULT_FRICTION_COEFFICIENT

        return DEFAULT_FRICTION_COEFFICIENT if self.rod_friction_coefficient is None else self.rod_friction_coefficient

    def pump_vertical_depth(self) -> float:
        """The pump's true vertical depth [m]: the head of the fluid columns above it."""
        return float(self.path().vertical_depth(self.pump_depth))

    def pressures(self) -> tuple[float, float] | None:
        """Discharge and intake pressure at the pump [Pa], or None when the well gives neither its
        fluid level (pump submergence) nor its intake pressure; the heads over the pump's true
        vertical depth."""
        from ..core.rods.pump import pump_pressures

        if self.pump_submergence is None and self.pump_intake_pressure is None:
            return None
        vertical = self.pump_vertical_depth()
        if self.pump_submergence is not None and self.pump_submergence > vertical:
            raise ConfigError(f"well.pump_submergence {self.pump_submergence:.6g} m is more than the pump's true "
                              f"vertical depth {vertical:.6g} m (the survey {self.survey}): the fluid level would "
                              f"stand above the wellhead")
        return pump_pressures(vertical, self.fluid_density, submergence=self.pump_submergence,
                              intake_pressure=self.pump_intake_pressure, tubing_head_pressure=self.tubing_head_pressure,
                              casing_head_pressure=self.casing_head_pressure)

    def pump(self) -> Pump:
        """The pump with its valves' pressures, fillage, gas and tubing stretch."""
        from ..core.rods.pump import Pump, tubing_stiffness

        found = self.pressures()
        if found is None:
            raise ConfigError("the well needs pump_submergence (fluid level above the pump) or pump_intake_pressure "
                              "for the pump's valves")
        stiffness = math.inf
        if not self.tubing_anchored:
            if self.tubing_size is None:
                raise ConfigError("well.tubing_size is needed for an unanchored tubing's stretch")
            stiffness = tubing_stiffness(self.tubing_size, self.pump_depth)
        return Pump(math.pi * self.plunger_diameter**2 / 4.0, found[0], found[1], fillage=self.pump_fillage,
                    gas_exponent=self.gas_exponent, tubing_stiffness=stiffness)


def _survey_path(file: str, pump_depth: float) -> SurveyPath:
    """The minimum-curvature path of a survey file (read once per file and content), checked
    to reach the pump's measured depth [m]."""
    import os

    try:
        info = os.stat(file)
        key = (os.path.abspath(file), info.st_mtime_ns, info.st_size)
    except (OSError, ValueError):
        key = (file, 0, 0)
    path = _read_survey_path(key)
    if path.depth < pump_depth - 1e-6:
        raise ConfigError(f"{file}: the survey reaches {path.depth:.6g} m of measured depth, short of the pump "
                          f"depth {pump_depth:.6g} m")
    vertical = float(path.vertical_depth(pump_depth))
    if not vertical > 0.0:
        raise ConfigError(f"{file}: the survey puts the pump ({pump_depth:.6g} m measured) at a true vertical depth "
                          f"of {vertical:.4g} m, at or above the wellhead: no fluid column stands over it")
    return path


_SURVEYS: dict = {}


def _read_survey_path(key: tuple) -> SurveyPath:
    """The path of the survey file ``key[0]`` (cached by file, modification time and size)."""
    if key not in _SURVEYS:
        import numpy as np

        from ..core.rods.survey_path import SurveyPath
        from ..readers.survey import read_survey

        raw = read_survey(key[0])
        try:
            _SURVEYS[key] = SurveyPath(np.array(raw.measured_depth), np.array(raw.inclination), np.array(raw.azimuth))
        except DownholeError as exc:
            raise ConfigError(f"{raw.source}: {exc}") from None
    return _SURVEYS[key]
