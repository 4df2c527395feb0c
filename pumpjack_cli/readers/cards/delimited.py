"""Delimited-text cards: comma-, semicolon- or tab-separated columns under a header line.

Three layouts: ``crank_angle, load``; ``position, load``; ``time, position, load``.
Units, delimiters, decimal commas, encodings, index columns, column mapping, limits and
every refusal are specified in ``docs/cards.md``; every refusal is a one-line
:class:`~pumpjack_cli.errors.CardError` naming the file (``<stdin>`` for ``-``), the
line and the column. The reader puts the rows in time order and drops the repeated
closing sample of a closed position card; it knows no unit (no stroke, no kinematics).
"""

from __future__ import annotations

import io
import re
from dataclasses import dataclass
from itertools import repeat

import numpy as np

from ...errors import CardError
from .raw import KINDS, LAYOUT_TEXT, LAYOUTS, UNITS, RawCard, show, unit_of

#: File name endings read as delimited text without looking at the content.
EXTENSIONS = (".csv", ".tsv", ".txt")
MIN_POINTS = 8
MAX_POINTS = 100_000
#: Lines of any kind (points, comments, blanks), counted before the text is split.
MAX_LINES = 2 * MAX_POINTS
MAX_COLUMNS = 64
#: Largest magnitude of a load [N] and a position [m] in a card, far beyond any pumping
#: unit (the largest API Spec 11E structure rating is below 0.3 MN, the longest stroke
#: below 10 m): a larger number is a wrong unit or a corrupt file, refused by its line
#: before it can overflow the computation.
LIMITS = {"load": (1e7, "10 MN"), "position": (1e3, "1 km")}

_KIND_OF_NAME = {name: kind for kind, (names, _) in KINDS.items() for name in names}
#: Index or sample-number columns, ignored ('#' is read as 'no'); so are unnamed columns.
_INDEX_NAMES = {"index", "idx", "i", "n", "no", "nr", "num", "number", "sample", "sample_no", "sample_number",
                "point", "point_no", "point_number", "pt"}
_KNOWN_TEXT = ("known: crank_angle/angle/theta, time/t, position/displacement/pos, load/force/prl/polished_rod_load/rod_load, "
               "index columns (index, sample, n, #, point); map others with --card-columns position=...,load=...[,time=...]")
_DELIMITERS = ("\t", ";", ",")
_DELIMITER_NAMES = {"\t": "tab", ";": "semicolon", ",": "comma"}
_UNIT_AT_END = re.compile(r"^(.*?)\s*(?:[\[(]\s*([^\[\]()]*?)\s*[\])]|,\s*([^,]+?))\s*$")


@dataclass(frozen=True)
class _Column:
    values: np.ndarray
    unit: str
    factor: float


def _is_content(line: str) -> bool:
    """Neither blank nor a comment; '#' directly followed by a delimiter is the index column '#'."""
    text = line.strip()
    return bool(text) and (not text.startswith("#") or text[1:2] in _DELIMITERS)


def recognises(text: str) -> bool:
    """True when the first line that is not a comment or blank holds a comma, semicolon or tab."""
    header = next((line for line in io.StringIO(text) if _is_content(line)), "")
    return any(d in header for d in _DELIMITERS)


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


