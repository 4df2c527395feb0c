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
from functools import cache, partial

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
#: glibc's allocator thresholds set in a process that analyses cards [bytes]: an array below
#: ``M_MMAP_THRESHOLD`` comes from the heap, and freed memory at the heap's top is handed back
#: to the system past ``M_TRIM_THRESHOLD``. These are the ceilings glibc's own sliding
#: thresholds reach on a 64-bit system (``DEFAULT_MMAP_THRESHOLD_MAX``, twice it), set at once.
MMAP_THRESHOLD, TRIM_THRESHOLD = 32 << 20, 64 << 20
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3   # mallopt's parameter numbers (malloc.h)


def default_workers() -> int:
    """All the cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


@contextmanager
def executor(scheduler: str | None, pool: LocalPool | None, cards: int) -> Iterator[tuple[Callable, int]]:
    """The function that runs the chunks, and the tasks it runs at once (the workers the
    chunks are cut for): on the Dask cluster of ``scheduler`` (connected now; its threads),
    on the local ``pool`` (:func:`local_pool`), or in this process (no pool, or one card)."""
    if scheduler is not None:
        with _dask_client(scheduler) as client:
            yield partial(_on_dask, client, scheduler), max(1, _threads(client, scheduler))
    elif pool is None or cards <= 1:
        yield in_process, 1
    else:
        yield partial(on_pool, pool), pool.workers


@cache
def roomy_allocator() -> None:
    """Let this process's arrays be reused from the heap (:data:`MMAP_THRESHOLD`,
    :data:`TRIM_THRESHOLD`; nothing where the C library is not glibc). The analysis of a
    block of cards makes and frees many arrays of 0.1-1 MB (32 cards on the 3600-angle grids);
    above the mapping threshold each is a fresh mapping of the system's, its pages zeroed on
    first touch. glibc raises that threshold by itself only as it sees such blocks freed, and
    not at all in a process started with ``MALLOC_TRIM_THRESHOLD_`` in its environment, as a
    Dask nanny starts its workers (``distributed.nanny.pre-spawn-environ``): measured on
    2000 cards in one process, 1.90 ms of CPU a card without this call, 1.75 ms with it, and
    2.68 ms with the nanny's setting (docs/batch.md). A process keeps at most
    :data:`TRIM_THRESHOLD` of freed memory. Once a process (a forked worker inherits it)."""
    import ctypes

    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):   # not glibc: its own allocator's thresholds stay
        return
    mallopt(_M_MMAP_THRESHOLD, MMAP_THRESHOLD)
    mallopt(_M_TRIM_THRESHOLD, TRIM_THRESHOLD)


def in_process(chunks, settings: dict, store_chunk) -> None:
    """The chunks one after the other in this process."""
    roomy_allocator()
    for chunk in chunks:
        store_chunk(analyse_chunk(chunk, settings))


def _worker_start(parent: int) -> None:
    """A local worker: interrupts are the parent's to handle (a terminal's Ctrl-C reaches
    the whole process group), the worker ends when its parent is gone, its allocator is made
    roomy (:func:`roomy_allocator`) and the analyses are imported before the first task."""
    import signal
    import threading

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # not the parent's handler, inherited through fork
    roomy_allocator()
    threading.Thread(target=_leave_with, args=(parent,), name="parent-watch", daemon=True).start()
    from .. import downhole, torque  # noqa: F401 - imported while the parent reads the manifest


def _leave_with(parent: int) -> None:
    """End this process once its parent has died (it is then a child of another process)."""
    while os.getppid() == parent:
        time.sleep(PARENT_POLL)
    os._exit(1)


class LocalPool:
    """A local pool of processes (``concurrent.futures``), its number of workers, and whether
    a run has given it work."""

    def __init__(self, executor, workers: int):
        self.executor, self.workers, self.used = executor, workers, False


@contextmanager
def local_pool(workers: int) -> Iterator[LocalPool | None]:
    """A local pool of ``workers`` forked processes (None for one worker), started at once so
    that the workers import the analyses while this process reads the manifest and the store.
    Its workers are killed if the run stops early (an error, an interrupt: their tasks'
    cards are not stored) or gave them no work, and end after their last task otherwise."""
    if workers <= 1:
        yield None
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else None
    others = set(multiprocessing.active_children())
    pool = LocalPool(ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method),
                                         initializer=_worker_start, initargs=(os.getpid(),)), workers)
    pool.executor.submit(int)          # the workers are forked for the first task
    try:
        yield pool
    except BaseException:
        _stop(pool.executor, others)
        raise
    if pool.used:
        pool.executor.shutdown(wait=True)
    else:
        _stop(pool.executor, others)


#: How long a stopped pool's manager thread is waited for to end [s] (it ends at once once its
#: workers are killed and its pipes unblocked; the bound keeps a stop from hanging).
MANAGER_END = 5.0


def _stop(executor, others: set) -> None:
    """Kill the pool's workers (the processes other than ``others``) and let it go."""
    import multiprocessing

    results, calls = executor._result_queue, executor._call_queue     # shutdown lets go of them
    manager = executor._executor_manager_thread
    for process in set(multiprocessing.active_children()) - others:
        process.kill()
    executor.shutdown(wait=False, cancel_futures=True)   # its workers are killed: nothing to wait for
    _unblock_results(results, calls)
    # the manager thread closes its wake-up pipe as it ends; the interpreter's exit wakes every pool's
    # manager through that pipe and, in a race with the closing, wrote to a closed one ("Exception
    # ignored ... Bad file descriptor" on stderr after the one line): let it end first
    if manager is not None:
        manager.join(timeout=MANAGER_END)
    if calls is not None and (manager is None or manager.is_alive()):
        # the manager closes the task pipe's reading end as it finds the pool broken; closed here as
        # well while it ran, the two closes raced (EBADF in its thread, or another file's descriptor
        # closed): only when it did not get there
        calls._reader.close()


