"""Delimited-text cards: comma-, semicolon- or tab-separated columns under a header line,
after an optional metadata preamble.

Three layouts: ``crank_angle, load``; ``position, load``; ``time, position, load``.
Units, delimiters, decimal commas, encodings, index columns, column mapping, the
preamble, this tool's own CSV outputs, limits and every refusal are specified in
``docs/cards.md``; every refusal is a one-line :class:`~pumpjack_cli.errors.CardError`
naming the file (``<stdin>`` for ``-``), the line and the column. The reader puts the
rows in time order and drops the repeated closing sample of a closed position card; it
knows no unit (no stroke, no kinematics): a stated stroke is checked against the
positions' own range only.
"""

from __future__ import annotations

import re
from bisect import bisect_right
from collections.abc import Callable
from datetime import datetime
from functools import lru_cache, wraps
from itertools import compress, repeat
from typing import TypeVar

import numpy as np

from ...errors import CardError
from ...quantities import UNIT_SPELLINGS
from .raw import (DEFAULT_UNITS, DELIMITERS, KINDS, LAYOUT_TEXT, LAYOUTS, MAX_POINTS, MIN_POINTS,
                  STATED_STROKE_TOLERANCE, UNITS, CardFile, Column, RawCard, assemble, content_lines_of, in_si,
                  is_content, show, stated_spm, unit_of, written_card)

#: File name endings read as delimited text without looking at the content.
EXTENSIONS = (".csv", ".tsv", ".txt")
#: Lines of any kind (points, comments, blanks), counted before the text is split.
MAX_LINES = 2 * MAX_POINTS
MAX_COLUMNS = 64

_KIND_OF_NAME = {name: kind for kind, (names, _) in KINDS.items() for name in names}
#: Index or sample-number columns, ignored ('#' is read as 'no'); so are unnamed columns.
_INDEX_NAMES = {"index", "idx", "i", "n", "no", "nr", "num", "number", "sample", "sample_no", "sample_number",
                "point", "point_no", "point_number", "pt"}
_KNOWN_TEXT = ("known: crank_angle/angle/theta, time/t, position/displacement/pos, load/force/prl/polished_rod_load/rod_load, "
               "index columns (index, sample, n, #, point); map others with --card-columns position=...,load=...[,time=...]")
_DELIMITER_NAMES = {"\t": "tab", ";": "semicolon", ",": "comma"}
_UNIT_AT_END = re.compile(r"^(.*?)\s*(?:[\[(]\s*([^\[\]()]*?)\s*[\])]|,\s*([^,]+?))\s*$")

#: Preamble keys (folded as column names are: case, spaces, dots and dashes; '/' as '_') -> canonical key.
PREAMBLE_KEYS = {
    "well": "well", "well_name": "well", "wellname": "well", "well_id": "well",
    "date": "date", "date_time": "timestamp", "datetime": "timestamp", "timestamp": "timestamp",
    "time_stamp": "timestamp", "time": "time",
    "spm": "spm", "strokes_per_minute": "spm", "pumping_speed": "spm", "stroke_rate": "spm",
    "stroke": "stroke", "stroke_length": "stroke", "surface_stroke": "stroke",
    "units": "units", "unit_system": "units",
}
_PREAMBLE_TEXT = "Well Name, Date, Time, SPM, Stroke, Units"
#: Unit systems a preamble's Units line may name -> the --card-units they mean.
_UNIT_SYSTEMS = {"si": "si", "metric": "si", "field": "field", "oilfield": "field", "english": "field",
                 "imperial": "field", "us": "field"}
#: A time of day (the value of a preamble's Time line; a header's first column may be "time").
_CLOCK = re.compile(r"^\d{1,2}:\d{2}(?::\d{2}(?:\.\d+)?)?$")
_LENGTH = re.compile(r"^([0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?)\s*(\S*)$")
#: What a line of up to _KEPT_LINE characters means as a preamble entry or a header is kept for
#: the _KEPT lines seen last (:func:`_kept`).
_KEPT, _KEPT_LINE = 256, 1000
_Meaning = TypeVar("_Meaning")


