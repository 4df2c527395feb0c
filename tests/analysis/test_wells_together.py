"""The cards of one unit analysed together equal each card analysed alone.

`torques` and `downholes` solve K cards of one unit as one array computation (the torques,
peaks and duties on the summary grid; the dampings, Gibbs transfers, pump-card figures and
conditions); the single commands are the same functions with one card. Here the K-card
results are compared with the one-card results number by number (1e-12 relative: the same
operations per card, only stacked), for units of every kind with a sample card, with a card
among them that cannot be analysed, and with cards whose balance fails.
"""

from __future__ import annotations

import math

import pytest

from pumpjack_cli.analysis.card_runs import CardSource
from pumpjack_cli.analysis.downhole import Production, downholes
from pumpjack_cli.analysis.torque import torques
from pumpjack_cli.config import load_unit
from pumpjack_cli.errors import PumpjackError

from helpers import field_cards

UNITS = ("sk8-3.5-4000", "c-114d-133-54", "m-912d-365-168")


def _same(together, alone) -> None:
    (result_k, said_k), (result_1, said_1) = together, alone
    assert said_k == said_1
    if isinstance(result_1, PumpjackError):
        assert isinstance(result_k, PumpjackError) and str(result_k) == str(result_1)
        return
    assert [s.name for s in result_k.summary] == [s.name for s in result_1.summary]
    for a, b in zip(result_k.summary, result_1.summary):
        if isinstance(b.value, str):
            assert a.value == b.value, a.name
        else:
            assert a.value == pytest.approx(b.value, rel=1e-12, abs=1e-300) or (math.isnan(a.value)
                                                                                and math.isnan(b.value)), a.name


def _cards(tmp_path, unit: str, count: int = 12) -> list[CardSource]:
    """``count`` variations of the unit's sample card (swing, noise, speed)."""
    return [CardSource(tmp_path / name) for _, _, name, _ in field_cards(tmp_path, count, seed=7, units=(unit,))]


@pytest.mark.parametrize("unit_name", UNITS)
def test_torque_of_many_cards_equals_each_card_alone(tmp_path, monkeypatch, unit_name):
    """12 cards in blocks of 5 (the block's arrays are the cards', whatever the block)."""
    import pumpjack_cli.analysis.torque as torque_module

    monkeypatch.setattr(torque_module, "BLOCK", 5)
    unit = load_unit(unit_name)
    cards = _cards(tmp_path, unit_name)
    together = torques(unit, cards, None, 8, "auto", "api", "equal-peaks")
    for k, card in enumerate(cards):
        _same(together[k], torques(unit, [card], None, 8, "auto", "api", "equal-peaks")[0])
    assert all(not isinstance(r, PumpjackError) for r, _ in together)


@pytest.mark.parametrize("unit_name", UNITS)
def test_downhole_of_many_cards_equals_each_card_alone(tmp_path, unit_name):
    unit = load_unit(unit_name)
    if unit.well is None:
        pytest.skip(f"{unit_name} has no well")
    cards = _cards(tmp_path, unit_name)
    together = downholes(unit, cards, None, "auto", None, None)
    for k, card in enumerate(cards):
        _same(together[k], downholes(unit, [card], None, "auto", None, None)[0])
    assert all(not isinstance(r, PumpjackError) for r, _ in together)


def _without(unit, change):
    """The unit with its data changed by ``change`` (a function of its unit-file dictionary)."""
    data = unit.model_dump(by_alias=True)
    change(data)
    return type(unit).model_validate(data)


def _no_pressures(data):
    data["well"]["pump_submergence"] = data["well"]["pump_intake_pressure"] = None


def _no_grade(data):
    data["well"]["rod_string"][0]["grade"] = None


@pytest.mark.parametrize("production", [
    Production(runtime=0.75),   # the unit's plunger fit: the slippage
    Production(runtime=0.5, pump_efficiency=0.85, system_efficiency=0.8, electricity_price=3e-8),
])
@pytest.mark.parametrize("change", [None, _no_pressures, _no_grade])
def test_the_production_and_warnings_of_many_cards_equal_each_card_alone(tmp_path, production, change):
    """The well's figures (intake pressure, fluid level, slippage, production, energy) and the rods'
    Goodman loadings, found once for the unit and as arrays for the cards, and each card's
    warnings (a fluid level clipped, no pressures for the damping, no grade for the Goodman
    loading), with tables and without."""
    unit = load_unit("sk8-3.5-4000")
    unit = unit if change is None else _without(unit, change)
    cards = _cards(tmp_path, "sk8-3.5-4000", 6)
    for tables in (False, True):
        together = downholes(unit, cards, None, "auto", None, None, service_factor=0.9, production=production,
                             tables=tables)
        for k, card in enumerate(cards):
            _same(together[k], downholes(unit, [card], None, "auto", None, None, service_factor=0.9,
                                         production=production, tables=tables)[0])
    said = " ".join(" ".join(notes) for _, notes in together)
    assert ("Goodman loading is left out" in said) == (change is _no_grade)
    assert ("damping factor 0.05 assumed" in said) == (change is _no_pressures)


def test_a_card_that_cannot_be_read_does_not_change_the_others(tmp_path):
    unit = load_unit("sk8-3.5-4000")
    cards = _cards(tmp_path, "sk8-3.5-4000", 6)
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,position_m,load_kN\n0,0,1\n1,1,nan\n", encoding="utf-8")
    mixed = [*cards[:3], CardSource(bad), *cards[3:]]
    for analysis in (lambda cs: torques(unit, cs, None, 8, "auto", "api", "equal-peaks"),
                     lambda cs: downholes(unit, cs, None, "auto", None, None)):
        together = analysis(mixed)
        assert isinstance(together[3][0], PumpjackError)
        for k, card in enumerate(mixed):
            _same(together[k], analysis([card])[0])


def test_a_card_whose_figures_fail_sends_every_card_alone(tmp_path):
    """A card with no positive mean torque has no cyclic load factor: the K-card figures fail,
    and every card is answered alone, that card with its message, the others as alone. The
    card is the crank runs of a sample card with its load turned upside down (the rods pushing
    the unit), for each balance criterion."""
    import dataclasses

    from pumpjack_cli.analysis.card_runs import card_runs
    from pumpjack_cli.analysis.torque import SUMMARY_STEPS, card_torques

    unit = load_unit("sk8-3.5-4000")
    mechanism = unit.geometry.mechanism()
    found = [card_runs(unit, mechanism, card, None, (8, SUMMARY_STEPS), "auto") for card in _cards(tmp_path, "sk8-3.5-4000", 4)]
    cards, runs = [r.card for r, _ in found], [list(run) for _, run in found]
    cards[2] = dataclasses.replace(cards[2], load=-cards[2].load)
    runs[2] = [dataclasses.replace(run, load=-run.load) for run in runs[2]]
    for criterion in ("equal-peaks", "min-rms", "min-peak"):
        together = card_torques(unit, cards, runs, "api", criterion)
        assert isinstance(together[2][0], PumpjackError)
        for k in range(4):
            alone = card_torques(unit, [cards[k]], [runs[k]], "api", criterion)[0]
            if isinstance(alone[0], PumpjackError):
                assert str(together[k][0]) == str(alone[0])
            else:
                _same((_result(together[k]), together[k][1]), (_result(alone), alone[1]))


def _result(found):
    """A CardTorque as a result of its summaries, for :func:`_same`."""
    from pumpjack_cli.results import Result

    torque, _ = found
    return Result("", torque.card_summary + torque.summary, ())
