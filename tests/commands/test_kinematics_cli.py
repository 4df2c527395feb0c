"""`pumpjack kinematics` as a user runs it: CSV and JSON equal the library, field units, --spm, --steps.

Library values (for "parses back exactly") come from pumpjack_cli.core directly, not
from the CLI. The speed of [SK8Rotation2013] is checked in tests/validation/test_sk8rotation2013.py.
"""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.kinematics import uniform_kinematics

from helpers import FOOT, INCH, SK8


# Angles are printed in degrees rounded to 1e-9 degree (documented in units.py), so a
# degree column can differ from value·180/pi by half a unit in the 9th decimal, plus
# the rounding of the product (~1e-13 near 360): allow 6e-10 degree.
DEG_TOL = 6e-10


def _csv_columns(text: str) -> dict[str, list[str]]:
    rows = list(csv.DictReader(io.StringIO(text)))
    assert rows, "no CSV rows"
    return {key: [row[key] for row in rows] for key in rows[0]}


def _floats(values: list[str]) -> np.ndarray:
    return np.array([float(v) for v in values])


@pytest.fixture(scope="module")
def library_result():
    """The library's own result for the bundled SK8 at the motor's rated speed, 360 steps."""
    config = load_unit(SK8)
    return uniform_kinematics(config.geometry.mechanism(), config.drive.rated_crank_speed, 360)


# Exact-kinematics columns (SI, no scaling) and where the library keeps them.
SI_COLUMNS = {
    "time_s": lambda r: r.time,
    "position_m": lambda r: r.rod.position,
    "velocity_m_s": lambda r: r.rod.velocity,
    "acceleration_m_s2": lambda r: r.rod.acceleration,
    "torque_factor_m": lambda r: r.torque_factor,
    "beam_angular_velocity_rad_s": lambda r: r.beam_angular_velocity,
    "beam_angular_acceleration_rad_s2": lambda r: r.beam_angular_acceleration,
    "pitman_angular_velocity_rad_s": lambda r: r.pitman_angular_velocity,
    "pitman_angular_acceleration_rad_s2": lambda r: r.pitman_angular_acceleration,
    "position_harmonic_m": lambda r: r.approximations["harmonic"].position,
    "velocity_harmonic_m_s": lambda r: r.approximations["harmonic"].velocity,
    "acceleration_harmonic_m_s2": lambda r: r.approximations["harmonic"].acceleration,
    "position_two_term_m": lambda r: r.approximations["two_term"].position,
    "velocity_two_term_m_s": lambda r: r.approximations["two_term"].velocity,
    "acceleration_two_term_m_s2": lambda r: r.approximations["two_term"].acceleration,
}


ANGLE_COLUMNS = {
    "crank_angle_deg": lambda r: r.crank_angle,
    "beam_angle_deg": lambda r: r.beam_angle,
    "pitman_angle_deg": lambda r: r.pitman_angle,
}


# --- speed and period --------------------------------------------------------------


def test_spm_option_gives_period(run_cli):
    code, out, err = run_cli("kinematics", SK8, "--spm", "10", "-f", "json")
    assert (code, err) == (0, "")
    summary = json.loads(out)["summary"]
    # 10 strokes per minute: 60 s / 10 = 6 s per stroke; rel 1e-12 for the round trip
    # spm -> rad/s -> period.
    assert summary["period_s"] == pytest.approx(6.0, rel=1e-12)
    assert summary["strokes_per_minute_spm"] == pytest.approx(10.0, rel=1e-12)
    assert summary["crank_speed_rad_s"] == pytest.approx(2 * math.pi / 6, rel=1e-12)


# --- CSV and JSON reproduce the library ---------------------------------------------


def test_csv_parses_back_to_library_values(run_cli, library_result):
    code, out, err = run_cli("kinematics", SK8, "-f", "csv")
    assert (code, err) == (0, "")
    columns = _csv_columns(out)
    assert set(columns) == set(SI_COLUMNS) | set(ANGLE_COLUMNS)
    assert list(columns)[:6] == ["crank_angle_deg", "time_s", "position_m", "velocity_m_s",
                                 "acceleration_m_s2", "torque_factor_m"]
    for name, get in SI_COLUMNS.items():
        values = _floats(columns[name])
        expected = np.asarray(get(library_result), dtype=float)
        assert values.shape == (360,)
        # floats are written with repr: they must parse back to the same bits
        assert np.array_equal(values, expected), name
    for name, get in ANGLE_COLUMNS.items():
        values = _floats(columns[name])
        expected = np.asarray(get(library_result)) * (180 / math.pi)
        np.testing.assert_allclose(values, expected, rtol=0, atol=DEG_TOL, err_msg=name)


def test_csv_crank_angles_are_whole_degrees(run_cli):
    # 360 steps per revolution: crank angles 0, 1, ..., 359 degrees; with angles printed
    # to 1e-9 degree these come out as exact whole numbers.
    code, out, _ = run_cli("kinematics", SK8, "-f", "csv")
    assert code == 0
    assert _csv_columns(out)["crank_angle_deg"] == [f"{k}.0" for k in range(360)]


