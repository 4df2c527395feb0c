"""The bundled units, or the units of an operator's catalogue, as a result table (`pumpjack units`),
built without numpy or a single model."""

from __future__ import annotations

from pathlib import Path

from ..config.catalogue import catalogue_listing
from ..config.files import unit_listing
from ..readers.catalogue import read_catalogue
from ..results import Column, Result

#: The listing's columns, in order (names of the catalogue).
FIELDS = ("name", "kind", "designation", "stroke", "description")
#: The columns of a catalogue's listing, in order.
CATALOGUE_FIELDS = ("name", "designation", "crank_hole", "unit_class", "stroke", "published_stroke",
                    "stroke_difference", "stroke_check", "source")


def _table(title: str, rows: list[dict], fields: tuple[str, ...]) -> Result:
    return Result(title, (), tuple(Column(name, [row[name] for row in rows]) for name in fields))


def bundled_units() -> Result:
    """Name, kind, designation, exact stroke and description of every bundled unit."""
    return _table("Bundled units", unit_listing(), FIELDS)


def catalogue_units(path: Path) -> Result:
    """Every unit and crank hole of a catalogue file: name, designation, hole, kind, exact and
    published stroke, their difference and whether it is over 0.5 in, source."""
    catalogue = read_catalogue(path)
    return _table(f"Units of {catalogue.source}", catalogue_listing(catalogue), CATALOGUE_FIELDS)
