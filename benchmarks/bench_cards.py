"""Throughput of the card-file reader: cards per second for 200-point cards of each layout;
and the placement of many time cards of one unit, one by one and in groups.

Run: .venv/bin/python benchmarks/bench_cards.py
Each card is read from memory through ``read_card("-", stream=...)`` (parsing, no unit)
and placed on the unit's crank-angle axis (``place``: the branch map for a position
card, the least-squares time fit for a time card), without disk access; both steps
are timed apart and together. Fleets read thousands of cards; a 200-point card should
take well under 5 ms.

Then CARDS variations of the SK8-3,5-4000 sample card (180 samples; varied as
``bench_batch.py`` varies them, in memory) are placed one by one (``place_card``) and in
groups of GROUP (``place_cards``: one time fit for the group), in microseconds per card.
"""

from __future__ import annotations

import io
import sys
from pathlib import Path

import numpy as np

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.core.cards import CardSamples, place_card, place_cards
from pumpjack_cli.readers.cards import read_card
from timing import best_of, machine

POINTS = 200
#: Time cards placed one by one and in groups, and the size of a group.
CARDS = 1000
GROUP = 100
SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "sk8-3.5-4000-card.csv"


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


def varied(count: int, seed: int = 1) -> list[CardSamples]:
    """``count`` variations of the SK8 sample card as ``bench_batch.py`` makes them: the load scaled
    about its mean by 0.9-1.1 with Gaussian noise of 0.3 % of its range, the time stamps stretched
    for 0.95-1.05 times the speed."""
    raw = read_card(SAMPLE)
    rng = np.random.default_rng(seed)
    mean = raw.load.mean()
    return [CardSamples(load=mean + rng.uniform(0.9, 1.1) * (raw.load - mean)
                        + rng.normal(0.0, 0.003 * np.ptp(raw.load), raw.load.size),
                        position=raw.position, time=raw.time / rng.uniform(0.95, 1.05), source=f"card-{k:04d}")
            for k in range(count)]


def main() -> None:
    linkage = load_unit("sk8-3.5-4000").geometry.mechanism()
    print(f"machine: {machine()}, numpy {np.__version__}")
    for name, text in texts(linkage).items():
        raw = read_card("-", stream=io.StringIO(text))
        place(raw, linkage)
        reading = best_of(lambda: read_card("-", stream=io.StringIO(text)), 50)
        placing = best_of(lambda: place(raw, linkage), 50)
        print(f"{POINTS}-point {name}: read_card {reading * 1e3:6.3f} ms + place {placing * 1e3:6.3f} ms, "
              f"{1 / (reading + placing):8.0f} cards/s")
    cards = varied(CARDS)
    alone = best_of(lambda: [place_card(linkage, **card) for card in cards], 3)
    grouped = best_of(lambda: [place_cards(linkage, cards[k:k + GROUP]) for k in range(0, CARDS, GROUP)], 3)
    print(f"{CARDS} time cards of {cards[0]['time'].size} samples: place_card one by one {alone / CARDS * 1e6:6.0f} us/card, "
          f"place_cards in groups of {GROUP} {grouped / CARDS * 1e6:6.0f} us/card ({alone / grouped:.1f} x)")


if __name__ == "__main__":
    sys.exit(main())
