"""The accuracy study of the pump diagnosis: a confusion matrix over a wide corpus of predicted cards.

Wider than the tests' corpus (``tests/core/rods/test_diagnosis_corpus.py``): five bundled
wells, two speeds each, two true damping factors, four severities per condition, 200 and
400 samples per stroke, 1 % load noise, and the diagnosis at the energy-balance damping
and at 0.85 and 1.15 times it. Every card is made by the predictive model with one fault
at the pump boundary (``tests/diagnosis_corpus.py``); the diagnosis sees the surface card,
the rods and the well file only.

    python benchmarks/diagnosis_study.py            # prints the matrix as Markdown (minutes)
    python benchmarks/diagnosis_study.py --quick    # one speed, one damping

The result is the confusion matrix of ``docs/diagnosis.md``.
"""

from __future__ import annotations

import argparse
import collections
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import numpy as np  # noqa: E402

import diagnosis_corpus as corpus  # noqa: E402
from pumpjack_cli.core.rods.diagnosis import CONDITIONS  # noqa: E402

#: Wells and speeds [strokes/min] (None: the motor's rated speed): the thresholds of the rules
#: were set on the feature distributions of these wells' cards (docs/diagnosis.md).
WELLS = {"sk8-3.5-4000": (None, 7.0), "c-114d-133-54": (7.0, 11.0), "c-80d-133-48": (6.0, 9.0),
         "7sk12-2.5-5600": (6.0, 9.0), "m-912d-365-168": (5.0, 7.5)}
#: A well the thresholds never saw: the class III air-balanced A-228D-246-86 (``--held-out``).
HELD_OUT = {"a-228d-246-86": (6.0, 9.0)}
#: Four severities per condition, between and beyond the tests' (tests/diagnosis_corpus.py).
SEVERITIES = {
    "full": (0.3, 1.0, 2.0, 3.0),
    "fluid_pound": (0.85, 0.7, 0.55, 0.4),
    "gas_interference": (0.88, 0.75, 0.6, 0.45),
    "travelling_valve_leak": (0.7, 1.0, 1.3, 1.7),
    "standing_valve_leak": (0.7, 1.0, 1.3, 1.7),
    "tagging_down": (0.2, 0.3, 0.45, 0.6),
    "tagging_up": (0.2, 0.3, 0.45, 0.6),
    "unanchored_tubing": ("3-1/2", "2-7/8", "2-3/8"),
    "rod_part": (0.2, 0.4, 0.6, 0.8),
}
TRUE_DAMPINGS = (0.07, 0.15)
SAMPLES = (200, 400)
DAMPING_SCALES = (0.85, 1.0, 1.15)


def study(wells, dampings, records: list | None = None) -> tuple[collections.Counter, list, dict]:
    confusion: collections.Counter = collections.Counter()
    misses, fillage = [], collections.defaultdict(list)
    seed = 0
    for damping in dampings:
        corpus.TRUE_DAMPING = damping
        corpus.case.cache_clear()
        corpus._free.cache_clear()
        for item in corpus.cases(wells, SEVERITIES):
            for samples in SAMPLES:
                seed += 1
                for scale, (found, nu, _) in zip(DAMPING_SCALES, corpus.diagnosed(item, samples, 0.01, seed,
                                                                                 DAMPING_SCALES)):
                    label = str(found.label[0])
                    if records is not None:
                        records.append((item.well, item.spm, damping, item.condition, item.severity, samples, scale,
                                        label, {k: float(v[0]) for k, v in vars(found.features).items()}, nu))
                    confusion[(item.condition, label)] += 1
                    if label != item.condition:
                        misses.append((item.well, round(item.spm, 1), damping, item.condition, item.severity, samples,
                                       scale, round(nu, 3), label))
                    if item.condition in ("fluid_pound", "gas_interference"):
                        fillage[item.condition].append((item.fillage, float(found.features.fillage[0]),
                                                        float(found.features.travelling_valve_opening[0])))
    return confusion, misses, fillage


def markdown(confusion: collections.Counter) -> str:
    short = {c: c.replace("_", " ") for c in CONDITIONS}
    lines = ["| simulated \\ labelled | " + " | ".join(short[c] for c in CONDITIONS) + " | recall |",
             "|---" * (len(CONDITIONS) + 2) + "|"]
    for row in CONDITIONS:
        total = sum(confusion[(row, col)] for col in CONDITIONS)
        cells = [str(confusion[(row, col)]) if confusion[(row, col)] else "·" for col in CONDITIONS]
        lines.append(f"| **{short[row]}** | " + " | ".join(cells) + f" | {confusion[(row, row)] / total:.1%} |")
    right = sum(confusion[(c, c)] for c in CONDITIONS)
    lines.append(f"\n{right} of {sum(confusion.values())} cards labelled right: {right / sum(confusion.values()):.2%}.")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one speed per well, one true damping")
    parser.add_argument("--dump", help="pickle every card's features and label to this file")
    parser.add_argument("--held-out", action="store_true", help="the well the thresholds never saw, alone")
    args = parser.parse_args()
    wells = HELD_OUT if args.held_out else WELLS
    wells = {name: speeds[:1] for name, speeds in wells.items()} if args.quick else wells
    dampings = TRUE_DAMPINGS[:1] if args.quick else TRUE_DAMPINGS
    start = time.perf_counter()
    records: list | None = [] if args.dump else None
    confusion, misses, fillage = study(wells, dampings, records)
    if args.dump:
        import pickle

        with open(args.dump, "wb") as handle:
            pickle.dump(records, handle)
    print(markdown(confusion))
    for condition, rows in fillage.items():
        error = np.array([(mid - true, opening - true) for true, mid, opening in rows]) * 100
        print(f"\n{condition}: unloading-point fillage minus liquid fillage {error[:, 0].min():+.1f} .. "
              f"{error[:, 0].max():+.1f} points; travelling-valve opening minus liquid fillage "
              f"{error[:, 1].min():+.1f} .. {error[:, 1].max():+.1f} points")
    if records:
        ratio = collections.defaultdict(list)
        for record in records:
            if record[6] == 1.0:
                ratio[record[3]].append(record[9] / record[2])
        print("\nenergy-balance damping / true damping: " + "; ".join(
            f"{condition} {min(values):.2f}-{max(values):.2f}" for condition, values in ratio.items()))
    print(f"\n{len(misses)} cards labelled wrong:")
    for miss in misses:
        print("   ", miss)
    print(f"\n{time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
