"""Throughput of the full kinetostatic solve (spatial kinematics, loads, reactions).

Run: .venv/bin/python benchmarks/bench_reactions.py
Prints crank positions per second for `rational_mechanism` on SK8-3,5-4000 with its
sample card: batched 8 x 8 kinematic solves, then batched 20 x 20 normal equations
of the structural group 2-3-4-5 and the crank, for the whole revolution at once.
"""

from __future__ import annotations

import os
import platform
from pathlib import Path

import numpy as np

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import card_load
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.beam.kinetostatics import rational_mechanism
from pumpjack_cli.readers.cards import read_card
from timing import best_of

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    config = load_unit("sk8-3.5-4000")
    spatial, masses = config.geometry.spatial(), config.masses.model()
    card = place(read_card(ROOT / "samples" / "sk8-3.5-4000-card.csv"), spatial.planar).card
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"numpy {np.__version__}")
    for n in (360, 10_000, 100_000):
        theta = crank_grid(n)
        load = card_load(card, theta)
        best = best_of(lambda: rational_mechanism(spatial, masses, theta, 1.1422, 0.0, load), 3)
        print(f"rational_mechanism(), {n:>7} crank positions: {best * 1e3:8.1f} ms, {n / best:10.3e} positions/s")


if __name__ == "__main__":
    main()
