"""Fixed card blocks as XSPOC-type card storage keeps them: N little-endian float32 loads, then N
positions, as a binary file of 8 N bytes (``binary``) or as hex text, one block per line (``hex``).

A block names no units: ``--card-units si`` reads positions in m and loads in N, ``field``
in in and lbf, and a block is refused without them. Pairs (0, 0) are padding (a card of
fewer than N points) and dropped. A block has no time stamps: it is a position card. A
hex file of several lines holds several cards, in the file's order (:func:`.raw.several`).
"""

from __future__ import annotations

import re

import numpy as np

from ...errors import CardError
from .raw import CardFile, Column, RawCard, assemble, count_points, in_si, is_content, several, show, unit_of

#: Points of a block when ``--card-points`` is not given.
DEFAULT_POINTS = 200
BINARY_EXTENSIONS = (".bin", ".dat")
HEX_EXTENSIONS = (".hex",)
_HEX = re.compile(r"[0-9A-Fa-f]*")


def _points(file: CardFile) -> int:
    return file.points or DEFAULT_POINTS


def recognises_binary(file: CardFile) -> bool:
    """True for content that is not text and is 8 N bytes long (N points, ``--card-points`` or 200)."""
    return isinstance(file.data, bytes) and len(file.data) == 8 * _points(file) and not file.is_text


def recognises_hex(file: CardFile) -> bool:
    """True when the first line that is not a comment or blank is 16 N hex digits."""
    line = next(file.content_lines(), "").strip()
    return len(line) == 16 * _points(file) and _HEX.fullmatch(line) is not None


def _card(data: bytes, file: CardFile, where: str, line: int | None) -> RawCard:
    """The position card of one block; ``where`` names the file (and line) in messages, and
    ``line`` is the file's line of every point (None: a binary file, whose points are numbered)."""
    values = np.frombuffer(data, dtype="<f4").astype(float)
    points = values.size // 2
    kept = np.flatnonzero((values[:points] != 0.0) | (values[points:] != 0.0))
    count_points(kept.size, f"{where}: after the (0, 0) padding")
    columns = {}
    for kind, numbers in (("load", values[:points][kept]), ("position", values[points:][kept])):
        unit, factor = unit_of(None, kind, file.units, where)
        columns[kind] = Column(in_si(numbers, kind, unit, factor, lambda i: f"{where}: point {kept[i] + 1}",
                                     lambda i: str(np.float32(numbers[i]))), unit, factor)
    lines = kept + 1 if line is None else np.full(kept.size, line)
    return assemble(file.source, columns, lines)


def _units(file: CardFile) -> None:
    if file.units is None:
        raise CardError(f"{file.source}: a card block names no units: give --card-units si (positions in m, loads "
                        f"in N) or field (in, lbf)")


def read_binary(file: CardFile) -> RawCard:
    """The position card of a binary block of 8 N bytes: N float32 loads, then N positions."""
    _units(file)
    points = _points(file)
    if not isinstance(file.data, bytes):
        raise CardError(f"{file.source}: text, not a binary card block")
    if len(file.data) != 8 * points:
        raise CardError(f"{file.source}: {len(file.data):,} bytes; a block of {points} points is {8 * points:,} "
                        f"bytes ({points} float32 loads, then {points} positions); give --card-points")
    return _card(file.data, file, file.source, None)


def read_hex(file: CardFile) -> RawCard:
    """The position cards of hex text, one block of 16 N hex digits per line; several lines are
    several cards (strokes), the last the one read unless ``--stroke`` picks another."""
    _units(file)
    points = _points(file)
    cards = []
    for number, line in enumerate(file.text.split("\n"), 1):
        if not is_content(line):
            continue
        digits = line.strip()
        where = f"{file.source}: line {number}"
        if _HEX.fullmatch(digits) is None:
            bad = next(char for char in digits if char not in "0123456789abcdefABCDEF")
            raise CardError(f"{where}: {show(bad)} is not a hex digit; a hex card block is one line of "
                            f"{16 * points} hex digits")
        if len(digits) != 16 * points:
            raise CardError(f"{where}: {len(digits)} hex digits; a block of {points} points is {16 * points} "
                            f"({points} float32 loads, then {points} positions); give --card-points")
        cards.append(_card(bytes.fromhex(digits), file, where, number))
    if not cards:
        raise CardError(f"{file.source}: empty card")
    return several(cards)
