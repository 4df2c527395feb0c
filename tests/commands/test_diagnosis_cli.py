"""The pump's condition, production and fluid level as a user gets them from `downhole`,
`predict` and `batch`.

Cards are made by the predictive model with a fault at the pump (``core.rods.predict``,
``core.rods.pump_faults``) and written as a dynamometer's CSV (time, position, load) in
tmp_path; the commands read them as any card.
"""

from __future__ import annotations

import csv
import io
import json
import math
import re
import sqlite3
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.rods.predict import predict_cards
from pumpjack_cli.core.rods.pump import pump_pressures
from pumpjack_cli.core.rods.pump_faults import hanging_pump, parted_damping, parted_string

from helpers import sample_card

UNIT = "c-80d-133-48"        # the API unit of [Guo2007] without link masses: the API torque, quick
SPM = 8.0
DAMPING = 0.1


def _write(path: Path, cards, noise: float = 0.0, seed: int = 0) -> Path:
    """A card file as a dynamometer writes one: time, position and load, one stroke."""
    rng = np.random.default_rng(seed)
    load = cards.polished_rod_load + noise * np.ptp(cards.polished_rod_load) * rng.standard_normal(cards.time.size)
    rows = zip(cards.time, cards.polished_rod_position, load)
    path.write_text("time_s,position_m,load_n\n" + "".join(f"{float(t)!r},{float(s)!r},{float(w)!r}\n"
                                                            for t, s, w in rows))
    return path


def _cards(pump=None, rods=None, damping: float = DAMPING, samples: int = 200):
    unit = load_unit(UNIT)
    return predict_cards(unit.geometry.mechanism(), SPM * math.pi / 30, rods or unit.rods(), pump or unit.pump(),
                         damping=damping, fluid_density=unit.well.fluid_density, samples=samples, resolution=samples)


def _summary(run_cli, *argv) -> tuple[dict, str]:
    code, out, err = run_cli("downhole", UNIT, *argv, "-f", "json", "--what", "summary")
    assert code == 0, err
    return json.loads(out)["summary"], err


@pytest.mark.parametrize("share", [0.25, 0.55, 0.85])
def test_a_parted_string_is_labelled_with_its_break_depth_never_refused(run_cli, tmp_path, share):
    # the rods cut at the break, nothing on their free end, the whole string's damping per length
    unit = load_unit(UNIT)
    rods = unit.rods()
    hanging = parted_string(rods, share * rods.total_length)
    cards = _cards(hanging_pump(unit.pump()), hanging, parted_damping(rods, hanging, DAMPING))
    summary, err = _summary(run_cli, "--card", _write(tmp_path / "parted.csv", cards, 0.01, 7))
    assert summary["pump_condition"] == "rod_part"
    # the issue asks for the break within 15 % of its depth
    assert summary["rod_break_depth_m"] == pytest.approx(share * rods.total_length, rel=0.15)
    # the energy balance has no fluid load to balance: the stated fallback, and said so
    assert summary["damping_factor"] == 0.05
    assert "parted rod string" in err and "damping factor 0.05 assumed" in err


def test_a_full_pump_of_the_well_is_labelled_full_with_its_evidence(run_cli, tmp_path):
    summary, _ = _summary(run_cli, "--card", _write(tmp_path / "full.csv", _cards(), 0.01))
    assert summary["pump_condition"] == "full" and summary["pump_condition_confidence"] > 0.9
    assert summary["pump_condition_second"] == ""
    # Rowlan's F_o line from the well's fluid level, and the card on it
    unit = load_unit(UNIT)
    discharge, intake = unit.pump_pressures()
    area = math.pi * unit.well.plunger_diameter**2 / 4
    assert summary["reference_fluid_load_n"] == pytest.approx((discharge - intake) * area, rel=1e-12)
    assert summary["fluid_load_n"] == pytest.approx(summary["reference_fluid_load_n"], rel=0.05)
    assert summary["standing_valve_opening_percent"] < 2 and summary["travelling_valve_opening_percent"] > 98
    # the intake pressure from the card's fluid load and the discharge pressure over the pump's depth, and
    # the liquid above the pump it holds (no casing pressure): the well's fluid level, to the card's F_o
    rho_g = unit.well.fluid_density * 9.80665
    assert summary["discharge_pressure_pa"] == pytest.approx(rho_g * unit.well.pump_depth, rel=1e-12)
    assert summary["pump_intake_pressure_pa"] == pytest.approx(
        summary["discharge_pressure_pa"] - summary["fluid_load_n"] / area, rel=1e-12)
    assert summary["pump_submergence_m"] == pytest.approx(summary["pump_intake_pressure_pa"] / rho_g, rel=1e-12)
    error = abs(summary["fluid_load_n"] / summary["reference_fluid_load_n"] - 1.0)
    assert error < 0.02
    assert summary["pump_submergence_m"] == pytest.approx(
        unit.well.pump_submergence, abs=1.5 * error * summary["reference_fluid_load_n"] / (rho_g * area) + 0.1)
    assert summary["fluid_level_depth_m"] == pytest.approx(unit.well.pump_depth - summary["pump_submergence_m"])
    assert "inferred_production_m3_d" not in summary          # no runtime, no rate


