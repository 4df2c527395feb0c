"""`pumpjack predict` and `dynamics --well-model wave` as a user runs them.

Expected values come from independent routes: the diagnostic of `pumpjack downhole`
applied to the predicted surface card (a different solver of the same wave equation,
[Gibbs1963]), the loop area of the printed card, the torque analysis of the spatial
kinetostatics against the equation of motion's gearbox torque ([SK8Rotation2013] eq. 1,
[Spatial7SK12]), hydrostatics by hand for the fluid load ([API11L]) and limits.
"""

from __future__ import annotations

import csv
import io
import json
import math
import re

import numpy as np
import pytest

from pumpjack_cli.core.constants import STANDARD_GRAVITY

from helpers import FOOT, INCH, KILOGRAM_FORCE, POUND_FORCE, PSI, SK8, series


C114 = ("predict", "c-114d-133-54", "--spm", "10", "--damping", "0.1")
SK8_COUPLED = ("predict", "sk8-3.5-4000", "--crank-motion", "dynamic", "--damping", "0.1", "--samples", "256")


def test_predicted_surface_card_gives_back_the_pump_card(run_json, tmp_path):
    """Issue 13 round trip: the predicted surface card through `pumpjack downhole` with the same
    rods and damping: pump loads within 1 % of the load range, gross stroke within 1 mm."""
    predicted = run_json(*C114)
    card = tmp_path / "predicted.csv"
    rows = zip(series(predicted, "time_s"), series(predicted, "position_m"), series(predicted, "rod_load_n"))
    card.write_text("time_s,position_m,rod_load_n\n" + "".join(f"{t},{s},{w}\n" for t, s, w in rows))
    back = run_json("downhole", "c-114d-133-54", "--card", card, "--damping", "0.1", "--samples", "360")
    angle, other = series(predicted, "crank_angle_deg"), series(back, "crank_angle_deg")
    recovered = np.interp(angle, other, series(back, "pump_load_n"), period=360.0)
    load_range = np.ptp(series(predicted, "rod_load_n"))
    assert np.max(np.abs(recovered - series(predicted, "pump_load_n"))) < 0.01 * load_range
    assert abs(back["summary"]["gross_pump_stroke_m"] - predicted["summary"]["gross_pump_stroke_m"]) < 1e-3


def test_energy_per_cycle_closes(run_json):
    """Polished-rod work = work on the fluid + damping dissipation (1e-4), and the printed card's
    loop area (trapezoids over the printed samples) is the polished-rod work."""
    doc = run_json(*C114)
    s = doc["summary"]
    assert abs(s["rod_energy_residual"]) < 1e-4
    assert s["surface_card_work_j"] == pytest.approx(s["pump_card_work_j"] + s["damping_dissipation_j"], rel=1e-4)
    position, load = series(doc, "position_m"), series(doc, "rod_load_n")
    area = float(np.sum(0.5 * (load + np.roll(load, -1)) * (np.roll(position, -1) - position)))
    assert area == pytest.approx(s["surface_card_work_j"], rel=2e-3)
    assert s["polished_rod_power_w"] == pytest.approx(s["surface_card_work_j"] * 10.0 / 60.0, rel=1e-9)


def test_fluid_load_and_pump_work_of_a_full_pump_by_hand(run_json):
    """F_o = rho g (L - h) A_p (C-114D: 4000 ft, 300 ft of fluid above the pump, 900 kg/m^3,
    1.5 in plunger) and the pump card's work is F_o times the net stroke."""
    s = run_json(*C114)["summary"]
    area = math.pi * (1.5 * INCH) ** 2 / 4.0
    fluid_load = 900.0 * STANDARD_GRAVITY * (4000.0 - 300.0) * FOOT * area
    assert s["fluid_load_n"] == pytest.approx(fluid_load, rel=1e-12)
    assert s["pump_card_work_j"] == pytest.approx(fluid_load * s["net_pump_stroke_m"], rel=1e-3)
    # API RP 11L's design counterbalance effect from the same W_rf and F_o
    assert s["rp11l_counterbalance_effect_n"] == pytest.approx(1.06 * (s["buoyant_rod_weight_n"] + fluid_load / 2),
                                                               rel=1e-12)


def test_options_override_the_well(run_json):
    """A lower fluid level raises the fluid load by rho g dh A_p; an empty barrel carries none."""
    base = run_json(*C114)["summary"]
    deeper = run_json(*C114, "--submergence", "100 ft")["summary"]
    area = math.pi * (1.5 * INCH) ** 2 / 4.0
    assert deeper["fluid_load_n"] - base["fluid_load_n"] == pytest.approx(
        900.0 * STANDARD_GRAVITY * 200.0 * FOOT * area, rel=1e-9)
    empty = run_json(*C114, "--fillage", "0 %")["summary"]
    assert abs(empty["pump_card_work_j"]) < 1e-6 * base["pump_card_work_j"]
    assert empty["net_pump_stroke_m"] == pytest.approx(0.0, abs=1e-9)


