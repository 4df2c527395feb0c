"""CPU of the downhole analysis of K cards of one unit: the damping search, the Gibbs transfer,
the pump-card figures and the diagnosis features.

Run: .venv/bin/python benchmarks/bench_gibbs.py [--cards 2000] [--group 64] [--manifest FILE] [--profile]

Takes the first ``--cards`` cards of a generated field (``bench_batch.generate``; made in a
temporary folder unless ``--manifest`` names one), places them and puts them on their time
grids (360 samples) outside the timing, in groups of ``--group`` cards of one unit, and then
times, best of 3 with ``time.process_time`` on one thread, what :func:`..downhole.downholes`
does with a vertical well's cards after that:

* ``damping``: the energy balance's damping factors (``damping_factors``: the root search,
  each evaluation a Gibbs transfer of the pump's end and the pump-card figures);
* ``rest``: the pump cards at those dampings, their figures, their conditions (``diagnose``),
  the two cards' works and the rod loads.

It prints ms per card of both and their sum, and the evaluations of the energy balance per
group. ``--profile`` adds cProfile's top functions of one pass.

The cards are placed in this process, as a batch worker places them, and not read from a
file of time cards: placing frees large arrays, which raises glibc's thresholds for giving
memory back, and without that history the (K, H) temporaries of every evaluation are page
faults again each time (some 40 % more CPU on the machine measured), which a worker does not pay.
"""

from __future__ import annotations

import os

for _variable in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_variable] = "1"

import argparse  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

from bench_batch import generate  # noqa: E402
from timing import machine  # noqa: E402


def groups(manifest: Path, cards: int, size: int) -> list[tuple]:
    """(unit, string, time cards) of every group of ``size`` placed cards of one unit."""
    from pumpjack_cli.analysis.batch import per_card
    from pumpjack_cli.analysis.card_runs import time_cards
    from pumpjack_cli.analysis.downhole import DEFAULT_SAMPLES
    from pumpjack_cli.readers.manifest import read_manifest

    settings = per_card.Options()
    by_unit: dict[str, list] = {}
    for job in read_manifest(manifest)[:cards]:
        strokes = per_card._strokes(job, settings)
        by_unit.setdefault(job.unit, []).extend(s for s in strokes if isinstance(s, per_card._Stroke))
    found = []
    for strokes in by_unit.values():
        unit = per_card._unit(strokes[0].job, None)[0]
        for k in range(0, len(strokes), size):
            members = [s.card for s in strokes[k: k + size]]
            per_card._PlacedOnce.place_together(members, unit, None)
            surfaces, _, _ = time_cards(unit, unit.geometry.mechanism(), members, None, DEFAULT_SAMPLES, "auto")
            found.append((unit, unit.rods(), [surfaces[i][1] for i in sorted(surfaces)]))
    return found


def damping(unit, string, surface) -> np.ndarray:
    from pumpjack_cli.analysis.downhole import damping_factors

    return np.array([nu for nu, _ in damping_factors(unit, None, string, surface, "gibbs")])


def rest(unit, string, surface, nus) -> None:
    from pumpjack_cli.analysis.downhole import reference_fluid_load
    from pumpjack_cli.core.rods.analysis import card_work, summarise_pump_card, taper_loads
    from pumpjack_cli.core.rods.diagnosis import diagnose
    from pumpjack_cli.core.rods.downhole import pump_card

    periods = np.array([s.period for s in surface])
    positions, loads = np.array([s.position for s in surface]), np.array([s.load for s in surface])
    pumps = pump_card(string, periods, positions, loads, fluid_density=unit.require_well().fluid_density,
                      damping_factor=nus)
    summarise_pump_card(pumps.pump_position, pumps.pump_load)
    diagnose(pumps.pump_position, pumps.pump_load, reference_fluid_load(unit))
    card_work(positions, loads)
    card_work(pumps.pump_position, pumps.pump_load)
    taper_loads(string, pumps.joint_load)


def best(run, repeats: int = 3) -> float:
    """Shortest CPU time of ``run()`` [s]."""
    times = []
    for _ in range(repeats):
        start = time.process_time()
        run()
        times.append(time.process_time() - start)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cards", type=int, default=2000)
    parser.add_argument("--group", type=int, default=64)
    parser.add_argument("--manifest", type=Path)
    parser.add_argument("--profile", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        manifest = args.manifest or generate(Path(tmp), args.cards)
        batches = groups(manifest, args.cards, args.group)
    count = sum(len(surface) for _, _, surface in batches)
    from pumpjack_cli.core.rods import downhole

    evaluations = []
    real = downhole.decreasing_roots

    def counted(excess, *others, **options):
        calls = [0]

        def each(nu, rows):
            calls[0] += 1
            return excess(nu, rows)

        found = real(each, *others, **options)
        evaluations.append(calls[0])
        return found

    downhole.decreasing_roots = counted
    nus = [damping(*batch) for batch in batches]
    downhole.decreasing_roots = real
    searching = best(lambda: [damping(*batch) for batch in batches])
    after = best(lambda: [rest(*batch, nu) for batch, nu in zip(batches, nus)])
    print(f"machine: {machine()}")
    print(f"{count} cards in {len(batches)} groups of up to {args.group}; energy-balance evaluations per group: "
          f"{min(evaluations)}-{max(evaluations)} (mean {np.mean(evaluations):.1f})")
    print(f"ms per card: damping {1e3 * searching / count:.4f}, rest {1e3 * after / count:.4f}, "
          f"downhole {1e3 * (searching + after) / count:.4f}")
    if args.profile:
        import cProfile
        import pstats

        profile = cProfile.Profile()
        profile.runcall(lambda: [rest(*batch, damping(*batch)) for batch in batches])
        pstats.Stats(profile).sort_stats("tottime").print_stats(25)


if __name__ == "__main__":
    main()
