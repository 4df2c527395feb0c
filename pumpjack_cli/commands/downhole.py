"""`pumpjack downhole`: the pump card from a surface dynamometer card through the rod string."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import typer

from ..analysis.deviated import profile_shown
from ..analysis.downhole import DEFAULT_SAMPLES, Production
from ..analysis.downhole import downhole as run
from ..config import load_unit
from ..options import (CardColumnsOption, CardOption, CardSpmOption, CardUnitsOption, FormatOption, Output, OutputOption,
                       PlotOption, CrankMotion, CrankMotionOption, ServiceFactorOption, UnitArgument, UnitsOption, UnitSystem,
                       card_source, finite)
from ..options import What, WhatOption
from ..options import CatalogueOption
from ..errors import PumpjackError
from ..quantities import KWH
from ..options import CardFormatOption, CardPointsOption, StrokeOption, production_share
from ..options import ElectricityPriceOption, RuntimeOption
from ..options import FrictionCoefficientOption, GuideLimitOption, ProfileOption, SurveyOption, deviation

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
    method: Annotated[Method | None, typer.Option(
        help="gibbs: exact per-harmonic solution; everitt-jennings: finite-difference march in depth, which carries "
             "the friction of a deviated well [default: gibbs, everitt-jennings with a survey]")] = None,
    damping: Annotated[float | None, typer.Option(
        help="Gibbs' dimensionless damping factor nu of the rods, 0 for none [default: the unit file's, else from "
             "the energy balance with the well's fluid load]", min=0.0, max=2.0, callback=finite)] = None,
    samples: Annotated[int, typer.Option(help="time samples of the card per period", min=16, max=20_000)] = DEFAULT_SAMPLES,
    service_factor: ServiceFactorOption = 1.0,
    survey: SurveyOption = None,
    friction_coefficient: FrictionCoefficientOption = None,
    guide_limit: GuideLimitOption = None,
    profile: ProfileOption = False,
    runtime: RuntimeOption = None,
    pump_efficiency: Annotated[str | None, typer.Option(
        help="stated volumetric efficiency of the pump, '85 %', instead of the slippage from the plunger's clearance "
             "[default: the slippage, if the well gives plunger_clearance, plunger_length and viscosity]")] = None,
    system_efficiency: Annotated[float, typer.Option(
        help="efficiency from the electricity supply to the polished rod (motor, belts, gearbox, unit), for the "
             "energy per day [default: 1, the polished rod's own energy]", min=0.05, max=1.0, callback=finite)] = 1.0,
    electricity_price: ElectricityPriceOption = None,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Pump card from a surface dynamometer card through the rod string's wave equation.

    Pump strokes, fillage, fluid load and displacement; the pump's condition (full, fluid pound,
    gas, leaking valves, tagging, unanchored tubing, parted rods) with its evidence; intake
    pressure, fluid level, inferred production and energy per day; rod stresses and Goodman
    loading."""
    sink = Output(fmt, units, out, plot, what)
    source = card_source(card, card_units, card_columns, card_format, card_points, stroke)
    production = Production(production_share(runtime, "runtime", "--runtime"),
                            production_share(pump_efficiency, "fraction", "--pump-efficiency"), system_efficiency,
                            None if electricity_price is None else electricity_price / KWH)
    for option, given in (("--electricity-price", production.electricity_price),
                          ("--pump-efficiency", production.pump_efficiency)):
        if given is not None and production.runtime is None:
            raise PumpjackError(f"{option}: a rate per day needs --runtime (how long the unit runs a day)")
    options = deviation(survey, friction_coefficient, guide_limit, profile)
    result = run(load_unit(unit, catalogue), source, spm, crank_motion.value, None if method is None else method.value,
                 damping, samples, service_factor, options, production)
    sink.emit(result, profile_shown(result.columns) if profile else SHOWN)
