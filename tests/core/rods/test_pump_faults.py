"""The pump faults of the predictive model (``core/rods/pump_faults.py``).

Each fault must change the pump card the way the literature describes it, keep the rods'
energy balance (surface work = pump work + damping dissipation, independent of the pump
model), and, switched off, give the full-pump card to the last bit. The SK8-3,5-4000 well
of [SK8Rotation2013] (conftest: ``sk8_rods``, ``sk8_pump``) at its rated speed.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from pumpjack_cli.core.rods.analysis import card_work
from pumpjack_cli.core.rods.diagnosis import hanging_depth
from pumpjack_cli.core.rods.predict import predict, predict_cards
from pumpjack_cli.core.rods.pump import Pump, tubing_stiffness
from pumpjack_cli.core.rods.pump_faults import (FaultyChamber, hanging_pump, parted_damping, parted_string,
                                                pump_chamber, tag_stops)
from pumpjack_cli.errors import PredictionError

from helpers import SK8_CRANK_SPEED, SK8_FLUID_DENSITY, SK8_LINKAGE

SAMPLES = 400
DAMPING = 0.1


_MADE: dict = {}


def _cards(rods, pump: Pump, damping: float = DAMPING, speed: float = SK8_CRANK_SPEED):
    """The cards of the rods and pump at the SK8's rated speed, made once per module (the rods by identity)."""
    key = (id(rods), pump, damping, speed)
    if key not in _MADE:
        _MADE[key] = (rods, predict_cards(SK8_LINKAGE, speed, rods, pump, damping=damping,
                                          fluid_density=SK8_FLUID_DENSITY, samples=SAMPLES, resolution=SAMPLES))
    return _MADE[key][1]


def _displacement(pump: Pump, speed: float = SK8_CRANK_SPEED) -> float:
    """The pump's displacement rate with the polished rod's stroke [m^3/s]."""
    return pump.plunger_area * SK8_LINKAGE.stroke * speed / (2 * math.pi)


def _from_bottom(cards):
    """Plunger position above its lowest point and load, from the bottom of the stroke, with the
    upstroke's mask."""
    z, f = cards.plunger_position, cards.pump_load
    order = np.roll(np.arange(z.size), -int(np.argmin(z)))
    z, f = z[order] - z.min(), f[order]
    return z, f, np.arange(z.size) <= int(np.argmax(z))


def test_faults_switched_off_give_the_full_pump_card_exactly(sk8_rods, sk8_pump):
    # stops far outside the stroke and tight valves: the faulty chamber marches, the card is the same
    sound = _cards(sk8_rods, sk8_pump)
    idle = replace(sk8_pump, bottom_stop=-100.0, top_stop=100.0, travelling_valve_leak=0.0)
    assert idle.faulty and isinstance(pump_chamber(idle, 1e-6, 0.0, 0.01), FaultyChamber)
    faulty = _cards(sk8_rods, idle)
    for name in ("polished_rod_load", "plunger_position", "pump_load"):
        assert np.array_equal(getattr(faulty, name), getattr(sound, name)), name
    assert not replace(sk8_pump, standing_valve_leak=0.0).faulty


@pytest.mark.parametrize("key", ["travelling_valve_leak", "standing_valve_leak"])
def test_a_leak_loses_the_liquid_it_passes_and_keeps_the_energy_balance(sk8_rods, sk8_pump, key):
    sound = _cards(sk8_rods, sk8_pump)
    leak = 1.2 * _displacement(sk8_pump)
    cards = _cards(sk8_rods, replace(sk8_pump, **{key: leak}))
    s = cards.summary
    # the liquid delivered is the displacement less what passed the shut valve: more than nothing, less
    # than the sound pump's, and at least the displacement less the leak running the whole cycle
    assert 0.0 < s.net_plunger_stroke < sound.summary.net_plunger_stroke
    assert s.pump_displacement >= sound.summary.pump_displacement - leak * s.period - 1e-9
    # the rods do not know the pump model: surface work = pump work + damping dissipation
    assert abs(s.energy_residual) < 1e-4
    # the card loses area against the full rectangle
    assert float(card_work(cards.plunger_position, cards.pump_load)) < 0.99 * float(
        card_work(sound.plunger_position, sound.pump_load))


def test_the_shut_chamber_of_a_leaking_travelling_valve_follows_the_orifice_law(sk8_pump):
    # with both valves shut the chamber fills through the leak alone, q = Q sqrt(dp / dp_o)
    # ([White2011]): the plunger rises by h q / A_p in a step while it carries F = F_o (v / v_L)^2,
    # v_L = Q / A_p; stepped here with the rods' relation zeta = known - c F, as the march does
    leak, h, c = 2e-4, 0.01, 1e-6
    pump = replace(sk8_pump, travelling_valve_leak=leak)
    f_o, v_l = pump.fluid_load, leak / pump.plunger_area
    for rise in (0.1, 0.4, 0.9):                     # plunger speeds below v_L: the standing valve stays shut
        chamber = FaultyChamber(pump, c, 0.0, h)
        v = rise * v_l
        load, position = chamber.step(v * h + c * f_o * rise**2)    # the known position that asks for speed v
        assert load == pytest.approx(f_o * rise**2, rel=1e-9)
        assert position == pytest.approx(v * h, rel=1e-9)
        assert chamber.discharge == pytest.approx(-leak * rise * h, rel=1e-9)   # the liquid leaked back
    chamber = FaultyChamber(pump, c, 0.0, h)                        # faster than v_L: the standing valve opens
    load, position = chamber.step(2 * v_l * h + c * f_o)
    assert load == f_o and chamber.intake == pytest.approx(pump.plunger_area * position - leak * h, rel=1e-9)


