"""`pumpjack units`: list the bundled units."""

from __future__ import annotations

from ..config import bundled_units, read_unit_file
from ..core.linkage import dead_positions
from ..render import TEXT, Column, Report
from .common import FormatOption, OutputOption, UnitsOption, output


def units(fmt: FormatOption = None, units: UnitsOption = "si", out: OutputOption = None) -> None:
    """List the bundled units with their stroke; name one in any command, or give a file path."""
    series: dict[str, list] = {"name": [], "designation": [], "stroke": [], "crank_radius": [], "description": []}
    for name, path in bundled_units().items():
        config = read_unit_file(path)
        linkage = config.geometry.linkage()
        dead = dead_positions(linkage)
        series["name"].append(name)
        series["designation"].append(config.name)
        series["stroke"].append(linkage.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom))
        series["crank_radius"].append(linkage.crank_radius)
        series["description"].append(config.description)
    report = Report(
        title="Bundled units",
        summary=(),
        columns=(
            Column("name", TEXT, "name to give to the commands"),
            Column("designation", TEXT, "unit designation"),
            Column("stroke", "length", "polished-rod stroke, exact"),
            Column("crank_radius", "length", "crank radius r / R"),
            Column("description", TEXT, "what the file holds"),
        ),
        series=series,
    )
    output(report, fmt, units, out, None)
