"""Reading card files as a fleet's batch reads them: CPU time per file of ``CardSource(path).raw()``.

Run: .venv/bin/python benchmarks/bench_card_files.py [--cards 2000] [--folder DIR]

Writes ``--cards`` card files as ``bench_batch.py`` generates a field (the bundled units' sample
cards varied: a header and 180 rows of time, position and load) into a temporary folder, or
takes the ``card-*.csv`` files of ``--folder``, and reads every one through
``pumpjack_cli.analysis.card_runs.CardSource(path).raw()``, the batch's call (the file read,
its format told, its rows parsed, a time card looked at for several strokes; no unit). Prints
the CPU time per card, the best of three passes (``time.process_time``: other jobs on the
machine count less than in wall-clock time), then the same for each layout sample of
``samples/``.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bench_batch import generate
from pumpjack_cli.analysis.card_runs import CardSource
from timing import machine

SAMPLES = Path(__file__).resolve().parent.parent / "samples"
#: Layout samples and the card units a block needs.
LAYOUTS = {"sk8-3.5-4000-card.csv": None, "sk8-3.5-4000-preamble.csv": None, "sk8-3.5-4000-card.json": None,
           "sk8-3.5-4000-card.hex": "field", "sk8-3.5-4000-card.bin": "field", "sk8-3.5-4000-recording.csv": None}


def cpu_per_read(sources: list[CardSource], passes: int = 3) -> float:
    """Least CPU time [s] of ``passes`` passes over ``sources``, per source."""
    for source in sources[:50]:
        source.raw()
    best = float("inf")
    for _ in range(passes):
        start = time.process_time()
        for source in sources:
            source.raw()
        best = min(best, time.process_time() - start)
    return best / len(sources)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cards", type=int, default=2000)
    parser.add_argument("--folder", type=Path)
    args = parser.parse_args()
    print(f"machine: {machine()}, numpy {np.__version__}")
    with tempfile.TemporaryDirectory() as scratch:
        folder = args.folder or Path(scratch)
        if args.folder is None:
            generate(folder, args.cards)
        files = sorted(folder.glob("card-*.csv"))
        print(f"{len(files)} field cards: {cpu_per_read([CardSource(path) for path in files]) * 1e3:.4f} ms CPU a card")
    for name, units in LAYOUTS.items():
        reading = cpu_per_read([CardSource(SAMPLES / name, units=units)] * 200)
        print(f"{name:28s} {reading * 1e3:.4f} ms CPU a read")


if __name__ == "__main__":
    sys.exit(main())
