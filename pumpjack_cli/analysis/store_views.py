"""Views of a results store as result tables: everything (`batch export`) and one well card after card (`batch trend`)."""

from __future__ import annotations

from pathlib import Path

from ..errors import PumpjackError
from ..quantities import output_unit
from ..readers.store import Store
from ..results import STORED, TEXT, Column, Result
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


def _stored_rows(path: Path, well: str | None, analysis: str | None = None) -> tuple[list[str], list[tuple], dict]:
    """Column names, rows and each column's quantity kind (text columns, the fixed fields
    among them, as TEXT; numbers as STORED) of an existing store."""
    store = Store(path, create=False)
    try:
        names, rows = store.rows(well, analysis)
        kinds = {name: TEXT if store.is_text(name) else STORED for name in names}
    finally:
        store.close()
    return names, rows, kinds


def export_result(path: Path, analysis: str | None, well: str | None) -> Result:
    """Every stored row (of one analysis and one well if given): the fixed fields and text
    summary values as text, the summary numbers as stored (SI, suffixed names), empty where
    a row has none."""
    if analysis is not None and analysis not in ANALYSES:
        raise PumpjackError(f"--analysis {analysis}: use one of {', '.join(ANALYSES)}")
    names, rows, kinds = _stored_rows(path, well, analysis)
    if well is not None and not rows:
        raise PumpjackError(f"--well {well}: no {analysis + ' ' if analysis else ''}results for this well in {path}")
    columns = tuple(Column(name, [row[i] for row in rows], quantity=kinds[name], description=name.replace("_", " "))
                    for i, name in enumerate(names))
    return Result(f"{path}: {len(rows)} results", (), columns)


def trend_result(path: Path, well: str) -> Result:
    """One well's cards in time order (timestamp, then card) with the numbers operators follow
    from card to card; a card whose analysis failed shows its status and empty numbers."""
    names, rows, kinds = _stored_rows(path, well)
    if not rows:
        raise PumpjackError(f"--well {well}: no results for this well in {path}")
    index = {name: i for i, name in enumerate(names)}
    cards: dict[tuple[str, str], dict] = {}
    for row in rows:
        entry = cards.setdefault((row[index["timestamp"]], row[index["card"]]), {})
        entry[row[index["analysis"]]] = row
    order = sorted(cards)
    columns = [Column("timestamp", [key[0] for key in order]), Column("card", [key[1] for key in order])]
    for analysis in ("torque", "downhole"):
        columns.append(Column(f"{analysis}_status", [cards[key][analysis][index["status"]] if analysis in cards[key]
                                                     else "" for key in order]))
    for name, analysis in TREND:
        if name not in index:
            continue
        columns.append(Column(name, [cards[key][analysis][index[name]] if analysis in cards[key] else None
                                     for key in order], quantity=kinds[name],
                              description=f"{name.replace('_', ' ')} ({analysis})"))
    if "pump_fillage_percent" in index:
        columns.append(_sequence_column(columns))
    return Result(f"{well}: {len(order)} cards in time order ({path})", (), tuple(columns))


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
    from ..results import Note, Page, Section, Table

    names, rows, kinds = _stored_rows(path, None)
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
