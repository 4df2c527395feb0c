"""Slider-crank core: exact motion, series laws, limits, offset mechanism.

Expected values come from closed forms written out here, independently of the code:

* exact centric acceleration a = -r w^2 [cos p + L cos 2p / s + L^3 sin^2 2p / (4 s^3)],
  s = sqrt(1 - L^2 sin^2 p), L = r/l ([InertiaUNB600A] eq. 1; any theory-of-machines text);
* the textbook harmonic coefficients A2 = L + L^3/4 + 15 L^5/128,
  A4 = L^3/4 + 3 L^5/16, A6 = 9 L^5/128 of a = -r w^2 (cos p + A2 cos 2p - A4 cos 4p
  + A6 cos 6p) (binomial expansion of the radical, e.g. [NPTEL112101096] module 4);
* the offset stroke sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2).

The maxima of [InertiaUNB600A] eqs. 2-4 on its UNB-600A are checked in
tests/validation/test_inertia_unb600a.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.slider_crank.geometry import SliderCrank, check_slider_crank, dead_centres, stroke
from pumpjack_cli.core.slider_crank.mechanism import approximate_acceleration, exact_motion, law_errors, law_methods, series_coefficients, slider_inertia_laws
from pumpjack_cli.errors import GeometryError

from helpers import RPM, UNB600A_CRANK_RADIUS, UNB600A_ROD_LENGTH

# The UNB-600A drill pump of [InertiaUNB600A]: realistic proportions.
R_SEED, L2_SEED = UNB600A_CRANK_RADIUS, UNB600A_ROD_LENGTH
LAMBDA_SEED = R_SEED / L2_SEED
OMEGA = 65 * RPM  # 1/s, 65 rpm (the speed cancels in every ratio below)


def centric_acceleration(r: float, l: float, phi: np.ndarray, omega: float) -> np.ndarray:
    """The classical exact piston acceleration of a centric slider-crank ([InertiaUNB600A] eq. 1)."""
    lam = r / l
    s = np.sqrt(1.0 - lam**2 * np.sin(phi) ** 2)
    return -r * omega**2 * (np.cos(phi) + lam * np.cos(2 * phi) / s + lam**3 * np.sin(2 * phi) ** 2 / (4 * s**3))


mechanisms = st.builds(
    lambda r, ratio, share: SliderCrank(r, ratio * r, share * (ratio * r - r)),
    st.floats(0.01, 2.0),
    st.floats(1.5, 12.0),
    st.floats(-0.9, 0.9),
)


@settings(max_examples=60, deadline=None)
@given(mechanisms)
def test_velocity_and_acceleration_are_derivatives_of_position(mechanism):
    # Central differences with h = 1e-4 rad. First difference: truncation h^2/6 |x'''|
    # ~ 2e-9 * O(10) r, rounding eps x / h ~ 3e-11 r. Second difference: truncation
    # h^2/12 |x''''| ~ 1e-9 * O(10) r, rounding 4 eps x / h^2 ~ 1.2e-6 r for x <= 13 r.
    # Tolerances 1e-6 r and 1e-5 r leave about a factor of 10 on the larger term.
    h = 1e-4
    phi = crank_grid(97)
    x = lambda p: exact_motion(mechanism, p, 1.0).position  # noqa: E731
    m = exact_motion(mechanism, phi, 1.0)
    r = mechanism.crank_radius
    np.testing.assert_allclose(m.velocity, (x(phi + h) - x(phi - h)) / (2 * h), rtol=0, atol=1e-6 * r)
    np.testing.assert_allclose(m.acceleration, (x(phi + h) - 2 * x(phi) + x(phi - h)) / h**2, rtol=0, atol=1e-5 * r)


@pytest.mark.parametrize("r, l", [(R_SEED, L2_SEED), (0.1, 0.35), (1.0, 2.0)])
def test_centric_exact_equals_classical_formula(r, l):
    # Same formula written two ways; rel 1e-12 covers the different operation order.
    phi = crank_grid(360)
    a = exact_motion(SliderCrank(r, l), phi, OMEGA).acceleration
    np.testing.assert_allclose(a, centric_acceleration(r, l, phi, OMEGA), rtol=1e-12, atol=1e-12 * r * OMEGA**2)


def test_offset_zero_is_centric_and_small_offset_is_continuous():
    phi = crank_grid(180)
    centric = exact_motion(SliderCrank(0.2, 1.19), phi, OMEGA)
    zero = exact_motion(SliderCrank(0.2, 1.19, 0.0), phi, OMEGA)
    tiny = exact_motion(SliderCrank(0.2, 1.19, 1e-9), phi, OMEGA)
    for field in ("position", "velocity", "acceleration"):
        np.testing.assert_array_equal(getattr(zero, field), getattr(centric, field))
        # d/de is of order 1 (m/m and (1/s)^2 scaled): a 1e-9 m offset moves values by ~1e-9 x scale.
        np.testing.assert_allclose(getattr(tiny, field), getattr(centric, field), rtol=0, atol=1e-7)


@pytest.mark.parametrize("r, l, e", [(0.2, 1.19, 0.0), (0.2, 1.19, 0.3), (0.5, 1.0, -0.2), (0.1, 0.3, 0.15)])
def test_stroke_closed_form_and_dead_centres(r, l, e):
    mechanism = SliderCrank(r, l, e)
    expected = math.sqrt((l + r) ** 2 - e * e) - math.sqrt((l - r) ** 2 - e * e)
    assert stroke(mechanism) == pytest.approx(expected, rel=1e-14)
    # The dead centres are where the slider stops: zero velocity, extreme positions.
    dead = dead_centres(mechanism)
    m = exact_motion(mechanism, np.array([dead.crank_angle_outer, dead.crank_angle_inner]), 1.0)
    np.testing.assert_allclose(m.velocity, 0.0, atol=1e-14)
    np.testing.assert_allclose(m.position, [math.sqrt((l + r) ** 2 - e * e), math.sqrt((l - r) ** 2 - e * e)], rtol=1e-14)
    # ... and bracket every position of a dense sweep (the sweep misses the extremes by O(h^2)).
    sweep = exact_motion(mechanism, crank_grid(20000), 1.0).position
    assert sweep.max() - sweep.min() == pytest.approx(expected, rel=1e-6)


def test_centric_stroke_is_twice_the_crank():
    assert stroke(SliderCrank(R_SEED, L2_SEED)) == pytest.approx(2 * R_SEED, rel=1e-15)


@pytest.mark.parametrize("r, l, e", [(0.2, 0.2, 0.0), (0.2, 1.0, 0.8), (0.2, 1.0, -0.85), (0.0, 1.0, 0.0)])
def test_a_crank_that_cannot_turn_is_rejected(r, l, e):
    with pytest.raises(GeometryError, match="rod_length|crank_radius"):
        check_slider_crank(SliderCrank(r, l, e))


@pytest.mark.parametrize("lam", [0.05, LAMBDA_SEED, 0.25, 0.4])
def test_series_coefficients_are_the_textbook_ones(lam):
    a2 = lam + lam**3 / 4 + 15 * lam**5 / 128
    a4 = lam**3 / 4 + 3 * lam**5 / 16
    a6 = 9 * lam**5 / 128
    np.testing.assert_allclose(series_coefficients(lam, 1), [lam], rtol=1e-15)
    np.testing.assert_allclose(series_coefficients(lam, 2), [lam + lam**3 / 4, -lam**3 / 4], rtol=1e-15)
    np.testing.assert_allclose(series_coefficients(lam, 3), [a2, -a4, a6], rtol=1e-14)


def test_laws_equal_their_closed_forms():
    mechanism = SliderCrank(R_SEED, L2_SEED)
    phi = crank_grid(72)
    rw2 = R_SEED * OMEGA**2
    lam = LAMBDA_SEED
    a2 = lam + lam**3 / 4 + 15 * lam**5 / 128
    a4 = lam**3 / 4 + 3 * lam**5 / 16
    a6 = 9 * lam**5 / 128
    expected = {
        "harmonic": -rw2 * np.cos(phi),
        "two_term": -rw2 * (np.cos(phi) + lam * np.cos(2 * phi)),
        "series4": -rw2 * (np.cos(phi) + (lam + lam**3 / 4) * np.cos(2 * phi) - lam**3 / 4 * np.cos(4 * phi)),
        "series6": -rw2 * (np.cos(phi) + a2 * np.cos(2 * phi) - a4 * np.cos(4 * phi) + a6 * np.cos(6 * phi)),
    }
    assert law_methods() == tuple(expected)
    for name, values in expected.items():
        np.testing.assert_allclose(approximate_acceleration(name, mechanism, phi, OMEGA), values, rtol=0, atol=1e-13 * rw2)


def test_unknown_law_lists_the_valid_ones():
    with pytest.raises(ValueError, match="harmonic, two_term, series4, series6"):
        approximate_acceleration("parabolic", SliderCrank(0.2, 1.19), np.zeros(1), 1.0)


def test_series_converges_to_the_exact_law():
    # Each further binomial term is smaller by about lambda^2 / 4 (about 0.7 % here):
    # the max deviation must drop by more than a factor 20 per term.
    mechanism = SliderCrank(R_SEED, L2_SEED)
    phi = crank_grid(3600)
    exact = exact_motion(mechanism, phi, OMEGA).acceleration
    deviations = [np.max(np.abs(approximate_acceleration(n, mechanism, phi, OMEGA) - exact)) for n in law_methods()]
    for coarse, fine in zip(deviations, deviations[1:]):
        assert fine < coarse / 20


@pytest.mark.parametrize("name", ["harmonic", "two_term", "series4", "series6"])
def test_all_laws_agree_with_the_exact_one_as_lambda_goes_to_zero(name):
    # With lambda = 1e-6 every law differs from the exact acceleration by at most
    # lambda r w^2 (the whole second harmonic); the sinusoidal law by about that much.
    r, lam = 0.2, 1e-6
    mechanism = SliderCrank(r, r / lam)
    phi = crank_grid(360)
    exact = exact_motion(mechanism, phi, OMEGA).acceleration
    law = approximate_acceleration(name, mechanism, phi, OMEGA)
    assert np.max(np.abs(law - exact)) <= 1.01 * lam * r * OMEGA**2


def test_error_definitions_on_hand_made_curves():
    # exact = cos p, law = cos p / 2: peaks 1 and 1/2, so |1 - 1/2| = 0.5 and
    # |1 - 1/(1/2)| = 1; deviation cos p / 2 has max 1/2 and rms equal to half the exact rms.
    phi = crank_grid(64)
    errors = law_errors(phi, np.cos(phi), {"half": 0.5 * np.cos(phi)})["half"]
    assert (errors.peak, errors.peak_crank_angle) == (0.5, 0.0)
    assert errors.peak_error == pytest.approx(0.5, rel=1e-15)
    assert errors.peak_error_of_law == pytest.approx(1.0, rel=1e-15)
    assert errors.max_deviation == pytest.approx(0.5, rel=1e-15)
    assert errors.rms_deviation == pytest.approx(0.5, rel=1e-14)


def test_harmonic_rms_error_small_lambda_closed_form():
    # exact - sinusoidal = -r w^2 (lambda cos 2p + O(lambda^3)), so
    # rms(dev)/rms(exact) = lambda / sqrt(1 + lambda^2) + O(lambda^3): at lambda = 0.01 the
    # neglected part is ~ lambda^3 / 4 = 2.5e-7 of the ratio 0.01, i.e. rel 3e-5.
    lam = 0.01
    c = slider_inertia_laws(SliderCrank(0.2, 0.2 / lam), OMEGA, crank_grid(8))
    assert c.errors["harmonic"].rms_deviation == pytest.approx(lam / math.sqrt(1 + lam**2), rel=1e-4)


def test_inertia_laws_reject_zero_speed():
    with pytest.raises(ValueError, match="crank speed must be positive"):
        slider_inertia_laws(SliderCrank(0.2, 1.19), 0.0, crank_grid(8))
