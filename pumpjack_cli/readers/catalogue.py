"""An operator's unit catalogue: a CSV of one row per unit and crank hole, read into unit-file tables.

Each row becomes the table a unit file parses to (``name``, ``designation``,
``[geometry]`` with ``class``, the API 11E letters and ``rotation``, ``[counterbalance]``,
``[rating]``, ``sources``), its values written with the unit of their column's header
(``A_in`` = 72 gives ``A = "72 in"``); nothing physical is validated here (the unit-file
schema does that, :mod:`pumpjack_cli.config.catalogue`). The columns are :data:`COLUMNS`
(documented in ``docs/catalogue.md``); the file is bounded like a unit file, comment
lines start with ``#``, a cell holds no line break, and every refusal is one line naming
the file, the line and the column. A unit is named ``DESIGNATION/HOLE``
(:meth:`Catalogue.find`), the designation compared as :func:`~.unit_files.unit_source`
compares the bundled units' names (case-insensitive, a decimal comma read as a point).
"""

from __future__ import annotations

import csv
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any

from ..errors import ConfigError
from ..quantities import parse_quantity
from ..text_input import display_name, read_text
from .unit_files import HOLE_SPEC, designation_key

#: Largest catalogue [bytes]: some 100 000 rows of about 150 characters.
MAX_BYTES = 16 << 20


@dataclass(frozen=True)
class Field:
    """A catalogue column: the dimension of its numbers (None: text), where its value goes in
    the unit file's table (None: not there) and what it means (for messages)."""

    dimension: str | None
    key: tuple[str, ...] | None
    meaning: str


#: The columns, by the name a header gives them (a number's unit follows it: ``A_in``, ``B_kN``).
COLUMNS: dict[str, Field] = {
    "designation": Field(None, ("designation",), "API 11E or GOST 5866-76 designation"),
    "crank_hole": Field(None, None, "crank hole, 1 for the longest stroke"),
    "class": Field(None, ("geometry", "class"), "kind of unit (default: from the designation's letters)"),
    "rotation": Field(None, ("geometry", "rotation"), "crank rotation seen with the well to the right"),
    "A": Field("length", ("geometry", "A"), "centre bearing to horsehead arc"),
    "C": Field("length", ("geometry", "C"), "centre bearing to equalizer bearing"),
    "I": Field("length", ("geometry", "I"), "centre bearing to crank shaft, horizontal"),
    "K": Field("length", ("geometry", "K"), "centre bearing to crank shaft, straight"),
    "H": Field("length", ("geometry", "H"), "centre bearing above the ground"),
    "G": Field("length", ("geometry", "G"), "crank shaft above the ground"),
    "P": Field("length", ("geometry", "P"), "pitman, crank pin to equalizer bearing"),
    "R": Field("length", ("geometry", "R"), "crank radius of the hole"),
    "stroke": Field("length", None, "published polished-rod stroke of the hole"),
    "B": Field("force", ("counterbalance", "structural_unbalance"), "structural unbalance"),
    "tau": Field("angle", ("counterbalance", "phase"), "crank offset angle (a kind may keep it in [geometry])"),
    "beam_counterweight": Field("force", ("geometry", "beam_counterweight"), "beam-balanced: the beam counterweight"),
    "beam_counterweight_arm": Field("length", ("geometry", "beam_counterweight_arm"),
                                    "beam-balanced: the counterweight's distance behind the centre bearing"),
    "air_piston_area": Field("area", ("geometry", "air_cylinder", "piston_area"), "air-balanced: piston area"),
    "air_piston_diameter": Field("length", ("geometry", "air_cylinder", "piston_diameter"),
                                 "air-balanced: piston diameter"),
    "air_bottom_volume": Field("volume", ("geometry", "air_cylinder", "bottom_volume"),
                               "air-balanced: gas volume at the bottom of the stroke"),
    "air_lever": Field("length", ("geometry", "air_cylinder", "lever"),
                       "air-balanced: the piston rod's pin on the beam, from the centre bearing"),
    "air_pressure": Field("pressure", ("geometry", "air_cylinder", "pressure"), "air-balanced: gauge pressure"),
    "air_pressure_position": Field("length", ("geometry", "air_cylinder", "pressure_position"),
                                   "air-balanced: polished-rod position of the stated pressure"),
    "gearbox_torque": Field("torque", ("rating", "gearbox_torque"), "gearbox torque rating"),
    "structure_load": Field("force", ("rating", "structure_load"), "structure load rating"),
    "max_stroke": Field("length", ("rating", "max_stroke"), "maximum stroke rating"),
    "source": Field(None, ("sources",), "where the row's data come from"),
}
#: Columns every catalogue has (and the vertical offset: K, or H and G).
REQUIRED = ("designation", "crank_hole", "rotation", "A", "C", "I", "P", "R")
HEIGHTS = (("K",), ("H", "G"))
_BY_FOLDED = {name.casefold(): name for name in COLUMNS}
#: A unit to show in a header that lacks one, per dimension.
_EXAMPLE_UNITS = {"length": "in", "force": "lbf", "angle": "deg", "torque": "lbf_in", "area": "in2",
                  "volume": "ft3", "pressure": "psi"}
