"""Where the chunks of a batch run: this process, a local pool of processes, or a Dask cluster.

Every executor runs the same :func:`.per_card.analyse_chunk` on chunks of (index, job
fields) and hands each chunk's results to ``store_chunk`` as it finishes, in this
process, which alone writes the store.
"""

from __future__ import annotations

import itertools
import os

from ...errors import PumpjackError
from .per_card import analyse_chunk


def default_workers() -> int:
    """All the cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def in_process(chunks, settings: dict, store_chunk) -> None:
    """The chunks one after the other in this process."""
    for chunk in chunks:
        store_chunk(analyse_chunk(chunk, settings))


def on_pool(workers: int, chunks, settings: dict, store_chunk) -> None:
    """The chunks on a local pool of ``workers`` forked processes, at most two chunks per
    worker in flight, stored as they finish."""
    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else None
    with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method)) as pool:
        queue = iter(chunks)
        running = {pool.submit(analyse_chunk, chunk, settings) for chunk in itertools.islice(queue, 2 * workers)}
        while running:
            finished, running = wait(running, return_when=FIRST_COMPLETED)
            for future in finished:
                store_chunk(future.result())
                running |= {pool.submit(analyse_chunk, chunk, settings) for chunk in itertools.islice(queue, 1)}


def on_dask(address: str, chunks, settings: dict, store_chunk) -> None:
    """The chunks on the Dask distributed cluster of the scheduler at ``address``, stored as they finish."""
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise PumpjackError("--scheduler needs Dask: pip install 'pumpjack-cli[dask]'") from None
    try:
        client = Client(address, timeout="30s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise PumpjackError(f"--scheduler {address}: cannot connect: {exc}") from None
    try:
        futures = [client.submit(analyse_chunk, chunk, settings, pure=False) for chunk in chunks]
        for future in as_completed(futures):
            try:
                results = future.result()
            except Exception as exc:  # noqa: BLE001 - a lost worker or a broken cluster, not a card
                raise PumpjackError(f"--scheduler {address}: a task failed ({type(exc).__name__}: {exc}); the cards "
                                    f"stored so far are kept, run the same command again to go on") from None
            store_chunk(results)
    finally:
        client.close()
