"""Fields, not wells: many cards through the single-card analyses into one results store.

A manifest (CSV or TOML) names a well, a unit and a card (a path or a glob) per row,
with optional overrides. Each card goes through the very analyses of `pumpjack torque`
and `pumpjack downhole` (:func:`.torque.torque`, :func:`.downhole.downhole`), so a
stored summary is the single command's ``-f json`` summary; a card or a unit that
cannot be analysed becomes an ``error`` row with the message the single command would
print. The units are loaded once per worker process and the exact torque's responses
once per unit and grid (:func:`.torque._exact_basis`), so the per-card work is the
card's own. Results go to an embedded SQLite store (:mod:`.store`).
"""

from __future__ import annotations

import csv
import glob
import hashlib
import io
import itertools
import json
import math
import os
import tomllib
from dataclasses import asdict, dataclass
from pathlib import Path

from ..errors import PumpjackError, collected_warnings
from ..quantities import parse_quantity
from ..results import check_finite, converted_summary
from ..text_input import read_text

#: Analyses a card can go through, in the order they run.
ANALYSES = ("torque", "downhole")
#: Manifest columns: required, then optional.
REQUIRED_COLUMNS = ("well", "unit", "card")
OPTIONAL_COLUMNS = ("spm", "counterbalance_moment", "rod_string", "timestamp")
#: Suffixes of unit files (anything else in the unit column is a bundled unit's name).
UNIT_SUFFIXES = (".toml", ".yaml", ".yml", ".json")
#: Largest manifest [bytes].
MAX_MANIFEST_BYTES = 64 << 20
#: Crank positions of the per-angle table the batch does not keep (the summaries are
#: computed on their own fixed grid and do not depend on it).
STEPS = 4


@dataclass(frozen=True)
class Options:
    """Options that apply to every card: the analyses and their settings."""

    analyses: tuple[str, ...] = ANALYSES
    method: str = "api"
    balance: str = "equal-peaks"
    damping: float | None = None
    #: Units of card columns whose header names none ("si", "field"); None refuses them.
    card_units: str | None = None

    def for_analysis(self, analysis: str) -> dict:
        """The options that change an analysis' result (for the options hash; without
        --card-units the hash is that of a store written before the option existed)."""
        chosen = {"method": self.method, "balance": self.balance} if analysis == "torque" else {"damping": self.damping}
        return chosen if self.card_units is None else {**chosen, "card_units": self.card_units}


@dataclass(frozen=True)
class Job:
    """One card of the manifest with its well, unit and overrides (SI), and its manifest line."""

    well: str
    unit: str
    card: str
    line: int
    spm: float | None = None
    counterbalance_moment: float | None = None
    rod_string: str | None = None
    timestamp: str = ""


