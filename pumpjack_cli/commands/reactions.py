"""`pumpjack reactions`: joint reactions and balancing torque from a dynamometer card."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from ..config import UnitConfig, load_unit
from ..core.beam.card import card_load
from ..core.sampling import crank_grid
from ..core.beam.kinetostatics import Reactions, rational_mechanism
from ..errors import PumpjackError
from ..render import Column, Panel, Report, Scalar
from ..units import parse_quantity
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
from .kinematics import crank_speed

#: Reaction vectors of the output: field name, description.
REACTIONS = {
    "r12": "crank on pitman 2 at crank pin A",
    "r13": "crank on pitman 3 at crank pin A1",
    "r24": "pitman 2 on equalizer at B",
    "r34": "pitman 3 on equalizer at B1",
    "r45": "equalizer on beam at D",
    "r05": "frame on beam at centre bearing C",
    "r01": "frame on crank at the shaft bearings O, O1",
}
MOMENTS = {"m05": "bearing moment of the frame on the beam at C", "m01": "bearing moment of the frame on the crank"}

CardOption = Annotated[Path, typer.Option("--card", help="dynamometer card CSV (see docs/cards.md)", dir_okay=False)]


def reactions_report(run: CardRun, r: Reactions, title: str) -> Report:
    """Tabulate reactions: every component per crank angle, peaks and torque extremes."""
    theta, load = run.crank_angle, run.load
    columns = [
        Column("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation"),
        Column("time", "time", "time from crank angle 0", brief=False),
        Column("crank_speed", "angular_velocity", "crank angular velocity omega1", brief=False),
        Column("crank_acceleration", "angular_acceleration", "crank angular acceleration epsilon1", brief=False),
        Column("rod_load", "force", "polished-rod load from the card"),
    ]
    series = {"crank_angle": theta, "time": run.time, "crank_speed": run.omega, "crank_acceleration": run.epsilon,
              "rod_load": load}
    summary = [Scalar("mean_crank_speed", "angular_velocity", 2 * np.pi / run.period, "2 pi / cycle time"),
               Scalar("max_rod_load", "force", float(load.max()), "peak polished-rod load"),
               Scalar("min_rod_load", "force", float(load.min()), "minimum polished-rod load")]
    vectors = {name: getattr(r, name) for name in REACTIONS} | {name: getattr(r, name) for name in MOMENTS}
    for name, vector in vectors.items():
        is_moment = name in MOMENTS
        what = MOMENTS[name] if is_moment else REACTIONS[name]
        axes = "xy" if is_moment else "xyz"
        for i, axis in enumerate(axes):
            brief = name in ("r12", "r45", "r05") and axis == "y"
            columns.append(Column(f"{name}_{axis}", "torque" if is_moment else "force", f"{what}, {axis}", brief))
            series[f"{name}_{axis}"] = vector[:, i]
        magnitude = np.linalg.norm(vector, axis=-1)
        peak = int(np.argmax(magnitude))
        summary += [Scalar(f"peak_{name}", "torque" if is_moment else "force", float(magnitude[peak]), f"peak |{name.upper()}|: {what}"),
                    Scalar(f"peak_{name}_crank_angle", "angle", float(theta[peak]), f"crank angle of peak |{name.upper()}|")]
    torque = r.balancing_torque
    columns.append(Column("balancing_torque", "torque", "M_z: gearbox torque on the crank, + driving"))
    series["balancing_torque"] = torque
    for label, index in (("max", int(np.argmax(torque))), ("min", int(np.argmin(torque)))):
        summary += [Scalar(f"{label}_balancing_torque", "torque", float(torque[index]), f"{label} M_z (net gearbox torque)"),
                    Scalar(f"{label}_balancing_torque_crank_angle", "angle", float(theta[index]), f"crank angle of {label} M_z")]
    summary.append(Scalar("equilibrium_residual", "ratio", float(r.residual.max()),
                          "max |E x - f| of the group 2-3-4-5 / largest load"))
    panels = (
        Panel("rod load", ("rod_load",)),
        Panel("pitman reactions", ("r12_x", "r12_y", "r13_x", "r13_y")),
        Panel("beam reactions", ("r45_y", "r05_x", "r05_y")),
        Panel("balancing torque", ("balancing_torque",)),
    )
    return Report(title=title, summary=tuple(summary), columns=tuple(columns), series=series, panels=panels)


def require_masses(config: UnitConfig) -> None:
    if config.masses is None:
        raise PumpjackError(f"unit {config.name} has no [masses] section; reactions need the link masses")


class Rotation(str, Enum):
    uniform = "uniform"
    dynamic = "dynamic"


RotationOption = Annotated[Rotation, typer.Option(
    "--rotation", help="uniform: constant crank speed (--spm or the motor's rated speed); dynamic: the periodic "
    "motion from the machine's equation of motion under this card (as `pumpjack dynamics --card`)")]


@dataclass(frozen=True)
class CardRun:
    """Crank angles [rad], time [s], crank speed [1/s] and acceleration [1/s²] and the
    card's polished-rod load [N] on them, and the cycle time [s]."""

    crank_angle: np.ndarray
    time: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    load: np.ndarray
    period: float


