"""Speed of the gearbox-torque core on SK8-3,5-4000 with its sample card.

Run: .venv/bin/python benchmarks/bench_torque.py
Prints the time of the API net torque with its components, the exact method and the
three balance optimisers for 3600 crank angles, one core.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import platform  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from pumpjack_cli.analysis.card_runs import place  # noqa: E402
from pumpjack_cli.config import load_unit  # noqa: E402
from pumpjack_cli.core.beam.balance import recommend_counterbalance  # noqa: E402
from pumpjack_cli.core.beam.card import card_load  # noqa: E402
from pumpjack_cli.core.beam.counterbalance import counterbalance_from_masses  # noqa: E402
from pumpjack_cli.core.beam.torque import exact_net_torque, torque_components  # noqa: E402
from pumpjack_cli.core.sampling import crank_grid  # noqa: E402
from pumpjack_cli.readers.cards import read_card  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def best(function, repeat: int = 20) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    unit = load_unit("sk8-3.5-4000")
    linkage, masses = unit.geometry.mechanism(), unit.masses.model()
    spatial = unit.geometry.spatial()
    theta = crank_grid(3600)
    load = card_load(place(read_card(ROOT / "samples" / "sk8-3.5-4000-card.csv"), linkage).card, theta)
    balance = counterbalance_from_masses(linkage, masses)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}")
    print(f"API components, 3600 angles: {best(lambda: torque_components(linkage, theta, load, balance)) * 1e3:.2f} ms")
    print(f"exact method, 3600 angles: {best(lambda: exact_net_torque(spatial, masses, theta, load)) * 1e3:.1f} ms")
    for criterion in ("equal-peaks", "min-rms", "min-peak"):
        seconds = best(lambda: recommend_counterbalance(criterion, linkage, theta, load, balance))
        print(f"balance {criterion}, 3600 angles: {seconds * 1e3:.2f} ms")


if __name__ == "__main__":
    main()
