"""Throughput of `pumpjack batch` on a generated field, and where the time goes.

Run: .venv/bin/python benchmarks/bench_batch.py [--cards 10000] [--workers 2] [--split 2000] [--singles 5]

Generates ``--cards`` cards for the bundled beam units (variations of the sample cards:
the load scaled about its mean by 0.9-1.1, Gaussian noise of 0.3 % of the load range,
the time stamps stretched for a speed of 0.95-1.05 times the card's), a manifest with
one well per 20 cards of a unit and a time stamp per card, and

1. runs ``pumpjack batch MANIFEST`` (torque API with its balance, downhole Gibbs with its
   damping and the pump's condition) end to end as a user would, in a fresh process, with
   the peak resident memory of that process and its workers (sampled every 0.1 s; psutil,
   installed with the ``dev`` or ``dask`` extra);
2. analyses the first ``--split`` cards in this process, one core, as a worker does
   (:func:`pumpjack_cli.analysis.batch.per_card.analyse_chunk` in chunks of the run's size),
   and splits that time into parsing (reading the card files), physics (placing the cards,
   torque and balance, the damping search and the pump cards, the summaries), diagnosis (the
   pump's condition of the pump cards) and storing (the rows written to a store in the run's
   transactions), the physics again by phase (:data:`PHASES`);
3. runs ``pumpjack torque`` and ``pumpjack downhole`` on ``--singles`` cards as a shell loop
   would, for comparison.

The ratio printed last is the batch's CPU (wall time x workers) over the in-process
analysis time of the same number of cards: what the pool, the pickling and the store add.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import asdict
from pathlib import Path

import numpy as np

from timing import machine, process_tree

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(sys.executable).parent
UNITS = ("sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54", "c-80d-133-48")


def sample(unit: str) -> tuple[str, np.ndarray]:
    lines = (ROOT / "samples" / f"{unit}-card.csv").read_text(encoding="utf-8").splitlines()
    body = [line for line in lines if not line.startswith("#")]
    return body[0], np.array([[float(x) for x in line.split(",")] for line in body[1:]])


def generate(folder: Path, cards: int, seed: int = 1) -> Path:
    """``cards`` card files and their manifest in ``folder``; the manifest's path."""
    rng = np.random.default_rng(seed)
    samples = {unit: sample(unit) for unit in UNITS}
    rows = ["well,unit,card,timestamp"]
    for k in range(cards):
        unit = UNITS[k % len(UNITS)]
        header, data = samples[unit]
        card = data.copy()
        mean = card[:, 2].mean()
        card[:, 2] = mean + rng.uniform(0.9, 1.1) * (card[:, 2] - mean)
        card[:, 2] += rng.normal(0.0, 0.003 * np.ptp(data[:, 2]), len(card))
        card[:, 0] *= 1.0 / rng.uniform(0.95, 1.05)
        name = f"card-{k:06d}.csv"
        (folder / name).write_text(header + "\n" + "\n".join(f"{t:.4f},{s:.5f},{w:.4f}" for t, s, w in card) + "\n",
                                   encoding="utf-8")
        rows.append(f"well-{unit}-{k // (20 * len(UNITS)):05d},{unit},{name},2026-11-{1 + k % 28:02d}T{k % 24:02d}:00")
    manifest = folder / "manifest.csv"
    manifest.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return manifest


def _peak_memory(process: subprocess.Popen, found: list[float]) -> None:
    """Largest sum of the resident memory of ``process`` and its children [bytes], every 0.1 s."""
    import psutil

    try:
        root = psutil.Process(process.pid)
        while process.poll() is None:
            total = sum(info["memory_info"].rss for info in process_tree(root, ("memory_info",)).values())
            found[0] = max(found[0], total)
            time.sleep(0.1)
    except psutil.Error:
        pass


