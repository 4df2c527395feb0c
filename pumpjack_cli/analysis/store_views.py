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
    ("pump_condition", "downhole"),
    ("pump_condition_confidence", "downhole"),
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
    if "pump_fillage_percent" in by_name:
        shown.append(_sequence_column(shown))
    several = " (a row per option set where a card has several)" if len(lines) > len(cards) else ""
    return Result(f"{well}: {len(cards)} cards in time order{several} ({path})", (), tuple(shown))


#: The field page's columns of each well's latest card: (suffixed stored name, analysis, heading).
FIELD = (
    ("gearbox_loading_percent", "torque", "gearbox loading"),
    ("peak_net_torque_n_m", "torque", "peak net torque"),
    ("cyclic_load_factor", "torque", "cyclic load factor"),
    ("max_rod_load_n", "downhole", "PPRL"),
    ("pump_fillage_percent", "downhole", "pump fillage"),
    ("pump_displacement_m3_d", "downhole", "production (pump displacement)"),
)


def _slug(well: str) -> str:
    return "well-" + "".join(c if c.isalnum() else "-" for c in well)


def field_page(path: Path):
    """`batch report`: a field on one page. A sortable table with one row per well and its latest
    card (by time stamp, then card): the loading, the pump condition (text columns named
    ``pump_condition*`` when the store has them, else "not available"), the fillage and the
    production (any stored ``*production*`` or ``*fluid_level*`` figure too); each well links to
    its section below, the trend of its cards (:func:`trend_result`)."""
    from ..names import written_names
    from ..page import Note, Page, Section, Table

    columns, rows = _stored_rows(path, None, None, "si")
    names = [stored for stored, _, _, _ in columns]
    kinds = {stored: TEXT if text else STORED for stored, _, _, text in columns}
    if not rows:
        raise PumpjackError(f"{path}: no results to report")
    index = {name: i for i, name in enumerate(names)}
    known = written_names()
    condition = [n for n in names if n.startswith("pump_condition") and kinds[n] == TEXT]
    extra = [n for n in names if ("production" in n or "fluid_level" in n) and n not in dict(
        (f[0], 0) for f in FIELD) and not n.startswith("pump_condition")]
    wells: dict[str, dict[tuple[str, str], dict]] = {}
    for row in rows:
        entry = wells.setdefault(row[index["well"]], {}).setdefault((row[index["timestamp"]], row[index["card"]]), {})
        entry[row[index["analysis"]]] = row

    def quantity(name: str) -> str:
        return TEXT if kinds.get(name) == TEXT else known.get(name, (name, STORED, "si"))[1]

    def internal(name: str, stored):
        """A stored number (SI display units: % for a fraction, MPa for a stress) as the SI value
        the page converts to its unit system; text as it is."""
        kind = quantity(name)
        if stored is None or kind in (TEXT, STORED) or isinstance(stored, str):
            return stored
        return stored / output_unit(kind, "si").scale

    def value(cards: dict, name: str, analysis: str | None = None):
        for which in ([analysis] if analysis else ["torque", "downhole"]):
            row = cards.get(which)
            if row is not None and name in index and row[index[name]] is not None:
                return internal(name, row[index[name]])
        return None

    headers = [("well", TEXT), ("time stamp", TEXT), ("card", TEXT), ("unit", TEXT), ("status", TEXT)]
    headers += [(heading, quantity(name)) for name, _, heading in FIELD]
    headers += [(name.replace("_", " "), TEXT) for name in condition] or [("pump condition", TEXT)]
    headers += [(name.replace("_", " "), quantity(name)) for name in extra]
    table_rows, links, sections = [], [], []
    for well in sorted(wells):
        cards = wells[well]
        latest = cards[max(cards)]
        first = next(iter(latest.values()))
        status = ", ".join(f"{a} {latest[a][index['status']]}" for a in ANALYSES if a in latest)
        cells = [well, first[index["timestamp"]], Path(first[index["card"]]).name, first[index["unit"]], status]
        cells += [value(latest, name, analysis) for name, analysis, _ in FIELD]
        cells += [value(latest, name) for name in condition] or ["not available"]
        cells += [value(latest, name) for name in extra]
        table_rows.append(tuple(cells))
        links.append(_slug(well))
        trend = trend_result(path, well)
        trend_headers = tuple((known.get(c.name, (c.name,))[0].replace("_", " "),
                               TEXT if c.quantity == TEXT else quantity(c.name)) for c in trend.columns)
        trend_rows = tuple(zip(*([internal(c.name, v) if c.name != "card" else Path(v).name for v in c.values]
                                 for c in trend.columns)))
        sections.append(Section(_slug(well), f"Well {well}: {len(trend_rows)} cards in time order",
                                (Table(trend_headers, trend_rows, sortable=True),)))
    field = Section("field", "Wells, latest card", (
        Table(tuple(headers), tuple(table_rows), tuple(links), sortable=True),
        Note("click a heading to sort; a well's name leads to its cards" + (
            "" if condition else "; pump condition: not available (the store holds no diagnosis)"),
             "text" if condition else "missing")))
    return Page(f"Field report: {len(wells)} wells", f"results store {path}", (field, *sections))

def _sequence_column(columns: list[Column]) -> Column:
    """What the well's consecutive cards say together, from the fillage card after card
    (:func:`~pumpjack_cli.core.rods.diagnosis.sequence_conditions`); a card without a fillage
    (its downhole analysis failed) keeps its neighbours' reading apart."""
    import numpy as np

    from ..core.rods.diagnosis import sequence_conditions

    fillage = next(c for c in columns if c.name == "pump_fillage_percent").values
    shares = np.array([np.nan if value is None else value / 100.0 for value in fillage], dtype=float)
    return Column("sequence_condition", [str(text) for text in sequence_conditions(shares)])