def on_pool(pool: LocalPool, chunks, settings: dict, store_chunk) -> None:
    """The chunks on a local pool (:func:`local_pool`), at most :data:`IN_FLIGHT` chunks per
    worker in flight, stored as they finish."""
    from concurrent.futures import FIRST_COMPLETED, wait
    from concurrent.futures.process import BrokenProcessPool

    pool.used = True
    submit = pool.executor.submit
    try:
        queue = iter(chunks)
        running = {submit(analyse_chunk, chunk, settings) for chunk in itertools.islice(queue, IN_FLIGHT * pool.workers)}
        while running:
            finished, running = wait(running, timeout=WORKER_CHECK, return_when=FIRST_COMPLETED)
            if not finished and _a_worker_died(pool.executor):
                # a worker killed while it wrote a result leaves the pool's reader waiting for the rest of
                # the message for ever, and the pool never says it is broken: say it here
                raise BrokenProcessPool
            for future in finished:
                store_chunk(future.result())
                running |= {submit(analyse_chunk, chunk, settings) for chunk in itertools.islice(queue, 1)}
    except BrokenProcessPool:
        raise PumpjackError(f"a worker process ended abruptly (killed, or out of memory); {RESUME}") from None


#: How often a local pool's run looks whether a worker died while no task finished [s].
WORKER_CHECK = 1.0


def _a_worker_died(executor) -> bool:
    """Whether a process of the pool has ended (its workers end only with the pool)."""
    return any(process.exitcode is not None for process in list((executor._processes or {}).values()))


def _unblock_results(results, calls) -> None:
    """Let the pool's threads end after its workers were killed, so that the interpreter's exit,
    which joins them, does not wait for ever. A worker killed while it wrote a task's results
    leaves half a message in the results pipe, which the manager thread would read for ever:
    closing this process's end of the pipe's writing side (the workers' ends closed by their
    deaths) ends that read, and the manager then finds the pool broken. A task being written to
    the workers' pipe when they died fills it for good: the task queue's feeder thread is not
    waited for, and the manager, finding the pool broken, closes this process's end of that
    pipe's reading side so that the write fails (CPython gh-94777; :func:`_stop` closes it when the
    manager does not get there). (concurrent.futures keeps the pipes as ``_result_queue`` and
    ``_call_queue``, and forgets them at its shutdown.)"""
    if results is not None:
        results._writer.close()
    if calls is not None:
        calls.cancel_join_thread()


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
            pending |= {client.submit(dask_chunk, chunk, settings, pure=False)
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


def dask_chunk(chunk: list[tuple[int, dict]], settings: dict) -> list[tuple[int, list[dict]]]:
    """:func:`.per_card.analyse_chunk` as a Dask task, the worker's allocator made roomy
    (:func:`roomy_allocator`) first."""
    roomy_allocator()
    return analyse_chunk(chunk, settings)


def _cluster_failure(client, address: str, exc: Exception) -> str:
    """One line for what went wrong on the cluster: the scheduler lost (the client may still say it is
    running for a moment after its connection closed), or a task that failed."""
    from distributed.comm.core import CommClosedError

    if client.status != "running" or isinstance(exc, (CommClosedError, ConnectionError)):
        return f"--scheduler {address}: lost the connection to the scheduler; {RESUME}"
    first = (str(exc).strip().splitlines() or [""])[0][:200]
    return f"--scheduler {address}: a task failed ({type(exc).__name__}: {first}); {RESUME}"