def test_a_pounding_pump_reads_its_fillage(run_cli, tmp_path):
    unit = load_unit(UNIT)
    discharge, intake = pump_pressures(unit.well.pump_depth, unit.well.fluid_density, submergence=5.0)
    pump = replace(unit.pump(), discharge_pressure=discharge, intake_pressure=intake, fillage=0.62)
    summary, _ = _summary(run_cli, "--card", _write(tmp_path / "pound.csv", _cards(pump), 0.01, 3))
    assert summary["pump_condition"] == "fluid_pound"
    assert summary["pump_fillage_percent"] == pytest.approx(62.0, abs=3.0)


def test_production_and_energy_per_day_follow_from_the_card(run_cli, tmp_path):
    card = _write(tmp_path / "full.csv", _cards(), 0.01)
    summary, err = _summary(run_cli, "--card", card, "--runtime", "18 h", "--system-efficiency", "0.6",
                            "--electricity-price", "0.1")
    assert summary["runtime_percent"] == pytest.approx(75.0)
    # no clearance data in the unit: no slippage, said so; production = displacement x runtime
    assert "no slippage deducted" in err and "pump_slippage_m3_d" not in summary
    assert summary["inferred_production_m3_d"] == pytest.approx(0.75 * summary["pump_displacement_m3_d"], rel=1e-12)
    # polished-rod power = card work / period; / 0.6 x 18 h; at 0.1 per kWh
    power = summary["surface_card_work_j"] * summary["strokes_per_minute_spm"] / 60
    assert summary["energy_per_day_kwh_d"] == pytest.approx(power / 0.6 * 18 / 1000, rel=1e-9)
    assert summary["electricity_cost_per_day"] == pytest.approx(0.1 * summary["energy_per_day_kwh_d"], rel=1e-9)
    stated, _ = _summary(run_cli, "--card", card, "--runtime", "75 %", "--pump-efficiency", "85 %")
    assert stated["inferred_production_m3_d"] == pytest.approx(0.85 * 0.75 * summary["pump_displacement_m3_d"])


def test_the_slippage_past_the_plunger_comes_off_the_production(run_cli, tmp_path):
    # the well with a plunger fit and length: q = pi D (c/2)^3 dp / (12 mu L_p) while the plunger is loaded
    source = (Path(__file__).resolve().parents[2] / "configs" / f"{UNIT}.toml").read_text(encoding="utf-8")
    unit_file = tmp_path / "fitted.toml"
    unit_file.write_text(source.replace('plunger_diameter = "1.25 in"', 'plunger_diameter = "1.25 in"\n'
                                        'plunger_clearance = "0.005 in"\nplunger_length = "4 ft"'), encoding="utf-8")
    code, out, err = run_cli("downhole", unit_file, "--card", _write(tmp_path / "full.csv", _cards(), 0.01),
                             "--runtime", "24 h", "-f", "json", "--what", "summary")
    assert code == 0, err
    summary = json.loads(out)["summary"]
    well = load_unit(UNIT).well
    area = math.pi * well.plunger_diameter**2 / 4
    dp = summary["fluid_load_n"] / area
    mu = well.fluid_kinematic_viscosity * well.fluid_density
    slip = math.pi * well.plunger_diameter * (0.005 * 0.0254 / 2)**3 * dp / (12 * mu * 4 * 0.3048) * 86400
    # loaded for about half the cycle
    assert summary["pump_slippage_m3_d"] == pytest.approx(0.5 * slip, rel=0.1)
    assert summary["inferred_production_m3_d"] == pytest.approx(
        summary["pump_displacement_m3_d"] - summary["pump_slippage_m3_d"], rel=1e-12)


