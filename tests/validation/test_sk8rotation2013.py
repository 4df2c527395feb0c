"""[SK8Rotation2013]: the SK8-3,5-4000 data and the numbers the paper prints.

Source: [SK8Rotation2013] (Rozvidka ta rozrobka naftovykh i hazovykh rodovyshch 2013, no. 4(49)).
Its passport data of SK8-3,5-4000: k1 = 3500 mm, k = 2500 mm, r = 1010 mm, l = 3000 mm,
l1 = 2195 mm, l2 = 3000 mm; crank arm 1373 kg, pitman 130 kg, counterweight 650 kg (5200 kg in
all at 0.83 m), beam 1220 kg, horsehead 490 kg, equalizer 495 kg; motor 4AR180M4U3 30 kW,
1500/1460 rpm, M_start/M_n = 2.0, M_max/M_n = 2.2, rotor 0.232 kg·m²; gearbox Ts2NSh-750B
u_r = 37.18; sheaves 250 and 900 mm; well 1530 m, plunger 38 mm, rods 19/22/25 mm
(51/26/23 %), 820 kg/m³, 3e-6 m²/s, tubing 62 mm. Printed results: the motor line of
eqs. 25-26, omega1 = pi·1460/(30·37.18·900/250) = 1.1422 1/s (N = 60·omega1/(2 pi) ≈ 10.9
1/min) and the constant part of the reduced inertia, 66 798.5 kg·m².

Checked here: the bundled unit file as parsed, the equation of motion's drive and
`pumpjack kinematics`' summary against those numbers.
"""

from __future__ import annotations

import json
import math
import re

import pytest

from pumpjack_cli.core.dynamics.drive import motor_characteristic

from helpers import RPM, SK8, SK8_CRANK_SPEED


#: The strokes per minute the paper prints (one decimal).
PRINTED_SPM = 10.9
# Tolerance for values given with a unit ("3500 mm" -> 3500 * 1e-3): the conversion
# factor 1e-3 is not exact in binary, so the result may be one ulp from the decimal.
REL_UNIT = 1e-12


# --- the unit file as parsed --------------------------------------------------------


def test_name(sk8_unit):
    assert sk8_unit.name == "SK8-3,5-4000"


def test_geometry(sk8_unit):
    g = sk8_unit.geometry
    expected = {"front_arm": 3.5, "rear_arm": 2.5, "crank_radius": 1.01, "pitman": 3.0,
                "horizontal_offset": 2.195, "vertical_offset": 3.0}
    for field, value in expected.items():
        assert getattr(g, field) == pytest.approx(value, rel=REL_UNIT), field
    assert g.rotation == "clockwise"


def test_masses(sk8_unit):
    m = sk8_unit.masses
    assert m is not None
    expected = {"crank_arm": 1373.0, "pitman": 130.0, "counterweights": 650.0,
                "beam": 1220.0, "horsehead": 490.0, "equalizer": 495.0}
    for field, value in expected.items():
        assert getattr(m, field).mass == pytest.approx(value, rel=REL_UNIT), field
    assert m.counterweights.radius == pytest.approx(0.83, rel=REL_UNIT)
    assert m.counterweights.count == 8
    # [SK8Rotation2013]: counterweights of 5200 kg in all.
    assert m.counterweights.mass * m.counterweights.count == pytest.approx(5200.0, rel=REL_UNIT)


def test_drive(sk8_unit):
    d = sk8_unit.drive
    assert d is not None
    assert d.motor.model == "4AR180M4U3"
    assert d.motor.rated_power == pytest.approx(30e3, rel=REL_UNIT)
    assert d.motor.synchronous_speed == pytest.approx(1500 * RPM, rel=REL_UNIT)
    assert d.motor.rated_speed == pytest.approx(1460 * RPM, rel=REL_UNIT)
    assert d.motor.starting_torque_ratio == 2.0
    assert d.motor.breakdown_torque_ratio == 2.2
    assert d.motor.rotor_inertia == pytest.approx(0.232, rel=REL_UNIT)
    assert d.gearbox == "Ts2NSh-750B"
    assert d.gearbox_ratio == 37.18
    assert d.motor_sheave_diameter == pytest.approx(0.250, rel=REL_UNIT)
    assert d.gearbox_sheave_diameter == pytest.approx(0.900, rel=REL_UNIT)
    assert d.belt_ratio == pytest.approx(3.6, rel=REL_UNIT)


def test_rated_crank_speed_of_the_drive(sk8_unit):
    omega = sk8_unit.drive.rated_crank_speed
    # [SK8Rotation2013]'s formula with its data; only rounding separates the two (rel 1e-12).
    assert omega == pytest.approx(math.pi * 1460 / (30 * 37.18 * 900 / 250), rel=1e-12)
    # The number [SK8Rotation2013] prints, 1.1422 1/s: agreement to its last printed digit.
    assert abs(omega - SK8_CRANK_SPEED) < 1e-4


