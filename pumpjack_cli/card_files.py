"""Reading dynamometer-card files (delimited text) onto the crank-angle axis of a unit.

Three layouts: ``crank_angle, load``; ``position, load`` (each point on the branch of
its direction of travel, the loop's orientation from the sign of its work);
``time, position, load`` (the time stamps are the speed: the crank rotation is fitted
to the positions through the unit's exact kinematics). Units, delimiters, decimal
commas, encodings, index columns, column mapping, limits and every refusal are
specified in ``docs/cards.md``; every refusal is a one-line
:class:`~pumpjack_cli.errors.CardError` naming the file (``<stdin>`` for ``-``), the
line and the column.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from itertools import repeat
from pathlib import Path
from typing import IO

import numpy as np

from .core.beam.card import (Card, RotationFit, card_from_angles, crank_angle_from_position, fit_rotation,
                             largest_gap, loop_work, upstroke_points)
from .core.beam.geometry import CLOCKWISE, Linkage
from .errors import CardError
from .quantities import FOOT, INCH, KILOGRAM_FORCE, POUND_FORCE, UNIT_SPELLINGS
from .text_input import display_name, read_text

__all__ = ["CardError", "CardReading", "check_speed", "parse_card_columns", "read_card"]

#: Relative stroke mismatch refused, and warned about (the card is scaled to the unit's stroke).
STROKE_ERROR = 0.05
STROKE_WARNING = 0.02
#: RMS position residual of the time fit, relative to the stroke, refused and warned about.
FIT_ERROR = 0.10
FIT_WARNING = 0.02
#: Harmonics of the crank-speed variation fitted to time stamps (when the card has at
#: least four samples per parameter, else uniform rotation).
HARMONICS = 2
#: The other rotation direction "fits clearly better" when its uniform-rotation
#: residual is below half of the unit's and the unit's is above this fraction of the stroke.
ROTATION_EVIDENCE = 0.002
#: --spm and the card's time stamps may differ by this fraction; the card's speed wins.
SPEED_TOLERANCE = 0.02
#: A loop whose work is below this fraction of (stroke range x load range) has no
#: clear orientation and is read as listed.
WORK_TOLERANCE = 1e-3
#: The largest crank rotation without a sample that still counts as a whole cycle [rad]
#: (or two mean sample spacings, if larger).
MAX_GAP = math.radians(30.0)
MIN_POINTS = 8
MAX_POINTS = 100_000
#: Lines of any kind (points, comments, blanks), counted before the text is split.
MAX_LINES = 2 * MAX_POINTS
MAX_COLUMNS = 64
MAX_BYTES = 10_000_000
#: Largest magnitude of a load [N] and a position [m] in a card, far beyond any pumping
#: unit (the largest API Spec 11E structure rating is below 0.3 MN, the longest stroke
#: below 10 m): a larger number is a wrong unit or a corrupt file, refused by its line
#: before it can overflow the computation.
LIMITS = {"load": (1e7, "10 MN"), "position": (1e3, "1 km")}

#: Units of each column's dimension: lower-case spelling -> factor to SI (and the spellings of
#: :data:`~pumpjack_cli.quantities.UNIT_SPELLINGS`, the Cyrillic abbreviations among them).
_UNITS = {
    "angle": {"deg": math.pi / 180.0, "degree": math.pi / 180.0, "degrees": math.pi / 180.0, "°": math.pi / 180.0,
              "rad": 1.0},
    "time": {"s": 1.0, "sec": 1.0, "ms": 1e-3, "min": 60.0, "с": 1.0, "мс": 1e-3, "мин": 60.0},
    "length": {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "in": INCH, "ft": FOOT},
    "force": {"n": 1.0, "kn": 1e3, "lb": POUND_FORCE, "lbs": POUND_FORCE, "lbf": POUND_FORCE,
              "klb": 1e3 * POUND_FORCE, "klbs": 1e3 * POUND_FORCE, "kip": 1e3 * POUND_FORCE,
              "kips": 1e3 * POUND_FORCE, "klbf": 1e3 * POUND_FORCE, "kgf": KILOGRAM_FORCE, "tf": 1e3 * KILOGRAM_FORCE},
}
#: Column kinds: accepted names and dimension.
_KINDS = {
    "crank_angle": (("crank_angle", "angle", "theta"), "angle"),
    "time": (("time", "t"), "time"),
    "position": (("position", "displacement", "pos"), "length"),
    "load": (("load", "force", "prl", "polished_rod_load", "rod_load"), "force"),
}
_KIND_OF_NAME = {name: kind for kind, (names, _) in _KINDS.items() for name in names}
#: Index or sample-number columns, ignored ('#' is read as 'no'); so are unnamed columns.
_INDEX_NAMES = {"index", "idx", "i", "n", "no", "nr", "num", "number", "sample", "sample_no", "sample_number",
                "point", "point_no", "point_number", "pt"}
_DEFAULT_UNITS = {
    "si": {"angle": "deg", "time": "s", "length": "m", "force": "n"},
    "field": {"angle": "deg", "time": "s", "length": "in", "force": "lbf"},
}
_LAYOUTS = ({"crank_angle", "load"}, {"position", "load"}, {"time", "position", "load"})
_LAYOUT_TEXT = "a card has crank_angle and load, position and load, or time, position and load"
_KNOWN_TEXT = ("known: crank_angle/angle/theta, time/t, position/displacement/pos, load/force/prl/polished_rod_load/rod_load, "
               "index columns (index, sample, n, #, point); map others with --card-columns position=...,load=...[,time=...]")
_DELIMITERS = ("\t", ";", ",")
_DELIMITER_NAMES = {"\t": "tab", ";": "semicolon", ",": "comma"}
_UNIT_AT_END = re.compile(r"^(.*?)\s*(?:[\[(]\s*([^\[\]()]*?)\s*[\])]|,\s*([^,]+?))\s*$")
_ROTATION_NAMES = {CLOCKWISE: "clockwise", -CLOCKWISE: "counterclockwise"}


@dataclass(frozen=True)
class CardReading:
    """A card on the crank-angle axis, the samples it came from, and what the reader noticed.

    ``load`` [N], ``crank_angle`` [rad] (fitted or mapped, in [0, 2 pi)), ``position``
    [m] and ``time`` [s] are per sample, in SI, in cycle order (reversed when the file
    was), a repeated closing sample dropped; ``position`` as read (not shifted or
    scaled), None on a crank-angle card; ``time`` None without time stamps. ``speed``
    is the mean crank speed omega [rad/s] fitted to the time stamps (the card's pumping
    speed), ``crank_speed`` [rad/s] the fitted speed at each sample, ``fit_rms`` the RMS
    position residual of that fit [m] and ``fit_rms_relative`` the same over the unit's
    stroke [-]; all four None without time stamps. ``reversed`` is True when the rows
    were read in reverse (one warning says so).
    """

    card: Card
    source: str
    warnings: tuple[str, ...]
    load: np.ndarray
    crank_angle: np.ndarray
    position: np.ndarray | None = None
    time: np.ndarray | None = None
    speed: float | None = None
    crank_speed: np.ndarray | None = None
    fit_rms: float | None = None
    fit_rms_relative: float | None = None
    reversed: bool = False

    @property
    def strokes_per_minute(self) -> float | None:
        """The card's pumping speed [1/min], None without time stamps."""
        return None if self.speed is None else self.speed * 30.0 / math.pi


