"""Timing helper shared by the benchmark scripts."""

from __future__ import annotations

import time


def best_of(func, repeats: int) -> float:
    """Shortest of ``repeats`` wall-clock timings of ``func()`` [s]."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return min(times)
