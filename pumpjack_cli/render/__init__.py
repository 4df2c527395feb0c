"""The one renderer: a :class:`~pumpjack_cli.results.Result` to a text table, CSV, JSON or a plot.

Analyses build a result (SI values plus the quantity kind of each); commands hand it
to :meth:`Outputs.emit`; nothing else in the package prints results. Unit systems are
applied here only (``si`` or oilfield ``field``), and column names carry the unit suffix
of the system (``position_m`` / ``position_in``; dimensionless quantities carry none).
One module per job: :mod:`.formats` (the format names and plot suffixes, declared once),
:mod:`.delimited` (CSV and JSON), :mod:`.table` (the terminal table), :mod:`.plot`
(matplotlib), :mod:`.targets` (output files and standard output), :mod:`.display`
(values and unit labels in the unit system, shared by the writers). What a text output
holds (:data:`~.formats.CONTENTS`): the columns (a table and JSON add the summary) or
the summary only (CSV: one row per value).

This package imports nothing heavy at start-up (matplotlib only for a plot).
"""

from __future__ import annotations

import dataclasses
import functools
import os
import sys
from pathlib import Path

from ..errors import PumpjackError
from ..results import Result, check_finite
from .delimited import write_csv, write_json, write_summary_csv
from .formats import COLUMNS, CSV, JSON, PLOT_SUFFIXES, SUMMARY, TABLE, choose_format
from .plot import draw_plot
from .table import FILE_TABLE_WIDTH, write_table
from .targets import Target, drop_stdout, standard_output

__all__ = ["Outputs", "PageOutput", "drop_stdout"]

_WRITERS = {CSV: write_csv, JSON: write_json, TABLE: write_table}


class Outputs:
    """Where a result goes, checked when a command starts (before anything is computed):
    stdout or an ``--output`` file in a format holding ``what`` (:data:`~.formats.CONTENTS`),
    and an optional ``--plot`` file (drawn from the columns whatever the output holds).

    :meth:`emit` writes the plot and the output to temporary files (or stdout) and moves
    them into place only when both are complete, so a failure leaves every pre-existing
    file as it was and no temporary file behind.
    """

    def __init__(self, fmt: str | None, system: str, output: Path | None, plot: Path | None, what: str = COLUMNS):
        if plot is not None and plot.suffix.lower() not in PLOT_SUFFIXES:
            raise PumpjackError(f"--plot {plot}: use a file ending in {', '.join(PLOT_SUFFIXES)}")
        if output is not None and plot is not None and os.path.abspath(output) == os.path.abspath(plot):
            raise PumpjackError(f"--output and --plot name the same file {output}")
        if output is None and sys.stdout is None:
            raise PumpjackError("standard output is closed: give --output FILE")
        self.system = system
        self.format = choose_format(fmt, output)
        self.what = what
        self.output = None if output is None else Target(output, "--output")
        self.plot = None if plot is None else Target(plot, "--plot")

    def emit(self, result: Result) -> None:
        """Write the result (and its plot); one line on failure, nothing half-written."""
        check_finite(result)
        targets = [t for t in (self.plot, self.output) if t is not None]
        for target in targets:
            target.refuse_input()
        # the summary alone: the result without its columns, or in CSV (one table) a row per value
        shown = result if self.what == COLUMNS else dataclasses.replace(result, columns=())
        write = write_summary_csv if (self.format, self.what) == (CSV, SUMMARY) else _WRITERS[self.format]
        try:
            if self.plot is not None:
                with self.plot.written(binary=True) as stream:
                    draw_plot(result, self.system, stream, self.plot.path.suffix.lstrip(".").lower())
            if self.output is None:
                with standard_output() as stream:
                    write(shown, self.system, stream)
            else:
                if self.format == TABLE:
                    write = functools.partial(write_table, width=FILE_TABLE_WIDTH)
                with self.output.written() as stream:
                    write(shown, self.system, stream)
            for target in targets:
                target.commit()
        finally:
            for target in targets:
                target.discard()


class PageOutput:
    """Where a page of results goes (:mod:`.html`): an ``--output`` file, checked when the command
    starts and written atomically, or standard output."""

    def __init__(self, system: str, output: Path | None):
        if output is None and sys.stdout is None:
            raise PumpjackError("standard output is closed: give --output FILE")
        if output is not None and output.suffix.lower() not in (".html", ".htm"):
            raise PumpjackError(f"--output {output}: a page is HTML; use a file ending in .html")
        self.system = system
        self.output = None if output is None else Target(output, "--output")

    def emit(self, page) -> None:
        """Write the page; one line on failure, nothing half-written."""
        from .html import write_html

        if self.output is None:
            with standard_output() as stream:
                write_html(page, self.system, stream)
            return
        self.output.refuse_input()
        try:
            with self.output.written() as stream:
                write_html(page, self.system, stream)
            self.output.commit()
        finally:
            self.output.discard()
