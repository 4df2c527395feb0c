"""A dynamometer card on a crank-angle grid, with uniform or dynamic crank rotation."""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..card_files import read_card
from ..core.beam.card import Card, card_load
from ..core.beam.linkage import Linkage
from ..core.dynamics.periodic import steady_state
from ..core.sampling import crank_grid, cycle_period, uniform_time
from ..errors import PumpjackError
from .inputs import crank_speed
from .machine import machine

#: Crank rotation models of the card-driven analyses.
ROTATIONS = ("uniform", "dynamic")


def load_card(path: Path, linkage: Linkage, card_units: str) -> Card:
    """A dynamometer card on the unit's crank-angle axis; the reader's warnings go to stderr."""
    reading = read_card(path, linkage, card_units)
    for warning in reading.warnings:
        sys.stderr.write(f"pumpjack: warning: {warning}\n")
    return reading.card


@dataclass(frozen=True)
class CardRun:
    """Crank angles [rad], time [s], crank speed [1/s] and acceleration [1/s²] and the
    card's polished-rod load [N] on them, the cycle time [s] and the rotation model."""

    crank_angle: np.ndarray
    time: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    load: np.ndarray
    period: float
    rotation: str
    card: Path

    @property
    def mean_crank_speed(self) -> float:
        """Mean crank speed over the cycle [1/s] (2 pi / cycle time)."""
        return 2.0 * np.pi / self.period


def card_run(unit, linkage: Linkage, card: Path, card_units: str, spm: float | None, steps: int,
             rotation: str) -> CardRun:
    """The card on a crank-angle grid with uniform or dynamic rotation; card warnings go to stderr."""
    measured = load_card(card, linkage, card_units)
    theta = crank_grid(steps)
    load = card_load(measured, theta)
    if rotation == "uniform":
        omega = crank_speed(unit, spm)
        return CardRun(theta, uniform_time(theta, omega), np.full(steps, omega), np.zeros(steps), load,
                       cycle_period(omega), rotation, card)
    if spm is not None:
        raise PumpjackError("--spm sets a uniform crank speed; with --rotation dynamic the motor sets the speed")
    state = steady_state(machine(unit, measured), theta)
    return CardRun(theta, state.time, state.omega, state.epsilon, load, state.summary.period, rotation, card)
