"""`pumpjack dynamics`: non-uniform crank rotation from the machine's equation of motion (seed 004)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from ..config import UnitConfig, load_unit
from ..core.beam.card import Card
from ..core.dynamics.coefficients import CardLoad, Machine, mean_rod_speeds
from ..core.dynamics.drive import drive_inertia, motor_characteristic
from ..core.dynamics.periodic import DEFAULT_RTOL, SteadyState, steady_state
from ..core.sampling import crank_grid
from ..core.well import WellLoad, well_load
from ..errors import PumpjackError
from ..render import Column, Panel, Report, Scalar
from .common import (
    CardUnitsOption,
    FormatOption,
    OutputOption,
    PlotOption,
    UnitArgument,
    UnitsOption,
    UnitSystem,
    load_card,
    output,
)

CardOption = Annotated[
    Path | None,
    typer.Option("--card", help="drive the unit with a dynamometer card CSV instead of the well model (docs/cards.md)",
                 dir_okay=False),
]


def _well_load(config: UnitConfig) -> WellLoad:
    """The seed 004 well model of the unit's [well], friction at the mean rod speeds of the rated crank speed."""
    well = config.well
    if well is None:
        raise PumpjackError(f"unit {config.name} has no [well] section: give one, or a dynamometer card with --card")
    missing = [name for name in ("plunger_clearance", "pump_submergence") if getattr(well, name) is None]
    if missing:
        raise PumpjackError(f"unit {config.name}: well.{' and well.'.join(missing)} needed by the well model "
                            f"(or drive the unit with --card)")
    up, down = mean_rod_speeds(config.geometry.linkage(), config.drive.rated_crank_speed)
    return well_load(
        pump_depth=well.pump_depth,
        submergence=well.pump_submergence,
        plunger_diameter=well.plunger_diameter,
        plunger_clearance=well.plunger_clearance,
        rod_diameters=np.array([s.diameter for s in well.rod_string]),
        rod_fractions=np.array([s.fraction for s in well.rod_string]),
        rod_density=well.rod_density,
        fluid_density=well.fluid_density,
        kinematic_viscosity=well.fluid_kinematic_viscosity,
        tubing_diameter=well.tubing_inner_diameter,
        upstroke_speed=up,
        downstroke_speed=down,
    )


def build_machine(config: UnitConfig, card: Card | None = None) -> Machine:
    """The core's machine from a unit config: masses, drive, motor and the well model or a card."""
    for section in ("masses", "drive"):
        if getattr(config, section) is None:
            raise PumpjackError(f"unit {config.name} has no [{section}] section; the equation of motion needs it")
    drive, motor = config.drive, config.drive.motor
    return Machine(
        linkage=config.geometry.linkage(),
        masses=config.masses.model(),
        drive_inertia=drive_inertia(
            motor.rotor_inertia + drive.motor_sheave_inertia, drive.gearbox_sheave_inertia + drive.gearbox_inertia,
            0.0, drive.belt_ratio, drive.gearbox_ratio,
        ),
        drive_ratio=drive.total_ratio,
        motor=motor_characteristic(motor.rated_power, motor.synchronous_speed, motor.rated_speed,
                                   motor.starting_torque_ratio, motor.breakdown_torque_ratio),
        rod_load=_well_load(config) if card is None else CardLoad(card),
    )


