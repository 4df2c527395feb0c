"""What every analysis returns: a titled table of SI columns, summary values and plot panels.

A :class:`Result` declares each output column once, with its name, quantity kind,
description and values; the renderer (:mod:`pumpjack_cli.render`) turns it into a
terminal table, CSV, JSON or a plot, and the commands only choose which columns the
terminal table shows by default (:meth:`Result.showing`). Names follow
``docs/glossary.md``; the renderer adds the unit suffix of the chosen unit system.

This module imports nothing heavy: values may be numpy arrays or lists of text.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from .errors import PumpjackError
from .names import TEXT, lookup, suffixed
from .quantities import OutputUnit, output_unit

#: Quantity of a column of numbers already in SI display units under their suffixed
#: names (a results store's columns): shown as they are, None where a value is missing.
STORED = "stored"


@dataclass(frozen=True)
class Column:
    """A per-row series: an output name of the catalogue (:mod:`pumpjack_cli.names`, which
    gives its quantity kind and description) and its values (SI; a list may hold None where a
    value is missing, shown empty, or null in JSON). ``brief`` columns are the
    ones the terminal table shows; CSV, JSON and plots carry every column. A results store's
    columns, already suffixed and converted, give ``quantity=STORED`` and a description."""

    name: str
    values: Any
    brief: bool = False
    quantity: str = ""
    description: str = ""

    def __post_init__(self) -> None:
        if not self.quantity:
            quantity, description = lookup(self.name)
            object.__setattr__(self, "quantity", quantity)
            object.__setattr__(self, "description", description)


@dataclass(frozen=True, slots=True)
class Scalar:
    """One summary value: an output name of the catalogue (:mod:`pumpjack_cli.names`, which
    gives its quantity kind and description) and its value, a number (SI) or a text (a label)."""

    name: str
    value: float | str

    @property
    def quantity(self) -> str:
        """The quantity kind of the catalogue."""
        return lookup(self.name)[0]

    @property
    def description(self) -> str:
        """The meaning of the catalogue."""
        return lookup(self.name)[1]


@dataclass(frozen=True)
class Curve:
    """A further curve of a plot panel: two column names (x, y), or explicit SI values of
    one ``quantity`` on both axes (e.g. points of a Goodman diagram), or of ``quantity`` on
    x and ``y_quantity`` on y; NaN values break the line. ``style`` is a matplotlib format
    ("-", "--", "o"), ``color`` a matplotlib colour (None: the next of the cycle). The
    ``label`` may hold ``{}`` placeholders, one per ``label_values`` pair (quantity, SI
    value), which the renderer fills in the plot's unit system (a strength on psi axes is
    written in psi)."""

    label: str
    x: str | tuple[float, ...]
    y: str | tuple[float, ...]
    quantity: str | None = None
    style: str = "-"
    y_quantity: str | None = None
    color: str | None = None
    label_values: tuple[tuple[str, float], ...] = ()


@dataclass(frozen=True)
class Mark:
    """A vertical line on every plot panel whose x axis is the column ``column``: ``value``
    (SI) and its ``label`` (the dead positions: crank angles, or the ends of the stroke on
    a card)."""

    label: str
    column: str
    value: float


@dataclass(frozen=True)
class Panel:
    """One plot panel: solid curves and dashed curves (column names) against the column
    ``x`` (default: the first column), and horizontal lines at ``levels`` ((label, SI
    value) pairs in the quantity of the first solid curve, e.g. a rating). With ``clip``
    the vertical range follows the solid curves and the nearest approach of the others,
    so that a bound that grows without limit does not hide them. ``curves`` are drawn
    too; a panel of curves only names its x axis ``x_label``. Legends name the columns in
    words (:func:`~pumpjack_cli.names.words`) unless ``labels`` give (column, label) pairs.
    With ``colour`` (a column name) the solid curves are drawn as points coloured by that
    column, with a colour bar; ``y_down`` turns the vertical axis downward (a depth)."""

    title: str
    solid: tuple[str, ...]
    dashed: tuple[str, ...] = ()
    x: str | None = None
    levels: tuple[tuple[str, float], ...] = ()
    clip: bool = False
    curves: tuple[Curve, ...] = ()
    x_label: str | None = None
    colour: str | None = None
    y_down: bool = False
    labels: tuple[tuple[str, str], ...] = ()


@dataclass(frozen=True)
class Result:
    """Everything a command outputs: a title, summary values, columns and plot panels, SI;
    ``marks``, the vertical lines of its plots (the dead positions)."""

    title: str
    summary: tuple[Scalar, ...]
    columns: tuple[Column, ...]
    panels: tuple[Panel, ...] = ()
    marks: tuple[Mark, ...] = ()

    def __post_init__(self) -> None:
        for kind, names in (("summary value", [s.name for s in self.summary]), ("column", [c.name for c in self.columns])):
            if len(set(names)) == len(names):
                continue
            twice = sorted({name for name in names if names.count(name) > 1})
            raise ValueError(f"{self.title!r}: the {kind} {', '.join(twice)} is given twice")

    def column(self, name: str) -> Column:
        """The column called ``name``."""
        return next(c for c in self.columns if c.name == name)

    def showing(self, names: Iterable[str]) -> Result:
        """The same result with exactly the columns ``names`` shown in the terminal table."""
        shown = set(names)
        unknown = shown - {c.name for c in self.columns}
        if unknown:
            raise KeyError(f"no column {', '.join(sorted(unknown))} in {self.title!r}")
        return dataclasses.replace(
            self, columns=tuple(dataclasses.replace(c, brief=c.name in shown) for c in self.columns))

    @property
    def rows(self) -> int:
        """Number of rows (length of the first column; all columns have the same length)."""
        return len(self.columns[0].values) if self.columns else 0


def display_name(name: str, quantity: str, system: str) -> str:
    """Column or summary key with the unit suffix of the unit system (none for text, pure numbers
    or stored columns, already suffixed)."""
    return name if quantity == STORED else suffixed(name, quantity, system)


def converted_summary(result: Result, system: str) -> dict[str, float | str]:
    """Summary values in the display units of ``system``, keyed by suffixed name (text as it is).

    A number shown in the unit it is computed in (scale 1, no rounding: most of a summary in SI)
    is the value + 0.0, as :meth:`~.quantities.OutputUnit.convert` makes it, without the call."""
    shown = _shown(system)
    found: dict[str, float | str] = {}
    for s in result.summary:
        key, unit, as_computed = shown[s.name]
        value = s.value
        if isinstance(value, str) or unit is None:
            found[key] = value
        elif as_computed:
            found[key] = float(value) + 0.0
        else:
            found[key] = float(unit.convert(float(value)))
    return found


class _Shown(dict):
    """The suffixed name, the display unit (None for text) and whether it is the unit the value is
    computed in, of each summary name in one unit system: found when a name is first met."""

    def __init__(self, system: str) -> None:
        super().__init__()
        self.system = system

    def __missing__(self, name: str) -> tuple[str, OutputUnit | None, bool]:
        quantity = lookup(name)[0]
        unit = output_unit(quantity, self.system) if quantity != TEXT else None
        found = self[name] = (display_name(name, quantity, self.system), unit,
                              unit is not None and unit.scale == 1.0 and unit.decimals is None)
        return found


@functools.cache
def _shown(system: str) -> _Shown:
    """The summary names' display of a unit system (:class:`_Shown`), one table per system."""
    return _Shown(system)


def check_finite(result: Result) -> None:
    """Refuse to output NaN or infinity: name the value, or the column and the first bad row."""
    for s in result.summary:
        value = s.value
        if not (isinstance(value, str) or math.isfinite(value)):
            raise PumpjackError(f"result {s.name} is not finite ({value}); the computation failed")
    for c in result.columns:
        if c.quantity == TEXT:
            continue
        if c.quantity == STORED:
            first = next((i for i, v in enumerate(c.values) if v is not None and not math.isfinite(v)), None)
            if first is not None:
                raise PumpjackError(f"result column {c.name} is not finite at row {first} of {len(c.values)}")
            continue
        if hasattr(c.values, "dtype"):
            import numpy as np

            bad = np.flatnonzero(~np.isfinite(c.values.astype(float, copy=False)))
            first = int(bad[0]) if bad.size else None
        else:
            first = next((i for i, v in enumerate(c.values) if v is not None and not math.isfinite(float(v))), None)
        if first is not None:
            raise PumpjackError(f"result column {c.name} is not finite at row {first} of {len(c.values)}")
