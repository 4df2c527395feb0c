"""Dynamometer-card files read without any unit: :func:`read_card` -> :class:`RawCard`.

A reader turns the content of one file format into a :class:`RawCard` (SI columns, the
line of every sample, what the file states, warnings); putting the card on a unit's
crank-angle axis is :func:`pumpjack_cli.core.cards.place_card`, once per run.

**The registry.** :data:`READERS` maps a format name to its :class:`Reader`. Adding a
format is one module in this package, with a function ``read(file) -> RawCard`` that
takes a :class:`CardFile` (the content as read, bytes or text, with ``file.text`` decoding
it as UTF-8 or refusing it in one line, the file's name and the card options) and
refuses a bad file with a one-line :class:`~pumpjack_cli.errors.CardError`, a function
``recognises(file) -> bool`` (True when the content is surely of this format) and the
file name endings it claims, plus one line in :data:`READERS`. A file whose format is not
given is read by the first reader that recognises its content (the specific formats come
before delimited text, which takes any line with a comma), else by the one that claims
its name's ending, else as :data:`DEFAULT_FORMAT`.

A card with time stamps whose positions go through several strokes is a continuous
recording, split into its strokes whatever its format (:mod:`.recording`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path, PurePath
from typing import IO

from ...errors import CardError
from ...text_input import display_name, read_bytes
from . import block, delimited, json_card, recording
from .raw import DEFAULT_UNITS, MAX_POINTS, MIN_POINTS, CardFile, RawCard, checked_columns, parse_card_columns

__all__ = ["DEFAULT_FORMAT", "MAX_BYTES", "READERS", "CardFile", "RawCard", "Reader", "parse_card_columns",
           "read_card"]

MAX_BYTES = 10_000_000


@dataclass(frozen=True)
class Reader:
    """One card format: its parser, how its content is recognised, its file name endings."""

    read: Callable[[CardFile], RawCard]
    recognises: Callable[[CardFile], bool]
    extensions: tuple[str, ...] = ()


#: Format name -> reader, in the order their content is recognised.
READERS = {
    "json": Reader(json_card.read, json_card.recognises, json_card.EXTENSIONS),
    "hex": Reader(block.read_hex, block.recognises_hex, block.HEX_EXTENSIONS),
    "binary": Reader(block.read_binary, block.recognises_binary, block.BINARY_EXTENSIONS),
    "delimited": Reader(delimited.read, delimited.recognises, delimited.EXTENSIONS),
}
#: The format of a file no reader recognises.
DEFAULT_FORMAT = "delimited"


def _format_of(file: CardFile, path: Path | str) -> str:
    """The format of a card file: by content, by the name's ending, else the default.

    The last reader's content is not looked at when the name's ending (or the default) chooses
    that reader anyway: a delimited card named .csv is not searched for its header twice.
    """
    *specific, last = READERS
    for name in specific:
        if READERS[name].recognises(file):
            return name
    suffix = (path if isinstance(path, PurePath) else Path(str(path))).suffix.lower()
    fallback = next((name for name, reader in READERS.items() if suffix in reader.extensions), DEFAULT_FORMAT)
    return last if last == fallback or READERS[last].recognises(file) else fallback


def check_options(format: str | None = None, units: str | None = None, points: int | None = None) -> None:
    """Refuse an unknown card format or unit system, or a block size out of range, in one line
    (before anything is read)."""
    if format is not None and format not in READERS:
        raise CardError(f"--card-format {format!r}: use {', '.join(READERS)}")
    if units is not None and units not in DEFAULT_UNITS:
        raise CardError(f"--card-units {units!r}: use {' or '.join(DEFAULT_UNITS)}")
    if points is not None and not MIN_POINTS <= points <= MAX_POINTS:
        raise CardError(f"--card-points {points}: a card block has {MIN_POINTS} to {MAX_POINTS} points")


def read_card(path: Path | str, format: str | None = None, units: str | None = None,
              columns: Mapping[str, str] | None = None, *, points: int | None = None,
              stream: IO | None = None) -> RawCard:
    """Read a card file, whatever unit it was measured on.

    Parameters
    ----------
    path : pathlib.Path or str
        The card file; ``"-"`` reads ``stream`` (standard input by default), named
        ``<stdin>`` in messages.
    format : str, optional
        A name of :data:`READERS`; by default told from the content and the file name.
    units : str, optional
        Units of columns whose file names none: ``"si"`` (m, N, s, deg) or ``"field"``
        (in, lbf, s, deg); without them such a column is refused (a binary block names none).
    columns : mapping, optional
        Kind -> header text (:func:`parse_card_columns`); the mapped columns are
        used and every other column is ignored.
    points : int, optional
        Points of a binary or hex card block (``--card-points``; by default
        :data:`.block.DEFAULT_POINTS`).
    stream : file object, optional
        Text or binary stream read when ``path`` is ``"-"``.

    Returns
    -------
    RawCard
        The samples in SI and time order, their lines, what the file states, the reader's
        warnings; for a file of several cards (a recording, a hex file of several lines)
        the last, with every one in ``strokes``.

    Raises
    ------
    CardError
        One line naming the file, the line and the column of the problem.
    """
    check_options(format, units, points)
    mapping = None if columns is None else checked_columns(columns.items())
    source = display_name(path)
    file = CardFile(read_bytes(path, MAX_BYTES, "card file", CardError, stream), source, units, mapping, points)
    card = READERS[format or _format_of(file, path)].read(file)
    return recording.split(card) if card.time is not None and not card.strokes else card
