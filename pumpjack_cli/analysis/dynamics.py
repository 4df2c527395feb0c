"""Non-uniform crank rotation from the machine's equation of motion: the result table of `pumpjack dynamics`."""

from __future__ import annotations

from ..core.dynamics.periodic import steady_state
from ..core.sampling import crank_grid
from ..core.well import WellLoad
from ..results import Column, Panel, Result, Scalar
from .card_runs import CardSource
from .inputs import crank_columns, extreme_scalars
from .machine import machine

#: Well-model forces of the summary: name, description.
_WELL_FORCES = (
    ("upstroke_rod_load", "upstroke", "polished-rod load on the upstroke (well model)"),
    ("downstroke_rod_load", "downstroke", "polished-rod load on the downstroke (well model)"),
    ("rod_weight", "rod_weight", "weight of the rods in the fluid"),
    ("fluid_load", "fluid_load", "fluid load on the plunger"),
    ("plunger_friction", "plunger_friction", "plunger-barrel friction"),
    ("tubing_friction", "tubing_friction", "hydraulic loss of the fluid in the tubing, upstroke"),
    ("rod_friction", "rod_friction", "viscous drag of the rods, downstroke"),
)


def dynamics(unit, card: CardSource | None, rtol: float, steps: int) -> Result:
    """The periodic motion under the motor, the well model (or a card) and the weights ([SK8Rotation2013])."""
    measured = None if card is None else card.read(unit.geometry.linkage()).card
    machine_ = machine(unit, measured)
    result = steady_state(machine_, crank_grid(steps), rtol=rtol)
    s = result.summary
    summary = [
        Scalar("mean_crank_speed", "angular_velocity", s.mean_speed, "mean crank speed, 2 pi / cycle time"),
        Scalar("rated_crank_speed", "angular_velocity", s.rated_crank_speed,
               "uniform crank speed at the motor's rated speed ([SK8Rotation2013]: 1.1422 1/s)"),
        Scalar("start_crank_speed", "angular_velocity", s.start_speed, "crank speed at the start of the upstroke"),
    ]
    summary += extreme_scalars((
        ("max_crank_speed", s.max_speed, "angular_velocity", "max crank speed omega1"),
        ("min_crank_speed", s.min_speed, "angular_velocity", "min crank speed omega1"),
        ("max_crank_acceleration", s.max_acceleration, "angular_acceleration", "max crank acceleration epsilon1"),
        ("min_crank_acceleration", s.min_acceleration, "angular_acceleration", "min crank acceleration epsilon1"),
        ("max_motor_torque", s.max_motor_torque, "torque", "max motor torque"),
        ("min_motor_torque", s.min_motor_torque, "torque", "min motor torque (negative: generating)"),
        ("max_motor_power", s.max_power, "power", "max motor power"),
        ("min_motor_power", s.min_power, "power", "min motor power (negative: generating)"),
        ("max_static_torque", s.peak_static_torque, "torque", "max crank torque of load and weights without inertia"),
    ))
    c = s.convergence
    summary += [
        Scalar("speed_fluctuation", "percent", s.speed_fluctuation, "coefficient of speed fluctuation (max - min) / mean"),
        Scalar("period", "time", s.period, "time of one stroke cycle"),
        Scalar("strokes_per_minute", "stroke_rate", s.mean_speed, "pumping speed"),
        Scalar("energy_per_cycle", "energy", s.energy_per_cycle, "energy the motor delivers per cycle"),
        Scalar("rod_work_per_cycle", "energy", s.rod_work_per_cycle, "work of the polished-rod load per cycle"),
        Scalar("mean_motor_power", "power", s.mean_power, "mean motor power"),
        Scalar("constant_inertia", "moment_of_inertia", s.constant_inertia,
               "constant part of the reduced inertia: drive, crank arms, counterweights"),
        Scalar("starting_torque", "torque", s.starting_torque, "motor starting torque reduced to the crank"),
        Scalar("breakdown_torque_margin", "ratio", s.breakdown_torque_margin, "motor pull-out torque / max motor torque"),
        Scalar("shooting_iterations", "count", c.iterations, "integrations of the cycle to find the periodic start speed"),
        Scalar("periodicity_error", "ratio", c.periodicity_error, "|omega1 end - start| / start of the accepted cycle"),
        Scalar("rtol", "ratio", c.rtol, "relative tolerance of the integration (DOP853)"),
    ]
    if isinstance(machine_.rod_load, WellLoad):
        summary += [Scalar(name, "force", getattr(machine_.rod_load, field), what) for name, field, what in _WELL_FORCES]
    columns = (
        *crank_columns(result.crank_angle, result.time, result.omega, result.epsilon),
        Column("motor_speed", "angular_velocity", "motor shaft speed", result.motor_speed),
        Column("motor_torque", "torque", "motor shaft torque (linear characteristic)", result.motor_torque),
        Column("motor_power", "power", "motor shaft power", result.power),
        Column("velocity", "velocity", "polished-rod velocity, non-uniform rotation, up positive", result.rod.velocity),
        Column("velocity_uniform", "velocity", "polished-rod velocity, uniform rotation at the rated crank speed",
               result.rod_uniform.velocity),
        Column("acceleration", "acceleration", "polished-rod acceleration, non-uniform rotation",
               result.rod.acceleration),
        Column("acceleration_uniform", "acceleration", "polished-rod acceleration, uniform rotation",
               result.rod_uniform.acceleration),
        Column("inertia_torque", "torque", "I_red epsilon1 + 1/2 I_red' omega1^2: torque accelerating the masses",
               result.inertia_torque),
        Column("constant_inertia_torque", "torque", "I_const epsilon1 ([SK8Rotation2013] M_i1)",
               result.constant_inertia_torque),
        Column("rod_load", "force", "polished-rod load", result.rod_load),
        Column("load_torque", "torque", "polished-rod load x torque factor", result.load_torque),
        Column("gravity_torque", "torque", "torque of the links' weights and counterweights", result.gravity_torque),
        Column("reduced_inertia", "moment_of_inertia", "reduced moment of inertia I_red", result.reduced_inertia),
        Column("reduced_inertia_rate", "moment_of_inertia", "d I_red / d crank angle (per rad)",
               result.reduced_inertia_rate),
    )
    panels = (
        Panel("crank speed omega1", ("crank_speed",)),
        Panel("polished-rod velocity", ("velocity",), ("velocity_uniform",)),
        Panel("polished-rod acceleration", ("acceleration",), ("acceleration_uniform",)),
        Panel("motor torque", ("motor_torque",)),
    )
    source = "well model" if card is None else f"card {card.name}"
    return Result(f"{unit.name}: dynamics, {source}", tuple(summary), columns, panels)
