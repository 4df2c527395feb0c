"""Throughput of `pumpjack batch` on a generated field, against single-card commands.

Run: .venv/bin/python benchmarks/bench_batch.py [--cards 10000] [--singles 10]

Generates ``--cards`` cards for the bundled beam units (variations of the sample cards:
the load scaled about its mean by 0.9-1.1, Gaussian noise of 0.3 % of the load range,
the time stamps stretched for a speed of 0.95-1.05 times the card's), a manifest with
one well per 20 cards and a time stamp per card, and runs ``pumpjack batch MANIFEST``
(torque and downhole, every core) end to end as a user would, in a fresh process. Then
runs ``pumpjack torque`` and ``pumpjack downhole`` on ``--singles`` of the cards as a
shell loop would (one process per card and analysis) and prints both rates.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(sys.executable).parent
UNITS = ("sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54", "c-80d-133-48")


def sample(unit: str) -> tuple[list[str], np.ndarray]:
    lines = (ROOT / "samples" / f"{unit}-card.csv").read_text(encoding="utf-8").splitlines()
    body = [line for line in lines if not line.startswith("#")]
    return body[0], np.array([[float(x) for x in line.split(",")] for line in body[1:]])


def generate(folder: Path, cards: int, seed: int = 1) -> Path:
    rng = np.random.default_rng(seed)
    samples = {unit: sample(unit) for unit in UNITS}
    rows = ["well,unit,card,timestamp"]
    for k in range(cards):
        unit = UNITS[k % len(UNITS)]
        header, data = samples[unit]
        card = data.copy()
        mean = card[:, 2].mean()
        card[:, 2] = mean + rng.uniform(0.9, 1.1) * (card[:, 2] - mean)
        card[:, 2] += rng.normal(0.0, 0.003 * np.ptp(data[:, 2]), len(card))
        card[:, 0] *= 1.0 / rng.uniform(0.95, 1.05)
        name = f"card-{k:05d}.csv"
        (folder / name).write_text(header + "\n" + "\n".join(f"{t:.4f},{s:.5f},{w:.4f}" for t, s, w in card) + "\n",
                                   encoding="utf-8")
        rows.append(f"well-{unit}-{k // (20 * len(UNITS)):03d},{unit},{name},2026-11-{1 + k % 28:02d}T{k % 24:02d}:00")
    manifest = folder / "manifest.csv"
    manifest.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return manifest


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--cards", type=int, default=10_000)
    parser.add_argument("--singles", type=int, default=10)
    args = parser.parse_args()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        manifest = generate(folder, args.cards)
        start = time.perf_counter()
        done = subprocess.run([str(BIN / "pumpjack"), "batch", str(manifest), "--store", str(folder / "r.sqlite")],
                              capture_output=True, text=True, check=True)
        batch = time.perf_counter() - start
        print(done.stdout.strip())
        print(f"pumpjack batch, {args.cards} cards, torque + downhole: {batch:.1f} s end to end, "
              f"{args.cards / batch:.0f} cards/s")
        start = time.perf_counter()
        for k in range(args.singles):
            card = folder / f"card-{k:05d}.csv"
            for command in ("torque", "downhole"):
                subprocess.run([str(BIN / "pumpjack"), command, UNITS[k % len(UNITS)], "--card", str(card), "-f",
                                "csv"], capture_output=True, check=True)
        single = (time.perf_counter() - start) / args.singles
        print(f"shell loop of single commands (torque + downhole per card): {1 / single:.2f} cards/s; "
              f"batch is {single * args.cards / batch:.0f} x faster")


if __name__ == "__main__":
    main()