@dataclass(frozen=True)
class _Column:
    values: np.ndarray
    unit: str
    factor: float


@dataclass(frozen=True)
class _Table:
    columns: dict[str, _Column]
    lines: np.ndarray


def _show(text: str, limit: int = 40) -> str:
    """repr of a cell or name for a message, cut to ``limit`` characters."""
    return repr(text if len(text) <= limit else text[:limit] + "...")


def _is_content(line: str) -> bool:
    """Neither blank nor a comment; '#' directly followed by a delimiter is the index column '#'."""
    text = line.strip()
    return bool(text) and (not text.startswith("#") or text[1:2] in _DELIMITERS)


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


def _unit(unit: str | None, kind: str, default_units: str | None, where: str) -> tuple[str, float]:
    """Unit label and factor to SI of a column of ``kind``; ``where`` names it in a message.
    A column whose header names no unit takes ``default_units``' and is refused without them."""
    dimension = _KINDS[kind][1]
    if unit is None and default_units is None:
        si, field = _DEFAULT_UNITS["si"][dimension].replace("n", "N"), _DEFAULT_UNITS["field"][dimension]
        raise CardError(f"{where} names no unit: write it in the header ({kind}_{si}, {kind.capitalize()} ({field})) "
                        f"or give --card-units si or field")
    key = _DEFAULT_UNITS[default_units][dimension] if unit is None else unit.strip().lower().rstrip(".")
    key = UNIT_SPELLINGS.get(key, key)
    if key not in _UNITS[dimension]:
        raise CardError(f"{where} has unit {unit!r}, not a unit of {dimension} ({', '.join(_UNITS[dimension])})")
    return (key if unit is None else unit.strip()), _UNITS[dimension][key]


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
        unit = suffix if unit is None and stem and suffix.lower() in _UNITS[_KINDS[kind][1]] else unit
    elif unit is None and stem.lower() in _KIND_OF_NAME:
        kind, unit = _KIND_OF_NAME[stem.lower()], suffix
    elif key.lower() in _KIND_OF_NAME:
        kind = _KIND_OF_NAME[key.lower()]
    elif key.lower() in _INDEX_NAMES or not key:
        return None
    else:
        raise CardError(f"{prefix}: unknown column {_show(cell.strip())} (column {column}); {_KNOWN_TEXT}")
    return (kind, *_unit(unit, kind, default_units, f"{prefix}: column {column} {_show(cell.strip())}"))


