"""The results store of `pumpjack batch` under faults: files that are not stores, stores of
another version, damaged or extended stores, read-only and full file systems.

A refused file is left byte for byte as it was; every refusal is one line. The read-only
and full file systems are real: a tmpfs or a read-only bind mount in a private mount
namespace (``unshare -rm``), skipped where the system does not allow one.
"""

from __future__ import annotations

import errno
import json
import os
import shutil
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest

from helpers import field_cards, field_manifest, one_line_error, stored_results

#: The layout of a store written by pumpjack-cli 0.3.0 (version 0: no options column, no application id).
VERSION_0 = """
CREATE TABLE results (id INTEGER PRIMARY KEY, well TEXT NOT NULL, card TEXT NOT NULL, card_sha256 TEXT NOT NULL,
    timestamp TEXT NOT NULL, unit TEXT NOT NULL, analysis TEXT NOT NULL, options_sha256 TEXT NOT NULL,
    status TEXT NOT NULL, error TEXT NOT NULL, warnings TEXT NOT NULL,
    UNIQUE (well, card_sha256, analysis, options_sha256));
CREATE INDEX results_well ON results (well, timestamp, card);
"""


def _row(number: int, **fields) -> dict:
    """A stored row of card ``number`` (fixed fields and one summary value)."""
    return {"well": "W-1", "card": f"c{number}.csv", "card_sha256": f"{number:064x}", "timestamp": f"t{number:04d}",
            "unit": "u", "analysis": "torque", "options_sha256": "o" * 64, "options": "{}", "status": "ok",
            "error": "", "warnings": "", "summary": {"peak_net_torque_n_m": 1000.0 + number}, **fields}


def _store(path: Path, cards: int) -> Path:
    """A store of ``cards`` rows written through the store itself."""
    from pumpjack_cli.readers.store import Store

    store = Store(path, write=True)
    store.add_cards([[_row(number)] for number in range(cards)])
    store.close()
    return path


def _listing(folder: Path) -> dict[str, bytes]:
    return {path.name: path.read_bytes() for path in folder.iterdir() if path.is_file()}


def _foreign(path: Path, application_id: int = 0) -> None:
    """Another application's SQLite database (rollback journal), with or without an application id."""
    db = sqlite3.connect(path)
    db.executescript("CREATE TABLE customers (name TEXT); INSERT INTO customers VALUES ('ACME');"
                     f"PRAGMA application_id = {application_id};")
    db.close()


def _later(path: Path) -> None:
    _store(path, 1)
    db = sqlite3.connect(path)
    db.execute("PRAGMA user_version = 2")
    db.close()
    for suffix in ("-wal", "-shm"):
        Path(f"{path}{suffix}").unlink(missing_ok=True)


REFUSED = {
    "empty": (lambda path: path.write_bytes(b""), "is an empty file, not a results store"),
    "text": (lambda path: path.write_text("well,card\nW,c.csv\n"), "not an SQLite database"),
    "foreign": (_foreign, "an SQLite database without a results table"),
    "foreign-application": (lambda path: _foreign(path, 0x46524F47), "another application's SQLite database"),
    "later-version": (_later, "a results store of version 2, written by a later pumpjack-cli"),
}


@pytest.mark.parametrize("case", REFUSED)
def test_a_file_that_is_not_a_store_of_this_version_is_refused_and_left_as_it_was(run_cli, tmp_path, case):
    """Neither a run, nor export, nor trend changes a byte of it or adds a file beside it
    (no WAL journal switched on, no table added to another application's database); a
    store of a later version is refused instead of storing nothing while printing results."""
    make, fragment = REFUSED[case]
    rows = field_cards(tmp_path, 1)
    path = field_manifest(tmp_path, rows)
    store = tmp_path / "s.sqlite"
    make(store)
    before = _listing(tmp_path)
    for argv in (("batch", path, "--store", store, "--workers", "1"), ("batch", "export", "--store", store),
                 ("batch", "trend", "--store", store, "--well", rows[0][0])):
        one_line_error(*run_cli(*argv), f"--store {store}: ", fragment)
        assert _listing(tmp_path) == before


