"""How `pumpjack batch` cuts a field into tasks and keeps them in flight: many cards per task
(one worker call, one transaction), a few tasks per worker at a time, the progress moving
task by task, locally and on a Dask cluster.

The cards here are missing files (an error row each, at once), so that the tests time the
tasks, not the physics; the results of real cards are compared in ``test_batch_cli.py``
and ``test_batch_faults.py``.
"""

from __future__ import annotations

import pytest

from helpers import field_manifest, stored_results


@pytest.mark.parametrize("cards, workers, size", [
    (1, 2, 1), (7, 2, 1), (8, 2, 1), (9, 2, 2), (40, 2, 5), (40, 1, 10), (1000, 2, 125), (2048, 2, 256),
    (10_000, 2, 256), (100_000, 2, 256), (100_000, 64, 256), (500, 64, 2), (0, 2, 1),
])
def test_a_task_is_a_quarter_of_a_workers_share_up_to_256_cards(cards, workers, size):
    """Four tasks per worker at least (all busy to the end, the progress moving), at most
    256 cards a task (what a task costs to send and store is shared by many cards)."""
    from pumpjack_cli.analysis.batch.run import chunk_size

    assert chunk_size(cards, workers) == size


def _missing(folder, count: int):
    """A manifest of ``count`` wells whose card file is missing (an error row per analysis)."""
    return field_manifest(folder, [(f"W-{k:03d}", "sk8-3.5-4000", f"missing-{k:03d}.csv", "") for k in range(count)])


def test_each_task_is_one_worker_call_and_one_transaction_and_a_step_of_the_progress(tmp_path, monkeypatch):
    """40 cards on one worker: four tasks of ten cards, each analysed in one call, stored in one
    transaction and shown as one step of the progress; every card stored once."""
    from pumpjack_cli.analysis.batch import executors
    from pumpjack_cli.analysis.batch.per_card import Options
    from pumpjack_cli.analysis.batch.run import run_batch
    from pumpjack_cli.readers.store import Store

    calls, transactions, steps = [], [], []
    analyse_chunk, add_cards = executors.analyse_chunk, Store.add_cards
    monkeypatch.setattr(executors, "analyse_chunk", lambda chunk, settings: calls.append(len(chunk))
                        or analyse_chunk(chunk, settings))
    monkeypatch.setattr(Store, "add_cards", lambda self, cards: transactions.append(len(cards))
                        or add_cards(self, cards))
    store = tmp_path / "r.sqlite"
    tally = run_batch(_missing(tmp_path, 40), store, Options(), 1, progress=lambda done, total: steps.append((done, total)))
    assert calls == transactions == [10, 10, 10, 10]
    assert steps == [(10, 40), (20, 40), (30, 40), (40, 40)]
    assert (tally.analysed, tally.errors) == (40, 80) and len(stored_results(store)) == 80


def test_a_dask_run_keeps_two_tasks_per_worker_thread_in_flight_and_shows_its_progress(tmp_path, monkeypatch):
    """On a cluster of one thread the 40 cards are four tasks of ten, submitted two at a time
    (one more as one finishes), not all at once: a field of any size holds a bounded number of
    tasks on the cluster. The progress moves task by task as on the local pool."""
    distributed = pytest.importorskip("distributed")
    from pumpjack_cli.analysis.batch.executors import IN_FLIGHT
    from pumpjack_cli.analysis.batch.per_card import Options
    from pumpjack_cli.analysis.batch.run import run_batch

    submitted, in_flight, steps = [], [], []
    submit = distributed.Client.submit
    monkeypatch.setattr(distributed.Client, "submit", lambda self, *args, **kwargs: submitted.append(args[1])
                        or submit(self, *args, **kwargs))

    def progress(done: int, total: int) -> None:
        steps.append((done, total))
        in_flight.append(len(submitted) - (len(steps) - 1))  # submitted, less the tasks stored before this one

    store = tmp_path / "r.sqlite"
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=":0") \
            as cluster:
        tally = run_batch(_missing(tmp_path, 40), store, Options(), 2, cluster.scheduler_address, progress)
    assert [len(chunk) for chunk in submitted] == [10, 10, 10, 10]
    assert max(in_flight) == IN_FLIGHT == 2
    assert steps == [(10, 40), (20, 40), (30, 40), (40, 40)]
    assert (tally.analysed, tally.errors) == (40, 80) and len(stored_results(store)) == 80
