"""The machine of the equation of motion, the rigid-rod well load and the mass model of a unit."""

from __future__ import annotations

import numpy as np

from ..core.beam.card import Card
from ..core.beam.masses import MassModel
from ..core.dynamics.coefficients import CardLoad, Machine, mean_rod_speeds
from ..core.dynamics.drive import drive_inertia, motor_characteristic
from ..core.well import WellLoad, well_load
from ..errors import PumpjackError
from .inputs import require


def mass_model(unit, counterweight_count: int | None = None, counterweight_radius: float | None = None) -> MassModel:
    """The unit's masses, with the number of counterweight blocks or their radius [m] replaced if given."""
    require(unit, "masses", "this analysis needs the link masses")
    counterweights = unit.masses.counterweights
    if counterweight_count is not None:
        counterweights = counterweights.model_copy(update={"count": counterweight_count})
    if counterweight_radius is not None:
        if not 0 <= counterweight_radius <= 5:
            raise PumpjackError(f"--counterweight-radius: {counterweight_radius} m is outside 0..5 m")
        counterweights = counterweights.model_copy(update={"radius": counterweight_radius})
    return unit.masses.model_copy(update={"counterweights": counterweights}).model()


def well(unit) -> WellLoad:
    """The rigid-rod well model of [SK8Rotation2013] for the unit's [well], friction at the mean
    rod speeds of the rated crank speed."""
    if unit.well is None:
        raise PumpjackError(f"unit {unit.name} has no [well] section: give one, or a dynamometer card with --card")
    w = unit.well
    missing = [name for name in ("plunger_clearance", "pump_submergence") if getattr(w, name) is None]
    if missing:
        raise PumpjackError(f"unit {unit.name}: well.{' and well.'.join(missing)} needed by the well model "
                            f"(or drive the unit with --card)")
    up, down = mean_rod_speeds(unit.geometry.mechanism(), unit.drive.rated_crank_speed)
    return well_load(
        pump_depth=w.pump_depth,
        submergence=w.pump_submergence,
        plunger_diameter=w.plunger_diameter,
        plunger_clearance=w.plunger_clearance,
        rod_diameters=np.array([s.diameter for s in w.rod_string]),
        rod_fractions=np.array([s.fraction for s in w.rod_string]),
        rod_density=w.rod_density,
        fluid_density=w.fluid_density,
        kinematic_viscosity=w.fluid_kinematic_viscosity,
        tubing_diameter=w.tubing_inner_diameter,
        upstroke_speed=up,
        downstroke_speed=down,
    )


def machine(unit, card: Card | None = None, *, elastic_rods: bool = False) -> Machine:
    """The core's machine of the equation of motion: masses, drive, motor and the well model or
    a card; with ``elastic_rods`` no rod load (the coupled model carries the rods itself)."""
    for section in ("masses", "drive"):
        require(unit, section, "the equation of motion needs it")
    drive, motor = unit.drive, unit.drive.motor
    return Machine(
        linkage=unit.geometry.mechanism(),
        masses=unit.masses.model(),
        drive_inertia=drive_inertia(
            motor.rotor_inertia + drive.motor_sheave_inertia, drive.gearbox_sheave_inertia + drive.gearbox_inertia,
            0.0, drive.belt_ratio, drive.gearbox_ratio,
        ),
        drive_ratio=drive.total_ratio,
        motor=motor_characteristic(motor.rated_power, motor.synchronous_speed, motor.rated_speed,
                                   motor.starting_torque_ratio, motor.breakdown_torque_ratio),
        rod_load=None if elastic_rods else well(unit) if card is None else CardLoad(card),
    )
