"""Memory and throughput of `pumpjack batch --scheduler` on a Dask LocalCluster of two workers.

Run: .venv/bin/python benchmarks/bench_dask.py [--cards 10000] [--no-profiler]

Generates ``--cards`` cards as ``bench_batch.py`` does (its ``generate``), starts a
``distributed.LocalCluster`` of two worker processes of one thread each (the scheduler in
this process, each worker under its nanny), and runs ``pumpjack batch MANIFEST --scheduler
ADDRESS --store STORE`` (torque and downhole) in a fresh process whose standard error is a
pseudo-terminal, so that it draws its progress bar as on an operator's terminal. Every
0.5 s it takes the resident memory (RSS) of every process of the run: this one (the
scheduler and the nannies), the workers, the batch process, and their CPU time. It prints the
wall time, the cards per second, the peak of the total (a sum of RSS counts the pages
processes share once each: an upper bound) and of each process, the progress the bar drew,
and the CPU each process used over the run (to its last sample, so a process's last half
second may be missing).

A Dask worker samples the stacks of its tasks every 10 ms and keeps the last 1000 seconds
of these profiles (``distributed.worker.profile``); ``--no-profiler`` starts the workers
without it, as ``DASK_DISTRIBUTED__WORKER__PROFILE__ENABLED=False`` does for ``dask worker``.
RSS is read with psutil, which Dask distributed requires.
"""

from __future__ import annotations

import argparse
import logging
import os
import pty
import re
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import dask
import psutil
from distributed import LocalCluster

from bench_batch import generate
from timing import machine, process_tree

BIN = Path(sys.executable).parent
#: Seconds between two looks at the processes' memory.
SAMPLE = 0.5
MIB = 1 << 20


def _memory(root: psutil.Process, batch: int, cpu: dict[str, float] | None = None) -> dict[str, int]:
    """RSS [bytes] of every process under ``root`` (and of root), named by its role; ``cpu``
    gets each one's CPU time so far [s] (user + system)."""
    found = {}
    for pid, info in process_tree(root, ("memory_info", "cmdline", "cpu_times")).items():
        if pid == root.pid:
            role = "this process (scheduler, nannies)"
        elif pid == batch:
            role = "pumpjack batch"
        else:
            role = "resource tracker" if "resource_tracker" in " ".join(info["cmdline"] or ()) else "worker"
        found[f"{role} {pid}"] = info["memory_info"].rss
        if cpu is not None:
            cpu[f"{role} {pid}"] = info["cpu_times"].user + info["cpu_times"].system
    return found


def _terminal_reader(master: int, into: list[bytes]) -> threading.Thread:
    """A thread that keeps what the batch writes to its terminal (standard error)."""
    def read() -> None:
        while True:
            try:
                block = os.read(master, 65536)
            except OSError:  # the other end is closed
                return
            if not block:
                return
            into.append(block)

    thread = threading.Thread(target=read, daemon=True)
    thread.start()
    return thread


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--cards", type=int, default=10_000)
    parser.add_argument("--no-profiler", action="store_true", help="workers without Dask's statistical profiler")
    args = parser.parse_args()
    print(f"machine: {machine()}")
    dask.config.set({"distributed.worker.profile.enabled": not args.no_profiler})  # the nannies pass it on
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        start = time.perf_counter()
        manifest = generate(folder, args.cards)
        print(f"generated {args.cards} cards in {time.perf_counter() - start:.0f} s")
        with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0",
                          silence_logs=logging.ERROR) as cluster:
            master, terminal = pty.openpty()
            shown: list[bytes] = []
            reader = _terminal_reader(master, shown)
            start = time.perf_counter()
            batch = subprocess.Popen([str(BIN / "pumpjack"), "batch", str(manifest), "--store",
                                      str(folder / "r.sqlite"), "--scheduler", cluster.scheduler_address],
                                     stdout=subprocess.PIPE, stderr=terminal, text=True,
                                     env={**os.environ, "TERM": "xterm", "COLUMNS": "100"})
            os.close(terminal)
            root, peak, peaks, cpu_before, cpu_after = psutil.Process(), 0, {}, {}, {}
            _memory(root, batch.pid, cpu_before)
            while batch.poll() is None:
                sample = _memory(root, batch.pid, cpu_after)
                peak = max(peak, sum(sample.values()))
                for name, rss in sample.items():
                    peaks[name] = max(peaks.get(name, 0), rss)
                time.sleep(SAMPLE)
            wall = time.perf_counter() - start
            out = batch.stdout.read()
            reader.join(timeout=5)
            os.close(master)
    screen = b"".join(shown).decode(errors="replace")
    counts = [int(done) for done, total in re.findall(r"(\d+)/(\d+)", screen) if int(total) == args.cards]
    if batch.returncode:
        sys.exit(f"pumpjack batch failed ({batch.returncode}): {screen.strip()[-500:]}")
    print(out.strip())
    profiler = "without" if args.no_profiler else "with"
    print(f"pumpjack batch --scheduler (LocalCluster, 2 workers x 1 thread, {profiler} Dask's profiler), {args.cards} "
          f"cards, torque + downhole: {wall:.1f} s end to end, {args.cards / wall:.0f} cards/s")
    print(f"peak RSS of all processes (sum, sampled every {SAMPLE:g} s): {peak / MIB:.0f} MiB")
    for name, rss in sorted(peaks.items()):
        print(f"  peak {name}: {rss / MIB:.0f} MiB")
    print(f"progress bar: {len(set(counts))} distinct counts drawn, the last {max(counts, default=0)}/{args.cards}")
    print(f"CPU over the run (user + system, to the last sample; {SAMPLE:g} s apart):")
    used = {name: seconds - cpu_before.get(name, 0.0) for name, seconds in sorted(cpu_after.items())}
    for name, seconds in used.items():
        print(f"  {name}: {seconds:.1f} s")
    workers = sum(seconds for name, seconds in used.items() if name.startswith("worker"))
    print(f"  the workers together: {workers:.1f} s, {workers / args.cards * 1e3:.2f} ms a card (their first task "
          f"imports the analysis)")


if __name__ == "__main__":
    main()
