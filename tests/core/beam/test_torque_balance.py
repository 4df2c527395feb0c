"""Balance optimisers on small cases solved by hand, and the counterweight placement.

The bundled units with their sample cards are checked against brute-force scans in
tests/core/beam/test_torque_bundled_units.py.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.balance import (balance_criteria, equal_peaks_moment, equal_peaks_moments, min_peak_moment,
                                            min_rms_moment,
                                            recommend_counterbalance)
from pumpjack_cli.core.beam.counterbalance import (Counterbalance, counterbalance_from_masses,
                                                   counterweight_placement)
from pumpjack_cli.core.beam.masses import MassModel
from pumpjack_cli.core.constants import STANDARD_GRAVITY as G
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.errors import TorqueError

ZERO = MassModel(*[0.0] * 18)


def test_criteria_registry():
    assert balance_criteria() == ("equal-peaks", "min-rms", "min-peak")


def test_equal_peaks_by_hand():
    """Upstroke lines 10 - M and 2 - 0.5 M, downstroke -4 + M: the upstroke maximum is
    10 - M up to M = 16, so the peaks meet at 10 - M = -4 + M, M = 7."""
    base = np.array([10.0, 2.0, -4.0])
    sine = np.array([1.0, 0.5, -1.0])
    up = np.array([True, True, False])
    assert equal_peaks_moment(base, sine, up) == pytest.approx(7.0, rel=1e-15)


def test_equal_peaks_without_a_root():
    """Downstroke peak 5 + M already above the upstroke peak 1 - M at M = 0 and rising:
    no M >= 0 equalises them."""
    assert equal_peaks_moment(np.array([1.0, 5.0]), np.array([1.0, -1.0]), np.array([True, False])) is None


def test_equal_peaks_with_two_roots_takes_the_smaller_peak():
    """U(M) = max(M, 10 - M), D(M) = 6 - 0.1 M: U = D at M = 4/0.9 (largest |T| 5.556)
    and at M = 6/1.1 (largest |T| 5.455); the second is returned."""
    base = np.array([0.0, 10.0, 6.0])
    sine = np.array([-1.0, 1.0, 0.1])
    up = np.array([True, True, False])
    assert equal_peaks_moment(base, sine, up) == pytest.approx(6 / 1.1, rel=1e-14)


def test_equal_peaks_root_in_the_linear_tail():
    """Both maxima follow single lines: U = 100 - 0.001 M, D = -50 + 0.002 M meet at
    M = 150/0.003 = 50 000, beyond the bracket of any sampled crossing."""
    base = np.array([100.0, -50.0])
    sine = np.array([0.001, -0.002])
    assert equal_peaks_moment(base, sine, np.array([True, False])) == pytest.approx(5e4, rel=1e-14)


def test_equal_peaks_needs_both_strokes():
    with pytest.raises(TorqueError, match="both the upstroke and the downstroke"):
        equal_peaks_moment(np.ones(3), np.ones(3), np.ones(3, dtype=bool))


def test_min_rms_by_hand():
    """mean((a - M s)^2) with a = (3, -1, 2), s = (1, -1, 0.5): M = (3 + 1 + 1)/(1 + 1 + 0.25) = 20/9."""
    assert min_rms_moment(np.array([3.0, -1.0, 2.0]), np.array([1.0, -1.0, 0.5])) == pytest.approx(20 / 9, rel=1e-15)
    weighted = min_rms_moment(np.array([3.0, -1.0]), np.array([1.0, -1.0]), weights=np.array([3.0, 1.0]))
    assert weighted == pytest.approx((9 + 1) / (3 + 1), rel=1e-15)
    with pytest.raises(TorqueError, match="vanishes"):
        min_rms_moment(np.ones(3), np.zeros(3))


def test_min_peak_by_hand():
    """max(|10 - M|, |-4 + M|, |3 - 0.2 M|): the kink of the first two at M = 7 (value 3),
    and |3 - 1.4| = 1.6 < 3 there, so M = 7; a flat optimum at M = 0 when every line
    rises with M."""
    base = np.array([10.0, -4.0, 3.0])
    sine = np.array([1.0, -1.0, 0.2])
    assert min_peak_moment(base, sine) == pytest.approx(7.0, rel=1e-15)
    assert min_peak_moment(np.array([1.0, 2.0]), np.array([-1.0, -0.5])) == 0.0   # |1 + M|, |2 + M/2|


def test_recommendation_on_a_square_card():
    """A square card (W_up on the upstroke, W_down on the downstroke), B = 0, tau = 0,
    conventional SK8 geometry: equal-peaks and min-peak agree (the largest |T| is the
    larger stroke peak), min-rms differs, and each reported peak is the maximum of the
    torque recomputed here with the recommended M."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    theta = crank_grid(3600)
    m = lk.motion(theta)
    w = np.where(m.beam_rate > 0, 70e3, 35e3)
    bal = Counterbalance(0.0, 0.0, 0.0)
    results = {c: recommend_counterbalance(c, lk, theta, w, bal) for c in balance_criteria()}
    tf = lk.front_arm * m.beam_rate
    for r in results.values():
        torque = tf * w - r.value * np.sin(theta)
        assert r.peak_net_torque == pytest.approx(np.max(np.abs(torque)), rel=1e-12)
        assert r.rms_torque == pytest.approx(math.sqrt(np.mean(torque**2)), rel=1e-12)
    assert results["equal-peaks"].upstroke_peak == pytest.approx(results["equal-peaks"].downstroke_peak, rel=1e-12)
    assert results["min-peak"].value == pytest.approx(results["equal-peaks"].value, rel=1e-9)
    assert results["min-rms"].rms_torque < results["min-peak"].rms_torque


