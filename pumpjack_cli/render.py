"""The one renderer: a :class:`~pumpjack_cli.results.Result` to a text table, CSV, JSON or a plot.

Analyses build a result (SI values plus the quantity kind of each); commands hand it
to :func:`emit`; nothing else in the package prints results. Unit systems are applied
here only (``si`` or oilfield ``field``), and column names carry the unit suffix of
the system (``position_m`` / ``position_in``; dimensionless quantities carry none).
CSV and JSON are written with the standard library; floats are written with ``repr``
so that they parse back to exactly the numbers the library computed. CSV is streamed
in blocks of rows straight from the arrays, so a million-row table never becomes
per-column Python lists. The terminal table is laid out here, without a layout
engine: numbers and headers are never cut; columns that do not fit the width are
folded into further blocks.

This module imports nothing heavy at start-up (matplotlib only for a plot).
"""

from __future__ import annotations

import csv
import io
import json
import os
import re
import shutil
import stat
import sys
import textwrap
from pathlib import Path
from typing import Any, TextIO

from .errors import PumpjackError
from .quantities import output_unit
from .text_input import describe_os_error, input_kind
from .results import STORED, TEXT, Column, Result, check_finite, converted_summary, display_name

FORMATS = ("table", "csv", "json")
PLOT_SUFFIXES = (".png", ".svg", ".pdf")
#: Rows converted and written at a time by the CSV writer.
CSV_BLOCK = 4096
#: Tables with at least this many rows are formatted for CSV on every core.
PARALLEL_ROWS = 100_000
#: Width of a table written to a file.
FILE_TABLE_WIDTH = 160
#: Output paths written in place, never replaced by a rename (devices, /dev/stdout, /proc/self/fd/N).
SPECIAL_FILES = ("/dev/", "/proc/")


def _is_array(values: Any) -> bool:
    return hasattr(values, "dtype")


def _display_values(column: Column, values: Any, system: str) -> list:
    """Values (a slice of a column) in display units as Python objects; text passes through."""
    if column.quantity in (TEXT, STORED):
        return list(values)
    unit = output_unit(column.quantity, system)
    if _is_array(values):
        return unit.convert(values.astype(float, copy=False)).tolist()
    return [unit.convert(float(v)) for v in values]


def _unit_label(quantity: str, system: str) -> str:
    return "" if quantity in (TEXT, STORED) else output_unit(quantity, system).label


def _csv_block(result: Result, system: str, start: int) -> str:
    """CSV text of the rows [start, start + CSV_BLOCK): floats by ``repr``, text quoted as CSV needs."""
    columns = [_display_values(c, c.values[start:start + CSV_BLOCK], system) for c in result.columns]
    if any(c.quantity in (TEXT, STORED) for c in result.columns):
        buffer = io.StringIO()
        csv.writer(buffer, lineterminator="\n").writerows(
            [v if isinstance(v, str) else "" if v is None else repr(v) for v in row] for row in zip(*columns))
        return buffer.getvalue()
    return "\n".join(map(",".join, zip(*(list(map(repr, values)) for values in columns)))) + "\n"


#: The result a forked CSV worker formats (set by the parent just before it forks).
_FORKED: tuple[Result, str] | None = None


def _forked_block(start: int) -> str:
    return _csv_block(*_FORKED, start)


def write_csv(result: Result, system: str, stream: TextIO) -> None:
    """Columns as CSV: a header of suffixed snake_case names, then the rows, block by block.

    Writing a float's shortest round-trip text (``repr``) costs a few hundred
    nanoseconds; a table of :data:`PARALLEL_ROWS` rows or more is formatted by forked
    worker processes on every core, block by block and written in order.
    """
    global _FORKED
    writer = csv.writer(stream, lineterminator="\n")
    writer.writerow(display_name(c.name, c.quantity, system) for c in result.columns)
    starts = range(0, result.rows, CSV_BLOCK)
    workers = min(os.cpu_count() or 1, len(starts))
    serial = result.rows < PARALLEL_ROWS or workers < 2
    if not serial:
        import multiprocessing

        serial = "fork" not in multiprocessing.get_all_start_methods()
    if serial:
        for start in starts:
            stream.write(_csv_block(result, system, start))
        return
    _FORKED = (result, system)
    try:
        with multiprocessing.get_context("fork").Pool(workers) as pool:
            for text in pool.imap(_forked_block, starts):
                stream.write(text)
    finally:
        _FORKED = None