def _kept(meaning: Callable[..., _Meaning]) -> Callable[..., _Meaning]:
    """``meaning(line, *options)``, worked out once for a short line: a fleet's card files come
    from a few exports, so their headers and preamble keys repeat. A refusal is not kept."""
    known = lru_cache(maxsize=_KEPT)(meaning)

    @wraps(meaning)
    def meaning_of(line: str, *options) -> _Meaning:
        return (known if len(line) <= _KEPT_LINE else meaning)(line, *options)
    return meaning_of


def recognises(file: CardFile) -> bool:
    """True when the first line after the preamble that is not a comment or blank holds a
    comma, semicolon or tab."""
    return file.is_text and any(d in _preamble_lines(file.text)[2] for d in DELIMITERS)


def _split_unit(cell: str) -> tuple[str, str | None]:
    """Name and the unit written in brackets or after a comma, if any."""
    text = cell.strip().strip('"').strip()
    found = _UNIT_AT_END.match(text)
    if found and found.group(1):
        return found.group(1), found.group(2) if found.group(2) is not None else found.group(3)
    return text, None


def _name_key(name: str) -> str:
    """The name with spaces, dots and dashes as underscores and '#' as 'no'; case kept."""
    return re.sub(r"[\s.\-]+", "_", name.strip().replace("#", " no ")).strip("_")


def _column(cell: str, default_units: str | None, column: int,
            kind: str | None = None) -> tuple[str, str, float] | None:
    """Kind, unit label and factor to SI of header cell number ``column`` (from 1).

    Without ``kind`` the cell is named by the reader's rules (None for an index or
    unnamed column); with it (a mapped column) only its unit is looked for, in brackets,
    after a comma or as a suffix that is a unit of its dimension. A refusal's message
    follows the header's place (:func:`_layout`).
    """
    name, unit = _split_unit(cell)
    key = _name_key(name)
    stem, _, suffix = key.rpartition("_")
    if kind is not None:
        unit = suffix if unit is None and stem and suffix.lower() in UNITS[KINDS[kind][1]] else unit
    elif unit is None and stem.lower() in _KIND_OF_NAME:
        kind, unit = _KIND_OF_NAME[stem.lower()], suffix
    elif key.lower() in _KIND_OF_NAME:
        kind = _KIND_OF_NAME[key.lower()]
    elif key.lower() in _INDEX_NAMES or not key:
        return None
    else:
        raise CardError(f"unknown column {show(cell.strip())} (column {column}); {_KNOWN_TEXT}")
    return (kind, *unit_of(unit, kind, default_units, f"column {column} {show(cell.strip())}"))


@_kept
def _layout(header: str, default_units: str | None, mapping: tuple[tuple[str, str], ...] | None
            ) -> tuple[str, int, tuple[tuple[str, tuple[int, str, float]], ...]]:
    """The delimiter of a header line, its number of cells and its used columns as (kind, (column
    index, unit label, factor to SI)) pairs; ``mapping`` holds ``--card-columns``' (kind, header)
    pairs. A refusal's message is what follows the header's place, "card.csv: line 4: ", which
    the reader puts before it."""
    delimiter = next((d for d in DELIMITERS if d in header), None)
    if delimiter is None:
        hint = f" (a preamble line? its keys are {_PREAMBLE_TEXT})" if ":" in header else ""
        raise CardError(f"no comma, semicolon or tab in the header {show(header.strip())}{hint}; "
                        f"a card has named columns, e.g. position_in,load_lbf")
    if header.count(delimiter) >= MAX_COLUMNS:
        raise CardError(f"{header.count(delimiter) + 1} columns; a card file has at most {MAX_COLUMNS}")
    cells = header.split(delimiter)
    if all(_is_float(cell.replace(",", ".")) for cell in cells):
        raise CardError("numbers where the header should be; the first line names the columns, "
                        "e.g. position_in,load_lbf")
    used = _header(cells, default_units, None if mapping is None else dict(mapping))
    return delimiter, len(cells), tuple(used.items())


