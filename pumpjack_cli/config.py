"""Validated unit configs: geometry, masses, drive and motor, well.

A unit file is TOML, YAML or JSON. Values are SI numbers or strings with a unit
(``"3500 mm"``, ``"137.5 in"``, ``"1460 rpm"``), converted once here by
:func:`pumpjack_cli.units.parse_quantity`; everything downstream is SI. Unknown keys
are rejected. Geometry may be written with the GOST / Soviet-textbook names or the
API Spec 11E letters (see ``docs/glossary.md``):

=================  ======  ===========  ============================================
field              GOST    API 11E      meaning
=================  ======  ===========  ============================================
front_arm          k1      A            centre bearing to horsehead arc (polished rod)
rear_arm           k       C            centre bearing to equalizer bearing
crank_radius       r       R            crank shaft to crank pin
pitman             l       P            crank pin to equalizer bearing
horizontal_offset  l1      I            crank shaft to centre bearing, horizontal
vertical_offset    l2      H - G or     centre bearing above crank shaft;
                           sqrt(K²-I²)  K is the straight distance
=================  ======  ===========  ============================================
"""

from __future__ import annotations

import dataclasses
import json
import math
import tomllib
from functools import partial
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, Strict, ValidationError, model_validator

from .core.beam.masses import MassModel
from .core.beam.geometry import CLOCKWISE, COUNTERCLOCKWISE, Linkage, check_assembly, dead_positions
from .core.beam.redundancy import PinTilts, PitmanSection
from .core.beam.spatial import SpatialLinkage
from .core.slider_crank.geometry import SliderCrank, check_slider_crank
from .core.slider_crank.geometry import stroke as slider_stroke
from .errors import ConfigError, GeometryError
from .units import parse_quantity


def _quantity(dimension: str) -> BeforeValidator:
    return BeforeValidator(partial(parse_quantity, dimension=dimension))


Length = Annotated[float, _quantity("length")]
Mass = Annotated[float, _quantity("mass")]
MomentOfInertia = Annotated[float, _quantity("moment_of_inertia")]
RotationalSpeed = Annotated[float, _quantity("rotational_speed")]
Power = Annotated[float, _quantity("power")]
Density = Annotated[float, _quantity("density")]
KinematicViscosity = Annotated[float, _quantity("kinematic_viscosity")]
Fraction = Annotated[float, _quantity("fraction")]
Angle = Annotated[float, _quantity("angle")]
#: Plain numbers without a unit; strict so that ``true`` is not read as 1.
Number = Annotated[float, Strict()]
Count = Annotated[int, Strict()]


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


#: Accepted spellings of each geometry field: (GOST / Soviet textbook, API Spec 11E).
GEOMETRY_ALIASES: dict[str, tuple[str, ...]] = {
    "front_arm": ("k1", "A"),
    "rear_arm": ("k", "C"),
    "crank_radius": ("r", "R"),
    "pitman": ("l", "P"),
    "horizontal_offset": ("l1", "I"),
    "vertical_offset": ("l2",),
}


