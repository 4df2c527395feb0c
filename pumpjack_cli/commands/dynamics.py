"""`pumpjack dynamics`: non-uniform crank rotation from the machine's equation of motion."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from ..analysis.dynamics import dynamics as run
from ..config import load_unit
from ..core.dynamics.periodic import DEFAULT_RTOL
from ..errors import PumpjackError
from ..options import (CardColumnsOption, CardUnitsOption, FormatOption, Output, OutputOption, PlotOption, UnitArgument,
                       UnitsOption, UnitSystem, card_source, finite, positive)
from ..options import What, WhatOption
from ..options import CatalogueOption
from ..options import CardFormatOption, CardPointsOption, StrokeOption

SHOWN = ("crank_angle", "time", "crank_speed", "crank_acceleration", "motor_torque", "velocity", "velocity_uniform",
         "inertia_torque")
#: The elastic-rod model needs this many time samples per revolution at least.
WAVE_SAMPLES = 64
#: Crank positions (rigid-rod model) or time samples (wave model) per revolution by default.
DEFAULT_POINTS = 360


class WellModel(str, Enum):
    rigid = "rigid"
    wave = "wave"


def dynamics(
    unit: UnitArgument,
    card: Annotated[Path | None, typer.Option(
        "--card", help="drive the unit with a dynamometer card CSV instead of the well model (docs/cards.md)",
        dir_okay=False)] = None,
    card_units: CardUnitsOption = None,
    card_columns: CardColumnsOption = None,
    card_format: CardFormatOption = None,
    card_points: CardPointsOption = None,
    stroke: StrokeOption = None,
    rtol: Annotated[float, typer.Option(help="relative tolerance of the integration and of the periodicity",
                                        min=1e-13, max=1e-3, callback=finite)] = DEFAULT_RTOL,
    steps: Annotated[int | None, typer.Option(
        help="crank positions per revolution in the output of the rigid-rod model [default: 360]", min=4,
        max=1_000_000)] = None,
    well_model: Annotated[WellModel, typer.Option(
        help="rigid: the rigid-rod well model of [SK8Rotation2013]; wave: the elastic rods of the unit's [well] "
             "(damped wave equation, pump valves) solved together with the machine, on --samples time samples")
    ] = WellModel.rigid,
    samples: Annotated[int | None, typer.Option(
        help=f"with --well-model wave: time samples per revolution, {WAVE_SAMPLES} to 20000 [default: 360]",
        min=WAVE_SAMPLES, max=20_000)] = None,
    damping: Annotated[float | None, typer.Option(
        help="with --well-model wave: Gibbs' damping factor nu of the rods, above 0 [default: the unit file's, "
             "else 0.05]", max=2.0, callback=positive)] = None,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Non-uniform crank rotation from the machine's equation of motion.

    The periodic motion under the motor's characteristic, the well (or a dynamometer
    card) and the weights."""
    sink = Output(fmt, units, out, plot, what)
    if well_model is WellModel.rigid:
        for given, option in ((damping, "--damping"), (samples, "--samples")):
            if given is not None:
                raise PumpjackError(f"{option} applies to --well-model wave")
        source = None if card is None else card_source(card, card_units, card_columns, card_format, card_points, stroke)
        sink.emit(run(load_unit(unit, catalogue), source, rtol, DEFAULT_POINTS if steps is None else steps), SHOWN)
        return
    if card is not None:
        raise PumpjackError("--card drives the unit with a measured load; --well-model wave predicts it: give one")
    if steps is not None:
        raise PumpjackError("--steps counts the rigid-rod model's crank positions; the wave model takes --samples "
                            "(time samples per revolution)")
    from ..analysis.predict import wave_dynamics

    sink.emit(wave_dynamics(load_unit(unit, catalogue), DEFAULT_POINTS if samples is None else samples, damping), ("crank_angle", "time", "crank_speed",
                                                              "crank_acceleration", "motor_torque", "rod_load",
                                                              "inertia_torque"))
