"""`pumpjack batch`: the manifest's cards not yet in the store, through an executor, into the store."""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass
from pathlib import Path

from ...errors import PumpjackError
from ...readers.catalogue import Catalogue, read_catalogue
from ...readers.manifest import Job, read_manifest
from ...readers.store import Store
from .executors import in_process, on_dask, on_pool
from .keys import card_digest, options_hash, unit_digest, with_files
from .per_card import ANALYSES, Options, card_fields

#: Cards per task handed to a worker.
CHUNK = 16


@dataclass(frozen=True)
class Tally:
    """What a run did: cards in the manifest, cards analysed now and skipped as done, the
    results stored now by status, and the run's wall time [s]."""

    cards: int
    analysed: int
    skipped: int
    ok: int
    errors: int
    seconds: float


@dataclass(frozen=True)
class _Pending:
    """A card to analyse: its digest, the options hash of each analysis, and the analyses not yet stored."""

    card_digest: str
    hashes: dict[str, str]
    wanted: tuple[str, ...]


def _check(options: Options) -> None:
    """Refuse unknown analyses and torque options before anything runs."""
    from ..torque import check_options

    for analysis in options.analyses:
        if analysis not in ANALYSES:
            raise PumpjackError(f"--analyses: unknown analysis {analysis!r}; use {', '.join(ANALYSES)}")
    check_options(options.method, options.balance)


def _pending(jobs: list[Job], options: Options, done: set, catalogue: Catalogue | None) -> dict[int, _Pending]:
    """The jobs (by index) with an analysis not in ``done`` (the store's keys; a card named
    twice in the manifest is analysed once); units named in the ``catalogue`` by its rows."""
    digests: dict[str, str] = {}
    pending = {}
    for index, job in enumerate(jobs):
        if job.unit not in digests:
            digests[job.unit] = unit_digest(job.unit, catalogue)
        card = card_digest(job.card)
        hashes = {a: options_hash(job, a, options, digests[job.unit]) for a in options.analyses}
        wanted = tuple(a for a in options.analyses if (job.well, card, a, hashes[a]) not in done)
        done.update((job.well, card, a, hashes[a]) for a in wanted)
        if wanted:
            pending[index] = _Pending(card, hashes, wanted)
    return pending


def run_batch(manifest: Path, store_path: Path, options: Options, workers: int, scheduler: str | None = None,
              progress=None) -> Tally:
    """Analyse every card of the manifest not yet in the store, on a local process pool
    (``workers``) or a Dask cluster (``scheduler`` address), storing each card's results
    in one transaction as it arrives. ``progress(done, total)`` is called as cards finish."""
    start = time.perf_counter()
    _check(options)
    jobs = read_manifest(manifest)
    catalogue = None if options.catalogue is None else read_catalogue(Path(options.catalogue))
    store = Store(store_path)
    try:
        pending = _pending(jobs, options, with_files(store.done()), catalogue)
        indices = list(pending)
        chunks = [[(i, asdict(jobs[i])) for i in indices[k:k + CHUNK]] for k in range(0, len(indices), CHUNK)]
        settings = asdict(options)
        counts = {"ok": 0, "error": 0}
        finished = 0

        def store_chunk(results) -> None:
            nonlocal finished
            for index, outcomes in results:
                job, key = jobs[index], pending[index]
                rows = [{"well": job.well, **card_fields(job, key.card_digest, o), "unit": job.unit, "analysis": o["analysis"],
                         "options_sha256": key.hashes[o["analysis"]], "status": o["status"], "error": o["error"],
                         "warnings": o["warnings"], "summary": o["summary"]}
                        for o in outcomes if o["analysis"] in key.wanted]
                store.add_card(rows)
                for row in rows:
                    counts[row["status"]] += 1
                finished += 1
                if progress is not None:
                    progress(finished, len(pending))

        if scheduler is not None:
            on_dask(scheduler, chunks, settings, store_chunk)
        elif workers <= 1 or len(chunks) <= 1:
            in_process(chunks, settings, store_chunk)
        else:
            on_pool(workers, chunks, settings, store_chunk)
    finally:
        store.close()
    return Tally(len(jobs), len(pending), len(jobs) - len(pending), counts["ok"], counts["error"],
                 time.perf_counter() - start)
