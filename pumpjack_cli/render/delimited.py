"""CSV and JSON writers, written with the standard library.

Floats are written with ``repr`` so that they parse back to exactly the numbers the
library computed. CSV is streamed in blocks of rows straight from the arrays, so a
million-row table never becomes per-column Python lists; the JSON series likewise.
"""

from __future__ import annotations

import csv
import io
import json
import os
from typing import Any, TextIO

from ..results import STORED, TEXT, Column, Result, converted_summary, display_name
from .display import CSV_BLOCK, display_values, unit_label

#: Tables with at least this many rows are formatted for CSV on every core.
PARALLEL_ROWS = 100_000


def _csv_block(result: Result, system: str, start: int) -> str:
    """CSV text of the rows [start, start + CSV_BLOCK): floats by ``repr``, text quoted as CSV needs,
    a missing value (None) as an empty cell."""
    columns = [display_values(c, c.values[start:start + CSV_BLOCK], system) for c in result.columns]
    if any(c.quantity in (TEXT, STORED) for c in result.columns) or any(None in values for values in columns):
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


def write_summary_csv(result: Result, system: str, stream: TextIO) -> None:
    """The summary as CSV: a header ``name,value,unit,description``, then one row per value,
    named as in JSON's summary (with the unit suffix), numbers by ``repr``, text as it is."""
    writer = csv.writer(stream, lineterminator="\n")
    writer.writerow(("name", "value", "unit", "description"))
    for (name, value), s in zip(converted_summary(result, system).items(), result.summary):
        writer.writerow((name, value if isinstance(value, str) else repr(value), unit_label(s.quantity, system), s.description))


def _json_values(column: Column, values: Any, system: str) -> str:
    """A slice of a column as the lines of a JSON array indented as ``json.dump(indent=1)``
    writes them inside the document's "series" (floats by ``repr``, as json does; a missing
    value is null)."""
    shown = display_values(column, values, system)
    if column.quantity in (TEXT, STORED):
        return ",\n   ".join(map(json.dumps, shown))
    return ",\n   ".join("null" if v is None else repr(v) for v in shown)


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
            display_name(c.name, c.quantity, system): {"unit": unit_label(c.quantity, system), "description": c.description}
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
