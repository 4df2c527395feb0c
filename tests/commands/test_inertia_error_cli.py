"""`pumpjack inertia-error` as a user runs it: formats, library equality, errors, help.

Library values for the "JSON equals library" checks come from pumpjack_cli.core, called
directly. The summary of UNB-600A against the closed forms of [InertiaUNB600A] eqs. 2-4 is
checked in tests/validation/test_inertia_unb600a.py.
"""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.config import load_any_unit
from pumpjack_cli.core.beam.inertia_laws import beam_inertia_laws
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.slider_crank.geometry import SliderCrank
from pumpjack_cli.core.slider_crank.mechanism import slider_inertia_laws
from pumpjack_cli.core.slider_crank.support_friction import redundant_support_friction
from pumpjack_cli.quantities import parse_quantity

from helpers import BEAM_UNITS, POUND_FORCE, REPO_ROOT, RPM, UNB600A_CRANK_RADIUS, UNB600A_ROD_LENGTH

UNB = "unb-600a"
R, L2 = UNB600A_CRANK_RADIUS, UNB600A_ROD_LENGTH
OMEGA = 65 * RPM  # 1/s, the bundled file's 65 rpm



def _percent(fraction: float) -> float:
    """A fraction as the JSON writes it in %: converted, to 15 significant digits (README "Output")."""
    return float(f"{100 * fraction:.15g}")

def _json(run_cli, *args):
    code, out, err = run_cli("inertia-error", *args, "-f", "json")
    assert (code, err) == (0, "")
    return json.loads(out)


def test_slider_json_equals_library(run_cli):
    doc = _json(run_cli, UNB, "--steps", "24", "--rpm", "50", "--mass", "300 kg")
    omega = parse_quantity("50 rpm", "rotational_speed")  # the CLI's conversion of --rpm
    c = slider_inertia_laws(SliderCrank(R, L2), omega, crank_grid(24))
    series, summary = doc["series"], doc["summary"]
    assert series["acceleration_m_s2"] == c.acceleration.tolist()
    assert series["position_m"] == c.position.tolist()
    assert series["inertia_force_n"] == (-300.0 * c.acceleration).tolist()
    for name, error in c.errors.items():
        assert series[f"acceleration_{name}_m_s2"] == c.laws[name].tolist()
        assert summary[f"{name}_peak_error_percent"] == _percent(error.peak_error)
        assert summary[f"{name}_max_deviation_percent"] == _percent(error.max_deviation)
        assert summary[f"{name}_rms_deviation_percent"] == _percent(error.rms_deviation)
    assert summary["crank_speed_rad_s"] == pytest.approx(omega, rel=1e-15)


def test_csv_parses_back_and_table_renders(run_cli):
    code, out, err = run_cli("inertia-error", UNB, "--steps", "8", "-f", "csv")
    assert (code, err) == (0, "")
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 8
    assert {"crank_angle_deg", "acceleration_m_s2", "inertia_force_n", "acceleration_series6_m_s2"} <= set(rows[0])
    c = slider_inertia_laws(SliderCrank(R, L2), OMEGA, crank_grid(8))
    assert [float(row["acceleration_m_s2"]) for row in rows] == c.acceleration.tolist()
    code, out, err = run_cli("inertia-error", UNB, "--steps", "8", "-f", "table")
    assert (code, err) == (0, "")
    assert "UNB-600A: inertia force" in out and "harmonic_peak_error" in out


def test_field_units(run_cli):
    si = _json(run_cli, UNB, "--steps", "4")["summary"]
    field = _json(run_cli, UNB, "--steps", "4", "--units", "field")["summary"]
    assert field["peak_inertia_force_lbf"] == pytest.approx(si["peak_inertia_force_n"] / POUND_FORCE, rel=1e-14)
    assert field["harmonic_peak_error_percent"] == si["harmonic_peak_error_percent"]


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_beam_units_json_equals_library(run_cli, name):
    doc = _json(run_cli, name, "--spm", "8", "--steps", "12")
    omega = parse_quantity("8 spm", "rotational_speed")  # the CLI's conversion of --spm
    c = beam_inertia_laws(load_any_unit(name).geometry.mechanism(), omega, crank_grid(12))
    assert doc["series"]["acceleration_m_s2"] == c.acceleration.tolist()
    assert set(c.errors) == {"harmonic", "two_term", "chord"}
    for law, error in c.errors.items():
        assert doc["summary"][f"{law}_peak_error_percent"] == _percent(error.peak_error)
    # No mass given: accelerations only.
    assert not any(key.startswith("inertia_force") for key in doc["series"])


def test_beam_unit_peak_error_agrees_with_kinematics_command(run_cli):
    # Two commands, two code paths: kinematics prints max|a_law|/max|a| - 1 (signed),
    # inertia-error its absolute value; the extremes there are parabola-refined, here
    # taken on a 0.05 degree grid, so they agree to ~1e-6 relative.
    inertia = _json(run_cli, "sk8-3.5-4000", "--steps", "8")["summary"]
    code, out, _ = run_cli("kinematics", "sk8-3.5-4000", "--steps", "8", "-f", "json")
    kinematics = json.loads(out)["summary"]
    for law in ("harmonic", "two_term"):
        assert inertia[f"{law}_peak_error_percent"] == pytest.approx(abs(kinematics[f"{law}_peak_acceleration_error_percent"]), rel=1e-5)


