"""`pumpjack reactions` as a user runs it."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import card_load
from pumpjack_cli.analysis.reactions import SUMMARY_STEPS
from pumpjack_cli.core.sampling import crank_grid, extremes, peak
from pumpjack_cli.core.beam.kinetostatics import rational_mechanism
from pumpjack_cli.core.constants import STANDARD_GRAVITY
from pumpjack_cli.readers.cards import read_card

from helpers import INCH, POUND_FORCE, SK8


def library(card, steps=360):
    """The rational mechanism on the card at the card's own speed (its time stamps take
    precedence over the drive's rated speed)."""
    config = load_unit(SK8)
    spatial = config.geometry.spatial()
    theta = crank_grid(steps)
    reading = place(read_card(card), spatial.planar)
    load = card_load(reading.card, theta)
    _, r = rational_mechanism(spatial, config.masses.model(), theta, reading.speed, 0.0, load)
    return theta, load, r


def test_json_equals_the_library(run_cli, sk8_card):
    code, out, err = run_cli("reactions", SK8, "--card", sk8_card, "-f", "json")
    assert (code, err) == (0, "")
    data = json.loads(out)
    theta, load, r = library(sk8_card)
    series = data["series"]
    assert series["rod_load_n"] == load.tolist()
    for name in ("r12", "r13", "r24", "r34", "r45", "r05", "r01"):
        for i, axis in enumerate("xyz"):
            assert series[f"{name}_{axis}_n"] == getattr(r, name)[:, i].tolist()
    assert series["net_torque_n_m"] == r.net_torque.tolist()
    summary = data["summary"]
    # the summary's extremes come from a fixed 3600-point grid, refined between points
    dense_theta, _, dense = library(sk8_card, SUMMARY_STEPS)
    assert summary["max_net_torque_n_m"] == extremes(dense_theta, dense.net_torque)[0].value
    assert summary["peak_r12_n"] == peak(dense_theta, dense.r12).value
    assert summary["peak_r12_n"] >= np.linalg.norm(r.r12, axis=-1).max()
    assert summary["equilibrium_residual"] < 1e-9


def test_csv_and_field_units(run_cli, sk8_card):
    code, out, _ = run_cli("reactions", SK8, "--card", sk8_card, "--steps", "24", "--units", "field")
    assert code == 0
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 24
    theta, load, r = library(sk8_card, 24)
    assert float(rows[5]["r45_y_lbf"]) == pytest.approx(r.r45[5, 1] / POUND_FORCE, rel=1e-12)
    assert float(rows[5]["net_torque_lbf_in"]) == pytest.approx(r.net_torque[5] / (POUND_FORCE * INCH), rel=1e-12)


def test_counterweight_options_change_only_the_counterweight_torque(run_cli, sk8_card):
    """Uniform rotation: point counterweights on a circle exert no inertia torque; their
    weight m g r sin(theta) (in line with the pin) helps the gearbox. Taking two of the
    eight 650 kg blocks off raises M_z by 2 x 650 g 0.83 sin(theta)."""
    def torque(*extra):
        code, out, err = run_cli("reactions", SK8, "--card", sk8_card, "--steps", "36", "-f", "json", *extra)
        assert (code, err) == (0, "")
        return np.array(json.loads(out)["series"]["net_torque_n_m"])

    theta = crank_grid(36)
    lighter = torque("--counterweight-count", "6") - torque()
    assert np.allclose(lighter, 2 * 650 * STANDARD_GRAVITY * 0.83 * np.sin(theta), rtol=0, atol=1e-6)
    farther = torque("--counterweight-radius", "93 cm") - torque()
    assert np.allclose(farther, -8 * 650 * STANDARD_GRAVITY * 0.10 * np.sin(theta), rtol=0, atol=1e-6)


def test_no_weights_no_inertia_is_the_torque_factor_method(run_cli, sk8_card):
    code, out, _ = run_cli("reactions", SK8, "--card", sk8_card, "--steps", "36", "-f", "json",
                           "--no-weights", "--no-inertia")
    assert code == 0
    data = json.loads(out)["series"]
    config = load_unit(SK8)
    from pumpjack_cli.core.beam.linkage import motion

    theta = crank_grid(36)
    tf = config.geometry.mechanism().front_arm * motion(config.geometry.mechanism(), theta).beam_rate
    expected = tf * np.array(data["rod_load_n"])
    assert np.allclose(data["net_torque_n_m"], expected, rtol=0, atol=1e-9 * np.abs(expected).max())


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (["--card", "nope.csv"], "nope.csv: cannot read"),
        (["--counterweight-radius", "3,5 m"], "--counterweight-radius"),
        (["--counterweight-radius", "9 m"], "outside"),
        (["--counterweight-count", "40"], "--counterweight-count"),
    ],
)
def test_bad_options(run_cli, sk8_card, args, fragment):
    argv = ["reactions", SK8] + (["--card", str(sk8_card)] if args[0] != "--card" else []) + args
    code, out, err = run_cli(*argv)
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and err.startswith("pumpjack: error:") and fragment in err


def test_unit_without_masses(run_cli, sk8_api_yaml, sk8_card):
    code, _, err = run_cli("reactions", sk8_api_yaml, "--card", sk8_card, "--spm", "10")
    assert code == 2 and "no [masses] section" in err


def test_broken_card_is_one_line(run_cli, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("position_m,load_n\n0.1,abc\n", encoding="utf-8")
    code, out, err = run_cli("reactions", SK8, "--card", bad)
    assert code == 2 and out == ""
    assert err.strip() == f"pumpjack: error: {bad}: line 2: load 'abc' is not a number"


def test_plot(run_cli, tmp_path, sk8_card):
    target = tmp_path / "r.png"
    code, _, _ = run_cli("reactions", SK8, "--card", sk8_card, "--plot", target, "-o", tmp_path / "r.csv")
    assert code == 0
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_dynamic_rotation_balances_the_motor(run_cli, sk8_drivable_card):
    """--crank-motion dynamic: the kinetostatics run on the speed and acceleration of the
    machine's equation of motion. The gearbox torque on the crank is then the motor
    torque through the drive less what accelerates the drive's own inertia,
    M_z = u M_motor - I_drive eps1: two independent models (spatial kinetostatics,
    reduced-inertia equation of motion) must agree through the power balance."""
    from pumpjack_cli.core.dynamics.periodic import steady_state

    code, out, err = run_cli("reactions", SK8, "--card", sk8_drivable_card, "--crank-motion", "dynamic", "--steps", "90",
                             "-f", "json")
    assert (code, err) == (0, "")
    series = json.loads(out)["series"]
    config = load_unit(SK8)
    theta = crank_grid(90)
    card = place(read_card(sk8_drivable_card), config.geometry.mechanism()).card
    machine = config.machine(card)
    state = steady_state(machine, theta)
    assert series["crank_speed_rad_s"] == state.crank_speed.tolist()
    expected = machine.drive_ratio * state.motor_torque - machine.drive_inertia * state.crank_acceleration
    torque = np.array(series["net_torque_n_m"])
    assert np.max(np.abs(torque - expected)) < 1e-9 * np.max(np.abs(expected))


def test_spm_with_dynamic_rotation_is_an_error(run_cli, sk8_card):
    code, _, err = run_cli("reactions", SK8, "--card", sk8_card, "--crank-motion", "dynamic", "--spm", "8")
    assert code == 2 and "--spm sets a uniform crank speed" in err
