"""The one renderer: a :class:`Report` to a rich table, CSV, JSON or a plot.

Commands build a :class:`Report` (SI values plus the quantity kind of each) and hand
it to :func:`emit`; nothing else in the package prints results. Unit systems are
applied here only (``si`` or oilfield ``field``), and column names carry the unit
suffix of the system (``position_m`` / ``position_in``). CSV and JSON are written
with the standard library, never through rich; floats are written with ``repr`` so
that they parse back to exactly the numbers the library computed.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import sys
import tempfile
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TextIO

import numpy as np

from .errors import PumpjackError
from .units import output_unit

FORMATS = ("table", "csv", "json")


@dataclass(frozen=True)
class Column:
    """A per-crank-angle series: base name, quantity kind, description.

    ``brief`` columns are the ones shown in the terminal table; CSV, JSON and plots
    carry every column.
    """

    name: str
    quantity: str
    description: str
    brief: bool = True


@dataclass(frozen=True)
class Scalar:
    """One summary value (SI) with its quantity kind and description."""

    name: str
    quantity: str
    value: float
    description: str


@dataclass(frozen=True)
class Panel:
    """One plot panel: solid curves and dashed curves (column base names) against the x column."""

    title: str
    solid: tuple[str, ...]
    dashed: tuple[str, ...] = ()


@dataclass(frozen=True)
class Report:
    """Everything a command outputs: SI values with their quantity kinds."""

    title: str
    summary: tuple[Scalar, ...]
    columns: tuple[Column, ...]
    series: Mapping[str, np.ndarray]
    panels: tuple[Panel, ...] = ()

    def column(self, name: str) -> Column:
        return next(c for c in self.columns if c.name == name)


TEXT = "text"


def display_name(name: str, quantity: str, system: str) -> str:
    """Column or summary key with the unit suffix of the unit system."""
    if quantity == TEXT:
        return name
    return f"{name}_{output_unit(quantity, system).suffix}"


def _display_values(column: Column, values, system: str) -> list:
    """A column's values in display units (text columns pass through)."""
    if column.quantity == TEXT:
        return list(values)
    return output_unit(column.quantity, system).convert(np.asarray(values, dtype=float)).tolist()


def _unit_label(quantity: str, system: str) -> str:
    return "" if quantity == TEXT else output_unit(quantity, system).label


def converted_summary(report: Report, system: str) -> dict[str, float]:
    """Summary values in the display units of ``system``, keyed by suffixed name."""
    return {
        display_name(s.name, s.quantity, system): float(output_unit(s.quantity, system).convert(s.value))
        for s in report.summary
    }


def converted_series(report: Report, system: str) -> dict[str, list]:
    """Series in the display units of ``system``, keyed by suffixed name."""
    return {
        display_name(c.name, c.quantity, system): _display_values(c, report.series[c.name], system)
        for c in report.columns
    }


def check_finite(report: Report) -> None:
    """Refuse to output NaN or infinity: name the column and the first bad row."""
    for s in report.summary:
        if not math.isfinite(s.value):
            raise PumpjackError(f"result {s.name} is not finite ({s.value}); the computation failed")
    for c in report.columns:
        if c.quantity == TEXT:
            continue
        values = np.asarray(report.series[c.name], dtype=float)
        bad = np.flatnonzero(~np.isfinite(values))
        if bad.size:
            raise PumpjackError(f"result column {c.name} is not finite at row {bad[0]} of {values.size}")


def write_csv(report: Report, system: str, stream: TextIO) -> None:
    """Series as CSV: a header of suffixed snake_case names, one row per crank angle."""
    series = converted_series(report, system)
    writer = csv.writer(stream, lineterminator="\n")
    writer.writerow(series)
    for row in zip(*series.values()):
        writer.writerow([v if isinstance(v, str) else repr(v) for v in row])


def to_json_dict(report: Report, system: str) -> dict:
    """The JSON document: title, unit system, summary, column descriptions and series."""
    return {
        "title": report.title,
        "units": system,
        "summary": converted_summary(report, system),
        "columns": {
            display_name(c.name, c.quantity, system): {
                "unit": _unit_label(c.quantity, system),
                "description": c.description,
            }
            for c in report.columns
        },
        "series": converted_series(report, system),
    }


def write_json(report: Report, system: str, stream: TextIO) -> None:
    json.dump(to_json_dict(report, system), stream, indent=1)
    stream.write("\n")


def _format(value: float) -> str:
    return f"{value:.6g}"


