"""A labelled corpus of dynamometer cards made by the predictive model, for the pump diagnosis.

Every card is a surface card of ``core.rods.predict`` (the damped wave equation of the rods
driven by the unit's exact polished-rod motion, the pump's valves at the bottom) with one
physical fault switched on at the pump boundary: a void in the chamber (fluid pound), gas
p V^n (gas interference), a leaking travelling or standing valve, a stop at the bottom or
top of the stroke (tagging), unanchored tubing, or the string parted at a depth (the rods cut
at the break, nothing on their free end). The diagnosis sees only what a dynamometer and the
well file give: the surface card (with 1 % load noise), the rods, the pump and the fluid
level. It never sees the fault, so the labels are tested on cards it did not draw.

Used by ``tests/core/rods/test_diagnosis_corpus.py`` (a modest grid) and
``benchmarks/diagnosis_study.py`` (the full study whose confusion matrix is in
``docs/diagnosis.md``).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.rods.predict import predict_cards
from pumpjack_cli.core.rods.pump import pump_pressures, tubing_stiffness
from pumpjack_cli.core.rods.pump_faults import hanging_pump, parted_damping, parted_string, tag_stops

#: The conditions of the label set ([Zhang2020]'s templates less sand and plunger out of the barrel).
CONDITIONS = ("full", "fluid_pound", "gas_interference", "travelling_valve_leak", "standing_valve_leak",
              "tagging_down", "tagging_up", "unanchored_tubing", "rod_part")

#: Severities per condition (mild to severe), as the fault model's parameter:
#: full: the fluid level as a share of the well's submergence; fluid_pound, gas: the liquid
#: fillage; leaks: the leak at the full pressure difference / the pump's displacement rate
#: (below about 0.8 a leak hardly changes the card: docs/diagnosis.md); tagging: the
#: interference as a share of the rods' stretch under the fluid load F_o / k_r (the
#: compression a stop puts on the rods, k_r x interference, against F_o); unanchored: the
#: API tubing size; rod_part: the break's share of the depth.
SEVERITIES = {
    "full": (1.0, 0.4, 2.5),
    "fluid_pound": (0.8, 0.65, 0.45),
    "gas_interference": (0.85, 0.7, 0.5),
    "travelling_valve_leak": (0.8, 1.2, 1.6),
    "standing_valve_leak": (0.8, 1.2, 1.6),
    "tagging_down": (0.2, 0.3, 0.45),
    "tagging_up": (0.2, 0.3, 0.45),
    "unanchored_tubing": ("3-1/2", "2-7/8", "2-3/8"),
    "rod_part": (0.85, 0.55, 0.25),
}

#: The wells: a bundled unit and its pumping speeds [strokes/min] (None: the motor's rated speed).
WELLS = {"sk8-3.5-4000": (None, 7.0), "c-114d-133-54": (7.0, 11.0)}
#: Gibbs' damping factor the cards are made with.
TRUE_DAMPING = 0.1
#: Samples per stroke the model is solved on; fewer are every k-th of these.
RESOLUTION = 400
#: Polytropic exponent of the gas cards.
GAS_EXPONENT = 1.2
#: Fluid level above the pump of a pumped-off well [m] (fluid pound): a few metres.
POUND_SUBMERGENCE = 10.0


@dataclass(frozen=True)
class Case:
    """One simulated stroke: the well, the condition and its severity, and the surface card
    (uniform time grid of one period from crank angle 0, up positive) with what the fault
    model says the diagnosis should find: the liquid fillage and the break's depth [m]."""

    well: str
    spm: float
    condition: str
    severity: object
    period: float
    position: np.ndarray
    load: np.ndarray
    fillage: float
    break_depth: float
    submergence: float

    def card(self, samples: int, noise: float, seed: int) -> tuple[np.ndarray, np.ndarray]:
        """The surface card on ``samples`` points (every k-th of the model's) with white load noise of
        RMS ``noise`` times the load range."""
        step = RESOLUTION // samples
        position, load = self.position[::step], self.load[::step]
        rng = np.random.default_rng(seed)
        return position, load + noise * float(np.ptp(load)) * rng.standard_normal(load.size)


@functools.lru_cache(maxsize=None)
def unit(name: str):
    return load_unit(name)


def crank_speed(name: str, spm: float | None) -> float:
    u = unit(name)
    return u.drive.rated_crank_speed if spm is None else spm * math.pi / 30.0