def test_well(sk8_unit):
    w = sk8_unit.well
    assert w is not None
    assert w.pump_depth == pytest.approx(1530.0, rel=REL_UNIT)
    assert w.plunger_diameter == pytest.approx(0.038, rel=REL_UNIT)
    # [SK8Rotation2013] lists the taper 19 mm (51 %), 22 mm (26 %), 25 mm (23 %); the file
    # gives it from the top down, as the rod string hangs: thickest rods at the top
    assert [s.diameter for s in w.rod_string] == pytest.approx([0.025, 0.022, 0.019], rel=REL_UNIT)
    assert [s.fraction for s in w.rod_string] == pytest.approx([0.23, 0.26, 0.51], rel=REL_UNIT)
    assert w.fluid_density == pytest.approx(820.0, rel=REL_UNIT)
    assert w.fluid_kinematic_viscosity == pytest.approx(3e-6, rel=REL_UNIT)
    assert w.tubing_inner_diameter == pytest.approx(0.062, rel=REL_UNIT)


# --- the drive of the equation of motion (eqs. 25-26) ------------------------------


def test_motor_characteristic_is_eqs_25_26():
    # M_n = P / omega_n; a = M_n n_s / (n_s - n_n); b = -30 M_n / (pi (n_s - n_n)), n in rpm.
    m_n = 30_000 / (1460 * math.pi / 30)
    a = m_n * 1500 / (1500 - 1460)
    b = -30 * m_n / (math.pi * (1500 - 1460))
    m = motor_characteristic(30e3, 1500 * RPM, 1460 * RPM, 2.0, 2.2)
    assert m.rated_torque == pytest.approx(m_n, rel=1e-14)
    assert m.a == pytest.approx(a, rel=1e-13) and m.b == pytest.approx(b, rel=1e-13)
    assert (round(m_n, 2), round(a, 1), round(b, 3)) == (196.22, 7358.2, -46.844)
    # The line passes through (rated speed, rated torque) and (synchronous speed, 0).
    assert m.torque(1460 * RPM) == pytest.approx(m_n, rel=1e-12)
    assert m.torque(1500 * RPM) == pytest.approx(0.0, abs=1e-9)
    assert (m.starting_torque, m.breakdown_torque) == pytest.approx((2.0 * m_n, 2.2 * m_n))


def test_rated_crank_speed_of_the_machine_is_1_1422(sk8_machine):
    omega1 = math.pi * 1460 / (30 * 37.18 * 900 / 250)
    assert omega1 == pytest.approx(SK8_CRANK_SPEED, abs=1e-4)  # 1.14227...; [SK8Rotation2013] prints 1.1422
    assert sk8_machine.rated_crank_speed == pytest.approx(omega1, rel=1e-12)
    assert sk8_machine.drive_ratio == pytest.approx(37.18 * 3.6, rel=1e-14)


def test_constant_part_of_the_reduced_inertia(sk8_machine):
    # [SK8Rotation2013]: "the constant part of the reduced inertia 66 798.5 kg m^2"; the bundled
    # unit's ESTIMATED sheave and gearbox inertias are chosen to reproduce it
    # (docs/dynamics.md): drive + 2 (J_arm + m_arm r_arm^2) + m_cw r_cw^2.
    crank = 2 * (257 + 1373 * 0.45**2) + 5200 * 0.83**2
    drive = (0.232 + 0.1) * (37.18 * 3.6) ** 2 + (40.154 + 0.5) * 37.18**2
    assert sk8_machine.constant_inertia == pytest.approx(crank + drive, rel=1e-12)
    assert sk8_machine.constant_inertia == pytest.approx(66_798.5, abs=0.2)


# --- `pumpjack kinematics` at the rated speed -----------------------------------------


def test_kinematics_table_shows_the_crank_speed(run_cli, monkeypatch):
    monkeypatch.setenv("COLUMNS", "200")  # wide enough that rich does not wrap or cut rows
    code, out, err = run_cli("kinematics", SK8, "-f", "table")
    assert (code, err) == (0, "")
    speed_line = next(line for line in out.splitlines() if re.search(r"\bcrank_speed\b", line))
    # The table prints 6 significant digits: [SK8Rotation2013]'s pi·1460/(30·37.18·3.6) = 1.14227.
    assert "1.14227" in speed_line
    spm_line = next(line for line in out.splitlines() if "strokes_per_minute" in line)
    spm = float(re.search(r"\d+\.\d+", spm_line).group())
    assert abs(spm - PRINTED_SPM) < 0.05  # [SK8Rotation2013] prints 10.9 (one decimal: ±0.05)


def test_kinematics_json_summary_matches(run_cli):
    code, out, err = run_cli("kinematics", SK8, "-f", "json")
    assert (code, err) == (0, "")
    summary = json.loads(out)["summary"]
    assert abs(summary["crank_speed_rad_s"] - SK8_CRANK_SPEED) < 1e-4  # [SK8Rotation2013] prints 4 decimals
    assert abs(summary["strokes_per_minute_spm"] - PRINTED_SPM) < 0.05  # [SK8Rotation2013] prints 1 decimal
    # period = 2 pi / omega1 (one rotation of the crank is one stroke cycle)
    assert summary["period_s"] == pytest.approx(2 * math.pi / summary["crank_speed_rad_s"], rel=1e-12)
