"""Reading dynamometer-card files (CSV) onto the crank-angle axis of a unit.

Accepted columns (any order, names case-insensitive, ``#`` lines are comments):

* ``crank_angle`` and ``load`` — crank angle in this package's convention (from 12
  o'clock in the direction of rotation);
* ``position`` and ``load`` — polished-rod position, in the order measured;
* ``time``, ``position`` and ``load`` — the same with a time stamp, which must increase.

Units come from the header, as a suffix or in brackets: ``position_in``,
``load_lbf``, ``load [kN]``, ``crank_angle (deg)``, ``time_s``; columns without a
unit take those of ``default_units`` (``si``: m, N, s, deg; ``field``: in, lbf, s, deg).
Also accepted as names: angle/theta, displacement/pos, force/prl, t.

A card of positions is shifted so that its lowest point is the bottom of the stroke
and scaled to the unit's exact stroke; a card whose stroke differs from the unit's by
more than :data:`STROKE_ERROR` is rejected, by more than :data:`STROKE_WARNING`
warned about.
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .core.beam.card import Card, card_from_angles, crank_angle_from_position, upstroke_points
from .core.beam.geometry import Linkage, dead_positions
from .errors import PumpjackError
from .quantities import INPUT_UNITS

STROKE_ERROR = 0.05
STROKE_WARNING = 0.02
MIN_POINTS = 8

#: Column kinds: accepted names and dimension.
_COLUMNS = {
    "crank_angle": (("crank_angle", "angle", "theta"), "angle"),
    "time": (("time", "t"), "time"),
    "position": (("position", "displacement", "pos"), "length"),
    "load": (("load", "force", "prl", "polished_rod_load"), "force"),
}
_TIME_UNITS = {"s": 1.0, "min": 60.0}
_DEFAULT_UNITS = {
    "si": {"angle": "deg", "time": "s", "length": "m", "force": "n"},
    "field": {"angle": "deg", "time": "s", "length": "in", "force": "lbf"},
}
_LAYOUTS = ({"crank_angle", "load"}, {"position", "load"}, {"time", "position", "load"})


class CardError(PumpjackError):
    """A card file that cannot be read or does not fit the unit."""


@dataclass(frozen=True)
class CardReading:
    """A card on the crank-angle axis plus what the reader noticed."""

    card: Card
    source: str
    warnings: tuple[str, ...]


def _factors(dimension: str) -> dict[str, float]:
    return _TIME_UNITS if dimension == "time" else INPUT_UNITS[dimension]


def _parse_header(cell: str, source: str, default_units: str) -> tuple[str, float]:
    """Column kind and factor to SI from one header cell."""
    text = cell.strip().lower()
    bracket = re.match(r"^(.*?)\s*[\[(]\s*(.+?)\s*[\])]$", text)
    name, unit = (bracket.group(1), bracket.group(2)) if bracket else (text, None)
    name = name.replace(" ", "_").replace("-", "_")
    for kind, (names, dimension) in _COLUMNS.items():
        factors = _factors(dimension)
        candidates = [(name, unit)]
        if unit is None and "_" in name:
            stem, suffix = name.rsplit("_", 1)
            candidates.insert(0, (stem, suffix))
        for stem, suffix in candidates:
            if stem not in names:
                continue
            if suffix is None:
                return kind, factors[_DEFAULT_UNITS[default_units][dimension]]
            key = suffix.replace("·", "*").replace(".", "*")
            if key not in factors:
                raise CardError(
                    f"{source}: header: column {cell.strip()!r} has unit {suffix!r}, "
                    f"not a unit of {dimension} ({', '.join(factors)})"
                )
            return kind, factors[key]
    raise CardError(
        f"{source}: header: unknown column {cell.strip()!r}; use crank_angle and load, position and load, "
        f"or time, position and load"
    )


def _read_rows(path: Path, default_units: str) -> dict[str, np.ndarray]:
    source = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise CardError(f"{source}: cannot read: {exc.strerror}") from None
    rows = [(number, row) for number, row in enumerate(csv.reader(text.splitlines()), start=1)
            if row and not row[0].lstrip().startswith("#")]
    if not rows:
        raise CardError(f"{source}: empty card")
    header_line, header = rows[0]
    kinds = [_parse_header(cell, source, default_units) for cell in header]
    names = [kind for kind, _ in kinds]
    if len(set(names)) != len(names) or set(names) not in _LAYOUTS:
        raise CardError(
            f"{source}: line {header_line}: columns {', '.join(names)}; a card has crank_angle and load, "
            f"position and load, or time, position and load"
        )
    values = np.empty((len(rows) - 1, len(names)))
    for i, (number, row) in enumerate(rows[1:]):
        if len(row) != len(names):
            raise CardError(f"{source}: line {number}: {len(row)} values, the header has {len(names)}")
        for j, cell in enumerate(row):
            try:
                value = float(cell)
            except ValueError:
                raise CardError(f"{source}: line {number}: {names[j]} {cell.strip()!r} is not a number") from None
            if not math.isfinite(value):
                raise CardError(f"{source}: line {number}: {names[j]} is {cell.strip()}, not a finite number")
            values[i, j] = value * kinds[j][1]
    if values.shape[0] < MIN_POINTS:
        raise CardError(f"{source}: {values.shape[0]} points; a card needs at least {MIN_POINTS}")
    columns = {name: values[:, j] for j, name in enumerate(names)}
    if "time" in columns:
        steps = np.diff(columns["time"])
        if np.any(steps <= 0):
            line = rows[1 + int(np.argmax(steps <= 0)) + 1][0]
            raise CardError(f"{source}: line {line}: time does not increase")
    return columns


def read_card(path: Path, linkage: Linkage, default_units: str = "si") -> CardReading:
    """Read a card file and put it on the crank-angle axis of ``linkage``."""
    source = str(path)
    columns = _read_rows(path, default_units)
    load = columns["load"]
    if "crank_angle" in columns:
        return CardReading(card_from_angles(columns["crank_angle"], load), source, ())
    position = columns["position"]
    if np.allclose(position[0], position[-1]) and np.allclose(load[0], load[-1]):
        position, load = position[:-1], load[:-1]  # a closed card repeats its first point
    steps = np.diff(position)
    if np.all(steps >= 0) or np.all(steps <= 0):
        raise CardError(f"{source}: the polished rod moves only {'up' if steps.sum() > 0 else 'down'}; "
                        f"a card covers a whole cycle")
    upstroke = upstroke_points(position)
    dead = dead_positions(linkage)
    stroke = linkage.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom)
    card_stroke = float(position.max() - position.min())
    mismatch = card_stroke / stroke - 1.0
    message = (f"{source}: card stroke {card_stroke:.4g} m differs from the unit's exact stroke "
               f"{stroke:.4g} m by {100 * mismatch:+.1f} %")
    if abs(mismatch) > STROKE_ERROR:
        raise CardError(f"{message}; wrong unit, crank hole or position units?")
    warnings = (f"{message}; positions scaled to the unit's stroke",) if abs(mismatch) > STROKE_WARNING else ()
    scaled = (position - position.min()) * (stroke / card_stroke)
    theta = crank_angle_from_position(linkage, scaled, upstroke)
    return CardReading(card_from_angles(theta, load), source, warnings)