def _json_values(column: Column, values: Any, system: str) -> str:
    """A slice of a column as the lines of a JSON array indented as ``json.dump(indent=1)``
    writes them inside the document's "series" (floats by ``repr``, as json does)."""
    shown = _display_values(column, values, system)
    if column.quantity in (TEXT, STORED):
        return ",\n   ".join(map(json.dumps, shown))
    return ",\n   ".join(map(repr, shown))


def write_json(result: Result, system: str, stream: TextIO) -> None:
    """The JSON document: title, unit system, summary, column descriptions and the series.

    The text is that of ``json.dump(document, stream, indent=1)`` plus a newline, but the
    series are written block by block from the arrays, never as one Python list per
    column, so that memory stays that of the arrays on long grids.
    """
    head = json.dumps({
        "title": result.title,
        "units": system,
        "summary": converted_summary(result, system),
        "columns": {
            display_name(c.name, c.quantity, system): {"unit": _unit_label(c.quantity, system), "description": c.description}
            for c in result.columns
        },
        "series": {},
    }, indent=1)
    stream.write(head.removesuffix("{}\n}") + ("{" if result.columns else "{}\n}\n"))
    for i, column in enumerate(result.columns):
        stream.write(f"{',' if i else ''}\n  {json.dumps(display_name(column.name, column.quantity, system))}: ")
        if result.rows == 0:
            stream.write("[]")
            continue
        stream.write("[")
        for start in range(0, result.rows, CSV_BLOCK):
            stream.write(f"{',' if start else ''}\n   {_json_values(column, column.values[start:start + CSV_BLOCK], system)}")
        stream.write("\n  ]")
    if result.columns:
        stream.write("\n }\n}\n")


def _wrap(text: str, width: int) -> list[str]:
    """Lines of at most ``width`` characters that never break inside a number written with
    digit groups ("13 300 lbf" stays on one line)."""
    guarded = re.sub(r"(?<=\d) (?=\d)", "\u00a0", text)
    return [line.replace("\u00a0", " ") for line in textwrap.wrap(guarded, width)]


def _format(value: float) -> str:
    return f"{value:.6g}"


def _summary_lines(result: Result, system: str, width: int) -> list[str]:
    """Summary as aligned lines: name, value, unit, and the meaning wrapped to the width."""
    rows = []
    for s in result.summary:
        unit = output_unit(s.quantity, system)
        rows.append((s.name, _format(unit.convert(float(s.value))), unit.label, s.description))
    if not rows:
        return []
    name_w = max(len(r[0]) for r in rows)
    value_w = max(len(r[1]) for r in rows)
    unit_w = max(len(r[2]) for r in rows)
    lead = name_w + value_w + unit_w + 6
    room = width - lead
    lines = []
    for name, value, label, meaning in rows:
        head = f"{name:<{name_w}}  {value:>{value_w}}  {label:<{unit_w}}  "
        if lead > width:
            lines += [name, f"    {value}  {label}".rstrip()]
            lines += ["    " + more for more in _wrap(meaning, max(width - 4, 20))]
        elif room >= 24:
            wrapped = _wrap(meaning, room) or [""]
            lines.append((head + wrapped[0]).rstrip())
            lines += [" " * lead + more for more in wrapped[1:]]
        else:
            lines.append(head.rstrip())
            lines += ["    " + more for more in _wrap(meaning, max(width - 4, 20))]
    return lines


