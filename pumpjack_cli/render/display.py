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