_NUMBER = re.compile(r"^[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?$")
_WHOLE = re.compile(r"^[0-9]+$")
@dataclass(frozen=True)
class CatalogueRow:
    """One unit and crank hole of a catalogue: its file and line, designation and hole, the unit
    file's table, the published stroke [m] (None if not given) and the header of the column of
    each key of the table (``"geometry.A"`` -> ``"A_in"``)."""

    source: str
    line: int
    designation: str
    hole: int
    table: dict[str, Any]
    stroke: float | None
    columns: dict[str, str]

    @property
    def name(self) -> str:
        """The name a command gives the unit: ``DESIGNATION/HOLE``."""
        return f"{self.designation}/{self.hole}"

    @property
    def place(self) -> str:
        """The file and line, as messages start."""
        return f"{self.source}: line {self.line}"


@dataclass(frozen=True)
class Catalogue:
    """The rows of a catalogue file, in the file's order."""

    source: str
    rows: tuple[CatalogueRow, ...]

    @cached_property
    def _holes(self) -> dict[str, list[CatalogueRow]]:
        """The rows of each designation (:func:`designation_key`), in the file's order."""
        found: dict[str, list[CatalogueRow]] = {}
        for row in self.rows:
            found.setdefault(designation_key(row.designation), []).append(row)
        return found

    def find(self, spec: str) -> CatalogueRow | None:
        """The row ``spec`` names (``DESIGNATION/HOLE``, or a designation with one hole), None when
        the catalogue has no such designation; a ConfigError for a hole it does not have or a
        designation of several holes without one."""
        found = HOLE_SPEC.match(spec.strip())
        designation, hole = (found["designation"], int(found["hole"])) if found else (spec, None)
        rows = self._holes.get(designation_key(designation))
        if rows is None:
            return None
        holes = ", ".join(str(row.hole) for row in rows)
        if hole is None and len(rows) > 1:
            raise ConfigError(f"unit {spec!r}: {self.source} has crank holes {holes} of {rows[0].designation}; "
                              f"name one as {rows[0].designation}/HOLE")
        chosen = [row for row in rows if hole is None or row.hole == hole]
        if not chosen:
            raise ConfigError(f"unit {spec!r}: {self.source} has crank holes {holes} of {rows[0].designation}, "
                              f"not {hole}")
        return chosen[0]


