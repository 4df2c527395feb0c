"""`pumpjack reactions`: joint reactions and balancing torque from a dynamometer card."""

from __future__ import annotations

from typing import Annotated

import typer

from ..analysis.reactions import reactions as run
from ..config import load_unit
from ..options import (CardColumnsOption, CardOption, CardUnitsOption, FormatOption, OutputOption, PlotOption, CrankMotion, CrankMotionOption,
                     CardSpmOption, StepsOption, UnitArgument, UnitsOption, UnitSystem, Output, card_source, quantity)
from ..options import What, WhatOption
from ..options import CatalogueOption
from ..options import CardFormatOption, CardPointsOption, StrokeOption

SHOWN = ("crank_angle", "rod_load", "r12_y", "r45_y", "r05_y", "net_torque")


def reactions(
    unit: UnitArgument,
    card: CardOption,
    card_units: CardUnitsOption = None,
    card_columns: CardColumnsOption = None,
    card_format: CardFormatOption = None,
    card_points: CardPointsOption = None,
    stroke: StrokeOption = None,
    spm: CardSpmOption = None,
    steps: StepsOption = 360,
    crank_motion: CrankMotionOption = CrankMotion.uniform,
    no_inertia: Annotated[bool, typer.Option("--no-inertia", help="leave out the links' inertia forces and moments")] = False,
    no_weights: Annotated[bool, typer.Option("--no-weights", help="leave out the links' weights")] = False,
    counterweight_count: Annotated[int | None, typer.Option(help="number of counterweight blocks instead of the unit's", min=0, max=16)] = None,
    counterweight_radius: Annotated[str | None, typer.Option(help="counterweight radius instead of the unit's, e.g. '0.9 m'")] = None,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Joint reactions and balancing torque of the rational mechanism from a dynamometer card.

    The spatial mechanism without redundant constraints (spherical pins), with weights
    and d'Alembert inertia."""
    sink = Output(fmt, units, out, plot, what)
    radius = quantity(counterweight_radius, "length", "--counterweight-radius")
    source = card_source(card, card_units, card_columns, card_format, card_points, stroke)
    result = run(load_unit(unit, catalogue), source, spm, steps, crank_motion.value, weights=not no_weights,
                 inertia=not no_inertia, counterweight_count=counterweight_count, counterweight_radius=radius)
    sink.emit(result, SHOWN)
