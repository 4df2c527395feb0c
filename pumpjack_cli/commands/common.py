"""Options shared by every result-printing command, defined once."""

from __future__ import annotations

import sys
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from ..card_files import read_card
from ..core.beam.card import Card
from ..core.beam.geometry import Linkage
from ..render import Report, emit


class Format(str, Enum):
    table = "table"
    csv = "csv"
    json = "json"


class UnitSystem(str, Enum):
    si = "si"
    field = "field"


FormatOption = Annotated[
    Format | None,
    typer.Option("--format", "-f", help="table, csv or json [default: table on a terminal, csv in a pipe]"),
]
OutputOption = Annotated[
    Path | None,
    typer.Option("--output", "-o", help="write to this file (atomically) instead of stdout", dir_okay=False),
]
PlotOption = Annotated[
    Path | None,
    typer.Option("--plot", help="also draw the curves to FILE.png, .svg or .pdf", dir_okay=False),
]
UnitsOption = Annotated[
    UnitSystem,
    typer.Option("--units", help="si (m, m/s, N, N·m) or field (in, ft/s, lbf, lbf·in)"),
]
UnitArgument = Annotated[str, typer.Argument(help="bundled unit name (see `pumpjack units`) or path to a unit file")]
CardUnitsOption = Annotated[
    UnitSystem, typer.Option("--card-units", help="units of card columns whose header names none: si (m, N) or field (in, lbf)")
]


def load_card(card: Path, linkage: Linkage, card_units: UnitSystem) -> Card:
    """A dynamometer card on the unit's crank-angle axis; the reader's warnings go to stderr."""
    reading = read_card(card, linkage, card_units.value)
    for warning in reading.warnings:
        sys.stderr.write(f"pumpjack: warning: {warning}\n")
    return reading.card


def output(report: Report, fmt: Format | None, units: UnitSystem, out: Path | None, plot: Path | None) -> None:
    """Hand a report to the renderer with the shared options."""
    emit(report, fmt.value if fmt else None, units.value, out, plot)
