"""Make the sample dynamometer cards in samples/ with the predictive wave model of `pumpjack predict`.

Run from the repository root: ``python samples/make_cards.py`` rewrites
``samples/<unit>-card.csv`` for every unit below; ``tests/core/test_card_placement.py`` checks that
the committed files are exactly what this script makes.

Model (:func:`pumpjack_cli.core.rods.predict.predict_cards`, docs/predict.md): the
tapered rod string of the unit's ``[well]`` as a damped wave equation ([Gibbs1963]),
driven at the top by the unit's exact polished-rod motion at uniform crank speed, the
pump's travelling and standing valves at the bottom with the pressures of the well's
depth, fluid and fluid level; Gibbs' damping factor 0.05; the periodic steady state.
So the cards carry the stress waves of real ones (load pick-up and release delayed
and ringing through the rods) but no Coulomb friction, gas or pump wear; they are for
trying the program, not for diagnosing a well. Each file says so in its comment lines.
The 180 samples start at the bottom of the stroke, as a dynamometer's card does.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from pumpjack_cli.config import load_unit  # noqa: E402
from pumpjack_cli.core.rods.downhole import DEFAULT_DAMPING_FACTOR  # noqa: E402
from pumpjack_cli.core.rods.predict import predict_cards  # noqa: E402

POINTS = 180

#: unit name -> (strokes per minute (None: the motor's rated speed), position unit and factor, load unit and factor)
CARDS = {
    "sk8-3.5-4000": (None, ("m", 1.0), ("kN", 1e-3)),
    "7sk12-2.5-5600": (8.0, ("m", 1.0), ("kN", 1e-3)),
    "c-114d-133-54": (10.0, ("in", 1 / 0.0254), ("lbf", 1 / 4.4482216152605)),
    "c-80d-133-48": (8.0, ("in", 1 / 0.0254), ("lbf", 1 / 4.4482216152605)),
    "c-228d-213-86": (7.0, ("in", 1 / 0.0254), ("lbf", 1 / 4.4482216152605)),
    "m-912d-365-168": (6.0, ("in", 1 / 0.0254), ("lbf", 1 / 4.4482216152605)),
    "a-228d-246-86": (9.0, ("in", 1 / 0.0254), ("lbf", 1 / 4.4482216152605)),
}


def card(name: str, spm: float | None) -> tuple[np.ndarray, np.ndarray, np.ndarray, str]:
    """Time [s], position [m] and load [N] over one cycle from the bottom of the stroke, and a description."""
    unit = load_unit(name)
    well = unit.well
    omega = unit.drive.rated_crank_speed if spm is None else spm * math.pi / 30.0
    cards = predict_cards(unit.geometry.mechanism(), omega, unit.rods(), unit.pump(), damping=DEFAULT_DAMPING_FACTOR,
                          fluid_density=well.fluid_density, samples=POINTS, rod_density=well.rod_density)
    order = np.roll(np.arange(POINTS), -int(np.argmin(cards.polished_rod_position)))
    position, load = cards.polished_rod_position[order], cards.polished_rod_load[order]
    time = np.arange(POINTS) * (2 * math.pi / omega) / POINTS
    s = cards.summary
    about = (f"{unit.name} at {60 * omega / (2 * math.pi):.3f} strokes/min; W_rf = {s.buoyant_rod_weight / 1e3:.2f} kN, "
             f"F_o = {s.fluid_load / 1e3:.2f} kN, damping factor {DEFAULT_DAMPING_FACTOR:g}, "
             f"plunger stroke {s.gross_plunger_stroke * 1e3:.0f} mm")
    return time, position, load, about


def write(name: str) -> str:
    spm, (p_unit, p_factor), (l_unit, l_factor) = CARDS[name]
    time, position, load, about = card(name, spm)
    lines = [
        f"# Sample dynamometer card for {name}: synthetic, made by samples/make_cards.py",
        "# (rod string as a damped wave equation with the pump's valves, `pumpjack predict`; no friction or gas).",
        f"# {about}.",
        f"time_s,position_{p_unit},load_{l_unit}",
    ]
    lines += [f"{t:.4f},{p * p_factor:.5f},{w * l_factor:.4f}" for t, p, w in zip(time, position, load)]
    return "\n".join(lines) + "\n"


def main() -> None:
    for name in CARDS:
        (ROOT / "samples" / f"{name}-card.csv").write_text(write(name), encoding="utf-8")


if __name__ == "__main__":
    main()
