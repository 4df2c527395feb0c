"""Redundant-support friction against hand-checked textbook beam cases.

Sources of the expected values (all derived by hand here, not from the code):

1. Fixed-ended beam whose end B settles by Delta: end reactions 12 EI Delta / L^3 and
   end moments 6 EI Delta / L^2 ([NPTEL105101085], Structural Analysis II, module 5
   lecture 1, example 5.5; the slope-deflection fixed-end moment 6 EI Delta / L^2).
   End B turned by theta instead: force 6 EI theta / L^2, moment 4 EI theta / L at B
   (slope-deflection equation M_N = 2EI/L (2 theta_N + theta_F - 3 psi), e.g. [Hibbeler2012],
   Structural Analysis, ch. 11).
2. Fixed-ended beam pushed up at mid-span by a support raised delta_C: the central
   point load P = 192 EI delta_C / L^3 (mid-span deflection P L^3 / (192 EI) of a
   fixed-fixed beam, [TimoshenkoGere1972], Mechanics of Materials, table of beam
   deflections), end reactions -P/2 and end moments P L / 8.
3. Two equal spans a (clamp A, support C, clamp B), B settled Delta, slope-deflection
   by hand: moment equilibrium at C, 4EI theta_C/a + 2EI/a (2 theta_C - 3 Delta/a) = 0,
   gives theta_C = 3 Delta / (4a); then at B
   M_B = 2EI/a (theta_C - 3 Delta/a) = -9 EI Delta / (2 a^2) (counterclockwise on the
   beam), R_B = 15 EI Delta / (2 a^3), and at C Y_C = -12 EI Delta / a^3
   (shears of the two spans; check: R_A = 9 EI Delta / (2 a^3), R_A + Y_C + R_B = 0).
4. Stepped cantilever (Maxwell-Mohr integral by hand): tip deflection under a unit tip
   force (1/(3E)) [(L^3 - (L - a)^3)/J1 + (L - a)^3/J2], slope under a unit tip moment
   a/(E J1) + (L - a)/(E J2), cross term (1/(2E)) [(L^2 - (L - a)^2)/J1 + (L - a)^2/J2].

Tolerance: the code solves small linear systems in floating point; rel 1e-12 allows
for condition numbers up to ~1e3 and nothing more.
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.slider_crank.support_friction import flexibility_matrix, guide_edge_reactions, reduction_coefficients, redundant_support_friction

E = 2.06e11  # Pa, steel
J = np.pi * 0.07**4 / 64  # m^4, 70 mm round rod
EJ = E * J
REL = 1e-12


def solve(lengths, second_moments, settlement=0.0, turn=0.0, travel=(0.0,), position=None, offset=0.0,
          guide_length=0.4, f=0.1):
    return redundant_support_friction(lengths, second_moments, E, guide_length, f, settlement, turn,
                                      np.asarray(travel, dtype=float), position, offset)


@pytest.mark.parametrize("span", [0.5, 1.6, 3.0])
def test_fixed_beam_end_settlement(span):
    delta = 2e-4
    r = solve([span], [J], settlement=delta)
    assert r.force[0] == pytest.approx(12 * EJ * delta / span**3, rel=REL)
    assert r.moment[0] == pytest.approx(-6 * EJ * delta / span**2, rel=REL)
    np.testing.assert_array_equal(r.intermediate, 0.0)


@pytest.mark.parametrize("span", [0.5, 1.6])
def test_fixed_beam_end_rotation(span):
    theta = 3e-4
    r = solve([span], [J], turn=theta)
    assert r.force[0] == pytest.approx(-6 * EJ * theta / span**2, rel=REL)
    assert r.moment[0] == pytest.approx(4 * EJ * theta / span, rel=REL)


def test_turned_guide_settles_with_travel():
    # A guide turned by theta is a sloping line: after a travel s the link end sits
    # Delta + theta s off A's axis; the reactions are those of that settlement plus the turn.
    span, theta, s = 1.6, 3e-4, 0.25
    r = solve([span], [J], turn=theta, travel=[s])
    assert r.force[0] == pytest.approx(12 * EJ * theta * s / span**3 - 6 * EJ * theta / span**2, rel=REL)
    assert r.moment[0] == pytest.approx(-6 * EJ * theta * s / span**2 + 4 * EJ * theta / span, rel=REL)


def test_fixed_beam_with_raised_mid_support():
    span, delta_c = 2.0, 1e-4
    r = solve([span], [J], position=span / 2, offset=delta_c)
    p = 192 * EJ * delta_c / span**3
    assert r.intermediate[0] == pytest.approx(p, rel=REL)
    assert r.force[0] == pytest.approx(-p / 2, rel=REL)
    assert r.moment[0] == pytest.approx(p * span / 8, rel=REL)


@pytest.mark.parametrize("a", [0.5, 1.0])
def test_two_equal_spans_end_settled(a):
    delta = 1e-4
    r = solve([2 * a], [J], settlement=delta, position=a)
    assert r.force[0] == pytest.approx(7.5 * EJ * delta / a**3, rel=REL)
    assert r.moment[0] == pytest.approx(-4.5 * EJ * delta / a**2, rel=REL)
    assert r.intermediate[0] == pytest.approx(-12 * EJ * delta / a**3, rel=REL)


def test_intermediate_support_moves_along_the_link():
    # Frame-fixed support at z_C0 = 1.4 m: after a travel of 0.4 m it touches the link at
    # z = 1.0 m, the mid-span of a 2 m beam, so case 2 applies there.
    span, delta_c = 2.0, 1e-4
    r = solve([span], [J], position=1.4, offset=delta_c, travel=[0.4])
    assert r.intermediate[0] == pytest.approx(192 * EJ * delta_c / span**3, rel=REL)


def test_stepped_cantilever_flexibility():
    length, a, j1, j2 = 1.8, 0.7, 3 * J, J
    expected = np.array([
        [((length**3 - (length - a) ** 3) / j1 + (length - a) ** 3 / j2) / (3 * E),
         ((length**2 - (length - a) ** 2) / j1 + (length - a) ** 2 / j2) / (2 * E)],
        [((length**2 - (length - a) ** 2) / j1 + (length - a) ** 2 / j2) / (2 * E),
         (a / j1 + (length - a) / j2) / E],
    ])
    np.testing.assert_allclose(flexibility_matrix([a, length - a], [j1, j2], E), expected, rtol=REL)
    # And the fixed-fixed stepped beam is its inverse applied to (Delta, 0).
    delta = 1e-4
    r = solve([a, length - a], [j1, j2], settlement=delta)
    np.testing.assert_allclose([r.force[0], r.moment[0]], np.linalg.solve(expected, [delta, 0.0]), rtol=1e-10)


def test_equal_sections_equal_one_section():
    one = solve([2.0], [J], settlement=1e-4, turn=1e-4, position=1.3, offset=5e-5, travel=[0.0, 0.2, 0.4])
    split = solve([0.3, 0.9, 0.8], [J, J, J], settlement=1e-4, turn=1e-4, position=1.3, offset=5e-5,
                  travel=[0.0, 0.2, 0.4])
    for field in ("force", "moment", "intermediate"):
        np.testing.assert_allclose(getattr(split, field), getattr(one, field), rtol=1e-10)


def test_reduction_coefficients_are_relative_to_the_smallest_section():
    # [InertiaUNB600A] reduces to J_0 = J_2 (the rod); alpha_i = J_i / J_0.
    np.testing.assert_allclose(reduction_coefficients([8.0, 2.0, 4.0]), [4.0, 1.0, 2.0], rtol=0)


def test_edge_reactions_and_friction_seed_cases():
    # [InertiaUNB600A]: with M_B <= 0.5 R_B l_n both edge forces point the same way and
    # F = f R_B; otherwise they oppose and F = f 2 M_B / l_n, larger by 2 M_B / (l_n R_B).
    l_n, f = 0.4, 0.1
    outer, inner = guide_edge_reactions(np.array([100.0, 100.0]), np.array([10.0, 50.0]), l_n)
    np.testing.assert_allclose(outer, [75.0, 175.0])
    np.testing.assert_allclose(inner, [25.0, -75.0])
    r_same = f * (abs(outer[0]) + abs(inner[0]))
    r_opposite = f * (abs(outer[1]) + abs(inner[1]))
    assert r_same == pytest.approx(f * 100.0)
    assert r_opposite == pytest.approx(f * 2 * 50.0 / l_n)


def test_friction_is_f_times_edge_forces_plus_support():
    r = solve([1.0, 1.0], [2 * J, J], settlement=1e-4, turn=-2e-4, position=1.5, offset=3e-5,
              travel=np.linspace(0, 0.4, 5), f=0.12)
    np.testing.assert_allclose(r.guide_friction, 0.12 * (np.abs(r.outer_edge) + np.abs(r.inner_edge)), rtol=1e-15)
    np.testing.assert_allclose(r.intermediate_friction, 0.12 * np.abs(r.intermediate), rtol=1e-15)
    np.testing.assert_allclose(r.total_friction, r.guide_friction + r.intermediate_friction, rtol=1e-15)
    np.testing.assert_allclose(r.outer_edge + r.inner_edge, r.force, rtol=1e-13)


def test_no_misalignment_no_force():
    r = solve([0.5, 1.0], [4 * J, J], position=1.0, travel=[0.0, 0.3])
    np.testing.assert_array_equal(r.total_friction, 0.0)
