"""`pumpjack inertia-error`: accuracy of the approximate inertia-force laws."""

from __future__ import annotations

from typing import Annotated

import typer

from ..analysis.inertia import inertia_error as run
from ..config import load_any_unit
from ..options import finite, FormatOption, OutputOption, PlotOption, UnitArgument, UnitsOption, UnitSystem, Output, quantity
from ..options import What, WhatOption
from ..options import CatalogueOption

SHOWN_LAWS = ("crank_angle", "time", "position", "velocity", "acceleration", "inertia_force")
SHOWN_SUPPORT = ("crank_angle", "travel", "outer_edge_reaction", "inner_edge_reaction", "guide_friction",
                 "support_reaction", "total_friction")


def inertia_error(
    unit: UnitArgument,
    spm: Annotated[float | None, typer.Option(
        "--spm", "--rpm", min=0.1, max=1000, callback=finite,
        help="crank speed, revolutions (double strokes) per minute [default: slider-crank: from its file; "
             "beam unit: from motor and drive]",
    )] = None,
    mass: Annotated[str | None, typer.Option(
        help="reciprocating (suspended) mass with its unit, e.g. '3000 kg' or '6600 lb', for the inertia forces "
             "[default: slider-crank: from its file; beam unit: none, accelerations only]",
    )] = None,
    support_friction: Annotated[bool, typer.Option(
        "--support-friction",
        help="slider-crank only: friction in the crosshead guide from the redundant supports of the stepped slider",
    )] = False,
    steps: Annotated[int, typer.Option(help="crank positions per revolution", min=4, max=10_000_000)] = 360,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Error of the approximate inertia-force laws against the exact motion.

    Errors at the peak and over the cycle, for slider-crank and beam pumping units."""
    sink = Output(fmt, units, out, plot, what)
    result = run(load_any_unit(unit, catalogue), spm, quantity(mass, "mass", "--mass"), support_friction, steps)
    names = {c.name for c in result.columns}
    sink.emit(result, tuple(name for name in (SHOWN_SUPPORT if support_friction else SHOWN_LAWS) if name in names))
