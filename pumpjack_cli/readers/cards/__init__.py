"""Dynamometer-card files read without any unit: :func:`read_card` -> :class:`RawCard`.

A reader turns the text of one file format into a :class:`RawCard` (SI columns, the
line of every sample, warnings); putting the card on a unit's crank-angle axis is
:func:`pumpjack_cli.core.cards.place_card`, once per run.

**The registry.** :data:`READERS` maps a format name to its :class:`Reader`. Adding a
format is one module in this package, with a function ``read(text, source,
default_units, mapping) -> RawCard`` that refuses a bad file with a one-line
:class:`~pumpjack_cli.errors.CardError`, a function ``recognises(text) -> bool`` (True
when the content is surely of this format) and the file name endings it claims, plus
one line in :data:`READERS`. A file whose format is not given is read by the first
reader that recognises its content, else by the one that claims its name's ending, else
as :data:`DEFAULT_FORMAT`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import IO

from ...errors import CardError
from ...text_input import display_name, read_text
from . import delimited
from .raw import DEFAULT_UNITS, RawCard, checked_columns, parse_card_columns

__all__ = ["DEFAULT_FORMAT", "MAX_BYTES", "READERS", "RawCard", "Reader", "parse_card_columns", "read_card"]

MAX_BYTES = 10_000_000


@dataclass(frozen=True)
class Reader:
    """One card format: its parser, how its content is recognised, its file name endings."""

    read: Callable[[str, str, str | None, dict[str, str] | None], RawCard]
    recognises: Callable[[str], bool]
    extensions: tuple[str, ...] = ()


#: Format name -> reader.
READERS = {
    "delimited": Reader(delimited.read, delimited.recognises, delimited.EXTENSIONS),
}
#: The format of a file no reader recognises.
DEFAULT_FORMAT = "delimited"


def _format_of(text: str, path: Path | str) -> str:
    """The format of a card file: by content, by the name's ending, else the default."""
    suffix = Path(str(path)).suffix.lower()
    return next((name for name, reader in READERS.items() if reader.recognises(text)),
                next((name for name, reader in READERS.items() if suffix in reader.extensions), DEFAULT_FORMAT))


def read_card(path: Path | str, format: str | None = None, units: str | None = None,
              columns: Mapping[str, str] | None = None, *, stream: IO | None = None) -> RawCard:
    """Read a card file, whatever unit it was measured on.

    Parameters
    ----------
    path : pathlib.Path or str
        The card file; ``"-"`` reads ``stream`` (standard input by default), named
        ``<stdin>`` in messages.
    format : str, optional
        A name of :data:`READERS`; by default told from the content and the file name.
    units : str, optional
        Units of columns whose header names none: ``"si"`` (m, N, s, deg) or
        ``"field"`` (in, lbf, s, deg); without them such a column is refused.
    columns : mapping, optional
        Kind -> header text (:func:`parse_card_columns`); the mapped columns are
        used and every other column is ignored.
    stream : file object, optional
        Text or binary stream read when ``path`` is ``"-"``.

    Returns
    -------
    RawCard
        The samples in SI and time order, their lines, the reader's warnings.

    Raises
    ------
    CardError
        One line naming the file, the line and the column of the problem.
    """
    if format is not None and format not in READERS:
        raise CardError(f"card format {format!r}: use {' or '.join(READERS)}")
    if units is not None and units not in DEFAULT_UNITS:
        raise CardError(f"card units {units!r}: use {' or '.join(DEFAULT_UNITS)}")
    mapping = None if columns is None else checked_columns(columns.items())
    text = read_text(path, MAX_BYTES, "card file", CardError, stream)
    reader = READERS[format or _format_of(text, path)]
    return reader.read(text, display_name(path), units, mapping)
