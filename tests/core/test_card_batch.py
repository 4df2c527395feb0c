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


def test_cards_fit_alike_in_blocks_of_any_size(monkeypatch):
    """The fit evaluates and factorises the cards still iterating in blocks (fit._BLOCK): in blocks of
    5, 12 cards come out of fit_rotations to the bit as in one block and as each alone."""
    mechanism, cards = varied("sk8-3.5-4000", 12, seed=11)
    time = np.stack([card["time"] for card in cards])
    position = np.stack([card["position"] for card in cards])
    position = (position - position.min(axis=1, keepdims=True)) * (
        mechanism.dead_positions().stroke / np.ptp(position, axis=1, keepdims=True))
    whole = fit.fit_rotations(mechanism, time, position, 6)
    monkeypatch.setattr(fit, "_BLOCK", 5)
    blocks = fit.fit_rotations(mechanism, time, position, 6)
    alone = [fit.fit_rotations(mechanism, time[k:k + 1], position[k:k + 1], 6)[0] for k in (0, 7)]
    for a, b in zip(whole, blocks):
        assert np.array_equal(a.crank_angle, b.crank_angle) and np.array_equal(a.crank_speed, b.crank_speed)
        assert (a.rms, a.uniform_rms, a.offset, a.scale) == (b.rms, b.uniform_rms, b.offset, b.scale)
    for k, single in zip((0, 7), alone):
        assert np.array_equal(single.crank_acceleration, whole[k].crank_acceleration) and single.rms == whole[k].rms


def test_a_stage_starts_from_the_last_evaluation_of_the_one_before():
    """A stage's first evaluation takes k ds/dtheta, s and r from the last of the stage before (its new
    harmonics at zero leave the crank angles as they were) and gives the Jacobian and sums of squares
    a fresh evaluation gives."""
    mechanism, _ = varied("sk8-3.5-4000", 1)
    rng = np.random.default_rng(12)
    tc = np.tile(np.linspace(-4.5, 4.5, 180), (3, 1))
    p = rng.uniform(0.0, mechanism.dead_positions().stroke, tc.shape)
    for before, after in ((0, 2), (2, 6)):
        params = np.column_stack([rng.uniform(0.0, 6.0, 3), rng.uniform(0.6, 0.8, 3), rng.normal(0.0, 0.02, (3, 2 * before)),
                                  rng.normal(0.0, 0.01, 3), rng.uniform(0.98, 1.02, 3)])
        last, _ = fit._evaluate(mechanism, tc, p, params)
        wider = np.concatenate([params[:, :-2], np.zeros((3, 2 * (after - before))), params[:, -2:]], axis=1)
        fresh, fresh_cost = fit._evaluate(mechanism, tc, p, wider)
        reused, reused_cost = fit._evaluate(mechanism, tc, p, wider, last[[0, -2, -1]])
        assert relative_difference(reused, fresh) <= 1e-15 and relative_difference(reused_cost, fresh_cost) <= 1e-15


def test_time_cards_the_checks_single_out_are_prepared_alone():
    """place_cards checks the plain time cards of a group at once and hands a card that fails a check
    or draws a warning to the single path: a stroke 3 % long (a warning), rows reversed against
    their time stamps, a rod that does not move, one that only rises, a stroke 10 % short, NaN
    positions, integer columns, time stamps of another length, each among good cards, come back
    word for word as place_card makes them."""
    mechanism, cards = varied("sk8-3.5-4000", 12, seed=13)
    position = cards[0]["position"]
    cards[1] = {**cards[1], "position": cards[1]["position"] * 1.03}
    cards[2] = {**cards[2], "position": cards[2]["position"][::-1].copy(), "load": cards[2]["load"][::-1].copy()}
    cards[3] = {**cards[3], "position": np.full(position.size, 0.5)}
    cards[4] = {**cards[4], "position": np.linspace(0.0, 1.0, position.size)}
    cards[5] = {**cards[5], "position": cards[5]["position"] * 0.9}
    cards[6] = {**cards[6], "position": np.where(np.arange(position.size) == 7, np.nan, cards[6]["position"])}
    cards[7] = {**cards[7], "position": np.round(cards[7]["position"] * 1000).astype(int),
                "position_unit": ("mm", 0.001), "load": np.round(cards[7]["load"]).astype(int)}
    cards[8] = {**cards[8], "time": cards[8]["time"][:-1]}
    together = place_cards(mechanism, cards)
    for k, (batch, card) in enumerate(zip(together, cards)):
        alone = single(mechanism, card)
        assert type(batch) is type(alone), k
        if isinstance(alone, CardError):
            assert str(batch) == str(alone), k
        else:
            assert_same_placement(batch, alone)
    assert "positions scaled to the unit's stroke" in together[1].warnings[0]
    assert [isinstance(found, CardError) for found in together] == [False, False, True, True, True, True, True,
                                                                     True, True, False, False, False]


def test_cards_from_angles_is_card_from_angles_of_each_row():
    """Rows with repeated angles, an angle of 2 pi (what a remainder can round to) or NaN go the
    single way; every row's card and largest gap are card_from_angles' and largest_gap's."""
    rng = np.random.default_rng(14)
    theta = rng.uniform(0.0, 2 * np.pi, (6, 40))
    load = rng.normal(40e3, 5e3, theta.shape)
    theta[1, 5] = theta[1, 9]
    theta[2, 3] = 2 * np.pi
    theta[3, 0] = np.nan
    load[4, 2] = -0.0
    cards, gaps = fit.cards_from_angles(theta, load)
    for row, (card, gap) in enumerate(zip(cards, gaps)):
        expected = fit.card_from_angles(theta[row], load[row])
        assert np.array_equal(card.crank_angle, expected.crank_angle, equal_nan=True), row
        assert np.array_equal(card.load, expected.load, equal_nan=True), row
        assert np.array_equal(np.signbit(card.load), np.signbit(expected.load)), row
        assert np.array_equal(gap, fit.largest_gap(theta[row]), equal_nan=True), row
