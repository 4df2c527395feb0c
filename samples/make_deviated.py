"""Make the deviated-well samples in samples/: a J-shaped survey and a card predicted over it.

Run from the repository root: ``python samples/make_deviated.py`` rewrites
``samples/j-well-survey.csv`` and ``samples/sk8-3.5-4000-deviated-card.csv``;
``tests/core/rods/test_deviated_round_trip.py`` checks that the committed files are exactly
what this script makes.

The survey is the J-shaped hole of the deviated-wells issue: vertical to 500 m, built at
3 deg per 30 m to 45 deg, then held; stations every 30 m in the build (as an MWD survey
gives them) and one at 1700 m, azimuth 30 deg. Minimum curvature between the stations
reproduces the constant build exactly ([SawarynThorogood2005]).

The card: SK8-3,5-4000 (its rods, 38 mm pump at 1530 m measured depth, 820 kg/m³ fluid,
100 m of fluid above the pump, vertical height) over that hole, predicted by the time march
of `pumpjack predict --survey` (:func:`pumpjack_cli.core.rods.deviated_predict.predict_deviated_cards`:
gravity along the hole, soft-string side load and Coulomb drag, [JohancsikSPE11380];
friction coefficient 0.2, Gibbs' damping factor 0.05, the pump's valves) at the motor's
rated speed. 200 samples from the bottom of the stroke, as a controller's card block holds.
For trying `pumpjack downhole --survey`, not for diagnosing a real well.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from pumpjack_cli.config import load_unit  # noqa: E402
from pumpjack_cli.core.rods.deviated_predict import DeviatedPrediction, predict_deviated_cards  # noqa: E402
from pumpjack_cli.core.rods.survey_path import SurveyPath  # noqa: E402

UNIT = "sk8-3.5-4000"
POINTS = 200
DAMPING = 0.05
FRICTION = 0.2
#: The J-shaped hole: kick-off [m], build rate [deg per 30 m], final inclination [deg], last station [m], azimuth [deg].
KICK_OFF, BUILD, HOLD, BOTTOM, AZIMUTH = 500.0, 3.0, 45.0, 1700.0, 30.0


def stations() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Measured depth [m], inclination and azimuth [deg] of the survey's stations."""
    build = np.arange(1, int(HOLD / BUILD) + 1)
    depth = np.concatenate([[0.0, KICK_OFF], KICK_OFF + 30.0 * build, [BOTTOM]])
    inclination = np.concatenate([[0.0, 0.0], BUILD * build, [HOLD]])
    return depth, inclination, np.full(depth.size, AZIMUTH)


def survey_text() -> str:
    lines = ["# J-shaped survey: vertical to 500 m, build 3 deg/30 m to 45 deg, hold (samples/make_deviated.py)",
             "measured_depth_m,inclination_deg,azimuth_deg"]
    lines += [f"{d:g},{i:g},{a:g}" for d, i, a in zip(*stations())]
    return "\n".join(lines) + "\n"


def path() -> SurveyPath:
    depth, inclination, azimuth = stations()
    return SurveyPath(depth, np.radians(inclination), np.radians(azimuth))


def prediction() -> tuple[DeviatedPrediction, float, object]:
    """The predicted cards over the J-shaped hole, the crank speed [1/s] and the unit."""
    from pumpjack_cli.core.rods.pump import Pump, pump_pressures

    unit = load_unit(UNIT)
    well = unit.well
    hole = path()
    discharge, intake = pump_pressures(float(hole.vertical_depth(well.pump_depth)), well.fluid_density,
                                       submergence=well.pump_submergence)
    pump = Pump(math.pi * well.plunger_diameter**2 / 4.0, discharge, intake)
    omega = unit.drive.rated_crank_speed
    found = predict_deviated_cards(unit.geometry.mechanism(), omega, unit.rods(), hole, pump, damping=DAMPING,
                                   fluid_density=well.fluid_density, friction_coefficient=FRICTION, samples=POINTS)
    return found, omega, unit


def card_text(found: DeviatedPrediction, omega: float, unit) -> str:
    cards = found.cards
    order = np.roll(np.arange(POINTS), -int(np.argmin(cards.polished_rod_position)))
    time = np.arange(POINTS) * (2 * math.pi / omega) / POINTS
    s = cards.summary
    lines = [
        f"# Sample dynamometer card for {UNIT} over samples/j-well-survey.csv: synthetic, made by samples/make_deviated.py",
        "# (rods along the hole with gravity, side load and Coulomb drag, the pump's valves: `pumpjack predict --survey`).",
        f"# {unit.name} at {60 * omega / (2 * math.pi):.3f} strokes/min; weight along the hole {s.buoyant_rod_weight / 1e3:.2f} kN, "
        f"F_o = {s.fluid_load / 1e3:.2f} kN, friction coefficient {FRICTION:g}, damping factor {DAMPING:g}, "
        f"drag work {found.friction_work / 1e3:.2f} kJ per cycle.",
        "time_s,position_m,load_kN",
    ]
    lines += [f"{t:.4f},{p:.5f},{w / 1e3:.4f}" for t, p, w in
              zip(time, cards.polished_rod_position[order], cards.polished_rod_load[order])]
    return "\n".join(lines) + "\n"


def main() -> None:
    (ROOT / "samples" / "j-well-survey.csv").write_text(survey_text(), encoding="utf-8")
    (ROOT / "samples" / f"{UNIT}-deviated-card.csv").write_text(card_text(*prediction()), encoding="utf-8")


if __name__ == "__main__":
    main()
