"""A pump pounding fluid whose state repeats only after two strokes.

C-228D-213-86's rods and pump at 15 strokes/min with 40 % fillage and Gibbs' damping 0.05: the
plunger hits the fluid where the rods' vibration from the stroke before leaves it, and the
strokes alternate (pump displacements of 1.169 and 1.103 l at 1080 samples per cycle); no
state repeats every stroke. The alternation is the model's, not the time step's: it stays at
twice the samples, with displacements that move by the first-order error of the fluid hit's
timing, and it is gone at a higher damping. The cards are those of the stroke of the higher
load; works and production are the two strokes' means, so that the energy balance of the rods
over their period closes (:func:`pumpjack_cli.core.rods.predict.assemble`).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from pumpjack_cli.core.rods.predict import predict_cards
from pumpjack_cli.core.rods.predict_solver import DISTINCT_STROKES, LONGEST_REPEAT, converge
from pumpjack_cli.errors import PredictionError

SPEED = 2 * np.pi * 15 / 60


@pytest.fixture(scope="module")
def well():
    from pumpjack_cli.config import load_unit

    unit = load_unit("c-228d-213-86")
    return unit.geometry.mechanism(), unit.rods(), dataclasses.replace(unit.pump(), fillage=0.4), unit.well.fluid_density


def _cards(well, resolution: int = 1024, damping: float = 0.05):
    mechanism, rods, pump, density = well
    return predict_cards(mechanism, SPEED, rods, pump, damping=damping, fluid_density=density, samples=360,
                         resolution=resolution)


@pytest.fixture(scope="module")
def alternating(well):
    return _cards(well)


def test_the_strokes_alternate_at_twice_the_samples_too(well, alternating):
    """Two strokes at 1080 and at 2160 samples per cycle, 6 % apart in displacement; the strokes'
    displacements move by 0.3-0.6 % between the grids (the fluid hit's timing, first order in the
    step), asserted within 1.5 %."""
    coarse, fine = alternating.summary, _cards(well, 2048).summary
    assert coarse.convergence.strokes == fine.convergence.strokes == 2
    a, b = np.array(coarse.stroke_displacements), np.array(fine.stroke_displacements)
    assert abs(a[0] - a[1]) > 0.05 * a.mean()
    assert np.all(np.abs(a - b) < 0.015 * b)


def test_a_higher_damping_settles_every_stroke(well):
    """At damping 0.2 the rods' vibration dies within a stroke: one stroke repeats."""
    s = _cards(well, damping=0.2).summary
    assert s.convergence.strokes == 1 and len(s.stroke_displacements) == 1


def test_the_card_is_the_stroke_of_the_higher_load_and_production_the_mean(well, alternating):
    s = alternating.summary
    assert s.peak_polished_rod_load.value == max(s.stroke_peak_loads)
    assert float(np.max(alternating.polished_rod_load)) <= s.peak_polished_rod_load.value
    assert s.pump_displacement == pytest.approx(np.mean(s.stroke_displacements), rel=1e-12)
    assert s.net_plunger_stroke * well[2].plunger_area == pytest.approx(s.pump_displacement, rel=1e-12)
    assert s.pump_rate * s.period == pytest.approx(s.pump_displacement, rel=1e-12)
    assert s.convergence.change <= s.convergence.tolerance


def test_the_energy_balance_closes_over_the_two_strokes(alternating):
    """Surface work = pump work + damping dissipation over the period of two strokes, to the 1e-4
    that a pounding pump's valve events leave at 1080 samples (the same as for a pump pounding
    every stroke alike, tests/core/rods/test_predict_energy.py); asserted 1e-3."""
    assert abs(alternating.summary.energy_residual) < 1e-3


class _Repeating:
    """A stand-in for the pump's march: its cycles are given pump loads (plunger positions 0), one
    second long, the rods' modes damped by ``damping`` [1/s]."""

    def __init__(self, loads, damping: float = 1.0):
        modes = type("Modes", (), {"count": 0, "damping": damping})
        self.loads, self.samples = iter(loads), 2
        self.model = type("Model", (), {"modes": modes, "pump": type("Pump", (), {"gas_exponent": None}),
                                        "response": type("Response", (), {"step": 0.5})})
        self.chamber = type("Chamber", (), {"discharge": 0.0})()

    def cycle(self, velocity, position):
        load = next(self.loads)
        self.chamber.discharge += float(load.sum())
        return load, np.zeros_like(load)


KNOWN = type("Known", (), {"plunger_velocity_down": None, "plunger_down": None})


def test_converge_takes_the_shortest_repeat_and_keeps_the_strokes_in_order():
    """Strokes c, a, b, c: the fourth repeats the first, and the last three are the state."""
    a, b, c = np.array([1.0, 0.0]), np.array([0.0, 1.0]), np.array([0.5, 0.5])
    loads, strokes, volumes, how = converge(_Repeating([c, a, b, c, a, b, c, a, b]), KNOWN, 1.0, 1.0, 1e-8, 20)
    assert how.strokes == 3 and how.cycles == 4 and np.array_equal(loads, [a, b, c])
    assert volumes == (1.0, 1.0, 1.0) and strokes.shape == (3, 2)


def test_strokes_nearly_alike_are_marched_on_to_one_repeating_stroke():
    """Strokes alternating by less than DISTINCT_STROKES (as a state converging slowly with
    alternating sign does) are not taken for a cycle of two: the march goes on until one repeats."""
    tiny = 0.01 * DISTINCT_STROKES
    loads = [np.array([1.0 + tiny * (-1) ** k, 0.0]) for k in range(30)] + [np.array([1.0, 0.0])] * 3
    found, _, _, how = converge(_Repeating(loads), KNOWN, 1.0, 1.0, 1e-8, 40)
    assert how.strokes == 1 and how.cycles == 32 and np.array_equal(found, [[1.0, 0.0]])


def test_no_repeat_within_the_longest_is_refused():
    loads = [np.array([np.sin(k), 0.0]) for k in range(50)]
    with pytest.raises(PredictionError, match=f"no repeat within {LONGEST_REPEAT} strokes"):
        converge(_Repeating(loads), KNOWN, 1.0, 1.0, 1e-8, 50)


def test_a_state_jittering_after_the_transient_is_taken_with_its_change():
    """A load that keeps changing by up to 2e-3 at one sample from stroke to stroke and repeats after no
    number of strokes (a valve event moving by a sample) is the state once the rods' transient has decayed below the tolerance over the cycles
    marched (e^{-c T n / 2} = e^{-20} < 1e-8 at c = 1/s, T = 1 s, 40 cycles), its change returned;
    with a damping too light for the transient to have died (c = 0.1/s: e^{-2}), it is refused."""
    loads = [np.array([1.0, 1e-3 * np.sin(k)]) for k in range(40)]
    found, _, _, how = converge(_Repeating(loads), KNOWN, 1.0, 1.0, 1e-8, 40)
    assert how.strokes == 1 and how.change == pytest.approx(1e-3 * abs(np.sin(39) - np.sin(38)), rel=1e-12)
    assert np.array_equal(found, [loads[-1]])
    with pytest.raises(PredictionError, match="did not converge in 40 cycles"):
        converge(_Repeating(loads, damping=0.1), KNOWN, 1.0, 1.0, 1e-8, 40)
    wild = [np.array([1.0, 0.1 * (-1) ** k * (1 + k % 3)]) for k in range(40)]
    with pytest.raises(PredictionError, match="no repeat within"):
        converge(_Repeating(wild), KNOWN, 1.0, 1.0, 1e-8, 40)
