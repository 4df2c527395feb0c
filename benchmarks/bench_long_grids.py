"""Time and peak memory of the card commands and the JSON writer on a million crank angles.

Run: .venv/bin/python benchmarks/bench_long_grids.py [--steps 1000000]

Each command runs once in a fresh process, as a user would run it, writing to a file in
a temporary folder; the script prints its wall time and the peak resident memory of the
process (``os.wait4``): ``torque`` and ``reactions`` on SK8-3,5-4000 with its sample card
(the batched spatial kinetostatics and the exact torque basis), and ``kinematics -f json``
(the JSON writer). To measure another checkout of the package with the same environment,
put it first on ``PYTHONPATH``.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PUMPJACK = str(Path(sys.executable).parent / "pumpjack")
CARD = str(ROOT / "samples" / "sk8-3.5-4000-card.csv")


def run(argv: list[str]) -> tuple[float, int]:
    """Wall time [s] and peak resident memory [KiB] of one run."""
    start = time.perf_counter()
    process = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    elapsed = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{' '.join(argv)} failed: {process.stderr.read().decode().strip()}")
    return elapsed, usage.ru_maxrss


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=1_000_000)
    steps = str(parser.parse_args().steps)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}")
    with tempfile.TemporaryDirectory() as folder:
        out = str(Path(folder) / "out")
        commands = {
            "torque": [PUMPJACK, "torque", "sk8-3.5-4000", "--card", CARD, "--steps", steps, "-f", "csv", "-o", out],
            "reactions": [PUMPJACK, "reactions", "sk8-3.5-4000", "--card", CARD, "--steps", steps, "-f", "csv", "-o",
                          out],
            "kinematics -f json": [PUMPJACK, "kinematics", "sk8-3.5-4000", "--steps", steps, "-f", "json", "-o", out],
        }
        for name, argv in commands.items():
            elapsed, peak = run(argv)
            print(f"{name}, --steps {steps}: {elapsed:.1f} s, peak memory {peak / 1024:.0f} MiB")


if __name__ == "__main__":
    main()