class Geometry(_Section):
    """Four-bar geometry of a conventional (class I) unit, rotation direction included."""

    front_arm: Length = Field(gt=0, le=20, description="k1 / A: centre bearing to horsehead arc [m]")
    rear_arm: Length = Field(gt=0, le=20, description="k / C: centre bearing to equalizer bearing [m]")
    crank_radius: Length = Field(gt=0, le=5, description="r / R: crank shaft to crank pin [m]")
    pitman: Length = Field(gt=0, le=20, description="l / P: crank pin to equalizer bearing [m]")
    horizontal_offset: Length = Field(
        ge=0, le=20, description="l1 / I: horizontal distance crank shaft - centre bearing [m]"
    )
    vertical_offset: Length = Field(
        gt=0, le=20, description="l2 / H-G: height of the centre bearing above the crank shaft [m]"
    )
    rotation: Literal["clockwise", "counterclockwise"] = Field(
        description="crank rotation seen with the well to the right"
    )
    crank_half_spacing: Length | None = Field(
        default=None, gt=0, le=5,
        description="spatial model: crank shaft mid-plane to each crank pin, along the shaft [m]",
    )
    equalizer_half_length: Length | None = Field(
        default=None, gt=0, le=5, description="spatial model: equalizer bearing D to each pin, BD = DB1 [m]"
    )

    @model_validator(mode="before")
    @classmethod
    def _names(cls, data: Any) -> Any:
        """Map GOST names and API letters to field names; reject double definitions."""
        if not isinstance(data, dict):
            return data
        data = dict(data)
        api_height = [key for key in ("H", "G", "K") if key in data]
        if api_height:
            if "K" in data and ("H" in data or "G" in data):
                raise ValueError("give either K or both H and G, not both")
            if "K" not in data and not ("H" in data and "G" in data):
                raise ValueError("API letters H and G come together (vertical offset = H - G)")
        for field, aliases in GEOMETRY_ALIASES.items():
            given = [name for name in (field, *aliases) if name in data]
            if field == "vertical_offset" and api_height:
                given.append("H and G" if "H" in data else "K")
            if len(given) > 1:
                raise ValueError(f"{field} is given twice (as {' and '.join(given)}); give one")
            if given and given[0] != field and given[0] in aliases:
                data[field] = data.pop(given[0])
        if "H" in data and "G" in data:
            data["vertical_offset"] = parse_quantity(data.pop("H"), "length") - parse_quantity(data.pop("G"), "length")
        elif "K" in data:
            k = parse_quantity(data.pop("K"), "length")
            i = parse_quantity(data.get("horizontal_offset", 0.0), "length")
            if not k > i:
                raise ValueError(f"K = {k:.4g} m must exceed I = {i:.4g} m")
            data["vertical_offset"] = math.sqrt(k * k - i * i)
        rotation = data.get("rotation")
        if isinstance(rotation, str):
            data["rotation"] = {"cw": "clockwise", "ccw": "counterclockwise"}.get(rotation.lower(), rotation.lower())
        return data

    @model_validator(mode="after")
    def _assembles(self) -> "Geometry":
        if self._pitman_lean >= self.pitman:
            raise ValueError(
                f"pitman ({self.pitman:.4g} m) is shorter than the offset of its ends along the crank shaft "
                f"|crank_half_spacing - equalizer_half_length| = {self._pitman_lean:.4g} m"
            )
        try:
            check_assembly(self.linkage())
        except GeometryError as exc:
            raise ValueError(str(exc)) from None
        return self

    def linkage(self) -> Linkage:
        """The numerical core's planar four-bar: the pitman projected on the beam plane
        when the crank pins and the equalizer pins are spaced differently."""
        return Linkage(
            front_arm=self.front_arm,
            rear_arm=self.rear_arm,
            crank_radius=self.crank_radius,
            pitman=math.sqrt(self.pitman**2 - self._pitman_lean**2),
            horizontal_offset=self.horizontal_offset,
            vertical_offset=self.vertical_offset,
            rotation=CLOCKWISE if self.rotation == "clockwise" else COUNTERCLOCKWISE,
        )

    @property
    def _pitman_lean(self) -> float:
        """Offset of the pitman ends along the crank shaft, |b - e| [m] (0 without spatial data)."""
        if self.crank_half_spacing is None or self.equalizer_half_length is None:
            return 0.0
        return abs(self.crank_half_spacing - self.equalizer_half_length)

    def spatial(self, source: str = "unit") -> SpatialLinkage:
        """The spatial model; needs crank_half_spacing and equalizer_half_length."""
        if self.crank_half_spacing is None or self.equalizer_half_length is None:
            raise ConfigError(
                f"{source}: geometry: the spatial model needs crank_half_spacing and equalizer_half_length"
            )
        return SpatialLinkage(self.linkage(), self.crank_half_spacing, self.equalizer_half_length)


