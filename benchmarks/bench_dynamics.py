"""Wall time of one periodic solve of the equation of motion.

Run: .venv/bin/python benchmarks/bench_dynamics.py
Prints the best time of `steady_state` on SK8-3,5-4000 (coefficient tables, splines,
shooting with DOP853 over both strokes, output on 360 crank angles and the summary
on 3600) with the [SK8Rotation2013] well model and with its sample dynamometer card, at the
default and a loose tolerance. The sample card (elastic rods) asks more than the seed
motor's pull-out torque, so its load swing is halved about its mean here, as the tests do.
"""

from __future__ import annotations

import os
import platform
from pathlib import Path

import numpy as np

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import Card
from pumpjack_cli.core.dynamics.periodic import DEFAULT_RTOL, steady_state
from pumpjack_cli.readers.cards import read_card
from timing import best_of

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    config = load_unit("sk8-3.5-4000")
    well = config.machine()
    sample = place(read_card(ROOT / "samples" / "sk8-3.5-4000-card.csv"), config.geometry.mechanism()).card
    mean = float(np.mean(sample.load))
    card = config.machine(Card(sample.crank_angle, mean + 0.5 * (sample.load - mean)))
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"numpy {np.__version__}")
    steady_state(well)  # imports scipy
    for label, machine, rtol in (("well model", well, DEFAULT_RTOL), ("well model", well, 1e-8),
                                 ("half card", card, DEFAULT_RTOL), ("half card", card, 1e-8)):
        result = steady_state(machine, rtol=rtol)
        best = best_of(lambda: steady_state(machine, rtol=rtol), 5)
        c = result.summary.convergence
        print(f"steady_state(), {label:11}, rtol {rtol:.0e}: {best * 1e3:7.1f} ms "
              f"({c.iterations} shots, {c.evaluations} right-hand-side evaluations)")


if __name__ == "__main__":
    main()