@pytest.mark.parametrize("argv, words", [
    (("--runtime", "75"), "--runtime: '75' has no unit"),
    (("--runtime", "25 h"), "--runtime: '25 h' is outside 0 .. 100 %"),
    (("--runtime", "0 %"), "--runtime: '0 %' is outside"),
    (("--pump-efficiency", "120 %", "--runtime", "24 h"), "--pump-efficiency: '120 %' is outside"),
    (("--electricity-price", "0.1"), "--electricity-price: a rate per day needs --runtime"),
    (("--pump-efficiency", "85 %"), "--pump-efficiency: a rate per day needs --runtime"),
])
def test_bad_production_options_get_one_line_and_exit_2(run_cli, argv, words):
    code, out, err = run_cli("downhole", "sk8-3.5-4000", "--card", Path(__file__).resolve().parents[2] / "samples" /
                             "sk8-3.5-4000-card.csv", *argv)
    assert code == 2 and out == ""
    assert err.startswith(f"pumpjack: error: {words}") and err.count("\n") == 1


@pytest.mark.parametrize("argv, words", [
    (("--tag-bottom", "5"), "--tag-bottom: '5' has no unit"),
    (("--tag-top", "30 m"), "the top tag must be within the plunger's stroke"),
    (("--travelling-valve-leak", "-5 m3/d"), "--travelling-valve-leak: '-5 m3/d' must be above 0"),
    (("--standing-valve-leak", "5 kg"), "--standing-valve-leak"),
    (("--parted-at", "150 %"), "--parted-at: the break must lie a rod's length"),
    (("--parted-at", "1e-300 m"), "--parted-at: the break must lie a rod's length"),
    (("--parted-at", "50 %", "--tag-top", "3 cm"), "--parted-at: nothing hangs on a parted string's free end"),
    (("--travelling-valve-leak", "50 %", "--fillage", "80 %"), "valve leaks are modelled with a pump full of liquid"),
])
def test_bad_fault_options_get_one_line_and_exit_2(run_cli, argv, words):
    code, out, err = run_cli("predict", UNIT, "--spm", "8", "--damping", "0.1", "--samples", "64", *argv)
    assert code == 2 and out == ""
    assert words in err and err.count("\n") == 1 and err.startswith("pumpjack: error: ")


def test_faults_are_refused_with_the_machine_coupled(run_cli):
    code, _, err = run_cli("predict", "sk8-3.5-4000", "--crank-motion", "dynamic", "--damping", "0.1",
                           "--tag-bottom", "5 cm")
    assert code == 2 and "tagging down: the pump faults are simulated at uniform crank speed" in err


def test_predict_simulates_each_fault_for_the_user(run_json):
    def run(*argv):
        return run_json("predict", UNIT, "--spm", "8", "--damping", "0.1", "--samples", "128", *argv)

    def summary(*argv):
        return run(*argv)["summary"]

    full = summary()
    leaking = summary("--travelling-valve-leak", "120 %")
    assert leaking["net_pump_stroke_m"] < 0.8 * full["net_pump_stroke_m"]
    lowest = min(run("--tag-bottom", "5 cm")["series"]["pump_load_n"])
    assert lowest < min(run()["series"]["pump_load_n"]) - 0.2 * full["fluid_load_n"]
    parted = summary("--parted-at", "40 %")
    assert parted["buoyant_rod_weight_n"] == pytest.approx(0.4 * full["buoyant_rod_weight_n"], rel=1e-9)
    assert parted["pump_displacement_m3_d"] == 0.0


def _sequence(folder: Path, name: str, pumps) -> list[str]:
    """Manifest rows of one well's cards, five minutes apart."""
    rows = []
    for k, pump in enumerate(pumps):
        card = _write(folder / f"{name}-{k:02d}.csv", _cards(pump), 0.005, k)
        rows.append(f"{name},{UNIT},{card.name},2026-11-24T{8 + k // 12:02d}:{5 * (k % 12):02d}")
    return rows