def test_a_leaking_travelling_valve_carries_the_orifice_law_load_on_the_card(sk8_rods, sk8_pump):
    # the same law on the predicted card, with the plunger's speed from its exact position: within the
    # held plunger's slide between samples (docs/predict.md)
    leak = 1.2 * _displacement(sk8_pump)
    pump = replace(sk8_pump, travelling_valve_leak=leak)
    cards = _cards(sk8_rods, pump)
    h = cards.summary.period / SAMPLES
    v = (cards.plunger_position - np.roll(cards.plunger_position, 1)) / h
    f_o, v_l = pump.fluid_load, leak / pump.plunger_area
    between = (cards.pump_load > 0.05 * f_o) & (cards.pump_load < 0.95 * f_o) & (v > 0)
    assert between.sum() > 10
    assert np.median(np.abs(cards.pump_load[between] - f_o * (v[between] / v_l)**2)) < 0.02 * f_o


def test_the_leaking_valves_change_the_card_as_echometer_describes(sk8_rods, sk8_pump):
    # [EchometerLeakValve]: a leaking standing valve keeps load on the plunger near the top and the
    # bottom of the downstroke, where the plunger is slow; a leaking travelling valve loses the load
    # before the top of the upstroke and picks it up late
    leak = 1.2 * _displacement(sk8_pump)
    z, f, up = _from_bottom(_cards(sk8_rods, replace(sk8_pump, standing_valve_leak=leak)))
    stroke, f_o = float(z.max()), sk8_pump.fluid_load
    near_bottom = ~up & (z < 0.05 * stroke) & (z > 0.005 * stroke)
    assert f[near_bottom].mean() > 0.3 * f_o
    z0, f0, up0 = _from_bottom(_cards(sk8_rods, sk8_pump))
    assert np.abs(f0[~up0 & (z0 < 0.05 * stroke) & (z0 > 0.005 * stroke)]).max() < 0.05 * f_o
    z, f, up = _from_bottom(_cards(sk8_rods, replace(sk8_pump, travelling_valve_leak=leak)))
    near_top = up & (z > 0.97 * z.max())
    assert f[near_top].mean() < 0.7 * f_o
    picked = z[up & (f >= 0.9 * f_o)].min()          # where the standing valve opens
    assert picked > 0.01 * z.max()
    assert z0[up0 & (f0 >= 0.9 * f_o)].min() < 0.002 * z0.max()


@pytest.mark.parametrize("end", ["bottom", "top"])
def test_a_stop_holds_the_plunger_and_spikes_the_load(sk8_rods, sk8_pump, end):
    # tagging: the plunger never passes the stop; the stop pushes the rods, a load spike beyond the
    # sound card's range at that end of the stroke, of the order of the rods' impedance E A / a times
    # the plunger's speed when it meets the stop ([Gibbs1963])
    sound = _cards(sk8_rods, sk8_pump)
    interference = 0.05
    bottom, top = tag_stops(sound.plunger_position, sound.pump_load, sk8_pump,
                            interference if end == "bottom" else None, interference if end == "top" else None)
    cards = _cards(sk8_rods, replace(sk8_pump, bottom_stop=bottom, top_stop=top))
    z, f = cards.plunger_position, cards.pump_load
    f_o = sk8_pump.fluid_load
    slide = 0.005 * float(np.ptp(sound.plunger_position))      # the held rod end's slide between samples
    if end == "bottom":
        assert z.min() >= bottom - slide and z.min() > sound.plunger_position.min() + 0.5 * interference
        assert f.min() < sound.pump_load.min() - 0.3 * f_o
    else:
        assert z.max() <= top + slide and z.max() < sound.plunger_position.max() - 0.5 * interference
        assert f.max() > sound.pump_load.max() + 0.3 * f_o
    assert abs(cards.summary.energy_residual) < 1e-4
    # the spike against the impedance: the free plunger's speed where it passes the stop
    free_speed = np.abs(np.gradient(sound.plunger_position, sound.time))
    passing = np.argmin(np.abs(sound.plunger_position - (bottom if end == "bottom" else top))
                        + 10.0 * (np.gradient(sound.plunger_position) * (1 if end == "bottom" else -1) > 0))
    impedance = float(np.sqrt(sk8_rods.youngs_modulus[-1] * sk8_rods.area[-1] * sk8_rods.mass_per_length[-1]))
    spike = (sound.pump_load.min() - f.min()) if end == "bottom" else (f.max() - sound.pump_load.max())
    assert 0.3 < spike / (impedance * free_speed[passing]) < 3.0


