"""The bundled units as a result table (`pumpjack units`), built without numpy or a single model."""

from __future__ import annotations

from ..config.files import unit_listing
from ..results import TEXT, Column, Result


def bundled_units() -> Result:
    """Name, kind, designation, exact stroke and description of every bundled unit."""
    rows = unit_listing()
    fields = (("name", TEXT, "name to give to the commands"), ("kind", TEXT, "machine kind"),
              ("designation", TEXT, "unit designation"), ("stroke", "length", "stroke of the polished rod or piston, exact"),
              ("description", TEXT, "what the file holds"))
    return Result("Bundled units", (), tuple(Column(name, quantity, what, [row[name] for row in rows])
                                            for name, quantity, what in fields))
