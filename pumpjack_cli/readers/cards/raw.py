"""The raw card every card reader returns, and the column kinds and layouts they share.

A raw card is what a file says, in SI, before any unit is involved: the columns of one
of three layouts, the source line of every sample for messages, and what the reader
noticed. Putting it on a unit's crank-angle axis is
:func:`pumpjack_cli.core.cards.place_card`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np

from ...errors import CardError
from ...quantities import FOOT, INCH, KILOGRAM_FORCE, POUND_FORCE, UNIT_SPELLINGS

#: Column kinds: accepted names and dimension.
KINDS = {
    "crank_angle": (("crank_angle", "angle", "theta"), "angle"),
    "time": (("time", "t"), "time"),
    "position": (("position", "displacement", "pos"), "length"),
    "load": (("load", "force", "prl", "polished_rod_load", "rod_load"), "force"),
}
#: Units of each column's dimension: lower-case spelling -> factor to SI (and the spellings of
#: :data:`~pumpjack_cli.quantities.UNIT_SPELLINGS`, the Cyrillic abbreviations among them).
UNITS = {
    "angle": {"deg": math.pi / 180.0, "degree": math.pi / 180.0, "degrees": math.pi / 180.0, "°": math.pi / 180.0,
              "rad": 1.0},
    "time": {"s": 1.0, "sec": 1.0, "ms": 1e-3, "min": 60.0, "с": 1.0, "мс": 1e-3, "мин": 60.0},
    "length": {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "in": INCH, "ft": FOOT},
    "force": {"n": 1.0, "kn": 1e3, "lb": POUND_FORCE, "lbs": POUND_FORCE, "lbf": POUND_FORCE,
              "klb": 1e3 * POUND_FORCE, "klbs": 1e3 * POUND_FORCE, "kip": 1e3 * POUND_FORCE,
              "kips": 1e3 * POUND_FORCE, "klbf": 1e3 * POUND_FORCE, "kgf": KILOGRAM_FORCE, "tf": 1e3 * KILOGRAM_FORCE},
}
#: The units of columns whose file names none (``--card-units``), by dimension.
DEFAULT_UNITS = {
    "si": {"angle": "deg", "time": "s", "length": "m", "force": "n"},
    "field": {"angle": "deg", "time": "s", "length": "in", "force": "lbf"},
}
LAYOUTS = ({"crank_angle", "load"}, {"position", "load"}, {"time", "position", "load"})
LAYOUT_TEXT = "a card has crank_angle and load, position and load, or time, position and load"


@dataclass(frozen=True)
class RawCard:
    """A card as its file gives it, in SI, without a unit.

    Attributes
    ----------
    source : str
        The file's name for messages (``<stdin>`` for ``-``).
    load : numpy.ndarray
        Polished-rod load of every sample [N].
    lines : numpy.ndarray
        The file's line number of every sample (for messages).
    time : numpy.ndarray or None
        Time stamps [s], increasing (rows listed in reverse time order are turned back).
    position : numpy.ndarray or None
        Polished-rod position as measured [m] (not shifted or scaled).
    crank_angle : numpy.ndarray or None
        Crank angles as given [rad] (an angle card; no position, no time).
    column_units : dict
        Kind -> (unit as written, factor to SI [SI unit per unit]) of each column read,
        so that messages quote a value in the file's own unit.
    reversed : bool
        True when the rows were read in reverse to put them in time order.
    metadata : dict
        What the file says about the well and the measurement (well name, date, pumping
        speed, stroke); empty when the format has no such preamble.
    warnings : tuple of str
        One line for each thing the reader noticed and mended.
    """

    source: str
    load: np.ndarray
    lines: np.ndarray
    time: np.ndarray | None = None
    position: np.ndarray | None = None
    crank_angle: np.ndarray | None = None
    column_units: dict[str, tuple[str, float]] = field(default_factory=dict)
    reversed: bool = False
    metadata: dict[str, object] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()


def show(text: str, limit: int = 40) -> str:
    """repr of a cell or name for a message, cut to ``limit`` characters."""
    return repr(text if len(text) <= limit else text[:limit] + "...")


def unit_of(unit: str | None, kind: str, default_units: str | None, where: str) -> tuple[str, float]:
    """Unit label and factor to SI of a column of ``kind``; ``where`` names it in a message.
    A column whose file names no unit takes ``default_units``' and is refused without them."""
    dimension = KINDS[kind][1]
    if unit is None and default_units is None:
        si, field_unit = DEFAULT_UNITS["si"][dimension].replace("n", "N"), DEFAULT_UNITS["field"][dimension]
        raise CardError(f"{where} names no unit: write it in the header ({kind}_{si}, {kind.capitalize()} "
                        f"({field_unit})) or give --card-units si or field")
    key = DEFAULT_UNITS[default_units][dimension] if unit is None else unit.strip().lower().rstrip(".")
    key = UNIT_SPELLINGS.get(key, key)
    if key not in UNITS[dimension]:
        raise CardError(f"{where} has unit {unit!r}, not a unit of {dimension} ({', '.join(UNITS[dimension])})")
    return (key if unit is None else unit.strip()), UNITS[dimension][key]


def checked_columns(pairs: Iterable[tuple[str, str]]) -> dict[str, str]:
    """A column mapping kind -> header text, validated."""
    mapping = {}
    for kind, header in pairs:
        key = str(kind).strip().lower()
        if key not in KINDS:
            raise CardError(f"--card-columns: unknown column kind {show(str(kind))}; use {', '.join(KINDS)}")
        if key in mapping:
            raise CardError(f"--card-columns: {key} given twice")
        if not isinstance(header, str) or not header.strip():
            raise CardError(f"--card-columns: {key} needs a header name")
        mapping[key] = header.strip().strip('"').strip()
    if set(mapping) not in LAYOUTS:
        raise CardError(f"--card-columns: {', '.join(mapping) or 'nothing'} given; {LAYOUT_TEXT}")
    return mapping


def parse_card_columns(text: str) -> dict[str, str]:
    """The mapping of ``--card-columns position=Pos (in),load=PRL[,time=Time]``.

    Pairs ``kind=header`` separated by commas; kinds position, load, time or
    crank_angle; headers as written in the file (case and surrounding spaces
    ignored; a header holding a comma or '=' cannot be mapped).

    >>> parse_card_columns("position=Pos (in), load=PRL, time=Time")
    {'position': 'Pos (in)', 'load': 'PRL', 'time': 'Time'}
    """
    pairs = [part.partition("=") for part in text.split(",")]
    for kind, equals, _ in pairs:
        if not equals:
            raise CardError(f"--card-columns: {show(kind.strip())} is not kind=header "
                            f"(e.g. position=Pos (in),load=PRL,time=Time)")
    return checked_columns((kind, header) for kind, _, header in pairs)
