"""The `pumpjack` command: output formats, units, files, errors, help, pipes.

Independent reference numbers ([SK8Rotation2013], SK8-3,5-4000 with motor 4AR180M4U3 at its
rated 1460 rpm, gearbox 37.18, sheaves 250/900 mm):
omega1 = pi·1460/(30·37.18·900/250) = 1.1422 1/s and N = 60·omega1/(2 pi) ≈ 10.9 1/min.
Library values (for "parses back exactly") come from pumpjack_cli.core directly, not
from the CLI.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.config import load_unit, read_unit_file
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.errors import PumpjackError

from helpers import REPO_ROOT

SK8 = "sk8-3.5-4000"
SEED_OMEGA1 = 1.1422  # 1/s, [SK8Rotation2013] (printed to 4 decimals)
SEED_SPM = 10.9  # 1/min, [SK8Rotation2013] (printed to 1 decimal)
INCH, FOOT = 0.0254, 0.3048  # m, exact definitions
# Angles are printed in degrees rounded to 1e-9 degree (documented in units.py), so a
# degree column can differ from value·180/pi by half a unit in the 9th decimal, plus
# the rounding of the product (~1e-13 near 360): allow 6e-10 degree.
DEG_TOL = 6e-10


def _csv_columns(text: str) -> dict[str, list[str]]:
    rows = list(csv.DictReader(io.StringIO(text)))
    assert rows, "no CSV rows"
    return {key: [row[key] for row in rows] for key in rows[0]}


def _floats(values: list[str]) -> np.ndarray:
    return np.array([float(v) for v in values])


@pytest.fixture(scope="module")
def library_result():
    """The library's own result for the bundled SK8 at the motor's rated speed, 360 steps."""
    config = load_unit(SK8)
    return uniform_kinematics(config.geometry.mechanism(), config.drive.rated_crank_speed, 360)


# Exact-kinematics columns (SI, no scaling) and where the library keeps them.
SI_COLUMNS = {
    "time_s": lambda r: r.time,
    "position_m": lambda r: r.rod.position,
    "velocity_m_s": lambda r: r.rod.velocity,
    "acceleration_m_s2": lambda r: r.rod.acceleration,
    "torque_factor_m": lambda r: r.torque_factor,
    "beam_angular_velocity_rad_s": lambda r: r.beam_angular_velocity,
    "beam_angular_acceleration_rad_s2": lambda r: r.beam_angular_acceleration,
    "pitman_angular_velocity_rad_s": lambda r: r.pitman_angular_velocity,
    "pitman_angular_acceleration_rad_s2": lambda r: r.pitman_angular_acceleration,
    "position_harmonic_m": lambda r: r.approximations["harmonic"].position,
    "velocity_harmonic_m_s": lambda r: r.approximations["harmonic"].velocity,
    "acceleration_harmonic_m_s2": lambda r: r.approximations["harmonic"].acceleration,
    "position_two_term_m": lambda r: r.approximations["two_term"].position,
    "velocity_two_term_m_s": lambda r: r.approximations["two_term"].velocity,
    "acceleration_two_term_m_s2": lambda r: r.approximations["two_term"].acceleration,
}
ANGLE_COLUMNS = {
    "crank_angle_deg": lambda r: r.crank_angle,
    "beam_angle_deg": lambda r: r.beam_angle,
    "pitman_angle_deg": lambda r: r.pitman_angle,
}


# --- [SK8Rotation2013] speed ----------------------------------------------------------------


def test_table_shows_seed_crank_speed(run_cli, monkeypatch):
    monkeypatch.setenv("COLUMNS", "200")  # wide enough that rich does not wrap or cut rows
    code, out, err = run_cli("kinematics", SK8, "-f", "table")
    assert (code, err) == (0, "")
    speed_line = next(line for line in out.splitlines() if re.search(r"\bcrank_speed\b", line))
    # The table prints 6 significant digits: [SK8Rotation2013]'s pi·1460/(30·37.18·3.6) = 1.14227.
    assert "1.14227" in speed_line
    spm_line = next(line for line in out.splitlines() if "strokes_per_minute" in line)
    spm = float(re.search(r"\d+\.\d+", spm_line).group())
    assert abs(spm - SEED_SPM) < 0.05  # [SK8Rotation2013] prints 10.9 (one decimal: ±0.05)


def test_json_summary_matches_seed(run_cli):
    code, out, err = run_cli("kinematics", SK8, "-f", "json")
    assert (code, err) == (0, "")
    summary = json.loads(out)["summary"]
    assert abs(summary["crank_speed_rad_s"] - SEED_OMEGA1) < 1e-4  # [SK8Rotation2013] prints 4 decimals
    assert abs(summary["strokes_per_minute_spm"] - SEED_SPM) < 0.05  # [SK8Rotation2013] prints 1 decimal
    # period = 2 pi / omega1 (one rotation of the crank is one stroke cycle)
    assert summary["period_s"] == pytest.approx(2 * math.pi / summary["crank_speed_rad_s"], rel=1e-12)


def test_spm_option_gives_period(run_cli):
    code, out, err = run_cli("kinematics", SK8, "--spm", "10", "-f", "json")
    assert (code, err) == (0, "")
    summary = json.loads(out)["summary"]
    # 10 strokes per minute: 60 s / 10 = 6 s per stroke; rel 1e-12 for the round trip
    # spm -> rad/s -> period.
    assert summary["period_s"] == pytest.approx(6.0, rel=1e-12)
    assert summary["strokes_per_minute_spm"] == pytest.approx(10.0, rel=1e-12)
    assert summary["crank_speed_rad_s"] == pytest.approx(2 * math.pi / 6, rel=1e-12)


# --- CSV and JSON reproduce the library ---------------------------------------------


def test_csv_parses_back_to_library_values(run_cli, library_result):
    code, out, err = run_cli("kinematics", SK8, "-f", "csv")
    assert (code, err) == (0, "")
    columns = _csv_columns(out)
    assert set(columns) == set(SI_COLUMNS) | set(ANGLE_COLUMNS)
    assert list(columns)[:6] == ["crank_angle_deg", "time_s", "position_m", "velocity_m_s",
                                 "acceleration_m_s2", "torque_factor_m"]
    for name, get in SI_COLUMNS.items():
        values = _floats(columns[name])
        expected = np.asarray(get(library_result), dtype=float)
        assert values.shape == (360,)
        # floats are written with repr: they must parse back to the same bits
        assert np.array_equal(values, expected), name
    for name, get in ANGLE_COLUMNS.items():
        values = _floats(columns[name])
        expected = np.asarray(get(library_result)) * (180 / math.pi)
        np.testing.assert_allclose(values, expected, rtol=0, atol=DEG_TOL, err_msg=name)


def test_csv_crank_angles_are_whole_degrees(run_cli):
    # 360 steps per revolution: crank angles 0, 1, ..., 359 degrees; with angles printed
    # to 1e-9 degree these come out as exact whole numbers.
    code, out, _ = run_cli("kinematics", SK8, "-f", "csv")
    assert code == 0
    assert _csv_columns(out)["crank_angle_deg"] == [f"{k}.0" for k in range(360)]


def test_json_equals_library(run_cli, library_result):
    code, out, err = run_cli("kinematics", SK8, "-f", "json")
    assert (code, err) == (0, "")
    doc = json.loads(out)
    assert doc["units"] == "si"
    assert "SK8-3,5-4000" in doc["title"]
    series = doc["series"]
    assert set(series) == set(doc["columns"]) == set(SI_COLUMNS) | set(ANGLE_COLUMNS)
    for name, get in SI_COLUMNS.items():
        assert series[name] == np.asarray(get(library_result), dtype=float).tolist(), name
    for name, get in ANGLE_COLUMNS.items():
        np.testing.assert_allclose(series[name], np.asarray(get(library_result)) * (180 / math.pi),
                                   rtol=0, atol=DEG_TOL, err_msg=name)
    assert doc["columns"]["position_m"]["unit"] == "m"

    s, summary = library_result.summary, doc["summary"]
    exact = {
        "crank_speed_rad_s": s.crank_speed,
        "period_s": s.period,
        "stroke_m": s.stroke,
        "max_velocity_m_s": s.max_velocity.value,
        "min_velocity_m_s": s.min_velocity.value,
        "max_acceleration_m_s2": s.max_acceleration.value,
        "min_acceleration_m_s2": s.min_acceleration.value,
        "max_torque_factor_m": s.max_torque_factor.value,
        "min_torque_factor_m": s.min_torque_factor.value,
    }
    for key, value in exact.items():
        assert summary[key] == value, key
    degrees = {
        "crank_angle_bottom_deg": s.crank_angle_bottom,
        "crank_angle_top_deg": s.crank_angle_top,
        "upstroke_crank_travel_deg": s.upstroke_crank_travel,
        "downstroke_crank_travel_deg": s.downstroke_crank_travel,
        "max_velocity_crank_angle_deg": s.max_velocity.crank_angle,
    }
    for key, value in degrees.items():
        assert abs(summary[key] - value * 180 / math.pi) <= DEG_TOL, key
    # Scaled summary values: one multiplication, rel 1e-12.
    assert summary["strokes_per_minute_spm"] == pytest.approx(s.crank_speed * 60 / (2 * math.pi), rel=1e-12)
    err = s.approximation_errors["harmonic"]
    assert summary["harmonic_position_error_percent"] == pytest.approx(100 * err.position, rel=1e-12)
    assert summary["harmonic_peak_acceleration_error_percent"] == pytest.approx(100 * err.peak_acceleration, rel=1e-12)


def test_field_units(run_cli):
    _, si_out, _ = run_cli("kinematics", SK8, "-f", "csv")
    code, field_out, err = run_cli("kinematics", SK8, "-f", "csv", "--units", "field")
    assert (code, err) == (0, "")
    si, field = _csv_columns(si_out), _csv_columns(field_out)
    conversions = {
        # field column: (SI column, exact factor SI -> field unit)
        "position_in": ("position_m", 1 / INCH),
        "torque_factor_in": ("torque_factor_m", 1 / INCH),
        "velocity_ft_s": ("velocity_m_s", 1 / FOOT),
        "acceleration_ft_s2": ("acceleration_m_s2", 1 / FOOT),
        "position_two_term_in": ("position_two_term_m", 1 / INCH),
        "time_s": ("time_s", 1.0),
        "crank_angle_deg": ("crank_angle_deg", 1.0),
    }
    for name, (si_name, factor) in conversions.items():
        assert name in field, name
        # one division by an exact definition: rel 1e-12 (values near zero: abs 1e-15 m)
        np.testing.assert_allclose(_floats(field[name]), _floats(si[si_name]) * factor, rtol=1e-12, atol=1e-15,
                                   err_msg=name)
    assert "position_m" not in field and "velocity_m_s" not in field


def test_field_units_json_summary(run_cli):
    _, si_out, _ = run_cli("kinematics", SK8, "-f", "json")
    code, field_out, _ = run_cli("kinematics", SK8, "-f", "json", "--units", "field")
    assert code == 0
    si, field = json.loads(si_out)["summary"], json.loads(field_out)["summary"]
    assert json.loads(field_out)["units"] == "field"
    assert field["stroke_in"] == pytest.approx(si["stroke_m"] / INCH, rel=1e-12)
    assert field["max_velocity_ft_s"] == pytest.approx(si["max_velocity_m_s"] / FOOT, rel=1e-12)


def test_gost_and_api_files_give_identical_csv(run_cli):
    args = ("--spm", "10", "-f", "csv")
    code_a, gost, err_a = run_cli("kinematics", REPO_ROOT / "configs" / "sk8-3.5-4000.toml", *args)
    code_b, api, err_b = run_cli("kinematics", REPO_ROOT / "samples" / "sk8-3.5-4000-api.yaml", *args)
    assert (code_a, code_b, err_a, err_b) == (0, 0, "", "")
    assert gost.startswith("crank_angle_deg,")
    assert gost == api


def test_steps_option(run_cli):
    code, out, _ = run_cli("kinematics", SK8, "--steps", "12", "-f", "csv")
    assert code == 0
    angles = _floats(_csv_columns(out)["crank_angle_deg"])
    np.testing.assert_allclose(angles, np.arange(12) * 30.0, rtol=0, atol=DEG_TOL)


def test_default_format_is_csv_in_a_pipe(run_cli):
    # capsys' stdout is not a terminal
    code, out, err = run_cli("kinematics", SK8)
    assert (code, err) == (0, "")
    assert out.splitlines()[0].startswith("crank_angle_deg,time_s,position_m,")
    _, explicit, _ = run_cli("kinematics", SK8, "-f", "csv")
    assert out == explicit


# --- files -------------------------------------------------------------------------


@pytest.mark.parametrize(("name", "fmt"), [("out.csv", "csv"), ("out.json", "json"), ("OUT.JSON", "json")])
def test_output_file_format_from_suffix(run_cli, tmp_path, name, fmt):
    target = tmp_path / name
    code, out, err = run_cli("kinematics", SK8, "--steps", "24", "-o", target)
    assert (code, out, err) == (0, "", "")
    _, reference, _ = run_cli("kinematics", SK8, "--steps", "24", "-f", fmt)
    assert target.read_text(encoding="utf-8") == reference
    # written atomically: no temporary file left beside it
    assert [p.name for p in tmp_path.iterdir()] == [name]


def test_output_file_has_the_usual_mode(run_cli, tmp_path):
    target = tmp_path / "out.csv"
    assert run_cli("kinematics", SK8, "--steps", "8", "-o", target)[0] == 0
    umask = os.umask(0)
    os.umask(umask)
    assert target.stat().st_mode & 0o777 == 0o666 & ~umask


def test_explicit_format_wins_over_suffix(run_cli, tmp_path):
    target = tmp_path / "out.csv"
    assert run_cli("kinematics", SK8, "--steps", "8", "-f", "json", "-o", target)[0] == 0
    assert json.loads(target.read_text(encoding="utf-8"))["units"] == "si"


def test_output_into_missing_directory(run_cli, tmp_path):
    target = tmp_path / "no-such-dir" / "out.csv"
    code, out, err = run_cli("kinematics", SK8, "-o", target)
    assert code == 2
    assert out == ""
    assert len(err.splitlines()) == 1 and err.startswith("pumpjack: error:")
    assert "no-such-dir" in err
    assert not target.exists()
    assert list(tmp_path.iterdir()) == []


def test_output_onto_a_directory(run_cli, tmp_path):
    code, out, err = run_cli("kinematics", SK8, "-o", tmp_path)
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and err.startswith("pumpjack: error:")
    assert "--output" in err


def test_plot_png(run_cli, tmp_path):
    plot = tmp_path / "curves.png"
    code, out, err = run_cli("kinematics", SK8, "--steps", "36", "-f", "csv", "--plot", plot)
    assert (code, err) == (0, "")
    assert out.startswith("crank_angle_deg,")
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"  # PNG signature (PNG spec, section 5.2)
    assert [p.name for p in tmp_path.iterdir()] == ["curves.png"]


def test_plot_bad_suffix_writes_nothing(run_cli, tmp_path):
    out_file = tmp_path / "out.csv"
    code, out, err = run_cli("kinematics", SK8, "-o", out_file, "--plot", tmp_path / "bad.txt")
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and err.startswith("pumpjack: error:")
    assert "--plot" in err and "bad.txt" in err
    assert list(tmp_path.iterdir()) == []


# --- errors ------------------------------------------------------------------------


def _invalid_config(tmp_path: Path) -> Path:
    path = tmp_path / "broken-unit.toml"
    path.write_text('name = "x"\n[geometry]\nk1 = "3,5 m"\nk = 2.5\nr = 1.01\nl = 3\nl1 = 2.195\nl2 = 3\n'
                    'rotation = "cw"\n', encoding="utf-8")
    return path


ERROR_CASES = [
    # (id, argv builder, fragments the one line must contain)
    ("unknown-unit", lambda tmp: ["kinematics", "sk99-nope"], ["sk99-nope", "sk8-3.5-4000"]),
    ("missing-file", lambda tmp: ["kinematics", tmp / "missing.toml"], ["missing.toml", "no such file"]),
    ("invalid-config", lambda tmp: ["kinematics", _invalid_config(tmp)],
     ["broken-unit.toml", "geometry.front_arm", "decimal comma"]),
    ("steps-2", lambda tmp: ["kinematics", SK8, "--steps", "2"], ["--steps"]),
    ("spm-0", lambda tmp: ["kinematics", SK8, "--spm", "0"], ["--spm"]),
    ("bad-format", lambda tmp: ["kinematics", SK8, "-f", "xml"], ["--format", "xml"]),
    ("bad-units", lambda tmp: ["kinematics", SK8, "--units", "imperial"], ["--units", "imperial"]),
    ("unknown-option", lambda tmp: ["kinematics", SK8, "--bogus"], ["--bogus"]),
    ("unknown-command", lambda tmp: ["no-such-command", SK8], ["no-such-command"]),
    ("missing-argument", lambda tmp: ["kinematics"], ["Missing argument", "unit"]),
    ("no-drive-no-spm", lambda tmp: ["kinematics", REPO_ROOT / "samples" / "sk8-3.5-4000-api.yaml"],
     ["[drive]", "--spm"]),
]


@pytest.mark.parametrize(("make_argv", "fragments"), [c[1:] for c in ERROR_CASES], ids=[c[0] for c in ERROR_CASES])
def test_user_error_is_one_line(run_cli, tmp_path, make_argv, fragments):
    code, out, err = run_cli(*make_argv(tmp_path))
    assert code == 2
    assert out == ""
    assert "Traceback" not in err
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert err.endswith("\n")
    assert lines[0].startswith("pumpjack: error: ")
    for fragment in fragments:
        assert fragment in lines[0]


def test_debug_raises_in_process(tmp_path):
    from pumpjack_cli.cli import main

    with pytest.raises(PumpjackError, match="sk99-nope"):
        main(["--debug", "kinematics", "sk99-nope"])
    with pytest.raises(PumpjackError, match="decimal comma"):
        main(["--debug", "kinematics", str(_invalid_config(tmp_path))])


def test_debug_after_the_subcommand_also_works(run_cli):
    # --debug is accepted anywhere on the command line; on a good run it changes nothing.
    code, out, err = run_cli("kinematics", SK8, "--steps", "4", "-f", "csv", "--debug")
    assert (code, err) == (0, "")
    assert out.startswith("crank_angle_deg,")
    with pytest.raises(PumpjackError):
        run_cli("kinematics", "sk99-nope", "--debug")


# --- help and the units command ----------------------------------------------------


@pytest.mark.parametrize(
    ("argv", "fragments"),
    [
        (["--help"], ["kinematics", "units", "--debug"]),
        (["kinematics", "--help"], ["--spm", "--steps", "--format", "--output", "--plot", "--units"]),
        (["units", "--help"], ["--format", "--output", "--units"]),
    ],
)
def test_help(run_cli, argv, fragments):
    code, out, err = run_cli(*argv)
    assert code == 0
    assert "Usage" in out
    for fragment in fragments:
        assert fragment in out


def test_no_arguments_shows_help_without_empty_error(run_cli):
    code, out, err = run_cli()
    assert code == 0
    assert "Usage" in out
    assert not any(line.strip() == "pumpjack: error:" for line in err.splitlines())


def test_units_lists_every_bundled_unit(run_cli):
    code, out, err = run_cli("units", "-f", "csv")
    assert (code, err) == (0, "")
    rows = list(csv.DictReader(io.StringIO(out)))
    stems = sorted(p.stem for p in (REPO_ROOT / "configs").glob("*.toml"))
    assert [row["name"] for row in rows] == stems
    by_name = {row["name"]: row for row in rows}
    assert by_name["sk8-3.5-4000"]["designation"] == "SK8-3,5-4000"
    assert by_name["c-114d-133-54"]["designation"] == "C-114D-133-54"
    # 7SK12-2,5-5600: 2.5 m stroke by its designation; the file solves r (given to
    # 0.1 mm) for that stroke, and dS/dr ~ 2 A/C = 2.4, so |S - 2.5 m| < 0.05 mm * 2.4.
    assert abs(float(by_name["7sk12-2.5-5600"]["stroke_m"]) - 2.5) < 1.5e-4


@pytest.mark.parametrize("name", sorted(p.stem for p in (REPO_ROOT / "configs").glob("*.toml")
                                         if read_unit_file(p).kind == "beam-pump"))
def test_units_stroke_equals_kinematics_stroke(run_cli, name):
    # The listing and the kinematics summary must agree on the exact stroke
    # (two commands, two code paths; rel 1e-12 allows for summation order).
    _, listing, _ = run_cli("units", "-f", "csv")
    stroke = {row["name"]: float(row["stroke_m"]) for row in csv.DictReader(io.StringIO(listing))}[name]
    code, out, err = run_cli("kinematics", name, "--spm", "10", "--steps", "8", "-f", "json")
    assert (code, err) == (0, "")
    assert stroke == pytest.approx(json.loads(out)["summary"]["stroke_m"], rel=1e-12)


def test_units_field_and_json(run_cli):
    _, si_out, _ = run_cli("units", "-f", "json")
    code, out, _ = run_cli("units", "-f", "json", "--units", "field")
    assert code == 0
    si, field = json.loads(si_out)["series"], json.loads(out)["series"]
    assert field["name"] == si["name"]
    # stroke in inches = stroke in metres / 0.0254 (one division: rel 1e-12)
    assert field["stroke_in"] == pytest.approx([s / INCH for s in si["stroke_m"]], rel=1e-12)


# --- the real console script (subprocess) -------------------------------------------


def test_script_csv_equals_in_process(run_script, run_cli):
    proc = run_script("kinematics", SK8, "--steps", "36", "-f", "csv")
    assert (proc.returncode, proc.stderr) == (0, "")
    assert proc.stdout == run_cli("kinematics", SK8, "--steps", "36", "-f", "csv")[1]


def test_script_default_format_in_a_pipe(run_script):
    proc = run_script("kinematics", SK8, "--steps", "6")
    assert proc.returncode == 0
    assert proc.stdout.splitlines()[0].startswith("crank_angle_deg,time_s,position_m")
    assert len(proc.stdout.splitlines()) == 7


def test_script_error_is_one_line(run_script):
    proc = run_script("kinematics", "sk99-nope")
    assert proc.returncode == 2
    assert proc.stdout == ""
    assert proc.stderr.count("\n") == 1
    assert proc.stderr.startswith("pumpjack: error: unknown unit 'sk99-nope'")
    assert "Traceback" not in proc.stderr


def test_script_debug_shows_traceback(run_script):
    proc = run_script("--debug", "kinematics", "sk99-nope")
    assert proc.returncode != 0
    assert "Traceback" in proc.stderr
    assert "ConfigError" in proc.stderr and "sk99-nope" in proc.stderr


def test_script_help(run_script):
    proc = run_script("--help")
    assert proc.returncode == 0
    assert "kinematics" in proc.stdout


def test_script_broken_pipe_is_quiet(pumpjack_script, repo_root):
    # 20000 rows (several MB) cannot fit in a pipe buffer, so the writer is certainly
    # still writing when the reader closes the pipe: EPIPE is hit every time, not by
    # chance. The timeout only guards against a hang.
    proc = subprocess.Popen(
        [pumpjack_script, "kinematics", SK8, "--steps", "20000", "-f", "csv"],
        cwd=repo_root, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
    )
    try:
        header = proc.stdout.readline()
        proc.stdout.close()
        stderr = proc.stderr.read()
        proc.wait(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert header.startswith(b"crank_angle_deg,")
    assert stderr == b"", stderr.decode(errors="replace")


def test_script_pipe_into_head(pumpjack_script, repo_root):
    # The shell form of the same check: `pumpjack kinematics ... | head -n1`.
    proc = subprocess.run(
        f"'{pumpjack_script}' kinematics {SK8} --steps 20000 | head -n1",
        shell=True, cwd=repo_root, capture_output=True, text=True, timeout=120,
    )
    assert proc.stdout.startswith("crank_angle_deg,")
    assert proc.stdout.count("\n") == 1
    assert proc.stderr == ""
