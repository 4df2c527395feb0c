"""Speed of a deviated well: the diagnostic of a 200-point card (target: at most 20 ms on one core) and the
predictive and coupled time marches.

Run: .venv/bin/python benchmarks/bench_deviated.py
The well is the sample of samples/make_deviated.py: SK8-3,5-4000's rods (1530 m, three tapers) in the
J-shaped hole (vertical to 500 m, 3 deg/30 m to 45 deg, hold), friction coefficient 0.2. The diagnostic
runs on the sample card (200 points) with the damping given (one march) and with the damping from the
energy balance (Brent's method, about seven marches). The thread pools are limited to one thread
before numpy is imported.
"""

from __future__ import annotations

import os

for _variable in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_variable] = "1"

import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "samples")]

from pumpjack_cli.core.rods.deviated_diagnostic import (deviated_damping_from_fluid_load,  # noqa: E402
                                                        deviated_pump_card)
from timing import best_of, machine  # noqa: E402


def main() -> None:
    import make_deviated as module  # samples/make_deviated.py
    start = time.perf_counter()
    found, omega, unit = module.prediction()
    predicted = time.perf_counter() - start
    cards, rods, path = found.cards, unit.rods(), module.path()
    period, position, load = cards.summary.period, cards.polished_rod_position, cards.polished_rod_load
    rho = unit.well.fluid_density

    def diagnose():
        return deviated_pump_card(rods, path, period, position, load, fluid_density=rho, damping_factor=0.05,
                                  friction_coefficient=0.2)

    def blind():
        return deviated_damping_from_fluid_load(rods, path, period, position, load, cards.summary.fluid_load,
                                                fluid_density=rho, friction_coefficient=0.2)

    print(f"machine: {machine()}, numpy {np.__version__}, 1 thread")
    print(f"card: {position.size} points; string: {len(rods.length)} tapers, {rods.total_length:.0f} m, "
          f"{diagnose().grid.nodes} nodes")
    print(f"deviated diagnostic, damping given:          {best_of(diagnose, 20) * 1e3:7.2f} ms per card (target 20 ms)")
    print(f"deviated diagnostic, damping from the energy: {best_of(blind, 3) * 1e3:7.2f} ms per card")
    print(f"predict over the survey, {found.cards.time.size} samples (1200 steps per cycle): {predicted:.2f} s "
          f"({found.cards.summary.convergence.cycles} cycles)")
    from pumpjack_cli.core.dynamics.coupled_deviated import predict_coupled_deviated

    start = time.perf_counter()
    both, _ = predict_coupled_deviated(unit.machine(elastic_rods=True), rods, path, unit.pump(), damping=0.1,
                                       fluid_density=rho, friction_coefficient=0.2, samples=512)
    print(f"coupled machine and deviated rods, 512 steps per revolution: {time.perf_counter() - start:.2f} s "
          f"({both.summary.convergence.cycles} revolutions)")


if __name__ == "__main__":
    main()
