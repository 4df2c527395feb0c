"""The manifest of `pumpjack batch`: a CSV or TOML list of cards, each with its well, unit and overrides.

A row names a well, a unit (a bundled unit's name or a unit file) and a card (a path or
a glob), with optional ``spm``, ``counterbalance_moment`` (with its unit), ``rod_string``
(a file), ``survey`` (the well's deviation survey, a file: docs/deviated.md) and
``timestamp``. Relative paths are taken from the manifest's folder. A
manifest that cannot be read or has a malformed row is refused with one line naming the
line; a card or unit that does not exist is left for the analysis.
"""

from __future__ import annotations

import csv
import glob
import io
import math
import os
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path

from ..errors import PumpjackError
from ..quantities import SPM_RANGE, parse_quantity
from ..text_input import read_text
from .unit_files import names_a_file

#: Manifest columns: required, then optional.
REQUIRED_COLUMNS = ("well", "unit", "card")
OPTIONAL_COLUMNS = ("spm", "counterbalance_moment", "rod_string", "timestamp", "survey", "runtime")
#: Largest manifest [bytes].
MAX_MANIFEST_BYTES = 64 << 20
#: The header of a TOML manifest's card table.
_CARDS_TABLE = re.compile(r"^[ \t]*\[\[[ \t]*cards[ \t]*\]\]", re.MULTILINE)


@dataclass(frozen=True)
class Job:
    """One card of the manifest with its well, unit and overrides (spm [1/min], counterbalance
    moment [N·m]), and its manifest line (where its CSV row or its TOML table starts)."""

    well: str
    unit: str
    card: str
    line: int
    spm: float | None = None
    counterbalance_moment: float | None = None
    rod_string: str | None = None
    timestamp: str = ""
    survey: str | None = None
    #: Share of the day the unit runs (0, 1], for the inferred production of `downhole`.
    runtime: float | None = None


def _row_error(source: str, line: int, message: str) -> PumpjackError:
    return PumpjackError(f"{source}: line {line}: {message}")


def read_manifest(path: Path) -> list[Job]:
    """The manifest's rows as jobs, globs expanded (relative paths are taken from the
    manifest's folder). A manifest that cannot be read, lacks a required column or has a
    malformed row is refused with one line; a card or unit that does not exist is left
    for the analysis, which records it as an error row."""
    source = str(path)
    text = read_text(path, MAX_MANIFEST_BYTES, "manifest", PumpjackError)
    records = _toml_records(text, source) if path.suffix.lower() == ".toml" else _csv_records(text, source)
    jobs = []
    for number, row in records:
        jobs += _jobs(row, number, path.parent, source)
    if not jobs:
        raise PumpjackError(f"{source}: the manifest names no card")
    return jobs


def _toml_records(text: str, source: str) -> list[tuple[int, dict]]:
    """(line, row) of each ``[[cards]]`` table: the line of its header (of the ``cards`` key
    for an inline array of tables)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise PumpjackError(f"{source}: not valid TOML: {exc}") from None
    rows = data.get("cards")
    if not isinstance(rows, list) or not all(isinstance(row, dict) for row in rows):
        raise PumpjackError(f"{source}: a TOML manifest lists its cards as [[cards]] tables")
    lines = [text.count("\n", 0, match.start()) + 1 for match in _CARDS_TABLE.finditer(text)]
    if len(lines) != len(rows):
        key = re.search(r"^[ \t]*cards[ \t]*=", text, re.MULTILINE)
        lines = [text.count("\n", 0, key.start()) + 1 if key else 1] * len(rows)
    return [(line, dict(row)) for line, row in zip(lines, rows)]


def _csv_records(text: str, source: str) -> list[tuple[int, dict]]:
    """(line, row) of each non-blank record after the header (the line where it starts: a
    quoted cell may hold line breaks), cells stripped."""
    reader = csv.reader(io.StringIO(text))
    cells_of = _checked(reader, source)
    header = [cell.strip().lstrip("\ufeff").lower() for cell in next(cells_of, [])]
    missing = [name for name in REQUIRED_COLUMNS if name not in header]
    if missing:
        raise PumpjackError(f"{source}: line 1: the manifest needs the columns {', '.join(REQUIRED_COLUMNS)} "
                            f"(missing: {', '.join(missing)})")
    unknown = [name for name in header if name not in REQUIRED_COLUMNS + OPTIONAL_COLUMNS]
    if unknown:
        raise PumpjackError(f"{source}: line 1: unknown column {unknown[0]!r}; columns: "
                            f"{', '.join(REQUIRED_COLUMNS + OPTIONAL_COLUMNS)}")
    records = []
    start = reader.line_num + 1
    for cells in cells_of:
        number, start = start, reader.line_num + 1
        if not any(cell.strip() for cell in cells):
            continue
        if len(cells) != len(header):
            raise _row_error(source, number, f"{len(cells)} cells for {len(header)} columns")
        records.append((number, dict(zip(header, (cell.strip() for cell in cells)))))
    return records


def _checked(reader, source: str):
    """The records of a CSV reader; a record it refuses (a cell over its size limit) is one
    line naming its line."""
    try:
        yield from reader
    except csv.Error as exc:
        raise _row_error(source, reader.line_num, f"not a CSV row: {exc}") from None


def _spm(row: dict, number: int, source: str) -> float | None:
    """The row's strokes per minute [1/min], if given."""
    spm = row.get("spm")
    if spm is None or spm == "":
        return None
    if isinstance(spm, bool):
        raise _row_error(source, number, f"spm: {str(spm).lower()} is not a number (strokes per minute)")
    try:
        spm = float(spm)
    except (TypeError, ValueError):
        raise _row_error(source, number, f"spm: {spm!r} is not a number (strokes per minute)") from None
    if not (math.isfinite(spm) and SPM_RANGE[0] <= spm <= SPM_RANGE[1]):
        raise _row_error(source, number,
                         f"spm: {spm:g} is outside {SPM_RANGE[0]:g} .. {SPM_RANGE[1]:g} strokes per minute")
    return spm


