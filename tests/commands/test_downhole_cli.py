"""`pumpjack downhole` as a user runs it: the surface card of a bundled unit carried down its rods.

Expected values come from independent routes: the wave equation called directly on the
command's own surface columns with a rod string built here by hand from the unit file
and the RP 11L rod table ([API11L] Table 4.1), identities of the rod loads (the top of
the string is the polished rod, the bottom the pump, a joint is one load), the energy
balance of the undamped string ([Gibbs1963]), the agreement of the two methods
([Gibbs1963], [EverittJennings1992]) and hand arithmetic on the printed numbers (the
modified Goodman diagram of [API11BR], the pump's displacement).
"""

from __future__ import annotations

import csv
import functools
import math

import numpy as np
import pytest

from pumpjack_cli.core.constants import STANDARD_GRAVITY, STEEL_DENSITY
from pumpjack_cli.core.rods.downhole import pump_card
from pumpjack_cli.core.rods.string import RodString

from helpers import (BARREL, CARD_UNITS, INCH, LB_PER_FT, POUND_FORCE, PSI, RP11L_TABLE_4_1, SK8, SK8_FLUID_DENSITY,
                     SK8_PUMP_DEPTH, sample_card, series)

#: The 1, 7/8 and 3/4 in rods (the 25, 22 and 19 mm rods of SK8) of RP 11L Table 4.1 ([API11L]).
SK8_ROD_SIZES = (1.0, 0.875, 0.75)


def sk8_rods_by_hand() -> RodString:
    """SK8-3,5-4000's string from its unit file: 1530 m, 25/22/19 mm rods over 23/26/51 %
    from the top ([SK8Rotation2013]), with RP 11L's weights and elastic constants."""
    lengths = SK8_PUMP_DEPTH * np.array([0.23, 0.26, 0.51])
    weight, elastic_constant = np.array([RP11L_TABLE_4_1[size] for size in SK8_ROD_SIZES]).T
    mass = weight * LB_PER_FT
    axial_stiffness = 12.0 / (elastic_constant * 1e-6) * POUND_FORCE  # E A [N]
    area = np.pi * (np.array(SK8_ROD_SIZES) * INCH) ** 2 / 4.0
    return RodString(lengths, area, axial_stiffness / area, mass, material_density=np.full(3, STEEL_DENSITY))


@pytest.fixture(scope="module")
def downhole(run_card_json):
    """`pumpjack downhole UNIT --card CARD ...` run once per argument list."""
    return functools.partial(run_card_json, "downhole")


@pytest.fixture(scope="module")
def sk8(downhole):
    return downhole(SK8, "--damping", "0.1")


def test_pump_card_is_the_wave_equation_of_the_unit_files_rods(sk8):
    """The command's pump card equals the Gibbs solution computed here from its own surface
    columns with the SK8 string built by hand: the wiring (rods, datum, fluid, period) is right."""
    time = series(sk8, "time_s")
    period = 60.0 / sk8["summary"]["strokes_per_minute_spm"]
    assert time[1] * time.size == pytest.approx(period, rel=1e-12)
    by_hand = pump_card(sk8_rods_by_hand(), period, series(sk8, "position_m"), series(sk8, "rod_load_n"),
                        fluid_density=SK8_FLUID_DENSITY, damping_factor=0.1, method="gibbs")
    load_range = np.ptp(series(sk8, "rod_load_n"))
    assert np.max(np.abs(by_hand.pump_load - series(sk8, "pump_load_n"))) < 1e-6 * load_range
    assert np.max(np.abs(by_hand.pump_position - series(sk8, "pump_position_m"))) < 1e-9


def test_buoyant_rod_weight_of_the_seed_taper_by_hand(sk8):
    """W_rf = g sum m_i L_i (1 - rho_f / rho_s), RP 11L weights with couplings, 820 kg/m^3 oil."""
    mass = sum(RP11L_TABLE_4_1[size][0] * LB_PER_FT * SK8_PUMP_DEPTH * share
               for size, share in zip(SK8_ROD_SIZES, (0.23, 0.26, 0.51)))
    expected = STANDARD_GRAVITY * mass * (1.0 - SK8_FLUID_DENSITY / 7850.0)
    assert sk8["summary"]["buoyant_rod_weight_n"] == pytest.approx(expected, rel=1e-12)


