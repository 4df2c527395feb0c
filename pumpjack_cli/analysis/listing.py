"""The bundled units as a result table (`pumpjack units`), built without numpy or a single model."""

from __future__ import annotations

from ..config.files import unit_listing
from ..results import Column, Result

#: The listing's columns, in order (names of the catalogue).
FIELDS = ("name", "kind", "designation", "stroke", "description")


def bundled_units() -> Result:
    """Name, kind, designation, exact stroke and description of every bundled unit."""
    rows = unit_listing()
    return Result("Bundled units", (), tuple(Column(name, [row[name] for row in rows]) for name in FIELDS))
