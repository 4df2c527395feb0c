"""`pumpjack units`: list the bundled units, or the units of a catalogue."""

from __future__ import annotations

from ..analysis.listing import bundled_units, catalogue_units
from ..options import CatalogueOption, FormatOption, OutputOption, UnitsOption, UnitSystem, Output

SHOWN = ("name", "kind", "designation", "stroke", "description")
CATALOGUE_SHOWN = ("name", "unit_class", "stroke", "published_stroke", "stroke_check")


def units(catalogue: CatalogueOption = None, fmt: FormatOption = None, units: UnitsOption = UnitSystem.si,
          out: OutputOption = None) -> None:
    """List the bundled units with their stroke; name one in any command, or give a file path.

    With --catalogue, the catalogue's units and crank holes instead, with the exact stroke
    beside the published one."""
    sink = Output(fmt, units, out, None)
    if catalogue is None:
        sink.emit(bundled_units(), SHOWN)
    else:
        sink.emit(catalogue_units(catalogue), CATALOGUE_SHOWN)
