"""A Mark II and an air-balanced unit through the commands that read a unit: kinematics,
predict, torque, downhole and batch (issue 22), with their sample cards."""

from __future__ import annotations

import json
import math
import sqlite3

import pytest

from helpers import REPO_ROOT, sample_card

KINDS = {"m-912d-365-168": "mark-ii", "a-228d-246-86": "air-balanced"}


@pytest.mark.parametrize("unit", KINDS)
def test_kinematics_of_each_kind(run_json, unit):
    doc = run_json("kinematics", unit, "--spm", "6")
    position = doc["series"]["position_m"]
    assert max(position) - min(position) == pytest.approx(doc["summary"]["stroke_m"], rel=1e-3)


@pytest.mark.parametrize("unit, variable", [("m-912d-365-168", "counterbalance_moment_n_m"),
                                             ("a-228d-246-86", "air_pressure_pa")])
def test_torque_balances_each_kind_in_its_own_terms(run_json, unit, variable):
    doc = run_json("torque", unit, "--card", sample_card(unit))
    summary = doc["summary"]
    recommended = summary[f"recommended_{variable}"]
    assert recommended > 0
    # the recommended counterbalance levels the two strokes' peaks (the default criterion)
    assert summary["recommended_upstroke_peak_torque_n_m"] == pytest.approx(
        summary["recommended_downstroke_peak_torque_n_m"], rel=1e-6)
    # the mean net torque is the card's work per radian: the counterbalance does no work per turn
    net = doc["series"]["recommended_net_torque_n_m"]
    assert sum(net) / len(net) * 2 * math.pi == pytest.approx(summary["card_work_j"], rel=2e-3)


@pytest.mark.parametrize("unit", KINDS)
def test_downhole_and_predict_run_on_each_kind(run_json, unit):
    pump = run_json("downhole", unit, "--card", sample_card(unit))
    assert pump["summary"]["fluid_load_n"] > 0
    predicted = run_json("predict", unit, "--spm", "6")
    assert predicted["summary"]["stroke_m"] > 0


def test_batch_stores_each_kind(run_cli, tmp_path):
    manifest = tmp_path / "manifest.csv"
    manifest.write_text("well,unit,card\n" + "".join(f"w{i},{unit},{sample_card(unit)}\n"
                                                     for i, unit in enumerate(KINDS)), encoding="utf-8")
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", "run", manifest, "--store", store, "--workers", "1")
    assert code == 0, err
    rows = sqlite3.connect(store).execute("SELECT unit, analysis, status FROM results").fetchall()
    assert sorted(rows) == sorted((unit, analysis, "ok") for unit in KINDS for analysis in ("downhole", "torque"))


def test_units_lists_the_new_kinds(run_cli):
    code, out, err = run_cli("units", "-f", "json")
    assert code == 0
    assert set(KINDS) <= set(json.loads(out)["series"]["name"])


def test_the_spatial_model_is_refused_for_a_class_three_unit_with_masses(run_cli, tmp_path):
    """With link masses a Mark II runs the API torque with its inertia terms; the spatial
    kinetostatics (reactions, torque --method exact) is the class I unit's and says so."""
    conventional = (REPO_ROOT / "configs" / "c-114d-133-54.toml").read_text(encoding="utf-8")
    masses = conventional[conventional.index("[masses.crank_arm]"):conventional.index("# ILLUSTRATIVE well")]
    mark = (REPO_ROOT / "configs" / "m-912d-365-168.toml").read_text(encoding="utf-8")
    unit = tmp_path / "mark.toml"
    unit.write_text(mark.replace("[counterbalance]", masses + "\n[counterbalance]"), encoding="utf-8")
    card = sample_card("m-912d-365-168")
    code, out, err = run_cli("torque", unit, "--card", card, "-f", "json")
    assert code == 0, err
    for argv in (("reactions", unit, "--card", card), ("torque", unit, "--card", card, "--method", "exact")):
        code, out, err = run_cli(*argv)
        assert code == 2 and err.count("\n") == 1 and "is a mark-ii unit; the spatial kinetostatics" in err, err


def test_batch_names_a_mark_ii_and_an_air_balanced_unit_of_a_catalogue(run_cli, tmp_path):
    """Manifest rows naming catalogue units by designation and crank hole: the Mark II of the
    sample catalogue ([LufkinM912]) and an air-balanced row with the bundled unit's letters ([UnitDatabase2018] row 1669); the
    torque of each equals the single command's on the same catalogue unit."""
    catalogue = tmp_path / "field.csv"
    sample = (REPO_ROOT / "samples" / "catalogue.csv").read_text(encoding="utf-8")
    header = next(line for line in sample.splitlines() if line and not line.startswith("#"))
    mark = next(line for line in sample.splitlines() if line.startswith("M-912D-365-168,1,"))
    catalogue.write_text(
        "designation,crank_hole,class,rotation,A_in,C_in,I_in,P_in,K_in,R_in,B_lbf,air_piston_diameter_in,"
        "air_bottom_volume_ft3,air_lever_in,air_pressure_psi\n"
        "A-228D-246-86,1,air-balanced,ccw,131,56,54,122,133.42,18.25,73,12,10.24,80,150\n", encoding="utf-8")
    marks = tmp_path / "marks.csv"
    marks.write_text(f"{header}\n{mark}\n", encoding="utf-8")
    for units, name, card in ((catalogue, "A-228D-246-86/1", sample_card("a-228d-246-86")),
                              (marks, "M-912D-365-168/1", sample_card("m-912d-365-168"))):
        manifest = tmp_path / "manifest.csv"
        manifest.write_text(f"well,unit,card\nw1,{name},{card}\n", encoding="utf-8")
        store = tmp_path / f"{name[0]}.sqlite"
        code, out, err = run_cli("batch", "run", manifest, "--store", store, "--catalogue", units,
                                 "--analyses", "torque", "--workers", "1")
        assert code == 0, err
        stored = sqlite3.connect(store).execute(
            "SELECT status, recommended_peak_net_torque_n_m FROM results").fetchall()
        assert len(stored) == 1 and stored[0][0] == "ok"
        code, out, err = run_cli("torque", name, "--card", card, "--catalogue", units, "-f", "json")
        assert code == 0, err
        assert stored[0][1] == pytest.approx(json.loads(out)["summary"]["recommended_peak_net_torque_n_m"],
                                             rel=1e-12)
