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

from pydantic import Field, PlainValidator, ValidationInfo, field_validator, model_validator

from ..core.designations import parse_designation
from ..errors import ConfigError, DesignationError
from ..quantities import parse_quantity
from .drive import Drive
from .letters import BeamLetters
from .masses import Masses
from .unit_classes import UNIT_CLASSES, designation_types, unit_class
from .well import Well
if TYPE_CHECKING:  # the core's models are imported when a command uses them
    from ..core.beam.card import Card
    from ..core.beam.counterbalance import CounterbalanceModel
    from ..core.designations import Ratings
    from ..core.beam.masses import MassModel
    from ..core.beam.redundancy import JointCompliance, PinTilts, PitmanSection
    from ..core.beam.spatial import SpatialLinkage
    from ..core.dynamics.coefficients import Machine
    from ..core.rods.plausibility import WellLimits
    from ..core.rods.pump import Pump
    from ..core.rods.string import RodString
    from ..core.well import WellLoad
from .quantities import (Angle, Area, AreaMoment, Force, Length, Pressure, RotationalStiffness, Section,
                         Text, Torque, at_least)


def _kind_geometry(value: Any, info: ValidationInfo) -> BeamLetters:
    """A ``[geometry]`` validated by the schema of its kind alone (``class``, set by
    :meth:`UnitConfig._unit_class`, names it in :data:`~.unit_classes.UNIT_CLASSES`): the
    other kinds' schemas are not built, which keeps a command's start-up short. Errors keep
    their place in the file (``geometry.pitman``)."""
    if isinstance(value, BeamLetters):
        return value
    if not isinstance(value, dict):
        raise ValueError(f"expected a table of keys, got {value!r}")
    return UNIT_CLASSES[value["class"]].model().model_validate(value, context=info.context)


#: The ``[geometry]`` of any kind of unit: the schema its ``class`` names in the registry (typed
#: ``Any`` for pydantic, so that ``model_dump`` writes out the kind's own schema whole).
if TYPE_CHECKING:
    Geometry = BeamLetters
else:
    Geometry = Annotated[Any, PlainValidator(_kind_geometry)]


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

    # At least 1 N·m/rad: a pin that tilts a radian under 1 N·m constrains nothing (real pins are
    # 1e5-1e8 N·m/rad), and far below it the flexibility matrix of the self-stress states is singular.
    crank_pin_stiffness: RotationalStiffness | None = Field(
        default=None, ge=1.0, le=1e12, description="crank pins A, A1 with their studs [N·m/rad]; none: rigid")
    equalizer_pin_stiffness: RotationalStiffness | None = Field(
        default=None, ge=1.0, le=1e12, description="equalizer pins B, B1 and bearing [N·m/rad]; none: rigid")
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


#: The largest counterbalance moment M a unit file may give or imply [N·m].
MOMENT_LIMIT = 1e7
#: A counterbalance effect tells the counterbalance only where the torque factor is at least this
#: share of its largest, and crank counterweights' torque (M sin) at least this share of M: nearer a
#: dead position, or with the counterweights' arm nearer the vertical, the moment it implies grows
#: without bound.
CBE_TORQUE_FACTOR_SHARE = 0.05
#: The SI unit of each rating, for messages.
RATING_UNITS = {"gearbox_torque": "N·m", "structure_load": "N", "max_stroke": "m"}
#: The largest value of each rating, of [rating] and of a designation alike (SI).
RATING_LIMITS = {"gearbox_torque": 1e7, "structure_load": 1e7, "max_stroke": 20.0}


class Rating(Section):
    """Ratings of the unit, completing or overriding what its designation gives ([API11E], [GOST5866])."""

    gearbox_torque: Annotated[Torque, at_least(1.0, "1 N*m")] | None = Field(
        default=None, gt=0, le=RATING_LIMITS["gearbox_torque"], description="gearbox (reducer) peak torque rating [N·m]")
    structure_load: Annotated[Force, at_least(1.0, "1 N")] | None = Field(
        default=None, gt=0, le=RATING_LIMITS["structure_load"], description="structure (polished-rod load) rating [N]")
    max_stroke: Annotated[Length, at_least(0.01, "10 mm")] | None = Field(
        default=None, gt=0, le=RATING_LIMITS["max_stroke"], description="maximum polished-rod stroke [m]")


