"""Cards of one unit placed together (``place_cards``, ``fit_rotations``) equal the same cards placed
one by one (``place_card``, ``fit_rotation``).

Truth is the single-card path: the batch evaluates the same model for all the cards still
iterating at once, and each card must take the sequence of iterates its own fit takes. The
cards are the bundled sample cards varied as ``benchmarks/bench_batch.py`` varies them (load
scaled about its mean by 0.9-1.1, Gaussian noise of 0.3 % of the load range, time stamps
stretched for 0.95-1.05 times the speed), plus position noise of 1e-4 of the stroke so that the
cards need different numbers of iterations; built in memory.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam import card as fit
from pumpjack_cli.core.cards import CardSamples, PlacedCard, place_card, place_cards
from pumpjack_cli.errors import CardError
from pumpjack_cli.readers.cards import read_card

from helpers import sample_card

#: Per-sample and per-card figures of a time fit compared between the two paths.
ARRAYS = ("crank_angle", "crank_speed", "crank_acceleration", "load")
SCALARS = ("speed", "fit_rms", "fit_rms_relative")


def varied(unit: str, count: int, seed: int = 1) -> tuple[object, list[CardSamples]]:
    """The unit's mechanism and ``count`` variations of its sample card, as place_card's keywords."""
    mechanism = load_unit(unit).geometry.mechanism()
    raw = read_card(sample_card(unit))
    rng = np.random.default_rng(seed)
    stroke = mechanism.dead_positions().stroke
    cards = []
    for k in range(count):
        mean = raw.load.mean()
        load = mean + rng.uniform(0.9, 1.1) * (raw.load - mean) + rng.normal(0.0, 0.003 * np.ptp(raw.load), raw.load.size)
        position = raw.position + rng.normal(0.0, 1e-4 * stroke, raw.position.size)
        cards.append(CardSamples(load=load, position=position, time=raw.time / rng.uniform(0.95, 1.05),
                                 source=f"card-{k:02d}.csv", position_unit=raw.column_units["position"]))
    return mechanism, cards


def relative_difference(a, b) -> float:
    """Largest difference over the largest magnitude (0 when both are the same)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), np.finfo(float).tiny))


def assert_same_placement(batch: PlacedCard, single: PlacedCard) -> None:
    """The two placements agree to 1e-12 relative; the figures of a time fit are None on both or on neither."""
    for name in ARRAYS + SCALARS:
        if getattr(single, name) is None:
            assert getattr(batch, name) is None, name
        else:
            assert relative_difference(getattr(batch, name), getattr(single, name)) <= 1e-12, name
    assert relative_difference(batch.card.crank_angle, single.card.crank_angle) <= 1e-12
    assert relative_difference(batch.card.load, single.card.load) <= 1e-12
    assert (batch.warnings, batch.source, batch.reversed) == (single.warnings, single.source, single.reversed)


def single(mechanism, card: CardSamples) -> PlacedCard | CardError:
    try:
        return place_card(mechanism, **card)
    except CardError as error:
        return error


def test_fifty_cards_together_equal_each_alone():
    """50 SK8-3,5-4000 cards of 180 samples: one group, one fit of all of them."""
    mechanism, cards = varied("sk8-3.5-4000", 50)
    together = place_cards(mechanism, cards)
    assert len(together) == 50
    speeds = set()
    for batch, card in zip(together, cards):
        assert isinstance(batch, PlacedCard)
        assert_same_placement(batch, place_card(mechanism, **card))
        speeds.add(batch.speed)
    assert len(speeds) == 50  # the cards differ: each its own fit


def test_a_mark_ii_card_together_equals_alone():
    """The class III mechanism (Mark II, M-912D-365-168) through the same batched fit."""
    mechanism, cards = varied("m-912d-365-168", 12, seed=3)
    for batch, card in zip(place_cards(mechanism, cards), cards):
        assert isinstance(batch, PlacedCard)
        assert_same_placement(batch, place_card(mechanism, **card))


