"""Where the chunks of a batch run: this process, a local pool of processes, or a Dask cluster.

Every executor runs the same :func:`.per_card.analyse_chunk` on chunks of (index, job
fields) and hands each chunk's results to ``store_chunk`` as it finishes, in this
process, which alone writes the store. :func:`executor` chooses one and holds what it
needs (a Dask client is connected before the store is opened). The chunks are taken from
their iterator as tasks finish, :data:`IN_FLIGHT` per worker at most, so that neither
this process nor the workers hold a whole field's tasks. A run that stops early
(an interrupt, a store that cannot be written, a lost worker) stops its workers too, and
a local worker whose parent has died (``kill -9``) ends itself.
"""

from __future__ import annotations

import itertools
import os
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from functools import partial

from ...errors import PumpjackError
from .per_card import analyse_chunk

#: Seconds between a local worker's looks at its parent.
PARENT_POLL = 0.5
#: Seconds a Dask run goes on without its scheduler, or with no worker in the cluster,
#: before it ends (the stated timeout of docs/batch.md).
DASK_LOST = 10.0
#: Seconds to fetch a finished task's results before it counts as pending again (its
#: worker lost between the task's end and the fetch).
DASK_FETCH = 2.0
#: Tasks in flight per worker (a local process or a cluster's thread): one running, one
#: waiting to start as soon as it ends.
IN_FLIGHT = 2
#: What the end of a stopped run tells the user to do.
RESUME = "the cards stored so far are kept; run the same command again to go on"


def default_workers() -> int:
    """All the cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


@contextmanager
def executor(scheduler: str | None, workers: int, cards: int) -> Iterator[tuple[Callable, int]]:
    """The function that runs the chunks, and the tasks it runs at once (the workers the
    chunks are cut for): on the Dask cluster of ``scheduler`` (connected now; its threads),
    on ``workers`` local processes, or in this process (one worker or one card)."""
    if scheduler is not None:
        with _dask_client(scheduler) as client:
            yield partial(_on_dask, client, scheduler), max(1, _threads(client, scheduler))
    elif workers <= 1 or cards <= 1:
        yield in_process, 1
    else:
        yield partial(on_pool, workers), workers


def in_process(chunks, settings: dict, store_chunk) -> None:
    """The chunks one after the other in this process."""
    for chunk in chunks:
        store_chunk(analyse_chunk(chunk, settings))


def _worker_start(parent: int) -> None:
    """A local worker: interrupts are the parent's to handle (a terminal's Ctrl-C reaches
    the whole process group), and the worker ends when its parent is gone."""
    import signal
    import threading

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # not the parent's handler, inherited through fork
    threading.Thread(target=_leave_with, args=(parent,), name="parent-watch", daemon=True).start()


def _leave_with(parent: int) -> None:
    """End this process once its parent has died (it is then a child of another process)."""
    while os.getppid() == parent:
        time.sleep(PARENT_POLL)
    os._exit(1)


def on_pool(workers: int, chunks, settings: dict, store_chunk) -> None:
    """The chunks on a local pool of ``workers`` forked processes, at most :data:`IN_FLIGHT`
    chunks per worker in flight, stored as they finish; the workers are killed if the run
    stops early."""
    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
    from concurrent.futures.process import BrokenProcessPool

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else None
    others = set(multiprocessing.active_children())
    pool = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method), initializer=_worker_start,
                               initargs=(os.getpid(),))
    try:
        queue = iter(chunks)
        running = {pool.submit(analyse_chunk, chunk, settings)
                   for chunk in itertools.islice(queue, IN_FLIGHT * workers)}
        while running:
            finished, running = wait(running, return_when=FIRST_COMPLETED)
            for future in finished:
                store_chunk(future.result())
                running |= {pool.submit(analyse_chunk, chunk, settings) for chunk in itertools.islice(queue, 1)}
    except BaseException as exc:
        for process in set(multiprocessing.active_children()) - others:
            process.kill()
        pool.shutdown(wait=False, cancel_futures=True)   # its workers are killed: nothing to wait for
        _unblock(pool)
        if isinstance(exc, BrokenProcessPool):
            raise PumpjackError(f"a worker process ended abruptly (killed, or out of memory); {RESUME}") from None
        raise
    pool.shutdown(wait=True)


def _unblock(pool) -> None:
    """Let the pool's manager thread end after its workers were killed: a worker killed while it
    wrote a task's results leaves half a message in the results pipe, which the thread would read
    for ever (and the interpreter's exit joins that thread). Closing this process's end of the
    pipe's writing side, the workers' ends being closed by their deaths, ends that read
    (concurrent.futures keeps the pipe as ``_result_queue``)."""
    queue = getattr(pool, "_result_queue", None)
    if queue is not None:
        queue._writer.close()


@contextmanager
def _dask_client(address: str):
    """A client of the scheduler at ``address``; Dask's own log is silenced (a failure
    is the one line of this program)."""
    import logging

    try:
        from distributed import Client
    except ImportError:
        raise PumpjackError("--scheduler needs Dask: pip install 'pumpjack-cli[dask]'") from None
    silenced = logging.root.manager.disable
    logging.disable(logging.CRITICAL)
    try:
        try:
            client = Client(address, timeout=DASK_LOST)
        except (OSError, TimeoutError, ValueError) as exc:
            raise PumpjackError(f"--scheduler {address}: cannot connect: {' '.join(str(exc).split())}") from None
        try:
            yield client
        finally:
            client.close(timeout=DASK_LOST)
    finally:
        logging.disable(silenced)


def _threads(client, address: str) -> int:
    """The threads of the cluster's workers now."""
    try:
        return sum(client.nthreads().values())
    except Exception as exc:  # noqa: BLE001 - a lost scheduler: not a card
        raise PumpjackError(_cluster_failure(client, address, exc)) from None


