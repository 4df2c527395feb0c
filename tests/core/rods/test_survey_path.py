"""The minimum-curvature path of a survey ([SawarynThorogood2005]) against closed forms of straight
slants and circular builds, its own derivatives, and the vertical hole."""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.rods.path import VerticalPath
from pumpjack_cli.core.rods.survey_path import SurveyPath
from pumpjack_cli.errors import DownholeError


def _path(depth, inclination_deg, azimuth_deg) -> SurveyPath:
    return SurveyPath(np.array(depth, dtype=float), np.radians(inclination_deg), np.radians(azimuth_deg))


def test_a_straight_slant_is_s_cos_phi_deep_and_s_sin_phi_away():
    path = _path([0, 2000], [40, 40], [120, 120])
    s = np.linspace(0, 2500, 11)  # past the last station the hole goes on straight
    phi, psi = np.radians(40), np.radians(120)
    assert np.allclose(path.vertical_depth(s), s * np.cos(phi), rtol=0, atol=1e-9)
    assert np.allclose(path.north_east(s), np.c_[s * np.sin(phi) * np.cos(psi), s * np.sin(phi) * np.sin(psi)],
                       rtol=0, atol=1e-9)
    assert np.allclose(path.inclination(s), phi) and np.allclose(path.azimuth(s), psi)
    assert np.all(path.inclination_rate(s) == 0) and np.all(path.dogleg_severity(s) == 0)


def test_a_constant_build_is_a_circle_whatever_the_station_spacing():
    """Vertical to 500 m, then 3 deg per 30 m: on the arc of radius R = 1 / kappa,
    TVD = 500 + R sin(kappa x) and the departure R (1 - cos(kappa x)), x below the kick-off."""
    kappa = np.radians(3.0) / 30.0
    coarse = _path([0, 500, 950], [0, 0, 45], [0, 0, 0])
    fine = _path([0, 500, *(500 + 30.0 * np.arange(1, 16))], [0, 0, *(3.0 * np.arange(1, 16))], np.zeros(17))
    x = np.linspace(0.0, 450.0, 19)
    for path in (coarse, fine):
        assert np.allclose(path.vertical_depth(500 + x), 500 + np.sin(kappa * x) / kappa, rtol=0, atol=1e-8)
        assert np.allclose(path.north_east(500 + x)[:, 0], (1 - np.cos(kappa * x)) / kappa, rtol=0, atol=1e-8)
        assert np.allclose(path.inclination(500 + x), kappa * x, rtol=0, atol=1e-12)
        assert np.allclose(path.inclination_rate(500 + x[1:-1]), kappa, rtol=1e-10)
        assert np.allclose(path.dogleg_severity(500 + x[1:-1]) * 30.0, np.radians(3.0), rtol=1e-10)


def test_each_interval_ends_where_the_ratio_factor_puts_it():
    """[SawarynThorogood2005]: r_j+1 - r_j = D/2 (t_j + t_j+1) RF, RF = (2 / beta) tan(beta / 2)."""
    depth = np.array([0.0, 300.0, 700.0, 1300.0])
    inc, azi = np.radians([0.0, 20.0, 55.0, 88.0]), np.radians([0.0, 10.0, 80.0, 140.0])
    path = SurveyPath(depth, inc, azi)
    t = np.c_[np.sin(inc) * np.cos(azi), np.sin(inc) * np.sin(azi), np.cos(inc)]
    r = path.position(depth)
    for j in range(3):
        beta = np.arccos(t[j] @ t[j + 1])
        step = (depth[j + 1] - depth[j]) / 2 * (t[j] + t[j + 1]) * 2 / beta * np.tan(beta / 2)
        assert np.allclose(r[j + 1] - r[j], step, rtol=0, atol=1e-9)


def test_rates_are_the_derivatives_of_the_angles_and_of_the_position():
    path = _path([0, 100, 700, 1500], [0, 30, 60, 75], [0, 0, 90, 200])
    s = np.array([50.0, 250.0, 400.0, 650.0, 900.0, 1200.0])  # away from the stations (the rates jump there)
    h = 1e-3
    for value, rate in ((path.inclination, path.inclination_rate), (path.azimuth, path.azimuth_rate)):
        assert np.allclose(rate(s), (value(s + h) - value(s - h)) / (2 * h), rtol=1e-6, atol=1e-10)
    slope = (path.position(s + h) - path.position(s - h)) / (2 * h)
    assert np.allclose(slope, path.tangent(s), rtol=0, atol=1e-8)
    assert np.allclose(np.linalg.norm(path.tangent(s), axis=-1), 1.0)
    curvature = (path.tangent(s + h) - path.tangent(s - h)) / (2 * h)
    assert np.allclose(curvature, path.tangent_rate(s), rtol=0, atol=1e-9)
    # |t'|^2 = phi'^2 + (psi' sin phi)^2: the two components of the side-load formula
    assert np.allclose(path.dogleg_severity(s), np.hypot(path.inclination_rate(s),
                                                         path.azimuth_rate(s) * np.sin(path.inclination(s))))


def test_a_vertical_survey_is_the_vertical_hole():
    path, vertical = _path([0, 800, 2000], [0, 0, 0], [0, 45, 90]), VerticalPath()
    s = np.linspace(0, 2000, 9)
    assert path.vertical
    for name in ("vertical_depth", "inclination", "inclination_rate", "azimuth_rate", "north_east"):
        assert np.array_equal(getattr(path, name)(s), getattr(vertical, name)(s)), name


@pytest.mark.parametrize("depth, inclination, words", [
    ([0, 100, 200], [0, 90, 270], "inclinations must lie between 0 and 180"),
    ([0, 100, 100], [0, 10, 20], "must start at the wellhead"),
    ([10, 100], [0, 10], "must start at the wellhead"),
])
def test_impossible_stations_are_refused(depth, inclination, words):
    with pytest.raises(DownholeError, match=words):
        _path(depth, inclination, np.zeros(len(depth)))


def test_a_half_turn_between_two_stations_is_refused():
    with pytest.raises(DownholeError, match="turns by 180 degrees between 100 m and 200 m"):
        _path([0, 100, 200], [0, 90, 90], [0, 0, 180])


def test_a_turn_sharper_than_any_drilled_build_is_refused():
    """10 deg/m is the limit: 9.9 degrees of build over one metre passes; 30 degrees over half a metre
    (60 deg/m, a survey slip) is refused with its stations and rate."""
    _path([0, 100, 101], [0, 0, 9.9], [0, 0, 0])
    with pytest.raises(DownholeError, match="turns by 30 degrees over 0.5 m between 100 m and 100.5 m: 60 deg/m"):
        _path([0, 100, 100.5], [0, 0, 30.0], [0, 0, 0])
