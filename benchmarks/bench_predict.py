"""Wall time of one predictive steady state (pumpjack_cli.core.rods.predict and core.dynamics.coupled).

Run: .venv/bin/python benchmarks/bench_predict.py
Prints the best of five timings of:
* ``predict`` for a four-taper string (API 1-1/8, 1, 7/8, 3/4 in rods, 15/20/25/40 %,
  2500 m, 1.5 in plunger, 8 strokes/min on the C-114D-133-54 motion), 1024 samples per
  cycle, at Gibbs damping 0.1 and 0.05 (lighter damping needs more cycles);
* ``predict`` for the SK8-3,5-4000 seed well (three tapers) at the rated speed;
* ``predict_coupled`` for SK8-3,5-4000 and its well, 1024 and 512 steps per revolution.
Goal: the uniform-rotation four-taper steady state under 0.5 s.
"""

from __future__ import annotations

import os
import platform

import numpy as np

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.geometry import Linkage
from pumpjack_cli.core.dynamics.coupled import predict_coupled
from pumpjack_cli.core.rods.predict import predict
from pumpjack_cli.core.rods.pump import Pump, pump_pressures
from pumpjack_cli.core.rods.string import RodString
from timing import best_of

INCH = 0.0254
LB_PER_FT = 0.45359237 / 0.3048
E_STEEL = 30.5e6 * 6894.757293168


def _position(linkage: Linkage, samples: int) -> np.ndarray:
    m = linkage.motion(np.arange(samples) * 2 * np.pi / samples)
    return linkage.front_arm * (m.beam_angle - linkage.dead_positions().beam_angle_bottom)


def four_taper():
    d = np.array([1.125, 1.0, 0.875, 0.75]) * INCH
    rods = RodString(2500.0 * np.array([0.15, 0.20, 0.25, 0.40]), np.pi * d**2 / 4, np.full(4, E_STEEL),
                     np.array([3.676, 2.904, 2.224, 1.634]) * LB_PER_FT)
    pd, pi = pump_pressures(2500.0, 900.0, submergence=150.0)
    linkage = Linkage(*(INCH * np.array([72, 64, 24, 74.5, 64, 116 - 41])))
    return rods, Pump(np.pi * (1.5 * INCH) ** 2 / 4, pd, pi), _position(linkage, 1024), 60.0 / 8.0


def sk8_well():
    d = np.array([25.0, 22.0, 19.0]) * 1e-3
    rods = RodString(1530.0 * np.array([0.23, 0.26, 0.51]), np.pi * d**2 / 4, np.full(3, E_STEEL),
                     np.array([2.904, 2.224, 1.634]) * LB_PER_FT)
    pd, pi = pump_pressures(1530.0, 820.0, submergence=100.0)
    return rods, Pump(np.pi * 0.038**2 / 4, pd, pi)


def main() -> None:
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"numpy {np.__version__}, load average {os.getloadavg()[0]:.2f}")
    rods, pump, position, period = four_taper()
    for damping in (0.1, 0.05):
        result = predict(rods, pump, position, period, damping=damping, fluid_density=900.0)
        best = best_of(lambda: predict(rods, pump, position, period, damping=damping, fluid_density=900.0), 5)
        c = result.summary.convergence
        print(f"predict, four tapers, 1024 samples, nu {damping:4}: {best * 1e3:6.1f} ms "
              f"({c.cycles} cycles, {c.modes} modes, last change {c.change:.1e})")
    rods, pump = sk8_well()
    linkage = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    sk8 = _position(linkage, 1024)
    best = best_of(lambda: predict(rods, pump, sk8, 2 * np.pi / 1.1422, damping=0.1, fluid_density=820.0), 5)
    print(f"predict, SK8 seed well, 1024 samples, nu 0.1:    {best * 1e3:6.1f} ms")
    machine = load_unit("sk8-3.5-4000").machine()
    for samples in (1024, 512):
        result = predict_coupled(machine, rods, pump, damping=0.1, fluid_density=820.0, samples=samples)
        best = best_of(lambda: predict_coupled(machine, rods, pump, damping=0.1, fluid_density=820.0,
                                               samples=samples), 3)
        print(f"predict_coupled, SK8, {samples:4} steps/rev, nu 0.1:  {best * 1e3:6.1f} ms "
              f"({result.summary.convergence.cycles} revolutions)")


if __name__ == "__main__":
    main()
