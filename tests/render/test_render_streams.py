"""The renderer's streamed JSON against the json module: the same text, block by block.

``write_json`` writes the series block by block from the arrays (never one Python list
per column); its text must be exactly ``json.dumps(document, indent=1)`` plus a newline,
with the document built here independently from the columns. Checked for a result of
several blocks with numbers (unit conversion included), text and stored columns with
missing values, for one without rows and one without columns.
"""

from __future__ import annotations

import io
import json
import math

import numpy as np
import pytest

from pumpjack_cli.render.delimited import write_json
from pumpjack_cli.render.display import CSV_BLOCK
from pumpjack_cli.results import STORED, Column, Result, Scalar

from helpers import INCH

ROWS = 2 * CSV_BLOCK + 17


def _document(result: Result, system: str) -> str:
    """The expected text: json.dumps of the whole document built from the columns."""
    unit, factor = {"si": ("m", 1.0), "field": ("in", 1.0 / INCH)}[system]
    position, name, value = result.columns
    document = {
        "title": result.title,
        "units": system,
        "summary": {f"stroke_{unit}": 2.5 * factor},
        "columns": {f"position_{unit}": {"unit": unit, "description": position.description},
                    "name": {"unit": "", "description": name.description},
                    "value": {"unit": "", "description": "stored"}},
        # a converted value is written to 15 significant digits (README "Output"), an SI one as computed
        "series": {f"position_{unit}": [float(v) * factor if factor == 1.0 else float(f"{float(v) * factor:.15g}")
                                        for v in position.values], "name": list(name.values),
                   "value": list(value.values)},
    }
    return json.dumps(document, indent=1) + "\n"


def _full(result: Result, system: str) -> str:
    written = io.StringIO()
    write_json(result, system, written)
    return written.getvalue()


def _result(rows: int) -> Result:
    rng = np.random.default_rng(5)
    position = rng.normal(size=rows) * 10.0 ** rng.integers(-6, 6, size=rows)
    names = [f"well \"{i}\" é" for i in range(rows)]
    stored = [None if i % 7 == 0 else (f"t{i}" if i % 5 == 0 else i / 3) for i in range(rows)]
    return Result("streamed: \u00b0 and \"quotes\"", (Scalar("stroke", 2.5),),
                  (Column("position", position), Column("name", names),
                   Column("value", stored, quantity=STORED, description="stored")))


@pytest.mark.parametrize("system", ["si", "field"])
@pytest.mark.parametrize("rows", [ROWS, 1, 0])
def test_streamed_json_is_the_json_modules_text(system, rows):
    result = _result(rows)
    text = _full(result, system)
    assert text == _document(result, system)
    parsed = json.loads(text)
    assert len(parsed["series"]["name"]) == rows
    assert all(math.isfinite(v) for v in parsed["series"][f"position_{'m' if system == 'si' else 'in'}"])


def test_a_result_without_columns():
    result = Result("nothing", (Scalar("stroke", 2.5),), ())
    text = _full(result, "si")
    assert text == json.dumps({"title": "nothing", "units": "si", "summary": {"stroke_m": 2.5}, "columns": {},
                               "series": {}}, indent=1) + "\n"


def test_a_name_given_twice_is_refused_where_the_result_is_made():
    """Summary and columns are keyed by name in every output (JSON objects, the store's columns, the
    CSV summary's rows): a name given twice would drop one value and shift the rows after it."""
    with pytest.raises(ValueError, match="the summary value stroke is given twice"):
        Result("t", (Scalar("stroke", 1.0), Scalar("stroke", 1.0)), ())
    with pytest.raises(ValueError, match="the column position is given twice"):
        Result("t", (), (Column("position", np.zeros(2)), Column("position", np.ones(2))))