def _checked_columns(pairs: Iterable[tuple[str, str]]) -> dict[str, str]:
    """A column mapping kind -> header text, validated."""
    mapping = {}
    for kind, header in pairs:
        key = str(kind).strip().lower()
        if key not in _KINDS:
            raise CardError(f"--card-columns: unknown column kind {_show(str(kind))}; use {', '.join(_KINDS)}")
        if key in mapping:
            raise CardError(f"--card-columns: {key} given twice")
        if not isinstance(header, str) or not header.strip():
            raise CardError(f"--card-columns: {key} needs a header name")
        mapping[key] = header.strip().strip('"').strip()
    if set(mapping) not in _LAYOUTS:
        raise CardError(f"--card-columns: {', '.join(mapping) or 'nothing'} given; {_LAYOUT_TEXT}")
    return mapping


def parse_card_columns(text: str) -> dict[str, str]:
    """The mapping of ``--card-columns position=Pos (in),load=PRL[,time=Time]``.

    Pairs ``kind=header`` separated by commas; kinds position, load, time or
    crank_angle; headers as written in the file (case and surrounding spaces
    ignored; a header holding a comma or '=' cannot be mapped).

    >>> parse_card_columns("position=Pos (in), load=PRL, time=Time")
    {'position': 'Pos (in)', 'load': 'PRL', 'time': 'Time'}
    """
    pairs = [part.partition("=") for part in text.split(",")]
    for kind, equals, _ in pairs:
        if not equals:
            raise CardError(f"--card-columns: {_show(kind.strip())} is not kind=header "
                            f"(e.g. position=Pos (in),load=PRL,time=Time)")
    return _checked_columns((kind, header) for kind, _, header in pairs)


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
                                f"the header has {', '.join(_show(c.strip()) for c in cells[:12])}")
            found[kind] = [(matches[0], *_column(cells[matches[0]], default_units, prefix, matches[0] + 1, kind)[1:])]
    kinds = [kind for kind, where in found.items() for _ in where]
    if len(set(kinds)) != len(kinds) or set(kinds) not in _LAYOUTS:
        raise CardError(f"{prefix}: columns {', '.join(kinds) or 'none'}; {_LAYOUT_TEXT}")
    return {kind: where[0] for kind, where in found.items()}


def _numbers(cells: list[str], kind: str, lines: np.ndarray, source: str) -> np.ndarray:
    """One column's cells as finite floats, or a one-line error at the first culprit."""
    try:
        values = np.fromiter(map(float, cells), dtype=float, count=len(cells))
    except ValueError:
        i = next(i for i, cell in enumerate(cells) if not _is_float(cell))
        what = "is empty" if not cells[i].strip() else f"{_show(cells[i].strip())} is not a number"
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


