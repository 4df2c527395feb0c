"""`pumpjack report`: one well on one page, a self-contained HTML file."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import typer

from ..analysis.report import ReportOptions, report as run
from ..analysis.torque import Energy
from ..config import load_unit
from ..options import ElectricityPriceOption, RuntimeOption, production_share
from ..options import (CatalogueOption, CardColumnsOption, CardFormatOption, CardOption, CardPointsOption, CardSpmOption, CardUnitsOption,
                       CrankMotion, CrankMotionOption, OutputOption, ServiceFactorOption, StepsOption, StrokeOption,
                       UnitArgument, UnitsOption, UnitSystem, card_source, finite)
from ..quantities import KWH
from ..errors import ConfigError
from ..readers.unit_files import unit_source
from ..render import PageOutput
from ..analysis.downhole import downhole_methods
from ..analysis.torque import balance_criteria, torque_methods

#: The choices of `torque` and `downhole`, from the analyses' registries (commands never import each other).
Method = Enum("Method", {name: name for name in torque_methods()}, module=__name__, type=str)
Balance = Enum("Balance", {name: name for name in balance_criteria()}, module=__name__, type=str)
DownholeMethod = Enum("DownholeMethod", {name: name for name in downhole_methods()}, module=__name__, type=str)


def report(
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
    method: Annotated[Method, typer.Option(help="torque method, as `pumpjack torque --method`")] = Method["api"],
    balance: Annotated[Balance, typer.Option(help="balance criterion, as `pumpjack torque --balance`")] = Balance["equal-peaks"],
    downhole_method: Annotated[DownholeMethod | None, typer.Option(
        help="pump-card method, as `pumpjack downhole --method` [default: gibbs, everitt-jennings with the drag in a "
             "deviated well]")] = None,
    damping: Annotated[float | None, typer.Option(
        help="Gibbs' damping factor nu, as `pumpjack downhole --damping`", min=0.0, max=2.0, callback=finite)] = None,
    samples: Annotated[int | None, typer.Option(
        help="time samples of the card per period, as `pumpjack downhole --samples`", min=16, max=20_000)] = None,
    service_factor: ServiceFactorOption = 1.0,
    drive_efficiency: Annotated[float, typer.Option(
        help="efficiency of belt and gearbox, as `pumpjack torque`", min=0.1, max=1.0, callback=finite)] = 1.0,
    motor_efficiency: Annotated[float, typer.Option(
        help="efficiency of the motor, as `pumpjack torque`", min=0.1, max=1.0, callback=finite)] = 1.0,
    electricity_price: ElectricityPriceOption = None,
    runtime: RuntimeOption = None,
    catalogue: CatalogueOption = None,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
) -> None:
    """One well on one page: unit, cards, torque and ratings, balance, rod loading, pump, provenance.

    A self-contained HTML file (plots inline as SVG, nothing fetched from the network) whose
    numbers are those of `pumpjack torque` and `pumpjack downhole` with the same options."""
    sink = PageOutput(units.value, out)
    source = card_source(card, card_units, card_columns, card_format, card_points, stroke)
    energy = Energy(drive_efficiency, motor_efficiency, None if electricity_price is None else electricity_price / KWH)
    options = ReportOptions(spm, crank_motion.value, method.value, balance.value, damping,
                            None if downhole_method is None else downhole_method.value, steps, samples, service_factor,
                            energy, units.value, production_share(runtime, "runtime", "--runtime"))
    try:   # the file the provenance hashes: the unit file, or the catalogue that holds the unit
        unit_file = unit_source(unit)
    except ConfigError:
        if catalogue is None:
            raise
        unit_file = catalogue
    page, _ = run(load_unit(unit, catalogue), unit_file, source, options)
    sink.emit(page)