def test_beam_unit_with_mass_gives_forces(run_cli):
    doc = _json(run_cli, "sk8-3.5-4000", "--mass", "5000 kg", "--steps", "6")
    assert doc["series"]["inertia_force_n"] == pytest.approx([-5000 * a for a in doc["series"]["acceleration_m_s2"]], rel=1e-15)
    assert doc["summary"]["peak_inertia_force_n"] == pytest.approx(5000 * doc["summary"]["peak_acceleration_m_s2"], rel=1e-15)


def test_support_friction_json_equals_library_and_extremes_at_dead_centres(run_cli):
    doc = _json(run_cli, UNB, "--support-friction", "--steps", "36")
    slider = load_any_unit(UNB).stepped_slider
    travel = np.array(doc["series"]["travel_m"])
    # Travel from the outer dead centre of a centric crank: r (1 - cos p) + l2 - sqrt(l2^2 - r^2 sin^2 p).
    phi = np.radians(doc["series"]["crank_angle_deg"])
    np.testing.assert_allclose(travel, R * (1 - np.cos(phi)) + L2 - np.sqrt(L2**2 - (R * np.sin(phi)) ** 2), atol=1e-15)
    r = redundant_support_friction(
        [s.length for s in slider.sections], [math.pi * s.diameter**4 / 64 for s in slider.sections],
        slider.elastic_modulus, slider.guide_length, slider.friction_coefficient, slider.settlement, slider.turn,
        travel, slider.intermediate_support.position, slider.intermediate_support.offset,
    )
    assert doc["series"]["guide_friction_n"] == r.guide_friction.tolist()
    assert doc["series"]["support_reaction_n"] == r.intermediate.tolist()
    summary = doc["summary"]
    assert {summary["max_guide_friction_crank_angle_deg"], summary["min_guide_friction_crank_angle_deg"]} == {0.0, 180.0}
    assert summary["max_guide_friction_n"] == summary["guide_friction_outer_dead_centre_n"]


def test_plot_and_output_file(run_cli, tmp_path):
    code, out, err = run_cli("inertia-error", UNB, "--steps", "36", "-o", tmp_path / "r.json",
                             "--plot", tmp_path / "r.png")
    assert (code, out, err) == (0, "", "")
    assert json.loads((tmp_path / "r.json").read_text())["title"].startswith("UNB-600A")
    assert (tmp_path / "r.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_help(run_cli):
    code, out, _ = run_cli("inertia-error", "--help")
    assert code == 0 and "--support-friction" in out and "--rpm" in out


def _unb_variant(tmp_path: Path, old: str, new: str) -> Path:
    text = (REPO_ROOT / "configs" / "unb-600a.toml").read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "unit.toml"
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path


@pytest.mark.parametrize("old, new, message", [
    ('rod_length = "1.19 m"', 'rod_length = "0.2 m"', "geometry: the crank cannot turn: rod_length"),
    ('rod_length = "1.19 m"', 'rod_length = "0.15 m"', "geometry: the crank cannot turn: rod_length"),
    ('offset = "0 m"', 'offset = "1.0 m"', "must exceed crank_radius + |offset|"),
    ('mass = "240 kg"', 'mass = "-240 kg"', "reciprocating.mass: Input should be greater than 0"),
    ('crank_speed = "65 rpm"', 'crank_speed = "0 rpm"', "reciprocating.crank_speed: Input should be greater than 0"),
    ('position = "1300 mm"', 'position = "300 mm"', "stepped_slider.intermediate_support.position"),
    ('elastic_modulus = "206 GPa"', 'elastic_modulus = "206 kg"', "stepped_slider.elastic_modulus"),
])
def test_bad_unit_file_exits_2_with_one_line(run_cli, tmp_path, old, new, message):
    code, out, err = run_cli("inertia-error", _unb_variant(tmp_path, old, new))
    assert code == 2 and out == ""
    assert err.startswith("pumpjack: error: ") and err.count("\n") == 1
    assert message in err


@pytest.mark.parametrize("args, message", [
    ((UNB, "--mass", "-5 kg"), "--mass must be positive"),
    ((UNB, "--mass", "0 kg"), "--mass must be positive"),
    ((UNB, "--rpm", "0"), "'--spm' / '--rpm'"),
    (("c-114d-133-54",), "give the speed with --spm"),
    (("sk8-3.5-4000", "--support-friction"), "--support-friction needs a slider-crank unit"),
    (("no-such-unit",), "unknown unit"),
])
def test_bad_options_exit_2_with_one_line(run_cli, args, message):
    code, out, err = run_cli("inertia-error", *args)
    assert code == 2 and out == ""
    assert err.startswith("pumpjack: error: ") and err.count("\n") == 1
    assert message in err


def test_support_friction_needs_a_stepped_slider(run_cli, tmp_path):
    text = (REPO_ROOT / "configs" / "unb-600a.toml").read_text(encoding="utf-8")
    path = tmp_path / "plain.toml"
    path.write_text(text[: text.index("\n[stepped_slider]")] + "\n", encoding="utf-8")
    code, _, err = run_cli("inertia-error", path, "--support-friction")
    assert code == 2 and "has no [stepped_slider] section" in err
    code, _, err = run_cli("inertia-error", path, "--steps", "4")
    assert (code, err) == (0, "")


def test_real_console_script(run_script):
    done = run_script("inertia-error", UNB, "--steps", "4", "-f", "csv")
    assert done.returncode == 0 and done.stdout.startswith("crank_angle_deg,")
    done = run_script("inertia-error", UNB, "--mass", "-1 kg")
    assert done.returncode == 2 and done.stderr == "pumpjack: error: --mass must be positive, got -1.0 kg\n"
