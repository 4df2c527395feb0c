"""Make the sample dynamometer cards in samples/ from a documented load model.

Run from the repository root: ``python samples/make_cards.py`` rewrites
``samples/<unit>-card.csv`` for every unit below; ``tests/test_cards.py`` checks that
the committed files are exactly what this script makes.

Load model (a rigid rod string with an elastic load transfer; the classical static
"ideal card" of pumping-well textbooks plus rod and fluid inertia):

* rod weight in air W_r = sum(rho_s g A_i L_i), rho_s the well's rod density, and in
  fluid W_rf = W_r (1 - rho_f / rho_s) (Archimedes), by pumpjack_cli.core.well;
* fluid load on the plunger W_f = rho_f g L A_p (pump full, no tubing or casing
  pressure, the column from the pump depth), by pumpjack_cli.core.well;
* rod stretch under the fluid load delta = W_f sum(L_i / (E A_i)), E = 2.06e11 Pa: the
  fluid load is picked up linearly over the first delta of the upstroke and released
  over the first delta of the downstroke (Hooke's law);
* inertia of the rods, and of the fluid column while it is carried, m a with a the
  exact polished-rod acceleration at uniform crank speed (rigid string);
* friction, plunger and rods together, a constant 2 % of W_r against the motion
  (illustrative).

So the cards carry the shapes and magnitudes of real ones (load pick-up and release,
inertia humps) but not the rod-string waves; they are for trying the program, not for
diagnosing a well. Each file says so in its comment lines.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from pumpjack_cli.config import load_unit  # noqa: E402
from pumpjack_cli.core.beam.kinematics import uniform_kinematics  # noqa: E402
from pumpjack_cli.core.constants import STANDARD_GRAVITY  # noqa: E402
from pumpjack_cli.core.well import buoyant_weight, fluid_load, rod_string_mass  # noqa: E402

STEEL_MODULUS = 2.06e11
POINTS = 180

#: unit name -> (strokes per minute, position unit and factor, load unit and factor)
CARDS = {
    "sk8-3.5-4000": (None, ("m", 1.0), ("kN", 1e-3)),
    "7sk12-2.5-5600": (8.0, ("m", 1.0), ("kN", 1e-3)),
    "c-114d-133-54": (10.0, ("in", 1 / 0.0254), ("lbf", 1 / 4.4482216152605)),
    "c-80d-133-48": (8.0, ("in", 1 / 0.0254), ("lbf", 1 / 4.4482216152605)),
}


def card(name: str, spm: float | None) -> tuple[np.ndarray, np.ndarray, np.ndarray, str]:
    """Time [s], position [m] and load [N] over one cycle from the bottom of the stroke, and a description."""
    unit = load_unit(name)
    well = unit.well
    omega = unit.drive.rated_crank_speed if spm is None else spm * math.pi / 30.0
    run = uniform_kinematics(unit.geometry.linkage(), omega, POINTS)
    start = int(np.argmin(run.rod.position))
    order = np.roll(np.arange(POINTS), -start)
    position, acceleration = run.rod.position[order], run.rod.acceleration[order]
    lengths = np.array([s.fraction for s in well.rod_string]) * well.pump_depth
    diameters = np.array([s.diameter for s in well.rod_string])
    areas = np.pi / 4 * diameters**2
    rod_mass = rod_string_mass(diameters, lengths, well.rod_density)
    w_rf = buoyant_weight(rod_mass, well.rod_density, well.fluid_density)
    w_f = fluid_load(well.plunger_diameter, well.pump_depth, well.fluid_density)
    fluid_mass = w_f / STANDARD_GRAVITY
    stretch = w_f * float(np.sum(lengths / (STEEL_MODULUS * areas)))
    stroke = run.summary.stroke
    top = int(np.argmax(position))
    rising = np.arange(POINTS) <= top
    carried = np.where(rising, np.minimum(position / stretch, 1.0), np.clip(1.0 - (stroke - position) / stretch, 0.0, 1.0))
    friction = 0.02 * rod_mass * STANDARD_GRAVITY * np.where(rising, 1.0, -1.0)
    load = w_rf + carried * w_f + (rod_mass + carried * fluid_mass) * acceleration + friction
    time = np.arange(POINTS) * (2 * math.pi / omega) / POINTS
    about = (f"{unit.name} at {60 * omega / (2 * math.pi):.3f} strokes/min; W_rf = {w_rf / 1e3:.2f} kN, "
             f"W_f = {w_f / 1e3:.2f} kN, rod stretch {stretch * 1e3:.0f} mm")
    return time, position, load, about


def write(name: str) -> str:
    spm, (p_unit, p_factor), (l_unit, l_factor) = CARDS[name]
    time, position, load, about = card(name, spm)
    lines = [
        f"# Sample dynamometer card for {name}: synthetic, made by samples/make_cards.py",
        "# (rigid rods, elastic load transfer, rod and fluid inertia, 2 % friction; no rod-string waves).",
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
