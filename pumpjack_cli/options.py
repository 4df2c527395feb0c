"""Options shared by the commands, defined once, and the one hand-over to the renderer.

Imports nothing heavy: `pumpjack units` and every command's ``--help`` use it.
"""

from __future__ import annotations

import math
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from .errors import PumpjackError
from .quantities import SPM_RANGE, parse_quantity
from .render import Outputs
from .render.formats import CONTENTS, CSV, FORMATS, PLOT_SUFFIXES, TABLE
from .results import Result

#: The ``--format`` choices, one member per name of :data:`~pumpjack_cli.render.formats.FORMATS`.
Format = Enum("Format", {name: name for name in FORMATS}, module=__name__, type=str)
#: The ``--what`` choices, one member per name of :data:`~pumpjack_cli.render.formats.CONTENTS`.
What = Enum("What", {name: name for name in CONTENTS}, module=__name__, type=str)


def _either(names: tuple[str, ...]) -> str:
    """Names for a help text: "a, b or c"."""
    return f"{', '.join(names[:-1])} or {names[-1]}"


class UnitSystem(str, Enum):
    si = "si"
    field = "field"


class CrankMotion(str, Enum):
    uniform = "uniform"
    card = "card"
    dynamic = "dynamic"
    auto = "auto"


FormatOption = Annotated[
    Format | None,
    typer.Option("--format", "-f", help=f"{_either(FORMATS)} [default: {TABLE} on a terminal, {CSV} in a pipe]"),
]
OutputOption = Annotated[
    Path | None,
    typer.Option("--output", "-o", help="write to this file (atomically) instead of stdout", dir_okay=False),
]
PlotOption = Annotated[
    Path | None,
    typer.Option("--plot", help=f"also draw the curves to FILE{_either(PLOT_SUFFIXES)}", dir_okay=False),
]
WhatOption = Annotated[What, typer.Option(
    "--what", help="columns: the per-row columns (table and JSON show the summary too); summary: the summary "
    "values only (CSV: one row each, name,value,unit,description)")]
UnitsOption = Annotated[
    UnitSystem,
    typer.Option("--units", help="si (m, m/s, N, N·m) or field (in, ft/s, lbf, lbf·in)"),
]
UnitArgument = Annotated[str, typer.Argument(
    help="bundled unit name (see `pumpjack units`), path to a unit file, or DESIGNATION/HOLE of --catalogue")]
CatalogueOption = Annotated[Path | None, typer.Option(
    "--catalogue", help="your unit catalogue: a CSV of one row per unit and crank hole, whose units are named "
    "DESIGNATION/HOLE (docs/catalogue.md)", dir_okay=False)]
CardOption = Annotated[Path, typer.Option(
    "--card", help="dynamometer card file (delimited text, JSON, binary or hex block, a recording), or - for "
    "standard input (see docs/cards.md)", dir_okay=False)]

CardColumnsOption = Annotated[str | None, typer.Option(
    "--card-columns", help="which card columns to read, for headers the reader does not know: "
    "'position=NAME,load=NAME[,time=NAME]' or 'crank_angle=NAME,load=NAME'")]
CardUnitsOption = Annotated[UnitSystem | None, typer.Option(
    "--card-units", help="units of card columns whose file names none: si (m, N) or field (in, lbf); a binary or "
    "hex block needs them [default: such a column is refused]")]
CardFormatOption = Annotated[str | None, typer.Option(
    "--card-format", help="card file format: json, hex, binary or delimited [default: told from the content, "
    "then the file name's ending]")]
CardPointsOption = Annotated[int | None, typer.Option(
    "--card-points", help="points of a binary or hex card block (8 bytes each) [default: 200]", min=8,
    max=100_000)]
StrokeOption = Annotated[str | None, typer.Option(
    "--stroke", help="the card of a file of several strokes (a recording, a hex file of several lines): a number "
    "from 1, last or median (the median card of all strokes) [default: last, the card a controller shows]")]


def card_source(card: Path, units: UnitSystem | None, columns: str | None, format: str | None = None,
                points: int | None = None, stroke: str | None = None):
    """The card options as the run layer's :class:`~pumpjack_cli.analysis.card_runs.CardSource`,
    the ``--card-columns`` text parsed into its mapping and ``--stroke`` into its choice, the
    format and block size checked (bad options: one-line CardError)."""
    from .analysis.card_runs import CardSource, parse_stroke  # numpy: only when a command runs
    from .readers.cards import parse_card_columns

    mapping = None if columns is None else parse_card_columns(columns)
    return CardSource(card, None if units is None else units.value, mapping, format, points, parse_stroke(stroke))


def finite(value: float | None) -> float | None:
    """Refuse NaN and infinity in a float option (typer's range check lets NaN through)."""
    if value is not None and not math.isfinite(value):
        raise typer.BadParameter(f"{value} is not a finite number")
    return value


def positive(value: float | None) -> float | None:
    """A finite float option above 0 (typer's ranges include their ends)."""
    if finite(value) is not None and value <= 0.0:
        raise typer.BadParameter(f"{value} is not above 0")
    return value