def test_very_slow_full_pump_is_the_static_card(run_json):
    """At 0.1 strokes/min the dynamics vanish: PPRL = W_rf + F_o, MPRL = W_rf (0.5 %; what is
    left is the force wave Z dv = m a dv the plunger's start sends up the rods, proportional to
    the speed), and the plunger loses the static stretch of the stroke (1 mm)."""
    s = run_json("predict", "c-114d-133-54", "--spm", "0.1", "--damping", "0.1")["summary"]
    assert s["max_rod_load_n"] == pytest.approx(s["buoyant_rod_weight_n"] + s["fluid_load_n"], rel=0.005)
    assert s["min_rod_load_n"] == pytest.approx(s["buoyant_rod_weight_n"], rel=0.005)
    assert s["gross_pump_stroke_m"] == pytest.approx(s["stroke_m"] - s["static_stretch_m"], abs=1e-3)


def test_coupled_gearbox_torque_is_the_kinetostatic_net_torque(run_json):
    """Two models of the same crank: the equation of motion's net gearbox torque M_drive - I_drive eps
    (`dynamics --well-model wave`) and the spatial kinetostatics' net torque under the predicted load
    with the coupled omega, eps (`predict --crank-motion dynamic`)."""
    gearbox = series(run_json("dynamics", "sk8-3.5-4000", "--well-model", "wave", "--damping", "0.1", "--samples",
                         "256"), "net_torque_n_m")
    net = series(run_json(*SK8_COUPLED), "net_torque_n_m")
    assert np.max(np.abs(gearbox - net)) < 1e-5 * np.max(np.abs(gearbox))


def test_coupled_energy_closure_and_comparisons(run_json):
    s = run_json(*SK8_COUPLED)["summary"]
    assert abs(s["machine_energy_residual"]) < 1e-4
    assert abs(s["rod_energy_residual"]) < 1e-4
    assert s["energy_per_cycle_j"] == pytest.approx(s["rod_work_per_cycle_j"], rel=1e-4)
    speed = s["mean_crank_speed_rad_s"]
    assert s["speed_fluctuation_percent"] == pytest.approx(
        100.0 * (s["max_crank_speed_rad_s"] - s["min_crank_speed_rad_s"]) / speed, rel=1e-9)
    rigid = run_json("dynamics", "sk8-3.5-4000", "--steps", "3600")["summary"]
    assert s["rigid_rod_speed_fluctuation_percent"] == pytest.approx(rigid["speed_fluctuation_percent"], rel=1e-9)
    assert s["rigid_rod_max_motor_torque_n_m"] == pytest.approx(rigid["max_motor_torque_n_m"], rel=1e-6)
    for name in ("uniform_max_rod_load_n", "uniform_min_rod_load_n", "uniform_peak_net_torque_n_m"):
        assert math.isfinite(s[name])


def test_wave_dynamics_is_the_coupled_prediction(run_json):
    wave = run_json("dynamics", "sk8-3.5-4000", "--well-model", "wave", "--damping", "0.1", "--samples", "256")
    coupled = run_json(*SK8_COUPLED)
    for name in ("crank_speed_rad_s", "motor_torque_n_m", "rod_load_n"):
        assert np.array_equal(series(wave, name), series(coupled, name))
    assert wave["summary"]["speed_fluctuation_percent"] == coupled["summary"]["speed_fluctuation_percent"]


def test_field_units(run_json):
    si, field = run_json(*C114), run_json(*C114, "--units", "field")
    assert field["summary"]["max_rod_load_lbf"] * POUND_FORCE == pytest.approx(si["summary"]["max_rod_load_n"],
                                                                               rel=1e-9)
    assert np.allclose(series(field, "chamber_pressure_psi") * PSI, series(si, "chamber_pressure_pa"), rtol=1e-9)