def _column(cell: str, default_units: str | None, prefix: str, column: int,
            kind: str | None = None) -> tuple[str, str, float] | None:
    """Kind, unit label and factor to SI of header cell number ``column`` (from 1).

    Without ``kind`` the cell is named by the reader's rules (None for an index or
    unnamed column); with it (a mapped column) only its unit is looked for, in brackets,
    after a comma or as a suffix that is a unit of its dimension.
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
        raise CardError(f"{prefix}: unknown column {show(cell.strip())} (column {column}); {_KNOWN_TEXT}")
    return (kind, *unit_of(unit, kind, default_units, f"{prefix}: column {column} {show(cell.strip())}"))


def _header(cells: list[str], line: int, source: str, default_units: str | None,
            mapping: dict[str, str] | None) -> dict[str, tuple[int, str, float]]:
    """Used columns: kind -> (column index, unit label, factor to SI)."""
    found: dict[str, list[tuple[int, str, float]]] = {}
    prefix = f"{source}: line {line}"
    if mapping is None:
        for j, cell in enumerate(cells):
            named = _column(cell, default_units, prefix, j + 1)
            if named is not None:
                found.setdefault(named[0], []).append((j, *named[1:]))
    else:
        folded = [cell.strip().strip('"').strip().casefold() for cell in cells]
        for kind, header in mapping.items():
            matches = [j for j, cell in enumerate(folded) if cell == header.casefold()]
            if len(matches) != 1:
                where = "no column" if not matches else f"{len(matches)} columns ({', '.join(str(j + 1) for j in matches)})"
                raise CardError(f"{prefix}: --card-columns {kind}={header!r}: {where} of that name; "
                                f"the header has {', '.join(show(c.strip()) for c in cells[:12])}")
            found[kind] = [(matches[0], *_column(cells[matches[0]], default_units, prefix, matches[0] + 1, kind)[1:])]
    kinds = [kind for kind, where in found.items() for _ in where]
    if len(set(kinds)) != len(kinds) or set(kinds) not in LAYOUTS:
        raise CardError(f"{prefix}: columns {', '.join(kinds) or 'none'}; {LAYOUT_TEXT}")
    return {kind: where[0] for kind, where in found.items()}


def _numbers(cells: list[str], kind: str, lines: np.ndarray, source: str) -> np.ndarray:
    """One column's cells as finite floats, or a one-line error at the first culprit."""
    try:
        values = np.fromiter(map(float, cells), dtype=float, count=len(cells))
    except ValueError:
        i = next(i for i, cell in enumerate(cells) if not _is_float(cell))
        what = "is empty" if not cells[i].strip() else f"{show(cells[i].strip())} is not a number"
        raise CardError(f"{source}: line {lines[i]}: {kind} {what}") from None
    bad = ~np.isfinite(values)
    if bad.any():
        i = int(np.argmax(bad))
        raise CardError(f"{source}: line {lines[i]}: {kind} is {cells[i].strip()[:40]}, not a finite number")
    return values


def _bounded(values: np.ndarray, kind: str, lines: np.ndarray, cells: list[str], unit: str,
             source: str) -> np.ndarray:
    """The column's SI values if none is beyond its kind's :data:`LIMITS`, else a one-line
    error at the first culprit."""
    if kind not in LIMITS:
        return values
    limit, shown = LIMITS[kind]
    beyond = np.abs(values) > limit
    if beyond.any():
        i = int(np.argmax(beyond))
        raise CardError(f"{source}: line {lines[i]}: {kind} {cells[i].strip()[:40]} {unit} is beyond {shown}: "
                        f"not a polished-rod {kind}; check the column's unit")
    return values


def _is_float(cell: str) -> bool:
    try:
        float(cell)
    except ValueError:
        return False
    return True