def test_bad_cards_come_back_as_their_errors_and_leave_the_others_alone():
    """Among good cards: a card of the wrong stroke (refused before the fit), one whose time stamps
    do not increase (refused by the fit's input check), one of another unit's motion (refused
    after the fit) and one with no positions; each comes back as the error place_card raises,
    with its message, and the good cards as they are alone."""
    mechanism, cards = varied("sk8-3.5-4000", 8, seed=5)
    cards[1] = {**cards[1], "position": cards[1]["position"] * 1.3}
    time = cards[3]["time"].copy()
    time[10], time[11] = time[11], time[10]
    cards[3] = {**cards[3], "time": time}
    jumbled = np.random.default_rng(0).permutation(cards[5]["position"])
    rising = np.roll(jumbled, -1) > np.roll(jumbled, 1)
    cards[5] = {**cards[5], "position": jumbled, "load": np.where(rising, 52e3, 40e3)}
    cards[6] = CardSamples(load=cards[6]["load"], source="card-06.csv")
    together = place_cards(mechanism, cards)
    for k, (batch, card) in enumerate(zip(together, cards)):
        alone = single(mechanism, card)
        if k in (1, 3, 5, 6):
            assert isinstance(batch, CardError) and isinstance(alone, CardError), k
            assert str(batch) == str(alone), k
        else:
            assert isinstance(batch, PlacedCard) and isinstance(alone, PlacedCard), k
            assert_same_placement(batch, alone)
    assert str(together[1]).startswith("card-01.csv: card stroke")
    assert str(together[3]) == "time fit: time must increase strictly"
    assert str(together[5]).startswith("card-05.csv: the time stamps do not fit this unit's motion")


def test_cards_of_other_kinds_and_sizes_go_one_by_one():
    """An angle card, a position card, a time card of a different length and a reversed position
    card among time cards: each placed as place_card places it."""
    mechanism, cards = varied("sk8-3.5-4000", 4, seed=7)
    short = {key: value[::2] if isinstance(value, np.ndarray) else value for key, value in cards[0].items()}
    angles = CardSamples(load=cards[1]["load"], crank_angle=np.linspace(0.0, 2 * np.pi, 180, endpoint=False))
    position_only = CardSamples(load=cards[2]["load"], position=cards[2]["position"], source="position.csv")
    backwards = CardSamples(load=cards[2]["load"][::-1], position=cards[2]["position"][::-1], source="backwards.csv")
    mixed = [short, angles, cards[1], position_only, cards[2], backwards, cards[3]]
    together = place_cards(mechanism, mixed)
    for batch, card in zip(together, mixed):
        assert isinstance(batch, PlacedCard)
        assert_same_placement(batch, place_card(mechanism, **card))
    assert [batch.speed is None for batch in together] == [False, True, False, True, False, True, False]
    assert together[5].reversed
    assert place_cards(mechanism, []) == []


def test_fit_rotations_names_the_card_it_refuses():
    mechanism, cards = varied("sk8-3.5-4000", 3)
    time = np.stack([card["time"] for card in cards])
    position = np.stack([card["position"] for card in cards])
    position[2, 5] = np.nan
    with pytest.raises(CardError, match=r"^time fit: time and position must be finite numbers \(card 2\)$"):
        fit.fit_rotations(mechanism, time, position)
    with pytest.raises(CardError, match="needs matching 2-D arrays"):
        fit.fit_rotations(mechanism, time[0], position[0])


def test_the_other_rotation_direction_is_tried_per_card():
    """A card of the counterclockwise twin among clockwise cards: its warning, as alone."""
    mechanism, cards = varied("sk8-3.5-4000", 3, seed=9)
    twin = dataclasses.replace(mechanism, rotation=-mechanism.rotation)
    time = np.arange(180) * 0.05
    theta = 0.3 + 0.7 * time
    motion = twin.motion(theta)
    load = np.where(motion.beam_rate > 0, 52e3, 40e3)
    cards.insert(1, CardSamples(load=load, position=motion.rod_position, time=time, source="ccw.csv"))
    together = place_cards(mechanism, cards)
    assert len(together[1].warnings) == 1 and "fit counterclockwise rotation better" in together[1].warnings[0]
    for batch, card in zip(together, cards):
        assert_same_placement(batch, place_card(mechanism, **card))


def test_the_batched_steps_are_the_least_squares_solutions():
    """Householder QR of [J r] and back substitution give lstsq's solution for full-rank J; a
    rank-deficient J (a column repeated) and an underdetermined one (fewer rows than columns)
    get lstsq's minimum-norm solution."""
    rng = np.random.default_rng(2)
    augmented = rng.normal(size=(5, 40, 9))
    augmented[1, :, 3] = augmented[1, :, 2]
    steps = fit._steps(augmented)
    for k in range(5):
        expected = np.linalg.lstsq(augmented[k, :, :8], -augmented[k, :, 8], rcond=None)[0]
        assert relative_difference(steps[k], expected) < 1e-12
    wide = rng.normal(size=(2, 6, 9))
    for k, step in enumerate(fit._steps(wide)):
        assert np.array_equal(step, np.linalg.lstsq(wide[k, :, :8], -wide[k, :, 8], rcond=None)[0])
