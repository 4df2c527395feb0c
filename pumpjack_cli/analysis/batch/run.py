"""`pumpjack batch`: the manifest's cards not yet in the store, through an executor, into the store.

The store is read (read-only) to find what is done; it is opened for writing only when
there are cards to store, after the executor is ready (a Dask scheduler that refuses the
connection leaves no store behind). SIGINT and SIGTERM end a run with one line: the
workers are stopped, and every card stored so far is complete (the same command goes on).
"""

from __future__ import annotations

import itertools
import math
import time
from collections import Counter
from contextlib import contextmanager
from dataclasses import asdict, dataclass
from pathlib import Path

from ...errors import PumpjackError
from ...readers.catalogue import Catalogue, read_catalogue
from ...readers.manifest import Job, read_manifest
from ...readers.store import Store
from .executors import RESUME, LocalPool, executor, local_pool
from .keys import card_digest, options_key, unit_digest, with_files
from .per_card import ANALYSES, Options, card_fields

#: The most cards in one task (one worker call): enough that the pickling and scheduling of a
#: task, and the transaction that stores it, are shared by many cards, and the cards of one
#: unit can be computed together.
MAX_CHUNK = 256
#: Tasks per worker a smaller field is cut into, so that every worker has work to the end
#: and the progress moves.
TASKS_PER_WORKER = 4


@dataclass(frozen=True)
class Tally:
    """What a run did: cards in the manifest, cards analysed now and skipped as done, the
    results this run stored by status, the results another run stored first (two runs on
    one store), and the run's wall time [s]."""

    cards: int
    analysed: int
    skipped: int
    ok: int
    errors: int
    stored_by_another: int
    seconds: float


@dataclass(frozen=True)
class _Pending:
    """A card to analyse: its digest, the options (JSON text, hash) of each analysis, and
    the analyses not yet stored."""

    card_digest: str
    keys: dict[str, tuple[str, str]]
    wanted: tuple[str, ...]


def chunk_size(cards: int, workers: int) -> int:
    """Cards per task for ``cards`` cards on ``workers`` workers (processes, or a cluster's
    threads): a share that cuts the field into :data:`TASKS_PER_WORKER` tasks per worker, from
    1 to :data:`MAX_CHUNK` cards. The executors hold at most a few tasks per worker in flight,
    so that the memory of a run is bounded whatever the size of the field.

    >>> chunk_size(100_000, 2), chunk_size(1000, 2), chunk_size(40, 2), chunk_size(3, 8)
    (256, 125, 5, 1)
    """
    return max(1, min(MAX_CHUNK, math.ceil(cards / (TASKS_PER_WORKER * max(1, workers)))))


#: The smallest task of a run's tail (fewer cards only when fewer are left).
TAIL_TASK = 32


def task_sizes(cards: int, workers: int) -> list[int]:
    """The tasks ``cards`` cards are cut into on ``workers`` workers: :func:`chunk_size` cards each,
    until fewer than two such tasks per worker are left; from there each task takes half of a
    worker's share of what is left, ceil(left / (2 workers)) (at least :data:`TAIL_TASK` cards, at
    most the chunk size), so that the workers run out of work together instead of one waiting on
    the other's last long task.

    >>> task_sizes(1000, 2)
    [125, 125, 125, 125, 125, 94, 71, 53, 40, 32, 32, 32, 21]
    >>> task_sizes(40, 2) == [5] * 8, sum(task_sizes(10_000, 2)), len(task_sizes(10_000, 2))
    (True, 10000, 47)
    """
    size, sizes, left = chunk_size(cards, workers), [], cards
    while left > 0:
        step = min(left, size, max(min(size, TAIL_TASK), math.ceil(left / (2 * max(1, workers)))))
        sizes.append(step)
        left -= step
    return sizes


def _check(options: Options) -> None:
    """Refuse unknown analyses and torque options before anything runs."""
    from ..torque import check_options

    for analysis in options.analyses:
        if analysis not in ANALYSES:
            raise PumpjackError(f"--analyses: unknown analysis {analysis!r}; use {', '.join(ANALYSES)}")
    check_options(options.method, options.balance)


def _check_jobs(jobs: list[Job], manifest: Path) -> None:
    """Refuse a row whose counterbalance moment a unit's [counterbalance] would refuse,
    naming its line and field, before anything runs (the schema is imported only for a
    manifest that gives moments)."""
    moments = [job for job in jobs if job.counterbalance_moment is not None]
    if not moments:
        return
    from pydantic import ValidationError

    from ...config.beam_unit import CounterbalanceConfig
    from ...config.files import error_message

    checked = set()   # each moment once: a glob row gives thousands of cards the same one
    for job in moments:
        if job.counterbalance_moment not in checked:
            checked.add(job.counterbalance_moment)
            try:
                CounterbalanceConfig(moment=job.counterbalance_moment)
            except ValidationError as exc:
                first = exc.errors()[0]
                raise PumpjackError(f"{manifest}: line {job.line}: counterbalance_moment: "
                                    f"{error_message(first, CounterbalanceConfig)}") from None


