"""Time of the README's test command: wall clock and the CPU of every process it starts.

Run: .venv/bin/python benchmarks/bench_tests.py [--split] [-- PYTEST_ARGUMENTS]

Prints the CPU of a fixed pure-Python loop (the machine's calibration), then runs
``python -m pytest -q`` (the Makefile's ``make test`` after the install; one process, or the
workers of ``-n`` when given after ``--``) in the repository and prints the tests counted, the
wall time and the user and system CPU of the run and every process it started
(``resource.getrusage(RUSAGE_CHILDREN)``, what ``/usr/bin/time`` reports). With ``--split`` the tests run with the plugin
``cpu_per_test.py`` (the CPU of each test, its own and its children's), and the CPU is
also printed by the groups of :data:`GROUPS`, the other tests, and what no test counts
(the interpreters' start-up, imports and collection in the pytest processes).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from timing import best_of, machine

ROOT = Path(__file__).resolve().parent.parent


#: Groups of tests whose CPU ``--split`` prints: (label, test ids containing one of these).
GROUPS = (
    ("extreme unit-file values through the commands", ("test_extreme_field_values_are_refused_by_name",)),
    ("documented commands, documents' tables, glossary runs",
     ("test_docs_commands.py", "test_doc_tables.py", "test_glossary.py")),
    ("batch against the single commands, 200 cards", ("test_batch_results_equal_the_single_commands",)),
    ("the fleet's fault tests (real processes, Dask)", ("test_batch_faults.py",)),
    ("mypy over the core", ("test_the_core_type_checks",)),
)


def _split(folder: Path, total: float) -> None:
    """The CPU of the groups, of the other tests and of what no test counts, from the plugin's files."""
    tests = [row for path in folder.glob("*.json") for row in json.loads(path.read_text(encoding="utf-8"))]
    counted = 0.0
    for label, parts in GROUPS:
        cpu = sum(own + children for name, own, children in tests if any(part in name for part in parts))
        counted += cpu
        print(f"  {label}: {cpu:.1f} s")
    tested = sum(own + children for _, own, children in tests)
    print(f"  the other tests ({len(tests)} in all): {tested - counted:.1f} s")
    print(f"  what no test counts (start-up, imports, collection of the pytest processes): {total - tested:.1f} s")


def reference_cpu() -> float:
    """The best CPU time of three runs of a fixed pure-Python loop [s]: the interpreter's speed on
    this machine, to which the suite's CPU is roughly proportional (its tests are mostly Python),
    so that runs on different days' machines can be compared."""
    return best_of(lambda: sum(i * i % 7 for i in range(2_000_000)), 3, time.process_time)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--split", action="store_true", help="also the CPU by groups of tests (cpu_per_test.py)")
    parser.add_argument("pytest_args", nargs="*", help="more arguments of pytest (after --), e.g. -n auto")
    arguments = parser.parse_args()
    split = arguments.split
    print(f"machine: {machine()}")
    print(f"reference loop: {reference_cpu():.3f} s of CPU")
    with tempfile.TemporaryDirectory() as folder:
        command, environment = [sys.executable, "-m", "pytest", "-q", *arguments.pytest_args], dict(os.environ)
        if split:
            command += ["-p", "cpu_per_test"]
            environment["PUMPJACK_CPU_SPLIT"] = folder
            environment["PYTHONPATH"] = os.pathsep.join(filter(None, (str(Path(__file__).parent),
                                                                      environment.get("PYTHONPATH"))))
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, env=environment)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        user, system = after.ru_utime - before.ru_utime, after.ru_stime - before.ru_stime
        lines = done.stdout.strip().splitlines()
        for line in lines:
            if line.startswith(("FAILED", "ERROR")):
                print(line)
        print(lines[-1] if lines else done.stderr.strip()[-500:])
        print(f"wall {wall:.1f} s, CPU {user:.1f} s user + {system:.1f} s system = {user + system:.1f} s")
        if split:
            _split(Path(folder), user + system)
    raise SystemExit(done.returncode)


if __name__ == "__main__":
    main()
