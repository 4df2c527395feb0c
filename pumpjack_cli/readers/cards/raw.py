"""The raw card every card reader returns, and the column kinds, layouts, limits and checks they share.

A raw card is what a file says, in SI, before any unit is involved: the columns of one
of three layouts, the source line of every sample for messages, what the file states
about the well, and what the reader noticed. Putting it on a unit's crank-angle axis is
:func:`pumpjack_cli.core.cards.place_card`.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Iterator
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from ...errors import CardError
from ...names import written_names
from ...quantities import FOOT, INCH, KILOGRAM_FORCE, POUND_FORCE, SPM_RANGE, UNIT_SPELLINGS, output_unit
from ...text_input import decode_text

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
#: Lines of a card file's text looked at one by one for its first content lines (its format, a
#: delimited card's preamble and header come within them), before the rest is split at once.
HEAD_LINES = 32
#: Column delimiters of delimited text, in the order a header is searched for them.
DELIMITERS = ("\t", ";", ",")
MIN_POINTS = 8
MAX_POINTS = 100_000
#: Largest magnitude of a load [N] and a position [m] in a card, far beyond any pumping
#: unit (the largest API Spec 11E structure rating is below 0.3 MN, the longest stroke
#: below 10 m): a larger number is a wrong unit or a corrupt file, refused by its line
#: before it can overflow the computation.
LIMITS = {"load": (1e7, "10 MN"), "position": (1e3, "1 km")}
#: A stroke the file states may differ from its positions' range by this fraction, as a
#: card's stroke may from the unit's (``core.cards.STROKE_ERROR``); beyond, it is refused.
STATED_STROKE_TOLERANCE = 0.05
#: The surface card among the columns this tool writes (``predict``, ``downhole``, ``torque``
#: with ``-f csv`` or ``-f json``): output name -> column kind ...
_WRITTEN_KINDS = {"time": "time", "position": "position", "rod_load": "load", "crank_angle": "crank_angle"}
#: ... and the layouts taken, the first the table holds: the time card, else positions, else angles.
_WRITTEN_LAYOUTS = (("time", "position", "load"), ("position", "load"), ("crank_angle", "load"))
_SPM = re.compile(r"^([0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?)\s*(?:spm|1/min|/min|strokes/min)?$", re.IGNORECASE)


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
        What the file states about the well and the measurement, by canonical key:
        ``well`` (text), ``timestamp`` (ISO 8601 text), ``spm`` [1/min], ``stroke`` [m],
        ``units`` (``"si"`` or ``"field"``); a stroke of a recording adds ``start``, the
        time of its first sample [s]. Empty when the file states nothing.
    metadata_lines : dict
        The file's line of each metadata key (for messages).
    warnings : tuple of str
        One line for each thing the reader noticed and mended.
    strokes : tuple of RawCard
        Every card of a file that holds several, in the file's order: the strokes of a
        continuous recording (:mod:`.recording`), the lines of a hex file, each named
        "<file> stroke k" (k from 1) in messages. The raw card itself is then the last
        of them (what a controller shows) under the file's name; empty for a file of
        one card.
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
    metadata_lines: dict[str, int] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    strokes: tuple[RawCard, ...] = ()


@dataclass(frozen=True)
class CardFile:
    """What a reader reads: a card file's content as read, its name for messages, and the
    card options (``--card-units``, ``--card-columns`` as a mapping, ``--card-points``)."""

    data: bytes | str
    source: str
    units: str | None = None
    columns: dict[str, str] | None = None
    points: int | None = None

    @cached_property
    def text(self) -> str:
        """The content as UTF-8 text (LF line ends, no byte-order mark); content that is not
        text is refused in one line naming its line."""
        return decode_text(self.data, self.source, CardError)

    @cached_property
    def is_text(self) -> bool:
        """Whether the content is UTF-8 text."""
        try:
            self.text
        except CardError:
            return False
        return True

    @cached_property
    def lines(self) -> list[str]:
        """The lines of the text, without their ends (none for binary content)."""
        return self.text.split("\n") if self.is_text else []

    def content_lines(self) -> Iterator[str]:
        """The lines that are neither blank nor ``#`` comments, lazily (none for binary content):
        the text is not split for the first of them."""
        return (line for _, line, _ in content_lines_of(self.text)) if self.is_text else iter(())


def content_lines_of(text: str) -> Iterator[tuple[int, str, int]]:
    """The lines of ``text`` that are neither blank nor comments (:func:`is_content`), lazily, each
    with its index among the lines (``text.split("\\n")``) and where the line after it starts:
    the first :data:`HEAD_LINES` lines are found one by one, the rest split off at once when the
    lines are looked at beyond them."""
    start = 0
    for i in range(HEAD_LINES):
        end = text.find("\n", start)
        line = text[start:end if end >= 0 else len(text)]
        start += len(line) + 1
        if is_content(line):
            yield i, line, start
        if end < 0:
            return
    for i, line in enumerate(text[start:].split("\n"), HEAD_LINES):
        start += len(line) + 1
        if is_content(line):
            yield i, line, start


def is_content(line: str) -> bool:
    """Neither blank nor a comment; '#' directly followed by a delimiter is the index column '#'."""
    text = line.strip()
    return bool(text) and (not text.startswith("#") or text[1:2] in DELIMITERS)


@dataclass(frozen=True)
class Column:
    """One column as read: values in SI, the unit as written and its factor to SI."""

    values: np.ndarray
    unit: str
    factor: float


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


def in_si(numbers: np.ndarray, kind: str, unit: str, factor: float, where: Callable[[int], str],
          written: Callable[[int], str]) -> np.ndarray:
    """A column's numbers (as written, in ``unit``) in SI, if every one is finite and within its
    kind's :data:`LIMITS`; else one line at the first culprit, ``where(i)`` naming the file and
    its place ("card.csv: line 7") and ``written(i)`` the value as the file writes it. A column
    within its kind's limits is finite too (NaN compares false), so one comparison passes a good
    column of a limited kind."""
    values = numbers * factor
    if (np.abs(values) <= LIMITS[kind][0]).all() if kind in LIMITS else np.isfinite(numbers).all():
        return values
    bad = ~np.isfinite(numbers)
    if bad.any():
        i = int(np.argmax(bad))
        raise CardError(f"{where(i)}: {kind} is {written(i)}, not a finite number")
    if kind in LIMITS:
        limit, shown = LIMITS[kind]
        beyond = np.abs(values) > limit
        if beyond.any():
            i = int(np.argmax(beyond))
            raise CardError(f"{where(i)}: {kind} {written(i)} {unit} is beyond {shown}: not a polished-rod {kind}; "
                            f"check the column's unit")
    return values


def count_points(points: int, source: str) -> None:
    """Refuse a card of fewer than :data:`MIN_POINTS` or more than :data:`MAX_POINTS` points."""
    if points < MIN_POINTS:
        raise CardError(f"{source}: {points} points; a card needs at least {MIN_POINTS}")
    if points > MAX_POINTS:
        raise CardError(f"{source}: {points} points; a card has at most {MAX_POINTS}")


def written_card(names: list[str]) -> dict[str, tuple[int, str, float]] | None:
    """The surface card's columns in a table this tool wrote (``pumpjack predict -f csv``):
    kind -> (index, unit, factor to SI). The time card (time, position, rod_load) is taken
    when the table has it, else positions or crank angles with rod_load; every other
    column is ignored. None when a name is not one the tool writes or the table holds no
    surface card (a user's table, read by its own rules)."""
    known = written_names()
    if not names or not all(name in known for name in names):
        return None
    found: dict[str, tuple[int, str, float]] = {}
    for j, name in enumerate(names):
        base, quantity, system = known[name]
        kind = _WRITTEN_KINDS.get(base)
        if kind is not None and kind not in found:
            unit = output_unit(quantity, system)
            found[kind] = (j, unit.label, 1.0 / unit.scale)
    layout = next((layout for layout in _WRITTEN_LAYOUTS if set(layout) <= set(found)), None)
    return None if layout is None else {kind: found[kind] for kind in layout}


def stated_spm(value: object, where: str) -> float:
    """A pumping speed a file states [1/min]: a number, or a text "7.8" or "7.8 spm" (also
    1/min, strokes/min), within :data:`SPM_RANGE`; else one line, ``where`` naming the file
    and line."""
    text = str(value).strip()
    found = None if isinstance(value, bool) else _SPM.match(text)
    if found is None:
        raise CardError(f"{where}: SPM {show(text)} is not a number of strokes per minute (e.g. 7.8 or 7.8 spm)")
    spm = float(found.group(1))
    if not SPM_RANGE[0] <= spm <= SPM_RANGE[1]:
        raise CardError(f"{where}: SPM {spm:g} is outside {SPM_RANGE[0]:g} .. {SPM_RANGE[1]:g} strokes per minute")
    return spm


def _time_order(time: np.ndarray, lines: np.ndarray, column: Column, source: str) -> bool:
    """True if the rows are in reverse time order; refuse repeated or unordered time stamps."""
    steps = time[1:] - time[:-1]
    if steps.size and steps.min() > 0:
        return False
    if np.any(steps == 0):
        i = int(np.argmax(steps == 0)) + 1
        raise CardError(f"{source}: line {lines[i]}: time {time[i] / column.factor:.6g} {column.unit} repeats "
                        f"line {lines[i - 1]}; duplicated time stamps")
    if np.all(steps < 0):
        return True
    if np.any(steps < 0):
        raise CardError(f"{source}: line {lines[int(np.argmax(steps < 0)) + 1]}: time does not increase")
    return False


def _close(a: float, b: float) -> bool:
    """``numpy.allclose(a, b)`` of two finite numbers (its tolerances), without its array machinery."""
    return abs(a - b) <= 1e-8 + 1e-5 * abs(b)


def assemble(source: str, columns: dict[str, Column], lines: np.ndarray, **stated) -> RawCard:
    """The raw card of one layout's columns (SI) and the line of every row: rows in reverse time
    order are turned back (one warning), a position card closed by repeating its first sample
    loses the repeat. ``stated`` are the file's ``metadata`` and ``metadata_lines``."""
    units = {kind: (column.unit, column.factor) for kind, column in columns.items()}
    load = columns["load"].values
    if "crank_angle" in columns:
        return RawCard(source, load, lines, crank_angle=columns["crank_angle"].values, column_units=units, **stated)
    time = columns["time"].values if "time" in columns else None
    position = columns["position"].values
    backwards = time is not None and _time_order(time, lines, columns["time"], source)
    if _close(position[0], position[-1]) and _close(load[0], load[-1]):
        position, load, lines = position[:-1], load[:-1], lines[:-1]  # a closed card repeats its first point
        time = None if time is None else time[:-1]
    if backwards:
        position, load, time, lines = position[::-1], load[::-1], time[::-1], lines[::-1]
    warnings = (f"{source}: rows listed in reverse time order; read in time order",) if backwards else ()
    return RawCard(source, load, lines, time, position, column_units=units, reversed=backwards, warnings=warnings,
                   **stated)


def several(cards: Sequence[RawCard]) -> RawCard:
    """The raw card of a file of several cards: the last, with every one, named "<file> stroke
    k" (k from 1), in ``strokes``; a single card as it is."""
    if len(cards) == 1:
        return cards[0]
    named = tuple(replace(card, source=f"{card.source} stroke {k}") for k, card in enumerate(cards, 1))
    return replace(cards[-1], strokes=named)