def read_catalogue(path: Path) -> Catalogue:
    """The rows of a catalogue file as unit-file tables (docs/catalogue.md); a file that cannot be
    read, a header without a required column or with an unknown one, and a malformed row are
    refused with one line naming the file, the line and the column."""
    source = display_name(path)
    text = read_text(path, MAX_BYTES, "unit catalogue", ConfigError)
    lines = [(number, line) for number, line in enumerate(text.split("\n"), start=1)
             if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise ConfigError(f"{source}: empty: a unit catalogue is a header line ({', '.join(REQUIRED)}, ...) "
                          f"and a row per unit and crank hole")
    split = _split(lines, source)
    header_line, header = next(split)
    columns = _header(header, header_line, source)
    rows: list[CatalogueRow] = []
    seen: dict[tuple[str, int], int] = {}
    for number, cells in split:
        if len(cells) != len(columns):
            hint = ' (a cell holding a comma is quoted: "SK8-3,5-4000")' if len(cells) > len(columns) else ""
            raise ConfigError(f"{source}: line {number}: {len(cells)} cells for the header's {len(columns)} "
                              f"columns{hint}")
        row = _row(zip(columns, cells), number, source)
        key = (designation_key(row.designation), row.hole)
        if key in seen:
            raise ConfigError(f"{source}: line {number}: {row.name} is given twice (lines {seen[key]} and {number})")
        seen[key] = number
        rows.append(row)
    if not rows:
        raise ConfigError(f"{source}: no unit rows under the header (line {header_line})")
    return Catalogue(source, tuple(rows))


def _split(lines: list[tuple[int, str]], source: str) -> Iterator[tuple[int, list[str]]]:
    """(line number, stripped cells) of each line: one CSV row a line (no cell holds a line break)."""
    reader = csv.reader((line for _, line in lines), strict=True)
    for index, (number, _) in enumerate(lines, start=1):
        try:
            cells = next(reader)
        except csv.Error as exc:
            raise ConfigError(f"{source}: line {number}: not valid CSV: {exc}") from None
        if reader.line_num != index:
            raise ConfigError(f"{source}: line {number}: not valid CSV: a quoted cell is not closed on its line")
        yield number, [cell.strip() for cell in cells]


@dataclass(frozen=True)
class _Column:
    """A header cell: the column's name (a key of :data:`COLUMNS`), its unit (None for text) and the cell."""

    name: str
    unit: str | None
    header: str


def _header(cells: list[str], line: int, source: str) -> list[_Column]:
    """The header's columns, each known, once, with a unit where it holds numbers."""
    where = f"{source}: line {line}"
    columns = [_column(cell.lstrip("\ufeff"), j + 1, where) for j, cell in enumerate(cells)]
    names = [column.name for column in columns]
    for column in columns:
        if names.count(column.name) > 1:
            twice = " and ".join(c.header for c in columns if c.name == column.name)
            raise ConfigError(f"{where}: column {column.name} is given twice ({twice})")
    missing = [name for name in REQUIRED if name not in names]
    if not any(all(name in names for name in height) for height in HEIGHTS):
        missing.append("K (or H and G)")
    if missing:
        raise ConfigError(f"{where}: missing column{'s' if len(missing) > 1 else ''} {', '.join(missing)} "
                          f"(a unit catalogue has {', '.join(REQUIRED)} and K or H and G; docs/catalogue.md)")
    return columns


def _column(cell: str, number: int, where: str) -> _Column:
    """A header cell's column: a name of :data:`COLUMNS`, then ``_`` and a unit for a number column
    (``A_in``, ``B_kN``, ``gearbox_torque_lbf_in``: an underscore inside a unit multiplies)."""
    if not cell:
        raise ConfigError(f"{where}: column {number} has no name")
    name, unit = _BY_FOLDED.get(cell.casefold()), None
    if name is None:
        name = next((n for n in sorted(COLUMNS, key=len, reverse=True)
                     if cell.casefold().startswith(n.casefold() + "_") and COLUMNS[n].dimension), None)
        if name is None:
            raise ConfigError(f"{where}: unknown column {cell!r} (column {number}); the columns are "
                              f"{', '.join(COLUMNS)}, numbers with a unit (A_in, B_lbf; docs/catalogue.md)")
        unit = cell[len(name) + 1:].replace("_", "*")
    dimension = COLUMNS[name].dimension
    if dimension is None and unit is None:
        return _Column(name, None, cell)
    if unit is None:
        raise ConfigError(f"{where}: column {cell!r} names no unit: write it after the name, e.g. "
                          f"{name}_{_EXAMPLE_UNITS[dimension]}")
    try:
        parse_quantity(f"1 {unit}", dimension)
    except ValueError as exc:
        raise ConfigError(f"{where}: column {cell!r}: {exc}") from None
    return _Column(name, unit, cell)


def _row(cells: Iterable[tuple[_Column, str]], line: int, source: str) -> CatalogueRow:
    """A row, its cells by column, as a unit file's table."""
    table: dict[str, Any] = {}
    given: dict[str, tuple[_Column, str]] = {}
    for column, value in cells:
        if not value:
            if column.name in REQUIRED:
                raise ConfigError(f"{source}: line {line}: column {column.header} is empty")
            continue
        if column.unit is not None:
            if not _NUMBER.match(value):
                raise ConfigError(f"{source}: line {line}: column {column.header}: {value!r} is not a number "
                                  f"(a decimal point, the unit in the header)")
            value = f"{value} {column.unit}"
        given[column.name] = (column, value)
    hole = given["crank_hole"][1]
    if not _WHOLE.match(hole) or int(hole) < 1:
        raise ConfigError(f"{source}: line {line}: column crank_hole: {hole!r} is not a whole number from 1")
    designation = given["designation"][1]
    table["name"] = f"{designation}/{int(hole)}"
    headers = {}
    for name, (column, value) in given.items():
        key = COLUMNS[name].key
        if key is None:
            continue
        section = table
        for part in key[:-1]:
            section = section.setdefault(part, {})
        section[key[-1]] = [value] if key == ("sources",) else value
        headers[".".join(key)] = column.header
    stroke = given.get("stroke")
    return CatalogueRow(source, line, designation, int(hole), table,
                        None if stroke is None else parse_quantity(stroke[1], "length"), headers)