def card_run(config: UnitConfig, linkage, card: Path, card_units: UnitSystem, spm: float | None, steps: int,
             rotation: Rotation) -> CardRun:
    """The card on a crank-angle grid with uniform or dynamic rotation; card warnings go to stderr."""
    measured = load_card(card, linkage, card_units)
    theta = crank_grid(steps)
    load = card_load(measured, theta)
    if rotation is Rotation.uniform:
        omega = crank_speed(config, spm)
        return CardRun(theta, theta / omega, np.full(steps, omega), np.zeros(steps), load, 2 * np.pi / omega)
    if spm is not None:
        raise PumpjackError("--spm sets a uniform crank speed; with --rotation dynamic the motor sets the speed")
    from ..core.dynamics.periodic import steady_state
    from .dynamics import build_machine

    state = steady_state(build_machine(config, measured), theta)
    return CardRun(theta, state.time, state.omega, state.epsilon, load, state.summary.period)


SpmOption = Annotated[
    float | None, typer.Option(help="pumping speed, strokes/min [default: from motor and drive]", min=0.1, max=60)
]
StepsOption = Annotated[int, typer.Option(help="crank positions per revolution", min=4, max=1_000_000)]


def reactions(
    unit: UnitArgument,
    card: CardOption,
    card_units: CardUnitsOption = UnitSystem.si,
    spm: SpmOption = None,
    steps: StepsOption = 360,
    rotation: RotationOption = Rotation.uniform,
    no_inertia: Annotated[bool, typer.Option("--no-inertia", help="leave out the links' inertia forces and moments")] = False,
    no_weights: Annotated[bool, typer.Option("--no-weights", help="leave out the links' weights")] = False,
    counterweight_count: Annotated[int | None, typer.Option(help="number of counterweight blocks instead of the unit's", min=0, max=16)] = None,
    counterweight_radius: Annotated[str | None, typer.Option(help="counterweight radius instead of the unit's, e.g. '0.9 m'")] = None,
    fmt: FormatOption = None,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Joint reactions and balancing torque of the rational mechanism from a dynamometer card.

    The spatial mechanism without redundant constraints (spherical pins), with weights
    and d'Alembert inertia."""
    config = load_unit(unit)
    require_masses(config)
    spatial = config.geometry.spatial(config.name)
    counterweights = config.masses.counterweights
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
    masses = config.masses.model_copy(update={"counterweights": counterweights}).model()
    run = card_run(config, spatial.planar, card, card_units, spm, steps, rotation)
    _, r = rational_mechanism(spatial, masses, run.crank_angle, run.omega, run.epsilon, run.load,
                              weights=not no_weights, inertia=not no_inertia)
    title = f"{config.name}: reactions and balancing torque, card {card.name}, {rotation.value} rotation"
    output(reactions_report(run, r, title), fmt, units, out, plot)
