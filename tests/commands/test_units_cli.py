"""`pumpjack units` as a user runs it: the listing of the bundled pumping units (not units of
measure: those are tests/quantities/)."""

from __future__ import annotations

import csv
import io
import json

import pytest

from pumpjack_cli.config import read_unit_file

from helpers import INCH, REPO_ROOT


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