def test_rp11l_counterbalance_effect_of_the_measured_loads(sk8):
    """API RP 11L's design CBE = 1.06 (W_rf + F_o/2) with the card's W_rf and measured F_o;
    with this well's F_o above 0.128 W_rf it lies between the static downstroke and upstroke
    loads (W_rf and W_rf + F_o)."""
    s = sk8["summary"]
    assert s["rp11l_counterbalance_effect_n"] == pytest.approx(
        1.06 * (s["buoyant_rod_weight_n"] + 0.5 * s["fluid_load_n"]), rel=1e-14)
    assert s["buoyant_rod_weight_n"] < s["rp11l_counterbalance_effect_n"] < s["buoyant_rod_weight_n"] + s["fluid_load_n"]


def test_taper_loads_are_the_polished_rod_the_joints_and_the_pump(sk8):
    """Top of taper 1 is the polished rod, the bottom of taper 3 the pump (datum: zero static
    tension there), and a joint carries one load on both sides. The Gibbs solution carries
    the harmonics below the Nyquist frequency of the 360 samples (the Nyquist one has no
    phase to propagate), so the polished-rod load it holds is the card less that component,
    c (-1)^k with c = mean((-1)^k P_k)."""
    s = sk8["summary"]
    area = np.pi * (np.array(SK8_ROD_SIZES) * INCH) ** 2 / 4.0
    card_load = series(sk8, "rod_load_n")
    alternating = (-1.0) ** np.arange(card_load.size)
    load = card_load - np.mean(alternating * card_load) * alternating
    assert s["taper_1_top_max_stress_mpa"] * 1e6 * area[0] == pytest.approx(load.max(), rel=1e-9)
    assert s["taper_1_top_min_stress_mpa"] * 1e6 * area[0] == pytest.approx(load.min(), rel=1e-9)
    assert s["taper_3_bottom_max_stress_mpa"] * 1e6 * area[2] == pytest.approx(s["max_pump_load_n"], rel=1e-9)
    assert s["taper_3_bottom_min_stress_mpa"] * 1e6 * area[2] == pytest.approx(s["min_pump_load_n"], rel=1e-9)
    for upper, lower in ((1, 2), (2, 3)):
        for extreme in ("max", "min"):
            above = s[f"taper_{upper}_bottom_{extreme}_stress_mpa"] * area[upper - 1]
            below = s[f"taper_{lower}_top_{extreme}_stress_mpa"] * area[lower - 1]
            assert above == pytest.approx(below, rel=1e-9)


def test_goodman_loading_and_displacement_by_hand(sk8):
    """Modified Goodman ([API11BR]): S_A = T/4 + 0.5625 S_min, loading = (S_max - S_min) /
    (S_A - S_min), grade D T = 115 000 psi, the larger of each taper's two ends; Q = A_p S_n N."""
    s = sk8["summary"]
    strength = 115_000 * PSI / 1e6
    for i in (1, 2, 3):
        ends = []
        for end in ("top", "bottom"):
            high, low = s[f"taper_{i}_{end}_max_stress_mpa"], s[f"taper_{i}_{end}_min_stress_mpa"]
            ends.append((high - low) / (strength / 4.0 + 0.5625 * low - low))
        assert s[f"taper_{i}_goodman_loading_percent"] == pytest.approx(100.0 * max(ends), rel=1e-9)
    area = math.pi * 0.038**2 / 4.0
    per_day = area * s["net_pump_stroke_m"] * s["strokes_per_minute_spm"] * 1440.0
    assert s["pump_displacement_m3_d"] == pytest.approx(per_day, rel=1e-9)
    assert s["pump_fillage_percent"] == pytest.approx(100.0 * s["net_pump_stroke_m"] / s["gross_pump_stroke_m"],
                                                      rel=1e-9)


@pytest.mark.parametrize("unit", CARD_UNITS)
def test_gibbs_and_everitt_jennings_agree_on_the_bundled_wells(downhole, unit):
    """Issue 12: gross pump stroke within 1 mm, pump loads within 2 % of the card's load range."""
    gibbs = downhole(unit, "--damping", "0.1")
    ej = downhole(unit, "--damping", "0.1", "--method", "everitt-jennings")
    load_range = np.ptp(series(gibbs, "rod_load_n"))
    assert abs(gibbs["summary"]["gross_pump_stroke_m"] - ej["summary"]["gross_pump_stroke_m"]) < 1e-3
    assert np.max(np.abs(series(gibbs, "pump_load_n") - series(ej, "pump_load_n"))) < 0.02 * load_range