def _stored_keys(path: Path) -> set:
    """The keys of the rows already in the store (read-only; none if there is no store yet)."""
    if not path.exists() and not path.is_symlink():
        return set()
    store = Store(path)
    try:
        return store.done()
    finally:
        store.close()


def _pending(jobs: list[Job], options: Options, done: set, catalogue: Catalogue | None) -> dict[int, _Pending]:
    """The jobs (by index) with an analysis not in ``done`` (the store's keys; a card named
    twice in the manifest is analysed once); units named in the ``catalogue`` by its rows."""
    digests: dict[str, str] = {}
    known: dict = {}
    pending = {}
    for index, job in enumerate(jobs):
        if job.unit not in digests:
            digests[job.unit] = unit_digest(job.unit, catalogue)
        card = card_digest(job.card)
        keys = {a: options_key(job, a, options, digests[job.unit], known) for a in options.analyses}
        wanted = tuple(a for a in options.analyses if (job.well, card, a, keys[a][1]) not in done)
        done.update((job.well, card, a, keys[a][1]) for a in wanted)
        if wanted:
            pending[index] = _Pending(card, keys, wanted)
    return pending


class Interrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM during a run (a KeyboardInterrupt, so that the executors stop as for Ctrl-C)."""


@contextmanager
def _signals_stop_the_run():
    """SIGINT and SIGTERM raise :class:`Interrupted` in the main thread while the run lasts."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(number, _frame):
        raise Interrupted(signal.Signals(number).name)

    previous = {number: signal.signal(number, stop) for number in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, signal.SIG_DFL if handler is None else handler)


def run_batch(manifest: Path, store_path: Path, options: Options, workers: int, scheduler: str | None = None,
              progress=None) -> Tally:
    """Analyse every card of the manifest not yet in the store, on a local process pool
    (``workers``) or a Dask cluster (``scheduler`` address), storing the results of each
    task's cards in one transaction as it arrives. ``progress(done, total)`` is called as
    tasks finish, with the cards done and to do."""
    start = time.perf_counter()
    _check(options)
    stored: Counter = Counter()
    with local_pool(workers if scheduler is None else 1) as pool:
        jobs = read_manifest(manifest)
        _check_jobs(jobs, manifest)
        catalogue = None if options.catalogue is None else read_catalogue(Path(options.catalogue))
        with _signals_stop_the_run():
            try:
                pending = _pending(jobs, options, with_files(_stored_keys(store_path)), catalogue)
                if pending:
                    _analyse(jobs, pending, store_path, options, pool, scheduler, progress, stored)
            except KeyboardInterrupt as exc:
                raise PumpjackError(f"interrupted ({exc or 'SIGINT'}) after storing {stored['ok'] + stored['error']} "
                                    f"results; {RESUME}") from None
    return Tally(len(jobs), len(pending), len(jobs) - len(pending), stored["ok"], stored["error"],
                 stored["another"], time.perf_counter() - start)


def _analyse(jobs: list[Job], pending: dict[int, _Pending], store_path: Path, options: Options,
             pool: LocalPool | None, scheduler: str | None, progress, stored: Counter) -> None:
    """The pending cards through the executor, in tasks of :func:`task_sizes` cards, into the
    store (opened for writing once the executor is ready), the cards of each finished task in
    one transaction; ``stored`` counts the results stored by status, and those another run
    stored first as ``another``."""
    indices = list(pending)
    finished = 0

    def store_chunk(results) -> None:
        nonlocal finished
        cards = []
        for index, outcomes in results:
            job, key = jobs[index], pending[index]
            cards.append([{"well": job.well, **card_fields(job, key.card_digest, o), "unit": job.unit,
                           "analysis": o["analysis"], "options": key.keys[o["analysis"]][0],
                           "options_sha256": key.keys[o["analysis"]][1], "status": o["status"], "error": o["error"],
                           "warnings": o["warnings"], "summary": o["summary"]}
                          for o in outcomes if o["analysis"] in key.wanted])
        statuses = store.add_cards(cards)
        for rows, done in zip(cards, statuses):
            stored.update(done)
            stored["another"] += len(rows) - len(done)
        finished += len(cards)
        if progress is not None:
            progress(finished, len(pending))

    with executor(scheduler, pool, len(indices)) as (execute, slots):
        bounds = itertools.accumulate(task_sizes(len(indices), slots), initial=0)
        # a job's fields are plain values: its fields' dict is the plain data (asdict's deep copies cost more)
        chunks = ([(i, dict(vars(jobs[i]))) for i in indices[start:stop]] for start, stop in itertools.pairwise(bounds))
        store = Store(store_path, write=True)
        try:
            execute(chunks, asdict(options), store_chunk)
        finally:
            store.close()
