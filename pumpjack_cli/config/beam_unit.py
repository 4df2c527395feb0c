"""Schema of a beam pumping unit file (kind ``beam-pump``): geometry, masses, drive, well.

Values are SI numbers or strings with a unit, converted once by the field types of
:mod:`.quantities`; unknown keys are rejected. Geometry may be written with the GOST
names or the API Spec 11E letters ([API11E]; :mod:`.geometry_names`). Symbols in
parentheses in the descriptions are those of the source papers ([Spatial7SK12],
[PopovychSenchishak], [SK8Rotation2013]).
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Field, field_validator, model_validator

from ..core.beam.geometry import Linkage, beam_linkage, check_assembly
from ..core.designations import parse_designation
from ..core.dynamics.drive import belt_ratio, rated_crank_speed, total_ratio
from ..errors import ConfigError, DesignationError, GeometryError
from .geometry_names import ROTATION_SIGNS, canonical_geometry
if TYPE_CHECKING:  # the spatial and mass models are imported when a command uses them
    from ..core.beam.masses import MassModel
    from ..core.beam.redundancy import JointCompliance, PinTilts, PitmanSection
    from ..core.beam.spatial import SpatialLinkage
from .quantities import (Angle, Area, AreaMoment, Count, Density, Force, Fraction, KinematicViscosity, Length, Mass,
                         MomentOfInertia, Number, Power, Pressure, RotationalSpeed, RotationalStiffness, Section,
                         Torque, WeightPerLength, at_least)


class Geometry(Section):
    """Four-bar geometry of a conventional (class I) unit, rotation direction included."""

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
    def _assembles(self) -> "Geometry":
        try:
            check_assembly(self.linkage())
        except GeometryError as exc:
            raise ValueError(str(exc)) from None
        return self

    def linkage(self) -> Linkage:
        """The numerical core's planar four-bar (:func:`~pumpjack_cli.core.beam.geometry.beam_linkage`)."""
        return beam_linkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                            self.vertical_offset, ROTATION_SIGNS[self.rotation], self.crank_half_spacing,
                            self.equalizer_half_length)

    def spatial(self, source: str = "unit") -> SpatialLinkage:
        """The spatial model; needs crank_half_spacing and equalizer_half_length."""
        if self.crank_half_spacing is None or self.equalizer_half_length is None:
            raise ConfigError(
                f"{source}: geometry: the spatial model needs crank_half_spacing and equalizer_half_length"
            )
        from ..core.beam.spatial import SpatialLinkage

        return SpatialLinkage(self.linkage(), self.crank_half_spacing, self.equalizer_half_length)


class CrankArm(Section):
    """One of the two crank arms of the double crank (link 1), without counterweights."""

    mass: Mass = Field(gt=0, le=2e4, description="one crank arm (m_kr, m_1) [kg]")
    cg_radius: Length = Field(
        ge=0, le=5, description="crank shaft to the arm's centre of mass, towards the crank pin (OS_1) [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about its centre of mass, axis along the crank shaft [kg·m²]"
    )


class Counterweights(Section):
    """Counterweight blocks on the crank arms, treated as point masses at their centre of mass."""

    radius_range: tuple[Length, Length] | None = Field(
        default=None, description="smallest and largest radius the blocks can be set to in the crank's slots [m]")

    mass: Mass = Field(ge=0, le=5e3, description="one block (m_pr1) [kg]")
    count: Count = Field(ge=0, le=16, description="number of blocks on both arms together (shared equally)")
    radius: Length = Field(ge=0, le=5, description="crank shaft to the blocks' centre of mass (r_pr, OS_pr) [m]")
    phase: Angle = Field(
        default=0.0, gt=-math.pi, le=math.pi,
        description="angle from the crank pin direction to the blocks' centre of mass, in the direction of "
        "rotation; 0 on conventional units, whose blocks sit on the crank arm in line with the pin [rad]",
    )


class Pitman(Section):
    """One pitman (links 2 and 3 are equal)."""

    mass: Mass = Field(gt=0, le=5e3, description="one pitman (m_2) [kg]")
    cg_from_crank_pin: Length = Field(
        ge=0, le=20, description="crank pin A to the centre of mass, along the pitman (AS_2) [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about its centre of mass, across the pitman (J_S2) [kg·m²]"
    )


class Equalizer(Section):
    """Equalizer (cross-yoke, link 4); centre of mass at its bearing D on the beam."""

    mass: Mass = Field(ge=0, le=2e4, description="equalizer (m_tr, m_4) [kg]")
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about D, axis along the crank shaft (its pin line BB1) [kg·m²]"
    )
    transverse_inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about D, axes across the pin line [kg·m²]"
    )


class BeamPart(Section):
    """The walking beam body or the horsehead; centre of mass on the beam line D-C-E."""

    mass: Mass = Field(ge=0, le=5e4, description="mass [kg]")
    cg: Length = Field(
        ge=-20, le=20, description="centre bearing C to the centre of mass along the beam, towards the well positive [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e6, description="moment of inertia about its centre of mass, axis along the crank shaft [kg·m²]"
    )