class CrankArm(_Section):
    """One of the two crank arms of the double crank (link 1), without counterweights."""

    mass: Mass = Field(gt=0, le=2e4, description="one crank arm (m_kr, m_1) [kg]")
    cg_radius: Length = Field(
        ge=0, le=5, description="crank shaft to the arm's centre of mass, towards the crank pin (OS_1) [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about its centre of mass, axis along the crank shaft [kg·m²]"
    )


class Counterweights(_Section):
    """Counterweight blocks on the crank arms, treated as point masses at their centre of mass."""

    mass: Mass = Field(ge=0, le=5e3, description="one block (m_pr1) [kg]")
    count: Count = Field(ge=0, le=16, description="number of blocks on both arms together (shared equally)")
    radius: Length = Field(ge=0, le=5, description="crank shaft to the blocks' centre of mass (r_pr, OS_pr) [m]")
    phase: Angle = Field(
        default=0.0, gt=-math.pi, le=math.pi,
        description="angle from the crank pin direction to the blocks' centre of mass, in the direction of "
        "rotation; 0 on conventional units, whose blocks sit on the crank arm in line with the pin [rad]",
    )


class Pitman(_Section):
    """One pitman (links 2 and 3 are equal)."""

    mass: Mass = Field(gt=0, le=5e3, description="one pitman (m_2) [kg]")
    cg_from_crank_pin: Length = Field(
        ge=0, le=20, description="crank pin A to the centre of mass, along the pitman (AS_2) [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about its centre of mass, across the pitman (J_S2) [kg·m²]"
    )


class Equalizer(_Section):
    """Equalizer (cross-yoke, link 4); centre of mass at its bearing D on the beam."""

    mass: Mass = Field(ge=0, le=2e4, description="equalizer (m_tr, m_4) [kg]")
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about D, axis along the crank shaft (its pin line BB1) [kg·m²]"
    )
    transverse_inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about D, axes across the pin line [kg·m²]"
    )


class BeamPart(_Section):
    """The walking beam body or the horsehead; centre of mass on the beam line D-C-E."""

    mass: Mass = Field(ge=0, le=5e4, description="mass [kg]")
    cg: Length = Field(
        ge=-20, le=20, description="centre bearing C to the centre of mass along the beam, towards the well positive [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e6, description="moment of inertia about its centre of mass, axis along the crank shaft [kg·m²]"
    )


class Masses(_Section):
    """Masses, centres of mass and inertias of the moving links (seed 000/003/004 names in brackets)."""

    crank_arm: CrankArm
    counterweights: Counterweights
    pitman: Pitman
    equalizer: Equalizer
    beam: BeamPart = Field(description="walking beam body (m_b, m_bal)")
    horsehead: BeamPart = Field(description="horsehead (m_gb)")

    def model(self) -> MassModel:
        """The numerical core's view of the masses."""
        return MassModel(
            crank_arm_mass=self.crank_arm.mass,
            crank_arm_cg=self.crank_arm.cg_radius,
            crank_arm_inertia=self.crank_arm.inertia,
            counterweight_mass=self.counterweights.mass * self.counterweights.count,
            counterweight_radius=self.counterweights.radius,
            counterweight_phase=self.counterweights.phase,
            pitman_mass=self.pitman.mass,
            pitman_cg=self.pitman.cg_from_crank_pin,
            pitman_inertia=self.pitman.inertia,
            equalizer_mass=self.equalizer.mass,
            equalizer_inertia=self.equalizer.inertia,
            equalizer_transverse_inertia=self.equalizer.transverse_inertia,
            beam_mass=self.beam.mass,
            beam_cg=self.beam.cg,
            beam_inertia=self.beam.inertia,
            horsehead_mass=self.horsehead.mass,
            horsehead_cg=self.horsehead.cg,
            horsehead_inertia=self.horsehead.inertia,
        )


