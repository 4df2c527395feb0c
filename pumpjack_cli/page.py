"""A page of results: the engineer's report (`pumpjack report`, `batch report`).

A :class:`Page` lays out results (:mod:`pumpjack_cli.results`) as sections of values, tables,
figures and notes; :mod:`pumpjack_cli.render.html` writes it as one self-contained HTML file.
Only the commands that make a page import this module.
"""

from __future__ import annotations

from dataclasses import dataclass

from .results import Result, Scalar


@dataclass(frozen=True)
class Values:
    """Summary values of a result shown on a page: the scalars named (those the result has), each
    with its meaning, its value in the page's unit system and its unit; ``source`` names the
    command whose ``-f json`` summary the values equal (the page keys each by it)."""

    source: str
    result: Result
    names: tuple[str, ...]

    def present(self) -> tuple[Scalar, ...]:
        """The named scalars the result has, in the order named."""
        found = {s.name: s for s in self.result.summary}
        return tuple(found[name] for name in self.names if name in found)


@dataclass(frozen=True)
class SideBySide:
    """Pairs of summary values of one result shown side by side (the present counterbalance
    and the recommended one): rows of (label, first name, second name), ``columns`` the two
    headings."""

    source: str
    result: Result
    columns: tuple[str, str]
    rows: tuple[tuple[str, str, str], ...]


@dataclass(frozen=True)
class Quantities:
    """Input data shown on a page: rows of (label, SI value or text, quantity kind) converted to
    the page's unit system (text shown as it is)."""

    rows: tuple[tuple[str, float | str, str], ...]


@dataclass(frozen=True)
class Table:
    """A table of text and numbers: headers, each with its quantity kind ("" or ``text`` for
    text; numbers are SI and shown in the page's units), the rows, and optionally a link target
    per row (an anchor on the page). ``sortable``: the reader can sort it by a column."""

    headers: tuple[tuple[str, str], ...]
    rows: tuple[tuple[object, ...], ...]
    links: tuple[str | None, ...] = ()
    sortable: bool = False


@dataclass(frozen=True)
class Figure:
    """The plot panels of a result (all, or those ``panels`` lists by title) drawn inline."""

    result: Result
    panels: tuple[str, ...] = ()


@dataclass(frozen=True)
class Note:
    """A paragraph (``kind``: ``text``, ``warning`` or ``missing`` for what is not available)."""

    text: str
    kind: str = "text"


@dataclass(frozen=True)
class Section:
    """One section of a page: an anchor, a heading and its blocks."""

    anchor: str
    title: str
    blocks: tuple[object, ...]


@dataclass(frozen=True)
class Page:
    """A page of results (one self-contained HTML file): title, subtitle, sections."""

    title: str
    subtitle: str
    sections: tuple[Section, ...]
