"""`--catalogue FILE` as an operator uses it: commands and batch runs on catalogue units, and
`pumpjack units --catalogue` in every format.

A catalogue unit gives what its unit file gives (kinematics and torque to the bit); a
published stroke more than 0.5 in off is one warning line; a bad catalogue or name is one
error line with exit code 2.
"""

from __future__ import annotations

import csv
import io
import json
import sqlite3

import pytest

from pumpjack_cli.cli import COMMANDS

from helpers import INCH, REPO_ROOT, sample_card

SAMPLE = REPO_ROOT / "samples" / "catalogue.csv"
HEADER = "designation,crank_hole,rotation,A_in,C_in,I_in,P_in,H_in,G_in,R_in,stroke_in,B_lbf,tau_deg"
#: C-80D-133-48 ([Guo2007] Table 12.1) in its longest hole, with a published stroke to fill in.
ROW = "C-80D-133-48,1,cw,64,64,64,74.5,116,41,24,{stroke},440,0"
#: Its exact stroke [in] (tests/readers/test_catalogue.py).
STROKE_24 = 49.363864381
CARD = sample_card("c-80d-133-48")


def catalogue(folder, stroke="", name="field.csv"):
    path = folder / name
    path.write_text(f"{HEADER}\n{ROW.format(stroke=stroke)}\n", encoding="utf-8")
    return path


def unit_file(folder):
    """The unit file that says what ``ROW`` says."""
    path = folder / "unit.toml"
    path.write_text('name = "C-80D-133-48/1"\ndesignation = "C-80D-133-48"\n\n[geometry]\nA = "64 in"\nC = "64 in"\n'
                    'I = "64 in"\nP = "74.5 in"\nH = "116 in"\nG = "41 in"\nR = "24 in"\nrotation = "cw"\n\n'
                    '[counterbalance]\nstructural_unbalance = "440 lbf"\nphase = "0 deg"\n', encoding="utf-8")
    return path


UNIT_COMMANDS = [name for name in COMMANDS if name not in ("units", "batch")]


@pytest.mark.parametrize("command", [*UNIT_COMMANDS, "units", "batch run"])
def test_every_command_that_takes_a_unit_takes_a_catalogue(run_cli, command):
    code, out, _ = run_cli(*command.split(), "--help")
    assert code == 0 and "--catalogue" in out


def _without_stroke_note(err: str) -> str:
    """stderr less `torque`'s note on the stroke loading (C-80D-133-48's letters give 49.36 in, its rating 48 in)."""
    return "".join(line for line in err.splitlines(keepends=True) if "stroke loading" not in line)


@pytest.mark.parametrize("command", [("kinematics", "--spm", "8", "--steps", "36"),
                                     ("torque", "--card", CARD, "--steps", "36")])
def test_a_command_on_a_catalogue_unit_prints_what_its_unit_file_gives(run_cli, tmp_path, command):
    name, *options = command
    code, by_row, err = run_cli(name, "C-80D-133-48/1", "--catalogue", catalogue(tmp_path), *options, "-f", "json")
    assert (code, _without_stroke_note(err)) == (0, "")
    code, by_file, err = run_cli(name, unit_file(tmp_path), *options, "-f", "json")
    assert (code, _without_stroke_note(err)) == (0, "")
    row, file = json.loads(by_row), json.loads(by_file)
    assert (row["summary"], row["series"]) == (file["summary"], file["series"])


def test_torque_on_the_sample_catalogue_balances_as_the_bundled_unit(run_cli):
    """C-80D-133-48/1 of the sample has the bundled C-80D-133-48's geometry and B; the recommended
    counterbalance (which does not depend on the present moment M, not in a catalogue) is the same,
    to round-off: the search takes the net torque less the counterbalance's (analysis/torque.py),
    so M enters and leaves by a subtraction (the bundled unit without its M gives the catalogue's
    figure bit for bit; with it the two differ in the last bit)."""
    code, out, err = run_cli("torque", "C-80D-133-48/1", "--catalogue", SAMPLE, "--card", CARD, "-f", "json")
    assert (code, _without_stroke_note(err)) == (0, "")
    code, bundled, err = run_cli("torque", "c-80d-133-48", "--card", CARD, "-f", "json")
    assert (code, _without_stroke_note(err)) == (0, "")
    name = "recommended_counterbalance_moment_n_m"
    assert json.loads(out)["summary"][name] == pytest.approx(json.loads(bundled)["summary"][name], rel=1e-12)


@pytest.mark.parametrize(("off", "warned"), [(1.0, True), (0.3, False)])
def test_a_published_stroke_off_by_more_than_half_an_inch_is_a_warning(run_cli, tmp_path, off, warned):
    path = catalogue(tmp_path, f"{STROKE_24 + off:.9f}")
    code, out, err = run_cli("kinematics", "C-80D-133-48/1", "--catalogue", path, "--spm", "8", "-f", "json")
    assert code == 0 and json.loads(out)["summary"]["stroke_m"] == pytest.approx(STROKE_24 * INCH, abs=1e-10)
    if warned:
        assert err == (f"pumpjack: warning: {path}: line 2: C-80D-133-48/1: the exact stroke 49.36 in (1.2538 m) "
                       f"differs from the published 50.36 in by -1.00 in, more than 0.5 in: check the letters, R_in "
                       f"and the stroke\n")
    else:
        assert err == ""


