"""Deviated wells as a user runs them: `--survey` and `--friction-coefficient` on `downhole`, `predict` and
`dynamics --well-model wave`, `[well] survey` in a unit file, the profile and rod-guide advice, the batch
manifest's survey column, and every refusal as one line with exit code 2.

Expected values come from independent routes: the vertical methods for a vertical survey (to 1e-9), the
J-shaped hole's geometry in closed form (a circular build: R sin 45 deg, then cos 45 deg per metre of hold),
hydrostatics at the pump's true vertical depth, and the sample card's own making (samples/make_deviated.py:
damping 0.05, friction 0.2, 100 m of fluid above the pump).
"""

from __future__ import annotations

import csv
import io
import json
import math
import shutil

import numpy as np
import pytest

from pumpjack_cli.core.constants import STANDARD_GRAVITY

from helpers import REPO_ROOT, SK8, SK8_CARD, SK8_FLUID_DENSITY, SK8_PUMP_DEPTH, SK8_TOML, assert_same_summary

J_SURVEY = REPO_ROOT / "samples" / "j-well-survey.csv"
DEVIATED_CARD = REPO_ROOT / "samples" / "sk8-3.5-4000-deviated-card.csv"
#: The J-shaped hole's true vertical depth at the pump, in closed form: 500 m vertical, a 3 deg/30 m arc to 45 deg
#: (450 m of hole, radius 30 / (3 pi / 180)), then 1530 - 950 m held at 45 deg.
PUMP_TVD = 500.0 + 30.0 / math.radians(3.0) * math.sin(math.radians(45.0)) + (SK8_PUMP_DEPTH - 950.0) * math.cos(
    math.radians(45.0))
#: The SK8's plunger and fluid level above it (configs/sk8-3.5-4000.toml).
PLUNGER, SUBMERGENCE = 0.038, 100.0