def _parse(text: str, source: str, default_units: str | None,
           mapping: dict[str, str] | None) -> tuple[dict[str, _Column], np.ndarray]:
    """The used columns of a card's text, in SI, and the line number of each row."""
    if text.count("\n") >= MAX_LINES:
        raise CardError(f"{source}: more than {MAX_LINES} lines; a card file has at most {MAX_LINES}")
    lines = text.split("\n")
    kept = [i for i, line in enumerate(lines) if _is_content(line)]
    if not kept:
        raise CardError(f"{source}: empty card")
    header_line = kept[0] + 1
    header = lines[kept[0]]
    delimiter = next((d for d in _DELIMITERS if d in header), None)
    if delimiter is None:
        raise CardError(f"{source}: line {header_line}: no comma, semicolon or tab in the header {show(header.strip())}; "
                        f"a card has named columns, e.g. position_in,load_lbf")
    if header.count(delimiter) >= MAX_COLUMNS:
        raise CardError(f"{source}: line {header_line}: {header.count(delimiter) + 1} columns; "
                        f"a card file has at most {MAX_COLUMNS}")
    cells = header.split(delimiter)
    if all(_is_float(cell.replace(",", ".")) for cell in cells):
        raise CardError(f"{source}: line {header_line}: numbers where the header should be; "
                        f"the first line names the columns, e.g. position_in,load_lbf")
    used = _header(cells, header_line, source, default_units, mapping)
    rows = [lines[i] for i in kept[1:]]
    numbers = np.array(kept[1:], dtype=int) + 1
    if len(rows) > MAX_POINTS:
        raise CardError(f"{source}: {len(rows)} points; a card has at most {MAX_POINTS}")
    widths = np.fromiter(map(str.count, rows, repeat(delimiter)), dtype=int, count=len(rows)) + 1
    wrong = widths != len(cells)
    if wrong.any():
        i = int(np.argmax(wrong))
        hint = ("; a decimal comma or thousands separator in a comma-separated file?"
                if delimiter == "," and widths[i] > len(cells) else "")
        raise CardError(f"{source}: line {numbers[i]}: {widths[i]} values, the header has {len(cells)}{hint}")
    flat = delimiter.join(rows).split(delimiter) if rows else []
    if '"' in text:
        flat = [cell.strip().strip('"') for cell in flat]
    columns = {kind: flat[j::len(cells)] for kind, (j, _, _) in used.items()}
    if delimiter != ",":
        columns = _decimal_commas(columns, used, numbers, source, _DELIMITER_NAMES[delimiter])
    values = {kind: _Column(_bounded(_numbers(columns[kind], kind, numbers, source) * factor, kind, numbers,
                                     columns[kind], unit, source), unit, factor)
              for kind, (_, unit, factor) in used.items()}
    if len(rows) < MIN_POINTS:
        raise CardError(f"{source}: {len(rows)} points; a card needs at least {MIN_POINTS}")
    return values, numbers


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


def _time_order(time: np.ndarray, lines: np.ndarray, column: _Column, source: str) -> bool:
    """True if the rows are in reverse time order; refuse repeated or unordered time stamps."""
    steps = np.diff(time)
    if np.any(steps == 0):
        i = int(np.argmax(steps == 0)) + 1
        raise CardError(f"{source}: line {lines[i]}: time {time[i] / column.factor:.6g} {column.unit} repeats "
                        f"line {lines[i - 1]}; duplicated time stamps")
    if np.all(steps < 0):
        return True
    if np.any(steps < 0):
        raise CardError(f"{source}: line {lines[int(np.argmax(steps < 0)) + 1]}: time does not increase")
    return False


def read(text: str, source: str, default_units: str | None, mapping: dict[str, str] | None) -> RawCard:
    """The raw card of a delimited text (see :func:`pumpjack_cli.readers.cards.read_card`).

    Rows in reverse time order are turned back (one warning); a position card closed by
    repeating its first sample loses the repeat.
    """
    columns, lines = _parse(text, source, default_units, mapping)
    units = {kind: (column.unit, column.factor) for kind, column in columns.items()}
    load = columns["load"].values
    if "crank_angle" in columns:
        return RawCard(source, load, lines, crank_angle=columns["crank_angle"].values, column_units=units)
    time = columns["time"].values if "time" in columns else None
    position = columns["position"].values
    backwards = time is not None and _time_order(time, lines, columns["time"], source)
    if np.allclose(position[0], position[-1]) and np.allclose(load[0], load[-1]):
        position, load, lines = position[:-1], load[:-1], lines[:-1]  # a closed card repeats its first point
        time = None if time is None else time[:-1]
    if backwards:
        position, load, time, lines = position[::-1], load[::-1], time[::-1], lines[::-1]
    warnings = (f"{source}: rows listed in reverse time order; read in time order",) if backwards else ()
    return RawCard(source, load, lines, time, position, column_units=units, reversed=backwards, warnings=warnings)