class Motor(_Section):
    """Induction motor nameplate data (seed 004, eqs. 25-26)."""

    model: str = Field(description="motor type designation")
    rated_power: Power = Field(gt=0, le=1e6, description="rated shaft power [W]")
    synchronous_speed: RotationalSpeed = Field(gt=0, le=400, description="synchronous speed n_s [rad/s]")
    rated_speed: RotationalSpeed = Field(gt=0, le=400, description="rated speed n_n [rad/s]")
    starting_torque_ratio: Number = Field(gt=0, le=10, description="starting torque / rated torque")
    breakdown_torque_ratio: Number = Field(gt=1, le=10, description="pull-out (maximum) torque / rated torque")
    rotor_inertia: MomentOfInertia = Field(gt=0, le=1e3, description="rotor moment of inertia [kg·m²]")

    @model_validator(mode="after")
    def _slip(self) -> "Motor":
        if not self.rated_speed < self.synchronous_speed:
            raise ValueError("rated_speed must be below synchronous_speed (an induction motor has slip)")
        return self


class Drive(_Section):
    """Motor, V-belt drive and gearbox between the motor and the crank shaft."""

    motor: Motor
    gearbox: str = Field(description="gearbox type designation")
    gearbox_ratio: Number = Field(gt=1, le=200, description="gearbox reduction ratio u_r")
    motor_sheave_diameter: Length = Field(gt=0, le=3, description="motor (driving) sheave diameter d_1 [m]")
    gearbox_sheave_diameter: Length = Field(gt=0, le=5, description="gearbox (driven) sheave diameter d_2 [m]")
    motor_sheave_inertia: MomentOfInertia = Field(
        default=0.0, ge=0, le=1e3, description="motor (driving) sheave, on the motor shaft; 0: not counted [kg·m²]"
    )
    gearbox_sheave_inertia: MomentOfInertia = Field(
        default=0.0, ge=0, le=1e4, description="gearbox (driven) sheave, on the gearbox input shaft; 0: not counted [kg·m²]"
    )
    gearbox_inertia: MomentOfInertia = Field(
        default=0.0, ge=0, le=1e4,
        description="gears and shafts of the gearbox referred to its input shaft; 0: not counted [kg·m²]",
    )

    @property
    def belt_ratio(self) -> float:
        """V-belt reduction u_belt = d_2 / d_1."""
        return self.gearbox_sheave_diameter / self.motor_sheave_diameter

    @property
    def total_ratio(self) -> float:
        """Motor speed / crank speed, u = u_r u_belt (belt slip neglected)."""
        return self.gearbox_ratio * self.belt_ratio

    @property
    def rated_crank_speed(self) -> float:
        """Crank speed at the motor's rated speed, omega_1 = pi n_n / (30 u) [1/s] (seed 004)."""
        return self.motor.rated_speed / self.total_ratio


class RodSection(_Section):
    """One section of a tapered rod string."""

    diameter: Length = Field(gt=0, le=0.06, description="rod diameter [m]")
    fraction: Fraction = Field(gt=0, le=1, description="share of the string length (0..1, or '51 %')")


class Well(_Section):
    """Downhole data of the well the unit pumps (seed 004)."""

    pump_depth: Length = Field(gt=0, le=5000, description="pump setting depth [m]")
    plunger_diameter: Length = Field(gt=0, le=0.15, description="pump plunger diameter [m]")
    rod_string: tuple[RodSection, ...] = Field(min_length=1, description="rod sections from the top down")
    fluid_density: Density = Field(gt=100, le=2000, description="produced fluid density [kg/m³]")
    fluid_kinematic_viscosity: KinematicViscosity = Field(
        gt=0, le=1e-2, description="produced fluid kinematic viscosity [m²/s]"
    )
    tubing_inner_diameter: Length = Field(gt=0, le=0.2, description="tubing inner diameter [m]")
    plunger_clearance: Length | None = Field(
        default=None, gt=0, le=1e-3, description="clearance between plunger and barrel, for the plunger friction [m]"
    )
    pump_submergence: Length | None = Field(
        default=None, ge=0, le=5000, description="depth of the pump below the dynamic fluid level, h [m]"
    )
    rod_density: Density = Field(default=7850.0, gt=1000, le=10000, description="rod material density (steel) [kg/m³]")

    @model_validator(mode="after")
    def _taper(self) -> "Well":
        total = sum(section.fraction for section in self.rod_string)
        if abs(total - 1.0) > 0.005:
            raise ValueError(f"rod_string fractions add up to {total:.3f}, not 1")
        return self


