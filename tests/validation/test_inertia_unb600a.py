"""[InertiaUNB600A]: the UNB-600A drill pump and the maxima of its eqs. 2-4.

Source: [InertiaUNB600A], on the accuracy of the inertia forces of the reciprocating link
(exact and approximate laws of the piston motion), drill pump UNB-600A with r = 0.2 m and
l2 = 1.19 m. At the maximum (w t = 0), lambda = r/l2: Phi_max = m w^2 (r + r^2/l2) (eq. 2),
Phi_c = m r w^2 (eq. 3), Phi_1 = m r w^2 (1 + lambda) (eq. 4), so the sinusoidal law's error
is delta_sin = 1 - 1/(1 + lambda) = 14.3885 % and the first approximation's delta_1 = 0.
Checked here: the bundled unit file, the slider-crank core and `pumpjack inertia-error`.
"""

from __future__ import annotations

import json

import pytest

from pumpjack_cli.config import load_any_unit
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.slider_crank.geometry import SliderCrank
from pumpjack_cli.core.slider_crank.mechanism import slider_inertia_laws

from helpers import RPM, UNB600A_CRANK_RADIUS as R, UNB600A_ROD_LENGTH as L2

LAMBDA = R / L2
#: The bundled file's speed, 65 rpm [1/s], and its (estimated) mass of the reciprocating parts [kg].
OMEGA, MASS = 65 * RPM, 240.0


def test_bundled_unb600a_is_the_papers_mechanism():
    config = load_any_unit("unb-600a")
    assert config.kind == "slider-crank"
    assert (config.geometry.crank_radius, config.geometry.rod_length, config.geometry.offset) == (R, L2, 0.0)
    assert config.stroke() == pytest.approx(2 * R, rel=1e-15)
    assert config.reciprocating.crank_speed == pytest.approx(OMEGA, rel=1e-15)
    assert any("ESTIMATED" in source for source in config.sources)


def test_core_maxima_are_eqs_2_to_4():
    # For lambda < 1/4 the largest force is at w t = 0 for every law, and
    # Phi_max / (m r w^2) = 1 + lambda (eq. 2), 1 (eq. 3), 1 + lambda (eq. 4), so
    # delta_sin = 1 - 1/(1 + lambda) = 14.39 % and delta_1 = 0 for UNB-600A.
    c = slider_inertia_laws(SliderCrank(R, L2), OMEGA, crank_grid(36))
    rw2 = R * OMEGA**2
    assert c.peak == pytest.approx(OMEGA**2 * (R + R**2 / L2), rel=1e-14)
    assert c.peak_crank_angle == 0.0
    assert c.errors["harmonic"].peak == pytest.approx(rw2, rel=1e-14)
    assert c.errors["two_term"].peak == pytest.approx(rw2 * (1 + LAMBDA), rel=1e-14)
    assert c.errors["harmonic"].peak_error == pytest.approx(LAMBDA / (1 + LAMBDA), rel=1e-12)
    assert c.errors["harmonic"].peak_error_of_law == pytest.approx(LAMBDA, rel=1e-12)
    assert c.errors["two_term"].peak_error == pytest.approx(0.0, abs=1e-14)
    # Position from the inner dead centre: the whole stroke at the outer one.
    assert c.position[0] == pytest.approx(2 * R, rel=1e-14)
    assert c.stroke == pytest.approx(2 * R, rel=1e-14)


def test_command_summary_is_eqs_2_to_4(run_cli):
    code, out, err = run_cli("inertia-error", "unb-600a", "--steps", "12", "-f", "json")
    assert (code, err) == (0, "")
    summary = json.loads(out)["summary"]
    assert summary["crank_to_rod_ratio"] == pytest.approx(LAMBDA, rel=1e-15)
    assert summary["stroke_m"] == pytest.approx(2 * R, rel=1e-14)
    assert summary["peak_inertia_force_n"] == pytest.approx(MASS * OMEGA**2 * (R + R**2 / L2), rel=1e-13)
    assert summary["harmonic_peak_inertia_force_n"] == pytest.approx(MASS * R * OMEGA**2, rel=1e-13)
    assert summary["two_term_peak_inertia_force_n"] == pytest.approx(MASS * R * OMEGA**2 * (1 + LAMBDA), rel=1e-13)
    assert summary["harmonic_peak_error_percent"] == pytest.approx(100 * LAMBDA / (1 + LAMBDA), rel=1e-12)
    assert summary["harmonic_peak_error_of_law_percent"] == pytest.approx(100 * LAMBDA, rel=1e-12)
    assert summary["two_term_peak_error_percent"] == pytest.approx(0.0, abs=1e-12)
