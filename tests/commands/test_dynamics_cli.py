"""`pumpjack dynamics` as a user runs it: output formats, card input, errors, help."""

from __future__ import annotations

import csv
import io
import json
import math

import pytest

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.dynamics.periodic import steady_state
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.readers.cards import read_card

from helpers import FOOT, HORSEPOWER, SK8


@pytest.fixture
def unit_file(tmp_path, sk8_toml):
    """Write a copy of the SK8 unit with one line replaced; returns its path."""
    def write(old: str, new: str):
        text = sk8_toml.read_text(encoding="utf-8")
        assert text.count(old) == 1, old
        path = tmp_path / "unit.toml"
        path.write_text(text.replace(old, new), encoding="utf-8")
        return path

    return write


def test_json_equals_the_library(run_cli):
    code, out, err = run_cli("dynamics", SK8, "--steps", "24", "-f", "json")
    assert (code, err) == (0, "")
    data = json.loads(out)
    r = steady_state(load_unit(SK8).machine(), crank_grid(24))
    series, summary = data["series"], data["summary"]
    assert series["crank_speed_rad_s"] == r.crank_speed.tolist()
    assert series["crank_acceleration_rad_s2"] == r.crank_acceleration.tolist()
    assert series["velocity_m_s"] == r.rod.velocity.tolist()
    assert series["velocity_uniform_m_s"] == r.rod_uniform.velocity.tolist()
    assert series["motor_power_w"] == r.power.tolist()
    assert series["inertia_torque_n_m"] == r.inertia_torque.tolist()
    assert summary["mean_crank_speed_rad_s"] == r.summary.mean_speed
    assert summary["energy_per_cycle_j"] == r.summary.energy_per_cycle
    assert summary["rated_crank_speed_rad_s"] == pytest.approx(math.pi * 1460 / (30 * 37.18 * 3.6), rel=1e-12)
    assert summary["periodicity_error"] <= 1e-9
    assert summary["strokes_per_minute_spm"] == pytest.approx(60 / r.summary.period, rel=1e-12)
    assert summary["speed_fluctuation_percent"] == pytest.approx(
        100 * (r.summary.max_speed.value - r.summary.min_speed.value) / r.summary.mean_speed, rel=1e-12)


def test_csv_in_field_units(run_cli):
    code, out, _ = run_cli("dynamics", SK8, "--steps", "12", "--units", "field")
    assert code == 0
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 12
    r = steady_state(load_unit(SK8).machine(), crank_grid(12))
    assert float(rows[3]["motor_power_hp"]) == pytest.approx(r.power[3] / HORSEPOWER, rel=1e-12)
    assert float(rows[3]["velocity_ft_s"]) == pytest.approx(r.rod.velocity[3] / FOOT, rel=1e-12)
    assert float(rows[3]["crank_angle_deg"]) == 90.0


def test_table_shows_the_summary(run_cli):
    code, out, _ = run_cli("dynamics", SK8, "--steps", "8", "-f", "table")
    assert code == 0
    for name in ("mean_crank_speed", "speed_fluctuation", "energy_per_cycle", "shooting_iterations"):
        assert name in out


def test_card_drives_the_machine(run_cli, sk8_drivable_card):
    code, out, err = run_cli("dynamics", SK8, "--card", sk8_drivable_card, "--steps", "36", "--rtol", "1e-8", "-f",
                             "json")
    assert (code, err) == (0, "")
    data = json.loads(out)
    assert "card sk8-drivable-card.csv" in data["title"]
    config = load_unit(SK8)
    card = place(read_card(sk8_drivable_card), config.geometry.mechanism()).card
    r = steady_state(config.machine(card), crank_grid(36), rtol=1e-8)
    assert data["series"]["crank_speed_rad_s"] == r.crank_speed.tolist()
    summary = data["summary"]
    # Energy closure to the integrator's accuracy: DOP853 holds each step's local error of the
    # energy state within rtol of its scale (12 right-hand-side evaluations a step), so the
    # cycle's energy is off by at most steps x rtol of the cycle work (steps of the last of the
    # shots, taken as their mean); the periodicity residual (|omega_end - omega_0| <= rtol
    # omega_0) adds 2 rtol of the kinetic energy, far less here.
    convergence = r.summary.convergence
    steps = convergence.evaluations / (12 * len(convergence.start_speeds))
    bound = steps * 1e-8
    assert abs(summary["energy_per_cycle_j"] / summary["rod_work_per_cycle_j"] - 1.0) <= bound
    assert bound < 1e-4  # the bound itself is tight enough to mean something
    assert "fluid_load_n" not in summary  # the well model's forces only without a card


def test_the_sample_card_is_too_much_for_the_seed_motor(run_cli, sk8_card):
    """With elastic rods the seed well's card needs more than the pull-out torque of the SK8's
    motor at the counterbalance of [SK8Rotation2013]: refused with the numbers, not solved."""
    code, out, err = run_cli("dynamics", SK8, "--card", sk8_card, "--steps", "36", "-f", "json")
    assert code == 2 and out == ""
    assert "the motor is too weak" in err and "pull-out torque" in err


def test_plot(run_cli, tmp_path):
    plot = tmp_path / "dyn.png"
    code, _, err = run_cli("dynamics", SK8, "--steps", "36", "-o", tmp_path / "dyn.csv", "--plot", plot)
    assert (code, err) == (0, "")
    assert plot.stat().st_size > 10_000


@pytest.mark.parametrize(
    "old, new, message",
    [
        ('plunger_clearance = "0.1 mm"', "", "well.plunger_clearance needed by the well model"),
        ('rated_power = "30 kW"', 'rated_power = "5 kW"', "motor is too weak"),
        ('rotor_inertia = "0.232 kg*m2"', 'rotor_inertia = "0 kg*m2"', "rotor_inertia"),
        ('gearbox_sheave_inertia = "40.154 kg*m2"', 'gearbox_sheave_inertia = "-1 kg*m2"', "gearbox_sheave_inertia"),
        ('pump_submergence = "100 m"', 'pump_submergence = "1600 m"', "submergence"),
    ],
)
def test_bad_units_exit_2_with_one_line(run_cli, unit_file, old, new, message):
    code, out, err = run_cli("dynamics", unit_file(old, new), "--steps", "8")
    assert code == 2 and out == ""
    assert err.startswith("pumpjack: error: ") and err.count("\n") == 1
    assert message in err


def test_card_that_does_not_fit_exits_2(run_cli, tmp_path):
    # An angle card with the downstroke's load on the upstroke: it would drive the motor, the rods doing
    # work on the unit; the card is refused when it is placed, before the machine is solved.
    card = tmp_path / "backwards.csv"
    rows = ["crank_angle_deg,load_n"] + [f"{a},{37000 if a < 178 else 51000}" for a in range(0, 360, 10)]
    card.write_text("\n".join(rows) + "\n", encoding="utf-8")
    code, _, err = run_cli("dynamics", SK8, "--card", card)
    assert code == 2 and f"{card}: on these crank angles the rods do" in err and err.count("\n") == 1


def test_rtol_out_of_range_is_an_option_error(run_cli):
    code, _, err = run_cli("dynamics", SK8, "--rtol", "0.1")
    assert code == 2 and "--rtol" in err


def test_help_and_the_real_console_script(run_script):
    result = run_script("dynamics", "--help")
    assert result.returncode == 0 and "--card" in result.stdout and "--rtol" in result.stdout
    result = run_script("dynamics", SK8, "--steps", "4")
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.splitlines()[0].startswith("crank_angle_deg,time_s,crank_speed_rad_s")