def test_json_equals_library(run_cli, library_result):
    code, out, err = run_cli("kinematics", SK8, "-f", "json")
    assert (code, err) == (0, "")
    doc = json.loads(out)
    assert doc["units"] == "si"
    assert "SK8-3,5-4000" in doc["title"]
    series = doc["series"]
    assert set(series) == set(doc["columns"]) == set(SI_COLUMNS) | set(ANGLE_COLUMNS)
    for name, get in SI_COLUMNS.items():
        assert series[name] == np.asarray(get(library_result), dtype=float).tolist(), name
    for name, get in ANGLE_COLUMNS.items():
        np.testing.assert_allclose(series[name], np.asarray(get(library_result)) * (180 / math.pi),
                                   rtol=0, atol=DEG_TOL, err_msg=name)
    assert doc["columns"]["position_m"]["unit"] == "m"

    s, summary = library_result.summary, doc["summary"]
    exact = {
        "crank_speed_rad_s": s.crank_speed,
        "period_s": s.period,
        "stroke_m": s.stroke,
        "max_velocity_m_s": s.max_velocity.value,
        "min_velocity_m_s": s.min_velocity.value,
        "max_acceleration_m_s2": s.max_acceleration.value,
        "min_acceleration_m_s2": s.min_acceleration.value,
        "max_torque_factor_m": s.max_torque_factor.value,
        "min_torque_factor_m": s.min_torque_factor.value,
    }
    for key, value in exact.items():
        assert summary[key] == value, key
    degrees = {
        "crank_angle_bottom_deg": s.crank_angle_bottom,
        "crank_angle_top_deg": s.crank_angle_top,
        "upstroke_crank_travel_deg": s.upstroke_crank_travel,
        "downstroke_crank_travel_deg": s.downstroke_crank_travel,
        "max_velocity_crank_angle_deg": s.max_velocity.crank_angle,
    }
    for key, value in degrees.items():
        assert abs(summary[key] - value * 180 / math.pi) <= DEG_TOL, key
    # Scaled summary values: one multiplication, rel 1e-12.
    assert summary["strokes_per_minute_spm"] == pytest.approx(s.crank_speed * 60 / (2 * math.pi), rel=1e-12)
    err = s.approximation_errors["harmonic"]
    assert summary["harmonic_position_error_percent"] == pytest.approx(100 * err.position, rel=1e-12)
    assert summary["harmonic_peak_acceleration_error_percent"] == pytest.approx(100 * err.peak_acceleration, rel=1e-12)


def test_field_units(run_cli):
    _, si_out, _ = run_cli("kinematics", SK8, "-f", "csv")
    code, field_out, err = run_cli("kinematics", SK8, "-f", "csv", "--units", "field")
    assert (code, err) == (0, "")
    si, field = _csv_columns(si_out), _csv_columns(field_out)
    conversions = {
        # field column: (SI column, exact factor SI -> field unit)
        "position_in": ("position_m", 1 / INCH),
        "torque_factor_in": ("torque_factor_m", 1 / INCH),
        "velocity_ft_s": ("velocity_m_s", 1 / FOOT),
        "acceleration_ft_s2": ("acceleration_m_s2", 1 / FOOT),
        "position_two_term_in": ("position_two_term_m", 1 / INCH),
        "time_s": ("time_s", 1.0),
        "crank_angle_deg": ("crank_angle_deg", 1.0),
    }
    for name, (si_name, factor) in conversions.items():
        assert name in field, name
        # one division by an exact definition: rel 1e-12 (values near zero: abs 1e-15 m)
        np.testing.assert_allclose(_floats(field[name]), _floats(si[si_name]) * factor, rtol=1e-12, atol=1e-15,
                                   err_msg=name)
    assert "position_m" not in field and "velocity_m_s" not in field


def test_field_units_json_summary(run_cli):
    _, si_out, _ = run_cli("kinematics", SK8, "-f", "json")
    code, field_out, _ = run_cli("kinematics", SK8, "-f", "json", "--units", "field")
    assert code == 0
    si, field = json.loads(si_out)["summary"], json.loads(field_out)["summary"]
    assert json.loads(field_out)["units"] == "field"
    assert field["stroke_in"] == pytest.approx(si["stroke_m"] / INCH, rel=1e-12)
    assert field["max_velocity_ft_s"] == pytest.approx(si["max_velocity_m_s"] / FOOT, rel=1e-12)


def test_gost_and_api_files_give_identical_csv(run_cli, sk8_toml, sk8_api_yaml):
    args = ("--spm", "10", "-f", "csv")
    code_a, gost, err_a = run_cli("kinematics", sk8_toml, *args)
    code_b, api, err_b = run_cli("kinematics", sk8_api_yaml, *args)
    assert (code_a, code_b, err_a, err_b) == (0, 0, "", "")
    assert gost.startswith("crank_angle_deg,")
    assert gost == api


def test_steps_option(run_cli):
    code, out, _ = run_cli("kinematics", SK8, "--steps", "12", "-f", "csv")
    assert code == 0
    angles = _floats(_csv_columns(out)["crank_angle_deg"])
    np.testing.assert_allclose(angles, np.arange(12) * 30.0, rtol=0, atol=DEG_TOL)
