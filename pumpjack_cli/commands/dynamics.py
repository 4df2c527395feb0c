"""`pumpjack dynamics`: non-uniform crank rotation from the machine's equation of motion."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..analysis.dynamics import dynamics as run
from ..config import load_unit
from ..core.dynamics.periodic import DEFAULT_RTOL
from ..analysis.card_runs import CardSource
from ..options import CardColumnsOption, finite, CardUnitsOption, FormatOption, OutputOption, PlotOption, UnitArgument, UnitsOption, UnitSystem, Output

SHOWN = ("crank_angle", "time", "crank_speed", "crank_acceleration", "motor_torque", "velocity", "velocity_uniform",
         "inertia_torque")


def dynamics(
    unit: UnitArgument,
    card: Annotated[Path | None, typer.Option(
        "--card", help="drive the unit with a dynamometer card CSV instead of the well model (docs/cards.md)",
        dir_okay=False)] = None,
    card_units: CardUnitsOption = UnitSystem.si,
    card_columns: CardColumnsOption = None,
    rtol: Annotated[float, typer.Option(help="relative tolerance of the integration and of the periodicity",
                                        min=1e-13, max=1e-3, callback=finite)] = DEFAULT_RTOL,
    steps: Annotated[int, typer.Option(help="crank positions per revolution in the output", min=4, max=1_000_000)] = 360,
    fmt: FormatOption = None,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Non-uniform crank rotation from the machine's equation of motion.

    The periodic motion under the motor's characteristic, the well (or a dynamometer
    card) and the weights."""
    sink = Output(fmt, units, out, plot)
    source = None if card is None else CardSource(card, card_units.value, card_columns)
    sink.emit(run(load_unit(unit), source, rtol, steps), SHOWN)
