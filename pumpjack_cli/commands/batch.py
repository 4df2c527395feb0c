"""`pumpjack batch`: a field's cards through torque and downhole into a results store; export and trend."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from typer.core import TyperGroup

from ..analysis.batch.executors import default_workers
from ..analysis.batch.per_card import ANALYSES, Options
from ..analysis.batch.run import run_batch
from ..analysis.store_views import export_result, field_page, trend_result
from ..errors import PumpjackError
from ..options import (CardFormatOption, CardPointsOption, CardUnitsOption, CatalogueOption, FormatOption, Output,
                       OutputOption, UnitsOption, UnitSystem, finite)
from ..render import standard_output

VERBS = ("run", "export", "trend", "report")


class BatchGroup(TyperGroup):
    """`pumpjack batch MANIFEST ...` is `pumpjack batch run MANIFEST ...`; `pumpjack batch` alone shows the help."""

    def parse_args(self, ctx, args):
        if not args:
            args = ["--help"]
        elif args[0] not in VERBS and not args[0].startswith("-"):
            args = ["run", *args]
        return super().parse_args(ctx, args)


app = typer.Typer(cls=BatchGroup, add_completion=False, pretty_exceptions_enable=False, rich_markup_mode=None,
                  context_settings={"help_option_names": ["-h", "--help"]},
                  help="A field's dynamometer cards through torque and downhole into an SQLite results store.")

StoreOption = Annotated[Path, typer.Option("--store", help="SQLite results store", dir_okay=False)]


@app.command("run")
def run(
    manifest: Annotated[Path, typer.Argument(help="CSV or TOML manifest: well, unit, card (path or glob) per row; "
                                             "optional spm, counterbalance_moment, rod_string, timestamp",
                                             dir_okay=False)],
    store: Annotated[Path, typer.Option("--store", help="SQLite results store (created if missing; cards already "
                                                        "in it with the same analysis and options are skipped)",
                                        dir_okay=False)] = Path("results.sqlite"),
    analyses: Annotated[str, typer.Option(help="comma-separated analyses: torque, downhole")] = ",".join(ANALYSES),
    method: Annotated[str, typer.Option(help="torque: api or exact (needs [masses])")] = "api",
    balance: Annotated[str, typer.Option(help="torque: equal-peaks, min-rms or min-peak")] = "equal-peaks",
    damping: Annotated[float | None, typer.Option(
        help="downhole: Gibbs' damping factor nu [default: the unit file's, else the energy balance]",
        min=0.0, max=2.0, callback=finite)] = None,
    card_units: CardUnitsOption = None,
    card_format: CardFormatOption = None,
    card_points: CardPointsOption = None,
    catalogue: CatalogueOption = None,
    workers: Annotated[int | None, typer.Option(help="local worker processes [default: every core]", min=1,
                                                max=1024)] = None,
    scheduler: Annotated[str | None, typer.Option(
        help="address of a Dask scheduler (tcp://host:8786) to run the cards on its cluster")] = None,
) -> None:
    """Analyse every card of a manifest into the results store, skipping cards already done."""
    chosen = tuple(name.strip() for name in analyses.split(",") if name.strip())
    if not chosen:
        raise PumpjackError("--analyses: name at least one of torque, downhole")
    options = Options(chosen, method, balance, damping, card_units.value if card_units else None, card_format,
                      card_points, None if catalogue is None else str(catalogue))
    progress = _progress() if _terminal() else None
    try:
        tally = run_batch(manifest, store, options, workers or default_workers(), scheduler,
                          progress.advance if progress else None)
    finally:
        if progress is not None:
            progress.stop()
    another = f" ({tally.stored_by_another} stored first by another run)" if tally.stored_by_another else ""
    _report(f"{tally.cards} cards: {tally.analysed} analysed, {tally.skipped} already in {store}; stored "
            f"{tally.ok} results ok, {tally.errors} errors{another}; {tally.seconds:.1f} s, "
            f"{tally.analysed / tally.seconds if tally.seconds > 0 else 0.0:.0f} cards/s")


def _report(line: str) -> None:
    """The run's line on standard output (none if it is closed); one that cannot be written
    (a full disk) is one error line, the results being stored."""
    import sys

    if sys.stdout is None:
        return
    with standard_output(" (the results are stored)") as out:
        out.write(line + "\n")


@app.command("export")
def export(
    store: StoreOption,
    analysis: Annotated[str | None, typer.Option(help="only this analysis (torque or downhole)")] = None,
    well: Annotated[str | None, typer.Option(help="only this well")] = None,
    units: UnitsOption = UnitSystem.si,
    fmt: FormatOption = None,
    out: OutputOption = None,
) -> None:
    """The stored results as CSV, JSON or a table: one row per card and analysis."""
    sink = Output(fmt, units, out, None)
    result = export_result(store, analysis, well, units.value)
    sink.emit(result, ("well", "card", "analysis", "status", "error"))


@app.command("trend")
def trend(
    store: StoreOption,
    well: Annotated[str, typer.Option(help="the well whose cards are shown in time order")],
    units: UnitsOption = UnitSystem.si,
    fmt: FormatOption = None,
    out: OutputOption = None,
) -> None:
    """A well's summary numbers card after card, in time order (peak torque, loading, fillage, loads)."""
    sink = Output(fmt, units, out, None)
    result = trend_result(store, well, units.value)
    sink.emit(result, tuple(c.name for c in result.columns))


@app.command("report")
def report(
    store: StoreOption,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
) -> None:
    """A field on one page: each well's latest card, sortable, linking to its cards (self-contained HTML)."""
    from ..render import PageOutput

    sink = PageOutput(units.value, out)
    sink.emit(field_page(store))


def _terminal() -> bool:
    import sys

    return sys.stderr is not None and sys.stderr.isatty()


class _progress:
    """A rich progress bar on the terminal's stderr."""

    def __init__(self):
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

        self.bar = Progress("cards", BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                            console=Console(stderr=True), transient=True)
        self.task = None
        self.bar.start()

    def advance(self, done: int, total: int) -> None:
        if self.task is None:
            self.task = self.bar.add_task("cards", total=total)
        self.bar.update(self.task, completed=done)

    def stop(self) -> None:
        self.bar.stop()
