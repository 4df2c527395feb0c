"""A dynamometer card on crank-angle grids, with uniform or dynamic crank rotation.

The crank speed of a uniform run is the card's own when its time stamps give one (a
``--spm`` that disagrees by more than 2 % is an error that prints both), else
``--spm``, else the motor's rated speed through the drive. A run is evaluated on the
output grid (``--steps``) and on a fixed summary grid, so that the extremes a command
reports do not depend on ``--steps``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..card_files import CardReading, check_speed, parse_card_columns, read_card
from ..core.beam.card import card_load
from ..core.beam.linkage import Linkage
from ..core.beam.torque import crank_rates_from_time
from ..core.dynamics.periodic import steady_state
from ..core.sampling import crank_grid, cycle_period, uniform_time
from ..errors import PumpjackError, warn
from ..quantities import parse_quantity
from .inputs import crank_speed
from .machine import machine

#: Harmonics of the time-against-angle fit of a card's time stamps (--rotation card).
CARD_HARMONICS = 4
#: Steps of the integration t = int dtheta / omega over one revolution.
FINE_STEPS = 3600
#: Crank-angle points per time sample when a card is put on a uniform time grid.
RESAMPLE_FACTOR = 8

#: Crank rotation models of the card-driven analyses: constant speed; the speed and
#: acceleration fitted to the card's time stamps; the machine's equation of motion;
#: auto: the card's time stamps if it has them and no --spm is given, else constant speed.
ROTATIONS = ("uniform", "card", "dynamic", "auto")


@dataclass(frozen=True)
class CardSource:
    """Where a card comes from: a path (``-`` for standard input), the units of columns
    whose header names none (None: such a column is refused), and an optional
    ``--card-columns`` mapping text."""

    path: Path
    units: str | None = None
    columns: str | None = None

    def read(self, linkage: Linkage) -> CardReading:
        """The card on the unit's crank-angle axis; the reader's warnings are noted (:func:`~pumpjack_cli.errors.warn`)."""
        mapping = None if self.columns is None else parse_card_columns(self.columns)
        reading = read_card(self.path, linkage, self.units, columns=mapping)
        for warning in reading.warnings:
            warn(warning)
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


@functools.lru_cache(maxsize=8)
def _crank_rates(linkage: Linkage, time: bytes, crank_angle: bytes) -> tuple[np.ndarray, np.ndarray]:
    """The fit of :func:`crank_rates_from_time` for a card's samples, kept (read-only) for the
    next analysis of the same card (a batch runs torque and downhole on every card)."""
    rates = crank_rates_from_time(linkage, np.frombuffer(time), np.frombuffer(crank_angle), CARD_HARMONICS)
    for values in rates:
        values.flags.writeable = False
    return rates


def _card_rotations(linkage: Linkage, reading: CardReading, thetas: list[np.ndarray]) -> list[CardRun]:
    """The crank speed and acceleration the card's time stamps give ([Takacs2016]), on each grid."""
    if reading.time is None:
        raise PumpjackError(f"{reading.source}: --rotation card needs a card with time stamps")
    omega_s, alpha_s = _crank_rates(linkage, reading.time.tobytes(), reading.crank_angle.tobytes())
    order = np.argsort(reading.crank_angle)
    angles = reading.crank_angle[order]
    fine = np.linspace(0.0, 2.0 * np.pi, FINE_STEPS + 1)
    rate = 1.0 / np.interp(fine, angles, omega_s[order], period=2.0 * np.pi)
    elapsed = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(fine))])
    return [CardRun(theta, np.interp(theta, fine, elapsed),
                    np.interp(theta, angles, omega_s[order], period=2.0 * np.pi),
                    np.interp(theta, angles, alpha_s[order], period=2.0 * np.pi), card_load(reading.card, theta),
                    float(elapsed[-1]), "card") for theta in thetas]


def card_runs(unit, linkage: Linkage, source: CardSource, spm: float | None, grids: tuple[int, ...],
              rotation: str) -> tuple[CardReading, list[CardRun]]:
    """The card read once and run on each crank-angle grid of ``grids`` (steps per revolution)."""
    reading = source.read(linkage)
    thetas = [crank_grid(steps) for steps in grids]
    if rotation == "auto":
        rotation = "uniform" if reading.time is None or spm is not None else "card"
    if rotation == "uniform":
        omega = uniform_speed(unit, reading, spm)
        runs = [CardRun(theta, uniform_time(theta, omega), np.full(theta.size, omega), np.zeros(theta.size),
                        card_load(reading.card, theta), cycle_period(omega), rotation) for theta in thetas]
        return reading, runs
    if spm is not None:
        raise PumpjackError(f"--spm sets a uniform crank speed; with --rotation {rotation} the "
                            f"{'card' if rotation == 'card' else 'motor'} sets the speed")
    if rotation == "card":
        return reading, _card_rotations(linkage, reading, thetas)
    state = steady_state(machine(unit, reading.card), np.concatenate(thetas))
    runs, start = [], 0
    for theta in thetas:
        part = slice(start, start + theta.size)
        runs.append(CardRun(theta, state.time[part], state.omega[part], state.epsilon[part],
                            card_load(reading.card, theta), state.summary.period, rotation))
        start += theta.size
    return reading, runs


@dataclass(frozen=True)
class TimeCard:
    """A card on a uniform time grid over one period: t_k = k T / N [s], the crank angle
    [rad], the polished-rod position [m] from the bottom of the stroke (exact kinematics)
    and the load [N] at each sample."""

    time: np.ndarray
    crank_angle: np.ndarray
    position: np.ndarray
    load: np.ndarray
    period: float


def time_card(unit, linkage: Linkage, source: CardSource, spm: float | None, samples: int,
              rotation: str) -> tuple[CardReading, TimeCard]:
    """The card on ``samples`` equal time steps of one period: the crank's motion (uniform,
    from the card's time stamps or from the equation of motion) is resolved on a fine
    crank-angle grid and inverted, so a card of positions only is usable through the
    unit's exact kinematics."""
    reading, (run,) = card_runs(unit, linkage, source, spm, (RESAMPLE_FACTOR * samples,), rotation)
    time = np.arange(samples) * (run.period / samples)
    theta = np.interp(time, np.append(run.time, run.period), np.append(run.crank_angle, 2.0 * np.pi))
    return reading, TimeCard(time, theta, linkage.rod_position(theta), card_load(reading.card, theta), run.period)
