"""The pump-condition rules on pump cards drawn by hand from each condition's physics.

Every card here is written from its defining law, not from the predictive model: a harmonic
plunger motion z = S (1 - cos theta) / 2 and the load the valves allow (a rectangle for a
full pump; the load held until the plunger meets the liquid for fluid pound; a polytropic
compression for gas; the orifice law of a leaking valve while the plunger moves slower than
the leak; the tubing's spring for unanchored tubing; a compressive or tensile spike at the
ends for tagging; a flat card below the zero line for a parted string). The corpus of
predicted cards is in ``test_diagnosis_corpus.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.rods.diagnosis import (CONDITIONS, _running_median, card_features, classify, condition_scores,
                                              diagnose, hanging_depth, sequence_conditions)
from pumpjack_cli.core.rods.string import RodString
from pumpjack_cli.errors import DownholeError

N = 200
STROKE = 2.0
F_O = 10e3
THETA = 2 * np.pi * np.arange(N) / N
Z = STROKE * (1 - np.cos(THETA)) / 2          # up from the bottom, the upstroke first
UP = THETA < np.pi
SPEED = STROKE * np.sin(THETA) / 2 * (2 * np.pi)      # dz/dtheta x 2 pi: speed in strokes-per-cycle units
MEAN_SPEED = 2 * STROKE                                # mean |dz/dt| over a unit period


def full():
    return np.where(UP, F_O, 0.0)


def pound(fillage):
    """The load stays F_o on the downstroke until the plunger meets the liquid at ``fillage`` of the stroke."""
    return np.where(UP | (Z > fillage * STROKE), F_O, 0.0)


def gas(fillage, ratio=15.0, exponent=1.2):
    """Gas between the valves: the downstroke compresses (1 - f) of the barrel from p_i to p_d = ratio p_i."""
    volume = np.clip(Z - fillage * STROKE, 1e-9, None) / ((1 - fillage) * STROKE)   # V / V_top
    pressure = np.clip(volume**-exponent, 1.0, ratio)                              # p / p_i
    load = F_O * (ratio - pressure) / (ratio - 1.0)
    return np.where(UP, F_O, load)


def leaking(valve, share):
    """Orifice law: a shut valve passes Q sqrt(dp / dp_o); while the plunger moves slower than
    v_L = Q / A_p the load is F_o (v / v_L)^2 (travelling) or F_o (1 - (v / v_L)^2) (standing)."""
    v = np.abs(SPEED) / (share * MEAN_SPEED)
    if valve == "travelling":
        return np.where(UP, F_O * np.minimum(v, 1.0)**2, 0.0)
    return np.where(UP, F_O, F_O * np.clip(1.0 - v**2, 0.0, 1.0))


def unanchored(stretch):
    """The tubing spring: the load follows the plunger over ``stretch`` after each reversal."""
    load = np.where(UP, np.minimum(Z / stretch, 1.0), np.minimum((Z - STROKE + stretch) / stretch, 1.0))
    return F_O * np.clip(load, 0.0, 1.0)


def tagged(end, spike, samples=5):
    """The stop meets the plunger ``samples`` before the end of its stroke: the load swings by
    ``spike`` F_o (down at the bottom, up at the top) and back, a triangle in time."""
    load = full()
    turn = N if end == "bottom" else N // 2
    pulse = spike * F_O * (1.0 - np.abs(np.arange(-samples, samples + 1)) / (samples + 1))[:samples]
    load[turn - samples:turn] += -pulse if end == "bottom" else pulse
    return load


def parted(hanging):
    """A flat loop ``hanging`` F_o below the zero line, no fluid load."""
    return -hanging * F_O + 0.05 * F_O * np.sin(THETA)


CARDS = {
    "full": full(),
    "fluid_pound": pound(0.6),
    "gas_interference": gas(0.6),
    "travelling_valve_leak": leaking("travelling", 0.5),
    "standing_valve_leak": leaking("standing", 0.5),
    "tagging_down": tagged("bottom", 0.5),
    "tagging_up": tagged("top", 0.5),
    "unanchored_tubing": unanchored(0.05 * STROKE),
    "rod_part": parted(1.5),
}


@pytest.mark.parametrize("condition", CONDITIONS)
def test_each_condition_drawn_from_its_law_gets_its_label(condition):
    found = diagnose(Z, CARDS[condition], F_O)
    assert found.label.tolist() == [condition]
    assert 0.0 < found.confidence[0] <= 1.0


def test_every_card_of_a_well_at_once_gives_each_card_its_own_answer():
    # one call over K cards (the vectorised path of a batch) equals K calls of one card
    loads = np.vstack([CARDS[c] for c in CONDITIONS])
    many = diagnose(np.tile(Z, (len(CONDITIONS), 1)), loads, F_O)
    assert many.label.tolist() == list(CONDITIONS)
    for k, condition in enumerate(CONDITIONS):
        one = diagnose(Z, CARDS[condition], F_O)
        assert np.array_equal(one.scores[0], many.scores[k])


@pytest.mark.parametrize("condition", CONDITIONS)
def test_the_answer_does_not_depend_on_where_the_record_starts_or_on_the_unit(condition):
    # a controller starts its cards anywhere in the stroke; the load unit scales loads and F_o alike
    base = card_features(Z, CARDS[condition], F_O)
    for shift in (17, 101, 163):
        moved = card_features(np.roll(Z, shift), 4.4482216152605 * np.roll(CARDS[condition], shift),
                              4.4482216152605 * F_O)
        for name in ("fillage", "travelling_valve_opening", "standing_valve_opening", "fluid_load_ratio",
                     "slow_upstroke_load", "slow_downstroke_load", "bottom_spike", "top_spike"):
            assert np.allclose(getattr(moved, name), getattr(base, name), equal_nan=True), name
    assert diagnose(np.roll(Z, 57), np.roll(CARDS[condition], 57), F_O).label[0] == condition


@pytest.mark.parametrize("window", [3, 5, 9])
def test_the_running_median_stays_within_the_upstroke_and_within_the_downstroke(window):
    # against the median of each sample's window, its indices held to the sample's own part (the
    # upstroke up to the top, the downstroke after it), computed sample by sample
    samples = 40
    values = np.random.default_rng(window).standard_normal((4, samples))
    top = np.array([0, 7, 25, samples - 1])
    found = _running_median(values, top, window)
    half = window // 2
    for k in range(len(values)):
        for i in range(samples):
            first, last = (0, top[k]) if i <= top[k] else (top[k] + 1, samples - 1)
            around = np.clip(np.arange(i - half, i + half + 1), first, last)
            assert found[k, i] == np.median(values[k, around]), (k, i)


def test_the_valve_points_and_fillage_of_a_pounding_pump_are_where_the_load_crosses():
    # the liquid at 60 % of the stroke: the standing valve closes, the fillage and the travelling valve
    # opens there (to the interpolation between two samples); the upstroke transfer is at the bottom
    ft = card_features(Z, pound(0.6), F_O)
    step = float(np.max(np.diff(Z)))
    for name in ("standing_valve_closing", "fillage", "travelling_valve_opening"):
        assert float(getattr(ft, name)[0]) == pytest.approx(0.6, abs=step / STROKE)
    assert float(ft.travelling_valve_closing[0]) == pytest.approx(0.0, abs=1e-12)
    # the area: a fillage of the ideal rectangle F_o x S
    assert float(ft.area_ratio[0]) == pytest.approx(0.6, abs=0.02)


def test_the_transfer_travels_of_unanchored_tubing_are_its_stretch():
    # the load picked up from 10 % to 90 % over 0.8 of the stretch, and released likewise
    stretch = 0.05 * STROKE
    ft = card_features(Z, unanchored(stretch), F_O)
    step = float(np.max(np.diff(Z)))
    assert float(ft.pickup_travel[0]) == pytest.approx(0.8 * stretch, abs=2 * step)
    assert float(ft.unloading_travel[0]) == pytest.approx(0.8 * stretch, abs=2 * step)


def test_gas_releases_its_load_gradually_and_pound_at_once():
    # the compression curve of gas from p_i to 15 p_i with n = 1.2 releases 80 % of the load over
    # (2.4^-1/1.2 - 13.6^-1/1.2) = 0.370 of the gas share (1 - f); a pound, within a sample
    gassy, pounding = card_features(Z, gas(0.6), F_O), card_features(Z, pound(0.6), F_O)
    expected = (2.4**(-1 / 1.2) - 13.6**(-1 / 1.2)) * 0.4 * STROKE
    assert float(gassy.unloading_travel[0]) == pytest.approx(expected, rel=0.1)
    assert float(pounding.unloading_travel[0]) < float(np.max(np.diff(Z)))
    # the travelling valve opens where the gas reached p_d: liquid + compressed gas
    assert float(gassy.travelling_valve_opening[0]) == pytest.approx(0.6 + 0.4 * 15**(-1 / 1.2), abs=0.01)


def test_a_parted_string_is_told_from_a_pump_with_no_fluid_load():
    # below the zero line by the weight of the lost rods: rod part; on the zero line, no fluid load: a
    # part at the pump or a travelling valve stuck open, the second label; on the F_o line: the
    # standing valve does not hold ([EchometerPumpCards])
    assert diagnose(Z, parted(1.0), F_O).label[0] == "rod_part"
    at_pump = diagnose(Z, parted(0.0), F_O)
    assert at_pump.label[0] == "rod_part"
    stuck = diagnose(Z, F_O + 0.05 * F_O * np.sin(THETA), F_O)
    assert stuck.label[0] == "standing_valve_leak" and stuck.second[0] == "gas_interference"


def test_scores_are_probabilities_of_a_sort_and_the_second_label_is_given_when_close():
    scores = condition_scores(card_features(np.tile(Z, (3, 1)), np.vstack([full(), pound(0.6), pound(0.91)]), F_O))
    assert ((scores >= 0) & (scores <= 1)).all()
    near = classify(card_features(Z, pound(0.91), F_O))          # 9 % short: between full and pound
    assert {near.label[0], near.second[0]} == {"full", "fluid_pound"}


def test_bad_cards_are_refused_in_one_line():
    with pytest.raises(DownholeError, match="reference fluid load must be positive"):
        diagnose(Z, full(), 0.0)
    with pytest.raises(DownholeError, match="has no plunger stroke"):
        diagnose(np.zeros(N), full(), F_O)
    with pytest.raises(DownholeError, match="not finite"):
        diagnose(Z, np.where(UP, np.nan, 0.0), F_O)


def test_the_sequence_tells_a_pump_going_off_from_gas_coming_and_going():
    rng = np.random.default_rng(3)
    going_off = np.linspace(1.0, 0.55, 20) + 0.003 * rng.standard_normal(20)
    gassy = 0.75 + 0.12 * np.tile([1, -1], 10) + 0.01 * rng.standard_normal(20)
    steady = 0.98 + 0.005 * rng.standard_normal(20)
    assert set(sequence_conditions(going_off)[5:]) == {"pump_off"}
    assert set(sequence_conditions(gassy)[5:]) == {"gas_interference"}
    assert set(sequence_conditions(steady)[2:]) == {"steady"}
    assert sequence_conditions(going_off)[:2].tolist() == ["", ""]
    # a card without a fillage (its analysis failed) is skipped, not read as a jump
    holed = going_off.copy()
    holed[10] = np.nan
    found = sequence_conditions(holed)
    assert found[10] == "" and set(found[11:]) == {"pump_off"}


def test_the_hanging_depth_of_a_tapered_string():
    # 300 m of 4 kg/m over 700 m of 2 kg/m in water (steel 7850): the rods above 500 m weigh
    # g (300 x 4 + 200 x 2)(1 - 1000 / 7850)
    rods = RodString(np.array([300.0, 700.0]), np.full(2, 3e-4), np.full(2, 2.1e11), np.array([4.0, 2.0]))
    weight = 9.80665 * (300 * 4 + 200 * 2) * (1 - 1000 / 7850)
    assert float(hanging_depth(rods, weight, 1000.0)) == pytest.approx(500.0, rel=1e-12)


def test_a_plunger_resting_at_the_bottom_is_not_falling_slowly():
    """A full pump whose plunger rests at the bottom for the last tenth of a 400-sample cycle while
    the rods pick up the load, its computed position jittering by 0.4 % of the stroke there (as load
    noise of 3 % of the range carried down 7SK12-2,5-5600's rods makes it): the load it picks up at
    rest is no evidence of a standing valve that leaks while the plunger falls slowly, and the card
    is full. Its velocity taken from the raw samples put resting samples among the slowly falling
    ones (their mean load then 0.24 F_o, beyond the rule's full evidence 0.22); a leaking standing
    valve (leaking(), which gains its load while the plunger moves) still shows."""
    n = 400
    theta = 2 * np.pi * np.arange(n) / n
    rest = theta >= 1.8 * np.pi
    z = np.where(rest, 0.0, STROKE * (1 - np.cos(theta / 0.9)) / 2)
    z = z + np.where(rest, 0.004 * STROKE * np.random.default_rng(1).standard_normal(n), 0.0)
    load = np.where(theta < 0.9 * np.pi, F_O, 0.0) + np.where(rest, F_O * (theta - 1.8 * np.pi) / (0.2 * np.pi), 0.0)
    found = classify(card_features(z, load, F_O))
    assert abs(found.features.slow_downstroke_load[0]) < 0.05
    assert found.label[0] == "full"
    assert classify(card_features(Z, leaking("standing", 0.5), F_O)).label[0] == "standing_valve_leak"
