"""Throughput of the kinematics core and wall time of `pumpjack kinematics`.

Run: .venv/bin/python benchmarks/bench_kinematics.py
Prints crank positions per second for the closed-form core (beam and pitman angles
with both derivatives, for one array of crank angles) and for the whole
uniform-rotation result, then the median wall time of the command on a bundled
unit (a fresh interpreter each run, output to /dev/null).
"""

from __future__ import annotations

import os
import platform
import shutil
import statistics
import subprocess
import sys
import time

import numpy as np

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.beam.linkage import motion
from timing import best_of


def main() -> None:
    linkage = load_unit("sk8-3.5-4000").geometry.mechanism()
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    for n in (360, 100_000, 1_000_000):
        theta = crank_grid(n)
        seconds = best_of(lambda: motion(linkage, theta), 5)
        print(f"core motion(), {n:>9} crank positions: {seconds * 1e3:8.2f} ms, {n / seconds:12.3e} positions/s")
    seconds = best_of(lambda: uniform_kinematics(linkage, 1.1422, 360), 20)
    print(f"uniform_kinematics(), 360 steps with summary: {seconds * 1e3:.2f} ms")
    command = [shutil.which("pumpjack") or "pumpjack", "kinematics", "sk8-3.5-4000", "-f", "csv"]
    walls = []
    for _ in range(10):
        start = time.perf_counter()
        subprocess.run(command, stdout=subprocess.DEVNULL, check=True)
        walls.append(time.perf_counter() - start)
    print(f"`{' '.join(command[1:])}` wall time: median {statistics.median(walls):.3f} s, "
          f"min {min(walls):.3f} s over {len(walls)} runs")


if __name__ == "__main__":
    sys.exit(main())
