"""JSON cards: position and load arrays with the pumping speed, as card services hand them over,
and this tool's own ``-f json`` outputs that carry a surface card.

* ``{"S": [...], "F": [...], "SPM": 7.5}``: positions ``S`` in m and loads ``F`` in kN
  unless ``"S_unit"`` and ``"F_unit"`` name others (units of the delimited reader's
  table); ``SPM`` [1/min] is optional and stated (``RawCard.metadata["spm"]``); other
  keys are ignored. A position card.
* ``{"series": {...}, ...}`` as ``pumpjack predict -f json`` or ``downhole -f json`` write
  it: the surface card's series are taken (:func:`.raw.written_card`), every other
  output series is ignored; a series whose name the tool does not write is refused.

Every refusal names the file and the line of the value (the line of an array's item).
"""

from __future__ import annotations

import json
import math
import re

import numpy as np

from ...errors import CardError
from ...names import written_names
from ...text_input import digit_limit
from .raw import (CardFile, Column, RawCard, assemble, count_points, in_si, show, stated_spm, unit_of,
                  written_card)

EXTENSIONS = (".json",)
#: Units of the card-service arrays when the file names none.
SERVICE_UNITS = {"S": ("position", "m"), "F": ("load", "kN")}
_DECODER = json.JSONDecoder()
_SPACE = re.compile(r"[ \t\n\r]*")


def recognises(file: CardFile) -> bool:
    """True when the first line that is not blank starts with '{'."""
    return next(file.content_lines(), "").lstrip().startswith("{")


def _skip(text: str, at: int) -> int:
    return _SPACE.match(text, at).end()


def _members(text: str, at: int) -> dict[str, int]:
    """Key -> offset of its value, of the object whose '{' is at ``text[at]`` (a document already
    parsed, so well formed; a key given twice keeps its last value, as json does)."""
    offsets = {}
    at = _skip(text, at + 1)
    while text[at] != "}":
        key, at = _DECODER.raw_decode(text, at)
        at = _skip(text, _skip(text, at) + 1)
        offsets[key] = at
        _, at = _DECODER.raw_decode(text, at)
        at = _skip(text, at)
        at = _skip(text, at + 1) if text[at] == "," else at
    return offsets


def _items(text: str, at: int, count: int) -> list[int]:
    """Offsets of the first ``count`` items of the array whose '[' is at ``text[at]``."""
    offsets = []
    at = _skip(text, at + 1)
    for _ in range(count):
        offsets.append(at)
        _, at = _DECODER.raw_decode(text, at)
        at = _skip(text, _skip(text, at) + 1)
    return offsets


class _Lines:
    """The line of any offset of a text."""

    def __init__(self, text: str):
        self.ends = np.array([m.start() for m in re.finditer("\n", text)], dtype=np.int64)

    def __call__(self, offsets) -> np.ndarray:
        return np.searchsorted(self.ends, np.asarray(offsets, dtype=np.int64)) + 1


def _column(values: object, name: str, kind: str, unit: str, factor: float, text: str, at: int, line_of: _Lines,
            source: str) -> tuple[Column, np.ndarray]:
    """A JSON array of numbers as a column in SI, and the line of each item."""
    if not isinstance(values, list):
        raise CardError(f"{source}: line {line_of([at])[0]}: {name} is not an array of numbers")
    lines = line_of(_items(text, at, len(values)))
    bad = next((i for i, v in enumerate(values) if isinstance(v, bool) or not isinstance(v, (int, float))), None)
    if bad is not None:
        raise CardError(f"{source}: line {lines[bad]}: {name} item {bad + 1}: {show(json.dumps(values[bad]))} "
                        f"is not a number")
    numbers = np.array([v if isinstance(v, float) or abs(v) < 1e300 else math.inf for v in values], dtype=float)
    column = in_si(numbers, kind, unit, factor, lambda i: f"{source}: line {lines[i]}: {name} item {i + 1}",
                   lambda i: f"{numbers[i]:.9g}")
    return Column(column, unit, factor), lines


def read(file: CardFile) -> RawCard:
    """The raw card of a JSON card file (the two shapes of the module's description)."""
    text, source = file.text, file.source
    try:
        document = json.loads(text)
    except json.JSONDecodeError as exc:
        raise CardError(f"{source}: line {exc.lineno}: not valid JSON: {exc.msg} (column {exc.colno})") from None
    except RecursionError:
        raise CardError(f"{source}: not valid JSON: nested too deep") from None
    except ValueError as exc:
        raise CardError(f"{source}: not valid JSON: {digit_limit(exc) or exc}") from None
    if not isinstance(document, dict):
        raise CardError(f"{source}: a JSON card is an object with \"S\" and \"F\" arrays (or pumpjack's own "
                        f"output), not a {type(document).__name__}")
    line_of = _Lines(text)
    members = _members(text, _skip(text, 0))
    if "series" in document:
        return _written(document["series"], text, members["series"], line_of, source)
    if "S" not in document or "F" not in document:
        raise CardError(f"{source}: a JSON card has \"S\" and \"F\" arrays (positions [m], loads [kN]) and "
                        f"optionally \"SPM\", or the \"series\" of pumpjack's own -f json output")
    columns, lines = {}, {}
    for key, (kind, default) in SERVICE_UNITS.items():
        unit_key = f"{key}_unit"
        written = document.get(unit_key, default)
        where = f"{source}: line {line_of([members.get(unit_key, members[key])])[0]}: {unit_key}"
        unit, factor = unit_of(written if isinstance(written, str) else str(written), kind, None, where)
        columns[kind], lines[kind] = _column(document[key], key, kind, unit, factor, text, members[key], line_of,
                                             source)
    if len(columns["position"].values) != len(columns["load"].values):
        raise CardError(f"{source}: S has {len(columns['position'].values)} items and F "
                        f"{len(columns['load'].values)}; a card has one load for each position")
    count_points(len(lines["load"]), source)
    stated: dict = {"metadata": {}, "metadata_lines": {}}
    if document.get("SPM") is not None:
        line = int(line_of([members["SPM"]])[0])
        stated = {"metadata": {"spm": stated_spm(document["SPM"], f"{source}: line {line}")},
                  "metadata_lines": {"spm": line}}
    return assemble(source, columns, lines["position"], **stated)


def _written(series: object, text: str, at: int, line_of: _Lines, source: str) -> RawCard:
    """The surface card among the series of this tool's -f json output."""
    where = f"{source}: line {line_of([at])[0]}"
    if not isinstance(series, dict):
        raise CardError(f"{where}: \"series\" is not an object of columns")
    unknown = next((name for name in series if name not in written_names()), None)
    if unknown is not None:
        raise CardError(f"{where}: series {show(unknown)} is not a column pumpjack writes; a JSON card is "
                        f"pumpjack's own output or has \"S\" and \"F\" arrays")
    chosen = written_card(list(series))
    if chosen is None:
        raise CardError(f"{where}: the series hold no surface card (rod_load with time and position, position or "
                        f"crank_angle, as predict and downhole write)")
    offsets = _members(text, at)
    names = list(series)
    columns, lines = {}, {}
    for kind, (j, unit, factor) in chosen.items():
        columns[kind], lines[kind] = _column(series[names[j]], names[j], kind, unit, factor, text, offsets[names[j]],
                                             line_of, source)
    first = next(iter(chosen))
    sizes = {len(column.values) for column in columns.values()}
    if len(sizes) != 1:
        raise CardError(f"{where}: the series {', '.join(names[j] for j, _, _ in chosen.values())} differ in length")
    count_points(sizes.pop(), source)
    return assemble(source, columns, lines[first])