def _wrap_text_columns(columns: list[tuple[str, str, list[str], bool]], width: int):
    """Text cells wrapped (lines joined by newlines) so that the text columns fit beside the
    first column; numbers are never wrapped."""
    first = max(len(columns[0][0]), len(columns[0][1]), *(len(v) for v in columns[0][2]))
    room = max(width - first - 2, 20)
    return [(name, label, ["\n".join(_wrap(v, room)) or "" for v in values] if text else values, text)
            if i and text else (name, label, values, text) for i, (name, label, values, text) in enumerate(columns)]


def _cell_width(text: str) -> int:
    return max((len(part) for part in text.split("\n")), default=0)


def _table_blocks(columns: list[tuple[str, str, list[str], bool]], width: int) -> list[list[int]]:
    """Column indices per block: the first column starts every block, the others fill the width."""
    widths = [max(len(name), len(label), *(_cell_width(v) for v in values)) for name, label, values, _ in columns]
    blocks, current, used = [], [0], widths[0]
    for i in range(1, len(columns)):
        if len(current) > 1 and used + 2 + widths[i] > width:
            blocks.append(current)
            current, used = [0], widths[0]
        current.append(i)
        used += 2 + widths[i]
    blocks.append(current)
    return blocks


def _row_lines(columns: list[tuple[str, str, list[str], bool]], block: list[int]) -> list[str]:
    """Header (name, unit), a rule and the rows of one block; text left-aligned, numbers right-aligned."""
    widths = {i: max(len(columns[i][0]), len(columns[i][1]), *(_cell_width(v) for v in columns[i][2])) for i in block}

    def line(cells) -> str:
        return "  ".join(cell.ljust(widths[i]) if columns[i][3] else cell.rjust(widths[i]) for i, cell in cells).rstrip()

    def row(r: int) -> list[str]:
        parts = {i: columns[i][2][r].split("\n") for i in block}
        height = max(len(p) for p in parts.values())
        return [line((i, parts[i][k] if k < len(parts[i]) else "") for i in block) for k in range(height)]

    lines = [line((i, columns[i][0]) for i in block), line((i, columns[i][1]) for i in block),
             "  ".join("-" * widths[i] for i in block)]
    for r in range(len(columns[block[0]][2])):
        lines += row(r)
    return lines


def write_table(result: Result, system: str, stream: TextIO, width: int | None = None) -> None:
    """Title, summary and the brief columns as plain text that never cuts a number or a name."""
    width = width if width is not None else shutil.get_terminal_size(fallback=(80, 24)).columns
    width = max(width, 40)
    lines = _wrap(result.title, width) + [""]
    summary = _summary_lines(result, system, width)
    if summary:
        lines += summary + [""]
    brief = [c for c in result.columns if c.brief]
    columns = []
    for c in brief:
        label = _unit_label(c.quantity, system)
        values = _display_values(c, c.values, system)
        columns.append((c.name, f"[{label}]" if label else "",
                        [v if isinstance(v, str) else "" if v is None else _format(v) for v in values],
                        c.quantity == TEXT))
    if columns:
        columns = _wrap_text_columns(columns, width)
        for number, block in enumerate(_table_blocks(columns, width)):
            if number:
                lines.append("")
            lines += _row_lines(columns, block)
    hidden = len(result.columns) - len(brief)
    if hidden:
        lines += ["", f"{hidden} more columns with --format csv or json"]
    for start in range(0, len(lines), CSV_BLOCK):
        stream.write("\n".join(lines[start:start + CSV_BLOCK]) + "\n")


