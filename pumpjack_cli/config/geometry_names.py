"""The spellings of beam-unit geometry: GOST / Soviet-textbook names and API Spec 11E letters.

=================  ======  ===========  ============================================
field              GOST    API 11E      meaning
=================  ======  ===========  ============================================
front_arm          k1      A            centre bearing to horsehead arc (polished rod)
rear_arm           k       C            centre bearing to equalizer bearing
crank_radius       r       R            crank shaft to crank pin
pitman             l       P            crank pin to equalizer bearing
horizontal_offset  l1      I            crank shaft to centre bearing, horizontal
vertical_offset    l2      H - G or     centre bearing above crank shaft;
                           sqrt(K²-I²)  K is the straight distance
=================  ======  ===========  ============================================

The GOST names are those of the Soviet textbooks and of [SK8Rotation2013] (GOST 5866-76
units, [GOST5866]); the letters are those of [API11E].

Pure Python, no pydantic and no numpy: the schema (:mod:`.beam_unit`) validates through
:func:`canonical_geometry`, and ``pumpjack units`` uses :func:`linkage_of` to list the
bundled units' strokes without building a single model.
"""

from __future__ import annotations

from typing import Any

from ..core.beam.geometry import (CLOCKWISE, COUNTERCLOCKWISE, Linkage, beam_linkage, vertical_offset_from_frame,
                                  vertical_offset_from_heights)
from ..errors import GeometryError
from ..quantities import parse_quantity

#: Accepted spellings of each geometry field: (GOST / Soviet textbook, API Spec 11E).
GEOMETRY_ALIASES: dict[str, tuple[str, ...]] = {
    "front_arm": ("k1", "A"),
    "rear_arm": ("k", "C"),
    "crank_radius": ("r", "R"),
    "pitman": ("l", "P"),
    "horizontal_offset": ("l1", "I"),
    "vertical_offset": ("l2",),
}
ROTATION_NAMES = {"cw": "clockwise", "ccw": "counterclockwise"}
ROTATION_SIGNS = {"clockwise": CLOCKWISE, "counterclockwise": COUNTERCLOCKWISE}


def canonical_geometry(data: dict[str, Any]) -> dict[str, Any]:
    """A copy of a ``[geometry]`` table with field names only: GOST names and API letters
    mapped, H and G or K turned into the vertical offset, rotation spelled out.

    Raises ValueError when a dimension is given twice or the API letters are incomplete.

    >>> fields = canonical_geometry({"A": "72 in", "K": 5.0, "I": 3.0, "rotation": "CW"})
    >>> sorted(fields.items())   # vertical offset sqrt(5^2 - 3^2) = 4
    [('front_arm', '72 in'), ('horizontal_offset', 3.0), ('rotation', 'clockwise'), ('vertical_offset', 4.0)]
    """
    data = dict(data)
    api_height = [key for key in ("H", "G", "K") if key in data]
    if api_height:
        if "K" in data and ("H" in data or "G" in data):
            raise ValueError("give either K or both H and G, not both")
        if "K" not in data and not ("H" in data and "G" in data):
            raise ValueError("API letters H and G come together (vertical offset = H - G)")
    for field, aliases in GEOMETRY_ALIASES.items():
        given = [name for name in (field, *aliases) if name in data]
        if field == "vertical_offset" and api_height:
            given.append("H and G" if "H" in data else "K")
        if len(given) > 1:
            raise ValueError(f"{field} is given twice (as {' and '.join(given)}); give one")
        if given and given[0] != field and given[0] in aliases:
            data[field] = data.pop(given[0])
    if "H" in data and "G" in data:
        data["vertical_offset"] = vertical_offset_from_heights(parse_quantity(data.pop("H"), "length"),
                                                               parse_quantity(data.pop("G"), "length"))
    elif "K" in data:
        try:
            data["vertical_offset"] = vertical_offset_from_frame(
                parse_quantity(data.pop("K"), "length"), parse_quantity(data.get("horizontal_offset", 0.0), "length"))
        except GeometryError as exc:
            raise ValueError(str(exc)) from None
    rotation = data.get("rotation")
    if isinstance(rotation, str):
        data["rotation"] = ROTATION_NAMES.get(rotation.lower(), rotation.lower())
    return data


def rotation_sign(rotation: Any) -> int:
    """The sign of a ``rotation`` as written (clockwise, counterclockwise, cw, ccw; any case).

    Raises ValueError for anything else."""
    name = ROTATION_NAMES.get(rotation.lower(), rotation.lower()) if isinstance(rotation, str) else rotation
    if name not in ROTATION_SIGNS:
        raise ValueError(f"rotation {rotation!r} is neither clockwise nor counterclockwise (cw, ccw)")
    return ROTATION_SIGNS[name]


def linkage_of(geometry: dict[str, Any]) -> Linkage:
    """The planar class I linkage of a ``[geometry]`` table as written in a file (any spelling);
    clockwise when the table states no rotation (a kind with one rotation only)."""
    fields = canonical_geometry(geometry)
    lengths = {name: parse_quantity(fields[name], "length") for name in GEOMETRY_ALIASES}
    spatial = {name: parse_quantity(fields[name], "length") if name in fields else None
               for name in ("crank_half_spacing", "equalizer_half_length")}
    return beam_linkage(**lengths, rotation=rotation_sign(fields.get("rotation", "clockwise")), **spatial)


def slider_crank_of(crank_radius: Any, rod_length: Any, offset: Any = 0.0, rotation: str = "counterclockwise"):
    """The core's slider-crank from a ``[geometry]`` table of a slider-crank file (values with
    units or SI numbers): the offset is measured on the side the crank pin swings into first,
    so a clockwise crank (seen with the slider to the right) flips its sign."""
    from ..core.slider_crank.geometry import SliderCrank

    sign = 1.0 if rotation == "counterclockwise" else -1.0
    return SliderCrank(parse_quantity(crank_radius, "length"), parse_quantity(rod_length, "length"),
                       sign * parse_quantity(offset, "length"))
