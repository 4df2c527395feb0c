"""Start-up cost of the command line, in CPU time, against the floor of importing its libraries.

Run: .venv/bin/python benchmarks/bench_startup.py [--repeat 9]

The floor is what any command of a typer + numpy + pydantic tool pays before its own
work: ``python -c "import numpy, typer; from pydantic import BaseModel"`` with one model
defined and validated (``import pydantic`` alone is lazy and loads nothing, so the floor
validates a model as a unit file does). Each command is run ``repeat`` times, interleaved
with the floor so that both see the same machine load; the script prints the median CPU
time (user + system of the process, from ``wait4``) and the ratios:

* ``pumpjack kinematics sk8-3.5-4000 -f csv`` against the floor (aim: at most 1.3);
* ``pumpjack --help`` and ``pumpjack units`` against the floor (they import no numpy);
* the same kinematics command's terminal table against its CSV run (aim: at most 1.15);
* ``pumpjack kinematics sk8-3.5-4000 --steps 1000000 -f csv -o FILE``: wall time and peak
  resident memory (aim: below 8 s and 350 MiB).

The processes run as after a normal install: Python's bytecode caches are written
(``PYTHONDONTWRITEBYTECODE`` is removed from their environment; pip compiles the
libraries at install, and the package's own modules are compiled by a warm-up run).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from timing import machine

BIN = Path(sys.executable).parent
PUMPJACK = str(BIN / "pumpjack")
FLOOR = [sys.executable, "-c", "import numpy, typer\nfrom pydantic import BaseModel\n"
         "class Unit(BaseModel):\n    stroke: float\nUnit(stroke=1.0)"]
COMMANDS = {
    "help": [PUMPJACK, "--help"],
    "units": [PUMPJACK, "units", "-f", "csv"],
    "kinematics csv": [PUMPJACK, "kinematics", "sk8-3.5-4000", "-f", "csv"],
    "kinematics table": [PUMPJACK, "kinematics", "sk8-3.5-4000", "-f", "table"],
}
ENVIRONMENT = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}


def run(argv: list[str]) -> tuple[float, float, int]:
    """CPU time [s] (user + system), wall time [s] and peak resident memory [KiB] of one run,
    output discarded."""
    start = time.perf_counter()
    process = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENVIRONMENT)
    _, status, usage = os.wait4(process.pid, 0)
    elapsed = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{' '.join(argv)} failed with exit status {status}")
    return usage.ru_utime + usage.ru_stime, elapsed, usage.ru_maxrss


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=9)
    repeat = parser.parse_args().repeat
    print(f"machine: {machine()}")
    cpu: dict[str, list[float]] = {"floor": [], **{name: [] for name in COMMANDS}}
    for argv in COMMANDS.values():
        run(argv)
    for _ in range(repeat):
        cpu["floor"].append(run(FLOOR)[0])
        for name, argv in COMMANDS.items():
            cpu[name].append(run(argv)[0])
    median = {name: statistics.median(values) for name, values in cpu.items()}
    floor = median["floor"]
    print(f"floor (numpy, typer, one pydantic model validated): {floor * 1e3:.0f} ms CPU, median of {repeat}")
    for name, aim in (("kinematics csv", "<= 1.3"), ("help", "no numpy"), ("units", "no numpy")):
        print(f"pumpjack {name}: {median[name] * 1e3:.0f} ms CPU = {median[name] / floor:.2f} x floor (aim {aim})")
    table = median["kinematics table"] / median["kinematics csv"]
    print(f"pumpjack kinematics table: {median['kinematics table'] * 1e3:.0f} ms CPU = {table:.2f} x the CSV run "
          f"(aim <= 1.15)")
    with tempfile.TemporaryDirectory() as folder:
        big = [PUMPJACK, "kinematics", "sk8-3.5-4000", "--steps", "1000000", "-f", "csv", "-o",
               str(Path(folder) / "k.csv")]
        _, elapsed, peak = run(big)
        size = (Path(folder) / "k.csv").stat().st_size
    print(f"kinematics --steps 1000000 -f csv -o FILE: {elapsed:.2f} s, peak memory {peak / 1024:.0f} MiB "
          f"(aim < 8 s, < 350 MiB), file {size / 2**20:.0f} MiB")


if __name__ == "__main__":
    main()