class CounterbalanceConfig(Section):
    """The API 11E description of the counterbalance, for units without [masses] ([API11E], [Rowlan2004])."""

    structural_unbalance: Force = Field(
        default=0.0, ge=-1e6, le=1e6,
        description="B: force at the polished rod that holds the beam level with the pitmans off the crank pins, "
        "downward positive [N]")
    moment: Torque | None = Field(
        default=None, ge=0, le=MOMENT_LIMIT,
        description="M: largest moment of cranks and counterweights about the shaft [N·m]")
    phase: Angle = Field(default=0.0, gt=-math.pi, le=math.pi,
                         description="tau: crank offset angle, the lead of the counterweights' resultant ahead "
                         "of the crank pin in the direction of rotation; 0 for conventional units [rad]")
    counterbalance_effect: Force | None = Field(
        default=None, ge=0, le=1e7,
        description="CBE: the polished-rod load the counterbalance holds at counterbalance_effect_angle, as a crew "
        "measures it; instead of moment (or of the kind's own balancing variable) [N]")
    counterbalance_effect_angle: Angle | None = Field(
        default=None, gt=0, lt=2 * math.pi,
        description="crank angle at which counterbalance_effect was measured, from 12 o'clock in the direction of "
        "rotation [default: the cranks horizontal on the upstroke, 90 deg, 270 deg on a Mark II] [rad]")

    @model_validator(mode="after")
    def _moment_or_effect(self) -> "CounterbalanceConfig":
        if self.moment is not None and self.counterbalance_effect is not None:
            raise ValueError("give moment or counterbalance_effect, not both")
        return self


