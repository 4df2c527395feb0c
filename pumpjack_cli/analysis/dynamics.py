"""Non-uniform crank rotation from the machine's equation of motion: the result table of `pumpjack dynamics`."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..core.dynamics.periodic import steady_state
from ..core.sampling import crank_grid
from ..core.well import WellLoad
from ..results import Column, Panel, Result, Scalar
from .card_runs import CardSource
from .inputs import crank_columns, dead_position_marks, extreme_scalars, motor_levels

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: Well-model forces of the summary: name, description.
_WELL_FORCES = (("upstroke_rod_load", "upstroke"), ("downstroke_rod_load", "downstroke"), ("rod_weight", "rod_weight"),
                ("fluid_load", "fluid_load"), ("plunger_friction", "plunger_friction"),
                ("tubing_friction", "tubing_friction"), ("rod_friction", "rod_friction"))


def dynamics(unit: UnitConfig, card: CardSource | None, rtol: float, steps: int) -> Result:
    """The periodic motion under the motor, the well model (or a card) and the weights ([SK8Rotation2013])."""
    measured = None if card is None else card.read(unit).card
    machine_ = unit.machine(measured)
    result = steady_state(machine_, crank_grid(steps), rtol=rtol)
    s = result.summary
    summary = [
        Scalar("mean_crank_speed", s.mean_speed),
        Scalar("rated_crank_speed", s.rated_crank_speed),
        Scalar("start_crank_speed", s.start_speed),
    ]
    summary += extreme_scalars((
        ("max_crank_speed", s.max_speed),
        ("min_crank_speed", s.min_speed),
        ("max_crank_acceleration", s.max_acceleration),
        ("min_crank_acceleration", s.min_acceleration),
        ("max_motor_torque", s.max_motor_torque),
        ("min_motor_torque", s.min_motor_torque),
        ("max_motor_power", s.max_power),
        ("min_motor_power", s.min_power),
        ("max_static_torque", s.peak_static_torque),
    ))
    c = s.convergence
    summary += [
        Scalar("speed_fluctuation", s.speed_fluctuation),
        Scalar("period", s.period),
        Scalar("strokes_per_minute", s.mean_speed),
        Scalar("energy_per_cycle", s.energy_per_cycle),
        Scalar("rod_work_per_cycle", s.rod_work_per_cycle),
        Scalar("mean_motor_power", s.mean_power),
        Scalar("constant_inertia", s.constant_inertia),
        Scalar("starting_torque", s.starting_torque),
        Scalar("breakdown_torque_margin", s.breakdown_torque_margin),
        Scalar("shooting_iterations", c.iterations),
        Scalar("periodicity_error", c.periodicity_error),
        Scalar("rtol", c.rtol),
    ]
    if isinstance(machine_.rod_load, WellLoad):
        summary += [Scalar(name, getattr(machine_.rod_load, field)) for name, field in _WELL_FORCES]
    columns = (
        *crank_columns(result.crank_angle, result.time, result.crank_speed, result.crank_acceleration),
        Column("motor_speed", result.motor_speed),
        Column("motor_torque", result.motor_torque),
        Column("motor_power", result.power),
        Column("velocity", result.rod.velocity),
        Column("velocity_uniform", result.rod_uniform.velocity),
        Column("acceleration", result.rod.acceleration),
        Column("acceleration_uniform", result.rod_uniform.acceleration),
        Column("inertia_torque", result.inertia_torque),
        Column("constant_inertia_torque", result.constant_inertia_torque),
        Column("rod_load", result.rod_load),
        Column("rod_load_torque", result.rod_load_torque),
        Column("gravity_torque", result.gravity_torque),
        Column("reduced_inertia", result.reduced_inertia),
        Column("reduced_inertia_rate", result.reduced_inertia_rate),
    )
    panels = (
        Panel("crank speed ω1", ("crank_speed",)),
        Panel("polished-rod velocity", ("velocity",), ("velocity_uniform",),
              labels=(("velocity", "non-uniform rotation"), ("velocity_uniform", "uniform rotation"))),
        Panel("polished-rod acceleration", ("acceleration",), ("acceleration_uniform",),
              labels=(("acceleration", "non-uniform rotation"), ("acceleration_uniform", "uniform rotation"))),
        Panel("motor torque", ("motor_torque",), levels=motor_levels(machine_.motor)),
    )
    source = "well model" if card is None else f"card {card.name}"
    return Result(f"{unit.name}: dynamics, {source}", tuple(summary), columns, panels,
                  dead_position_marks(machine_.linkage))
