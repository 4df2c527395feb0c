"""`pumpjack kinematics`: exact polished-rod and link kinematics for uniform crank rotation."""

from __future__ import annotations

from typing import Annotated

import typer

from ..analysis.kinematics import kinematics as run
from ..config import load_unit
from ..options import SpmOption, FormatOption, OutputOption, PlotOption, UnitArgument, UnitsOption, UnitSystem, Output
from ..options import What, WhatOption
from ..options import CatalogueOption

SHOWN = ("crank_angle", "time", "position", "velocity", "acceleration", "torque_factor")


def kinematics(
    unit: UnitArgument,
    spm: SpmOption = None,
    steps: Annotated[int, typer.Option(help="crank positions per revolution", min=4, max=10_000_000)] = 360,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Exact kinematics of the polished rod, beam and pitman for uniform crank rotation.

    The elementary and refined textbook approximations are printed beside it."""
    sink = Output(fmt, units, out, plot, what)
    sink.emit(run(load_unit(unit, catalogue), spm, steps), SHOWN)