@pytest.mark.parametrize(("argv", "message"), [
    (("C-80D-133-48/2",), "unit 'C-80D-133-48/2': {file} has crank holes 1 of C-80D-133-48, not 2"),
    (("C-80D-133-84/1",), "unknown unit 'C-80D-133-84/1': not a file, a bundled unit or a unit of {file}; close: "
                          "C-80D-133-48/1"),
    (("C-80D-133-48/1", "--catalogue", "{folder}/none.csv"), "{folder}/none.csv: cannot read: no such file"),
])
def test_a_bad_name_or_catalogue_is_one_error_line(run_cli, tmp_path, argv, message):
    path = catalogue(tmp_path)
    argv = [arg.format(folder=tmp_path) for arg in argv]
    code, out, err = run_cli("kinematics", *argv[:1], "--catalogue", path, *argv[1:], "--spm", "8")
    assert (code, out) == (2, "")
    assert err.startswith(f"pumpjack: error: {message.format(file=path, folder=tmp_path)}") and err.count("\n") == 1


@pytest.mark.parametrize(("text", "message"), [
    (HEADER.replace(",R_in", "") + "\n", "line 1: missing column R"),
    (f"{HEADER}\n{ROW.format(stroke='')}\n{ROW.format(stroke='')}\n", "line 3: C-80D-133-48/1 is given twice"),
    (f"{HEADER}\n{ROW.format(stroke='fifty')}\n", "line 2: column stroke_in: 'fifty' is not a number"),
])
@pytest.mark.parametrize("command", [("kinematics", "C-80D-133-48/1", "--spm", "8"), ("units",)])
def test_a_bad_catalogue_is_one_error_line_for_every_command(run_cli, tmp_path, text, message, command):
    path = tmp_path / "field.csv"
    path.write_text(text, encoding="utf-8")
    code, out, err = run_cli(*command, "--catalogue", path)
    assert (code, out) == (2, "")
    assert err.startswith(f"pumpjack: error: {path}: {message}") and err.count("\n") == 1


# --- units --catalogue ------------------------------------------------------------------


def test_units_lists_the_catalogue_as_csv(run_cli, tmp_path):
    path = tmp_path / "field.csv"
    path.write_text(f"{HEADER},source\n{ROW.format(stroke=f'{STROKE_24 + 1:.9f}')},[Guo2007]\n"
                    f"{ROW.format(stroke='').replace(',1,cw,', ',2,cw,').replace(',24,', ',20,')},[Guo2007]\n",
                    encoding="utf-8")
    code, out, err = run_cli("units", "--catalogue", path, "-f", "csv", "--units", "field")
    assert (code, err) == (0, "")
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [row["name"] for row in rows] == ["C-80D-133-48/1", "C-80D-133-48/2"]
    assert [(row["crank_hole"], row["unit_class"], row["stroke_check"], row["source"]) for row in rows] == [
        ("1", "conventional", "differs", "[Guo2007]"), ("2", "conventional", "not published", "[Guo2007]")]
    assert float(rows[0]["stroke_in"]) == pytest.approx(STROKE_24, abs=1e-8)
    assert float(rows[0]["published_stroke_in"]) == pytest.approx(STROKE_24 + 1, abs=1e-8)
    assert float(rows[0]["stroke_difference_in"]) == pytest.approx(-1.0, abs=1e-8)
    assert rows[1]["published_stroke_in"] == rows[1]["stroke_difference_in"] == ""


def test_units_lists_the_catalogue_as_json_and_a_table(run_cli):
    code, out, err = run_cli("units", "--catalogue", SAMPLE, "-f", "json")
    assert (code, err) == (0, "")
    series = json.loads(out)["series"]
    assert series["name"] == [f"{d}/{h}" for d in ("C-114D-133-54", "C-80D-133-48", "M-912D-365-168") for h in (1, 2, 3)]
    assert series["published_stroke_m"][:6] == series["stroke_difference_m"][:6] == [None] * 6
    # [LufkinM912]'s 168, 149 and 130 in, exactly converted
    assert series["published_stroke_m"][6:] == [168 * INCH, 149 * INCH, 130 * INCH]
    assert series["stroke_check"] == ["not published"] * 6 + ["ok", "ok", "differs"]
    assert series["unit_class"] == ["conventional"] * 6 + ["mark-ii"] * 3
    # the listing's strokes are the kinematics' (two code paths; 1e-12 relative for the summation order)
    code, kin, _ = run_cli("kinematics", "C-114D-133-54/2", "--catalogue", SAMPLE, "--spm", "8", "--steps", "8",
                           "-f", "json")
    assert series["stroke_m"][1] == pytest.approx(json.loads(kin)["summary"]["stroke_m"], rel=1e-12)
    code, table, err = run_cli("units", "--catalogue", SAMPLE, "-f", "table")
    assert (code, err) == (0, "")
    assert f"Units of {SAMPLE}" in table and "C-80D-133-48/3" in table and "not published" in table


