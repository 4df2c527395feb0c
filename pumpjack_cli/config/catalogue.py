"""The units of an operator's catalogue (docs/catalogue.md), validated as unit files.

A catalogue row is read (:mod:`pumpjack_cli.readers.catalogue`) into the very table a unit
file parses to, and validated here by the unit-file schema (:func:`.files.parse_unit`):
one validation path, its messages naming the catalogue's file, the row's line and the
column instead of the key path. The kind of unit is the registry's
(:func:`.unit_classes.unit_class`: the ``class`` column, else the designation's letters).
The exact stroke of each row is compared with the stroke the catalogue publishes: a
difference over :data:`STROKE_TOLERANCE` is a warning when a unit is used and a flag in
the listing (:func:`catalogue_listing`, pure Python for ``pumpjack units``).
"""

from __future__ import annotations

from typing import Any

from ..errors import ConfigError, warn
from ..quantities import INCH
from ..readers.catalogue import Catalogue, CatalogueRow
from .files import field_path, parse_unit
from .geometry_names import GEOMETRY_ALIASES, rotation_sign
from .unit_classes import UNIT_CLASSES, unit_class

#: Largest difference between the exact and the published stroke of a crank hole taken as
#: agreement [m]: 0.5 in (issue 22), about the rounding of printed strokes and letters.
STROKE_TOLERANCE = 0.5 * INCH
#: The API letters that hold the vertical offset (K, or H and G).
_HEIGHT_LETTERS = ("H", "G", "K")
#: The ``[geometry]`` key of the crank offset tau of the kinds that keep it there.
OFFSET_KEY = "crank_offset"


def _columns(columns: dict[str, str], loc: tuple) -> str:
    """The catalogue column(s) of a schema error's location (``geometry.front_arm`` -> ``column A_in``),
    ``columns`` the header of each key of the table; the geometry as a whole is its letters' columns."""
    path = field_path(loc)
    section, _, field = path.partition(".")
    keys = {path}
    if section == "geometry":
        names = ((field, *GEOMETRY_ALIASES.get(field, ()), *(_HEIGHT_LETTERS if field == "vertical_offset" else ()))
                 if field else (*(name for aliases in GEOMETRY_ALIASES.values() for name in aliases), *_HEIGHT_LETTERS))
        keys = {f"geometry.{name}" for name in names}
    found = [header for key, header in columns.items() if key in keys]
    if not found:
        return f"{path} (no column of the catalogue gives it)"
    return f"column {found[0]}" if len(found) == 1 else f"columns {', '.join(found)}"


def row_class(row: CatalogueRow) -> str:
    """The kind of unit of a row (``class``, else the designation's letters), or a ConfigError
    naming the column that asks for a kind this version does not model."""
    try:
        return unit_class(row.table["geometry"], row.designation)
    except ValueError as exc:
        column = row.columns.get("geometry.class" if "class" in row.table["geometry"] else "designation")
        raise ConfigError(f"{row.place}: column {column}: {exc}") from None


def _stroke_difference(row: CatalogueRow, stroke: float) -> float | None:
    """The exact ``stroke`` [m] minus the row's published stroke [m]; None when none is published."""
    return None if row.stroke is None else stroke - row.stroke


def _differs(difference: float | None) -> bool:
    return difference is not None and abs(difference) > STROKE_TOLERANCE


def _offset_placed(row: CatalogueRow, kind: str) -> tuple[dict[str, Any], dict[str, str]]:
    """The row's table and columns with the crank offset tau where the kind's schema keeps it: its
    ``[geometry]`` :data:`OFFSET_KEY` if it has one (Mark II, reverse-mark), else ``[counterbalance]
    phase``, which needs the structural unbalance B beside it (a ConfigError without)."""
    balance = row.table.get("counterbalance", {})
    if "phase" not in balance:
        return row.table, row.columns
    if OFFSET_KEY in UNIT_CLASSES[kind].model().model_fields:
        table = {key: value for key, value in row.table.items() if key != "counterbalance"}
        table["geometry"] = {**row.table["geometry"], OFFSET_KEY: balance["phase"]}
        rest = {key: value for key, value in balance.items() if key != "phase"}
        if rest:
            table["counterbalance"] = rest
        moved = {"counterbalance.phase": f"geometry.{OFFSET_KEY}"}
        return table, {moved.get(key, key): header for key, header in row.columns.items()}
    if "structural_unbalance" not in balance:
        raise ConfigError(f"{row.place}: column {row.columns['counterbalance.phase']}: a crank offset needs the "
                          f"structural unbalance B of the same [counterbalance]")
    return row.table, row.columns


def catalogue_unit(row: CatalogueRow):
    """The unit of a catalogue row, validated by the unit-file schema (a ConfigError names the
    file, line and column); a warning when its exact stroke is off the published one by more
    than :data:`STROKE_TOLERANCE`."""
    table, columns = _offset_placed(row, row_class(row))
    unit = parse_unit(table, row.place, lambda loc: _columns(columns, loc))
    stroke = unit.geometry.mechanism().stroke
    difference = _stroke_difference(row, stroke)
    if _differs(difference):
        column = row.columns["geometry.R"]
        warn(f"{row.place}: {row.name}: the exact stroke {stroke / INCH:.2f} in ({stroke:.4f} m) differs from the "
             f"published {row.stroke / INCH:.2f} in by {difference / INCH:+.2f} in, more than "
             f"{STROKE_TOLERANCE / INCH:g} in: check the letters, {column} and the stroke")
    return unit


def catalogue_listing(catalogue: Catalogue) -> list[dict[str, Any]]:
    """The rows of a catalogue (name, designation, crank hole, kind, exact and published stroke [m],
    their difference and its flag, source) without building any model: the exact strokes come
    from the registry's raw-stroke functions (:data:`.unit_classes.UNIT_CLASSES`)."""
    listed = []
    for row in catalogue.rows:
        kind = row_class(row)
        try:
            rotation_sign(row.table["geometry"].get("rotation", "clockwise"))
        except ValueError as exc:
            raise ConfigError(f"{row.place}: {_columns(row.columns, ('geometry', 'rotation'))}: {exc}") from None
        try:
            stroke = UNIT_CLASSES[kind].stroke(row.table["geometry"])
        except ValueError as exc:
            raise ConfigError(f"{row.place}: {_columns(row.columns, ('geometry',))}: {exc}") from None
        difference = _stroke_difference(row, stroke)
        check = "not published" if difference is None else "differs" if _differs(difference) else "ok"
        listed.append({"name": row.name, "designation": row.designation, "crank_hole": str(row.hole),
                       "unit_class": kind, "stroke": stroke, "published_stroke": row.stroke,
                       "stroke_difference": difference, "stroke_check": check,
                       "source": row.table.get("sources", [""])[0]})
    return listed
