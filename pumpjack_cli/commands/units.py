"""`pumpjack units`: list the bundled units."""

from __future__ import annotations

from ..config import bundled_units, read_unit_file
from ..render import TEXT, Column, Report
from .common import FormatOption, OutputOption, UnitsOption, output


def units(fmt: FormatOption = None, units: UnitsOption = "si", out: OutputOption = None) -> None:
    """List the bundled units with their stroke; name one in any command, or give a file path."""
    series: dict[str, list] = {"name": [], "kind": [], "designation": [], "stroke": [], "description": []}
    for name, path in bundled_units().items():
        config = read_unit_file(path)
        series["name"].append(name)
        series["kind"].append(config.kind)
        series["designation"].append(config.name)
        series["stroke"].append(config.stroke())
        series["description"].append(config.description)
    report = Report(
        title="Bundled units",
        summary=(),
        columns=(
            Column("name", TEXT, "name to give to the commands"),
            Column("kind", TEXT, "machine kind"),
            Column("designation", TEXT, "unit designation"),
            Column("stroke", "length", "stroke of the polished rod or piston, exact"),
            Column("description", TEXT, "what the file holds"),
        ),
        series=series,
    )
    output(report, fmt, units, out, None)