def draw_plot(result: Result, system: str, stream, file_format: str) -> None:
    """Each panel against its x column (default: the first column), dashed curves for
    approximations and bounds, further curves, horizontal lines at the panel's levels,
    to a binary stream in ``file_format`` (png, svg or pdf)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    def shown(name: str):
        column = result.column(name)
        unit = output_unit(column.quantity, system)
        return unit.convert(np.asarray(column.values, dtype=float)), unit

    def values(curve_axis, quantity):
        if isinstance(curve_axis, str):
            return shown(curve_axis)
        unit = output_unit(quantity, system)
        return unit.convert(np.asarray(curve_axis, dtype=float)), unit

    shares_x = all(panel.x is None and not panel.curves for panel in result.panels)
    fig, axes = plt.subplots(len(result.panels), 1, sharex=shares_x, figsize=(8, 2.8 * len(result.panels)))
    for ax, panel in zip(np.atleast_1d(axes), result.panels):
        x_name = panel.x or result.columns[0].name
        x, x_unit = shown(x_name)
        for names, style in ((panel.solid, "-"), (panel.dashed, "--")):
            for name in names:
                ax.plot(x, shown(name)[0], style, label=name)
        y_unit = output_unit(result.column(panel.solid[0]).quantity, system) if panel.solid else None
        for curve in panel.curves:
            (cx, cx_unit), (cy, cy_unit) = values(curve.x, curve.quantity), values(curve.y, curve.quantity)
            ax.plot(cx, cy, curve.style, label=curve.label)
            y_unit = y_unit or cy_unit
            if not panel.solid:
                x_unit = cx_unit
        if panel.clip:
            solid = np.concatenate([shown(name)[0] for name in panel.solid])
            low, high = float(solid.min()), float(solid.max())
            ax.set_ylim(low - 0.5 * (high - low), high + 0.5 * (high - low))
        for label, value in panel.levels:
            ax.axhline(float(y_unit.convert(float(value))), color="red", linewidth=0.8, linestyle=":",
                       label=label or None)
        ax.set_ylabel(f"{panel.title} [{y_unit.label}]")
        ax.grid(True, alpha=0.3)
        if len(panel.solid) + len(panel.dashed) + len(panel.curves) + len([lv for lv in panel.levels if lv[0]]) > 1:
            ax.legend(fontsize="small")
        if not shares_x or ax is np.atleast_1d(axes)[-1]:
            name = panel.x_label if not panel.solid and panel.x_label else x_name
            ax.set_xlabel(f"{name} [{x_unit.label}]")
    fig.suptitle(result.title, fontsize="medium")
    fig.tight_layout()
    fig.savefig(stream, format=file_format)
    plt.close(fig)


class Target:
    """One output file, checked before anything is computed, written at the end.

    A regular file (or a new one) is written to a temporary file beside it and renamed
    onto it only when everything has been written; anything else (a device, a FIFO,
    ``/dev/stdout``) is written in place, never replaced.
    """

    def __init__(self, path: Path, option: str):
        self.path, self.option = path, option
        self.tmp: Path | None = None
        try:
            info = os.stat(path)
        except FileNotFoundError:
            info = None
        except OSError as exc:
            raise PumpjackError(f"{option} {path}: {describe_os_error(exc)}") from None
        if info is not None and stat.S_ISDIR(info.st_mode):
            raise PumpjackError(f"{option} {path}: is a directory")
        real = os.path.realpath(path)
        self.in_place = (info is not None and not stat.S_ISREG(info.st_mode)) or real.startswith(SPECIAL_FILES) \
            or str(path).startswith(SPECIAL_FILES)
        self.mode = stat.S_IMODE(info.st_mode) if info is not None and not self.in_place else None
        if self.in_place:
            if info is not None and not os.access(path, os.W_OK):
                raise PumpjackError(f"{option} {path}: not writable")
            return
        self.path = Path(real)  # through a symbolic link: replace the file it points to, keep the link
        directory = self.path.parent
        if not directory.is_dir():
            raise PumpjackError(f"{option} {path}: directory {path.parent} does not exist")
        if not os.access(directory, os.W_OK | os.X_OK):
            raise PumpjackError(f"{option} {path}: directory {path.parent} is not writable")

    def refuse_input(self) -> None:
        """Refuse a target that is one of the files the run has read (it would be replaced)."""
        kind = input_kind(self.path)
        if kind is not None:
            raise PumpjackError(f"{self.option} {self.path}: is the {kind} this run read; write the result elsewhere")

    def open(self, binary: bool = False):
        """A stream to write to: the temporary file, or the target itself when written in place."""
        try:
            if self.in_place:
                return open(self.path, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""}))
            import tempfile

            fd, name = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=self.path.suffix, dir=self.path.parent)
            self.tmp = Path(name)
            return os.fdopen(fd, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""}))
        except OSError as exc:
            raise PumpjackError(f"{self.option} {self.path}: cannot write: {describe_os_error(exc)}") from None

    def commit(self) -> None:
        """Move the written temporary file onto the target, with the target's mode (or the usual one)."""
        if self.tmp is None:
            return
        if self.mode is None:
            umask = os.umask(0)
            os.umask(umask)
        os.chmod(self.tmp, self.mode if self.mode is not None else 0o666 & ~umask)
        os.replace(self.tmp, self.path)
        self.tmp = None

    def discard(self) -> None:
        if self.tmp is not None:
            self.tmp.unlink(missing_ok=True)
            self.tmp = None


