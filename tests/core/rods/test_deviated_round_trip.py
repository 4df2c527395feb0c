"""Round trip of a deviated well: the predicted surface card of the J-shaped hole (vertical to 500 m, build
3 deg/30 m to 45 deg, hold; samples/make_deviated.py) diagnosed with the same survey gives back the
predicted pump card, and a diagnosis that ignores the drag does not.

The two directions are different solvers (a time march with the pump's valves; a march in depth from the
surface card), so the agreement is the model's, not an identity. What cannot come back exactly: where parts
of the string stick while the load transfers, the drag holding them is whatever keeps them still, which the
surface card does not show sample by sample; the regularised law then passes small position errors on as
drag (docs/deviated.md: about 2-3 % of F_o rms, at the valve events).
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.rods.analysis import card_work, summarise_pump_card
from pumpjack_cli.core.rods.deviated_diagnostic import deviated_damping_from_fluid_load, deviated_pump_card

from helpers import REPO_ROOT


def test_the_committed_samples_are_what_the_script_makes(deviated_sample):
    module, (found, omega, unit) = deviated_sample
    assert (REPO_ROOT / "samples" / "j-well-survey.csv").read_text(encoding="utf-8") == module.survey_text()
    assert (REPO_ROOT / "samples" / "sk8-3.5-4000-deviated-card.csv").read_text(encoding="utf-8") == \
        module.card_text(found, omega, unit)


@pytest.fixture(scope="module")
def round_trip(deviated_sample):
    module, (found, omega, unit) = deviated_sample
    cards, rods, path = found.cards, unit.rods(), module.path()

    def diagnose(mu: float, nu: float = module.DAMPING):
        return deviated_pump_card(rods, path, cards.summary.period, cards.polished_rod_position, cards.polished_rod_load,
                                  fluid_density=unit.well.fluid_density, damping_factor=nu, friction_coefficient=mu)

    return module, found, diagnose, rods, path, unit


def test_the_diagnosis_gives_back_the_predicted_pump_card(round_trip):
    module, found, diagnose, *_ = round_trip
    cards = found.cards
    back = diagnose(module.FRICTION)
    f_o, stroke = cards.summary.fluid_load, cards.summary.polished_rod_stroke
    predicted_work = float(card_work(cards.plunger_position, cards.pump_load))
    assert float(card_work(back.card.pump_position, back.card.pump_load)) == pytest.approx(predicted_work, rel=0.02)
    shift = back.card.pump_position - cards.plunger_position  # the two datums differ by a constant
    assert np.max(np.abs(shift - np.mean(shift))) < 0.01 * stroke
    levels = summarise_pump_card(back.card.pump_position, back.card.pump_load)
    truth = summarise_pump_card(cards.plunger_position, cards.pump_load)
    assert float(levels.upstroke_load) == pytest.approx(float(truth.upstroke_load), abs=0.02 * f_o)
    assert float(levels.downstroke_load) == pytest.approx(float(truth.downstroke_load), abs=0.02 * f_o)
    assert np.sqrt(np.mean((back.card.pump_load - cards.pump_load) ** 2)) < 0.1 * f_o
    assert back.friction_work == pytest.approx(found.friction_work, rel=0.02)


def test_a_diagnosis_that_ignores_the_drag_misses_the_work_by_far_more(round_trip):
    module, found, diagnose, *_ = round_trip
    cards = found.cards
    bare = diagnose(0.0)
    predicted_work = float(card_work(cards.plunger_position, cards.pump_load))
    assert float(card_work(bare.card.pump_position, bare.card.pump_load)) > 1.3 * predicted_work
    assert np.sqrt(np.mean((bare.card.pump_load - cards.pump_load) ** 2)) > 0.2 * cards.summary.fluid_load


def test_the_energy_balance_finds_the_damping_with_the_drag(round_trip):
    """Gibbs' way of fixing the damping, with the drag taking its share of the surface work."""
    module, found, _, rods, path, unit = round_trip
    cards = found.cards
    nu = deviated_damping_from_fluid_load(rods, path, cards.summary.period, cards.polished_rod_position,
                                          cards.polished_rod_load, cards.summary.fluid_load,
                                          fluid_density=unit.well.fluid_density, friction_coefficient=module.FRICTION)
    assert nu == pytest.approx(module.DAMPING, rel=0.03)