@functools.lru_cache(maxsize=None)
def _free(name: str, spm: float | None):
    """The full-pump prediction of a well at a speed (the datum of the tagging stops)."""
    return _predict(name, spm, unit(name).rods(), unit(name).pump(), TRUE_DAMPING)


def _predict(name, spm, rods, pump, damping):
    u = unit(name)
    return predict_cards(u.geometry.mechanism(), crank_speed(name, spm), rods, pump, damping=damping,
                         fluid_density=u.well.fluid_density, samples=RESOLUTION, rod_density=u.well.rod_density,
                         resolution=RESOLUTION)


@functools.lru_cache(maxsize=None)
def case(name: str, spm: float | None, condition: str, severity) -> Case:
    """The card of one well, speed, condition and severity (made once per process)."""
    u = unit(name)
    well, rods, pump = u.well, u.rods(), u.pump()
    omega = crank_speed(name, spm)
    submergence = well.pump_submergence
    displacement = pump.plunger_area * u.geometry.mechanism().stroke * omega / (2.0 * math.pi)
    fillage, depth, damping = 1.0, math.nan, TRUE_DAMPING

    def level(h):
        discharge, intake = pump_pressures(well.pump_depth, well.fluid_density, submergence=h)
        return replace(pump, discharge_pressure=discharge, intake_pressure=intake)

    if condition == "full":
        submergence = min(severity * well.pump_submergence, well.pump_depth)
        pump = level(submergence)
    elif condition == "fluid_pound":
        submergence, fillage = POUND_SUBMERGENCE, severity
        pump = replace(level(submergence), fillage=severity)
    elif condition == "gas_interference":
        fillage = severity
        pump = replace(pump, fillage=severity, gas_exponent=GAS_EXPONENT)
    elif condition == "travelling_valve_leak":
        pump = replace(pump, travelling_valve_leak=severity * displacement)
    elif condition == "standing_valve_leak":
        pump = replace(pump, standing_valve_leak=severity * displacement)
    elif condition in ("tagging_down", "tagging_up"):
        free = _free(name, spm)
        interference = severity * pump.fluid_load / rods.spring_constant
        bottom, top = tag_stops(free.plunger_position, free.pump_load, pump,
                                interference if condition == "tagging_down" else None,
                                interference if condition == "tagging_up" else None)
        pump = replace(pump, bottom_stop=bottom, top_stop=top)
    elif condition == "unanchored_tubing":
        pump = replace(pump, tubing_stiffness=tubing_stiffness(severity, well.pump_depth))
    elif condition == "rod_part":
        depth = severity * rods.total_length
        hanging = parted_string(rods, depth)
        damping = parted_damping(rods, hanging, TRUE_DAMPING)
        rods, pump = hanging, hanging_pump(pump)
    else:
        raise ValueError(condition)
    cards = _predict(name, spm, rods, pump, damping)
    return Case(name, 60.0 / cards.summary.period, condition, severity, cards.summary.period,
                cards.polished_rod_position, cards.polished_rod_load, fillage, depth, submergence)


def cases(wells=WELLS, severities=SEVERITIES, conditions=CONDITIONS) -> list[Case]:
    """Every (well, speed, condition, severity) of the grid."""
    return [case(name, spm, condition, severity) for name, speeds in wells.items() for spm in speeds
            for condition in conditions for severity in severities[condition]]


def diagnosed(item: Case, samples: int, noise: float = 0.01, seed: int = 0, scales=(1.0,)):
    """The diagnosis of a case as `pumpjack downhole` makes it: the surface card with noise, the
    energy-balance damping (the fallback 0.05 where it has no root), the Gibbs pump card of the
    well's rods at that damping times each of ``scales``, the features and the label against F_o
    from the well's fluid level. Returns [(Diagnosis, the damping used, the pump card)] per scale."""
    from pumpjack_cli.core.rods.diagnosis import balanced_damping, diagnose
    from pumpjack_cli.core.rods.downhole import DEFAULT_DAMPING_FACTOR, pump_card

    u = unit(item.well)
    rods, pump, density = u.rods(), u.pump(), u.well.fluid_density
    position, load = item.card(samples, noise, seed)
    nu, _ = balanced_damping(rods, item.period, position, load, pump.fluid_load, fluid_density=density,
                             fallback=DEFAULT_DAMPING_FACTOR)
    found = []
    for scale in scales:
        card = pump_card(rods, item.period, position, load, fluid_density=density, damping_factor=nu * scale)
        found.append((diagnose(card.pump_position, card.pump_load, pump.fluid_load), nu * scale, card))
    return found
