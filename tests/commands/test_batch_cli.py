"""`pumpjack batch` as an operator runs it: a field of cards into a results store.

Checked against the single-card commands (the same numbers to 1e-9 and the same error
messages), by re-running it, and with manifests that are broken. Runs killed, interrupted,
run twice at once or on a Dask cluster that fails are in ``test_batch_faults.py``; stores
that are not stores, damaged or on read-only and full file systems in ``test_batch_store.py``.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import sqlite3
from pathlib import Path

import pytest

from helpers import REPO_ROOT, assert_same_summary
from helpers import field_cards as field
from helpers import field_manifest as manifest
from helpers import stored_results as stored


def single(run_cli, folder: Path, command: str, unit: str, card: str):
    """The single-card command's JSON summary (``--what summary``: the same summary without the
    columns, tests/test_cli.py), or its error message."""
    argv = [command, unit, "--card", str(folder / card), "-f", "json", "--what", "summary"] + (
        ["--steps", "4"] if command == "torque" else [])
    code, out, err = run_cli(*argv)
    if code:
        return err.removeprefix("pumpjack: error: ").strip()
    return json.loads(out)["summary"]


@pytest.mark.parametrize("part", range(4))
def test_batch_results_equal_the_single_commands(run_cli, tmp_path, part):
    """200 cards in four parts: every stored number equals the single command's `-f json`
    summary to 1e-12 relative (the batch solves the dampings of a unit's cards together, each
    card's iterates its own), every error the single command's message."""
    rows = field(tmp_path, 50, seed=10 + part, start=50 * part)
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", manifest(tmp_path, rows), "--store", store, "--workers", "1")
    assert code == 0, err
    results = stored(store)
    assert len(results) == 2 * len(rows)
    compared = 0
    for _, unit, card, _ in rows:
        for command in ("torque", "downhole"):
            row, expected = results[(card, command)], single(run_cli, tmp_path, command, unit, card)
            if isinstance(expected, str):
                assert row["status"] == "error" and row["error"] == expected
                continue
            assert row["status"] == "ok", row["error"]
            compared += assert_same_summary(row, expected, 1e-12, 1e-12, card, command)
    assert compared > 2000


def test_rerun_skips_what_is_done_and_adds_what_is_new(run_cli, tmp_path):
    rows = field(tmp_path, 6)
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", manifest(tmp_path, rows[:4]), "--store", store, "--workers", "1")[0] == 0
    first = stored(store)
    code, out, _ = run_cli("batch", manifest(tmp_path, rows), "--store", store, "--workers", "1")
    assert code == 0 and "6 cards: 2 analysed, 4 already in" in out
    again = stored(store)
    assert len(again) == 12 and all(again[key] == first[key] for key in first)
    code, out, _ = run_cli("batch", manifest(tmp_path, rows), "--store", store, "--workers", "1")
    assert "0 analysed, 6 already in" in out and stored(store) == again
    code, out, _ = run_cli("batch", manifest(tmp_path, rows), "--store", store, "--workers", "1", "--balance",
                           "min-rms")
    assert "6 analysed" in out  # other options: other results, the old ones kept
    assert len(stored(store)) == 12 and len(sqlite3.connect(store).execute("SELECT * FROM results").fetchall()) == 18


def test_bad_cards_and_units_become_error_rows_with_the_single_commands_message(run_cli, tmp_path):
    rows = field(tmp_path, 4)
    (tmp_path / "broken.csv").write_text("when,where,what\n1,2,3\n")
    (tmp_path / "binary.csv").write_bytes(bytes(range(256)))
    os.mkfifo(tmp_path / "pipe.csv")   # no writer: hashing it for the run's key once waited for ever
    bad = [("bad-1", "c-80d-133-48", "broken.csv", ""), ("bad-2", "c-80d-133-48", "missing.csv", ""),
           ("bad-3", "no-such-unit", rows[0][2], ""), ("bad-4", "unb-600a", rows[0][2], ""),
           ("bad-5", "sk8-3.5-4000", "binary.csv", ""), ("bad-6", "sk8-3.5-4000", "pipe.csv", "")]
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", manifest(tmp_path, rows[:2] + bad + rows[2:]), "--store", store, "--workers",
                             "2")
    assert code == 0, err
    db = sqlite3.connect(store)
    for well, _, card, _ in rows:
        statuses = db.execute("SELECT status FROM results WHERE well = ? AND card LIKE ?", (well, f"%{card}")).fetchall()
        assert statuses == [("ok",), ("ok",)]
    for well, unit, card, _ in bad:
        for analysis in ("torque", "downhole"):
            status, error = db.execute("SELECT status, error FROM results WHERE well = ? AND analysis = ?",
                                       (well, analysis)).fetchone()
            assert status == "error" and error == single(run_cli, tmp_path, analysis, unit, card)


def test_export_and_trend(run_cli, tmp_path):
    rows = field(tmp_path, 10)
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", manifest(tmp_path, rows), "--store", store, "--workers", "1")[0] == 0
    code, out, err = run_cli("batch", "export", "--store", store, "-f", "csv", "--analysis", "torque")
    assert code == 0, err
    exported = list(csv.DictReader(io.StringIO(out)))
    assert len(exported) == 10 and {row["analysis"] for row in exported} == {"torque"}
    results = stored(store)
    for row in exported:
        assert float(row["peak_net_torque_n_m"]) == results[(Path(row["card"]).name, "torque")]["peak_net_torque_n_m"]
    code, out, err = run_cli("batch", "trend", "--store", store, "--well", "well-1", "-f", "json")
    assert code == 0, err
    trend = json.loads(out)["series"]
    assert trend["timestamp"] == sorted(trend["timestamp"]) and len(trend["timestamp"]) == 2
    for card, torque in zip(trend["card"], trend["peak_net_torque_n_m"]):
        assert torque == results[(Path(card).name, "torque")]["peak_net_torque_n_m"]
    code, out, err = run_cli("batch", "trend", "--store", store, "--well", "no-such-well")
    assert code == 2 and "no-such-well" in err
    for argv, fragment in ((("--analysis", "torgue"), "--analysis torgue: use one of torque, downhole"),
                           (("--well", "no-such-well"), "--well no-such-well: no results for this well"),
                           (("--well", "no-such-well", "--analysis", "downhole"), "no downhole results for this well")):
        code, out, err = run_cli("batch", "export", "--store", store, *argv)
        assert (code, out) == (2, "") and fragment in err and err.count("\n") == 1, err


@pytest.mark.parametrize("content, fragment", [
    ("well,unit\nw,sk8-3.5-4000\n", "needs the columns well, unit, card"),
    ("well,unit,card,colour\nw,sk8-3.5-4000,x.csv,red\n", "unknown column 'colour'"),
    ("well,unit,card,spm\nw,sk8-3.5-4000,x.csv,fast\n", "line 2: spm"),
    ("well,unit,card\nw,sk8-3.5-4000\n", "line 2: 2 cells for 3 columns"),
    ("well,unit,card\n,sk8-3.5-4000,x.csv\n", "line 2: well is empty"),
    ("well,unit,card,counterbalance_moment\nw,sk8-3.5-4000,x.csv,95000\n", "has no unit"),
    ("well,unit,card\nw,sk8-3.5-4000,nothing-*.csv\n", "no file matches"),
    ("well,unit,card\n", "names no card"),
    ("[[cards]]\nwell = 'w'\n", "unit is empty"),
    ("well,unit,card\nw,sk8-3.5-4000," + "x" * 200_000 + "\n", "line 2: not a CSV row: field larger than field limit"),
    ('well,unit,card\n"W\n17",sk8-3.5-4000,x.csv\n,sk8-3.5-4000,x.csv\n', "line 4: well is empty"),
    ("# field W\n\n[[cards]]\nwell = 'w'\nunit = 'sk8-3.5-4000'\ncard = 'x.csv'\n\n[[cards]]\nunit = 'u'\n",
     "line 8: well is empty"),
    ("[[cards]]\nwell = 'w'\nunit = 'sk8-3.5-4000'\ncard = 'x.csv'\nrod_string = 5\n",
     "line 1: rod_string: 5 is not a file name"),
    ("[[cards]]\nwell = 5\nunit = 'sk8-3.5-4000'\ncard = 'x.csv'\n", "line 1: well: 5 is not text"),
    ("[[cards]]\nwell = 'w'\nunit = 'sk8-3.5-4000'\ncard = ['x.csv']\n", "line 1: card: ['x.csv'] is not text"),
    ("[[cards]]\nwell = 'w'\nunit = 'sk8-3.5-4000'\ncard = 'x.csv'\nspm = true\n", "line 1: spm: true is not a number"),
    ("[[cards]]\nwell = 'w'\nunit = 'sk8-3.5-4000'\ncard = 'x.csv'\nspm = nan\n", "line 1: spm: nan is outside"),
    ("well,unit,card,counterbalance_moment\nw,sk8-3.5-4000,x.csv,1e300 N*m\n",
     "line 2: counterbalance_moment: Input should be less than or equal to 10000000 N·m"),
    ("well,unit,card,counterbalance_moment\nw,sk8-3.5-4000,x.csv,-5 kN*m\n",
     "line 2: counterbalance_moment: Input should be greater than or equal to 0 N·m"),
])
def test_broken_manifests_are_refused_with_one_line(run_cli, tmp_path, content, fragment):
    """Refused before anything runs, naming the line where the row starts in the file (a
    quoted cell may span lines; a TOML table's header line) and the field."""
    path = tmp_path / ("m.toml" if "[[cards]]" in content else "m.csv")
    path.write_text(content)
    code, out, err = run_cli("batch", path, "--store", tmp_path / "r.sqlite")
    assert code == 2 and out == "", err
    assert err.startswith("pumpjack: error: ") and err.count("\n") == 1 and fragment in err, err
    assert not (tmp_path / "r.sqlite").exists()


def test_a_card_path_with_glob_characters_that_names_a_file_is_that_file(tmp_path):
    """`W[1].csv` is that file even though, as a pattern, it would match `W1.csv`; a
    pattern that names no file is a pattern."""
    from pumpjack_cli.readers.manifest import read_manifest

    for name in ("W[1].csv", "W1.csv"):
        (tmp_path / name).write_text("time,position,load\n")
    for card, found in (("W[1].csv", ["W[1].csv"]), ("W[0-9].csv", ["W1.csv"]), ("W*.csv", ["W1.csv", "W[1].csv"])):
        jobs = read_manifest(manifest(tmp_path, [("w", "sk8-3.5-4000", card, "")]))
        assert [Path(job.card).name for job in jobs] == found


def test_manifest_files_that_are_not_manifests(run_cli, tmp_path):
    (tmp_path / "b.csv").write_bytes(bytes(range(256)))
    for target, fragment in ((tmp_path, "directory"), (tmp_path / "none.csv", "no such file"),
                             (tmp_path / "b.csv", "NUL")):
        code, out, err = run_cli("batch", target, "--store", tmp_path / "r.sqlite")
        assert code == 2 and err.count("\n") == 1 and fragment in err, err


def test_a_store_that_is_not_a_store(run_cli, tmp_path):
    rows = field(tmp_path, 1)
    (tmp_path / "s.sqlite").write_text("not a database")
    code, out, err = run_cli("batch", manifest(tmp_path, rows), "--store", tmp_path / "s.sqlite")
    assert code == 2 and "not a results store" in err
    code, out, err = run_cli("batch", "export", "--store", tmp_path / "none.sqlite")
    assert code == 2 and "no such results store" in err


@pytest.mark.parametrize("argv, fragment", [
    (("--method", "fancy"), "--method fancy"),
    (("--balance", "level"), "--balance level"),
    (("--analyses", "torque,bogus"), "unknown analysis 'bogus'"),
    (("--analyses", ","), "--analyses"),
    (("--store", "{tmp}/missing/r.sqlite"), "directory {tmp}/missing does not exist"),
    (("--workers", "0"), "--workers"),
    (("--damping", "nan"), "--damping"),
])
def test_bad_batch_options_are_refused_before_anything_runs(run_cli, tmp_path, argv, fragment):
    """{tmp} is this test's temporary folder: a store in a folder that is surely missing."""
    rows = field(tmp_path, 1)
    argv, fragment = [arg.format(tmp=tmp_path) for arg in argv], fragment.format(tmp=tmp_path)
    extra = () if "--store" in argv else ("--store", tmp_path / "r.sqlite")
    code, out, err = run_cli("batch", manifest(tmp_path, rows), *extra, *argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and fragment in err, err
    assert not (tmp_path / "r.sqlite").exists() and not (tmp_path / "missing").exists()


def test_an_internal_fault_on_one_card_is_an_error_row_not_a_stop(run_cli, tmp_path, monkeypatch):
    """A bug that raises on one card (simulated) is recorded as that card's error; the others run."""
    from pumpjack_cli.analysis.batch import per_card

    rows = field(tmp_path, 3)
    real = per_card._PlacedOnce.read

    def faulty(self, unit, spm):
        if self.name == rows[1][2]:
            raise ZeroDivisionError("simulated")
        return real(self, unit, spm)

    monkeypatch.setattr(per_card._PlacedOnce, "read", faulty)
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", manifest(tmp_path, rows), "--store", store, "--workers", "1")
    assert code == 0, err
    statuses = dict(sqlite3.connect(store).execute("SELECT card || analysis, status || error FROM results"))
    assert sum(v.startswith("error") for v in statuses.values()) == 2
    assert all("ZeroDivisionError: simulated" in v for v in statuses.values() if v.startswith("error"))


def test_cards_whose_header_names_no_unit_need_card_units(run_cli, tmp_path):
    """A card with a bare 'time,position,load' header (loads in N) is an error row naming
    the column, as the single command prints it; with --card-units si the same card gives
    the results of its kN twin (a different store, the options differ)."""
    rows = field(tmp_path, 1)
    named = tmp_path / rows[0][2]
    lines = named.read_text().splitlines()
    bare = tmp_path / "bare.csv"
    bare.write_text("time,position,load\n" + "".join(
        f"{t},{s},{float(w) * 1e3!r}\n" for t, s, w in (line.split(",") for line in lines[1:])))
    table = manifest(tmp_path, [("well-b", rows[0][1], "bare.csv", rows[0][3])])
    code, _, err = run_cli("batch", "run", table, "--store", tmp_path / "refused.sqlite", "--workers", "1")
    assert code == 0, err
    refused = stored(tmp_path / "refused.sqlite")
    for analysis in ("torque", "downhole"):
        assert refused[("bare.csv", analysis)]["status"] == "error"
        assert refused[("bare.csv", analysis)]["error"] == single(run_cli, tmp_path, analysis, rows[0][1], "bare.csv")
        assert "column 1 'time' names no unit" in refused[("bare.csv", analysis)]["error"]
    both = manifest(tmp_path, [rows[0], ("well-b", rows[0][1], "bare.csv", rows[0][3])], "both.csv")
    code, _, err = run_cli("batch", "run", both, "--store", tmp_path / "si.sqlite", "--workers", "1",
                           "--card-units", "si")
    assert code == 0, err
    given = stored(tmp_path / "si.sqlite")
    for analysis in ("torque", "downhole"):
        a, b = given[("bare.csv", analysis)], given[(rows[0][2], analysis)]
        assert a["status"] == b["status"] == "ok"
        numbers = [name for name, value in b.items() if isinstance(value, float)]
        assert len(numbers) > 5
        assert all(math.isclose(a[name], b[name], rel_tol=1e-9, abs_tol=1e-9) for name in numbers)


def test_a_unit_named_with_the_gost_comma_is_keyed_by_the_bundled_files_content(tmp_path):
    """`SK8-3,5-4000` in a manifest (a quoted CSV cell) is the bundled sk8-3.5-4000 unit for
    its content key too, not an unreadable name whose key never changes."""
    import hashlib

    from pumpjack_cli.analysis.batch.keys import unit_digest
    from pumpjack_cli.readers.manifest import read_manifest

    rows = field(tmp_path, 1)
    jobs = read_manifest(manifest(tmp_path, [("well-g", '"SK8-3,5-4000"', rows[0][2], "")]))
    expected = hashlib.sha256((REPO_ROOT / "configs" / "sk8-3.5-4000.toml").read_bytes()).hexdigest()
    assert [unit_digest(job.unit) for job in jobs] == [expected]


def test_a_changed_unit_file_is_analysed_again(run_cli, tmp_path, monkeypatch):
    """A bundled unit named with the GOST comma whose file changes (a copy in the temporary
    folder stands for the bundled one): the re-run analyses the card again; unchanged, it
    skips it."""
    from pumpjack_cli.analysis.batch import per_card
    from pumpjack_cli.readers import unit_files

    copy = tmp_path / "units" / "sk8-3.5-4000.toml"
    copy.parent.mkdir()
    copy.write_bytes((REPO_ROOT / "configs" / "sk8-3.5-4000.toml").read_bytes())
    monkeypatch.setattr(unit_files, "bundled_units", lambda: {"sk8-3.5-4000": copy})
    monkeypatch.setattr(per_card, "_UNITS", {})
    rows = field(tmp_path, 1)
    path, store = manifest(tmp_path, [("well-g", '"SK8-3,5-4000"', rows[0][2], "")]), tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", path, "--store", store, "--workers", "1")
    assert code == 0 and "1 cards: 1 analysed, 0 already in" in out, err
    assert {row["status"] for row in stored(store).values()} == {"ok"}
    code, out, err = run_cli("batch", path, "--store", store, "--workers", "1")
    assert code == 0 and "1 cards: 0 analysed, 1 already in" in out, err
    copy.write_text(copy.read_text(encoding="utf-8") + "# revised\n", encoding="utf-8")
    code, out, err = run_cli("batch", path, "--store", store, "--workers", "1")
    assert code == 0 and "1 cards: 1 analysed, 0 already in" in out, err
    keys = sqlite3.connect(store).execute("SELECT analysis, options_sha256 FROM results").fetchall()
    assert len(keys) == 4 and len(set(keys)) == 4


def test_text_summary_values_are_stored_and_shown_as_text(run_cli, tmp_path):
    """A summary value that is text (a pump-condition label) gets a TEXT column, keeps its
    text even when it looks like a number, and export and trend show it as text."""
    from pumpjack_cli.analysis import store_views
    from pumpjack_cli.readers.store import Store

    path = tmp_path / "r.sqlite"
    store = Store(path, write=True)
    for number, (label, fillage) in enumerate((("full pump", 97.5), ("100", 41.0))):
        store.add_cards([[{"well": "W-1", "card": f"c{number}.csv", "card_sha256": f"{number}", "unit": "sk8-3.5-4000",
                           "timestamp": f"2026-11-2{number}", "analysis": "downhole", "options_sha256": "o",
                           "options": "{}",
                           "status": "ok", "error": "", "warnings": "",
                           "summary": {"pump_condition": label, "pump_fillage_percent": fillage}}]])
    store.close()
    db = sqlite3.connect(path)
    declared = {row[1]: row[2] for row in db.execute("PRAGMA table_info(results)")}
    assert (declared["pump_condition"], declared["pump_fillage_percent"]) == ("TEXT", "REAL")
    assert db.execute("SELECT typeof(pump_condition), typeof(pump_fillage_percent) FROM results").fetchall() == [
        ("text", "real"), ("text", "real")]
    code, out, err = run_cli("batch", "export", "--store", path, "-f", "json")
    assert code == 0, err
    series = json.loads(out)["series"]
    assert series["pump_condition"] == ["full pump", "100"] and series["pump_fillage_percent"] == [97.5, 41.0]
    code, out, err = run_cli("batch", "export", "--store", path, "-f", "csv")
    assert code == 0, err
    assert [row["pump_condition"] for row in csv.DictReader(io.StringIO(out))] == ["full pump", "100"]
    assert ("pump_condition", "downhole") in store_views.TREND   # the trend shows the label card by card
    code, out, err = run_cli("batch", "trend", "--store", path, "--well", "W-1", "-f", "json")
    assert code == 0, err
    trend = json.loads(out)
    assert trend["series"]["pump_condition"] == ["full pump", "100"]
    code, out, err = run_cli("batch", "trend", "--store", path, "--well", "W-1")
    assert code == 0 and "full pump" in out, err


def test_trend_shows_the_results_of_every_option_set(run_cli, tmp_path):
    """An `--method api` run and an `--method exact` run into one store: trend shows each
    card's results of both, labelled by the option that differs, with the downhole results
    (the same options in both runs) beside each; a unit without masses shows its exact
    error beside its API numbers, not over them."""
    rows = field(tmp_path, 4)
    chosen = [rows[0], rows[3]]  # sk8-3.5-4000 with [masses], c-80d-133-48 without
    path, store = manifest(tmp_path, chosen), tmp_path / "r.sqlite"
    for method in ("api", "exact"):
        assert run_cli("batch", path, "--store", store, "--workers", "1", "--method", method)[0] == 0
    db = sqlite3.connect(store)
    for (well, unit, card, _), exact in zip(chosen, ("ok", "error")):
        api, downhole = (db.execute("SELECT peak_net_torque_n_m, pump_fillage_percent FROM results WHERE well = ? "
                                    "AND analysis = ? ORDER BY id", (well, analysis)).fetchone()[i]
                         for i, analysis in ((0, "torque"), (1, "downhole")))
        code, out, err = run_cli("batch", "trend", "--store", store, "--well", well, "-f", "json")
        assert code == 0, err
        document = json.loads(out)
        series = document["series"]
        assert series["options"] == ["--method api", "--method exact"]
        assert series["torque_status"] == ["ok", exact] and series["downhole_status"] == ["ok", "ok"]
        assert series["peak_net_torque_n_m"][0] == api and series["pump_fillage_percent"] == [downhole, downhole]
        assert (series["peak_net_torque_n_m"][1] is None) == (exact == "error")
        assert "a row per option set" in document["title"]
        code, out, err = run_cli("batch", "trend", "--store", store, "--well", well)
        assert code == 0 and "--method exact" in out, err


def test_export_and_trend_in_field_units(run_cli, tmp_path):
    """--units field: every stored number converted, under the suffix of the single commands'
    field output (lbf·in, lbf, in, hp, ft·lbf, bbl/d, psi), and no SI suffix left."""
    from helpers import BARREL, FOOT, HORSEPOWER, INCH, POUND_FORCE, PSI

    rows = field(tmp_path, 1)
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", manifest(tmp_path, rows), "--store", store, "--workers", "1")[0] == 0
    documents = {}
    for units in ("si", "field"):
        code, out, err = run_cli("batch", "export", "--store", store, "--units", units, "-f", "json")
        assert code == 0, err
        documents[units] = {name: [v for v in values if v is not None] for name, values in
                            json.loads(out)["series"].items()}
    si, fld = documents["si"], documents["field"]
    expected = {"peak_net_torque_n_m": ("peak_net_torque_lbf_in", 1 / (POUND_FORCE * INCH)),
                "max_rod_load_n": ("max_rod_load_lbf", 1 / POUND_FORCE),
                "net_pump_stroke_m": ("net_pump_stroke_in", 1 / INCH),
                "polished_rod_power_w": ("polished_rod_power_hp", 1 / HORSEPOWER),
                "surface_card_work_j": ("surface_card_work_ft_lbf", 1 / (POUND_FORCE * FOOT)),
                "pump_displacement_m3_d": ("pump_displacement_bbl_d", 1 / BARREL),
                "pump_intake_pressure_pa": ("pump_intake_pressure_psi", 1 / PSI),
                "gearbox_loading_percent": ("gearbox_loading_percent", 1.0)}
    for name, (field_name, factor) in expected.items():
        assert fld[field_name] == pytest.approx([value * factor for value in si[name]], rel=1e-12), name
    assert len(fld) == len(si)
    si_only = ("_n", "_n_m", "_m", "_w", "_j", "_m3_d", "_pa", "_mpa", "_kg")
    assert not [name for name in fld if name.endswith(si_only)]
    code, out, err = run_cli("batch", "export", "--store", store, "--units", "field", "-f", "csv")
    assert code == 0 and list(csv.DictReader(io.StringIO(out)).fieldnames) == list(fld), err
    code, out, err = run_cli("batch", "trend", "--store", store, "--well", rows[0][0], "--units", "field", "-f",
                             "json")
    assert code == 0, err
    series = json.loads(out)["series"]
    assert series["peak_net_torque_lbf_in"] == fld["peak_net_torque_lbf_in"][:1]
    assert "pump_displacement_bbl_d" in series and "peak_net_torque_n_m" not in series


def test_a_rod_string_file_that_is_not_one_is_an_error_row_naming_its_key(run_cli, tmp_path):
    rows = field(tmp_path, 1)
    (tmp_path / "rods.toml").write_text("rod_string = 5\n", encoding="utf-8")
    path = tmp_path / "m.csv"
    path.write_text(f"well,unit,card,rod_string\n{rows[0][0]},{rows[0][1]},{rows[0][2]},rods.toml\n")
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", path, "--store", store)[0] == 0
    errors = {row["error"] for row in stored(store).values()}
    assert errors == {f"{tmp_path / 'rods.toml'}: rod_string: Input should be a valid tuple"}


def test_a_rows_counterbalance_moment_and_rod_string_are_the_units_own(run_cli, tmp_path):
    """A manifest row's counterbalance moment and rod string give the results of the single
    commands on the unit file edited the same way."""
    rows = field(tmp_path, 4)
    well, unit, card, _ = rows[3]  # c-80d-133-48: [counterbalance] with a moment, one taper of 3/4 in rods
    rods = tmp_path / "rods.toml"
    rods.write_text('rod_string = [{ diameter = "0.875 in", fraction = "100 %", grade = "D" }]\n')
    text = (REPO_ROOT / "configs" / f"{unit}.toml").read_text(encoding="utf-8")
    edited = tmp_path / "edited.toml"
    edited.write_text(text.replace('moment = "130000 lbf*in"', 'moment = "95 kN*m"').replace(
        'diameter = "0.75 in"', 'diameter = "0.875 in"'), encoding="utf-8")
    path = tmp_path / "overrides.csv"
    path.write_text(f"well,unit,card,counterbalance_moment,rod_string\n{well},{unit},{card},95 kN*m,rods.toml\n")
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", path, "--store", store, "--workers", "1")[0] == 0
    results = stored(store)
    for analysis in ("torque", "downhole"):
        row, expected = results[(card, analysis)], single(run_cli, tmp_path, analysis, str(edited), card)
        assert row["status"] == "ok", row["error"]
        assert_same_summary(row, expected, 1e-9, 1e-12, analysis)
    assert results[(card, "torque")]["counterbalance_moment_n_m"] == pytest.approx(95e3)


def test_a_subnormal_rating_is_an_error_row_naming_the_field(run_cli, tmp_path):
    rows = field(tmp_path, 4)
    well, unit, card, _ = rows[3]
    broken = tmp_path / "tiny-rating.toml"
    broken.write_text((REPO_ROOT / "configs" / f"{unit}.toml").read_text(encoding="utf-8")
                      + '\n[rating]\ngearbox_torque = "1e-320 N*m"\n', encoding="utf-8")
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", manifest(tmp_path, [(well, broken.name, card, "")]), "--store", store, "--workers",
                   "1", "--analyses", "torque")[0] == 0
    error = stored(store)[(card, "torque")]["error"]
    assert "rating.gearbox_torque: 1e-320 is too small" in error and "not finite" not in error


def test_the_options_keys_a_run_makes_once_are_those_made_for_each_row(tmp_path):
    """A run makes each distinct options key once (the cards of a well share theirs, and a
    rod-string or survey file is hashed once): the key a row reuses is the one made for it
    afresh, whichever field of the row differs, and rows that differ in a field of the key get
    different keys."""
    from dataclasses import replace

    from pumpjack_cli.analysis.batch.keys import options_key
    from pumpjack_cli.analysis.batch.per_card import Options
    from pumpjack_cli.readers.manifest import Job

    for name, text in (("rods-a.toml", "a"), ("rods-b.toml", "b"), ("survey-a.csv", "a"), ("survey-b.csv", "b")):
        (tmp_path / name).write_text(text)
    base = Job("W-1", "sk8-3.5-4000", "c.csv", 2)
    jobs = [base, replace(base, well="W-2", card="d.csv", line=3, timestamp="2026-11-25"), replace(base, spm=7.5),
            replace(base, counterbalance_moment=9e4), replace(base, rod_string=str(tmp_path / "rods-a.toml")),
            replace(base, rod_string=str(tmp_path / "rods-b.toml")), replace(base, survey=str(tmp_path / "survey-a.csv")),
            replace(base, survey=str(tmp_path / "survey-b.csv")), replace(base, runtime=0.75)]
    options, known = Options(), {}
    made = [options_key(job, analysis, options, unit, known) for unit in ("u1", "u2") for job in jobs * 2
            for analysis in options.analyses]
    assert made == [options_key(job, analysis, options, unit) for unit in ("u1", "u2") for job in jobs * 2
                    for analysis in options.analyses]
    assert len(known) == 2 * 2 * (len(jobs) - 1)  # the first two jobs differ in no field of the key
    assert len(set(made)) == len(known) - 2  # a runtime is downhole's alone: torque's key is the first job's