def _parse(text: str, source: str, default_units: str | None, mapping: dict[str, str] | None) -> _Table:
    """The used columns of a card's text, in SI, with the line number of each row."""
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
        raise CardError(f"{source}: line {header_line}: no comma, semicolon or tab in the header {_show(header.strip())}; "
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
    return _Table(values, numbers)


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
        raise CardError(f"{source}: line {numbers[i1]}: {k1} {_show(columns[k1][i1].strip())} (column {used[k1][0] + 1}) "
                        f"has a comma but line {numbers[i2]}: {k2} {_show(columns[k2][i2].strip())} a point; "
                        f"cannot tell the decimal mark in this {delimiter}-separated file (thousands separators?)")
    return {kind: [cell.replace(",", ".") for cell in cells] for kind, cells in columns.items()}


def read_card(path: Path | str, linkage: Linkage, default_units: str | None = None, *,
              columns: Mapping[str, str] | None = None, stream: IO | None = None) -> CardReading:
    """Read a card file and put it on the crank-angle axis of ``linkage``.

    Parameters
    ----------
    path : pathlib.Path or str
        The card file; ``"-"`` reads ``stream`` (standard input by default), named
        ``<stdin>`` in messages.
    linkage : Linkage
        The unit the card was measured on.
    default_units : str, optional
        Units of columns whose header names none: ``"si"`` (m, N, s, deg) or
        ``"field"`` (in, lbf, s, deg); without them such a column is refused.
    columns : mapping, optional
        Kind -> header text (:func:`parse_card_columns`); the mapped columns are
        used and every other column is ignored.
    stream : file object, optional
        Text or binary stream read when ``path`` is ``"-"``.

    Returns
    -------
    CardReading
        The card on the crank-angle axis and the samples, speed and fit behind it.

    References
    ----------
    [Takacs2016], [SK8Rotation2013] (see :mod:`pumpjack_cli.core.beam.card`).
    """
    if default_units is not None and default_units not in _DEFAULT_UNITS:
        raise CardError(f"card units {default_units!r}: use {' or '.join(_DEFAULT_UNITS)}")
    mapping = None if columns is None else _checked_columns(columns.items())
    source = display_name(path)
    table = _parse(read_text(path, MAX_BYTES, "card file", CardError, stream), source, default_units, mapping)
    load = table.columns["load"].values
    if "crank_angle" in table.columns:
        theta = table.columns["crank_angle"].values % (2.0 * math.pi)
        if np.all(theta == theta[0]):
            raise CardError(f"{source}: every crank angle is {math.degrees(theta[0]):.6g} deg; a card covers a whole cycle")
        _check_coverage(theta, source, "crank angles")
        return CardReading(card_from_angles(theta, load), source, (), load, theta)
    return _position_reading(table, linkage, source)


def _check_coverage(theta: np.ndarray, source: str, what: str) -> None:
    gap = largest_gap(theta)
    if gap > max(MAX_GAP, 4.0 * math.pi / theta.size):
        raise CardError(f"{source}: the {what} leave {math.degrees(gap):.0f} deg of the crank's revolution without "
                        f"a sample; a card covers a whole cycle")


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


def _position_reading(table: _Table, linkage: Linkage, source: str) -> CardReading:
    """A position card (with or without time stamps) on the crank-angle axis."""
    columns, lines = table.columns, table.lines
    time = columns["time"].values if "time" in columns else None
    position, load = columns["position"].values, columns["load"].values
    warnings = []
    backwards = time is not None and _time_order(time, lines, columns["time"], source)
    if backwards:
        warnings.append(f"{source}: rows listed in reverse time order; read in time order")
    if np.allclose(position[0], position[-1]) and np.allclose(load[0], load[-1]):
        position, load, lines = position[:-1], load[:-1], lines[:-1]  # a closed card repeats its first point
        time = None if time is None else time[:-1]
    if backwards:
        position, load, time, lines = position[::-1], load[::-1], time[::-1], lines[::-1]
    unit, factor = columns["position"].unit, columns["position"].factor
    steps = np.diff(position)
    if np.all(steps == 0):
        raise CardError(f"{source}: the polished rod does not move (every position is {position[0] / factor:.6g} {unit}); "
                        f"a card covers a whole cycle")
    if np.all(steps >= 0) or np.all(steps <= 0):
        raise CardError(f"{source}: the polished rod moves only {'up' if steps.sum() > 0 else 'down'}; "
                        f"a card covers a whole cycle")
    stroke = linkage.dead_positions().stroke
    card_stroke = float(position.max() - position.min())
    mismatch = card_stroke / stroke - 1.0
    message = (f"{source}: card stroke {card_stroke / factor:.4g} {unit} differs from the unit's exact stroke "
               f"{stroke / factor:.4g} {unit} by {100 * mismatch:+.1f} %")
    if abs(mismatch) > STROKE_ERROR:
        raise CardError(f"{message}; wrong unit, crank hole or position units?")
    if abs(mismatch) > STROKE_WARNING:
        warnings.append(f"{message}; positions scaled to the unit's stroke")
    work = loop_work(position, load)
    if work < -WORK_TOLERANCE * card_stroke * float(np.ptp(load)):
        if time is not None:
            raise CardError(f"{source}: in time order the rods do {-work:.4g} J of work on the unit per cycle; a pumping "
                            f"unit does positive work: rows reversed against their time stamps, or a sign inverted?")
        backwards = True
        position, load, lines = position[::-1], load[::-1], lines[::-1]
        warnings.append(f"{source}: listed in reverse (the rods would do {-work:.4g} J of work on the unit per cycle; "
                        f"a pumping unit lifts them on the high load); read in reverse order")
    scaled = (position - position.min()) * (stroke / card_stroke)
    if time is None:
        theta = crank_angle_from_position(linkage, scaled, upstroke_points(scaled))
        return CardReading(card_from_angles(theta, load), source, tuple(warnings), load, theta, position,
                           reversed=backwards)
    fit, notes = _rotation(linkage, time, scaled, columns["position"], source)
    theta = fit.crank_angle % (2.0 * math.pi)
    _check_coverage(theta, source, f"samples at the fitted {fit.speed * 30.0 / math.pi:.4g} strokes/min")
    return CardReading(card_from_angles(theta, load), source, tuple(warnings + notes), load, theta, position, time,
                       fit.speed, fit.crank_speed, fit.rms, fit.rms / stroke, backwards)


def _rotation(linkage: Linkage, time: np.ndarray, scaled: np.ndarray, column: _Column,
              source: str) -> tuple[RotationFit, list[str]]:
    """The time fit and its warnings; the other rotation direction is tried only when the uniform fit is not near exact."""
    fit = fit_rotation(linkage, time, scaled, HARMONICS if time.size >= 4 * (2 + 2 * HARMONICS) else 0)
    stroke = linkage.dead_positions().stroke
    relative = fit.rms / stroke
    residual = f"RMS position error {fit.rms / column.factor:.3g} {column.unit}, {100 * relative:.2g} % of the stroke"
    if relative > FIT_ERROR:
        raise CardError(f"{source}: the time stamps do not fit this unit's motion ({residual}); "
                        f"wrong columns or a card from another unit?")
    if np.min(fit.crank_speed) <= 0.0:
        raise CardError(f"{source}: the crank angles fitted to the time stamps turn backwards at times "
                        f"(crank speed {np.min(fit.crank_speed):.3g} rad/s); wrong columns or a card from another unit?")
    if fit.uniform_rms > ROTATION_EVIDENCE * stroke:
        other = fit_rotation(dataclasses.replace(linkage, rotation=-linkage.rotation), time, scaled)
        if other.uniform_rms < 0.5 * fit.uniform_rms:
            own_name, other_name = _ROTATION_NAMES[linkage.rotation], _ROTATION_NAMES[-linkage.rotation]
            return fit, [f"{source}: at a steady crank speed the time stamps fit {other_name} rotation better than "
                         f"the unit's {own_name} (RMS position error {100 * other.uniform_rms / stroke:.2g} % of the "
                         f"stroke against {100 * fit.uniform_rms / stroke:.2g} %); check the unit's rotation"]
    if relative > FIT_WARNING:
        return fit, [f"{source}: the time stamps fit this unit's motion only roughly ({residual}); "
                     f"the fitted crank angles are used"]
    return fit, []


def check_speed(card_speed: float | None, spm_option: float | None, source: str = "the card") -> float | None:
    """The crank speed to use [rad/s]: the card's, checked against an ``--spm`` given too.

    Parameters
    ----------
    card_speed : float or None
        Crank speed fitted to the card's time stamps [rad/s] (``CardReading.speed``).
    spm_option : float or None
        Crank speed given on the command line [rad/s] (``--spm`` converted).
    source : str
        The card's name for the message.

    Returns
    -------
    float or None
        ``card_speed`` when there is one (the time stamps are the measurement),
        otherwise ``spm_option``.

    Raises
    ------
    CardError
        When both are given and differ by more than :data:`SPEED_TOLERANCE` (2 %);
        the message prints both in strokes per minute.

    >>> check_speed(0.6283, 0.63)            # 6.00 and 6.02 strokes/min: the card wins
    0.6283
    >>> check_speed(None, 0.63)
    0.63
    """
    for name, value in (("card speed", card_speed), ("--spm", spm_option)):
        if value is not None and not (math.isfinite(value) and value > 0):
            raise CardError(f"{name} {value!r}: not a positive speed")
    if card_speed is None or spm_option is None:
        return spm_option if card_speed is None else card_speed
    mismatch = spm_option / card_speed - 1.0
    if abs(mismatch) > SPEED_TOLERANCE:
        raise CardError(f"--spm {spm_option * 30.0 / math.pi:.4g} disagrees with the time stamps of {source} "
                        f"({card_speed * 30.0 / math.pi:.4g} strokes/min) by {100 * mismatch:+.1f} %; "
                        f"drop --spm or check the card")
    return card_speed