def test_a_new_store_carries_its_version_and_mark(run_cli, tmp_path):
    from pumpjack_cli.readers.store import APPLICATION_ID, VERSION

    rows = field_cards(tmp_path, 1)
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", field_manifest(tmp_path, rows), "--store", store, "--workers", "1")[0] == 0
    db = sqlite3.connect(store)
    assert [db.execute(f"PRAGMA {name}").fetchone()[0] for name in ("user_version", "application_id")] == [
        VERSION, APPLICATION_ID]
    db.close()
    assert sorted(path.name for path in tmp_path.iterdir() if path.name.startswith((".r.sqlite", "r.sqlite"))) == [
        "r.sqlite"]  # the temporary file it was built in is gone; the journal files go with the last connection


def test_a_store_of_version_0_is_read_as_it_is_and_upgraded_by_a_run(run_cli, tmp_path):
    """A store written before the version mark: export reads it without changing it; a run
    brings it to the current version and keeps its rows; trend labels the old result,
    whose options are unknown, by its hash."""
    rows = field_cards(tmp_path, 1)
    path = field_manifest(tmp_path, rows)
    store = tmp_path / "old.sqlite"
    assert run_cli("batch", path, "--store", tmp_path / "new.sqlite", "--workers", "1", "--analyses", "torque")[0] == 0
    new = stored_results(tmp_path / "new.sqlite")[(rows[0][2], "torque")]
    db = sqlite3.connect(store)
    db.executescript(VERSION_0)
    db.execute("ALTER TABLE results ADD COLUMN peak_net_torque_n_m REAL")
    db.execute("INSERT INTO results (well, card, card_sha256, timestamp, unit, analysis, options_sha256, status, "
               "error, warnings, peak_net_torque_n_m) VALUES (?, ?, ?, ?, ?, 'torque', ?, 'ok', '', '', 1.0)",
               [new[name] for name in ("well", "card", "card_sha256", "timestamp", "unit")] + ["f" * 64])
    db.commit()
    db.close()
    before = store.read_bytes()
    code, out, err = run_cli("batch", "export", "--store", store, "-f", "json")
    assert code == 0 and json.loads(out)["series"]["peak_net_torque_n_m"] == [1.0], err
    assert store.read_bytes() == before
    code, out, err = run_cli("batch", path, "--store", store, "--workers", "1", "--analyses", "torque")
    assert code == 0 and "1 analysed" in out, err
    db = sqlite3.connect(store)
    assert db.execute("PRAGMA user_version").fetchone()[0] == 1
    assert db.execute("SELECT options, peak_net_torque_n_m FROM results ORDER BY id").fetchall() == [
        ("", 1.0), (new["options"], new["peak_net_torque_n_m"])]
    db.close()
    code, out, err = run_cli("batch", "trend", "--store", store, "--well", rows[0][0], "-f", "json")
    assert code == 0, err
    labels = json.loads(out)["series"]["options"]
    assert labels[0].startswith("options ffffffffffff") and "--method api" in labels[1], labels