class UnitConfig(Section):
    """A whole pumping unit: identification, geometry and optional masses, drive, well."""

    kind: Literal["beam-pump"] = Field(default="beam-pump", description="machine kind (see UNIT_KINDS)")
    name: Text = Field(min_length=1, description="designation, e.g. SK8-3,5-4000")
    description: Text = Field(default="", description="one line shown by `pumpjack units`")
    sources: tuple[str, ...] = Field(default=(), description="where the data come from")
    designation: Text | None = Field(
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
                found = parse_designation(text, designation_types())
            except DesignationError as exc:
                raise ValueError(str(exc)) from None
            for name, top in RATING_LIMITS.items():
                value = getattr(found, name)
                if value > top:
                    raise ValueError(f"unit designation {text!r}: its {name.replace('_', ' ')} rating {value:.4g} "
                                     f"{RATING_UNITS[name]} is above {top:g} {RATING_UNITS[name]}, the limit of "
                                     f"[rating] {name}")
        return text

    @field_validator("geometry", mode="before")
    @classmethod
    def _unit_class(cls, geometry: Any, info: ValidationInfo) -> Any:
        """The kind of unit: ``class``, else the designation's letters, else conventional
        (:func:`~pumpjack_cli.config.unit_classes.unit_class`)."""
        if not isinstance(geometry, dict):
            return geometry
        return {**geometry, "class": unit_class(geometry, info.data.get("designation"))}

    # --- the core's objects of the unit: built here, once, for every analysis -------------

    def require(self, section: str, purpose: str) -> None:
        """Refuse a unit without the section an analysis needs, saying what it is needed for."""
        if getattr(self, section) is None:
            raise ConfigError(f"unit {self.name} has no [{section}] section; {purpose}")

    def crank_speed(self, spm: float | None) -> float:
        """Crank speed [1/s]: ``spm`` (strokes per minute) if given, else the motor's rated speed
        through the drive."""
        if spm is not None:
            return parse_quantity(f"{spm} spm", "rotational_speed")
        if self.drive is None:
            raise ConfigError(f"unit {self.name} has no [drive] section: give the speed with --spm")
        return self.drive.rated_crank_speed

    def require_well(self) -> Well:
        """The ``[well]``, required."""
        self.require("well", "the rod-string models need the pump depth, the plunger and the rod string")
        assert self.well is not None
        return self.well

    def rods(self) -> RodString:
        """The tapered rod string of the ``[well]`` (:meth:`.well.Well.rods`)."""
        try:
            return self.require_well().rods()
        except ConfigError as exc:
            raise ConfigError(f"unit {self.name}: {exc}") from None

    def pump_pressures(self) -> tuple[float, float] | None:
        """Discharge and intake pressure at the pump [Pa] (:meth:`.well.Well.pressures`)."""
        return self.require_well().pressures()

    def pump(self) -> Pump:
        """The pump of the ``[well]`` (:meth:`.well.Well.pump`)."""
        try:
            return self.require_well().pump()
        except ConfigError as exc:
            raise ConfigError(f"unit {self.name}: {exc}") from None

    def mass_model(self, counterweight_count: int | None = None, counterweight_radius: float | None = None) -> MassModel:
        """The masses, with the number of counterweight blocks or their radius [m] replaced if given."""
        self.require("masses", "this analysis needs the link masses")
        assert self.masses is not None
        if counterweight_radius is not None and not 0 <= counterweight_radius <= 5:
            raise ConfigError(f"--counterweight-radius: {counterweight_radius} m is outside 0..5 m")
        return self.masses.model(counterweight_count, counterweight_radius)

    def counterbalance_model(self) -> tuple[CounterbalanceModel, bool]:
        """The structure and counterbalance of the unit's kind (its geometry's ``counterbalance()``)
        and whether the present counterbalance is known; a measured ``[counterbalance]
        counterbalance_effect`` sets the kind's balancing variable (the moment M of crank
        counterweights) through the kind's own model
        (:func:`~pumpjack_cli.core.beam.counterbalance.value_for_effect`)."""
        try:
            model, known = self.geometry.counterbalance(self.counterbalance,
                                                        self.masses.model() if self.masses is not None else None)
        except ConfigError as exc:
            raise ConfigError(f"unit {self.name}: {exc}") from None
        given = self.counterbalance
        if given is None or given.counterbalance_effect is None:
            return model, known
        if known:
            raise ConfigError(f"unit {self.name}: [counterbalance] counterbalance_effect: the present "
                              f"{model.variable.replace('_', ' ')} is given too; give one of them")
        return self._measured_counterbalance(model, given.counterbalance_effect, given.counterbalance_effect_angle), True

    def _measured_counterbalance(self, model: CounterbalanceModel, effect: float,
                                 angle: float | None) -> CounterbalanceModel:
        """The counterbalance whose effect at crank angle ``angle`` [rad] (None: the cranks horizontal on the
        upstroke, :func:`~pumpjack_cli.core.beam.counterbalance.upstroke_test_angle`) is ``effect`` [N]."""
        import numpy as np

        from ..core.beam.counterbalance import upstroke_test_angle, value_for_effect
        from ..errors import TorqueError

        if angle is None:
            angle = upstroke_test_angle(self.geometry.mechanism())

        where = f"unit {self.name}: [counterbalance] counterbalance_effect"
        mechanism = self.geometry.mechanism()
        test = mechanism.motion(np.array([angle]))
        largest = float(np.max(np.abs(mechanism.torque_factor(np.linspace(0.0, 2.0 * math.pi, 361)))))
        if abs(float(test.torque_factor[0])) < CBE_TORQUE_FACTOR_SHARE * largest:
            raise ConfigError(f"{where}: at {math.degrees(angle):.4g} deg the torque factor is below "
                              f"{100 * CBE_TORQUE_FACTOR_SHARE:g} % of its largest, too near a dead position for the "
                              f"effect to tell the counterbalance; give it measured with the cranks nearer horizontal")
        if model.variable == "counterbalance_moment":
            share = abs(float(model.torque_per_value(test)[0]))
            if share < CBE_TORQUE_FACTOR_SHARE:
                raise ConfigError(f"{where}: at {math.degrees(angle):.4g} deg the counterweights' arm stands within "
                                  f"{math.degrees(math.asin(share)):.2g} deg of the vertical, where their torque is "
                                  f"{100 * share:.2g} % of M: the effect measured there does not tell the moment; give "
                                  f"it measured with the cranks nearer horizontal")
        try:
            value = value_for_effect(test, model, effect)
        except TorqueError as exc:
            raise ConfigError(f"{where}: {exc}") from None
        if not math.isfinite(value) or value < 0:
            raise ConfigError(f"{where}: {effect:.6g} N at {math.degrees(angle):.4g} deg gives a "
                              f"{model.variable.replace('_', ' ')} of {value:.6g} {model.symbol}, below 0; check the "
                              f"effect, its angle and structural_unbalance")
        top = MOMENT_LIMIT if model.variable == "counterbalance_moment" else math.inf
        if value > top:
            raise ConfigError(f"{where}: {effect:.6g} N at {math.degrees(angle):.4g} deg gives a counterbalance "
                              f"moment of {value:.6g} N·m, above the {top:g} N·m of [counterbalance] moment")
        return model.with_value(value)

    def ratings(self) -> Ratings:
        """The unit's ratings: its ``designation`` (or its name when that is a designation),
        completed or overridden by ``[rating]`` ([API11E], [GOST5866])."""
        from ..core.designations import Ratings

        text = self.designation if self.designation is not None else self.name
        try:
            designation = parse_designation(text, designation_types())
        except DesignationError:
            designation = None  # a name that is no designation (a validated designation parses)

        def pick(name: str) -> float | None:
            given = getattr(self.rating, name)
            return given if given is not None else (getattr(designation, name) if designation is not None else None)

        return Ratings(pick("gearbox_torque"), pick("structure_load"), pick("max_stroke"))

    def spatial(self) -> SpatialLinkage:
        """The spatial six-link model of the unit ([Spatial7SK12]): the class I unit's, with its pin
        spacings; another kind says it has none."""
        build = getattr(self.geometry, "spatial", None)
        if build is None:
            raise ConfigError(f"unit {self.name} is a {self.geometry.unit_class} unit; the spatial kinetostatics "
                              f"(reactions, compare-redundancy, torque --method exact) models the class I "
                              f"six-link mechanism of conventional units")
        return build(self.name)

    def well_limits(self) -> WellLimits | None:
        """What the rods and the fluid column of the ``[well]`` can produce, for the plausibility of
        a card (:mod:`~pumpjack_cli.core.rods.plausibility`); None without a ``[well]``."""
        import math

        from ..core.rods.plausibility import WellLimits
        from ..core.rods.pump import discharge_pressure

        if self.well is None:
            return None
        w = self.well
        largest = discharge_pressure(w.pump_vertical_depth(), w.fluid_density, w.tubing_head_pressure)
        hanging = None
        if w.survey is not None:
            from ..core.rods.deviated import axial_weight

            hanging = axial_weight(self.rods(), w.path(), w.fluid_density)
        return WellLimits(self.rods(), w.fluid_density, largest * math.pi * w.plunger_diameter**2 / 4.0, hanging)

    def rigid_well_load(self) -> WellLoad:
        """The rigid-rod well model of [SK8Rotation2013] for the ``[well]``, friction at the mean rod
        speeds of the rated crank speed."""
        import numpy as np

        from ..core.dynamics.coefficients import mean_rod_speeds
        from ..core.well import well_load

        if self.well is None:
            raise ConfigError(f"unit {self.name} has no [well] section: give one, or a dynamometer card with --card")
        w = self.well
        missing = [name for name in ("plunger_clearance", "pump_submergence") if getattr(w, name) is None]
        if missing:
            raise ConfigError(f"unit {self.name}: well.{' and well.'.join(missing)} needed by the well model "
                              f"(or drive the unit with --card)")
        self.require("drive", "the well model's friction needs the rated crank speed")
        up, down = mean_rod_speeds(self.geometry.mechanism(), self.crank_speed(None))
        return well_load(pump_depth=w.pump_depth, submergence=w.pump_submergence, plunger_diameter=w.plunger_diameter,
                         plunger_clearance=w.plunger_clearance, rod_diameters=np.array([s.diameter for s in w.rod_string]),
                         rod_fractions=np.array([s.fraction for s in w.rod_string]), rod_density=w.rod_density,
                         fluid_density=w.fluid_density, kinematic_viscosity=w.fluid_kinematic_viscosity,
                         tubing_diameter=w.tubing_inner_diameter, upstroke_speed=up, downstroke_speed=down)

    def machine(self, card: Card | None = None, *, elastic_rods: bool = False) -> Machine:
        """The machine of the equation of motion: masses, drive, motor and the well model or a card;
        with ``elastic_rods`` no rod load (the coupled model carries the rods itself)."""
        from ..core.dynamics.coefficients import CardLoad, Machine
        from ..core.dynamics.drive import drive_inertia, motor_characteristic

        for section in ("masses", "drive"):
            self.require(section, "the equation of motion needs it")
        assert self.masses is not None and self.drive is not None
        drive, motor = self.drive, self.drive.motor
        return Machine(
            linkage=self.geometry.mechanism(),
            masses=self.masses.model(),
            drive_inertia=drive_inertia(motor.rotor_inertia + drive.motor_sheave_inertia,
                                        drive.gearbox_sheave_inertia + drive.gearbox_inertia, 0.0, drive.belt_ratio,
                                        drive.gearbox_ratio),
            drive_ratio=drive.total_ratio,
            motor=motor_characteristic(motor.rated_power, motor.synchronous_speed, motor.rated_speed,
                                       motor.starting_torque_ratio, motor.breakdown_torque_ratio),
            rod_load=None if elastic_rods else self.rigid_well_load() if card is None else CardLoad(card),
        )