class Masses(Section):
    """Masses, centres of mass and inertias of the moving links.

    The names in parentheses in the descriptions are those of [Spatial7SK12],
    [PopovychSenchishak] and [SK8Rotation2013].
    """

    crank_arm: CrankArm
    counterweights: Counterweights
    pitman: Pitman
    equalizer: Equalizer
    beam: BeamPart = Field(description="walking beam body (m_b, m_bal)")
    horsehead: BeamPart = Field(description="horsehead (m_gb)")

    def model(self) -> MassModel:
        """The numerical core's view of the masses."""
        from ..core.beam.masses import MassModel, counterweight_set_mass

        return MassModel(
            crank_arm_mass=self.crank_arm.mass,
            crank_arm_cg=self.crank_arm.cg_radius,
            crank_arm_inertia=self.crank_arm.inertia,
            counterweight_mass=counterweight_set_mass(self.counterweights.mass, self.counterweights.count),
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


class Motor(Section):
    """Induction motor nameplate data ([SK8Rotation2013] eqs. 25-26)."""

    model: str = Field(description="motor type designation")
    rated_power: Annotated[Power, at_least(10.0, "10 W")] = Field(gt=0, le=1e6, description="rated shaft power [W]")
    synchronous_speed: Annotated[RotationalSpeed, at_least(1.0, "1 rad/s")] = Field(gt=0, le=400, description="synchronous speed n_s [rad/s]")
    rated_speed: Annotated[RotationalSpeed, at_least(1.0, "1 rad/s")] = Field(gt=0, le=400, description="rated speed n_n [rad/s]")
    starting_torque_ratio: Number = Field(gt=0, le=10, description="starting torque / rated torque")
    breakdown_torque_ratio: Number = Field(gt=1, le=10, description="pull-out (maximum) torque / rated torque")
    rotor_inertia: MomentOfInertia = Field(gt=0, le=1e3, description="rotor moment of inertia [kg·m²]")

    @model_validator(mode="after")
    def _slip(self) -> "Motor":
        if not self.rated_speed < self.synchronous_speed:
            raise ValueError("rated_speed must be below synchronous_speed (an induction motor has slip)")
        return self


class Drive(Section):
    """Motor, V-belt drive and gearbox between the motor and the crank shaft."""

    motor: Motor
    gearbox: str = Field(description="gearbox type designation")
    gearbox_ratio: Number = Field(gt=1, le=200, description="gearbox reduction ratio u_r")
    motor_sheave_diameter: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=3, description="motor (driving) sheave diameter d_1 [m]")
    gearbox_sheave_diameter: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=5, description="gearbox (driven) sheave diameter d_2 [m]")
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
        """V-belt reduction u_belt = d_2 / d_1 (:func:`~pumpjack_cli.core.dynamics.drive.belt_ratio`)."""
        return belt_ratio(self.motor_sheave_diameter, self.gearbox_sheave_diameter)

    @property
    def total_ratio(self) -> float:
        """Motor speed / crank speed (:func:`~pumpjack_cli.core.dynamics.drive.total_ratio`)."""
        return total_ratio(self.gearbox_ratio, self.belt_ratio)

    @property
    def rated_crank_speed(self) -> float:
        """Crank speed at the motor's rated speed [1/s] (:func:`~pumpjack_cli.core.dynamics.drive.rated_crank_speed`)."""
        return rated_crank_speed(self.motor.rated_speed, self.total_ratio)


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


class PitmanSectionConfig(Section):
    """Elastic pitman for the real mechanism ([Spatial7SK12] eqs. 18-21; defaults from that
    paper where it gives them: E = 2.1e11 Pa, J_z = 17.61e-6 m^4)."""

    youngs_modulus: Annotated[Pressure, at_least(1e9, "1 GPa")] = Field(
        default=2.1e11, gt=0, le=1e12, description="E [Pa] ([Spatial7SK12])")
    shear_modulus: Annotated[Pressure, at_least(1e9, "1 GPa")] = Field(
        default=8.08e10, gt=0, le=1e12, description="G [Pa]: E / (2 (1 + 0.3)) for steel")
    area: Annotated[Area, at_least(1e-4, "1 cm2")] = Field(gt=0, le=0.1, description="cross-section area [m²]")
    inplane_inertia: Annotated[AreaMoment, at_least(1e-8, "1 cm4")] = Field(
        default=17.61e-6, gt=0, le=1e-2,
        description="J_z: second moment about the pin direction [m⁴] ([Spatial7SK12])",
    )
    outofplane_inertia: Annotated[AreaMoment, at_least(1e-8, "1 cm4")] = Field(gt=0, le=1e-2, description="second moment across the pin direction [m⁴]")
    torsion_constant: Annotated[AreaMoment, at_least(1e-8, "1 cm4")] = Field(gt=0, le=1e-2, description="J_t, the polar moment J_p for a tube [m⁴]")

    def model(self) -> PitmanSection:
        from ..core.beam.redundancy import PitmanSection

        return PitmanSection(self.youngs_modulus, self.shear_modulus, self.area, self.inplane_inertia,
                             self.outofplane_inertia, self.torsion_constant)