Pressure = Annotated[float, _quantity("pressure")]
AreaMoment = Annotated[float, _quantity("area_moment")]
Area = Annotated[float, _quantity("area")]


class PitmanSectionConfig(_Section):
    """Elastic pitman for the real mechanism (seed 000 eqs. 18-21; defaults from the seed
    where it gives them: E = 2.1e11 Pa, J_z = 17.61e-6 m^4)."""

    youngs_modulus: Pressure = Field(default=2.1e11, gt=0, le=1e12, description="E [Pa] (seed 000)")
    shear_modulus: Pressure = Field(default=8.08e10, gt=0, le=1e12, description="G [Pa]: E / (2 (1 + 0.3)) for steel")
    area: Area = Field(gt=0, le=0.1, description="cross-section area [m²]")
    inplane_inertia: AreaMoment = Field(
        default=17.61e-6, gt=0, le=1e-2, description="J_z: second moment about the pin direction [m⁴] (seed 000)"
    )
    outofplane_inertia: AreaMoment = Field(gt=0, le=1e-2, description="second moment across the pin direction [m⁴]")
    torsion_constant: AreaMoment = Field(gt=0, le=1e-2, description="J_t, the polar moment J_p for a tube [m⁴]")

    def model(self) -> PitmanSection:
        return PitmanSection(self.youngs_modulus, self.shear_modulus, self.area, self.inplane_inertia,
                             self.outofplane_inertia, self.torsion_constant)


class Deviations(_Section):
    """Manufacturing and wear errors of side 3 (crank pin A1, pitman A1B1, pin B1)
    against side 2; all zero for an ideal unit."""

    crank_phase: Angle = Field(default=0.0, ge=-0.2, le=0.2,
                               description="crank pin A1 ahead of A in the direction of rotation [rad]")
    crank_radius: Length = Field(default=0.0, ge=-0.5, le=0.5, description="crank radius of A1 minus that of A [m]")
    pitman_length: Length = Field(default=0.0, ge=-0.5, le=0.5, description="pitman A1B1 minus pitman AB [m]")
    crank_pin_tilt_radial: Angle = Field(default=0.0, ge=-0.05, le=0.05,
                                         description="pin A1 bore turned about the arm's radial line [rad]")
    crank_pin_tilt_tangential: Angle = Field(default=0.0, ge=-0.05, le=0.05,
                                             description="pin A1 bore turned about the arm's tangent [rad]")
    equalizer_pin_roll: Angle = Field(default=0.0, ge=-0.05, le=0.05,
                                      description="pin B1 bore turned about the beam's long axis [rad]")
    equalizer_pin_yaw: Angle = Field(default=0.0, ge=-0.05, le=0.05,
                                     description="pin B1 bore turned about the vertical across the beam [rad]")

    def tilts(self) -> PinTilts:
        return PinTilts(self.crank_pin_tilt_radial, self.crank_pin_tilt_tangential,
                        self.equalizer_pin_roll, self.equalizer_pin_yaw)

    def apply(self, spatial: SpatialLinkage) -> SpatialLinkage:
        """The spatial model with the side-3 deviations of position."""
        return dataclasses.replace(spatial, crank_phase_offset=self.crank_phase,
                                   crank_radius_offset=self.crank_radius, pitman_length_offset=self.pitman_length)