def rear_heavy_case():
    """A square card 70/35 kN under a structural unbalance B = 100 kN (a beam far too
    heavy at the rear): TF (W - B) is negative on the upstroke and positive on the
    downstroke, so the downstroke peak already exceeds the upstroke one at M = 0 and
    every M > 0 widens the gap."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    theta = crank_grid(720)
    return lk, theta, np.where(lk.motion(theta).beam_rate > 0, 70e3, 35e3), Counterbalance(100e3, 0.0)


def test_recommendation_without_solution_says_why():
    lk, theta, w, bal = rear_heavy_case()
    r = recommend_counterbalance("equal-peaks", lk, theta, w, bal)
    assert r.value is None and r.peak_net_torque is None
    assert "no counterbalance moment >= 0 makes the stroke peaks equal" in r.note
    with pytest.raises(TorqueError, match="unknown balance criterion 'best'"):
        recommend_counterbalance("best", lk, theta, w, bal)


def test_min_rms_below_zero_is_clamped_with_a_note():
    lk, theta, w, bal = rear_heavy_case()
    r = recommend_counterbalance("min-rms", lk, theta, w, bal)
    assert r.value == 0.0 and "< 0" in r.note
    assert recommend_counterbalance("min-peak", lk, theta, w, bal).value == 0.0


def test_counterweight_radius_by_hand():
    """Arms 2 x 500 kg at 0.4 m (400 kg·m) and 2000 kg of blocks in line: M = 30 kN·m
    needs r = (30 000/g - 400)/2000 = 1.329 52 m; at the present 1.0 m the blocks must weigh
    (30 000/g - 400)/1.0 = 2659.15 kg."""
    masses = dataclasses.replace(ZERO, crank_arm_mass=500.0, crank_arm_cg=0.4, counterweight_mass=2000.0,
                                 counterweight_radius=1.0)
    p = counterweight_placement(30e3, masses, (0.5, 1.2))
    assert p.radius == pytest.approx((30e3 / G - 400.0) / 2000.0, rel=1e-14)
    assert p.mass == pytest.approx(30e3 / G - 400.0, rel=1e-14)
    assert not p.within_range and "outside the slots [0.5, 1.2] m" in p.note
    assert counterweight_placement(20e3, masses, (0.5, 1.2)).within_range


def test_counterweight_radius_round_trip_with_phase():
    """With a counterweight phase the radius found gives back M through counterbalance_from_masses."""
    lk = load_unit("sk8-3.5-4000").geometry.mechanism()
    masses = dataclasses.replace(load_unit("sk8-3.5-4000").masses.model(), counterweight_phase=0.3)
    p = counterweight_placement(70e3, masses, (0.3, 1.5))
    moved = dataclasses.replace(masses, counterweight_radius=p.radius)
    assert counterbalance_from_masses(lk, moved).moment == pytest.approx(70e3, rel=1e-12)
    heavier = dataclasses.replace(masses, counterweight_mass=p.mass)
    assert counterbalance_from_masses(lk, heavier).moment == pytest.approx(70e3, rel=1e-12)


def test_counterweight_moment_below_the_arms_alone():
    masses = dataclasses.replace(ZERO, crank_arm_mass=500.0, crank_arm_cg=0.4, counterweight_mass=2000.0,
                                 counterweight_radius=1.0)
    p = counterweight_placement(1000.0, masses, (0.0, 2.0))
    assert p.radius is None and p.mass is None and "crank arms alone give" in p.note
    with pytest.raises(TorqueError, match="must be >= 0"):
        counterweight_placement(-1.0, masses, (0.0, 2.0))
    with pytest.raises(TorqueError, match="slot range"):
        counterweight_placement(1.0, masses, (2.0, 1.0))


@pytest.mark.parametrize("call", [
    lambda: min_peak_moment(np.array([1.0, np.nan]), np.array([1.0, -1.0])),
    lambda: min_rms_moment(np.array([1.0, 2.0]), np.array([np.inf, 1.0])),
    lambda: equal_peaks_moment(np.array([1.0]), np.array([1.0]), np.array([True])),
    lambda: min_rms_moment(np.array([1.0, 2.0]), np.array([1.0, 1.0]), weights=np.array([1.0, -1.0])),
])
def test_optimisers_reject_bad_arrays(call):
    with pytest.raises(TorqueError):
        call()


def test_equal_peaks_is_a_root_that_brute_force_confirms():
    """Random piecewise-linear problems (ties in the sines and the torques included): the
    moment returned makes the up- and downstroke peaks equal to round-off, and a dense scan
    of g = U - D over [0, 2 M] finds no root of smaller largest |T|; a problem without a
    returned root has g of one sign on the scan."""
    rng = np.random.default_rng(11)
    for _ in range(300):
        n = int(rng.integers(4, 300))
        theta = np.sort(rng.uniform(0.0, 2 * np.pi, n))
        up = theta < rng.uniform(2.5, 3.8)
        if up.all() or not up.any():
            continue
        sine = np.sin(theta - rng.uniform(-0.3, 0.3))
        sine = np.round(sine, 1) if rng.random() < 0.3 else sine
        base = rng.normal(0.0, 1.0, n).cumsum() * 1e4 + rng.normal(0.0, 5e4) * sine
        base = np.round(base, -3) if rng.random() < 0.2 else base

        def g(m):
            return np.max(base[up, None] - m * sine[up, None], axis=0) - np.max(base[~up, None] - m * sine[~up, None],
                                                                                  axis=0)

        moment = equal_peaks_moment(base, sine, up)
        scan = np.linspace(0.0, 2 * moment if moment else 1e6, 4001)
        values = g(scan)
        if moment is None:
            assert np.all(values > 0) or np.all(values < 0)
            continue
        scale = np.max(np.abs(base)) + moment * np.max(np.abs(sine))
        assert abs(float(g(np.array([moment]))[0])) < 1e-9 * scale
        crossings = scan[:-1][values[:-1] * values[1:] <= 0]
        best = np.max(np.abs(base - moment * sine))
        for m in crossings:  # each scanned crossing is within a step of a root no better than the one returned
            assert np.max(np.abs(base - m * sine)) >= best - (scan[1] - scan[0]) * np.max(np.abs(sine)) - 1e-9 * scale


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), lines=st.integers(1, 400))
def test_the_envelope_of_the_lines_has_the_maximum_of_all_lines(seed, lines):
    """max_i (a_i - M s_i) over the envelope the equal-peaks search keeps equals the maximum over
    every line, at M = 0, at random M and far out (to rounding: a line may lead by an ulp)."""
    from pumpjack_cli.core.beam.balance import _fronts

    rng = np.random.default_rng(seed)
    base, sine = rng.normal(0.0, 1e4, lines), np.round(rng.uniform(-1.0, 1.0, lines), int(rng.integers(1, 6)))
    a, s, size = _fronts(base[None], sine)
    a, s = a[0, :size[0]], s[0, :size[0]]
    assert np.all(np.diff(s) > 0)
    for moment in (0.0, *rng.uniform(0.0, 1e5, 20), 1e12):
        assert np.max(a - moment * s) == pytest.approx(np.max(base - moment * sine), rel=1e-12, abs=1e-9 * (1 + moment))


def test_the_cards_of_one_grid_get_the_moments_they_have_alone():
    """K cards of one crank grid in one array computation, envelopes of different sizes, cards
    without a root and with several among them: each card's moment is its own alone, exactly."""
    rng = np.random.default_rng(5)
    for _ in range(40):
        n = int(rng.integers(4, 200))
        theta = np.sort(rng.uniform(0.0, 2 * np.pi, n))
        up = theta < rng.uniform(2.5, 3.8)
        if up.all() or not up.any():
            continue
        sine = np.sin(theta - rng.uniform(-0.3, 0.3))
        sine = np.round(sine, 1) if rng.random() < 0.3 else sine
        bases = rng.normal(0.0, 1.0, (7, n)).cumsum(axis=1) * 1e4 + rng.normal(0.0, 5e4, (7, 1)) * sine
        together = equal_peaks_moments(bases, sine, up)
        alone = [equal_peaks_moment(base, sine, up) for base in bases]
        assert [None if np.isnan(m) else float(m) for m in together] == alone
