"""Views of a results store as result tables: everything (`batch export`) and one well card after card (`batch trend`)."""

from __future__ import annotations

from pathlib import Path

from ..errors import PumpjackError
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


def _sequence_column(columns: list[Column]) -> Column:
    """What the well's consecutive cards say together, from the fillage card after card
    (:func:`~pumpjack_cli.core.rods.diagnosis.sequence_conditions`); a card without a fillage
    (its downhole analysis failed) keeps its neighbours' reading apart."""
    import numpy as np

    from ..core.rods.diagnosis import sequence_conditions

    fillage = next(c for c in columns if c.name == "pump_fillage_percent").values
    shares = np.array([np.nan if value is None else value / 100.0 for value in fillage], dtype=float)
    return Column("sequence_condition", [str(text) for text in sequence_conditions(shares)])
