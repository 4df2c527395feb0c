"""Throughput of the pump-card (downhole) calculation on one core.

Run: .venv/bin/python benchmarks/bench_downhole.py
Prints cards per second of `pump_card` for both methods on a 200-point card and a
four-taper string (5000 ft: 1, 7/8 and 3/4 in rods over 1-1/2 in sinker bars), one card
per call and a batch of 1000 cards per call, with the damping default and the checks on.
The thread pools are limited to one thread before numpy is imported.
"""

from __future__ import annotations

import os

for _variable in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_variable] = "1"

import platform  # noqa: E402

import numpy as np  # noqa: E402

from pumpjack_cli.core.rods.downhole import downhole_methods, pump_card, surface_card  # noqa: E402
from pumpjack_cli.core.rods.tables import RodSection, rod_string  # noqa: E402
from timing import best_of  # noqa: E402

FOOT = 0.3048
SAMPLES = 200
BATCH = 1000


def sample_card():
    """A 200-point surface card: a full pump card (3 m stroke, 23 kN) pushed to the surface."""
    string = rod_string([RodSection(0.0254, 1500 * FOOT), RodSection(0.0222, 1500 * FOOT),
                         RodSection(0.01905, 1600 * FOOT), RodSection(0.0381, 400 * FOOT, kind="sinker")])
    period = 7.5
    theta = 2 * np.pi * np.arange(SAMPLES) / SAMPLES
    position = 1.5 * (1 - np.cos(theta))
    load = 23e3 * (np.sin(theta - 0.1) > 0)
    surface = surface_card(string, period, position, load, fluid_density=1000.0)
    return string, period, surface.surface_position, surface.surface_load


def processor() -> str:
    """CPU model from /proc/cpuinfo where there is one."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as info:
            for line in info:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown cpu"


def main() -> None:
    string, period, position, load = sample_card()
    positions = position + 1e-3 * np.random.default_rng(1).standard_normal((BATCH, SAMPLES))
    loads = np.broadcast_to(load, (BATCH, SAMPLES))
    print(f"machine: {platform.machine()}, {processor()}, {os.cpu_count()} cores (1 thread used), "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    print(f"card: {SAMPLES} points, string: {len(string.length)} tapers, {string.total_length:.0f} m")
    for method in downhole_methods():
        single = best_of(lambda: pump_card(string, period, position, load, fluid_density=1000.0, method=method), 200)
        batch = best_of(lambda: pump_card(string, period, positions, loads, fluid_density=1000.0, method=method), 5)
        print(f"{method:17}: one card per call {1 / single:8.0f} cards/s ({single * 1e3:.3f} ms), "
              f"batch of {BATCH} {BATCH / batch:8.0f} cards/s ({batch * 1e3:.1f} ms)")


if __name__ == "__main__":
    main()
