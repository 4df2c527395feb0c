"""Timing helper shared by the benchmark scripts."""

from __future__ import annotations

import os
import platform
import time
from pathlib import Path


def best_of(func, repeats: int, clock=time.perf_counter) -> float:
    """Shortest of ``repeats`` timings of ``func()`` [s] by ``clock`` (default: the wall clock;
    ``time.process_time`` for the process's CPU)."""
    times = []
    for _ in range(repeats):
        start = clock()
        func()
        times.append(clock() - start)
    return min(times)


def machine() -> str:
    """The machine a benchmark ran on, for the record: architecture, processor model
    (/proc/cpuinfo), cores, Python."""
    try:
        lines = Path("/proc/cpuinfo").read_text().splitlines()
        model = next((line.split(":", 1)[1].strip() for line in lines if line.startswith("model name")), "")
    except OSError:
        model = ""
    return (f"{platform.machine()}, {model or platform.processor() or 'unknown CPU'}, {os.cpu_count()} cores, "
            f"{platform.python_implementation()} {platform.python_version()}")


def process_tree(root, attributes: tuple[str, ...]) -> dict[int, dict]:
    """The ``attributes`` (psutil's names: ``memory_info``, ``cmdline``, ``cpu_times``) of the
    psutil process ``root`` and of every process under it, by pid; one that ended meanwhile is
    left out. psutil comes with the ``dev`` and ``dask`` extras."""
    import psutil

    found = {}
    for process in [root, *root.children(recursive=True)]:
        try:
            found[process.pid] = process.as_dict(attrs=list(attributes))
        except psutil.NoSuchProcess:
            continue
    return found
