"""`pumpjack downhole`: the pump card from a surface dynamometer card through the rod string."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import typer

from ..analysis.downhole import DEFAULT_SAMPLES
from ..analysis.downhole import downhole as run
from ..config import load_unit
from ..options import (CardColumnsOption, CardOption, CardSpmOption, CardUnitsOption, FormatOption, Output, OutputOption,
                       PlotOption, CrankMotion, CrankMotionOption, ServiceFactorOption, UnitArgument, UnitsOption, UnitSystem,
                       card_source, finite)
from ..options import What, WhatOption
from ..options import CatalogueOption
from ..options import CardFormatOption, CardPointsOption, StrokeOption

SHOWN = ("time", "position", "rod_load", "pump_position", "pump_load")


class Method(str, Enum):
    gibbs = "gibbs"
    everitt_jennings = "everitt-jennings"


def downhole(
    unit: UnitArgument,
    card: CardOption,
    card_units: CardUnitsOption = None,
    card_columns: CardColumnsOption = None,
    card_format: CardFormatOption = None,
    card_points: CardPointsOption = None,
    stroke: StrokeOption = None,
    spm: CardSpmOption = None,
    crank_motion: CrankMotionOption = CrankMotion.auto,
    method: Annotated[Method, typer.Option(
        help="gibbs: exact per-harmonic solution; everitt-jennings: finite-difference march in depth")] = Method.gibbs,
    damping: Annotated[float | None, typer.Option(
        help="Gibbs' dimensionless damping factor nu of the rods, 0 for none [default: the unit file's, else from "
             "the energy balance with the well's fluid load]", min=0.0, max=2.0, callback=finite)] = None,
    samples: Annotated[int, typer.Option(help="time samples of the card per period", min=16, max=20_000)] = DEFAULT_SAMPLES,
    service_factor: ServiceFactorOption = 1.0,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Pump card from a surface dynamometer card through the rod string's wave equation.

    Pump strokes, fillage, fluid load and displacement; rod stresses and Goodman loading."""
    sink = Output(fmt, units, out, plot, what)
    source = card_source(card, card_units, card_columns, card_format, card_points, stroke)
    result = run(load_unit(unit, catalogue), source, spm, crank_motion.value, method.value,
                 damping, samples, service_factor)
    sink.emit(result, SHOWN)