def write_table(report: Report, system: str, stream: TextIO, width: int | None = None) -> None:
    """Summary and the brief columns as rich tables; units escaped from rich markup."""
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    console = Console(file=stream, width=width, highlight=False)
    summary = Table(title=escape(report.title), show_header=True, header_style="bold")
    for heading in ("quantity", "value", "unit", "meaning"):
        summary.add_column(heading, justify="right" if heading == "value" else "left")
    for s in report.summary:
        unit = output_unit(s.quantity, system)
        summary.add_row(s.name, _format(unit.convert(s.value)), escape(unit.label), escape(s.description))
    if report.summary:
        console.print(summary)
    brief = [c for c in report.columns if c.brief]
    table = Table(show_header=True, header_style="bold")
    for c in brief:
        label = _unit_label(c.quantity, system)
        heading = f"{c.name} [{label}]" if label else c.name
        table.add_column(escape(heading), justify="left" if c.quantity == TEXT else "right")
    rows = zip(*(_display_values(c, report.series[c.name], system) for c in brief))
    for row in rows:
        table.add_row(*(escape(v) if isinstance(v, str) else _format(v) for v in row))
    console.print(table)
    hidden = len(report.columns) - len(brief)
    if hidden:
        console.print(f"{hidden} more columns with --format csv or json")


def write_plot(report: Report, system: str, path: Path) -> None:
    """Each panel against the first column, dashed curves for approximations."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x_col = report.columns[0]
    x_unit = output_unit(x_col.quantity, system)
    x = x_unit.convert(np.asarray(report.series[x_col.name]))
    fig, axes = plt.subplots(len(report.panels), 1, sharex=True, figsize=(8, 2.6 * len(report.panels)))
    for ax, panel in zip(np.atleast_1d(axes), report.panels):
        for names, style in ((panel.solid, "-"), (panel.dashed, "--")):
            for name in names:
                unit = output_unit(report.column(name).quantity, system)
                ax.plot(x, unit.convert(np.asarray(report.series[name])), style, label=name)
        unit = output_unit(report.column(panel.solid[0]).quantity, system)
        ax.set_ylabel(f"{panel.title} [{unit.label}]")
        ax.grid(True, alpha=0.3)
        if len(panel.solid) + len(panel.dashed) > 1:
            ax.legend(fontsize="small")
    np.atleast_1d(axes)[-1].set_xlabel(f"{x_col.name} [{x_unit.label}]")
    fig.suptitle(report.title)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".").lower())
    plt.close(fig)


class atomic_path:
    """Context manager yielding a temporary path beside ``path``; renamed onto it on success."""

    def __init__(self, path: Path):
        self.path = path

    def __enter__(self) -> Path:
        directory = self.path.parent if str(self.path.parent) else Path(".")
        if not directory.is_dir():
            raise PumpjackError(f"{self.path}: directory {directory} does not exist")
        fd, name = tempfile.mkstemp(prefix=f".{self.path.name}.", dir=directory)
        os.close(fd)
        self.tmp = Path(name)
        return self.tmp

    def __exit__(self, exc_type, exc, tb) -> None:
        if exc_type is None:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(self.tmp, 0o666 & ~umask)  # mkstemp makes 0600; give the usual mode
            os.replace(self.tmp, self.path)
        else:
            self.tmp.unlink(missing_ok=True)


_WRITERS = {"csv": write_csv, "json": write_json, "table": write_table}
PLOT_SUFFIXES = (".png", ".svg", ".pdf")


def choose_format(fmt: str | None, output: Path | None) -> str:
    """Explicit format; else from the output file's suffix; else table on a terminal, csv in a pipe."""
    if fmt is not None:
        return fmt
    if output is not None:
        return {".json": "json", ".csv": "csv", ".txt": "table"}.get(output.suffix.lower(), "csv")
    return "table" if sys.stdout.isatty() else "csv"


def emit(report: Report, fmt: str | None, system: str, output: Path | None, plot: Path | None) -> None:
    """Write the report to stdout or ``output`` (atomically) and optionally a plot."""
    check_finite(report)
    if plot is not None and plot.suffix.lower() not in PLOT_SUFFIXES:
        raise PumpjackError(f"--plot {plot}: use a file ending in {', '.join(PLOT_SUFFIXES)}")
    fmt = choose_format(fmt, output)
    if output is None:
        _WRITERS[fmt](report, system, sys.stdout)
    else:
        buffer = io.StringIO()
        if fmt == "table":
            write_table(report, system, buffer, width=160)
        else:
            _WRITERS[fmt](report, system, buffer)
        with atomic_path(output) as tmp:
            tmp.write_text(buffer.getvalue(), encoding="utf-8")
    if plot is not None:
        write_plot(report, system, plot)