def _vertical_survey(folder) -> str:
    path = folder / "vertical.csv"
    path.write_text("measured_depth_ft,inclination_deg,azimuth_deg\n0,0,0\n6000,0,0\n", encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("method", [None, "everitt-jennings"])
def test_a_vertical_survey_gives_the_vertical_results(run_cli, tmp_path, method):
    argv = ["downhole", SK8, "--card", SK8_CARD, "-f", "json", *(["--method", method] if method else [])]
    code, plain, err = run_cli(*argv)
    assert code == 0, err
    code, surveyed, err = run_cli(*argv, "--survey", _vertical_survey(tmp_path), "--friction-coefficient", "0.3")
    assert code == 0, err
    plain, surveyed = json.loads(plain), json.loads(surveyed)
    assert_same_summary(surveyed["summary"], plain["summary"], 1e-9, 1e-9)
    for name, column in plain["series"].items():
        assert np.allclose(surveyed["series"][name], column, rtol=1e-9, atol=1e-9), name
    extra = surveyed["summary"]
    assert extra["pump_true_vertical_depth_m"] == SK8_PUMP_DEPTH and extra["friction_work_per_cycle_j"] == 0.0
    assert extra["max_side_load_n_m"] == 0.0 and extra["friction_coefficient"] == 0.3


@pytest.fixture(scope="module")
def deviated(run_json):
    return run_json("downhole", SK8, "--card", DEVIATED_CARD, "--survey", J_SURVEY, "--friction-coefficient", "0.2")


def test_downhole_on_the_deviated_sample_finds_what_made_it(deviated):
    """Blind, with the survey: the energy balance with the drag finds the damping the card was made with,
    the pump card is the full pump's, the intake pressure is the 100 m of fluid above the pump (a vertical
    height), and a diagnosis ignoring the drag would credit the pump with far more work."""
    s = deviated["summary"]
    assert "everitt-jennings" in deviated["title"] and "j-well-survey.csv" in deviated["title"]
    assert s["pump_true_vertical_depth_m"] == pytest.approx(PUMP_TVD, rel=1e-9)
    assert s["damping_factor"] == pytest.approx(0.05, rel=0.01)
    assert s["pump_fillage_percent"] > 99.0
    fluid_load = SK8_FLUID_DENSITY * STANDARD_GRAVITY * (PUMP_TVD - SUBMERGENCE) * math.pi * PLUNGER**2 / 4
    assert s["fluid_load_n"] == pytest.approx(fluid_load, rel=0.01)
    assert s["pump_intake_pressure_pa"] == pytest.approx(SK8_FLUID_DENSITY * STANDARD_GRAVITY * SUBMERGENCE, rel=0.05)
    assert s["pump_card_work_without_friction_j"] > 1.3 * s["pump_card_work_j"]
    assert s["friction_work_per_cycle_j"] > 0.5 * s["pump_card_work_j"]
    assert s["axial_rod_weight_n"] < s["buoyant_rod_weight_n"]
    assert 500.0 < s["max_side_load_depth_m"] < 950.0  # in the build, where the tension pulls the rods to the high side
    assert s["max_side_load_per_rod_n"] == pytest.approx(s["max_side_load_n_m"] * 7.62, rel=1e-12)
    assert {"pump_position_without_friction_m", "pump_load_without_friction_n"} <= set(deviated["series"])


def test_the_profile_and_the_rod_guides(run_cli):
    code, out, err = run_cli("downhole", SK8, "--card", DEVIATED_CARD, "--survey", J_SURVEY, "--profile",
                             "--guide-limit", "100 lbf", "--damping", "0.05", "-f", "csv")
    assert code == 0, err
    rows = list(csv.DictReader(io.StringIO(out)))
    depth = np.array([float(r["measured_depth_m"]) for r in rows])
    tvd = np.array([float(r["true_vertical_depth_m"]) for r in rows])
    assert depth[0] == 0.0 and depth[-1] == pytest.approx(SK8_PUMP_DEPTH) and tvd[-1] == pytest.approx(PUMP_TVD)
    dls = np.array([float(r["dogleg_severity_deg_30m"]) for r in rows])
    assert np.allclose(dls[(depth > 520) & (depth < 930)], 3.0, rtol=1e-9)  # the build's 3 deg per 30 m
    side = np.array([float(r["side_load_n_m"]) for r in rows])
    per_rod = np.array([float(r["side_load_per_rod_n"]) for r in rows])
    guides = np.array([float(r["rod_guides"]) for r in rows])
    limit = 100 * 4.4482216152605
    assert np.allclose(per_rod, side * 7.62)
    guided = guides > 0  # the fewest guides: one fewer would leave a contact over the limit
    assert np.all(per_rod / (guides + 1) <= limit * (1 + 1e-12)) and np.all(per_rod[guided] / guides[guided] > limit)
    assert np.all(guides[depth < 480] == 0) and guides.max() >= 1
    high = np.array([float(r["max_axial_load_n"]) for r in rows])
    low = np.array([float(r["min_axial_load_n"]) for r in rows])
    assert np.all(high >= low) and high[0] > high[-1]


def test_a_unit_file_names_its_survey_relative_to_itself(run_cli, tmp_path):
    folder = tmp_path / "wells"
    folder.mkdir()
    shutil.copy(J_SURVEY, folder / "j.csv")
    text = SK8_TOML.read_text(encoding="utf-8").replace("[well]\n", '[well]\nsurvey = "j.csv"\nrod_friction_coefficient = 0.2\n', 1)
    unit = folder / "unit.toml"
    unit.write_text(text, encoding="utf-8")
    code, out, err = run_cli("downhole", unit, "--card", DEVIATED_CARD, "--damping", "0.05", "-f", "json",
                             "--what", "summary")
    assert code == 0, err
    assert "warning" not in err  # the file gives the friction coefficient
    assert json.loads(out)["summary"]["pump_true_vertical_depth_m"] == pytest.approx(PUMP_TVD, rel=1e-9)


@pytest.mark.parametrize("content, words", [
    ("measured_depth_m,inclination_deg,azimuth_deg\n0,0,0\n800,10,0\n700,20,0\n",
     ["bad.csv: line 4: column 1 (measured_depth)", "does not go below"]),
    ("measured_depth_m,inclination_deg,azimuth_deg\n0,0,0\n800,190,0\n",
     ["bad.csv: line 3: column 2 (inclination)", "outside 0 .. 180 deg"]),
    ("measured_depth_m,inclination_deg,azimuth_deg\n0,0,0\n800,nan,0\n", ["bad.csv: line 3: column 2", "not a finite"]),
    ("measured_depth_m,inclination_deg,azimuth_deg\n0,0,0\n900,10,0\n",
     ["bad.csv: the survey reaches 900 m of measured depth, short of the pump depth 1530 m"]),
])
def test_bad_surveys_are_one_line_with_exit_code_2(run_cli, tmp_path, content, words):
    survey = tmp_path / "bad.csv"
    survey.write_text(content, encoding="utf-8")
    code, out, err = run_cli("downhole", SK8, "--card", DEVIATED_CARD, "--survey", survey)
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith("pumpjack: error: ")
    assert all(word in err for word in words), err


@pytest.mark.parametrize("argv, words", [
    (("downhole", SK8, "--card", DEVIATED_CARD, "--survey", J_SURVEY, "--method", "gibbs"),
     "--method gibbs: the survey makes the well deviated"),
    (("downhole", SK8, "--card", DEVIATED_CARD, "--survey", J_SURVEY, "--guide-limit", "100"), "--guide-limit: '100' has no unit"),
    (("downhole", SK8, "--card", DEVIATED_CARD, "--survey", J_SURVEY, "--guide-limit", "-3 lbf"), "--guide-limit -3 lbf: must be above 0"),
    (("dynamics", SK8, "--survey", J_SURVEY), "--survey applies to --well-model wave"),
    (("downhole", SK8, "--card", DEVIATED_CARD, "--survey", REPO_ROOT / "samples" / "none.csv"), "none.csv: cannot read: no such file"),
])
def test_bad_options_are_one_line_with_exit_code_2(run_cli, argv, words):
    code, out, err = run_cli(*argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and words in err, err


def test_a_friction_coefficient_beyond_one_is_refused_naming_the_key(run_cli, tmp_path):
    unit = tmp_path / "unit.toml"
    unit.write_text(SK8_TOML.read_text(encoding="utf-8").replace("[well]\n", "[well]\nrod_friction_coefficient = 1.5\n", 1),
                    encoding="utf-8")
    code, out, err = run_cli("downhole", unit, "--card", DEVIATED_CARD, "--survey", J_SURVEY)
    assert code == 2 and "well.rod_friction_coefficient" in err and err.count("\n") == 1


def test_predict_heads_at_the_true_vertical_depth_and_the_drag(run_json):
    doc = run_json("predict", SK8, "--survey", J_SURVEY, "--friction-coefficient", "0.2", "--damping", "0.05",
                   "--samples", "64")
    s = doc["summary"]
    fluid_load = SK8_FLUID_DENSITY * STANDARD_GRAVITY * (PUMP_TVD - SUBMERGENCE) * math.pi * PLUNGER**2 / 4
    assert s["fluid_load_n"] == pytest.approx(fluid_load, rel=1e-9)
    assert s["pump_true_vertical_depth_m"] == pytest.approx(PUMP_TVD, rel=1e-9)
    assert abs(s["rod_energy_residual"]) < 1e-5 and s["friction_work_per_cycle_j"] > 0
    # polished-rod work = pump work + damping + drag
    assert s["surface_card_work_j"] == pytest.approx(
        s["pump_card_work_j"] + s["damping_dissipation_j"] + s["friction_work_per_cycle_j"], rel=1e-5)


def test_dynamics_wave_model_along_the_hole(run_json):
    doc = run_json("dynamics", SK8, "--well-model", "wave", "--survey", J_SURVEY, "--friction-coefficient", "0.2",
                   "--damping", "0.1", "--samples", "64")
    s = doc["summary"]
    assert s["friction_work_per_cycle_j"] > 0 and abs(s["machine_energy_residual"]) < 1e-3
    assert s["pump_true_vertical_depth_m"] == pytest.approx(PUMP_TVD, rel=1e-9)


def test_batch_takes_a_survey_per_well(run_cli, run_json, tmp_path):
    manifest = tmp_path / "m.csv"
    manifest.write_text(f"well,unit,card,survey\nj,{SK8},{DEVIATED_CARD},{J_SURVEY}\nv,{SK8},{SK8_CARD},\n",
                        encoding="utf-8")
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", manifest, "--store", store, "--workers", "1", "--analyses", "downhole")
    assert code == 0, err
    code, out, err = run_cli("batch", "export", "--store", store, "-f", "json")
    assert code == 0, err
    rows = json.loads(out)["series"]
    by_well = {well: i for i, well in enumerate(rows["well"])}
    single = run_json("downhole", SK8, "--card", DEVIATED_CARD, "--survey", J_SURVEY)["summary"]
    assert rows["max_side_load_n_m"][by_well["j"]] == pytest.approx(single["max_side_load_n_m"], rel=1e-9)
    assert rows["pump_true_vertical_depth_m"][by_well["v"]] is None  # the vertical well has no survey figures


def test_predict_with_a_vertical_survey_is_the_vertical_prediction(run_json, tmp_path):
    plain = run_json("predict", SK8, "--samples", "64", "--damping", "0.1")
    surveyed = run_json("predict", SK8, "--samples", "64", "--damping", "0.1", "--survey", _vertical_survey(tmp_path))
    assert_same_summary(surveyed["summary"], plain["summary"], 1e-9, 1e-9)
    assert surveyed["summary"]["friction_work_per_cycle_j"] == 0.0


def test_a_card_is_judged_by_the_rods_weight_along_the_hole(sk8_unit, tmp_path):
    """A connected string's loads center on the weight it hangs; along a hole that turns horizontal at
    300 m, that is far less than its buoyant weight, and a card of it must not be refused as a parted
    string's (core/rods/plausibility.py)."""
    from pumpjack_cli.analysis.deviated import with_survey
    from pumpjack_cli.core.rods.plausibility import check_card_loads
    from pumpjack_cli.errors import CardError

    survey = tmp_path / "lateral.csv"
    survey.write_text("measured_depth_m,inclination_deg,azimuth_deg\n0,0,0\n300,0,0\n600,90,0\n2000,90,0\n",
                      encoding="utf-8")
    unit = with_survey(sk8_unit, survey)
    limits = unit.well_limits()
    hole = unit.well.path()
    q1, q2 = unit.rods().buoyant_weight_per_length(SK8_FLUID_DENSITY)[:2]
    joint = 0.23 * SK8_PUMP_DEPTH  # the 1 in rods end 51.9 m into the quarter circle of radius R, phi = (s - 300) / R
    build = 300.0 / math.radians(90.0)
    into = math.sin((joint - 300.0) / build)  # int cos(phi) ds from 300 m to the joint, over R
    assert hole.vertical_depth(SK8_PUMP_DEPTH) == pytest.approx(300.0 + build, rel=1e-9)
    assert limits.hanging_weight == pytest.approx(q1 * (300.0 + build * into) + q2 * build * (1 - into), rel=1e-6)
    theta = np.linspace(0.0, 2 * np.pi, 360, endpoint=False)
    position = 1.5 * (1 - np.cos(theta))
    load = limits.hanging_weight + 6e3 * (1 + np.sin(theta))  # the weight along the hole and a fluid load
    check_card_loads(load, position, stroke=3.0, crank_speed=1.0, well=limits, structure_rating=None, source="c")
    vertical = sk8_unit.well_limits()
    with pytest.raises(CardError, match="median load"):
        check_card_loads(load, position, stroke=3.0, crank_speed=1.0, well=vertical, structure_rating=None, source="c")
