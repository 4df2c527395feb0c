"""Views of a results store as result tables: everything (`batch export`) and one well card after card (`batch trend`).

Both show the stored summary numbers in a unit system: SI as stored, or field units with
the suffixes of the single commands (``peak_net_torque_lbf_in``), each stored column
mapped back to its output name and quantity through the catalogue
(:mod:`pumpjack_cli.names`).
"""

from __future__ import annotations

import itertools
import json
from functools import cache
from pathlib import Path

from ..errors import PumpjackError
from ..names import TEXT, catalogue
from ..quantities import output_unit
from ..readers.store import Store
from ..results import STORED, Column, Result, display_name
from .batch.per_card import ANALYSES

#: The summary values of `batch trend`, the consecutive-card view of a well: name, analysis.
TREND = (
    ("peak_net_torque_n_m", "torque"),
    ("gearbox_loading_percent", "torque"),
    ("cyclic_load_factor", "torque"),
    ("polished_rod_power_w", "torque"),
    ("max_rod_load_n", "downhole"),
    ("min_rod_load_n", "downhole"),
    ("fluid_load_n", "downhole"),
    ("pump_fillage_percent", "downhole"),
    ("net_pump_stroke_m", "downhole"),
    ("pump_displacement_m3_d", "downhole"),
    ("surface_card_work_j", "downhole"),
    ("pump_card_work_j", "downhole"),
)


@cache
def _stored_names() -> dict[str, tuple[str, str]]:
    """The column name a number is stored under (its SI suffix) -> its output name and quantity."""
    return {display_name(name, quantity, "si"): (name, quantity)
            for name, (quantity, _) in catalogue().items() if quantity != TEXT}


def _shown(stored: str, system: str) -> tuple[str, float]:
    """The name of a stored number's column in a unit system and the factor from the stored
    value; a name the catalogue does not know is shown as stored."""
    if stored not in _stored_names():
        return stored, 1.0
    name, quantity = _stored_names()[stored]
    return display_name(name, quantity, system), output_unit(quantity, system).scale / output_unit(quantity, "si").scale


def _stored_rows(path: Path, well: str | None, analysis: str | None, system: str) -> tuple[list, list[tuple]]:
    """The stored columns of an existing store as (stored name, shown name, factor, is text)
    and its rows."""
    store = Store(path)
    try:
        names, rows = store.rows(well, analysis)
        columns = [(name, name, 1.0, True) if store.is_text(name) else (name, *_shown(name, system), False)
                   for name in names]
    finally:
        store.close()
    return columns, rows


def _column(shown: str, values: list, factor: float, text: bool, description: str) -> Column:
    """A column of stored values, numbers scaled by ``factor`` (None where a row has none)."""
    if not text and factor != 1.0:
        values = [None if value is None else value * factor for value in values]
    return Column(shown, values, quantity=TEXT if text else STORED, description=description)


def export_result(path: Path, analysis: str | None, well: str | None, system: str = "si") -> Result:
    """Every stored row (of one analysis and one well if given): the fixed fields and text
    summary values as text, the summary numbers in ``system`` (SI as stored, or field units
    under field suffixes), empty where a row has none."""
    if analysis is not None and analysis not in ANALYSES:
        raise PumpjackError(f"--analysis {analysis}: use one of {', '.join(ANALYSES)}")
    columns, rows = _stored_rows(path, well, analysis, system)
    if well is not None and not rows:
        raise PumpjackError(f"--well {well}: no {analysis + ' ' if analysis else ''}results for this well in {path}")
    return Result(f"{path}: {len(rows)} results", (), tuple(
        _column(shown, [row[i] for row in rows], factor, text, shown.replace("_", " "))
        for i, (_, shown, factor, text) in enumerate(columns)))


def _settings(row: dict) -> dict[str, object]:
    """What made a stored result, flat: its options as they are written on the command
    line (``--method``), its overrides and file digests, the card file's digest; a store of
    version 0, which kept only the hash, gives the hash."""
    data = json.loads(row["options"]) if row.get("options") else {"options": row["options_sha256"][:12]}
    options = data.pop("options") if isinstance(data.get("options"), dict) else {}
    data.pop("analysis", None)
    return {**{f"--{key.replace('_', '-')}": value for key, value in options.items()}, **data,
            "card file": row["card_sha256"][:12]}


def _said(key: str, value: object) -> str:
    if value is None:
        return f"no {key}"
    shown = value[:12] if isinstance(value, str) and len(value) == 64 else value
    return f"{key} {shown}"


def _labels(rows: list[dict]) -> list[str]:
    """For the results of one card and analysis: what differs between them ("--method
    exact"), empty for a single result."""
    if len(rows) < 2:
        return [""] * len(rows)
    settings = [_settings(row) for row in rows]
    keys = list(dict.fromkeys(key for each in settings for key in each))
    differing = [key for key in keys if len({json.dumps(each.get(key)) for each in settings}) > 1]
    return [", ".join(_said(key, each.get(key)) for key in differing) for each in settings]


def _results_of(found: dict[str, list[dict]], analysis: str) -> list[tuple[dict | None, str]]:
    """(result, label) of each stored result of one card's analysis; (None, "") if it has none."""
    results = found.get(analysis, [])
    return list(zip(results, _labels(results))) or [(None, "")]


def trend_result(path: Path, well: str, system: str = "si") -> Result:
    """One well's cards in time order (timestamp, then card) with the numbers operators follow
    from card to card; a card whose analysis failed shows its status and empty numbers. A
    card with results of several option sets (a run with ``--method api`` and one with
    ``--method exact``) has a row per set, labelled by what differs in an ``options`` column."""
    columns, rows = _stored_rows(path, well, None, system)
    if not rows:
        raise PumpjackError(f"--well {well}: no results for this well in {path}")
    names = [stored for stored, _, _, _ in columns]
    cards: dict[tuple[str, str], dict[str, list[dict]]] = {}
    for row in rows:
        entry = dict(zip(names, row))
        cards.setdefault((entry["timestamp"], entry["card"]), {}).setdefault(entry["analysis"], []).append(entry)
    lines = []
    for key in sorted(cards):
        for (torque, first), (downhole, second) in itertools.product(
                *(_results_of(cards[key], analysis) for analysis in ANALYSES)):
            lines.append((key, "; ".join(label for label in (first, second) if label),
                          {"torque": torque, "downhole": downhole}))
    shown = [Column("timestamp", [key[0] for key, _, _ in lines]), Column("card", [key[1] for key, _, _ in lines])]
    if any(label for _, label, _ in lines):
        shown.append(Column("options", [label for _, label, _ in lines]))
    for analysis in ANALYSES:
        shown.append(Column(f"{analysis}_status", [found[analysis]["status"] if found[analysis] else ""
                                                   for _, _, found in lines]))
    by_name = {stored: (name, factor, text) for stored, name, factor, text in columns}
    for stored, analysis in TREND:
        if stored in by_name:
            name, factor, text = by_name[stored]
            shown.append(_column(name, [found[analysis][stored] if found[analysis] else None for _, _, found in lines],
                                 factor, text, f"{name.replace('_', ' ')} ({analysis})"))
    several = " (a row per option set where a card has several)" if len(lines) > len(cards) else ""
    return Result(f"{well}: {len(cards)} cards in time order{several} ({path})", (), tuple(shown))
