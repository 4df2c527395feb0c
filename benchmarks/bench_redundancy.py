"""Speed and memory of the real mechanism (compare-redundancy's core).

Run: .venv/bin/python benchmarks/bench_redundancy.py
Prints positions per second of `real_mechanism` on 7SK12-2,5-5600 with its sample card
and a 0.1 deg crank-phase error (rigid pins, and with 1 mrad of clearance at every pin),
and the wall time and peak resident memory of `pumpjack compare-redundancy
7sk12-2.5-5600 --steps 36000 -f csv -o FILE` in a fresh process.
"""

from __future__ import annotations

import dataclasses
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import card_load
from pumpjack_cli.core.beam.redundancy import JointCompliance, PinTilts, real_mechanism
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.readers.cards import read_card
from timing import best_of

ROOT = Path(__file__).resolve().parent.parent
UNIT = "7sk12-2.5-5600"


def main() -> None:
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"numpy {np.__version__}")
    config = load_unit(UNIT)
    ideal = config.geometry.spatial()
    actual = dataclasses.replace(ideal, crank_phase_offset=np.radians(0.1))
    card = place(read_card(ROOT / "samples" / f"{UNIT}-card.csv"), ideal.planar)
    masses, section = config.masses.model(), config.pitman_section.model()
    for label, joints in (("rigid pins", JointCompliance()), ("1 mrad clearance", JointCompliance(
            crank_pin_clearance=1e-3, equalizer_pin_clearance=1e-3))):
        for n in (3600, 36000):
            theta = crank_grid(n)
            load = card_load(card.card, theta)
            best = best_of(lambda: real_mechanism(ideal, actual, PinTilts(), section, masses, theta, card.speed, 0.0,
                                                  load, joints=joints), 3)
            print(f"real_mechanism, {label:16}, {n:6d} positions: {best:6.3f} s, {n / best:9.0f} positions/s")
    with tempfile.TemporaryDirectory() as folder:
        argv = [str(Path(sys.executable).parent / "pumpjack"), "compare-redundancy", UNIT, "--card",
                str(ROOT / "samples" / f"{UNIT}-card.csv"), "--crank-phase", "0.1 deg", "--steps", "36000", "-f",
                "csv", "-o", str(Path(folder) / "r.csv")]
        start = time.perf_counter()
        process = subprocess.Popen(argv)
        _, status, usage = os.wait4(process.pid, 0)
        elapsed = time.perf_counter() - start
        assert os.waitstatus_to_exitcode(status) == 0
    print(f"pumpjack compare-redundancy --steps 36000 -f csv -o FILE: {elapsed:.1f} s, "
          f"peak memory {usage.ru_maxrss / 1024:.0f} MiB")


if __name__ == "__main__":
    main()
