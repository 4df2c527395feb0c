"""The `pumpjack` program whatever the command: default format in a pipe, output and plot
files, one-line errors, --debug, help, and the real console script in pipes.

`pumpjack kinematics` serves as the example command; each command's own outputs are
checked in tests/commands/.
"""

from __future__ import annotations

import csv
import io
import json
import os
import subprocess
from pathlib import Path

import pytest

from pumpjack_cli.errors import PumpjackError
from pumpjack_cli.names import lookup

from helpers import SK8, SK8_API_YAML, SK8_CARD


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


# --- what an output holds: the columns, or the summary alone ---------------------------

SUMMARY_RUNS = [
    # (argv, a summary name, its CSV name and unit label in field units)
    (("kinematics", SK8, "--steps", "24"), "stroke", "stroke_in", "in"),
    (("torque", SK8, "--card", SK8_CARD, "--steps", "24"), "peak_net_torque", "peak_net_torque_lbf_in", "lbf·in"),
]


@pytest.mark.parametrize(("argv", "name", "csv_name", "unit"), SUMMARY_RUNS, ids=lambda v: v[0] if isinstance(v, tuple) else "")
def test_summary_csv_has_a_row_per_summary_value(run_cli, run_json, argv, name, csv_name, unit):
    """The rows hold the JSON document's summary, in its order and with its names, each with
    its unit label and meaning."""
    code, out, err = run_cli(*argv, "--units", "field", "-f", "csv", "--what", "summary")
    assert (code, err) == (0, "")
    header, *rows = csv.reader(io.StringIO(out))
    assert header == ["name", "value", "unit", "description"]
    summary = run_json(*argv, "--units", "field")["summary"]
    assert [(row[0], float(row[1])) for row in rows] == list(summary.items())
    assert next(row[2:] for row in rows if row[0] == csv_name) == [unit, lookup(name)[1]]


def test_summary_alone_in_json_and_the_table_and_the_plot_unchanged(run_cli, run_json, tmp_path):
    argv = ("kinematics", SK8, "--steps", "24")
    assert run_cli(*argv, "-f", "csv", "--what", "columns")[1] == run_cli(*argv, "-f", "csv")[1]
    assert json.loads(run_cli(*argv, "-f", "json", "--what", "summary")[1]) == {**run_json(*argv), "columns": {},
                                                                                "series": {}}
    table = run_cli(*argv, "-f", "table", "--what", "summary")[1]
    full = run_cli(*argv, "-f", "table")[1]
    assert full.startswith(table) and "[deg]" not in table and "max_velocity" in table and not table.endswith("\n\n")
    plot = tmp_path / "curves.png"
    code, out, err = run_cli(*argv, "-f", "csv", "--what", "summary", "--plot", plot)
    assert (code, err) == (0, "") and out.startswith("name,value,unit,description\n")
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


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
    ("no-drive-no-spm", lambda tmp: ["kinematics", SK8_API_YAML],
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


# --- help ----------------------------------------------------------------------


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
