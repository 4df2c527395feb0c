"""Grid and regularisation convergence of the deviated-well models, printed as the tables of docs/deviated.md.

Run: .venv/bin/python benchmarks/deviated_convergence.py   (about a minute)
The well: SK8-3,5-4000's rods and pump in the J-shaped hole of samples/make_deviated.py at the motor's
rated 10.9 strokes/min, Gibbs' damping 0.05, friction coefficient 0.2.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "samples")]

from pumpjack_cli.core.rods.analysis import card_work, summarise_pump_card  # noqa: E402
from pumpjack_cli.core.rods.deviated_diagnostic import deviated_pump_card  # noqa: E402
from pumpjack_cli.core.rods.deviated_predict import predict_deviated  # noqa: E402
from pumpjack_cli.core.rods.pump import Pump, pump_pressures  # noqa: E402


def main() -> None:
    import make_deviated as module  # samples/make_deviated.py
    from pumpjack_cli.config import load_unit

    unit = load_unit(module.UNIT)
    rods, path, well = unit.rods(), module.path(), unit.well
    discharge, intake = pump_pressures(float(path.vertical_depth(well.pump_depth)), well.fluid_density,
                                       submergence=well.pump_submergence)
    pump = Pump(np.pi * well.plunger_diameter**2 / 4, discharge, intake)
    omega = unit.drive.rated_crank_speed
    mechanism = unit.geometry.mechanism()
    f_o = pump.fluid_load

    def run(steps: int, eta: float = 0.01, segment: float = 15.0):
        theta = np.arange(steps) * 2 * np.pi / steps
        return predict_deviated(rods, path, pump, mechanism.rod_position(theta), 2 * np.pi / omega, damping=0.05,
                                fluid_density=well.fluid_density, friction_coefficient=0.2, regularisation=eta,
                                max_segment=segment)

    print("Time march, steps per cycle (segments at most 15 m; eta 0.01):\n")
    print("| steps | nodes | PPRL [kN] | MPRL [kN] | pump work [kJ] | drag work [kJ] | energy residual |")
    print("|---|---|---|---|---|---|---|")
    for steps in (256, 512, 1024, 2048, 4096):
        found = run(steps)
        s = found.cards.summary
        print(f"| {steps} | {found.grid.nodes} | {s.peak_polished_rod_load.value / 1e3:.3f} | "
              f"{s.minimum_polished_rod_load.value / 1e3:.3f} | {s.pump_card_work / 1e3:.3f} | "
              f"{found.friction_work / 1e3:.3f} | {s.energy_residual:.1e} |")
    print("\nTime march, the drag's band eta (1024 steps per cycle):\n")
    print("| eta | PPRL [kN] | MPRL [kN] | drag work [kJ] | rms change of the polished-rod load from the eta above [% of F_o] |")
    print("|---|---|---|---|---|")
    previous = None
    for eta in (0.1, 0.03, 0.01, 0.003, 0.001):
        found = run(1024, eta)
        s = found.cards.summary
        change = "" if previous is None else \
            f"{100 * np.sqrt(np.mean((found.cards.polished_rod_load - previous) ** 2)) / f_o:.2f}"
        previous = found.cards.polished_rod_load
        print(f"| {eta:g} | {s.peak_polished_rod_load.value / 1e3:.3f} | {s.minimum_polished_rod_load.value / 1e3:.3f} | "
              f"{found.friction_work / 1e3:.3f} | {change} |")
    found, _, _ = module.prediction()
    cards = found.cards
    truth = summarise_pump_card(cards.plunger_position, cards.pump_load)
    work = float(card_work(cards.plunger_position, cards.pump_load))
    print("\nRound trip, the predicted 200-point card diagnosed (the prediction's eta 0.01):\n")
    print("| diagnostic eta | segments at most [m] | pump work | plunger position [% of stroke] | upstroke level | "
          "downstroke level | rms load error | drag work |")
    print("|---|---|---|---|---|---|---|---|")
    for mu, eta, segment in ((0.2, 0.1, 15.0), (0.2, 0.03, 15.0), (0.2, 0.01, 15.0), (0.2, 0.003, 15.0),
                             (0.2, 0.01, 30.0), (0.2, 0.01, 7.5), (0.0, 0.01, 15.0)):
        back = deviated_pump_card(rods, path, cards.summary.period, cards.polished_rod_position,
                                  cards.polished_rod_load, fluid_density=well.fluid_density, damping_factor=0.05,
                                  friction_coefficient=mu, regularisation=eta, max_segment=segment)
        levels = summarise_pump_card(back.card.pump_position, back.card.pump_load)
        shift = back.card.pump_position - cards.plunger_position
        label = f"{eta:g}" if mu else "friction ignored"
        print(f"| {label} | {segment:g} | "
              f"{100 * (float(card_work(back.card.pump_position, back.card.pump_load)) / work - 1):+.2f} % | "
              f"{100 * np.max(np.abs(shift - shift.mean())) / cards.summary.polished_rod_stroke:.2f} | "
              f"{100 * (float(levels.upstroke_load) - float(truth.upstroke_load)) / f_o:+.2f} % of F_o | "
              f"{100 * (float(levels.downstroke_load) - float(truth.downstroke_load)) / f_o:+.2f} % of F_o | "
              f"{100 * np.sqrt(np.mean((back.card.pump_load - cards.pump_load) ** 2)) / f_o:.2f} % of F_o | "
              f"{100 * (back.friction_work / found.friction_work - 1):+.2f} % |")


if __name__ == "__main__":
    main()
