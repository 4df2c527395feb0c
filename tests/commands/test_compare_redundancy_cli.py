"""`pumpjack compare-redundancy` as a user runs it: the real mechanism against the rational one
on the 7SK12-2,5-5600 sample card ([Spatial7SK12]).

Expected values come from the core's real and rational mechanisms solved here, and from
`pumpjack reactions` for the rational columns.
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.analysis.reactions import REDUNDANCY_SUMMARY_STEPS
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import card_load
from pumpjack_cli.core.beam.kinetostatics import rational_mechanism
from pumpjack_cli.core.beam.redundancy import PinTilts, real_mechanism
from pumpjack_cli.core.sampling import crank_grid, peak
from pumpjack_cli.readers.cards import read_card

from helpers import sample_card

UNIT = "7sk12-2.5-5600"
CARD = sample_card(UNIT)


def compare(run_cli, *extra):
    code, out, err = run_cli("compare-redundancy", UNIT, "--card", CARD, "--spm", "8", "--steps", "72", "-f", "json", *extra)
    assert (code, err) == (0, "")
    return json.loads(out)


def test_command_without_errors_matches_reactions(run_cli):
    """Zero deviations: every difference column is zero to 1e-9 of the load, and the
    rational columns are exactly what `pumpjack reactions` prints."""
    data = compare(run_cli)
    series = data["series"]
    scale = max(series["rod_load_n"])
    for key, values in series.items():
        if key.endswith("_difference_n") or key.endswith("_difference_n_m"):
            assert max(abs(v) for v in values) < 1e-9 * scale, key
    code, out, _ = run_cli("reactions", UNIT, "--card", CARD, "--spm", "8", "--steps", "72", "-f", "json")
    reactions = json.loads(out)["series"]
    assert series["r12_y_rational_n"] == reactions["r12_y_n"]
    assert series["net_torque_rational_n_m"] == reactions["net_torque_n_m"]


def test_command_deviation_options_reach_the_solver(run_cli):
    """The summary's peak is found on the fixed summary grid (refined between points), at
    the card's own speed (its time stamps; --spm 8 agrees with them); the difference is
    like with like: real minus rational with the same error."""
    data = compare(run_cli, "--pitman-length", "2 mm")
    config = load_unit(UNIT)
    ideal = config.geometry.spatial()
    theta = crank_grid(REDUNDANCY_SUMMARY_STEPS)
    reading = place(read_card(CARD), ideal.planar)
    load = card_load(reading.card, theta)
    actual = dataclasses.replace(ideal, pitman_length_offset=0.002)
    masses, section = config.masses.model(), config.pitman_section.model()
    _, _, real = real_mechanism(ideal, actual, PinTilts(), section, masses, theta, reading.speed, 0.0, load)
    _, rational = rational_mechanism(actual, masses, theta, reading.speed, 0.0, load)
    expected = peak(theta, real.r12[:, 1] - rational.r12[:, 1]).value
    assert data["summary"]["peak_difference_r12_y_n"] == pytest.approx(expected, rel=1e-12)
    assert data["summary"]["deviation_pitman_length_m"] == pytest.approx(0.002, rel=1e-12)
    assert data["summary"]["equilibrium_residual"] < 1e-9


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (["--pitman-length", "80 cm"], "--pitman-length: Input should be less than or equal to 0.5"),
        (["--crank-phase", "0,5 deg"], "--crank-phase: '0,5 deg' has a decimal comma"),
        (["--crank-radius", "2 kg"], "--crank-radius: '2 kg' is a mass, not a length"),
        (["--crank-radius", "0.5 m", "--pitman-length", "-0.5 m"], "cannot assemble"),
        (["--crank-radius", "-0.4 m", "--pitman-length", "0.45 m"], "would have to roll"),
    ],
)
def test_command_bad_deviations(run_cli, args, fragment):
    code, out, err = run_cli("compare-redundancy", UNIT, "--card", CARD, "--spm", "8", *args)
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and fragment in err


def test_unit_without_pitman_section(run_cli, repo_root, tmp_path):
    text = (repo_root / "configs" / "c-114d-133-54.toml").read_text(encoding="utf-8")
    unit = tmp_path / "no-section.toml"
    unit.write_text(text[: text.index("[pitman_section]")], encoding="utf-8")
    code, _, err = run_cli("compare-redundancy", unit, "--card", sample_card("c-114d-133-54"), "--spm", "10")
    assert code == 2 and "no [pitman_section]" in err


def test_kinematic_part_is_the_rational_mechanisms_own_change(run_cli):
    """The command's kinematic columns are the rational mechanism with the error minus without
    (solved here), and kinematic + redundancy = real - error-free rational at every angle."""
    code, out, err = run_cli("compare-redundancy", UNIT, "--card", CARD, "--spm", "8", "--steps", "36",
                             "--crank-phase", "0.1 deg", "-f", "json")
    assert code == 0, err
    series = json.loads(out)["series"]
    config = load_unit(UNIT)
    ideal = config.geometry.spatial()
    theta = crank_grid(36)
    reading = place(read_card(CARD), ideal.planar)
    load = card_load(reading.card, theta)
    masses = config.masses.model()
    actual = dataclasses.replace(ideal, crank_phase_offset=np.radians(0.1))
    _, with_error = rational_mechanism(actual, masses, theta, reading.speed, 0.0, load)
    _, without = rational_mechanism(ideal, masses, theta, reading.speed, 0.0, load)
    kinematic = np.array(series["net_torque_kinematic_n_m"])
    assert np.max(np.abs(kinematic - (with_error.net_torque - without.net_torque))) < 1e-9 * np.max(
        np.abs(without.net_torque))
    total = np.array(series["net_torque_real_n_m"]) - np.array(series["net_torque_ideal_n_m"])
    assert np.allclose(kinematic + np.array(series["net_torque_difference_n_m"]), total, rtol=0, atol=1e-6)
    assert np.max(np.abs(kinematic)) > 10.0 * np.max(np.abs(series["net_torque_difference_n_m"]))