_WRITERS = {"csv": write_csv, "json": write_json, "table": write_table}


def drop_stdout() -> None:
    """Point standard output at /dev/null, so that the text still buffered for a pipe that
    closed (or a full disk) is not written again, and complained about, at exit."""
    if sys.stdout is None:
        return
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass


def choose_format(fmt: str | None, output: Path | None) -> str:
    """Explicit format; else from the output file's suffix; else table on a terminal, csv in a pipe."""
    if fmt is not None:
        return fmt
    if output is not None:
        return {".json": "json", ".csv": "csv", ".txt": "table"}.get(output.suffix.lower(), "csv")
    return "table" if sys.stdout is not None and sys.stdout.isatty() else "csv"


class Outputs:
    """Where a result goes, checked when a command starts (before anything is computed):
    stdout or an ``--output`` file in a format, and an optional ``--plot`` file.

    :meth:`emit` writes the plot and the output to temporary files (or stdout) and moves
    them into place only when both are complete, so a failure leaves every pre-existing
    file as it was and no temporary file behind.
    """

    def __init__(self, fmt: str | None, system: str, output: Path | None, plot: Path | None):
        if plot is not None and plot.suffix.lower() not in PLOT_SUFFIXES:
            raise PumpjackError(f"--plot {plot}: use a file ending in {', '.join(PLOT_SUFFIXES)}")
        if output is not None and plot is not None and os.path.abspath(output) == os.path.abspath(plot):
            raise PumpjackError(f"--output and --plot name the same file {output}")
        if output is None and sys.stdout is None:
            raise PumpjackError("standard output is closed: give --output FILE")
        self.system = system
        self.format = choose_format(fmt, output)
        self.output = None if output is None else Target(output, "--output")
        self.plot = None if plot is None else Target(plot, "--plot")

    def emit(self, result: Result) -> None:
        """Write the result (and its plot); one line on failure, nothing half-written."""
        check_finite(result)
        targets = [t for t in (self.plot, self.output) if t is not None]
        for target in targets:
            target.refuse_input()
        try:
            if self.plot is not None:
                with self.plot.open(binary=True) as stream:
                    draw_plot(result, self.system, stream, self.plot.path.suffix.lstrip(".").lower())
            if self.output is None:
                _WRITERS[self.format](result, self.system, sys.stdout)
                sys.stdout.flush()
            else:
                with self.output.open() as stream:
                    if self.format == "table":
                        write_table(result, self.system, stream, width=FILE_TABLE_WIDTH)
                    else:
                        _WRITERS[self.format](result, self.system, stream)
            for target in targets:
                target.commit()
        except BrokenPipeError:
            raise
        except OSError as exc:
            if self.output is None and exc.filename is None:
                drop_stdout()
                raise PumpjackError(f"cannot write standard output: {describe_os_error(exc)}") from None
            raise PumpjackError(f"cannot write {exc.filename or 'the output'}: {describe_os_error(exc)}") from None
        finally:
            for target in targets:
                target.discard()