@pytest.mark.parametrize("argv, fragment", [
    (("predict", "c-114d-133-54", "--spm", "10", "--fillage", "0.8"), "--fillage: '0.8' has no unit"),
    (("predict", "c-114d-133-54", "--spm", "10", "--fillage", "150 %"), "--fillage"),
    (("predict", "c-114d-133-54", "--spm", "10", "--fluid-density", "5 g/cm3"),
     "--fluid-density: Input should be less than or equal to 2000 kg/m³; got 5000 kg/m³"),
    (("predict", "c-114d-133-54", "--spm", "10", "--submergence", "10 km"), "--submergence"),
    (("predict", "c-114d-133-54", "--spm", "10", "--fluid-density", "900"), "--fluid-density: '900' has no unit"),
    (("predict", "c-114d-133-54", "--spm", "10", "--intake-pressure", "-1 MPa"), "--intake-pressure"),
    (("predict", "c-114d-133-54", "--spm", "10", "--damping", "0"), "'--damping': 0.0 is not above 0"),
    (("predict", "c-114d-133-54", "--spm", "10", "--submergence", "100 m", "--intake-pressure", "1 MPa"),
     "--submergence and --intake-pressure: give one of them"),
    (("predict", "c-114d-133-54"), "give the speed with --spm"),
    (("predict", "c-80d-133-48", "--crank-motion", "dynamic"), "[masses]"),
    (("predict", "sk8-3.5-4000", "--crank-motion", "dynamic", "--spm", "8"), "--spm"),
    (("predict", "unb-600a"), "not a beam pumping unit"),
    (("predict", "7sk12-2.5-5600", "--unanchored-tubing", "2-3/8"),
     "--unanchored-tubing with the unit's [well]: plunger_diameter 56 mm does not pass through the tubing"),
    (("dynamics", "sk8-3.5-4000", "--well-model", "wave", "--steps", "100"), "the wave model takes --samples"),
    (("dynamics", "sk8-3.5-4000", "--well-model", "wave", "--samples", "10"), "--samples"),
    (("dynamics", "sk8-3.5-4000", "--samples", "100"), "--samples applies to --well-model wave"),
    (("dynamics", "sk8-3.5-4000", "--damping", "0.1"), "--damping"),
    (("dynamics", "sk8-3.5-4000", "--well-model", "wave", "--damping", "0"), "'--damping': 0.0 is not above 0"),
])
def test_bad_options_are_one_line(run_cli, argv, fragment):
    code, out, err = run_cli(*argv, "-f", "csv")
    assert code == 2 and out == "", err
    assert err.startswith("pumpjack: error: ") and err.count("\n") == 1, err
    assert fragment in err, err


def test_the_net_torque_plot_shows_the_gearbox_rating():
    """SK8-3,5-4000's reducer is 4000 kgf·m ([GOST5866]): 39 226.6 N·m drawn at both signs."""
    from pumpjack_cli.analysis.predict import WellOverrides, predict
    from pumpjack_cli.config import load_unit

    result = predict(load_unit(SK8), None, "uniform", 256, 0.1, WellOverrides(), 1.0)
    (panel,) = [panel for panel in result.panels if panel.title == "net torque"]
    assert panel.levels == (("gearbox rating", pytest.approx(4000 * KILOGRAM_FORCE)),
                            ("", pytest.approx(-4000 * KILOGRAM_FORCE)))


def test_the_csv_summary_rows_carry_their_own_units_and_descriptions(run_cli):
    """Each CSV summary row of the coupled prediction (its summary is the longest: cards, machine,
    torque and ratings) carries its own unit and description: the unit agrees with the name's unit
    suffix and the ratings' rows say what they rate (a name given twice once shifted every later
    unit and description by a row)."""
    code, out, _ = run_cli(*SK8_COUPLED[:-1], "64", "--what", "summary", "-f", "csv")
    assert code == 0
    rows = {row["name"]: row for row in csv.DictReader(io.StringIO(out))}
    suffixes = {"N·m": "_n_m", "N": "_n", "%": "_percent", "m": "_m", "s": "_s", "deg": "_deg", "W": "_w", "J": "_j"}
    for name, row in rows.items():
        if row["unit"] in suffixes:
            assert name.endswith(suffixes[row["unit"]]), row
    assert "gearbox" in rows["gearbox_rating_n_m"]["description"]
    assert "stroke" in rows["stroke_loading_percent"]["description"]


def test_a_card_equal_peaks_cannot_balance_is_balanced_for_the_least_peak(run_cli):
    """At 60 strokes/min no moment >= 0 makes the SK8's stroke peaks equal: predict still prints its
    cards, says so, and recommends the moment of the least peak torque, whose peak is then no
    larger than the present counterbalance's (the minimum over all moments)."""
    code, out, err = run_cli("predict", "sk8-3.5-4000", "--spm", "60", "--damping", "0.1", "--samples", "64",
                             "--what", "summary", "-f", "json")
    assert code == 0, err
    assert "cannot be balanced by equal peaks" in err and "(min-peak)" in err
    summary = json.loads(out)["summary"]
    assert summary["recommended_peak_net_torque_n_m"] <= summary["peak_net_torque_n_m"]