def _header(cells: list[str], default_units: str | None,
            mapping: dict[str, str] | None) -> dict[str, tuple[int, str, float]]:
    """Used columns: kind -> (column index, unit label, factor to SI)."""
    found: dict[str, list[tuple[int, str, float]]] = {}
    written = None if mapping is not None else written_card([cell.strip().strip('"').strip() for cell in cells])
    if written is not None:
        return written
    if mapping is None:
        for j, cell in enumerate(cells):
            named = _column(cell, default_units, j + 1)
            if named is not None:
                found.setdefault(named[0], []).append((j, *named[1:]))
    else:
        folded = [cell.strip().strip('"').strip().casefold() for cell in cells]
        for kind, header in mapping.items():
            matches = [j for j, cell in enumerate(folded) if cell == header.casefold()]
            if len(matches) != 1:
                where = "no column" if not matches else f"{len(matches)} columns ({', '.join(str(j + 1) for j in matches)})"
                raise CardError(f"--card-columns {kind}={header!r}: {where} of that name; "
                                f"the header has {', '.join(show(c.strip()) for c in cells[:12])}")
            found[kind] = [(matches[0], *_column(cells[matches[0]], default_units, matches[0] + 1, kind)[1:])]
    kinds = [kind for kind, where in found.items() for _ in where]
    if len(set(kinds)) != len(kinds) or set(kinds) not in LAYOUTS:
        raise CardError(f"columns {', '.join(kinds) or 'none'}; {LAYOUT_TEXT}")
    return {kind: where[0] for kind, where in found.items()}


def _numbers(cells: list[str], kind: str, lines: np.ndarray, source: str) -> np.ndarray:
    """One column's cells as floats, or a one-line error at the first cell that is not a number
    (written with ASCII digits and no underscores: ``float`` would read "4_5.5" and Arabic-Indic
    digits, which no logger writes)."""
    joined = "".join(cells)
    try:
        if ("_" in joined or not joined.isascii()) and not all(map(_is_float, cells)):
            raise ValueError
        return np.fromiter(map(float, cells), dtype=float, count=len(cells))
    except ValueError:
        i = next(i for i, cell in enumerate(cells) if not _is_float(cell))
        what = "is empty" if not cells[i].strip() else f"{show(cells[i].strip())} is not a number"
        raise CardError(f"{source}: line {lines[i]}: {kind} {what}") from None


def _is_float(cell: str) -> bool:
    text = cell.strip()   # any whitespace around, a no-break space too, as float strips it
    if "_" in text or not text.isascii():
        return False
    try:
        float(cell)
    except ValueError:
        return False
    return True


@_kept
def _preamble_entry(line: str) -> tuple[str, str, str | None, str] | None:
    """(canonical key, key as written, unit written with the key, value) of a preamble line
    (``key,value``, ``key;value``, ``key<tab>value`` or ``key: value`` with a key of
    :data:`PREAMBLE_KEYS`), None for any other line (the header). A ``time`` line is one
    only when its value is a time of day: ``time,position,load`` is a header."""
    text = line.strip()
    delimiter = next((d for d in DELIMITERS if d in text), None)
    splits = [text.partition(delimiter)] if delimiter else []
    for key, separator, value in [*splits, text.partition(":")]:
        if not separator:
            continue
        name, unit = _split_unit(key)
        canonical = PREAMBLE_KEYS.get(_name_key(name.replace("/", "_")).lower())
        value = value.strip().rstrip(delimiter or "").strip().strip('"').strip()
        if canonical is not None and (canonical != "time" or _CLOCK.match(value)):
            return canonical, key.strip(), unit, value
    return None