def test_the_methods_converge_as_the_time_step_shrinks(downhole):
    def gap(samples):
        gibbs = downhole("c-114d-133-54", "--damping", "0.1", "--samples", samples)
        ej = downhole("c-114d-133-54", "--damping", "0.1", "--samples", samples, "--method", "everitt-jennings")
        return np.max(np.abs(series(gibbs, "pump_load_n") - series(ej, "pump_load_n")))

    coarse, fine = gap("100"), gap("400")
    assert fine < 0.5 * coarse


@pytest.mark.parametrize("method, tolerance", [("gibbs", 1e-9), ("everitt-jennings", 1e-4)])
def test_undamped_rods_pass_the_surface_work_to_the_pump(downhole, method, tolerance):
    doc = downhole("7sk12-2.5-5600", "--damping", "0", "--method", method)
    s = doc["summary"]
    assert s["pump_card_work_j"] == pytest.approx(s["surface_card_work_j"], rel=tolerance)


def test_energy_balance_damping_makes_the_pump_work_the_hydraulic_work(downhole):
    """Without --damping the rods dissipate what the surface card does beyond F_o S_n, with
    F_o = (p_d - p_i) A_p from the well's depth, fluid and fluid level ([Gibbs1963])."""
    doc = downhole(SK8)
    s = doc["summary"]
    area = math.pi * 0.038**2 / 4.0
    fluid_load = SK8_FLUID_DENSITY * STANDARD_GRAVITY * (SK8_PUMP_DEPTH - 100.0) * area
    assert s["pump_card_work_j"] == pytest.approx(fluid_load * s["net_pump_stroke_m"], rel=1e-4)
    assert 0.0 < s["damping_factor"] < 1.0


def test_position_only_card_goes_through_the_exact_kinematics(downhole, tmp_path):
    """Without time stamps the card's crank angles come from its positions and the speed from
    --spm: the same pump card as the time-stamped card at the same speed."""
    rows = list(csv.reader(line for line in sample_card("c-114d-133-54").read_text().splitlines()
                           if not line.startswith("#")))
    header = rows[0]
    keep = [i for i, name in enumerate(header) if not name.startswith("time")]
    path = tmp_path / "positions.csv"
    path.write_text("\n".join(",".join(row[i] for i in keep) for row in rows) + "\n")
    stamped = downhole("c-114d-133-54", "--damping", "0.1")
    plain = downhole("c-114d-133-54", "--damping", "0.1", "--spm",
                           repr(stamped["summary"]["strokes_per_minute_spm"]), card_file=path)
    assert abs(plain["summary"]["gross_pump_stroke_m"] - stamped["summary"]["gross_pump_stroke_m"]) < 1e-3
    load_range = np.ptp(series(stamped, "rod_load_n"))
    assert np.max(np.abs(series(plain, "pump_load_n") - series(stamped, "pump_load_n"))) < 0.01 * load_range


def test_field_units_are_the_si_numbers_converted(downhole):
    si = downhole("c-80d-133-48", "--damping", "0.1")
    field = downhole("c-80d-133-48", "--damping", "0.1", "--units", "field")
    assert field["summary"]["fluid_load_lbf"] * POUND_FORCE == pytest.approx(si["summary"]["fluid_load_n"], rel=1e-9)
    assert field["summary"]["gross_pump_stroke_in"] * INCH == pytest.approx(si["summary"]["gross_pump_stroke_m"],
                                                                            rel=1e-9)
    assert field["summary"]["pump_displacement_bbl_d"] * BARREL == pytest.approx(
        si["summary"]["pump_displacement_m3_d"], rel=1e-9)


def test_the_fluid_level_off_the_card_is_the_wells_in_feet(downhole):
    """C-228D-213-86's sample card was made (samples/make_cards.py) on a 5000 ft well whose
    pump is 500 ft below the fluid level: read back off its pump card in field units, the
    submergence and the fluid level's depth are depths in a well, in feet (not inches as a
    length on the unit), and the well's within 2 ft: an error of 1.5 lbf (5e-4) in the card's
    fluid load over the 1.5 in plunger's 0.0123 ft² of 59.3 lb/ft³ liquid."""
    summary = downhole("c-228d-213-86", "--units", "field")["summary"]
    assert summary["pump_submergence_ft"] == pytest.approx(500.0, abs=2.0)
    assert summary["fluid_level_depth_ft"] == pytest.approx(4500.0, abs=2.0)
    assert summary["pump_submergence_ft"] + summary["fluid_level_depth_ft"] == pytest.approx(5000.0, rel=1e-12)