def test_unanchored_tubing_slants_both_load_transfers_by_its_stretch(sk8_rods, sk8_pump):
    # [API11L]: the plunger stroke loses F_o / k_t; on the pump card the load is picked up and
    # released over that travel, a parallelogram
    k_t = tubing_stiffness("2-3/8", 1530.0)
    pump = replace(sk8_pump, tubing_stiffness=k_t)
    z, f, up = _from_bottom(_cards(sk8_rods, pump))
    f_o = pump.fluid_load
    pickup = z[up & (f >= 0.9 * f_o)].min() - z[up & (f >= 0.1 * f_o)].min()
    release = z[~up & (f >= 0.1 * f_o)].min()
    release = z[~up & (f > 0.9 * f_o)].min() - z[~up & (f <= 0.1 * f_o)].max()
    assert pickup == pytest.approx(0.8 * f_o / k_t, rel=0.25)
    assert release == pytest.approx(0.8 * f_o / k_t, rel=0.25)


def test_a_parted_string_hangs_its_own_buoyant_weight(sk8_rods, sk8_pump):
    # over a steady cycle the rods' inertia and damping forces average out: the mean polished-rod
    # load of a string hanging free is its buoyant weight, and the depth where the rods above weigh
    # that mean is the break
    depth = 0.55 * sk8_rods.total_length
    hanging = parted_string(sk8_rods, depth)
    assert hanging.total_length == pytest.approx(depth, rel=1e-12)
    cards = _cards(hanging, hanging_pump(sk8_pump), parted_damping(sk8_rods, hanging, DAMPING))
    mean = float(np.mean(cards.polished_rod_load))
    assert mean == pytest.approx(hanging.buoyant_weight(SK8_FLUID_DENSITY), rel=2e-3)
    assert float(hanging_depth(sk8_rods, mean, SK8_FLUID_DENSITY)) == pytest.approx(depth, rel=5e-3)
    # the same damping force per length: c = pi a nu / (2 L) kept
    assert hanging.damping_coefficient(parted_damping(sk8_rods, hanging, DAMPING)) == pytest.approx(
        sk8_rods.damping_coefficient(DAMPING), rel=1e-12)


@pytest.mark.parametrize("changes, words", [
    ({"travelling_valve_leak": -1e-5}, "travelling valve leak must be >= 0"),
    ({"standing_valve_leak": math.inf}, "standing valve leak must be >= 0"),
    ({"travelling_valve_leak": 1e-4, "fillage": 0.7}, "full of liquid"),
    ({"bottom_stop": 0.5, "top_stop": 0.4}, "must lie below the top stop"),
    ({"top_stop": math.nan}, "top stop must be finite"),
])
def test_fault_data_that_make_no_pump_are_refused_in_one_line(sk8_pump, changes, words):
    with pytest.raises(PredictionError, match=words) as error:
        replace(sk8_pump, **changes).check()
    assert "\n" not in str(error.value)


def test_a_break_outside_the_string_is_refused(sk8_rods):
    """Outside the string, or leaving less than the shortest pony rod (2 ft, [API11B]) above or below
    the break: a break 1e-300 m down left a section of no length."""
    for depth in (0.0, 1e-300, 0.5, sk8_rods.total_length - 0.5, sk8_rods.total_length, -5.0, math.nan):
        with pytest.raises(PredictionError, match="the break must lie a rod's length"):
            parted_string(sk8_rods, depth)
    assert parted_string(sk8_rods, 0.7).total_length == pytest.approx(0.7, rel=1e-12)


def test_faults_are_simulated_at_uniform_speed_only(sk8_unit, sk8_rods, sk8_pump):
    from pumpjack_cli.core.dynamics.coupled import predict_coupled

    with pytest.raises(PredictionError, match="uniform crank speed"):
        predict_coupled(sk8_unit.machine(elastic_rods=True), sk8_rods, replace(sk8_pump, standing_valve_leak=1e-5),
                        damping=DAMPING, fluid_density=SK8_FLUID_DENSITY, samples=64)


def test_predict_takes_the_faulty_pump_on_any_grid(sk8_rods, sk8_pump):
    # the leak's volume per step follows the step: the same leak on a grid twice as fine gives the
    # same liquid lost to the step's accuracy
    position = np.array([0.5 - 0.5 * math.cos(2 * math.pi * k / 512) for k in range(512)]) * 2.5
    pump = replace(sk8_pump, travelling_valve_leak=4e-4)
    coarse = predict(sk8_rods, pump, position[::2], 5.5, damping=DAMPING, fluid_density=SK8_FLUID_DENSITY)
    fine = predict(sk8_rods, pump, position, 5.5, damping=DAMPING, fluid_density=SK8_FLUID_DENSITY)
    assert coarse.summary.net_plunger_stroke == pytest.approx(fine.summary.net_plunger_stroke, rel=0.02)