def test_batch_tells_a_pump_going_off_from_gas_coming_and_going(run_cli, tmp_path):
    # 20 cards each: the fluid level falling to the pump and the fillage with it, card after card;
    # gas filling the barrel more on one stroke and less on the next, the fluid level high
    unit = load_unit(UNIT)
    pump, well = unit.pump(), unit.well
    levels = np.linspace(well.pump_submergence, 3.0, 20)
    going_off = []
    for k, level in enumerate(levels):
        discharge, intake = pump_pressures(well.pump_depth, well.fluid_density, submergence=float(level))
        going_off.append(replace(pump, discharge_pressure=discharge, intake_pressure=intake,
                                 fillage=float(np.clip(1.02 - 0.025 * k, 0.5, 1.0))))
    swings = np.random.default_rng(5).permutation(np.repeat([0.55, 0.62, 0.78, 0.86], 5))
    gassy = [replace(pump, fillage=float(f), gas_exponent=1.2) for f in swings]
    rows = _sequence(tmp_path, "off", going_off) + _sequence(tmp_path, "gas", gassy)
    manifest = tmp_path / "field.csv"
    manifest.write_text("well,unit,card,timestamp,runtime\n" + "".join(f"{row},20 h\n" for row in rows))
    store = tmp_path / "r.sqlite"
    code, _, err = run_cli("batch", manifest, "--store", store, "--analyses", "downhole", "--workers", "1")
    assert code == 0, err
    trends = {}
    for well_name in ("off", "gas"):
        code, out, err = run_cli("batch", "trend", "--store", store, "--well", well_name, "-f", "json")
        assert code == 0, err
        trends[well_name] = json.loads(out)["series"]
    assert set(trends["off"]["sequence_condition"][6:]) == {"pump_off"}
    assert set(trends["gas"]["sequence_condition"][6:]) == {"gas_interference"}
    # card by card the shape says fluid pound once the pump is going off, gas on the gas cards
    assert set(trends["off"]["pump_condition"][-8:]) == {"fluid_pound"}
    assert trends["gas"]["pump_condition"].count("gas_interference") >= 18
    # the label columns are text in the store and in the export; the runtime came from the manifest
    db = sqlite3.connect(store)
    types = {row[1]: row[2] for row in db.execute("PRAGMA table_info(results)")}
    db.close()
    assert types["pump_condition"] == "TEXT" and types["pump_condition_second"] == "TEXT"
    code, out, err = run_cli("batch", "export", "--store", store, "--well", "gas", "-f", "csv")
    assert code == 0, err
    columns = next(csv.DictReader(io.StringIO(out)))
    assert columns["pump_condition"] in ("gas_interference", "fluid_pound")
    assert float(columns["runtime_percent"]) == pytest.approx(100 * 20 / 24)


def test_a_pump_whose_leaks_outrun_it_lifts_nothing_and_both_leaking_drain_the_tubing(run_cli):
    """A travelling valve leaking ten times the displacement rate: the plunger lifts nothing, and the
    pump's displacement is 0, not the chamber bookkeeping's 1e-11 m of net stroke either side of it.
    Both valves leaking three times the rate let the tubing drain through the pump: a negative
    displacement, said with its rate (the model holds the tubing's pressure)."""
    code, out, err = run_cli("predict", UNIT, "--spm", "8", "--damping", "0.1", "--travelling-valve-leak", "1000 %",
                             "--what", "summary", "-f", "json")
    summary = json.loads(out)["summary"]
    assert code == 0 and summary["net_pump_stroke_m"] == 0.0 == summary["pump_displacement_m3_d"], err
    code, out, err = run_cli("predict", UNIT, "--spm", "8", "--damping", "0.1", "--travelling-valve-leak", "300 %",
                             "--standing-valve-leak", "300 %", "--what", "summary", "-f", "json")
    rate = json.loads(out)["summary"]["pump_displacement_m3_d"]
    assert code == 0 and rate < 0
    assert f"the tubing drains back into the well through it ({rate:.4g} m³/d" in err


def test_a_card_of_few_points_is_said_to_be_too_coarse_for_the_condition(run_cli, tmp_path):
    """SK8's sample card cut to 16 and to 24 points a stroke: too few to resolve the ends of the
    stroke, where tagging and leaks show (the 16-point card's Fourier ringing at the load's pickup
    read as a tag); the label is printed with a warning saying so. The card as shipped (360 points)
    has no such warning."""
    lines = sample_card("sk8-3.5-4000").read_text(encoding="utf-8").splitlines()
    header = [line for line in lines if line.startswith("#") or not line[:1].isdigit()]
    rows = [line for line in lines if line[:1].isdigit()]
    for points in (16, 24):
        path = tmp_path / f"few-{points}.csv"
        path.write_text("\n".join(header + rows[::-(-len(rows) // points)]) + "\n", encoding="utf-8")
        code, _, err = run_cli("downhole", "sk8-3.5-4000", "--card", path, "--what", "summary", "-f", "json")
        said = re.search(r"(\d+) points a stroke are too few to read the pump's condition", err)
        assert code == 0 and said and points - 1 <= int(said[1]) <= points, err   # a closing repeat is dropped
    code, _, err = run_cli("downhole", "sk8-3.5-4000", "--card", sample_card("sk8-3.5-4000"), "--what", "summary",
                           "-f", "json")
    assert code == 0 and "too few to read the pump's condition" not in err