class Deviations(Section):
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
    crank_phase_mode: Literal["pin-bore", "whole-arm"] = Field(
        default="pin-bore", description="what the crank phase turns: pin A1's bore alone, or the whole arm of "
                                        "side 3 with its counterweights (keyway play)")

    def tilts(self) -> PinTilts:
        from ..core.beam.redundancy import PinTilts

        return PinTilts(self.crank_pin_tilt_radial, self.crank_pin_tilt_tangential,
                        self.equalizer_pin_roll, self.equalizer_pin_yaw)

    def apply(self, spatial: SpatialLinkage) -> SpatialLinkage:
        """The spatial model with the side-3 deviations of position (and, for a whole-arm crank
        phase, of side 3's arm and counterweights)."""
        arm = self.crank_phase if self.crank_phase_mode == "whole-arm" else 0.0
        return dataclasses.replace(spatial, crank_phase_offset=self.crank_phase, crank_radius_offset=self.crank_radius,
                                   pitman_length_offset=self.pitman_length, arm_phase_offset=arm)


class JointsConfig(Section):
    """Rotational stiffness and clearance of the revolute pins of the real mechanism, across
    their axes (default: rigid pins without clearance, as [Spatial7SK12])."""

    crank_pin_stiffness: RotationalStiffness | None = Field(
        default=None, gt=0, le=1e12, description="crank pins A, A1 with their studs [N·m/rad]; none: rigid")
    equalizer_pin_stiffness: RotationalStiffness | None = Field(
        default=None, gt=0, le=1e12, description="equalizer pins B, B1 and bearing [N·m/rad]; none: rigid")
    crank_pin_clearance: Angle = Field(default=0.0, ge=0, le=0.05,
                                       description="free tilt of the crank pins: radial clearance / width [rad]")
    equalizer_pin_clearance: Angle = Field(default=0.0, ge=0, le=0.05,
                                           description="free tilt of the equalizer pins: radial clearance / width [rad]")

    def model(self) -> JointCompliance:
        from ..core.beam.redundancy import JointCompliance

        return JointCompliance(
            math.inf if self.crank_pin_stiffness is None else self.crank_pin_stiffness,
            math.inf if self.equalizer_pin_stiffness is None else self.equalizer_pin_stiffness,
            self.crank_pin_clearance, self.equalizer_pin_clearance)


class Rating(Section):
    """Ratings of the unit, completing or overriding what its designation gives ([API11E], [GOST5866])."""

    gearbox_torque: Torque | None = Field(default=None, gt=0, le=1e7, description="gearbox (reducer) peak torque rating [N·m]")
    structure_load: Force | None = Field(default=None, gt=0, le=1e7, description="structure (polished-rod load) rating [N]")
    max_stroke: Length | None = Field(default=None, gt=0, le=20, description="maximum polished-rod stroke [m]")


class CounterbalanceConfig(Section):
    """The API 11E description of the counterbalance, for units without [masses] ([API11E], [Rowlan2004])."""

    structural_unbalance: Force = Field(
        default=0.0, ge=-1e6, le=1e6,
        description="B: force at the polished rod that holds the beam level with the pitmans off the crank pins, "
        "downward positive [N]")
    moment: Torque | None = Field(
        default=None, ge=0, le=1e7, description="M: largest moment of cranks and counterweights about the shaft [N·m]")
    phase: Angle = Field(default=0.0, gt=-math.pi, le=math.pi,
                         description="tau: crank offset angle, 0 for conventional units [rad]")


class UnitConfig(Section):
    """A whole pumping unit: identification, geometry and optional masses, drive, well."""

    kind: Literal["beam-pump"] = Field(default="beam-pump", description="machine kind (see UNIT_KINDS)")
    name: str = Field(min_length=1, description="designation, e.g. SK8-3,5-4000")
    description: str = Field(default="", description="one line shown by `pumpjack units`")
    sources: tuple[str, ...] = Field(default=(), description="where the data come from")
    designation: str | None = Field(
        default=None, description="API 11E or GOST 5866 designation (C-228D-213-86, SK8-3,5-4000); ratings come from it")
    rating: Rating = Rating()
    counterbalance: CounterbalanceConfig | None = None
    geometry: Geometry
    masses: Masses | None = None
    drive: Drive | None = None
    well: Well | None = None
    pitman_section: PitmanSectionConfig | None = None
    deviations: Deviations = Deviations()
    joints: JointsConfig = JointsConfig()

    @field_validator("designation")
    @classmethod
    def _designation(cls, text: str | None) -> str | None:
        if text is not None:
            try:
                parse_designation(text)
            except DesignationError as exc:
                raise ValueError(str(exc)) from None
        return text