def test_a_sample_hole_whose_printed_stroke_is_off_warns_when_used(run_cli):
    """M-912D-365-168 hole 3: exact 130.83 in, printed 130 in ([LufkinM912]); hole 2 is within 0.5 in."""
    code, _, err = run_cli("kinematics", "M-912D-365-168/3", "--catalogue", SAMPLE, "--spm", "6", "-f", "csv")
    assert code == 0 and err == (f"pumpjack: warning: {SAMPLE}: line 13: M-912D-365-168/3: the exact stroke 130.83 in "
                                 f"(3.3230 m) differs from the published 130.00 in by +0.83 in, more than 0.5 in: check "
                                 f"the letters, R_in and the stroke\n")
    code, _, err = run_cli("kinematics", "m-912d-365-168/2", "--catalogue", SAMPLE, "--spm", "6", "-f", "csv")
    assert (code, err) == (0, "")


def test_units_without_a_catalogue_lists_the_bundled_units(run_cli):
    _, out, _ = run_cli("units", "-f", "csv")
    assert out.splitlines()[0] == "name,kind,designation,stroke_m,description"


# --- batch ------------------------------------------------------------------------------


def test_a_manifest_naming_a_catalogue_unit_stores_its_rows(run_cli, tmp_path):
    """The torque of a card on C-80D-133-48/1 is stored as the single command prints it (to
    1e-9), with the stroke warning; without --catalogue it is an error row; a re-run skips it."""
    path = catalogue(tmp_path, f"{STROKE_24 + 1:.9f}")
    manifest = tmp_path / "manifest.csv"
    manifest.write_text(f"well,unit,card\nW-1,C-80D-133-48/1,{CARD}\n", encoding="utf-8")
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", "run", manifest, "--store", store, "--catalogue", path, "--workers", "1",
                             "--analyses", "torque")
    assert code == 0 and "1 cards: 1 analysed" in out, err
    db = sqlite3.connect(store)
    db.row_factory = sqlite3.Row
    [row] = [dict(r) for r in db.execute("SELECT * FROM results")]
    assert (row["unit"], row["status"], row["error"]) == ("C-80D-133-48/1", "ok", "")
    assert "C-80D-133-48/1: the exact stroke 49.36 in" in row["warnings"]
    code, single, _ = run_cli("torque", "C-80D-133-48/1", "--catalogue", path, "--card", CARD, "--steps", "4",
                              "-f", "json")
    summary = json.loads(single)["summary"]
    numbers = [name for name, value in summary.items() if isinstance(value, float)]
    assert len(numbers) > 5 and all(row[name] == pytest.approx(summary[name], rel=1e-9) for name in numbers)
    code, out, err = run_cli("batch", "run", manifest, "--store", store, "--catalogue", path, "--workers", "1",
                             "--analyses", "torque")
    assert code == 0 and "1 cards: 0 analysed, 1 already in" in out, err
    code, out, err = run_cli("batch", "run", manifest, "--store", tmp_path / "none.sqlite", "--workers", "1",
                             "--analyses", "torque")
    [refused] = sqlite3.connect(tmp_path / "none.sqlite").execute("SELECT status, error FROM results").fetchall()
    assert refused[0] == "error" and "DESIGNATION/HOLE names a unit of --catalogue FILE" in refused[1]


def test_a_changed_catalogue_row_is_analysed_again_and_another_row_is_not(run_cli, tmp_path):
    path = catalogue(tmp_path)
    manifest = tmp_path / "manifest.csv"
    manifest.write_text(f"well,unit,card\nW-1,C-80D-133-48/1,{CARD}\n", encoding="utf-8")
    store = tmp_path / "r.sqlite"

    def run() -> str:
        code, out, err = run_cli("batch", manifest, "--store", store, "--catalogue", path, "--workers", "1",
                                 "--analyses", "torque")
        assert code == 0, err
        return out

    assert "1 analysed" in run()
    path.write_text(path.read_text(encoding="utf-8") + ROW.format(stroke="").replace(",1,cw,", ",2,cw,") + "\n",
                    encoding="utf-8")
    assert "0 analysed, 1 already in" in run()
    path.write_text(path.read_text(encoding="utf-8").replace(",440,0", ",450,0", 1), encoding="utf-8")
    assert "1 analysed" in run()


def test_a_bad_catalogue_stops_a_batch_before_any_card(run_cli, tmp_path):
    path = tmp_path / "field.csv"
    path.write_text("", encoding="utf-8")
    manifest = tmp_path / "manifest.csv"
    manifest.write_text(f"well,unit,card\nW-1,C-80D-133-48/1,{CARD}\n", encoding="utf-8")
    code, out, err = run_cli("batch", manifest, "--store", tmp_path / "r.sqlite", "--catalogue", path)
    assert (code, out) == (2, "") and err.startswith(f"pumpjack: error: {path}: empty")
    assert not (tmp_path / "r.sqlite").exists()
