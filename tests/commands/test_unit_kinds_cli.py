"""A Mark II and an air-balanced unit through the commands that read a unit: kinematics,
predict, torque, downhole and batch (issue 22), with their sample cards."""

from __future__ import annotations

import json
import math
import sqlite3

import pytest

from helpers import sample_card

KINDS = {"m-912d-365-168": "mark-ii", "air-balanced-example": "air-balanced"}


@pytest.mark.parametrize("unit", KINDS)
def test_kinematics_of_each_kind(run_json, unit):
    doc = run_json("kinematics", unit, "--spm", "6")
    position = doc["series"]["position_m"]
    assert max(position) - min(position) == pytest.approx(doc["summary"]["stroke_m"], rel=1e-3)


@pytest.mark.parametrize("unit, variable", [("m-912d-365-168", "counterbalance_moment_n_m"),
                                             ("air-balanced-example", "air_pressure_pa")])
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
