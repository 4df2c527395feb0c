"""Deviation surveys: a delimited text file of stations, measured depth, inclination and azimuth.

The format (``docs/deviated.md``): a header line naming the three columns with their units
as cards name theirs, ``measured_depth_m,inclination_deg,azimuth_deg`` (or ``_ft``; also
``md``, ``inc``, ``azi`` and a unit in brackets, ``MD (ft)``), then one station per line from
the surface down, comma-, semicolon- or tab-separated. Lines starting with ``#`` and blank
lines are skipped; the columns a survey export adds (true vertical depth, north, east,
dogleg severity, vertical section) are ignored, since the path is computed from the three
by minimum curvature. Without a station at the wellhead, the hole is taken as vertical from
the surface to the first one.

Refused with one line naming the file, the line and the column (a
:class:`~pumpjack_cli.errors.ConfigError`): a column without a unit or with one of the wrong
dimension, a missing or unknown column, a value that is not a number or not finite,
measured depths that do not increase, an inclination outside 0..180 degrees, an azimuth
outside -360..360 degrees. Whether the survey reaches the pump is the well's question
(:meth:`pumpjack_cli.config.well.Well.path`). No physics here: values come back in SI.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from ..errors import ConfigError
from ..quantities import FOOT, INCH
from ..text_input import display_name, read_text

#: Largest survey file [bytes]; a gyro survey every foot of a 5000 m well is about 0.5 MB.
MAX_BYTES = 10 << 20
#: Most stations a survey may hold.
MAX_STATIONS = 200_000
#: Column kinds: accepted names (folded: lower case, spaces, dots and dashes as underscores) and dimension.
KINDS = {
    "measured_depth": (("measured_depth", "md", "depth", "measureddepth"), "length"),
    "inclination": (("inclination", "inc", "incl", "inclination_angle"), "angle"),
    "azimuth": (("azimuth", "azi", "az", "azim", "direction"), "angle"),
}
#: Columns of survey exports that the minimum-curvature path replaces: skipped.
IGNORED = {"tvd", "true_vertical_depth", "north", "east", "ns", "ew", "n_s", "e_w", "northing", "easting",
           "dls", "dogleg", "dogleg_severity", "vs", "vertical_section", "index", "station", "no", "n", "number",
           "closure", "closure_distance", "closure_direction", "build_rate", "turn_rate", "tool", "comment"}
UNITS = {
    "length": {"m": 1.0, "ft": FOOT, "feet": FOOT, "foot": FOOT, "mm": 1e-3, "in": INCH, "м": 1.0},
    "angle": {"deg": math.pi / 180.0, "degree": math.pi / 180.0, "degrees": math.pi / 180.0, "°": math.pi / 180.0,
              "rad": 1.0, "град": math.pi / 180.0},
}
#: Longest measured depth a survey may state [m] (the deepest wells are about 12 km).
LONGEST = 20_000.0
_UNIT_AT_END = re.compile(r"^(.*?)\s*[\[(]\s*([^\[\]()]*?)\s*[\])]\s*$")
_DELIMITERS = ("\t", ";", ",")
_KNOWN = "measured_depth_m (or _ft), inclination_deg, azimuth_deg"


@dataclass(frozen=True)
class RawSurvey:
    """A survey as its file gives it, SI: measured depths [m], inclinations and azimuths [rad]
    from the surface down (a vertical station at the wellhead first when the file has none),
    the file's line of each station (0 for the one added), and the file's name."""

    source: str
    measured_depth: tuple[float, ...]
    inclination: tuple[float, ...]
    azimuth: tuple[float, ...]
    lines: tuple[int, ...]

    @property
    def depth(self) -> float:
        """Measured depth of the last station [m]."""
        return self.measured_depth[-1]


def _fold(name: str) -> str:
    return re.sub(r"[\s.\-/]+", "_", name.strip().strip('"').strip().lower()).strip("_")


def _column(cell: str, where: str) -> tuple[str, float] | None:
    """(kind, factor to SI) of a header cell, None for an ignored column."""
    text = cell.strip().strip('"').strip()
    found = _UNIT_AT_END.match(text)
    name, unit = (found.group(1), found.group(2)) if found and found.group(1) else (text, None)
    key = _fold(name)
    kind = next((k for k, (names, _) in KINDS.items() if key in names), None)
    if kind is None and unit is None:
        stem, _, suffix = key.rpartition("_")
        kind = next((k for k, (names, _) in KINDS.items() if stem in names), None)
        if kind is not None:
            unit = suffix
    if kind is None:
        if key in IGNORED or key.rpartition("_")[0] in IGNORED or not key:
            return None
        raise ConfigError(f"{where}: unknown column {text!r}; a survey has the columns {_KNOWN}")
    dimension = KINDS[kind][1]
    if unit is None:
        raise ConfigError(f"{where}: column {text!r} names no unit: write it in the header "
                          f"({kind}_{'m' if dimension == 'length' else 'deg'})")
    factor = UNITS[dimension].get(unit.strip().lower())
    if factor is None:
        raise ConfigError(f"{where}: column {text!r} has unit {unit!r}, not a unit of {dimension} "
                          f"({', '.join(UNITS[dimension])})")
    return kind, factor


def parse_survey(text: str, source: str) -> RawSurvey:
    """The stations of a survey file's text (module docstring); ``source`` names it in messages."""
    rows = [(number, line) for number, line in enumerate(text.split("\n"), start=1)
            if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        raise ConfigError(f"{source}: no header line: a survey has the columns {_KNOWN}")
    header_line, header = rows[0]
    delimiter = next((d for d in _DELIMITERS if d in header), None)
    if delimiter is None:
        raise ConfigError(f"{source}: line {header_line}: the header holds no comma, semicolon or tab; a survey "
                          f"has the columns {_KNOWN}")
    columns: dict[str, tuple[int, float]] = {}
    cells = header.split(delimiter)
    for index, cell in enumerate(cells):
        named = _column(cell, f"{source}: line {header_line}: column {index + 1}")
        if named is None:
            continue
        if named[0] in columns:
            raise ConfigError(f"{source}: line {header_line}: column {index + 1}: {named[0]} given twice")
        columns[named[0]] = (index, named[1])
    missing = [kind for kind in KINDS if kind not in columns]
    if missing:
        raise ConfigError(f"{source}: line {header_line}: no {' and no '.join(missing)} column; a survey has the "
                          f"columns {_KNOWN}")
    if len(rows) - 1 > MAX_STATIONS:
        raise ConfigError(f"{source}: {len(rows) - 1} stations; a survey holds at most {MAX_STATIONS}")
    depth: list[float] = []
    inclination: list[float] = []
    azimuth: list[float] = []
    lines: list[int] = []
    for number, line in rows[1:]:
        cells = line.split(delimiter)
        if len(cells) != len(header.split(delimiter)):
            raise ConfigError(f"{source}: line {number}: {len(cells)} cells for {len(header.split(delimiter))} "
                              f"columns")
        values = {}
        for kind, (index, factor) in columns.items():
            cell = cells[index].strip().strip('"').strip()
            where = f"{source}: line {number}: column {index + 1} ({kind})"
            if re.search(r"\d,\d", cell):
                raise ConfigError(f"{where}: {cell!r} has a decimal comma; write it with a point")
            try:
                value = float(cell)
            except ValueError:
                raise ConfigError(f"{where}: {cell!r} is not a number") from None
            if not math.isfinite(value):
                raise ConfigError(f"{where}: {cell!r} is not a finite number")
            values[kind] = value * factor
        md, inc, azi = values["measured_depth"], values["inclination"], values["azimuth"]
        where = f"{source}: line {number}: column"
        if not 0.0 <= md <= LONGEST:
            raise ConfigError(f"{where} {columns['measured_depth'][0] + 1} (measured_depth): {md:.6g} m is outside "
                              f"0 .. {LONGEST:g} m")
        if depth and not md > depth[-1]:
            raise ConfigError(f"{where} {columns['measured_depth'][0] + 1} (measured_depth): {md:.6g} m does not go "
                              f"below the station before it ({depth[-1]:.6g} m, line {lines[-1]}): stations must "
                              f"go down the hole")
        if not 0.0 <= inc <= math.pi + 1e-12:
            raise ConfigError(f"{where} {columns['inclination'][0] + 1} (inclination): {math.degrees(inc):.6g} deg is "
                              f"outside 0 .. 180 deg")
        if not -2.0 * math.pi - 1e-12 <= azi <= 2.0 * math.pi + 1e-12:
            raise ConfigError(f"{where} {columns['azimuth'][0] + 1} (azimuth): {math.degrees(azi):.6g} deg is "
                              f"outside -360 .. 360 deg")
        depth.append(md)
        inclination.append(min(inc, math.pi))
        azimuth.append(azi % (2.0 * math.pi))
        lines.append(number)
    if not depth:
        raise ConfigError(f"{source}: the survey has a header but no station")
    if depth[0] > 0.0:
        depth.insert(0, 0.0)
        inclination.insert(0, 0.0)
        azimuth.insert(0, azimuth[0])
        lines.insert(0, 0)
    return RawSurvey(source, tuple(depth), tuple(inclination), tuple(azimuth), tuple(lines))


def read_survey(path: Path | str) -> RawSurvey:
    """The survey file at ``path`` (:func:`parse_survey`), read as every input file is
    (:func:`~pumpjack_cli.text_input.read_text`: UTF-8 text of at most :data:`MAX_BYTES`)."""
    return parse_survey(read_text(path, MAX_BYTES, "survey file", ConfigError), display_name(path))
