"""A dynamometer card on crank-angle grids, with uniform or dynamic crank rotation.

A card is read without a unit (:func:`pumpjack_cli.readers.cards.read_card`) and placed
on the unit's crank-angle axis (:func:`pumpjack_cli.core.cards.place_card`) once, by
:meth:`CardSource.read`; ``--crank-motion card`` takes the crank speed and acceleration that
the placement's time fit gives at every sample.

The crank speed of a uniform run is the card's own when its time stamps give one (a
``--spm`` that disagrees by more than 2 % is an error that prints both), else the SPM
the file states, else ``--spm``, else the motor's rated speed through the drive. An SPM
the file states is checked against the time stamps too. A run is evaluated on the
output grid (``--steps``) and on a fixed summary grid, so that the extremes a command
reports do not depend on ``--steps``.

A file of several strokes (a continuous recording, a hex file of several blocks) gives
the card ``--stroke`` chooses: a stroke's number, the last (the default: the card a
controller shows, the most recent), or the median card of all its strokes
(:func:`median_card`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..core.beam.card import card_from_angles, card_load, periodic_interp, periodic_table, periodic_tables
from ..core.cards import PlacedCard, place_cards
from ..core.dynamics.periodic import steady_state
from ..core.mechanism import Mechanism
from ..core.rods.plausibility import check_cards_loads
from ..core.sampling import crank_grid, cycle_period, uniform_time
from ..errors import CardError, PumpjackError, collected_warnings, warn
from ..quantities import parse_quantity
from ..readers.cards import RawCard, check_options, read_card

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: --spm and the card's time stamps may differ by this fraction; the card's speed wins. So may
#: the SPM a file states and its time stamps, or --spm and the SPM stated by a card without them.
SPEED_TOLERANCE = 0.02
#: Steps of the integration t = int dtheta / omega over one revolution.
FINE_STEPS = 3600
#: The crank angles of that integration, 0 to 2 pi [rad].
_FINE = np.linspace(0.0, 2.0 * np.pi, FINE_STEPS + 1)
_FINE.flags.writeable = False
#: Crank-angle points per time sample when a card is put on a uniform time grid.
RESAMPLE_FACTOR = 8
#: The strokes ``--stroke`` may choose besides a number (from 1).
STROKE_CHOICES = ("last", "median")
#: Crank positions on which a card's plausibility is judged.
PLAUSIBILITY_STEPS = 360

#: Crank-motion models of the card-driven analyses: constant speed; the speed and
#: acceleration fitted to the card's time stamps; the machine's equation of motion;
#: auto: the card's time stamps if it has them and no --spm is given, else constant speed.
CRANK_MOTIONS = ("uniform", "card", "dynamic", "auto")


@dataclass(frozen=True)
class Reading(PlacedCard):
    """A placed card (:class:`~pumpjack_cli.core.cards.PlacedCard`) with the pumping speed its
    file states when it has no time stamps to measure one: ``stated_speed`` [rad/s] and the
    file's line of it, None without (a card with time stamps has its stated SPM checked
    against them instead)."""

    stated_speed: float | None = None
    stated_line: int | None = None

    @cached_property
    def motion_tables(self) -> tuple[tuple[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray], np.ndarray,
                                     np.ndarray]:
        """The fitted crank speed's and acceleration's periodic tables, and the speed and the time
        from crank angle 0 on the fine grid of :func:`_card_motion` (made once for every grid a
        card is run on; :func:`with_motion_tables` makes those of a unit's cards together)."""
        (found,) = _motion_tables([self])
        return found


def with_motion_tables(readings: list[Reading]) -> None:
    """Make the motion tables (:attr:`Reading.motion_tables`) of cards with time stamps together,
    those of as many samples in one array computation (each card's as alone)."""
    groups: dict[int, list[Reading]] = {}
    for reading in readings:
        if reading.time is not None and "motion_tables" not in vars(reading):
            groups.setdefault(reading.crank_angle.size, []).append(reading)
    for group in groups.values():
        for reading, tables in zip(group, _motion_tables(group)):
            object.__setattr__(reading, "motion_tables", tables)   # what the cached property would store


def _motion_tables(readings: list[Reading]) -> list[tuple]:
    """:attr:`Reading.motion_tables` of cards of as many samples, one array computation."""
    angle = np.array([r.crank_angle for r in readings])
    speed = periodic_tables(angle, np.array([r.crank_speed for r in readings]))
    acceleration = periodic_tables(angle, np.array([r.crank_acceleration for r in readings]))
    fine = np.empty((len(readings), FINE_STEPS + 1))
    for k in range(len(readings)):
        fine[k, :-1] = np.interp(_FINE[:-1], speed[0][k], speed[1][k])
    fine[:, -1] = fine[:, 0]      # 2 pi is crank angle 0
    elapsed = _elapsed(_FINE, fine)
    return [((speed[0][k], speed[1][k]), (acceleration[0][k], acceleration[1][k]), fine[k], elapsed[k])
            for k in range(len(readings))]


def parse_stroke(text: str | None) -> int | str:
    """The stroke ``--stroke`` chooses: a number from 1, ``last`` (also for None) or ``median``.

    >>> parse_stroke("3"), parse_stroke(None), parse_stroke("Median")
    (3, 'last', 'median')
    """
    choice = "last" if text is None else text.strip().lower()
    if choice in STROKE_CHOICES:
        return choice
    if choice.isdigit() and int(choice) >= 1:
        return int(choice)
    raise CardError(f"--stroke {text!r}: a stroke's number (from 1), last or median")


@dataclass(frozen=True)
class CardSource:
    """Where a card comes from and how it is read: a path (``-`` for standard input), the
    units of columns whose file names none (None: such a column is refused), an optional
    column mapping kind -> header (``--card-columns``, parsed), the format (None: told from
    the content and the name), the points of a card block, and the stroke of a file of
    several (:func:`parse_stroke`)."""

    path: Path
    units: str | None = None
    columns: Mapping[str, str] | None = None
    format: str | None = None
    points: int | None = None
    stroke: int | str = "last"

    def __post_init__(self):
        check_options(self.format, self.units, self.points)

    def raw(self) -> RawCard:
        """The card file read (no unit yet): for a file of several strokes, the last, holding all."""
        return read_card(self.path, self.format, self.units, self.columns, points=self.points)

    def read(self, unit: UnitConfig, spm: float | None = None) -> Reading:
        """The chosen card read, placed on the unit's crank-angle axis and checked against what
        the unit and its rods can produce (:func:`noted`). ``spm`` [1/min], the ``--spm``
        option, is the speed of a card without time stamps or a stated SPM."""
        return noted(chosen(self.raw(), self.stroke, unit.geometry.mechanism()), unit, spm)

    @property
    def name(self) -> str:
        """The card's name for titles."""
        return "<stdin>" if str(self.path) == "-" else self.path.name


def noted(reading: Reading, unit: UnitConfig, spm: float | None) -> Reading:
    """The reading checked against what the unit and its rods can produce (:func:`judged`,
    the one rule of every command), its warnings noted (:func:`~pumpjack_cli.errors.warn`)."""
    (found,) = judged(unit, [reading], spm)
    if isinstance(found, CardError):
        raise found
    for warning in found:
        warn(warning)
    return reading


def chosen(raw: RawCard, stroke: int | str, mechanism: Mechanism) -> Reading:
    """The card ``stroke`` chooses among a file's strokes (a file of one card is its only
    stroke), placed on ``mechanism``."""
    strokes = raw.strokes or (raw,)
    if stroke == "median" and raw.strokes:
        return median_card(raw, mechanism)
    if stroke in STROKE_CHOICES:
        return place(strokes[-1], mechanism)
    if not 1 <= int(stroke) <= len(strokes):
        held = f"{len(strokes)} strokes" if raw.strokes else "one card, not a recording of several strokes"
        raise CardError(f"{raw.source}: --stroke {stroke}: the file holds {held}")
    return place(strokes[int(stroke) - 1], mechanism)


def place(raw: RawCard, mechanism: Mechanism) -> Reading:
    """A raw card on the crank-angle axis of ``mechanism``: :func:`place_all` of one card."""
    (found,) = place_all([raw], mechanism)
    if isinstance(found, CardError):
        raise found
    return found


def place_all(raws: list[RawCard], mechanism: Mechanism) -> list[Reading | CardError]:
    """Raw cards on the crank-angle axis of ``mechanism``, together
    (:func:`~pumpjack_cli.core.cards.place_cards`: the time fits of a unit's cards one array
    computation), their messages in each file's own position unit, with the SPM each file
    states (:func:`stated`); a card that cannot be placed gets its error."""
    placed = place_cards(mechanism, [
        {"load": raw.load, "crank_angle": raw.crank_angle, "position": raw.position, "time": raw.time,
         "source": raw.source, "position_unit": raw.column_units.get("position", ("m", 1.0)),
         "reversed": raw.reversed, "warnings": raw.warnings} for raw in raws])
    out: list[Reading | CardError] = []
    for found, raw in zip(placed, raws):
        try:
            out.append(found if isinstance(found, CardError) else stated(found, raw))
        except CardError as exc:
            out.append(exc)
    return out


def stated(placed: PlacedCard, raw: RawCard) -> Reading:
    """``placed`` with the SPM ``raw``'s file states: checked against the speed of its time
    stamps (refused beyond :data:`SPEED_TOLERANCE`, as ``--spm``), or kept as the card's
    pumping speed when it has none."""
    fields = {name: getattr(placed, name) for name in PlacedCard.__dataclass_fields__}
    if "spm" not in raw.metadata:
        return Reading(**fields)
    line = raw.metadata_lines.get("spm")
    speed = float(raw.metadata["spm"]) * math.pi / 30.0
    if placed.speed is None:
        return Reading(**fields, stated_speed=speed, stated_line=line)
    _agree(speed, placed.speed, f"{raw.source}: line {line}: the stated SPM", "the card's time stamps",
           "check the SPM line or the time column")
    return Reading(**fields)


def _periodic(theta: np.ndarray, angle: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Per-sample ``values`` at crank angles ``angle`` [rad], interpolated periodically at ``theta``."""
    return periodic_interp(theta, periodic_table(angle, values))


def median_card(raw: RawCard, mechanism: Mechanism) -> Reading:
    """The median card of a file's strokes, point by point on a common crank-angle grid.

    Each stroke is placed on ``mechanism`` (its own time fit, the strokes' fits one array
    computation, :func:`place_all`), its load interpolated
    periodically on a grid of as many crank angles as the longest stroke has samples,
    and the median taken at each angle; likewise the fitted crank speed and
    acceleration of strokes with time stamps, whose mean speed is then 2 pi over the
    period T = integral of dtheta / omega. The median follows the strokes' common shape
    and ignores a stroke that departs from it (a gas pound, a glitch), which a mean would
    smear into every angle.
    """
    placed = place_all(list(raw.strokes), mechanism)
    for found in placed:
        if isinstance(found, CardError):
            raise found
    theta = crank_grid(max(p.crank_angle.size for p in placed))
    load = np.median([card_load(p.card, theta) for p in placed], axis=0)
    common = {"card": card_from_angles(theta, load), "source": raw.source, "load": load, "crank_angle": theta,
              "warnings": tuple(warning for p in placed for warning in p.warnings)}
    if any(p.time is None for p in placed):
        return stated(PlacedCard(**common), raw)
    omega = np.median([_periodic(theta, p.crank_angle, p.crank_speed) for p in placed], axis=0)
    alpha = np.median([_periodic(theta, p.crank_angle, p.crank_acceleration) for p in placed], axis=0)
    elapsed = _elapsed(np.append(theta, 2.0 * np.pi), np.append(omega, omega[0]))
    return stated(PlacedCard(**common, time=elapsed[:-1], speed=2.0 * np.pi / elapsed[-1], crank_speed=omega,
                             crank_acceleration=alpha, fit_rms=max(p.fit_rms for p in placed),
                             fit_rms_relative=max(p.fit_rms_relative for p in placed)), raw)


def _agree(given: float, known: float, given_name: str, known_name: str, hint: str) -> None:
    """Refuse two pumping speeds [rad/s] that differ by more than :data:`SPEED_TOLERANCE`,
    printing both in strokes per minute."""
    mismatch = given / known - 1.0
    if abs(mismatch) > SPEED_TOLERANCE:
        raise CardError(f"{given_name} {given * 30.0 / math.pi:.4g} disagrees with {known_name} "
                        f"({known * 30.0 / math.pi:.4g} strokes/min) by {100 * mismatch:+.1f} %; {hint}")


#: Crank speed assumed for the plausibility of a card without time stamps, stated SPM, --spm or
#: drive [strokes/min]: the fast end of beam pumping, which makes the peak-load bound generous.
FAST_PUMPING = 20.0


def judged(unit: UnitConfig, readings: list[Reading], spm: float | None) -> list[tuple[str, ...] | CardError]:
    """Each card's warnings (its own and the warning of a parted string, if any), or the refusal
    of a card the unit and its rods cannot have made, with the same one line for every command
    (:func:`~pumpjack_cli.core.rods.plausibility.check_cards_loads`, the cards of one unit
    judged in one array computation)."""
    mechanism = unit.geometry.mechanism()
    theta = crank_grid(PLAUSIBILITY_STEPS)
    verdicts = check_cards_loads(np.array([card_load(r.card, theta) for r in readings]), mechanism.rod_position(theta),
                                 stroke=mechanism.stroke, crank_speeds=np.array([_judged_speed(unit, r, spm)
                                                                                 for r in readings]),
                                 well=unit.well_limits(), structure_rating=unit.ratings().structure_load,
                                 sources=[r.source for r in readings])
    return [verdict if isinstance(verdict, CardError) else reading.warnings + ((verdict.warning,) if verdict.warning
                                                                              else ())
            for reading, verdict in zip(readings, verdicts)]


def _judged_speed(unit: UnitConfig, reading: Reading, spm: float | None) -> float:
    """The crank speed [1/s] a card's loads are judged at: its time stamps', the SPM its file
    states, ``--spm``, the drive's, else :data:`FAST_PUMPING`."""
    if reading.speed is not None:
        return reading.speed
    if reading.stated_speed is not None:
        return reading.stated_speed
    if spm is not None or unit.drive is None:
        return parse_quantity(f"{FAST_PUMPING if spm is None else spm} spm", "rotational_speed")
    return unit.crank_speed(None)


def check_speed(card_speed: float | None, spm_option: float | None, source: str = "the card") -> float | None:
    """The crank speed to use [rad/s]: the card's, checked against an ``--spm`` given too.

    Parameters
    ----------
    card_speed : float or None
        Crank speed fitted to the card's time stamps [rad/s] (``PlacedCard.speed``).
    spm_option : float or None
        Crank speed given on the command line [rad/s] (``--spm`` converted).
    source : str
        The card's name for the message.

    Returns
    -------
    float or None
        ``card_speed`` when there is one (the time stamps are the measurement),
        otherwise ``spm_option``.

    Raises
    ------
    CardError
        When both are given and differ by more than :data:`SPEED_TOLERANCE` (2 %);
        the message prints both in strokes per minute.

    >>> check_speed(0.6283, 0.63)            # 6.00 and 6.02 strokes/min: the card wins
    0.6283
    >>> check_speed(None, 0.63)
    0.63
    """
    for name, value in (("card speed", card_speed), ("--spm", spm_option)):
        if value is not None and not (math.isfinite(value) and value > 0):
            raise CardError(f"{name} {value!r}: not a positive speed")
    if card_speed is None or spm_option is None:
        return spm_option if card_speed is None else card_speed
    _agree(spm_option, card_speed, "--spm", f"the time stamps of {source}", "drop --spm or check the card")
    return card_speed


@dataclass(frozen=True)
class CardRun:
    """Crank angles [rad], time [s], crank speed [1/s] and acceleration [1/s²] and the
    card's polished-rod load [N] on them, the cycle time [s] and the crank-motion model."""

    crank_angle: np.ndarray
    time: np.ndarray
    crank_speed: np.ndarray
    crank_acceleration: np.ndarray
    load: np.ndarray
    period: float
    crank_motion: str

    @property
    def mean_crank_speed(self) -> float:
        """Mean crank speed over the cycle [1/s] (2 pi / cycle time)."""
        return 2.0 * np.pi / self.period


def uniform_speed(unit: UnitConfig, reading: Reading, spm: float | None) -> float:
    """Crank speed [1/s] of a uniform run: the card's time stamps, else the SPM its file
    states, else ``--spm``, else the drive."""
    option = None if spm is None else parse_quantity(f"{spm} spm", "rotational_speed")
    speed = check_speed(reading.speed, option, reading.source)
    if reading.stated_speed is not None:
        if option is not None:
            _agree(option, reading.stated_speed, "--spm", f"the SPM {reading.source} states on line "
                   f"{reading.stated_line}", "drop --spm or check the card")
        speed = reading.stated_speed
    return unit.crank_speed(None) if speed is None else speed


def _elapsed(theta: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Time [s] from crank angle 0 at each of the increasing crank angles ``theta`` [rad] from 0
    (the last 2 pi: the period), t = integral of dtheta / omega, by the trapezoidal rule; for
    the speeds ``omega`` of one card (N,) or of K cards (K, N)."""
    rate = 1.0 / omega
    steps = np.cumsum(0.5 * (rate[..., 1:] + rate[..., :-1]) * np.diff(theta), axis=-1)
    return np.concatenate([np.zeros(steps.shape[:-1] + (1,)), steps], axis=-1)


def _card_motion(reading: Reading, thetas: list[np.ndarray]) -> list[CardRun]:
    """The crank speed and acceleration fitted to the card's time stamps ([Takacs2016]), on each grid
    (on the grid of the time integration, its values)."""
    if reading.time is None:
        raise PumpjackError(f"{reading.source}: --crank-motion card needs a card with time stamps")
    speed, acceleration, fine, elapsed = reading.motion_tables
    runs = []
    for theta in thetas:
        on_fine = theta.size == FINE_STEPS and np.array_equal(theta, _FINE[:-1])
        runs.append(CardRun(theta, elapsed[:-1] if on_fine else np.interp(theta, _FINE, elapsed),
                            fine[:-1] if on_fine else periodic_interp(theta, speed),
                            periodic_interp(theta, acceleration), card_load(reading.card, theta), float(elapsed[-1]),
                            "card"))
    return runs


def card_runs(unit: UnitConfig, mechanism: Mechanism, source: CardSource, spm: float | None, grids: tuple[int, ...],
              crank_motion: str) -> tuple[Reading, list[CardRun]]:
    """The card read once and run on each crank-angle grid of ``grids`` (steps per revolution)."""
    reading = source.read(unit, spm)
    return reading, reading_runs(unit, reading, spm, grids, crank_motion)


def reading_runs(unit: UnitConfig, reading: Reading, spm: float | None, grids: tuple[int, ...],
                 crank_motion: str) -> list[CardRun]:
    """A card read and placed, run on each crank-angle grid of ``grids`` (steps per revolution)."""
    thetas = [crank_grid(steps) for steps in grids]
    if crank_motion == "auto":
        crank_motion = "uniform" if reading.time is None or spm is not None else "card"
    if crank_motion == "uniform":
        omega = uniform_speed(unit, reading, spm)
        return [CardRun(theta, uniform_time(theta, omega), np.full(theta.size, omega), np.zeros(theta.size),
                        card_load(reading.card, theta), cycle_period(omega), crank_motion) for theta in thetas]
    if spm is not None:
        raise PumpjackError(f"--spm sets a uniform crank speed; with --crank-motion {crank_motion} the "
                            f"{'card' if crank_motion == 'card' else 'motor'} sets the speed")
    if crank_motion == "card":
        return _card_motion(reading, thetas)
    state = steady_state(unit.machine(reading.card), np.concatenate(thetas))
    runs, start = [], 0
    for theta in thetas:
        part = slice(start, start + theta.size)
        runs.append(CardRun(theta, state.time[part], state.crank_speed[part], state.crank_acceleration[part],
                            card_load(reading.card, theta), state.summary.period, crank_motion))
        start += theta.size
    return runs


def each_card(cards: list, compute) -> tuple[dict[int, object], list, list[list[str]]]:
    """``compute(card)`` of each card with its warnings noted apart: the values by the cards'
    indices, each card's error (None where there is none) and each card's warnings (the K-card
    analyses start so: one card's problem stays that card's)."""
    values: dict[int, object] = {}
    errors: list = [None] * len(cards)
    said: list[list[str]] = [[] for _ in cards]
    for k, card in enumerate(cards):
        with collected_warnings() as noted:
            try:
                values[k] = compute(card)
            except PumpjackError as exc:
                errors[k] = exc
        said[k] += noted
    return values, errors, said


def alone(found: list[tuple[object, tuple[str, ...]]]):
    """The one card of a K-card analysis ([(value or error, warnings)]): its warnings given
    (:func:`~pumpjack_cli.errors.warn`), its error raised, else its value."""
    ((value, said),) = found
    for text in said:
        warn(text)
    if isinstance(value, PumpjackError):
        raise value
    return value


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


def time_card(unit: UnitConfig, mechanism: Mechanism, source: CardSource, spm: float | None, samples: int,
              crank_motion: str) -> tuple[Reading, TimeCard]:
    """The card on ``samples`` equal time steps of one period: :func:`time_cards` of one card."""
    readings, errors, said = time_cards(unit, mechanism, [source], spm, samples, crank_motion)
    return alone([(readings.get(0, errors[0]), tuple(said[0]))])


def time_cards(unit: UnitConfig, mechanism: Mechanism, sources: list, spm: float | None, samples: int,
               crank_motion: str) -> tuple[dict[int, tuple[Reading, TimeCard]], list, list[list[str]]]:
    """Each card on ``samples`` equal time steps of one period, as :func:`each_card` gives them
    (the readings and time cards by the cards' indices, each card's error and warnings): the
    crank's motion (uniform, from the card's time stamps or from the equation of motion) is
    resolved on a fine crank-angle grid and inverted, so a card of positions only is usable
    through the unit's exact kinematics; the polished rod's positions of all the cards are one
    array computation."""
    grid = crank_grid(RESAMPLE_FACTOR * samples)

    def timed(source) -> tuple[Reading, np.ndarray, float]:
        reading = source.read(unit, spm)
        card_motion = reading.time is not None and (crank_motion == "card" or (crank_motion == "auto" and spm is None))
        if card_motion and spm is None:       # the time integration's table, without the rest of a run
            *_, elapsed = reading.motion_tables
            return reading, np.interp(grid, _FINE, elapsed), float(elapsed[-1])
        (run,) = reading_runs(unit, reading, spm, (grid.size,), crank_motion)
        return reading, run.time, run.period

    found, errors, said = each_card(sources, timed)
    keys = sorted(found)
    if not keys:
        return {}, errors, said
    periods = [found[k][2] for k in keys]
    times = np.arange(samples) * (np.array(periods) / samples)[:, None]
    # each card's crank angles at its times, the inverse of its time at the grid's angles (and of
    # its period at 2 pi), that table's rows written in one array for every card
    when, angles = np.empty(grid.size + 1), np.append(grid, 2.0 * np.pi)
    thetas = np.empty((len(keys), samples))
    for theta, time, k, period in zip(thetas, times, keys, periods):
        when[:-1], when[-1] = found[k][1], period
        theta[:] = np.interp(time, when, angles)
    positions = mechanism.rod_position(thetas.ravel()).reshape(thetas.shape)
    cards = {}
    for k, time, theta, position, period in zip(keys, times, thetas, positions, periods):
        reading = found[k][0]
        cards[k] = reading, TimeCard(time, theta, position, card_load(reading.card, theta), period)
    return cards, errors, said