def _sha256(path: str | Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _row_error(source: str, line: int, message: str) -> PumpjackError:
    return PumpjackError(f"{source}: line {line}: {message}")


def read_manifest(path: Path) -> list[Job]:
    """The manifest's rows as jobs, globs expanded (relative paths are taken from the
    manifest's folder). A manifest that cannot be read, lacks a required column or has a
    malformed row is refused with one line; a card or unit that does not exist is left
    for the analysis, which records it as an error row."""
    source = str(path)
    text = read_text(path, MAX_MANIFEST_BYTES, "manifest", PumpjackError)
    if path.suffix.lower() == ".toml":
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise PumpjackError(f"{source}: not valid TOML: {exc}") from None
        rows = data.get("cards")
        if not isinstance(rows, list) or not all(isinstance(row, dict) for row in rows):
            raise PumpjackError(f"{source}: a TOML manifest lists its cards as [[cards]] tables")
        records = [(i + 1, {key: value for key, value in row.items()}) for i, row in enumerate(rows)]
    else:
        reader = csv.reader(io.StringIO(text))
        header = [cell.strip().lstrip("\ufeff").lower() for cell in next(reader, [])]
        missing = [name for name in REQUIRED_COLUMNS if name not in header]
        if missing:
            raise PumpjackError(f"{source}: line 1: the manifest needs the columns {', '.join(REQUIRED_COLUMNS)} "
                                f"(missing: {', '.join(missing)})")
        unknown = [name for name in header if name not in REQUIRED_COLUMNS + OPTIONAL_COLUMNS]
        if unknown:
            raise PumpjackError(f"{source}: line 1: unknown column {unknown[0]!r}; columns: "
                                f"{', '.join(REQUIRED_COLUMNS + OPTIONAL_COLUMNS)}")
        records = []
        for number, cells in enumerate(reader, start=2):
            if not any(cell.strip() for cell in cells):
                continue
            if len(cells) != len(header):
                raise _row_error(source, number, f"{len(cells)} cells for {len(header)} columns")
            records.append((number, dict(zip(header, (cell.strip() for cell in cells)))))
    folder = path.parent
    jobs = []
    for number, row in records:
        jobs += _jobs(row, number, folder, source)
    if not jobs:
        raise PumpjackError(f"{source}: the manifest names no card")
    return jobs


def _jobs(row: dict, number: int, folder: Path, source: str) -> list[Job]:
    for name in REQUIRED_COLUMNS:
        if not isinstance(row.get(name), str) or not row[name].strip():
            raise _row_error(source, number, f"{name} is empty")
    extra = set(row) - set(REQUIRED_COLUMNS + OPTIONAL_COLUMNS)
    if extra:
        raise _row_error(source, number, f"unknown field {sorted(extra)[0]!r}")

    def value(name: str, dimension: str) -> float | None:
        text = row.get(name)
        if text is None or text == "":
            return None
        try:
            return parse_quantity(text, dimension, require_unit=dimension != "stroke_rate")
        except ValueError as exc:
            raise _row_error(source, number, f"{name}: {exc}") from None

    spm = row.get("spm")
    if spm not in (None, ""):
        try:
            spm = float(spm)
        except (TypeError, ValueError):
            raise _row_error(source, number, f"spm: {spm!r} is not a number (strokes per minute)") from None
        if not (math.isfinite(spm) and 0.1 <= spm <= 60):
            raise _row_error(source, number, f"spm: {spm:g} is outside 0.1 .. 60 strokes per minute")
    else:
        spm = None
    moment = value("counterbalance_moment", "torque")
    unit = row["unit"].strip()
    if os.sep in unit or Path(unit).suffix.lower() in UNIT_SUFFIXES:
        unit = str(folder / unit) if not Path(unit).is_absolute() else unit
    rod_string = row.get("rod_string") or None
    if rod_string is not None and not Path(rod_string).is_absolute():
        rod_string = str(folder / rod_string)
    pattern = row["card"].strip()
    pattern = pattern if Path(pattern).is_absolute() else str(folder / pattern)
    cards = sorted(glob.glob(pattern)) if glob.has_magic(pattern) else [pattern]
    if not cards:
        raise _row_error(source, number, f"card: no file matches {row['card']!r}")
    timestamp = row.get("timestamp") or ""
    if not isinstance(timestamp, str):
        timestamp = str(timestamp)
    return [Job(row["well"].strip(), unit, card, number, spm, moment, rod_string, timestamp) for card in cards]


def options_hash(job: Job, analysis: str, options: Options, unit_digest: str) -> str:
    """What makes a result: the analysis and its options, the unit (its file's content) and the
    row's overrides (a rod-string file by its content)."""
    rod_digest = _sha256(job.rod_string) if job.rod_string and os.path.isfile(job.rod_string) else job.rod_string
    text = json.dumps({"analysis": analysis, "options": options.for_analysis(analysis), "unit": unit_digest,
                       "spm": job.spm, "counterbalance_moment": job.counterbalance_moment, "rod_string": rod_digest},
                      sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


def unit_digest(spec: str) -> str:
    """The content hash of a unit (a bundled name or a file), or the spec itself when it
    cannot be read (the analysis then records the error)."""
    from ..config.files import bundled_units

    path = Path(spec)
    if path.suffix.lower() not in UNIT_SUFFIXES and os.sep not in spec:
        path = bundled_units().get(spec.lower(), path)
    try:
        return _sha256(path)
    except OSError:
        return f"unreadable:{spec}"


@dataclass(frozen=True)
class Outcome:
    """One analysis of one card: ``ok`` with the summary (SI, suffixed names) or ``error`` with the message."""

    analysis: str
    status: str
    error: str
    warnings: str
    summary: dict


_UNITS: dict = {}


def _unit(job: Job):
    """The unit of a job with its overrides, loaded once per process."""
    key = (job.unit, job.counterbalance_moment, job.rod_string)
    if key not in _UNITS:
        from ..config import load_unit

        unit = load_unit(job.unit)
        if job.counterbalance_moment is not None:
            unit = _with_moment(unit, job.counterbalance_moment)
        if job.rod_string is not None:
            unit = _with_rod_string(unit, job.rod_string)
        _UNITS[key] = unit
    return _UNITS[key]


def _with_moment(unit, moment: float):
    """The unit whose API counterbalance moment is ``moment`` [N·m] (B and tau kept)."""
    from .machine import mass_model
    from .torque import counterbalance

    balance, _ = counterbalance(unit, mass_model(unit) if unit.masses is not None else None)
    section = {"structural_unbalance": balance.structural_unbalance, "moment": moment, "phase": balance.offset}
    data = unit.model_dump()
    data["counterbalance"] = section
    return type(unit).model_validate(data)


def _with_rod_string(unit, path: str):
    """The unit whose ``[well].rod_string`` is the one in the file ``path``."""
    from ..config.files import read_table

    if unit.well is None:
        raise PumpjackError(f"unit {unit.name} has no [well] section for the rod string of {path}")
    table = read_table(Path(path))
    sections = table.get("rod_string") if isinstance(table, dict) else None
    if sections is None:
        raise PumpjackError(f"{path}: no rod_string list in the file")
    data = unit.model_dump()
    data["well"]["rod_string"] = sections
    try:
        return type(unit).model_validate(data)
    except Exception as exc:  # a pydantic ValidationError, reported as the config reader does
        raise PumpjackError(f"{path}: rod_string: {str(exc).splitlines()[-1].strip()}") from None


class _CardOnce:
    """A card source read once for all the analyses of a card (duck-typed CardSource)."""

    def __init__(self, path: str, units: str | None):
        from .card_runs import CardSource

        self.source = CardSource(Path(path), units)
        self.name = self.source.name
        self._reading = None

    def read(self, linkage):
        if self._reading is None:
            self._reading = self.source.read(linkage)
        return self._reading


def analyse(job: Job, options: Options) -> list[Outcome]:
    """Every analysis of one card, each as the single command runs it; never raises for a
    problem of the card or the unit."""
    from .downhole import downhole
    from .torque import torque

    card = _CardOnce(job.card, options.card_units)
    outcomes = []
    for analysis in options.analyses:
        with collected_warnings() as noted:
            try:
                unit = _unit(job)
                if analysis == "torque":
                    result = torque(unit, card, job.spm, STEPS, "auto", options.method, options.balance)
                else:
                    result = downhole(unit, card, job.spm, "auto", "gibbs", options.damping)
                check_finite(result)
                status, error, summary = "ok", "", converted_summary(result, "si")
            except PumpjackError as exc:
                status, error, summary = "error", " ".join(str(exc).split()), {}
            except MemoryError:
                status, error, summary = "error", "not enough memory for this card", {}
            except Exception as exc:  # noqa: BLE001 - a fault of this program on one card must not stop a field
                status, error, summary = "error", (f"internal error ({type(exc).__name__}: "
                                                   f"{' '.join(str(exc).split())}); please report it"), {}
        outcomes.append(Outcome(analysis, status, error, " | ".join(noted), summary))
    return outcomes


def analyse_chunk(chunk: list[tuple[int, dict]], options: dict) -> list[tuple[int, list[dict]]]:
    """The analyses of a chunk of jobs (index, job fields) as plain data, for a process pool
    or a Dask worker; floating-point warnings are not printed."""
    import warnings

    settings = Options(**{**options, "analyses": tuple(options["analyses"])})
    out = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        for index, fields in chunk:
            out.append((index, [asdict(o) for o in analyse(Job(**fields), settings)]))
    return out


def job_fields(job: Job) -> dict:
    """A job as plain data (picklable for any executor)."""
    return {name: getattr(job, name) for name in ("well", "unit", "card", "line", "spm", "counterbalance_moment",
                                                  "rod_string", "timestamp")}


def default_workers() -> int:
    """All the cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


@dataclass(frozen=True)
class Tally:
    """What a run did: cards in the manifest, cards analysed now and skipped as done, and
    the results stored now by status."""

    cards: int
    analysed: int
    skipped: int
    ok: int
    errors: int
    seconds: float


#: Cards per task handed to a worker.
CHUNK = 16


def run_batch(manifest: Path, store_path: Path, options: Options, workers: int, scheduler: str | None = None,
              progress=None) -> Tally:
    """Analyse every card of the manifest not yet in the store, on a local process pool
    (``workers``) or a Dask cluster (``scheduler`` address), storing each card's results
    in one transaction as it arrives. ``progress(done, total)`` is called as cards finish."""
    import time

    from .store import Store

    start = time.perf_counter()
    from .torque import check_options

    for analysis in options.analyses:
        if analysis not in ANALYSES:
            raise PumpjackError(f"--analyses: unknown analysis {analysis!r}; use {', '.join(ANALYSES)}")
    check_options(options.method, options.balance)
    jobs = read_manifest(manifest)
    store = Store(store_path)
    try:
        done = store.done()
        digests: dict[str, str] = {}
        pending, keys = [], {}
        for index, job in enumerate(jobs):
            if job.unit not in digests:
                digests[job.unit] = unit_digest(job.unit)
            try:
                card_digest = _sha256(job.card)
            except OSError:
                card_digest = "unreadable:" + hashlib.sha256(job.card.encode()).hexdigest()
            hashes = {a: options_hash(job, a, options, digests[job.unit]) for a in options.analyses}
            wanted = tuple(a for a in options.analyses if (job.well, card_digest, a, hashes[a]) not in done)
            done.update((job.well, card_digest, a, hashes[a]) for a in wanted)
            if wanted:
                keys[index] = (card_digest, hashes, wanted)
                pending.append(index)
        chunks = [[(i, job_fields(jobs[i])) for i in pending[k:k + CHUNK]] for k in range(0, len(pending), CHUNK)]
        settings = asdict(options)
        counts = {"ok": 0, "error": 0}
        finished = 0

        def store_chunk(results) -> None:
            nonlocal finished
            for index, outcomes in results:
                job, (card_digest, hashes, wanted) = jobs[index], keys[index]
                rows = [{"well": job.well, "card": job.card, "card_sha256": card_digest, "timestamp": job.timestamp,
                         "unit": job.unit, "analysis": o["analysis"], "options_sha256": hashes[o["analysis"]],
                         "status": o["status"], "error": o["error"], "warnings": o["warnings"],
                         "summary": o["summary"]} for o in outcomes if o["analysis"] in wanted]
                store.add_card(rows)
                for row in rows:
                    counts[row["status"]] += 1
                finished += 1
                if progress is not None:
                    progress(finished, len(pending))

        if scheduler is not None:
            _on_dask(scheduler, chunks, settings, store_chunk)
        elif workers <= 1 or len(chunks) <= 1:
            for chunk in chunks:
                store_chunk(analyse_chunk(chunk, settings))
        else:
            _on_pool(workers, chunks, settings, store_chunk)
    finally:
        store.close()
    return Tally(len(jobs), len(pending), len(jobs) - len(pending), counts["ok"], counts["error"],
                 time.perf_counter() - start)


def _on_pool(workers: int, chunks, settings: dict, store_chunk) -> None:
    """The chunks on a local pool of forked processes, stored as they finish."""
    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else None
    with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method)) as pool:
        queue = iter(chunks)
        running = {pool.submit(analyse_chunk, chunk, settings) for chunk in _take(queue, 2 * workers)}
        while running:
            finished, running = wait(running, return_when=FIRST_COMPLETED)
            for future in finished:
                store_chunk(future.result())
                running |= {pool.submit(analyse_chunk, chunk, settings) for chunk in _take(queue, 1)}


def _take(iterator, count: int) -> list:
    return list(itertools.islice(iterator, count))


def _on_dask(address: str, chunks, settings: dict, store_chunk) -> None:
    """The chunks on a Dask distributed cluster (the same per-card function), stored as they finish."""
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