def dynamics_report(title: str, machine: Machine, result: SteadyState) -> Report:
    """Tabulate the periodic solution: per-angle motion, torques and power; summary and convergence."""
    s = result.summary
    summary = [
        Scalar("mean_crank_speed", "angular_velocity", s.mean_speed, "mean crank speed, 2 pi / cycle time"),
        Scalar("rated_crank_speed", "angular_velocity", s.rated_crank_speed,
               "uniform crank speed at the motor's rated speed (seed 004: 1.1422 1/s)"),
        Scalar("start_crank_speed", "angular_velocity", s.start_speed, "crank speed at the start of the upstroke"),
    ]
    for label, extreme, quantity, what in (
        ("max_crank_speed", s.max_speed, "angular_velocity", "max crank speed omega1"),
        ("min_crank_speed", s.min_speed, "angular_velocity", "min crank speed omega1"),
        ("max_crank_acceleration", s.max_acceleration, "angular_acceleration", "max crank acceleration epsilon1"),
        ("min_crank_acceleration", s.min_acceleration, "angular_acceleration", "min crank acceleration epsilon1"),
        ("max_motor_torque", s.max_motor_torque, "torque", "max motor torque"),
        ("min_motor_torque", s.min_motor_torque, "torque", "min motor torque (negative: generating)"),
        ("max_power", s.max_power, "power", "max motor power"),
        ("min_power", s.min_power, "power", "min motor power (negative: generating)"),
        ("peak_static_torque", s.peak_static_torque, "torque", "peak crank torque of load and weights without inertia"),
    ):
        summary.append(Scalar(label, quantity, extreme.value, what))
        summary.append(Scalar(f"{label}_crank_angle", "angle", extreme.crank_angle, f"crank angle of the {what}"))
    c = s.convergence
    summary += [
        Scalar("speed_fluctuation", "percent", s.speed_fluctuation, "coefficient of speed fluctuation (max - min) / mean"),
        Scalar("cycle_time", "time", s.period, "time of one stroke cycle"),
        Scalar("strokes_per_minute", "stroke_rate", s.mean_speed, "pumping speed"),
        Scalar("energy_per_cycle", "energy", s.energy_per_cycle, "energy the motor delivers per cycle"),
        Scalar("rod_work_per_cycle", "energy", s.rod_work_per_cycle, "work of the polished-rod load per cycle"),
        Scalar("mean_power", "power", s.energy_per_cycle / s.period, "mean motor power"),
        Scalar("constant_inertia", "moment_of_inertia", s.constant_inertia,
               "constant part of the reduced inertia: drive, crank arms, counterweights"),
        Scalar("starting_torque", "torque", s.starting_torque, "motor starting torque reduced to the crank"),
        Scalar("breakdown_torque_margin", "ratio", s.breakdown_torque_margin, "motor pull-out torque / max motor torque"),
        Scalar("shooting_iterations", "count", c.iterations, "integrations of the cycle to find the periodic start speed"),
        Scalar("periodicity_error", "ratio", c.periodicity_error, "|omega1 end - start| / start of the accepted cycle"),
        Scalar("rtol", "ratio", c.rtol, "relative tolerance of the integration (DOP853)"),
    ]
    if isinstance(machine.rod_load, WellLoad):
        for name, what in (
            ("upstroke", "polished-rod load on the upstroke (well model)"),
            ("downstroke", "polished-rod load on the downstroke (well model)"),
            ("rod_weight", "weight of the rods in the fluid"),
            ("fluid_load", "fluid load on the plunger"),
            ("plunger_friction", "plunger-barrel friction"),
            ("tubing_friction", "hydraulic loss of the fluid in the tubing, upstroke"),
            ("rod_friction", "viscous drag of the rods, downstroke"),
        ):
            label = f"{name}_rod_load" if name.endswith("stroke") else name
            summary.append(Scalar(label, "force", getattr(machine.rod_load, name), what))
    # (name, quantity, description, values, shown in the terminal table)
    table = (
        ("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation", result.crank_angle, True),
        ("time", "time", "time from crank angle 0", result.time, True),
        ("omega1", "angular_velocity", "crank angular velocity", result.omega, True),
        ("epsilon1", "angular_acceleration", "crank angular acceleration", result.epsilon, True),
        ("motor_speed", "angular_velocity", "motor shaft speed", result.motor_speed, False),
        ("motor_torque", "torque", "motor shaft torque (linear characteristic)", result.motor_torque, True),
        ("power", "power", "motor shaft power", result.power, False),
        ("velocity", "velocity", "polished-rod velocity, non-uniform rotation, up positive", result.rod.velocity, True),
        ("velocity_uniform", "velocity", "polished-rod velocity, uniform rotation at the rated crank speed",
         result.rod_uniform.velocity, True),
        ("acceleration", "acceleration", "polished-rod acceleration, non-uniform rotation", result.rod.acceleration, False),
        ("acceleration_uniform", "acceleration", "polished-rod acceleration, uniform rotation",
         result.rod_uniform.acceleration, False),
        ("inertia_torque", "torque", "I_red epsilon1 + 1/2 I_red' omega1^2: torque accelerating the masses",
         result.inertia_torque, True),
        ("constant_inertia_torque", "torque", "I_const epsilon1 (seed 004 M_i1)", result.constant_inertia_torque, False),
        ("rod_load", "force", "polished-rod load", result.rod_load, False),
        ("load_torque", "torque", "polished-rod load x torque factor", result.load_torque, False),
        ("gravity_torque", "torque", "torque of the links' weights and counterweights", result.gravity_torque, False),
        ("reduced_inertia", "moment_of_inertia", "reduced moment of inertia I_red", result.reduced_inertia, False),
        ("reduced_inertia_rate", "moment_of_inertia", "d I_red / d crank angle (per rad)",
         result.reduced_inertia_rate, False),
    )
    columns = tuple(Column(name, quantity, what, brief) for name, quantity, what, _, brief in table)
    series = {name: values for name, _, _, values, _ in table}
    panels = (
        Panel("crank speed omega1", ("omega1",)),
        Panel("polished-rod velocity", ("velocity",), ("velocity_uniform",)),
        Panel("polished-rod acceleration", ("acceleration",), ("acceleration_uniform",)),
        Panel("motor torque", ("motor_torque",)),
    )
    return Report(title=title, summary=tuple(summary), columns=columns, series=series, panels=panels)


def dynamics(
    unit: UnitArgument,
    card: CardOption = None,
    card_units: CardUnitsOption = UnitSystem.si,
    rtol: Annotated[float, typer.Option(help="relative tolerance of the integration and of the periodicity",
                                        min=1e-13, max=1e-3)] = DEFAULT_RTOL,
    steps: Annotated[int, typer.Option(help="crank positions per revolution in the output", min=4, max=1_000_000)] = 360,
    fmt: FormatOption = None,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Non-uniform crank rotation from the machine's equation of motion (seed 004).

    The periodic motion under the motor's characteristic, the well (or a dynamometer
    card) and the weights."""
    config = load_unit(unit)
    measured = None if card is None else load_card(card, config.geometry.linkage(), card_units)
    machine = build_machine(config, measured)
    result = steady_state(machine, crank_grid(steps), rtol=rtol)
    source = "well model" if card is None else f"card {card.name}"
    output(dynamics_report(f"{config.name}: dynamics, {source}", machine, result), fmt, units, out, plot)