def test_plot_shows_both_cards_and_the_goodman_diagram(run_cli, tmp_path):
    target = tmp_path / "cards.png"
    code, out, err = run_cli("downhole", "c-80d-133-48", "--card", sample_card("c-80d-133-48"), "--damping", "0.1",
                             "-f", "csv", "--plot", target)
    assert code == 0, err
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert out.startswith("time_s,crank_angle_deg,position_m,rod_load_n,pump_position_m,pump_load_n")


def test_card_in_the_wrong_load_unit_is_refused_by_the_rods(run_cli, tmp_path):
    """A card in lbf read as N lies far below the rods' buoyant weight: one line, exit 2."""
    text = sample_card("c-80d-133-48").read_text()
    path = tmp_path / "card.csv"
    path.write_text(text.replace("load_lbf", "load_N"))
    code, out, err = run_cli("downhole", "c-80d-133-48", "--card", path, "-f", "csv")
    assert code == 2 and out == ""
    assert err.startswith("pumpjack: error: ") and err.count("\n") == 1
    assert "lbf written as N?" in err


def test_unit_without_a_well_is_refused(run_cli):
    code, out, err = run_cli("downhole", "unb-600a", "--card", sample_card("c-80d-133-48"), "-f", "csv")
    assert code == 2 and out == "" and err.count("\n") == 1


def test_blind_diagnosis_of_the_sample_card_gives_back_the_well(downhole):
    """The SK8 sample card was made by the predictive model (modal solver, pump valves) with
    damping 0.05, a full pump and 100 m of fluid above the pump (samples/make_cards.py).
    Diagnosed with only the rods and the fluid level: the energy balance finds nu = 0.05
    (1 %), the pump is full, F_o = rho g (L - h) A_p (0.5 %) and the intake pressure is
    rho g h (1 %)."""
    s = downhole(SK8)["summary"]
    area = math.pi * 0.038**2 / 4.0
    assert s["damping_factor"] == pytest.approx(0.05, rel=0.01)
    assert s["pump_fillage_percent"] > 99.5
    assert s["fluid_load_n"] == pytest.approx(SK8_FLUID_DENSITY * STANDARD_GRAVITY * 1430.0 * area, rel=0.005)
    assert s["pump_intake_pressure_pa"] == pytest.approx(SK8_FLUID_DENSITY * STANDARD_GRAVITY * 100.0, rel=0.01)


@pytest.mark.parametrize("damping", ["0.5", "2"])
def test_a_damping_that_leaves_the_pump_card_negative_work_is_refused(run_cli, damping):
    """The SK8 sample card's surface work is about 48 kJ per cycle; a damping factor of 0.5 or 2 takes
    more than that from the rods, and the pump card would do negative work on the fluid (with a
    negative fluid load). A pump does no negative work: refused by name, no numbers."""
    code, out, err = run_cli("downhole", SK8, "--card", sample_card(SK8), "--damping", damping, "-f", "json")
    assert (code, out) == (2, "")
    assert "its pump card does -" in err and f"the damping factor {float(damping):g}" in err and err.count("\n") == 1


def test_a_card_refused_for_its_pump_work_leaves_the_others_of_a_batch_alone(tmp_path):
    """downholes of two position cards at the sample's speed, the sample card and a card of no loop
    (the load constant, the rods doing no work): the second is refused for its pump card's negative
    work, the first is as alone."""
    from pumpjack_cli.analysis.card_runs import CardSource
    from pumpjack_cli.analysis.downhole import downhole, downholes
    from pumpjack_cli.config import load_unit
    from pumpjack_cli.errors import PumpjackError
    from pumpjack_cli.results import Result

    rows = list(csv.reader(open(sample_card(SK8), encoding="utf-8")))
    header = next(i for i, row in enumerate(rows) if row and row[0] == "time_s")
    good, flat = tmp_path / "good.csv", tmp_path / "flat.csv"
    good.write_text("position_m,load_kN\n" + "".join(f"{s},{w}\n" for _, s, w in rows[header + 1:]), encoding="utf-8")
    flat.write_text("position_m,load_kN\n" + "".join(f"{s},40.0\n" for _, s, _ in rows[header + 1:]), encoding="utf-8")
    unit = load_unit(SK8)
    (first, _), (second, _) = downholes(unit, [CardSource(good), CardSource(flat)], 10.908, "uniform", None,
                                        0.05)
    assert isinstance(second, PumpjackError) and "its pump card does -" in str(second)
    assert isinstance(first, Result)
    alone = downhole(unit, CardSource(good), 10.908, "uniform", None, 0.05)
    assert [s.value for s in first.summary] == [s.value for s in alone.summary]
