"""`pumpjack units`: list the bundled units."""

from __future__ import annotations

from ..analysis.listing import bundled_units
from ..options import FormatOption, OutputOption, UnitsOption, UnitSystem, output

SHOWN = ("name", "kind", "designation", "stroke", "description")


def units(fmt: FormatOption = None, units: UnitsOption = UnitSystem.si, out: OutputOption = None) -> None:
    """List the bundled units with their stroke; name one in any command, or give a file path."""
    output(bundled_units(), SHOWN, fmt, units, out, None)