class UnitConfig(_Section):
    """A whole pumping unit: identification, geometry and optional masses, drive, well."""

    kind: Literal["beam-pump"] = Field(default="beam-pump", description="machine kind (see UNIT_KINDS)")
    name: str = Field(min_length=1, description="designation, e.g. SK8-3,5-4000")
    description: str = Field(default="", description="one line shown by `pumpjack units`")
    sources: tuple[str, ...] = Field(default=(), description="where the data come from")
    geometry: Geometry
    masses: Masses | None = None
    drive: Drive | None = None
    well: Well | None = None
    pitman_section: PitmanSectionConfig | None = None
    deviations: Deviations = Deviations()

    def stroke(self) -> float:
        """Exact polished-rod stroke [m], from the dead positions of the four-bar."""
        linkage = self.geometry.linkage()
        dead = dead_positions(linkage)
        return linkage.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom)


# --- slider-crank machines (reciprocating pumps, seed 001) -------------------------

Pressure = Annotated[float, _quantity("pressure")]


class SliderCrankGeometry(_Section):
    """Crank, connecting rod and line of stroke of a slider-crank (seed 001 symbols)."""

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
        """The numerical core's view: offset measured on the side the crank pin swings into first."""
        sign = 1.0 if self.rotation == "counterclockwise" else -1.0
        return SliderCrank(self.crank_radius, self.rod_length, sign * self.offset)


class Reciprocating(_Section):
    """The parts moving with the slider, and the crank speed."""

    mass: Mass = Field(gt=0, le=1e5, description="m: piston (plunger), rod and crosshead together [kg]")
    crank_speed: RotationalSpeed = Field(
        gt=0, le=400, description="omega: crank speed, e.g. '65 rpm' = 65 double strokes per minute [rad/s]"
    )


class SliderSection(_Section):
    """One section of a stepped slider, a solid round bar."""

    length: Length = Field(gt=0, le=20, description="l_i: section length along the slider [m]")
    diameter: Length = Field(gt=0, le=2, description="d_i: section diameter [m]")

    @property
    def second_moment(self) -> float:
        """J_i = pi d^4 / 64 [m^4], second moment of area of a solid circle."""
        return math.pi * self.diameter**4 / 64.0


class IntermediateSupport(_Section):
    """A redundant support fixed to the frame between the ends of the slider (seed 001 fig. 4)."""

    position: Length = Field(
        gt=0, le=20, description="z_C0: distance from the clamped end A along the slider at the outer dead centre [m]"
    )
    offset: Length = Field(ge=-0.01, le=0.01, description="delta_C: height of the support off the axis of A [m]")


class SteppedSlider(_Section):
    """Stepped slider on redundant supports (seed 001, second part): clamped at A (the
    piston end), held by guide B (the crosshead guide) that has settled and turned."""

    sections: tuple[SliderSection, ...] = Field(
        min_length=1, description="sections from the clamped end A to the guide B (crosshead)"
    )
    guide_length: Length = Field(gt=0, le=5, description="l_n: distance between the edge contacts of guide B [m]")
    settlement: Length = Field(
        ge=-0.01, le=0.01, description="Delta_B: guide B's axis off the axis of A at the outer dead centre [m]"
    )
    turn: Angle = Field(ge=-0.05, le=0.05, description="theta_B: angle of guide B's axis to the axis of A [rad]")
    intermediate_support: IntermediateSupport | None = None
    friction_coefficient: Number = Field(gt=0, le=1, description="f: sliding friction coefficient in the guides")
    elastic_modulus: Pressure = Field(gt=0, le=1e12, description="E: Young's modulus of the slider [Pa]")

    @property
    def length(self) -> float:
        """L: clamped end A to guide B [m]."""
        return sum(section.length for section in self.sections)


class SliderCrankConfig(_Section):
    """A reciprocating machine with a slider-crank drive (drill pump, compressor; seed 001)."""

    kind: Literal["slider-crank"] = Field(default="slider-crank", description="machine kind (see UNIT_KINDS)")
    name: str = Field(min_length=1, description="designation, e.g. UNB-600A")
    description: str = Field(default="", description="one line shown by `pumpjack units`")
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
        """Exact piston stroke [m]: sqrt((l2 + r)^2 - e^2) - sqrt((l2 - r)^2 - e^2)."""
        return slider_stroke(self.geometry.slider_crank())


