"""The plausibility rule from the command line: one card, one message, whichever command reads it.

A 1000-fold slip upwards is already refused by the reader (a load beyond 10 MN, a position
beyond 1 km), downwards by the rule. The wrong-unit card of issue 21 is the SK8-3,5-4000 sample card (loads in kN) under a
``load_lbf`` header. The 1000-fold slips multiply a sample card's load or position numbers
by 1000 or 1/1000 under the same header, for a card in SI (kN, m) and one in field units
(lbf, in).
"""

from __future__ import annotations

import re
import sqlite3

import pytest

from helpers import SK8, sample_card

#: Every single command that reads a card.
CARD_COMMANDS = ("torque", "downhole", "reactions", "dynamics", "compare-redundancy")


def _card(tmp_path, unit: str, *, header=None, column: int | None = None, factor: float = 1.0, name="card.csv"):
    """A sample card with its header replaced, or one column's numbers scaled."""
    lines = sample_card(unit).read_text(encoding="utf-8").splitlines()
    out = []
    for line in lines:
        if line.startswith("#") or not line[0].isdigit():
            out.append(line if header is None or line.startswith("#") else header(line))
            continue
        values = line.split(",")
        if column is not None:
            values[column] = repr(float(values[column]) * factor)
        out.append(",".join(values))
    path = tmp_path / name
    path.write_text("\n".join(out) + "\n", encoding="utf-8")
    return path


def test_the_wrong_unit_card_is_refused_with_one_message_by_every_command(run_cli, tmp_path):
    card = _card(tmp_path, SK8, header=lambda line: line.replace("load_kN", "load_lbf"), name="wrongunit.csv")
    errors = set()
    for command in CARD_COMMANDS:
        code, out, err = run_cli(command, SK8, "--card", card)
        assert code == 2 and out == "" and err.count("\n") == 1, (command, err)
        errors.add(err)
    assert len(errors) == 1
    message = errors.pop().removeprefix("pumpjack: error: ").strip()
    assert "these rods cannot have made this card" in message and message.endswith("kN written as lbf?")
    # batch: an error row of both analyses with the same message
    manifest = tmp_path / "manifest.csv"
    manifest.write_text(f"well,unit,card\nw1,{SK8},{card}\n", encoding="utf-8")
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", "run", manifest, "--store", store, "--workers", "1")
    assert code == 0, err
    rows = sqlite3.connect(store).execute("SELECT status, error FROM results").fetchall()
    assert len(rows) == 2 and all(status == "error" and error == message for status, error in rows)


@pytest.mark.parametrize("unit, slips", [
    (SK8, {1000.0: "beyond 10 MN: not a polished-rod load; check the column's unit",
           1e-3: "these rods cannot have made this card.*kN written as N, or klbf as lbf\\?"}),
    ("c-114d-133-54", {1000.0: "beyond 10 MN: not a polished-rod load; check the column's unit",
                       1e-3: "these rods cannot have made this card.*kN written as N, or klbf as lbf\\?"}),
])
@pytest.mark.parametrize("command", ["torque", "downhole"])
def test_a_thousandfold_load_slip_is_refused_in_si_and_field_units(run_cli, tmp_path, unit, slips, command):
    for factor, words in slips.items():
        card = _card(tmp_path, unit, column=2, factor=factor)
        code, out, err = run_cli(command, unit, "--card", card)
        assert code == 2 and out == "" and err.count("\n") == 1, err
        assert re.search(words + "$", err.strip()), err


@pytest.mark.parametrize("unit, header, factor, words", [
    (SK8, None, 1000.0, "beyond 1 km: not a polished-rod position; check the column's unit"),
    (SK8, None, 1e-3, "differs from the unit's exact stroke .*; wrong unit, crank hole or position units\\?"),
    (SK8, ("position_m", "position_mm"), 1.0, "differs from the unit's exact stroke .*; positions in m written as mm\\?"),
    (SK8, ("position_m", "position_in"), 1.0, "differs from the unit's exact stroke .*; positions in m written as in\\?"),
    ("c-114d-133-54", None, 1000.0, "beyond 1 km: not a polished-rod position; check the column's unit"),
    ("c-114d-133-54", None, 1e-3, "differs from the unit's exact stroke .*; wrong unit, crank hole or position units\\?"),
    ("c-114d-133-54", ("position_in", "position_m"), 1.0,
     "differs from the unit's exact stroke .*; positions in in written as m\\?"),
])
@pytest.mark.parametrize("command", ["torque", "downhole"])
def test_a_position_slip_is_refused_in_si_and_field_units(run_cli, tmp_path, unit, header, factor, words, command):
    relabel = None if header is None else (lambda line: line.replace(*header))
    card = _card(tmp_path, unit, header=relabel, column=1, factor=factor)
    code, out, err = run_cli(command, unit, "--card", card)
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert re.search(words + "$", err.strip()), err
