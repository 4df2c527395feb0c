"""Throughput of the card-file reader: cards per second for 200-point cards of each layout.

Run: .venv/bin/python benchmarks/bench_cards.py
Each card is read from memory through ``read_card("-", stream=...)`` (parsing, no unit)
and placed on the unit's crank-angle axis (``place``: the branch map for a position
card, the least-squares time fit for a time card), without disk access; both steps
are timed apart and together. Fleets read thousands of cards; a 200-point card should
take well under 5 ms.
"""

from __future__ import annotations

import io
import os
import platform
import sys

import numpy as np

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.readers.cards import read_card
from timing import best_of

POINTS = 200


def texts(linkage) -> dict[str, str]:
    """A crank-angle, a position and a time card of POINTS samples, CSV text."""
    run = uniform_kinematics(linkage, 1.1422, POINTS)
    load = 40e3 + 12e3 * (run.rod.velocity > 0) + 2e3 * np.sin(run.crank_angle)

    def rows(*columns):
        return "\n".join(",".join(f"{float(v):.6g}" for v in row) for row in zip(*columns))

    return {
        "crank-angle card": "crank_angle_rad,load_n\n" + rows(run.crank_angle, load),
        "position card": "position_m,load_n\n" + rows(run.rod.position, load),
        "time card (fit)": "time_s,position_m,load_n\n" + rows(run.time, run.rod.position, load),
        "time card, ;-delimited, decimal comma, CRLF, BOM": "\ufefftime_s;position_m;load_n\r\n" + rows(
            run.time, run.rod.position, load).replace(",", ";").replace(".", ",").replace("\n", "\r\n"),
    }


def main() -> None:
    linkage = load_unit("sk8-3.5-4000").geometry.mechanism()
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    for name, text in texts(linkage).items():
        raw = read_card("-", stream=io.StringIO(text))
        place(raw, linkage)
        reading = best_of(lambda: read_card("-", stream=io.StringIO(text)), 50)
        placing = best_of(lambda: place(raw, linkage), 50)
        print(f"{POINTS}-point {name}: read_card {reading * 1e3:6.3f} ms + place {placing * 1e3:6.3f} ms, "
              f"{1 / (reading + placing):8.0f} cards/s")


if __name__ == "__main__":
    sys.exit(main())