# --- reading files ---------------------------------------------------------------

BUNDLED_PACKAGE = "pumpjack_cli.configs"
SUFFIXES = (".toml", ".yaml", ".yml", ".json")


def _parse_text(path: Path, text: str) -> Any:
    suffix = path.suffix.lower()
    try:
        if suffix == ".toml":
            return tomllib.loads(text)
        if suffix == ".json":
            return json.loads(text)
        if suffix in (".yaml", ".yml"):
            import yaml

            return yaml.safe_load(text)
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: not valid TOML: {exc}") from None
    except json.JSONDecodeError as exc:
        raise ConfigError(f"{path}: not valid JSON: {exc.msg} at line {exc.lineno}") from None
    except Exception as exc:  # yaml.YAMLError; yaml is imported lazily
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark is not None else ""
        raise ConfigError(f"{path}: not valid YAML: {getattr(exc, 'problem', exc)}{where}") from None
    raise ConfigError(f"{path}: unknown file type {suffix!r}; use one of {', '.join(SUFFIXES)}")


def format_validation_error(source: str, error: ValidationError) -> str:
    """One line naming the file, the field and what is wrong with it."""
    first = error.errors()[0]
    where = ".".join(str(part) for part in first["loc"]) or "(top level)"
    message = first["msg"].removeprefix("Value error, ")
    if first["type"] == "extra_forbidden":
        message = "unknown key"
    more = len(error.errors()) - 1
    tail = f" (and {more} more problem{'s' if more > 1 else ''})" if more else ""
    return f"{source}: {where}: {message}{tail}"


#: Machine kinds a file can describe, by its top-level ``kind`` key (default beam-pump).
UNIT_KINDS: dict[str, type[BaseModel]] = {"beam-pump": UnitConfig, "slider-crank": SliderCrankConfig}


def parse_unit(data: Any, source: str) -> BaseModel:
    """Validate parsed file contents; ``source`` names the file in error messages."""
    if not isinstance(data, dict):
        raise ConfigError(f"{source}: expected a table of sections at the top level")
    kind = data.get("kind", "beam-pump")
    if kind not in UNIT_KINDS:
        raise ConfigError(f"{source}: kind: unknown machine kind {kind!r}; use one of {', '.join(UNIT_KINDS)}")
    try:
        return UNIT_KINDS[kind].model_validate(data)
    except ValidationError as exc:
        raise ConfigError(format_validation_error(source, exc)) from None


def read_unit_file(path: Path) -> BaseModel:
    """Read and validate one unit file."""
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise ConfigError(f"{path}: cannot read: {exc.strerror}") from None
    return parse_unit(_parse_text(path, text), str(path))


def bundled_units() -> dict[str, Path]:
    """Bundled unit files by name (file stem), sorted."""
    folder = resources.files(BUNDLED_PACKAGE)
    return {
        Path(entry.name).stem: Path(str(entry))
        for entry in sorted(folder.iterdir(), key=lambda e: e.name)
        if Path(entry.name).suffix in SUFFIXES
    }


def load_any_unit(spec: str) -> BaseModel:
    """A unit of any kind by bundled name (case-insensitive, ``sk8-3.5-4000``) or by file path."""
    path = Path(spec)
    if path.suffix.lower() in SUFFIXES or path.exists():
        if not path.exists():
            raise ConfigError(f"{spec}: no such file")
        return read_unit_file(path)
    units = bundled_units()
    key = spec.lower().replace(",", ".")
    if key not in units:
        raise ConfigError(f"unknown unit {spec!r}: give a file path or one of {', '.join(units)}")
    return read_unit_file(units[key])


def load_unit(spec: str) -> UnitConfig:
    """A beam pumping unit by bundled name or file path; other machine kinds are an error."""
    config = load_any_unit(spec)
    if not isinstance(config, UnitConfig):
        raise ConfigError(f"{spec}: is a {config.kind} machine, not a beam pumping unit")
    return config
