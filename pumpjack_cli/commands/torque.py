"""`pumpjack torque`: gearbox torque, counterbalance and loading from a dynamometer card."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import typer

from ..analysis.torque import Energy, torque as run
from ..config import load_unit
from ..options import ElectricityPriceOption
from ..options import (CardColumnsOption, CardOption, CardSpmOption, CardUnitsOption, FormatOption, Output, OutputOption,
                       PlotOption, CrankMotion, CrankMotionOption, StepsOption, UnitArgument, UnitsOption, UnitSystem,
                       card_source, finite)
from ..options import What, WhatOption
from ..quantities import KWH
from ..options import CatalogueOption
from ..options import CardFormatOption, CardPointsOption, StrokeOption

SHOWN = ("crank_angle", "rod_load", "torque_factor", "net_torque", "recommended_net_torque", "exact_net_torque",
         "permissible_load_max")


class Method(str, Enum):
    api = "api"
    exact = "exact"


class Balance(str, Enum):
    equal_peaks = "equal-peaks"
    min_rms = "min-rms"
    min_peak = "min-peak"


def torque(
    unit: UnitArgument,
    card: CardOption,
    card_units: CardUnitsOption = None,
    card_columns: CardColumnsOption = None,
    card_format: CardFormatOption = None,
    card_points: CardPointsOption = None,
    stroke: StrokeOption = None,
    spm: CardSpmOption = None,
    steps: StepsOption = 360,
    crank_motion: CrankMotionOption = CrankMotion.auto,
    method: Annotated[Method, typer.Option(
        help="api: torque factors, B and M (API 11E); exact: spatial kinetostatics with link weights and inertia "
             "(needs [masses])")] = Method.api,
    balance: Annotated[Balance, typer.Option(
        help="criterion for the recommended counterbalance: equal-peaks (equal upstroke and downstroke peak "
             "torques), min-rms (smallest RMS torque), min-peak (smallest peak torque)")] = Balance.equal_peaks,
    drive_efficiency: Annotated[float, typer.Option(
        help="efficiency of belt and gearbox between motor and crank, for the motor power", min=0.1, max=1.0,
        callback=finite)] = 1.0,
    motor_efficiency: Annotated[float, typer.Option(
        help="efficiency of the motor, for the energy it takes a day [default: 1, the energy at its shaft]", min=0.1,
        max=1.0, callback=finite)] = 1.0,
    electricity_price: ElectricityPriceOption = None,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Gearbox torque, counterbalance and loading of a unit from a dynamometer card.

    API 11E torque factors or the exact spatial model, the counterbalance that meets a
    balance criterion, loading against the unit's ratings, the permissible load diagram."""
    sink = Output(fmt, units, out, plot, what)
    source = card_source(card, card_units, card_columns, card_format, card_points, stroke)
    energy = Energy(drive_efficiency, motor_efficiency, None if electricity_price is None else electricity_price / KWH)
    result = run(load_unit(unit, catalogue), source, spm, steps, crank_motion.value,
                 method.value, balance.value, drive_efficiency, energy)
    names = {c.name for c in result.columns}
    sink.emit(result, tuple(name for name in SHOWN if name in names))
