"""Column values and unit labels in the chosen unit system, shared by the CSV and JSON
writers and the terminal table (text and stored columns pass through)."""

from __future__ import annotations

from typing import Any

from ..quantities import output_unit
from ..results import STORED, TEXT, Column

#: Rows converted and written at a time (CSV rows, JSON series, lines of a table).
CSV_BLOCK = 4096


def _is_array(values: Any) -> bool:
    return hasattr(values, "dtype")


def display_values(column: Column, values: Any, system: str) -> list:
    """Values (a slice of a column) in display units as Python objects; text and missing values
    (None) pass through."""
    if column.quantity in (TEXT, STORED):
        return list(values)
    unit = output_unit(column.quantity, system)
    if _is_array(values):
        return unit.convert(values.astype(float, copy=False)).tolist()
    return [None if v is None else unit.convert(float(v)) for v in values]


def unit_label(quantity: str, system: str) -> str:
    """The unit label of a quantity in the system ("" for text and stored columns)."""
    return "" if quantity in (TEXT, STORED) else output_unit(quantity, system).label


def display_number(value: float, quantity: str = "") -> str:
    """A number rounded for reading (a page, a legend): whole numbers from 1000 up, grouped by
    spaces ("84 362"); four significant digits below ("215.1", "3.264"); three below 1
    ("0.0523"); angles to 0.1 degree; never "-0" (CSV and JSON keep the full value).

    >>> [display_number(v) for v in (84362.31, 215.137, 3.26412, 0.052349, -0.0, 699999.9999999999, -1e-12)]
    ['84 362', '215.1', '3.264', '0.0523', '0', '700 000', '-1e-12']
    >>> display_number(46.00384, "angle"), display_number(-0.04, "angle")
    ('46.0', '0.0')
    """
    if quantity == "angle":
        text = f"{value:.1f}"
    elif value != value or value in (float("inf"), float("-inf")):
        text = str(value)
    elif abs(value) >= 1e15:
        text = f"{value:.4g}"
    elif abs(value) >= 1000:
        text = f"{value:,.0f}".replace(",", " ")
    elif abs(value) >= 1:
        text = f"{value:.4g}"
    elif value == 0:
        text = "0"
    elif abs(value) >= 1e-4:
        text = f"{value:.3g}"
    else:
        text = f"{value:.3g}"
    return "0" + text[2:] if text.startswith("-0") and float(text.replace(" ", "")) == 0 else text
