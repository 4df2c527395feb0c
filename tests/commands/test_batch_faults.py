"""The fleet of `pumpjack batch` under faults, with real processes: a run killed (SIGKILL)
or interrupted (SIGINT, SIGTERM), two runs on one fresh store, a Dask cluster whose worker
or scheduler is lost.

Each ends with whole cards in the store and no worker process left; each failure is one
line. The processes are found in the process table (/proc); the timeouts only guard a hang.
"""

from __future__ import annotations

import json
import os
import re
import signal
import sqlite3
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from helpers import (children_of, field_cards, field_manifest, gone, one_line_error, stored_count, stored_results,
                     wait_for_rows)


def _wells(folder: Path, cards: int, wells: int, name: str = "wells.csv") -> Path:
    """A manifest of ``wells`` wells sharing ``cards`` card files, after 32 wells whose card
    is missing: the first task stored holds error rows beside whole cards."""
    rows = field_cards(folder, cards)
    missing = [(f"M-{k:02d}", rows[0][1], f"missing-{k:02d}.csv", "") for k in range(32)]
    return field_manifest(folder, missing + [(f"W-{k:04d}", *rows[k % cards][1:]) for k in range(wells)], name)


def _whole_cards(store: Path) -> None:
    """Every card in the store has both analyses, once; the store passes its integrity check."""
    db = sqlite3.connect(store)
    counts = db.execute("SELECT COUNT(*) FROM results GROUP BY well, card_sha256").fetchall()
    assert counts and all(count == (2,) for count in counts)
    assert db.execute("PRAGMA quick_check").fetchall() == [("ok",)]
    db.close()


