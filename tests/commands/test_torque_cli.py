"""`pumpjack torque` as a user runs it: the two methods, the ratings, the balance and the loading.

Expected values come from independent routes: `pumpjack reactions` (the spatial
kinetostatics), hand arithmetic on the printed columns and the unit file's numbers,
and the definitions of the designations ([API11E], [GOST5866]).
"""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import numpy as np
import pytest

from helpers import FOOT, HORSEPOWER, KILOGRAM_FORCE, POUND_FORCE, REPO_ROOT, SK8_CARD, SK8_TOML, sample_card, series


@pytest.fixture(scope="module")
def torque(run_card_json):
    """`pumpjack torque UNIT --card CARD ...` run once per argument list."""
    return functools.partial(run_card_json, "torque")


def massless_sk8(tmp_path: Path) -> Path:
    """SK8-3,5-4000 with every link mass and moment of inertia zero (crank arms and pitmans
    at 1e-9 kg, the schema's positive floor): B = M = 0 and no inertia."""
    text = SK8_TOML.read_text(encoding="utf-8")
    text = re.sub(r'(?m)^mass = "[^"]*"', 'mass = "1e-9 kg"', text)
    text = re.sub(r'(?m)^(transverse_)?inertia = "[^"]*"', r'\1inertia = "0 kg*m2"', text)
    path = tmp_path / "massless.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_massless_exact_equals_api(torque, tmp_path):
    unit = massless_sk8(tmp_path)
    doc = torque(unit, "--crank-motion", "uniform", "--method", "exact", card_file=SK8_CARD)
    api = np.array(doc["series"]["api_net_torque_n_m"])
    exact = np.array(doc["series"]["exact_net_torque_n_m"])
    assert np.max(np.abs(exact - api)) < 1e-9 * np.max(np.abs(api))


@pytest.mark.parametrize("unit", ["sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54"])
def test_exact_method_equals_the_reactions_net_torque(torque, run_card_json, unit):
    doc = torque(unit, "--crank-motion", "uniform", "--method", "exact", "--steps", "72")
    reactions = series(run_card_json("reactions", unit, "--steps", "72"), "net_torque_n_m")
    exact = np.array(doc["series"]["net_torque_n_m"])
    assert np.max(np.abs(exact - reactions)) < 1e-9 * np.max(np.abs(reactions))


@pytest.mark.parametrize("unit,kgf_m", [("sk8-3.5-4000", 4000), ("7sk12-2.5-5600", 5600)])
@pytest.mark.parametrize("method", ["api", "exact"])
def test_gost_units_load_their_gearbox_against_the_designation(torque, unit, kgf_m, method):
    summary = torque(unit, "--method", method)["summary"]
    assert summary["gearbox_rating_n_m"] == pytest.approx(kgf_m * KILOGRAM_FORCE, rel=1e-12)
    assert summary["gearbox_loading_percent"] == pytest.approx(
        100 * summary["peak_net_torque_n_m"] / summary["gearbox_rating_n_m"], rel=1e-12)


def test_api_unit_without_masses_and_its_ratings(torque):
    """C-80D-133-48: 80 000 lbf·in, 13 300 lbf, 48 in ([API11E] designation), no [masses]."""
    doc = torque("c-80d-133-48", "--units", "field")
    s = doc["summary"]
    assert s["gearbox_rating_lbf_in"] == pytest.approx(80_000, rel=1e-12)
    assert s["structure_rating_lbf"] == pytest.approx(13_300, rel=1e-12)
    assert s["max_stroke_in"] == pytest.approx(48, rel=1e-12)
    loads = doc["series"]["rod_load_lbf"]
    # structure loading: the card's largest load over the rating (the card's own samples
    # include the largest; the 360-point column can only be smaller)
    assert s["structure_loading_percent"] >= 100 * max(loads) / 13_300 - 1e-9
    assert s["structure_loading_percent"] <= 100 * 1.01 * max(loads) / 13_300
    assert s["gearbox_loading_percent"] == pytest.approx(100 * s["peak_net_torque_lbf_in"] / 80_000, rel=1e-12)
    # polished-rod power = card work x strokes per second
    assert s["polished_rod_power_hp"] * HORSEPOWER == pytest.approx(
        s["card_work_ft_lbf"] * FOOT * POUND_FORCE * s["strokes_per_minute_spm"] / 60, rel=1e-9)