def end_to_end(manifest: Path, store: Path, workers: int) -> tuple[float, float, str]:
    """Wall time [s], peak memory [bytes] and the last line of a `pumpjack batch` run."""
    start = time.perf_counter()
    process = subprocess.Popen([str(BIN / "pumpjack"), "batch", str(manifest), "--store", str(store), "--workers",
                                str(workers)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    peak = [0.0]
    watcher = threading.Thread(target=_peak_memory, args=(process, peak), daemon=True)
    watcher.start()
    out, err = process.communicate()
    wall = time.perf_counter() - start
    watcher.join()
    if process.returncode:
        raise SystemExit(f"pumpjack batch failed: {err.strip()}")
    return wall, peak[0], out.strip().splitlines()[-1] if out.strip() else ""


#: The functions a worker's analysis is timed by (module path, attribute, phase), inner first:
#: the time of a phase is its function's less that of the phases it calls.
PHASES = (
    ("pumpjack_cli.analysis.batch.per_card", "_strokes", "parsing"),
    ("pumpjack_cli.analysis.batch.per_card", "_PlacedOnce.place_together", "placing"),
    ("pumpjack_cli.analysis.downhole", "diagnose", "diagnosis"),
    ("pumpjack_cli.analysis.torque", "torques", "torque"),
    ("pumpjack_cli.analysis.downhole", "downholes", "downhole"),
    ("pumpjack_cli.analysis.batch.per_card", "_checked", "summaries"),
)


def split(manifest: Path, cards: int, store: Path) -> dict[str, float]:
    """CPU seconds of each phase (:data:`PHASES`) and of storing for the first ``cards`` cards in
    this process, chunk by chunk as a worker analyses them."""
    import importlib

    from pumpjack_cli.analysis.batch import per_card
    from pumpjack_cli.analysis.batch.executors import roomy_allocator
    from pumpjack_cli.analysis.batch.run import chunk_size
    from pumpjack_cli.readers.manifest import read_manifest
    from pumpjack_cli.readers.store import Store

    jobs = read_manifest(manifest)[:cards]
    settings = asdict(per_card.Options())
    size = chunk_size(len(jobs), 1)
    roomy_allocator()       # as in a worker
    spent = dict.fromkeys([phase for _, _, phase in PHASES], 0.0)
    inner = [0.0]      # the time of the phases running inside the one being timed

    def timed(function, phase: str):
        def run(*args, **kwargs):
            outer, inner[0] = inner[0], 0.0
            start = time.process_time()
            try:
                return function(*args, **kwargs)
            finally:
                took = time.process_time() - start
                spent[phase] += took - inner[0]
                inner[0] = outer + took
        return run

    first = {job.unit: index for index, job in reversed(list(enumerate(jobs)))}
    per_card.analyse_chunk([(i, asdict(jobs[i])) for i in first.values()], settings)   # imports, units, caches
    patched = []
    for module, name, phase in PHASES:
        owner = importlib.import_module(module)
        *path, attribute = name.split(".")
        for part in path:
            owner = getattr(owner, part)
        real = owner.__dict__[attribute]
        patched.append((owner, attribute, real))
        function = real.__func__ if isinstance(real, staticmethod) else real
        setattr(owner, attribute, staticmethod(timed(function, phase)) if isinstance(real, staticmethod)
                else timed(function, phase))
    results = []
    start = time.process_time()
    try:
        for k in range(0, len(jobs), size):
            results.append(per_card.analyse_chunk([(i, asdict(jobs[i])) for i in range(k, min(k + size, len(jobs)))],
                                                  settings))
    finally:
        for owner, attribute, real in patched:
            setattr(owner, attribute, real)
    analysis = time.process_time() - start
    stored = Store(store, write=True)
    start = time.process_time()
    try:
        for chunk in results:
            stored.add_cards([[{"well": jobs[i].well, "card": jobs[i].card, "card_sha256": f"{i:064x}",
                                "timestamp": jobs[i].timestamp, "unit": jobs[i].unit, "analysis": o["analysis"],
                                "options": "{}", "options_sha256": "0" * 64, "status": o["status"],
                                "error": o["error"], "warnings": o["warnings"], "summary": o["summary"]}
                               for o in outcomes] for i, outcomes in chunk])
    finally:
        stored.close()
    storing = time.process_time() - start
    return {**spent, "other": analysis - sum(spent.values()), "storing": storing, "analysis": analysis + storing}


def singles(folder: Path, count: int) -> float:
    """Seconds per card of `pumpjack torque` + `pumpjack downhole` run as a shell loop."""
    start = time.perf_counter()
    for k in range(count):
        card = folder / f"card-{k:06d}.csv"
        for command in ("torque", "downhole"):
            subprocess.run([str(BIN / "pumpjack"), command, UNITS[k % len(UNITS)], "--card", str(card), "-f", "csv"],
                           capture_output=True, check=True)
    return (time.perf_counter() - start) / max(count, 1)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--cards", type=int, default=10_000)
    parser.add_argument("--workers", type=int, default=len(os.sched_getaffinity(0)))
    parser.add_argument("--split", type=int, default=2000, help="cards analysed in this process for the split")
    parser.add_argument("--singles", type=int, default=5)
    args = parser.parse_args()
    print(f"machine: {machine()}")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        manifest = generate(folder, args.cards)
        wall, peak, said = end_to_end(manifest, folder / "r.sqlite", args.workers)
        print(said)
        print(f"pumpjack batch, {args.cards} cards, torque + downhole + diagnosis, {args.workers} workers: "
              f"{wall:.1f} s end to end, {args.cards / wall:.0f} cards/s, peak memory of all processes "
              f"{peak / 2**20:.0f} MiB")
        cards = min(args.split, args.cards)
        found = split(manifest, cards, folder / "split.sqlite")
        per = {name: 1e3 * value / cards for name, value in found.items()}
        physics = per["placing"] + per["torque"] + per["downhole"] + per["summaries"] + per["other"]
        print(f"in this process, {cards} cards, ms of CPU per card: parsing {per['parsing']:.2f}, physics "
              f"{physics:.2f}, diagnosis {per['diagnosis']:.2f}, storing {per['storing']:.2f}; "
              f"total {per['analysis']:.2f}")
        print(f"  physics: placing {per['placing']:.2f}, torque {per['torque']:.2f}, downhole without the "
              f"diagnosis {per['downhole']:.2f}, summaries {per['summaries']:.2f}, the rest {per['other']:.2f}")
        ratio = wall * args.workers / (found["analysis"] / cards * args.cards)
        print(f"batch CPU (wall x workers) over in-process analysis of as many cards: {ratio:.2f}")
        if args.singles:
            single = singles(folder, args.singles)
            print(f"shell loop of single commands (torque + downhole per card): {1 / single:.2f} cards/s; "
                  f"batch is {single * args.cards / wall:.0f} x faster")


if __name__ == "__main__":
    main()
