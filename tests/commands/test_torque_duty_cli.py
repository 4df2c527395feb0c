"""`pumpjack torque` reports what the office asks: PPRL and MPRL, the stroke peaks, CLF, equivalent
torque, motor power, NEMA size and energy per day at the present and at the recommended
counterbalance, the cost of that energy, and a word when the geometry's stroke exceeds the
rating.

Expected values are computed here from what the command itself prints per crank angle (the
series of the net torque, at uniform speed so that every sample weighs the same) and from the
card file, read with the standard library, and the definitions: CLF = T_rms / T_mean
([DurhamLockard1988]); motor power = T_rms omega / eta; energy a day = the integral of
max(T, 0) over the crank angle per stroke x strokes a day; the standard NEMA ratings of
[NEMAMG1] typed from the standard. The command's summary is computed on 3600 crank angles,
the series here on 720, hence the tolerances.
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from helpers import HORSEPOWER, REPO_ROOT, sample_card

UNIT = "c-80d-133-48"
CARD = sample_card(UNIT)
#: [NEMAMG1] 10.32.4, hp.
NEMA_HP = (1, 1.5, 2, 3, 5, 7.5, 10, 15, 20, 25, 30, 40, 50, 60, 75, 100, 125, 150, 200, 250, 300, 350, 400, 450, 500)
ARGS = ("--crank-motion", "uniform", "--steps", "720", "--electricity-price", "0.12", "--drive-efficiency", "0.9",
        "--motor-efficiency", "0.88")


@pytest.fixture(scope="module")
def document(run_card_json):
    return run_card_json("torque", UNIT, *ARGS)


@pytest.fixture(scope="module")
def kinematics(run_json):
    return run_json("kinematics", UNIT, "--spm", "8")["summary"]


def test_pprl_and_mprl_are_the_cards_extremes(document):
    with CARD.open(encoding="utf-8") as stream:
        rows = [row for row in csv.reader(line for line in stream if not line.startswith("#"))]
    header, body = rows[0], rows[1:]
    loads = [float(row[next(i for i, name in enumerate(header) if name.startswith("load"))]) for row in body]
    unit = 4.4482216152605 if "lbf" in next(name for name in header if name.startswith("load")) else 1.0
    s = document["summary"]
    assert s["max_rod_load_n"] == pytest.approx(max(loads) * unit, rel=1e-12)
    assert s["min_rod_load_n"] == pytest.approx(min(loads) * unit, rel=1e-12)


def _stroke_peaks(document, kinematics, name):
    theta = np.radians(document["series"]["crank_angle_deg"])
    torque = np.array(document["series"][name])
    bottom = math.radians(kinematics["crank_angle_bottom_deg"])
    travel = math.radians(kinematics["upstroke_crank_travel_deg"])
    up = ((theta - bottom) % (2 * math.pi)) < travel
    return torque[up].max(), torque[~up].max()


def test_stroke_peaks_at_present_and_recommended_counterbalance(document, kinematics):
    s = document["summary"]
    up, down = _stroke_peaks(document, kinematics, "net_torque_n_m")
    span = s["peak_net_torque_n_m"]
    assert s["upstroke_peak_torque_n_m"] == pytest.approx(up, abs=2e-3 * span)
    assert s["downstroke_peak_torque_n_m"] == pytest.approx(down, abs=2e-3 * span)
    up, down = _stroke_peaks(document, kinematics, "recommended_net_torque_n_m")
    assert s["recommended_upstroke_peak_torque_n_m"] == pytest.approx(up, abs=2e-3 * span)
    assert s["recommended_downstroke_peak_torque_n_m"] == pytest.approx(down, abs=2e-3 * span)
    # equal-peaks: the recommendation makes them equal
    assert s["recommended_upstroke_peak_torque_n_m"] == pytest.approx(s["recommended_downstroke_peak_torque_n_m"],
                                                                      rel=1e-6)


@pytest.mark.parametrize("prefix, column", [("", "net_torque_n_m"), ("recommended_", "recommended_net_torque_n_m")])
def test_duty_at_both_counterbalances(document, prefix, column):
    s = document["summary"]
    torque = np.array(document["series"][column])
    rms, mean = math.sqrt(np.mean(torque**2)), np.mean(torque)
    omega = s["strokes_per_minute_spm"] * 2 * math.pi / 60
    assert s[prefix + "rms_net_torque_n_m"] == pytest.approx(rms, rel=2e-3)
    assert s[prefix + "cyclic_load_factor"] == pytest.approx(rms / mean, rel=2e-3)
    power = rms * omega / 0.9
    assert s[prefix + "rms_motor_power_w"] == pytest.approx(power, rel=2e-3)
    size = s[prefix + "nema_motor_size_w"] / HORSEPOWER
    assert size in NEMA_HP and size == min(hp for hp in NEMA_HP if hp * HORSEPOWER >= s[prefix + "rms_motor_power_w"])
    strokes_a_day = s["strokes_per_minute_spm"] * 1440
    energy = np.sum(np.maximum(torque, 0.0)) * (2 * math.pi / torque.size) * strokes_a_day / (0.9 * 0.88) / 3.6e6
    assert s[prefix + "motor_energy_kwh_d"] == pytest.approx(energy, rel=2e-3)
    assert s[prefix + "energy_cost_per_day"] == pytest.approx(0.12 * s[prefix + "motor_energy_kwh_d"], rel=1e-12)


def test_field_units_show_horsepower_and_a_note_on_the_stroke(run_cli):
    """C-80D-133-48's letters ([Guo2007] Table 12.1, R = 24 in) give a stroke longer than its 48 in rating:
    the stroke loading above 100 % comes with a warning naming both strokes."""
    code, out, err = run_cli("torque", UNIT, "--card", CARD, "--units", "field", "-f", "json", "--what", "summary")
    assert code == 0, err
    assert "stroke loading" in err and "48 in" in err and "longer than the rated maximum" in err
    import json

    s = json.loads(out)["summary"]
    assert s["nema_motor_size_hp"] in NEMA_HP and s["stroke_loading_percent"] > 100
    assert "energy_cost_per_day" not in s   # no price, no cost


def test_no_stroke_note_within_the_rating(run_cli):
    code, _, err = run_cli("torque", "sk8-3.5-4000", "--card", sample_card("sk8-3.5-4000"), "-f", "json",
                           "--what", "summary")
    assert code == 0 and "stroke loading" not in err, err


@pytest.mark.parametrize("option, value", [("--electricity-price", "-1"), ("--electricity-price", "nan"),
                                           ("--motor-efficiency", "0"), ("--motor-efficiency", "1.5")])
def test_bad_energy_options_are_refused_in_one_line(run_cli, option, value):
    code, out, err = run_cli("torque", UNIT, "--card", CARD, option, value)
    assert (code, out) == (2, "") and err.count("\n") == 1 and option in err, err


def test_the_sample_units_energy_docs_name_the_options():
    text = (REPO_ROOT / "docs" / "torque.md").read_text(encoding="utf-8")
    assert "--electricity-price" in text and "[NEMAMG1]" in text