def _stated_stroke(value: str, unit: str | None, default_units: str | None, where: str) -> float:
    """A stated stroke [m]: "144 in", or a bare number in the key's unit ("Stroke (in)") or the
    card's units."""
    found = _LENGTH.match(value)
    written = (found.group(2) or unit) if found else None
    if written is None and found and default_units is not None:
        written = DEFAULT_UNITS[default_units]["length"]
    key = UNIT_SPELLINGS.get(str(written).lower().rstrip("."), str(written).lower().rstrip("."))
    if found is None or float(found.group(1)) <= 0:
        raise CardError(f"{where}: Stroke {show(value)} is not a length (e.g. 144 in or 3.66 m)")
    if written is None:
        raise CardError(f"{where}: Stroke {show(value)} names no unit: write it (144 in, 3.66 m) or give Units or "
                        f"--card-units si or field")
    if key not in UNITS["length"]:
        raise CardError(f"{where}: Stroke {show(value)} has unit {written!r}, not a unit of length "
                        f"({', '.join(UNITS['length'])})")
    return float(found.group(1)) * UNITS["length"][key]


def _preamble(entries: list[tuple[int, tuple[str, str, str | None, str]]], source: str,
              card_units: str | None) -> tuple[dict[str, object], dict[str, int], str | None]:
    """The metadata of the preamble's lines (canonical keys), the line of each, and the units of
    columns whose header names none (``--card-units``, else the preamble's Units)."""
    given: dict[str, tuple[int, str, str | None, str]] = {}
    for line, (canonical, key, unit, value) in entries:
        where = f"{source}: line {line}"
        if canonical in given:
            raise CardError(f"{where}: {key} given twice (line {given[canonical][0]})")
        if not value:
            raise CardError(f"{where}: {key} is empty")
        given[canonical] = (line, key, unit, value)
    metadata: dict[str, object] = {}
    lines: dict[str, int] = {}
    if "units" in given:
        line, key, _, value = given["units"]
        system = _UNIT_SYSTEMS.get(value.lower())
        if system is None:
            raise CardError(f"{source}: line {line}: {key} {show(value)}: use si or field")
        if card_units is not None and card_units != system:
            raise CardError(f"{source}: line {line}: {key} {value}, but --card-units {card_units}")
        metadata["units"], lines["units"], card_units = system, line, system
    if "well" in given:
        metadata["well"], lines["well"] = given["well"][3], given["well"][0]
    if "spm" in given:
        line, _, unit, value = given["spm"]
        metadata["spm"] = stated_spm(value if unit is None else f"{value} {unit}", f"{source}: line {line}")
        lines["spm"] = line
    if "stroke" in given:
        line, _, unit, value = given["stroke"]
        metadata["stroke"] = _stated_stroke(value, unit, card_units, f"{source}: line {line}")
        lines["stroke"] = line
    stamp = given.get("timestamp") or given.get("date")
    if "time" in given and (stamp is None or "timestamp" in given):
        raise CardError(f"{source}: line {given['time'][0]}: a Time goes with a Date line (YYYY-MM-DD)")
    if stamp is not None:
        line, key, _, value = stamp
        text = value if "time" not in given else f"{value} {given['time'][3]}"
        try:
            when = datetime.fromisoformat(text)
        except ValueError:
            raise CardError(f"{source}: line {line}: {key} {show(text)} is not a date and time "
                            f"(YYYY-MM-DD HH:MM[:SS], ISO 8601)") from None
        metadata["timestamp"], lines["timestamp"] = when.isoformat(), line
    return metadata, lines, card_units