def _damage(path: Path) -> None:
    """Overwrite the middle pages of a store (its table's leaves and index pages) with garbage."""
    size = path.stat().st_size
    with open(path, "r+b") as handle:
        handle.seek(size // 3)
        handle.write(bytes(range(256)) * (size // 3 // 256))


def test_a_damaged_store_is_refused_after_its_integrity_check(run_cli, tmp_path):
    rows = field_cards(tmp_path, 1)
    store = _store(tmp_path / "r.sqlite", 300)
    _damage(store)
    before = store.read_bytes()
    for argv in (("batch", field_manifest(tmp_path, rows), "--store", store, "--workers", "1"),
                 ("batch", "export", "--store", store), ("batch", "trend", "--store", store, "--well", "W-1")):
        code, out, err = run_cli(*argv)
        one_line_error(code, out, err, f"--store {store}: ")
        assert "damaged" in err, err
        assert store.read_bytes() == before


@pytest.mark.parametrize("column, value, fragment", [
    ("note BLOB", b"\x00\xff", "column note (BLOB) is not one pumpjack-cli writes"),
    ("remark REAL", "see the log", "column remark holds str where a number belongs"),
    ("Shift TEXT", "night", "column Shift (TEXT) is not one pumpjack-cli writes"),
])
def test_a_store_with_a_column_of_another_kind_is_one_line(run_cli, tmp_path, column, value, fragment):
    """A column someone added by hand: a text summary column is a column like another,
    anything else is refused (not a traceback from the renderer)."""
    store = _store(tmp_path / "r.sqlite", 2)
    db = sqlite3.connect(store)
    db.execute(f"ALTER TABLE results ADD COLUMN {column}")
    db.execute(f"UPDATE results SET {column.split()[0]} = ?", (value,))
    db.commit()
    db.close()
    for argv in (("export", "--store", store, "-f", "json"), ("trend", "--store", store, "--well", "W-1")):
        one_line_error(*run_cli("batch", *argv), fragment)


def test_a_fifo_or_a_device_as_store_leaves_nothing_behind(run_cli, tmp_path):
    """A FIFO (opening it would wait for a writer) and a link to /dev/null are refused before
    SQLite touches them: no journal beside them, nothing written through them."""
    rows = field_cards(tmp_path, 1)
    path = field_manifest(tmp_path, rows)
    os.mkfifo(tmp_path / "fifo.sqlite")
    (tmp_path / "null.sqlite").symlink_to(os.devnull)
    before = sorted(tmp_path.iterdir())
    for store, kind in ((tmp_path / "fifo.sqlite", "a FIFO (named pipe)"), (tmp_path / "null.sqlite", "a device")):
        for argv in (("batch", path, "--store", store, "--workers", "1"), ("batch", "export", "--store", store)):
            one_line_error(*run_cli(*argv), f"--store {store}: is {kind}, not a results store")
        assert sorted(tmp_path.iterdir()) == before
    assert os.path.samefile(tmp_path / "null.sqlite", os.devnull)


def test_the_results_stored_are_counted_as_stored(run_cli, tmp_path, monkeypatch):
    """A card that another run stored between this run's look at the store and its write is
    not stored twice, and the line says so instead of counting it as stored."""
    from pumpjack_cli.readers.store import Store

    rows = field_cards(tmp_path, 1)
    path, store = field_manifest(tmp_path, rows), tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", path, "--store", store, "--workers", "1")
    assert code == 0 and "stored 2 results ok, 0 errors;" in out, err
    monkeypatch.setattr(Store, "done", lambda self: set())  # as if the other run stored them after the look
    code, out, err = run_cli("batch", path, "--store", store, "--workers", "1")
    assert code == 0 and "1 analysed" in out and "stored 0 results ok, 0 errors (2 stored first by another run)" \
        in out, err
    assert len(stored_results(store)) == 2


def _transactions(store) -> list[str]:
    """The statements that begin a transaction on the store's connection, as they run."""
    begun: list[str] = []
    store.db.set_trace_callback(lambda statement: begun.append(statement) if statement.startswith("BEGIN") else None)
    return begun


def test_the_cards_of_a_task_are_stored_in_one_transaction_each_card_once(tmp_path):
    """Many cards in one transaction; a card's row stored before (by another run) is not
    stored again and is missing from that card's statuses, the other cards' rows are stored."""
    from pumpjack_cli.readers.store import Store

    store = Store(_store(tmp_path / "r.sqlite", 2), write=True)
    begun = _transactions(store)
    cards = [[_row(number), _row(number, analysis="downhole", status="error", error="no", summary={})]
             for number in range(5)]
    assert store.add_cards(cards) == [["error"], ["error"], ["ok", "error"], ["ok", "error"], ["ok", "error"]]
    assert begun == ["BEGIN IMMEDIATE"]
    assert store.add_cards(cards) == [[]] * 5
    store.close()
    stored = sqlite3.connect(tmp_path / "r.sqlite").execute(
        "SELECT card, analysis, COUNT(*) FROM results GROUP BY card, analysis").fetchall()
    assert stored == [(f"c{n}.csv", analysis, 1) for n in range(5) for analysis in ("downhole", "torque")]


@pytest.mark.parametrize("broken, fragment", [
    ({"warnings": ["a list"]}, "r.sqlite: cannot write: "),  # SQLite refuses the value (as it would a full disk)
    ({"summary": {"Bad name": 1.0}}, "cannot store a result named 'Bad name'"),
])
def test_a_task_whose_transaction_fails_leaves_none_of_its_cards(tmp_path, broken, fragment):
    """A row that cannot be stored in the task's last card: one line, and none of the task's
    cards is stored, not even the column an earlier card of the task added; the store takes
    the same cards afterwards."""
    from pumpjack_cli.errors import PumpjackError
    from pumpjack_cli.readers.store import Store

    path = _store(tmp_path / "r.sqlite", 1)
    store = Store(path, write=True)
    cards = [[_row(1, summary={"new_value": 1.0})], [_row(2)], [_row(3, **broken)]]
    with pytest.raises(PumpjackError) as refused:
        store.add_cards(cards)
    message = str(refused.value)
    assert fragment in message and "\n" not in message
    assert list(stored_results(path)) == [("c0.csv", "torque")]
    assert "new_value" not in [row[1] for row in store.db.execute("PRAGMA table_info(results)")]
    assert store.add_cards(cards[:2]) == [["ok"], ["ok"]]
    store.close()
    assert stored_results(path)[("c1.csv", "torque")]["new_value"] == 1.0


def test_a_new_store_on_a_file_system_without_hard_links(run_cli, tmp_path, monkeypatch):
    """Where the new store cannot be linked into place (EPERM, as on FAT), it is renamed there."""
    def no_links(source, target):
        raise OSError(errno.EPERM, "Operation not permitted")

    monkeypatch.setattr(os, "link", no_links)
    rows = field_cards(tmp_path, 1)
    store = tmp_path / "r.sqlite"
    code, out, err = run_cli("batch", field_manifest(tmp_path, rows), "--store", store, "--workers", "1",
                             "--analyses", "torque")
    assert code == 0, err
    assert [row["status"] for row in stored_results(store).values()] == ["ok"]
    assert not [path for path in tmp_path.iterdir() if path.name.endswith(".new")]


def test_a_full_standard_output_after_the_run_is_one_line(tmp_path, capsys, monkeypatch):
    """`pumpjack batch ... > /dev/full`: the results are stored, the line that cannot be
    printed is one error line."""
    from pumpjack_cli.cli import main

    rows = field_cards(tmp_path, 1)
    store = tmp_path / "r.sqlite"
    with open("/dev/full", "w") as full:
        monkeypatch.setattr(sys, "stdout", full)
        code = main(["batch", str(field_manifest(tmp_path, rows)), "--store", str(store), "--workers", "1"])
    err = capsys.readouterr().err
    one_line_error(code, "", err, "standard output: cannot write: no space left on device", "results are stored")
    assert len(stored_results(store)) == 2


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads and writes whatever the permissions say")
def test_permissions_are_named(run_cli, tmp_path):
    """An unreadable store, and a directory this user may not write: named; export still
    reads the store there."""
    rows = field_cards(tmp_path, 1)
    (tmp_path / "box").mkdir()
    store = _store(tmp_path / "box" / "r.sqlite", 1)
    store.chmod(0o000)
    try:
        one_line_error(*run_cli("batch", "export", "--store", store), "is not readable")
    finally:
        store.chmod(0o644)
    store.parent.chmod(0o555)
    try:
        one_line_error(*run_cli("batch", field_manifest(tmp_path, rows), "--store", store, "--workers", "1"),
                       f"cannot write: directory {store.parent} is not writable")
        code, out, err = run_cli("batch", "export", "--store", store, "-f", "csv")
        assert code == 0 and "c0.csv" in out, err  # read where SQLite cannot make its journal's files
    finally:
        store.parent.chmod(0o755)


# --- real file systems: read-only, full ---------------------------------------------------

def _namespace(script: str, cwd: Path, pumpjack: str) -> None:
    """Run a shell script (``$1``: the console script ``pumpjack``) as root of a private user and
    mount namespace, whose mounts end with it; skip where the system allows none."""
    unshare = shutil.which("unshare")
    if unshare is None or subprocess.run([unshare, "-rm", "true"], capture_output=True).returncode != 0:
        pytest.skip("no private mount namespace (unshare -rm) on this system")
    done = subprocess.run([unshare, "-rm", "sh", "-c", script, "sh", pumpjack], cwd=cwd, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr


def _outcome(folder: Path, name: str) -> tuple[int, str, str]:
    return (int((folder / f"{name}.rc").read_text()), (folder / f"{name}.out").read_text(),
            (folder / f"{name}.err").read_text())


def _run(name: str, command: str) -> str:
    return f'"$1" {command} > {name}.out 2> {name}.err; echo $? > {name}.rc\n'


def test_a_store_on_a_read_only_file_system(run_cli, tmp_path, pumpjack_script):
    """Export and trend read a store in a read-only directory (SQLite cannot make its WAL
    journal's shared-memory file there); a run with nothing new to store succeeds without
    writing; a run with cards to store is refused naming the read-only file system."""
    rows = field_cards(tmp_path, 2)
    (tmp_path / "ro").mkdir()
    done, more = field_manifest(tmp_path, rows[:1]), field_manifest(tmp_path, rows, "more.csv")
    assert run_cli("batch", done, "--store", tmp_path / "ro" / "r.sqlite", "--workers", "1")[0] == 0
    before = _listing(tmp_path / "ro")
    _namespace("mount --bind ro ro && mount -o remount,ro,bind ro || exit 1\n"
               + _run("export", "batch export --store ro/r.sqlite -f csv")
               + _run("trend", f"batch trend --store ro/r.sqlite --well {rows[0][0]} -f csv")
               + _run("done", f"batch {done.name} --store ro/r.sqlite --workers 1")
               + _run("more", f"batch {more.name} --store ro/r.sqlite --workers 1"), tmp_path, pumpjack_script)
    for name in ("export", "trend"):
        code, out, err = _outcome(tmp_path, name)
        assert code == 0 and err == "" and rows[0][2] in out, err
    code, out, err = _outcome(tmp_path, "done")
    assert code == 0 and "0 analysed, 1 already in" in out, err
    one_line_error(*_outcome(tmp_path, "more"), "cannot write: read-only file system")
    assert _listing(tmp_path / "ro") == before


def test_a_full_disk_during_a_run_is_one_line(tmp_path, pumpjack_script):
    """A store on a 160 KiB tmpfs fills up: the run ends with one line naming the full
    device, not a traceback or "not a results store"."""
    rows = field_cards(tmp_path, 1)
    wells = [(f"W-{k}", *rows[0][1:]) for k in range(60)]  # one card, 60 wells: a row set per well
    path = field_manifest(tmp_path, wells)
    (tmp_path / "full").mkdir()
    _namespace("mount -t tmpfs -o size=160k tmpfs full || exit 1\n"
               + _run("full", f"batch {path.name} --store full/r.sqlite --workers 1 --analyses torque"), tmp_path,
               pumpjack_script)
    one_line_error(*_outcome(tmp_path, "full"), "full/r.sqlite: cannot write: no space left on device",
                   "every card stored before is kept")