SpmOption = Annotated[float | None, typer.Option(
    help="pumping speed, strokes/min [default: from motor and drive]", min=SPM_RANGE[0], max=SPM_RANGE[1],
    callback=finite)]
CardSpmOption = Annotated[float | None, typer.Option(
    "--spm", help="pumping speed, strokes/min [default: the card's time stamps, else from motor and drive]",
    min=SPM_RANGE[0], max=SPM_RANGE[1], callback=finite)]
StepsOption = Annotated[int, typer.Option(help="crank positions per revolution", min=4, max=1_000_000)]
CrankMotionOption = Annotated[CrankMotion, typer.Option(
    "--crank-motion", help="uniform: constant crank speed (the card's time stamps, --spm or the motor's rated speed); "
    "card: speed and acceleration from the card's time stamps; dynamic: the periodic motion from the machine's "
    "equation of motion under this card (as `pumpjack dynamics --card`); auto: card if the card has time "
    "stamps and no --spm is given, else uniform")]


class Output:
    """The output options of a command, checked before it computes anything."""

    def __init__(self, fmt: Format | None, units: UnitSystem, out: Path | None, plot: Path | None,
                 what: What = What.columns):
        self.targets = Outputs(fmt.value if fmt else None, units.value, out, plot, what.value)

    def emit(self, result: Result, shown: tuple[str, ...]) -> None:
        """Hand a result to the renderer, with the columns ``shown`` in the terminal table."""
        self.targets.emit(result.showing(shown))


def quantity(text: str | None, dimension: str, option: str) -> float | None:
    """An option's value with its unit (``--mass "3000 kg"``) in SI; a bare number is refused."""
    if text is None:
        return None
    try:
        return parse_quantity(text, dimension, require_unit=True)
    except ValueError as exc:
        raise PumpjackError(f"{option}: {exc}") from None


ServiceFactorOption = Annotated[float, typer.Option(
    help="service factor of the modified Goodman diagram (1: non-corrosive)", min=0.1, max=1.0, callback=finite)]



SurveyOption = Annotated[Path | None, typer.Option(
    "--survey", help="deviation survey CSV (measured_depth_m or _ft, inclination_deg, azimuth_deg) of the well: rods "
    "and drag along the hole (docs/deviated.md) [default: the unit's well.survey, else a vertical hole]",
    dir_okay=False)]
FrictionCoefficientOption = Annotated[float | None, typer.Option(
    "--friction-coefficient", help="Coulomb friction coefficient of rods and couplings on the tubing, with a survey "
    "[default: the unit's well.rod_friction_coefficient, else 0.2]", min=0.0, max=1.0, callback=finite)]
GuideLimitOption = Annotated[str | None, typer.Option(
    "--guide-limit", help="side load one coupling or rod guide may carry, with its unit ('150 lbf'): where the rods "
    "need guides and how many per rod [default: the unit's well.rod_guide_side_load_limit, else no advice]")]
ProfileOption = Annotated[bool, typer.Option(
    "--profile", help="output the rods' profile along the hole (measured and vertical depth, inclination, dogleg "
    "severity, side loads, axial load envelope, rod guides) instead of the cards")]


def deviation(survey: Path | None, friction: float | None, guide_limit: str | None, profile: bool):
    """The deviated-well options as the run layer's :class:`~pumpjack_cli.analysis.deviated.Deviation`."""
    from .analysis.deviated import Deviation  # numpy: only when a command runs
    from .config.well import GUIDE_LIMIT_RANGE

    limit = quantity(guide_limit, "force", "--guide-limit")
    if limit is not None and not limit > 0:
        raise PumpjackError(f"--guide-limit {guide_limit}: must be above 0")
    if limit is not None and not GUIDE_LIMIT_RANGE[0] <= limit <= GUIDE_LIMIT_RANGE[1]:
        raise PumpjackError(f"--guide-limit {guide_limit}: must lie between {GUIDE_LIMIT_RANGE[0]:g} and "
                            f"{GUIDE_LIMIT_RANGE[1]:g} N")
    return Deviation(survey, friction, limit, profile)

RuntimeOption = Annotated[str | None, typer.Option(
    "--runtime", help="share of the day the unit runs, '75 %' or '18 h', for the inferred production and the energy "
    "per day [default: no rate is given]")]
ElectricityPriceOption = Annotated[float | None, typer.Option(
    "--electricity-price", help="price of a kWh of electricity, in any currency: the energy cost per day is given in "
    "the same currency", min=0.0, max=1e6, callback=finite)]


def production_share(text: str | None, dimension: str, option: str) -> float | None:
    """A share in (0, 1] given with its unit (``--runtime "18 h"`` or ``"75 %"``, ``--pump-efficiency
    "85 %"``); None when not given; a value outside (0, 100 %] is refused naming the option."""
    share = quantity(text, dimension, option)
    if share is not None and not 0.0 < share <= 1.0:
        raise PumpjackError(f"{option}: {text!r} is outside 0 .. 100 % (24 h a day)")
    return share