def _check_stroke(metadata: dict[str, object], lines: dict[str, int], columns: dict[str, Column],
                  source: str) -> None:
    """Refuse positions whose range differs from the stated stroke by more than
    :data:`STATED_STROKE_TOLERANCE` (5 %, as the unit's stroke check)."""
    if "stroke" not in metadata or "position" not in columns:
        return
    position = columns["position"]
    stated, span = float(metadata["stroke"]), float(np.ptp(position.values))
    mismatch = span / stated - 1.0
    if abs(mismatch) > STATED_STROKE_TOLERANCE:
        raise CardError(f"{source}: line {lines['stroke']}: stated stroke {stated / position.factor:.4g} "
                        f"{position.unit}, but the positions span {span / position.factor:.4g} {position.unit} "
                        f"({100 * mismatch:+.1f} %); check the stroke or the position column's unit")


def read(file: CardFile) -> RawCard:
    """The raw card of a delimited text (see :func:`pumpjack_cli.readers.cards.read_card`): the
    used columns in SI, the line of each row, the preamble's statements as ``metadata``.

    Rows in reverse time order are turned back (one warning); a position card closed by
    repeating its first sample loses the repeat.
    """
    text, source = file.text, file.source
    if text.count("\n") >= MAX_LINES:
        raise CardError(f"{source}: more than {MAX_LINES} lines; a card file has at most {MAX_LINES}")
    entries, at, header, start = _preamble_lines(text)
    metadata, stated_lines, default_units = _preamble(entries, source, file.units)
    if at is None:
        raise CardError(f"{source}: empty card")
    try:
        delimiter, width, layout = _layout(header, default_units,
                                           None if file.columns is None else tuple(file.columns.items()))
    except CardError as error:
        raise CardError(f"{source}: line {at + 1}: {error}") from None
    used = dict(layout)
    rows, table = _table(text[start:], delimiter, width) if len(used) == width else ([], None)
    if table is None:
        numbers, columns = _cells(file.lines, text, at, delimiter, width, used, source)
    else:
        numbers = np.arange(at + 2, at + 2 + len(rows), dtype=int)
    values = {}
    for kind, (j, unit, factor) in used.items():
        if table is None:
            cells = columns[kind]
            found, written = _numbers(cells, kind, numbers, source), cells.__getitem__
        else:
            found, written = table[:, j], lambda i: rows[i].split(delimiter)[j]
        values[kind] = Column(in_si(found, kind, unit, factor, lambda i: f"{source}: line {numbers[i]}",
                                    lambda i: written(i).strip()[:40]), unit, factor)
    if numbers.size < MIN_POINTS:
        raise CardError(f"{source}: {numbers.size} points; a card needs at least {MIN_POINTS}")
    _check_stroke(metadata, stated_lines, values, source)
    return assemble(source, values, numbers, metadata=metadata, metadata_lines=stated_lines)


def _preamble_lines(text: str) -> tuple[list[tuple[int, tuple[str, str, str | None, str]]], int | None, str, int]:
    """The preamble's entries (each with its line number); the header, the first line that is
    neither blank, a comment (:func:`.raw.is_content`) nor a preamble entry: its index (None when
    there is none) and text; and where the line after it starts in ``text``. Only the lines down
    to the header are looked at."""
    entries = []
    for i, line, start in content_lines_of(text):
        entry = _preamble_entry(line)
        if entry is None:
            return entries, i, line, start
        entries.append((i + 1, entry))
    return entries, None, "", len(text) + 1


def _table(block: str, delimiter: str, width: int) -> tuple[list[str], np.ndarray | None]:
    """The lines of ``block`` (the text under a header of ``width`` cells, all of them used) down
    to the last that is not empty, and their numbers, a (lines, ``width``) array, when every one
    of them is a row of ``width`` numbers, as in most card files; else no numbers, and the rows
    are left to :func:`_cells`.

    The numbers are read in one call of numpy's text reader (:func:`numpy.loadtxt`), which passes
    each cell, stripped of whitespace, to the function behind ``float``
    (``PyOS_string_to_double``): each number is the double ``float`` reads. It reads less than
    ``float`` (no underscores, no digits but ASCII ones) and refuses a row of another width and a
    cell that is not a number (an empty, a blank, a quoted cell, a comment's first). It would skip
    an empty line, so rows with one are not given to it. Any of these leaves the rows to
    :func:`_cells`, which refuses what it must, naming the line and the column.
    """
    block = block.rstrip("\n")
    rows = block.split("\n") if block else []
    if not rows or len(rows) > MAX_POINTS or "" in rows:
        return rows, None
    try:
        table = np.loadtxt(rows, delimiter=delimiter, comments=None, dtype=float, ndmin=2)
    except ValueError:
        return rows, None
    return rows, table if table.shape == (len(rows), width) else None