def _moment(row: dict, number: int, source: str) -> float | None:
    """The row's counterbalance moment [N·m], if given (with its unit)."""
    text = row.get("counterbalance_moment")
    if text is None or text == "":
        return None
    try:
        return parse_quantity(text, "torque", require_unit=True)
    except ValueError as exc:
        raise _row_error(source, number, f"counterbalance_moment: {exc}") from None


def _runtime(row: dict, number: int, source: str) -> float | None:
    """The row's runtime as a share of the day, if given (``"75 %"``, ``"18 h"``)."""
    text = row.get("runtime")
    if text is None or text == "":
        return None
    try:
        share = parse_quantity(text, "runtime", require_unit=True)
    except ValueError as exc:
        raise _row_error(source, number, f"runtime: {exc}") from None
    if not 0.0 < share <= 1.0:
        raise _row_error(source, number, f"runtime: {text!r} is outside 0 .. 100 % (24 h a day)")
    return share


def _jobs(row: dict, number: int, folder: Path, source: str) -> list[Job]:
    for name in REQUIRED_COLUMNS:
        value = row.get(name)
        if value is not None and not isinstance(value, str):
            raise _row_error(source, number, f"{name}: {value!r} is not text")
        if value is None or not value.strip():
            raise _row_error(source, number, f"{name} is empty")
    extra = set(row) - set(REQUIRED_COLUMNS + OPTIONAL_COLUMNS)
    if extra:
        raise _row_error(source, number, f"unknown field {sorted(extra)[0]!r}")
    spm, moment = _spm(row, number, source), _moment(row, number, source)
    unit = row["unit"].strip()
    if names_a_file(unit) and not Path(unit).is_absolute():
        unit = str(folder / unit)
    rod_string = row.get("rod_string") or None
    if rod_string is not None and not isinstance(rod_string, str):
        raise _row_error(source, number, f"rod_string: {rod_string!r} is not a file name (text)")
    if rod_string is not None and not Path(rod_string).is_absolute():
        rod_string = str(folder / rod_string)
    survey = row.get("survey") or None
    if survey is not None and not Path(survey).is_absolute():
        survey = str(folder / survey)
    pattern = row["card"].strip()
    pattern = pattern if Path(pattern).is_absolute() else str(folder / pattern)
    cards = sorted(glob.glob(pattern)) if glob.has_magic(pattern) and not os.path.exists(pattern) else [pattern]
    if not cards:
        raise _row_error(source, number, f"card: no file matches {row['card']!r}")
    timestamp = row.get("timestamp") or ""
    if not isinstance(timestamp, str):
        timestamp = str(timestamp)
    runtime = _runtime(row, number, source)
    return [Job(row["well"].strip(), unit, card, number, spm, moment, rod_string, timestamp, survey, runtime)
            for card in cards]
