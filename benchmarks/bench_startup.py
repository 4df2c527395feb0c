"""Start-up cost of the command line, against the floor of importing its libraries.

Run: .venv/bin/python benchmarks/bench_startup.py [--repeat 7]

Each command is run ``repeat`` times, interleaved with the floor
``python -c "import numpy, pydantic, typer"`` so that both see the same machine load;
the script prints the median wall times and their ratios:

* ``pumpjack --help`` and ``pumpjack units`` against the floor (aim: below 0.5; they
  import no numpy);
* ``pumpjack kinematics sk8-3.5-4000 -f csv`` against the floor (aim: at most 1.3);
* the same command's default terminal table against its CSV run (aim: at most 1.15);
* ``pumpjack kinematics sk8-3.5-4000 --steps 1000000 -f csv -o FILE``: wall time and
  peak resident memory of the process (aim: below 8 s and 350 MiB);
* the lower bounds of the first two aims (:data:`BOUNDS`), against the same floor.

The processes run as after a normal install: Python's bytecode caches are written
(``PYTHONDONTWRITEBYTECODE`` is removed from their environment; pip compiles the
libraries at install, and the package's own modules are compiled by a warm-up run), so
that the package is not charged for compiling its sources on every run while the
libraries of the floor are not.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BIN = Path(sys.executable).parent
PUMPJACK = str(BIN / "pumpjack")
FLOOR = [sys.executable, "-c", "import numpy, pydantic, typer"]
COMMANDS = {
    "help": [PUMPJACK, "--help"],
    "units": [PUMPJACK, "units", "-f", "csv"],
    "kinematics csv": [PUMPJACK, "kinematics", "sk8-3.5-4000", "-f", "csv"],
    "kinematics table": [PUMPJACK, "kinematics", "sk8-3.5-4000", "-f", "table"],
}
#: Lower bounds of the two aims, timed the same way: what any typer command pays, what
#: reading the bundled unit files adds, and what validating one pydantic model adds to the floor.
BOUNDS = {
    "import typer": [sys.executable, "-c", "import typer"],
    "import typer + the bundled TOML files": [
        sys.executable, "-c", "import typer, tomllib, pumpjack_cli.configs as c, pathlib\n"
        "for f in sorted(pathlib.Path(c.__path__[0]).glob('*.toml')): tomllib.loads(f.read_text())"],
    "floor + one pydantic model": [
        sys.executable, "-c", "import numpy, pydantic, typer\nfrom pydantic import BaseModel\n"
        "class M(BaseModel):\n    x: float\nM(x=1)"],
}


ENVIRONMENT = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}


def run(argv: list[str]) -> tuple[float, int]:
    """Wall time [s] and peak resident memory [KiB] of one run, output discarded."""
    start = time.perf_counter()
    process = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENVIRONMENT)
    _, status, usage = os.wait4(process.pid, 0)
    elapsed = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} failed with exit code {process.returncode}")
    return elapsed, usage.ru_maxrss


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=7)
    repeat = parser.parse_args().repeat
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, {platform.python_implementation()} "
          f"{platform.python_version()}, {platform.system()} {platform.release()}")
    timed = {**COMMANDS, **BOUNDS}
    times: dict[str, list[float]] = {"floor": [], **{name: [] for name in timed}}
    for argv in timed.values():
        run(argv)
    for _ in range(repeat):
        times["floor"].append(run(FLOOR)[0])
        for name, argv in timed.items():
            times[name].append(run(argv)[0])
    median = {name: statistics.median(values) for name, values in times.items()}
    floor = median["floor"]
    print(f"floor (import numpy, pydantic, typer): {floor * 1e3:.0f} ms median of {repeat}")
    for name, aim in (("help", 0.5), ("units", 0.5), ("kinematics csv", 1.3)):
        print(f"pumpjack {name}: {median[name] * 1e3:.0f} ms = {median[name] / floor:.2f} x floor (aim <= {aim})")
    table = median["kinematics table"] / median["kinematics csv"]
    print(f"pumpjack kinematics table: {median['kinematics table'] * 1e3:.0f} ms = {table:.2f} x the CSV run "
          f"(aim <= 1.15)")
    for name in BOUNDS:
        print(f"bound: {name}: {median[name] * 1e3:.0f} ms = {median[name] / floor:.2f} x floor")
    with tempfile.TemporaryDirectory() as folder:
        big = [PUMPJACK, "kinematics", "sk8-3.5-4000", "--steps", "1000000", "-f", "csv", "-o",
               str(Path(folder) / "k.csv")]
        elapsed, peak = run(big)
        size = (Path(folder) / "k.csv").stat().st_size
    print(f"kinematics --steps 1000000 -f csv -o FILE: {elapsed:.2f} s, peak memory {peak / 1024:.0f} MiB "
          f"(aim < 8 s, < 350 MiB), file {size / 2**20:.0f} MiB")


if __name__ == "__main__":
    main()