def _cells(lines: list[str], text: str, at: int, delimiter: str, width: int,
           used: dict[str, tuple[int, str, float]], source: str) -> tuple[np.ndarray, dict[str, list[str]]]:
    """The line number of every row under the header at line index ``at`` (the lines that are
    neither blank nor comments), and the cells of each used column, without quotes and with
    decimal points; rows of another width than the header's, or too many, are refused."""
    kept = _content(lines, text)
    kept = kept[bisect_right(kept, at):]
    rows = [lines[i] for i in kept]
    numbers = np.array(kept, dtype=int) + 1
    if len(rows) > MAX_POINTS:
        raise CardError(f"{source}: {len(rows)} points; a card has at most {MAX_POINTS}")
    counts = list(map(str.count, rows, repeat(delimiter)))
    if counts.count(width - 1) != len(rows):
        widths = np.array(counts, dtype=int) + 1
        i = int(np.argmax(widths != width))
        hint = ("; a decimal comma or thousands separator in a comma-separated file?"
                if delimiter == "," and widths[i] > width else "")
        raise CardError(f"{source}: line {numbers[i]}: {widths[i]} values, the header has {width}{hint}")
    flat = delimiter.join(rows).split(delimiter) if rows else []
    columns = {kind: flat[j::width] for kind, (j, _, _) in used.items()}
    if '"' in text:
        columns = {kind: [cell.strip().strip('"') for cell in cells] for kind, cells in columns.items()}
    if delimiter != ",":
        columns = _decimal_commas(columns, used, numbers, source, _DELIMITER_NAMES[delimiter])
    return numbers, columns


def _content(lines: list[str], text: str) -> list[int]:
    """The indices of the lines that are neither blank nor comments (:func:`.raw.is_content`),
    looked at one by one only up to the last line holding a '#' (the comments of a card file
    come before its rows)."""
    kept = list(compress(range(len(lines)), map(str.strip, lines)))
    if "#" not in text:
        return kept
    cut = bisect_right(kept, text.count("\n", 0, text.rfind("#")))
    return [i for i in kept[:cut] if is_content(lines[i])] + kept[cut:]


def _decimal_commas(columns: dict[str, list[str]], used: dict[str, tuple[int, str, float]], numbers: np.ndarray,
                    source: str, delimiter: str) -> dict[str, list[str]]:
    """Cells with decimal points, from decimal commas when the file has commas and no points."""
    joined = "\n".join("\n".join(cells) for cells in columns.values())
    if "," not in joined:
        return columns
    if "." in joined:
        comma = next((kind, i) for kind, cells in columns.items() for i, cell in enumerate(cells) if "," in cell)
        point = next((kind, i) for kind, cells in columns.items() for i, cell in enumerate(cells) if "." in cell)
        (k1, i1), (k2, i2) = comma, point
        raise CardError(f"{source}: line {numbers[i1]}: {k1} {show(columns[k1][i1].strip())} (column {used[k1][0] + 1}) "
                        f"has a comma but line {numbers[i2]}: {k2} {show(columns[k2][i2].strip())} a point; "
                        f"cannot tell the decimal mark in this {delimiter}-separated file (thousands separators?)")
    return {kind: [cell.replace(",", ".") for cell in cells] for kind, cells in columns.items()}
