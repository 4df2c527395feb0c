"""Time of the README's test command: wall clock and the CPU of every process it starts.

Run: .venv/bin/python benchmarks/bench_tests.py

Runs ``python -m pytest -q`` (the Makefile's ``make test`` after the install; two xdist workers
from pyproject.toml) in the repository and prints the tests counted, the wall time and the user
and system CPU of the run and its workers (``resource.getrusage(RUSAGE_CHILDREN)``, what
``/usr/bin/time`` reports).
"""

from __future__ import annotations

import resource
import subprocess
import sys
import time
from pathlib import Path

from timing import machine

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    print(f"machine: {machine()}")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "pytest", "-q"], cwd=ROOT, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    user, system = after.ru_utime - before.ru_utime, after.ru_stime - before.ru_stime
    print(done.stdout.strip().splitlines()[-1] if done.stdout.strip() else done.stderr.strip()[-500:])
    print(f"wall {wall:.1f} s, CPU {user:.1f} s user + {system:.1f} s system = {user + system:.1f} s")
    raise SystemExit(done.returncode)


if __name__ == "__main__":
    main()