def test_permissible_loads_by_hand(torque):
    """W_max = B + (M sin(theta) + T_r)/TF and W_min = B + (M sin(theta) - T_r)/TF where TF > 0
    ([GaultSWPSC]), with B = 440 lbf and M = 130 000 lbf·in from the unit file."""
    doc = torque("c-80d-133-48", "--units", "field", "--steps", "24")
    series = doc["series"]
    b, m, rating = 440.0, 130_000.0, 80_000.0
    checked = 0
    for theta, tf, low, high in zip(series["crank_angle_deg"], series["torque_factor_in"],
                                    series["permissible_load_min_lbf"], series["permissible_load_max_lbf"]):
        if tf > 5:
            counter = m * math.sin(math.radians(theta))
            assert high == pytest.approx(b + (counter + rating) / tf, rel=1e-9)
            assert low == pytest.approx(b + (counter - rating) / tf, rel=1e-9)
            checked += 1
        elif tf < -5:
            counter = m * math.sin(math.radians(theta))
            assert high == pytest.approx(b + (counter - rating) / tf, rel=1e-9)
            assert low == pytest.approx(b + (counter + rating) / tf, rel=1e-9)
            checked += 1
    assert checked >= 15


def test_net_torque_is_the_sum_of_its_components(torque):
    series = torque("sk8-3.5-4000", "--steps", "36")["series"]
    parts = sum(np.array(series[name]) for name in ("rod_load_torque_n_m", "structural_torque_n_m",
                                                     "counterbalance_torque_n_m", "articulating_inertia_torque_n_m",
                                                     "rotary_inertia_torque_n_m"))
    assert np.allclose(parts, series["net_torque_n_m"], rtol=0, atol=1e-9 * np.max(np.abs(parts)))


@pytest.mark.parametrize("criterion", ["equal-peaks", "min-rms", "min-peak"])
def test_recommended_counterbalance_by_a_scan_of_m(torque, criterion):
    """The recommended net torque is the present one shifted by (M - M_rec) sin(theta);
    a scan of M around the recommendation finds nothing better for the criterion."""
    doc = torque("c-80d-133-48", "--balance", criterion, "--steps", "3600")
    s, series = doc["summary"], doc["series"]
    theta = np.radians(series["crank_angle_deg"])
    present = np.array(series["net_torque_n_m"])
    m0, m_rec = s["counterbalance_moment_n_m"], s["recommended_counterbalance_moment_n_m"]
    recommended = present + (m0 - m_rec) * np.sin(theta)
    assert np.allclose(recommended, series["recommended_net_torque_n_m"], rtol=0, atol=1e-6 * np.max(np.abs(present)))
    scan = m_rec + np.linspace(-0.05, 0.05, 201) * m_rec
    torques = present[None, :] + (m0 - scan[:, None]) * np.sin(theta)[None, :]
    if criterion == "min-peak":
        best = np.max(np.abs(torques), axis=1)
        assert np.max(np.abs(recommended)) <= best.min() * (1 + 1e-6)
    elif criterion == "min-rms":
        dt = 1 / np.array(series["crank_speed_rad_s"])
        rms = np.sqrt(np.sum(torques**2 * dt, axis=1) / np.sum(dt))
        assert math.sqrt(np.sum(recommended**2 * dt) / np.sum(dt)) <= rms.min() * (1 + 1e-6)
    else:
        assert s["recommended_upstroke_peak_torque_n_m"] == pytest.approx(s["recommended_downstroke_peak_torque_n_m"],
                                                                         rel=1e-6)


def test_a_mark_ii_designation_reads_the_geometry_as_a_mark_ii(run_cli, tmp_path):
    """The designation's letter names the kind: a conventional file relabelled M- is read with the
    Mark II schema (which turns counterclockwise only), and a class key that contradicts it is refused."""
    text = (REPO_ROOT / "configs" / "c-80d-133-48.toml").read_text(encoding="utf-8")
    unit = tmp_path / "mark.toml"
    unit.write_text(text.replace('designation = "C-80D-133-48"', 'designation = "M-912D-427-192"'), encoding="utf-8")
    code, out, err = run_cli("torque", unit, "--card", sample_card("c-80d-133-48"))
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "geometry.rotation: Input should be 'counterclockwise'" in err
    unit.write_text(text.replace('designation = "C-80D-133-48"', 'designation = "M-912D-427-192"')
                    .replace("[geometry]", '[geometry]\nclass = "conventional"'), encoding="utf-8")
    code, out, err = run_cli("torque", unit, "--card", sample_card("c-80d-133-48"))
    assert code == 2 and "class 'conventional' contradicts the designation 'M-912D-427-192'" in err


def test_exact_method_needs_masses(run_cli):
    code, out, err = run_cli("torque", "c-80d-133-48", "--card", sample_card("c-80d-133-48"), "--method", "exact")
    assert code == 2 and "has no [masses] section; --method exact needs the link masses" in err


def test_plot(run_cli, tmp_path):
    plot = tmp_path / "t.png"
    code, _, err = run_cli("torque", "sk8-3.5-4000", "--card", SK8_CARD, "--plot", plot, "-o",
                           tmp_path / "t.csv")
    assert (code, err) == (0, "") and plot.stat().st_size > 10_000
