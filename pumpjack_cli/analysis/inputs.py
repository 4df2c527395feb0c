"""From a validated unit and the options to the core's inputs, decided once for every analysis.

The crank speed (``--spm``, or the motor's rated speed through belt and gearbox), the
dynamometer card on a crank-angle grid with uniform or dynamic rotation, the machine
of the equation of motion, the rigid-rod well load, the mass model with optional
counterweight overrides: every command that needs one of these gets it here.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..card_files import read_card
from ..core.beam.card import Card, card_load
from ..core.beam.linkage import Linkage
from ..core.beam.masses import MassModel
from ..core.dynamics.coefficients import CardLoad, Machine, mean_rod_speeds
from ..core.dynamics.drive import drive_inertia, motor_characteristic
from ..core.dynamics.periodic import steady_state
from ..core.sampling import crank_grid, cycle_period, uniform_time
from ..core.well import WellLoad, well_load
from ..errors import PumpjackError
from ..quantities import parse_quantity

#: Crank rotation models of the card-driven analyses.
ROTATIONS = ("uniform", "dynamic")


def require(unit, section: str, purpose: str) -> None:
    """Refuse a unit without the config section an analysis needs, saying what it is needed for."""
    if getattr(unit, section) is None:
        raise PumpjackError(f"unit {unit.name} has no [{section}] section; {purpose}")


def crank_speed(unit, spm: float | None) -> float:
    """Crank speed [1/s]: from ``--spm`` (strokes per minute) if given, else the motor's rated speed through the drive."""
    if spm is not None:
        return parse_quantity(f"{spm} spm", "rotational_speed")
    if unit.drive is None:
        raise PumpjackError(f"unit {unit.name} has no [drive] section: give the speed with --spm")
    return unit.drive.rated_crank_speed


def load_card(path: Path, linkage: Linkage, card_units: str) -> Card:
    """A dynamometer card on the unit's crank-angle axis; the reader's warnings go to stderr."""
    reading = read_card(path, linkage, card_units)
    for warning in reading.warnings:
        sys.stderr.write(f"pumpjack: warning: {warning}\n")
    return reading.card


def mass_model(unit, counterweight_count: int | None = None, counterweight_radius: str | None = None) -> MassModel:
    """The unit's masses, with the number of counterweight blocks or their radius replaced if given."""
    require(unit, "masses", "this analysis needs the link masses")
    counterweights = unit.masses.counterweights
    if counterweight_count is not None:
        counterweights = counterweights.model_copy(update={"count": counterweight_count})
    if counterweight_radius is not None:
        try:
            radius = parse_quantity(counterweight_radius, "length")
        except ValueError as exc:
            raise PumpjackError(f"--counterweight-radius: {exc}") from None
        if not 0 <= radius <= 5:
            raise PumpjackError(f"--counterweight-radius: {radius} m is outside 0..5 m")
        counterweights = counterweights.model_copy(update={"radius": radius})
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
    up, down = mean_rod_speeds(unit.geometry.linkage(), unit.drive.rated_crank_speed)
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


def machine(unit, card: Card | None = None) -> Machine:
    """The core's machine of the equation of motion: masses, drive, motor and the well model or a card."""
    for section in ("masses", "drive"):
        require(unit, section, "the equation of motion needs it")
    drive, motor = unit.drive, unit.drive.motor
    return Machine(
        linkage=unit.geometry.linkage(),
        masses=unit.masses.model(),
        drive_inertia=drive_inertia(
            motor.rotor_inertia + drive.motor_sheave_inertia, drive.gearbox_sheave_inertia + drive.gearbox_inertia,
            0.0, drive.belt_ratio, drive.gearbox_ratio,
        ),
        drive_ratio=drive.total_ratio,
        motor=motor_characteristic(motor.rated_power, motor.synchronous_speed, motor.rated_speed,
                                   motor.starting_torque_ratio, motor.breakdown_torque_ratio),
        rod_load=well(unit) if card is None else CardLoad(card),
    )


@dataclass(frozen=True)
class CardRun:
    """Crank angles [rad], time [s], crank speed [1/s] and acceleration [1/s²] and the
    card's polished-rod load [N] on them, the cycle time [s] and the rotation model."""

    crank_angle: np.ndarray
    time: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    load: np.ndarray
    period: float
    rotation: str
    card: Path

    @property
    def mean_crank_speed(self) -> float:
        """Mean crank speed over the cycle [1/s] (2 pi / cycle time)."""
        return 2.0 * np.pi / self.period


def card_run(unit, linkage: Linkage, card: Path, card_units: str, spm: float | None, steps: int,
             rotation: str) -> CardRun:
    """The card on a crank-angle grid with uniform or dynamic rotation; card warnings go to stderr."""
    measured = load_card(card, linkage, card_units)
    theta = crank_grid(steps)
    load = card_load(measured, theta)
    if rotation == "uniform":
        omega = crank_speed(unit, spm)
        return CardRun(theta, uniform_time(theta, omega), np.full(steps, omega), np.zeros(steps), load,
                       cycle_period(omega), rotation, card)
    if spm is not None:
        raise PumpjackError("--spm sets a uniform crank speed; with --rotation dynamic the motor sets the speed")
    state = steady_state(machine(unit, measured), theta)
    return CardRun(theta, state.time, state.omega, state.epsilon, load, state.summary.period, rotation, card)