def test_kill_9_of_the_parent_leaves_whole_cards_and_no_worker(tmp_path, pumpjack_script):
    """SIGKILL in the middle of a run on two workers: the workers end with their parent (not
    adopted by init and left computing); the same command then finishes the rest, every
    card and analysis exactly once. The parent is stopped (SIGSTOP) between the look at its
    workers and the kill, so that the run cannot end in between, and the store is looked at
    every 20 ms: 480 wells on 24 card files (tasks of 60) keep the workers busy for a third of
    a second after the first rows even at a millisecond a card."""
    rows = field_cards(tmp_path, 24)
    path = field_manifest(tmp_path, [(f"W-{k:04d}", *rows[k % 24][1:]) for k in range(480)])
    store = tmp_path / "r.sqlite"
    process = subprocess.Popen([pumpjack_script, "batch", str(path), "--store", str(store), "--workers", "2"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    assert wait_for_rows(store, 2, process) >= 2
    os.kill(process.pid, signal.SIGSTOP)
    workers = children_of(process.pid)
    os.kill(process.pid, signal.SIGKILL)
    process.wait(timeout=60)
    assert len(workers) == 2 and gone(workers)
    assert 0 < stored_count(store) < 960
    _whole_cards(store)
    done = subprocess.run([pumpjack_script, "batch", str(path), "--store", str(store), "--workers", "2"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    counts = sqlite3.connect(store).execute("SELECT well, card, analysis, COUNT(*) FROM results "
                                            "GROUP BY well, card, analysis").fetchall()
    assert len(counts) == 960 and all(n == 1 for *_, n in counts)


#: How a run is stopped (a signal to the run, to its process group, or to one of its
#: workers) and the line it ends with.
STOPS = {
    "SIGINT": ("interrupted (SIGINT) after storing ", "run the same command again to go on"),
    "SIGTERM": ("interrupted (SIGTERM) after storing ", "run the same command again to go on"),
    "worker-killed": ("a worker process ended abruptly (killed, or out of memory)", "the cards stored so far are kept"),
}


@pytest.mark.parametrize("how", STOPS)
def test_a_stopped_run_ends_with_one_line_and_a_resumable_store(run_cli, tmp_path, pumpjack_script, how):
    """Ctrl-C (SIGINT to the whole process group), SIGTERM to the run, or one of its workers
    killed (as by the kernel when out of memory): one line, exit code 2, every worker gone,
    whole cards in the store, and the store goes on taking cards. 1000 wells (tasks of 129) keep
    the workers busy for a third of a second after the first rows even at a millisecond a card,
    and the store is looked at every 20 ms, so that the run is stopped before it ends."""
    path, store = _wells(tmp_path, 4, 1000), tmp_path / "r.sqlite"
    process = subprocess.Popen([pumpjack_script, "batch", str(path), "--store", str(store), "--workers", "2"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    assert wait_for_rows(store, 2, process) >= 2
    workers = children_of(process.pid)
    if how == "SIGINT":
        os.killpg(process.pid, signal.SIGINT)
    elif how == "SIGTERM":
        os.kill(process.pid, signal.SIGTERM)
    else:
        os.kill(workers[0], signal.SIGKILL)
    out, err = process.communicate(timeout=120)
    one_line_error(process.returncode, out, err, *STOPS[how])
    assert len(workers) == 2 and gone(workers)
    _whole_cards(store)
    first = field_manifest(tmp_path, [line.split(",") for line in path.read_text().splitlines()[1:41]], "first.csv")
    code, out, err = run_cli("batch", first, "--store", store, "--workers", "1")
    assert code == 0 and out.startswith("40 cards: "), err
    first_wells = "SELECT COUNT(*) FROM results WHERE well BETWEEN 'W-0000' AND 'W-0007'"
    assert sqlite3.connect(store).execute(first_wells).fetchone()[0] == 16
    _whole_cards(store)


def test_two_runs_on_one_fresh_store_both_finish(tmp_path, pumpjack_script):
    """Started together on a store that does not exist yet: both create it, add its columns
    and store their cards without a clash; each result is stored once, and the lines of the
    two runs count it once."""
    rows = field_cards(tmp_path, 6)
    path, store = field_manifest(tmp_path, rows), tmp_path / "r.sqlite"
    runs = [subprocess.Popen([pumpjack_script, "batch", str(path), "--store", str(store), "--workers", "1"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for _ in range(2)]
    outcomes = [run.communicate(timeout=300) for run in runs]
    assert [run.returncode for run in runs] == [0, 0], outcomes
    stored = [re.search(r"stored (\d+) results ok, (\d+) errors", out) for out, _ in outcomes]
    assert sum(int(found[1]) + int(found[2]) for found in stored) == 12, outcomes
    assert len(stored_results(store)) == 12 and stored_count(store) == 12
    _whole_cards(store)


# --- Dask -----------------------------------------------------------------------------------

def _guarded(run_cli, *argv):
    """``run_cli(*argv)`` in this process, interrupted after five minutes if it hangs (SIGINT,
    which the run turns into its one line): a guard, not a timing."""
    timer = threading.Timer(300, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        return run_cli(*argv)
    finally:
        timer.cancel()


def _kill_when(process: subprocess.Popen, ready) -> None:
    """Kill ``process`` in a thread of its own once ``ready()`` (a guard of two minutes against a hang)."""
    def kill() -> None:
        deadline = time.monotonic() + 120
        while not ready() and time.monotonic() < deadline:
            time.sleep(0.02)
        process.kill()

    threading.Thread(target=kill, daemon=True).start()


def test_a_dask_cluster_gives_the_local_results_and_its_losses_end_the_run_with_one_line(run_cli, tmp_path):
    """A real scheduler and worker process (`dask scheduler`, `dask worker`) on 127.0.0.1:
    the store equals the local pool's; the worker killed mid-run leaves the cluster without
    workers, and the run ends with one line after the stated 10 s; the scheduler killed
    while a run waits for it ends that run with one line at once; a scheduler that is not
    there creates no store. Dask's own log does not reach stderr."""
    distributed = pytest.importorskip("distributed")
    from pumpjack_cli.analysis.batch.executors import DASK_LOST

    dask = Path(sys.executable).parent / "dask"
    if not dask.is_file():
        pytest.skip("the dask command is not installed")
    rows = field_cards(tmp_path, 12)
    small, big = field_manifest(tmp_path, rows), _wells(tmp_path, 12, 600)
    processes = []

    def start(*argv) -> subprocess.Popen:
        """A Dask process whose files (the scheduler's address, a worker's scratch space) stay in this test's folder."""
        processes.append(subprocess.Popen([str(dask), *argv, "--no-dashboard"], cwd=tmp_path,
                                          env={**os.environ, "DASK_TEMPORARY_DIRECTORY": str(tmp_path)},
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        return processes[-1]

    try:
        scheduler = start("scheduler", "--host", "127.0.0.1", "--port", "0", "--scheduler-file", "scheduler.json")
        deadline = time.monotonic() + 120
        while not (tmp_path / "scheduler.json").exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        address = json.loads((tmp_path / "scheduler.json").read_text())["address"]
        worker = start("worker", address, "--no-nanny", "--nthreads", "1")
        with distributed.Client(address, timeout=60) as client:
            client.wait_for_workers(1, timeout=120)

        assert run_cli("batch", small, "--store", tmp_path / "local.sqlite", "--workers", "2")[0] == 0
        code, out, err = _guarded(run_cli, "batch", small, "--store", tmp_path / "dask.sqlite", "--scheduler", address)
        assert code == 0 and err == "", err
        local, remote = stored_results(tmp_path / "local.sqlite"), stored_results(tmp_path / "dask.sqlite")
        assert local.keys() == remote.keys() and len(local) == 24
        for key, row in local.items():
            assert {k: v for k, v in row.items() if k != "id"} == {k: v for k, v in remote[key].items() if k != "id"}

        lost_worker = tmp_path / "lost-worker.sqlite"
        _kill_when(worker, lambda: stored_count(lost_worker) > 0)
        one_line_error(*_guarded(run_cli, "batch", big, "--store", lost_worker, "--scheduler", address),
                       f"--scheduler {address}: no worker in the cluster for {DASK_LOST:g} s",
                       "the cards stored so far are kept")
        _whole_cards(lost_worker)

        lost_scheduler = tmp_path / "lost-scheduler.sqlite"
        _kill_when(scheduler, lost_scheduler.exists)  # the store is made once the client is connected
        one_line_error(*_guarded(run_cli, "batch", big, "--store", lost_scheduler, "--scheduler", address),
                       f"--scheduler {address}: lost the connection to the scheduler",
                       "the cards stored so far are kept")

        one_line_error(*_guarded(run_cli, "batch", small, "--store", tmp_path / "refused.sqlite", "--scheduler",
                                 address),
                       f"--scheduler {address}: cannot connect")
        assert not (tmp_path / "refused.sqlite").exists()
    finally:
        for process in processes:
            process.kill()
            process.wait(timeout=60)


def test_a_stopped_pool_lets_go_of_the_pipes_its_threads_would_block_on():
    """The interpreter's exit joins the pool's threads: after its workers are killed, this
    process's end of the results pipe's writing side and of the task pipe's reading side
    are closed (concurrent.futures forgets both at its shutdown), so that neither thread
    can wait for ever on a message a dead worker half wrote or half read."""
    from pumpjack_cli.analysis.batch import executors

    with pytest.raises(KeyboardInterrupt):
        with executors.local_pool(2) as pool:
            results, calls = pool.executor._result_queue, pool.executor._call_queue
            raise KeyboardInterrupt
    assert results._writer.closed and calls._reader.closed
