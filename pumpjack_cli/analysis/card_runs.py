"""A dynamometer card on crank-angle grids, with uniform or dynamic crank rotation.

The crank speed of a uniform run is the card's own when its time stamps give one (a
``--spm`` that disagrees by more than 2 % is an error that prints both), else
``--spm``, else the motor's rated speed through the drive. A run is evaluated on the
output grid (``--steps``) and on a fixed summary grid, so that the extremes a command
reports do not depend on ``--steps``.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..card_files import CardReading, check_speed, parse_card_columns, read_card
from ..core.beam.card import card_load
from ..core.beam.linkage import Linkage
from ..core.dynamics.periodic import steady_state
from ..core.sampling import crank_grid, cycle_period, uniform_time
from ..errors import PumpjackError
from ..quantities import parse_quantity
from .inputs import crank_speed
from .machine import machine

#: Crank rotation models of the card-driven analyses.
ROTATIONS = ("uniform", "dynamic")


@dataclass(frozen=True)
class CardSource:
    """Where a card comes from: a path (``-`` for standard input), the units of columns
    whose header names none, and an optional ``--card-columns`` mapping text."""

    path: Path
    units: str = "si"
    columns: str | None = None

    def read(self, linkage: Linkage) -> CardReading:
        """The card on the unit's crank-angle axis; the reader's warnings go to stderr."""
        mapping = None if self.columns is None else parse_card_columns(self.columns)
        reading = read_card(self.path, linkage, self.units, columns=mapping)
        for warning in reading.warnings:
            sys.stderr.write(f"pumpjack: warning: {warning}\n")
        return reading

    @property
    def name(self) -> str:
        """The card's name for titles."""
        return "<stdin>" if str(self.path) == "-" else self.path.name


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

    @property
    def mean_crank_speed(self) -> float:
        """Mean crank speed over the cycle [1/s] (2 pi / cycle time)."""
        return 2.0 * np.pi / self.period


def uniform_speed(unit, reading: CardReading, spm: float | None) -> float:
    """Crank speed [1/s] of a uniform run: the card's time stamps, else ``--spm``, else the drive."""
    option = None if spm is None else parse_quantity(f"{spm} spm", "rotational_speed")
    speed = check_speed(reading.speed, option, reading.source)
    return crank_speed(unit, None) if speed is None else speed


def card_runs(unit, linkage: Linkage, source: CardSource, spm: float | None, grids: tuple[int, ...],
              rotation: str) -> tuple[CardReading, list[CardRun]]:
    """The card read once and run on each crank-angle grid of ``grids`` (steps per revolution)."""
    reading = source.read(linkage)
    thetas = [crank_grid(steps) for steps in grids]
    if rotation == "uniform":
        omega = uniform_speed(unit, reading, spm)
        runs = [CardRun(theta, uniform_time(theta, omega), np.full(theta.size, omega), np.zeros(theta.size),
                        card_load(reading.card, theta), cycle_period(omega), rotation) for theta in thetas]
        return reading, runs
    if spm is not None:
        raise PumpjackError("--spm sets a uniform crank speed; with --rotation dynamic the motor sets the speed")
    state = steady_state(machine(unit, reading.card), np.concatenate(thetas))
    runs, start = [], 0
    for theta in thetas:
        part = slice(start, start + theta.size)
        runs.append(CardRun(theta, state.time[part], state.omega[part], state.epsilon[part],
                            card_load(reading.card, theta), state.summary.period, rotation))
        start += theta.size
    return reading, runs