def _on_dask(client, address: str, chunks, settings: dict, store_chunk) -> None:
    """The chunks on the Dask cluster, :data:`IN_FLIGHT` per worker thread (as many as there
    are now, at least one) submitted at a time and more as they finish, stored as they
    finish. The run ends with one line when a task fails, the scheduler is lost, or the
    cluster has had no worker for :data:`DASK_LOST` seconds (a task whose results were lost
    with their worker waits for another worker like any other)."""
    from distributed import wait

    queue = iter(chunks)
    pending: set = set()
    threads = _threads(client, address)
    idle_since = None
    while True:
        try:
            room = IN_FLIGHT * max(1, threads) - len(pending)
            pending |= {client.submit(analyse_chunk, chunk, settings, pure=False)
                        for chunk in itertools.islice(queue, max(0, room))}
            if not pending:
                return
            try:
                finished, pending = wait(pending, timeout=1.0, return_when="FIRST_COMPLETED")
            except TimeoutError:
                finished = set()
            results = []
            for future in finished:
                try:
                    results.append(future.result(timeout=DASK_FETCH))
                except TimeoutError:  # the worker that held the result is gone: the task runs again
                    pending.add(future)
            threads = sum(client.nthreads().values())
        except Exception as exc:  # noqa: BLE001 - a lost scheduler or worker, a broken cluster: not a card
            raise PumpjackError(_cluster_failure(client, address, exc)) from None
        for chunk in results:
            store_chunk(chunk)
        if results or threads:
            idle_since = None
        elif idle_since is None:
            idle_since = time.monotonic()
        elif time.monotonic() - idle_since > DASK_LOST:
            raise PumpjackError(f"--scheduler {address}: no worker in the cluster for {DASK_LOST:g} s; {RESUME}")


def _cluster_failure(client, address: str, exc: Exception) -> str:
    """One line for what went wrong on the cluster: the scheduler lost, or a task that failed."""
    if client.status != "running":
        return f"--scheduler {address}: lost the connection to the scheduler; {RESUME}"
    first = (str(exc).strip().splitlines() or [""])[0][:200]
    return f"--scheduler {address}: a task failed ({type(exc).__name__}: {first}); {RESUME}"
