"""`pumpjack units`: list the bundled units."""

from __future__ import annotations

from ..analysis.listing import bundled_units
from ..options import FormatOption, OutputOption, UnitsOption, UnitSystem, Output

SHOWN = ("name", "kind", "designation", "stroke", "description")


def units(fmt: FormatOption = None, units: UnitsOption = UnitSystem.si, out: OutputOption = None) -> None:
    """List the bundled units with their stroke; name one in any command, or give a file path."""
    Output(fmt, units, out, None).emit(bundled_units(), SHOWN)