def test_a_predicted_load_below_zero_is_said(run_cli):
    """At 30 strokes/min (2.7 times the SK8's rated speed) the predicted polished-rod load falls below
    zero, which no carrier bar can give (the rods float off it): the run says so, with where; at the
    rated speed the load stays above zero and nothing is said."""
    code, out, err = run_cli("predict", "sk8-3.5-4000", "--spm", "30", "--damping", "0.1", "--samples", "64",
                             "--what", "summary", "-f", "json")
    low = json.loads(out)["summary"]["min_rod_load_n"]
    assert code == 0 and low < 0
    assert f"the predicted polished-rod load falls to {low / 1e3:.4g} kN" in err and "rod float" in err
    code, out, err = run_cli("predict", "sk8-3.5-4000", "--damping", "0.1", "--samples", "64", "--what", "summary",
                             "-f", "json")
    assert code == 0 and json.loads(out)["summary"]["min_rod_load_n"] > 0 and "rod float" not in err


def test_a_pump_whose_strokes_alternate_is_predicted_with_its_strokes_named(run_cli):
    """C-228D-213-86 pounding fluid at 15 strokes/min and 40 % fillage settles into two unlike strokes
    (tests/core/rods/test_alternating_strokes.py): predict prints the cards of the stroke of the higher
    load and says so with both strokes' peaks and displacements; production is their mean."""
    code, out, err = run_cli("predict", "c-228d-213-86", "--spm", "15", "--fillage", "40 %", "--what", "summary",
                             "-f", "json")
    assert code == 0, err
    summary = json.loads(out)["summary"]
    assert summary["repeat_strokes"] == 2
    said = re.search(r"a cycle of 2 unlike strokes .* peak polished-rod loads ([\d.]+), ([\d.]+) kN, pump displacements "
                     r"([\d.]+), ([\d.]+) l; the cards are those of the highest load", err)
    assert said, err
    peaks, volumes = [float(x) for x in said.groups()[:2]], [float(x) for x in said.groups()[2:]]
    assert summary["max_rod_load_n"] / 1e3 == pytest.approx(max(peaks), abs=0.01)
    per_day = 86400 * summary["strokes_per_minute_spm"] / 60 * np.mean(volumes) / 1e3
    assert summary["pump_displacement_m3_d"] == pytest.approx(per_day, rel=1e-3)


def test_a_state_taken_above_the_tolerance_is_said_with_its_change(run_cli, monkeypatch):
    """When the march takes a state that repeats only within USABLE_CHANGE (a valve event moving by a
    sample, tests/core/rods/test_alternating_strokes.py), the run prints its change as
    periodicity_error and says that it is above the tolerance (here the real march's result is handed
    on with its change set to 3e-4)."""
    import dataclasses

    import pumpjack_cli.core.rods.predict as core_predict

    real = core_predict.converge

    def taken_above(*args):
        loads, positions, volumes, how = real(*args)
        return loads, positions, volumes, dataclasses.replace(how, changes=(*how.changes[:-1], 3e-4))

    monkeypatch.setattr(core_predict, "converge", taken_above)
    code, out, err = run_cli("predict", "sk8-3.5-4000", "--damping", "0.1", "--what", "summary", "-f", "json")
    assert code == 0, err
    assert json.loads(out)["summary"]["periodicity_error"] == 3e-4
    assert "the pump's state repeats to 0.0003 of the fluid load" in err and "not to the tolerance 1e-08" in err


def test_the_machine_and_rods_alternating_together_are_predicted_over_both_revolutions(run_cli):
    """SK8-3,5-4000 coupled with its motor at 70 % fillage repeats every second revolution (at uniform
    speed every stroke): the cards are the revolution of the higher load, and the rods' energy
    balance over both revolutions (1e-4, a pounding pump's) and the machine's over the one shown
    (motor work = polished-rod work + the machine's kinetic energy change, 3e-6: the rods' response
    is taken at the revolutions' mean step, which differ by 2e-5) close."""
    code, out, err = run_cli("predict", "sk8-3.5-4000", "--crank-motion", "dynamic", "--fillage", "70 %",
                             "--what", "summary", "-f", "json")
    assert code == 0, err
    summary = json.loads(out)["summary"]
    assert summary["repeat_strokes"] == 2 and "a cycle of 2 unlike strokes" in err
    assert abs(summary["rod_energy_residual"]) < 1e-3 and abs(summary["machine_energy_residual"]) < 1e-4
    assert summary["periodicity_error"] <= 1e-8
