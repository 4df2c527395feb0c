"""A dynamometer card placed on a unit's crank-angle axis: once per card and run.

The columns of a card as read (:class:`pumpjack_cli.readers.cards.RawCard`: load with
crank angles, positions, or time stamps and positions, in SI) go onto the crank angle
of the unit's :class:`~pumpjack_cli.core.mechanism.Mechanism` here, through its exact
kinematics (:mod:`pumpjack_cli.core.beam.card`):

* crank angles are taken as given (wrapped to one turn);
* a position card is shifted to the bottom of the stroke and scaled to the unit's
  stroke (refused beyond 5 %, a warning beyond 2 %), read in reverse when its loop
  work says so, and each point is mapped on the branch of its direction of travel;
* a time card is placed by one least-squares fit of theta(t), uniform rotation plus
  :data:`HARMONICS` harmonics of a periodic speed variation, which gives the crank
  angle of every sample and, analytically from the fitted series, the crank speed
  omega = dtheta/dt and acceleration alpha = d2theta/dt2 there (``--rotation card``);
  the other rotation direction is tried when the fit is not near exact.

Every refusal is a one-line :class:`~pumpjack_cli.errors.CardError` starting with the
card's name; the warnings are returned, one line each (``docs/cards.md``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Required, TypedDict, TypeVar

import numpy as np

from ..errors import CardError
from ..quantities import SPM_RANGE
from .beam.card import (Card, RotationFit, card_from_angles, cards_from_angles, crank_angle_from_position, fit_input_errors,
                        fit_rotation, fit_rotations, largest_gap, loop_work, time_samples, upstroke_points)
from .beam.geometry import CLOCKWISE, COUNTERCLOCKWISE
from .mechanism import Mechanism
from .sampling import ahead, wrapped

#: Relative stroke mismatch refused, and warned about (the card is scaled to the unit's stroke).
STROKE_ERROR = 0.05
STROKE_WARNING = 0.02
#: RMS position residual of the time fit, relative to the stroke, refused and warned about.
FIT_ERROR = 0.10
FIT_WARNING = 0.02
#: Harmonics of the periodic crank-speed variation fitted to time stamps, for the angles and
#: the rates alike; fewer when the card has under four samples per angle parameter (2 + 2K).
#: Enough: the machine's equation of motion under the SK8-3,5-4000 sample card (load swing
#: halved, so that its motor can drive it) gives a crank speed whose harmonics 1 to 6 are
#: 1.7, 1.9, 0.65, 0.61, 0.32 and 0.31 % of the mean, the 7th 0.13 % and every higher one
#: (the rod string's stress waves) below 0.06 %: six leave 0.12 % RMS of omega, and a quarter
#: of alpha's RMS (the 7th harmonic and the waves), unfitted. Few enough: Gaussian position
#: noise sigma on a 180-sample card passes into omega as 5.5 sigma/S RMS and into alpha as
#: 24 sigma/S omega^2 (S the stroke; the least-squares covariance, tests/core/test_card_time.py),
#: against about 2.6 and 7.7 for four harmonics and 8.4 and 47 for eight: a dynamometer
#: resolving 1e-4 S gives omega to 0.06 % and alpha to 0.24 % of omega^2.
HARMONICS = 6
#: The other rotation direction "fits clearly better" when its uniform-rotation
#: residual is below half of the unit's and the unit's is above this fraction of the stroke.
ROTATION_EVIDENCE = 0.002
#: A loop whose work is below this fraction of (stroke range x load range) has no
#: clear orientation and is read as listed.
WORK_TOLERANCE = 1e-3
#: The largest crank rotation without a sample that still counts as a whole cycle [rad]
#: (or two mean sample spacings, if larger).
MAX_GAP = math.radians(30.0)

_ROTATION_NAMES = {CLOCKWISE: "clockwise", COUNTERCLOCKWISE: "counterclockwise"}


@dataclass(frozen=True)
class PlacedCard:
    """A card on the crank-angle axis, the samples it came from, and what was noticed.

    ``load`` [N], ``crank_angle`` [rad] (fitted or mapped, in [0, 2 pi)), ``position``
    [m] and ``time`` [s] are per sample, in SI, in cycle order (reversed when the file
    was), a repeated closing sample dropped; ``position`` as read (not shifted or
    scaled), None on a crank-angle card; ``time`` None without time stamps. ``speed``
    is the mean crank speed omega [rad/s] fitted to the time stamps (the card's pumping
    speed), ``crank_speed`` [rad/s] and ``crank_acceleration`` [rad/s²] the fitted
    speed and acceleration at each sample, ``fit_rms`` the RMS position residual of that
    fit [m] and ``fit_rms_relative`` the same over the unit's stroke [-]; all None
    without time stamps. ``reversed`` is True when the rows were read in reverse (one
    warning says so).
    """

    card: Card
    source: str
    warnings: tuple[str, ...]
    load: np.ndarray
    crank_angle: np.ndarray
    position: np.ndarray | None = None
    time: np.ndarray | None = None
    speed: float | None = None
    crank_speed: np.ndarray | None = None
    crank_acceleration: np.ndarray | None = None
    fit_rms: float | None = None
    fit_rms_relative: float | None = None
    reversed: bool = False

    @property
    def strokes_per_minute(self) -> float | None:
        """The card's pumping speed [1/min], None without time stamps."""
        return None if self.speed is None else self.speed * 30.0 / math.pi


class CardSamples(TypedDict, total=False):
    """One card's samples and names as :func:`place_card` takes them (its keywords), for :func:`place_cards`."""

    load: Required[np.ndarray]
    crank_angle: np.ndarray | None
    position: np.ndarray | None
    time: np.ndarray | None
    source: str
    position_unit: tuple[str, float]
    reversed: bool
    warnings: tuple[str, ...]


def place_card(mechanism: Mechanism, load: np.ndarray, *, crank_angle: np.ndarray | None = None,
               position: np.ndarray | None = None, time: np.ndarray | None = None, source: str = "the card",
               position_unit: tuple[str, float] = ("m", 1.0), reversed: bool = False,
               warnings: tuple[str, ...] = ()) -> PlacedCard:
    """Put a card's samples on the crank-angle axis of ``mechanism``: :func:`place_cards` with one card.

    Parameters
    ----------
    mechanism : Mechanism
        The unit the card was measured on (:meth:`~pumpjack_cli.core.mechanism.Mechanism.turned`
        gives it turning the other way, to try the other rotation direction).
    load : numpy.ndarray
        Polished-rod load of every sample [N].
    crank_angle : numpy.ndarray, optional
        Crank angles [rad] of an angle card.
    position : numpy.ndarray, optional
        Polished-rod positions [m] of a position or time card, as measured.
    time : numpy.ndarray, optional
        Increasing time stamps [s] of a time card.
    source : str
        The card's name, first in every message.
    position_unit : (str, float)
        The unit the file wrote positions in and its size [m], for messages.
    reversed : bool
        The samples were read in reverse (kept in :attr:`PlacedCard.reversed`).
    warnings : tuple of str
        The reader's warnings, kept before the placement's own.

    Returns
    -------
    PlacedCard
        The card on the crank-angle axis, the samples in cycle order, and for a time
        card its mean speed, crank speed and acceleration at every sample.

    Raises
    ------
    CardError
        The card cannot be placed (one line, starting with ``source`` but for the time
        fit's checks of its input).

    References
    ----------
    [Takacs2016], [SK8Rotation2013] (see :mod:`pumpjack_cli.core.beam.card`).
    """
    placed = place_cards(mechanism, [CardSamples(load=load, crank_angle=crank_angle, position=position, time=time,
                                                 source=source, position_unit=position_unit, reversed=reversed,
                                                 warnings=warnings)])[0]
    if isinstance(placed, CardError):
        raise placed
    return placed


def place_cards(mechanism: Mechanism, cards: Sequence[CardSamples]) -> list[PlacedCard | CardError]:
    """Put K cards of one unit on its crank-angle axis, each as :func:`place_card` puts it.

    Each card is checked, oriented and scaled as alone (the plain time cards of as many
    samples with one array computation for their checks, a card that fails one or draws a
    warning then on its own), and a card with crank angles or with positions only is placed
    so; the time cards of as many samples are then fitted together
    (:func:`~pumpjack_cli.core.beam.card.fit_rotations`, one array computation for the group,
    a card whose length no other card has alone), and the fit's checks, the rare fit of the
    other rotation direction and the coverage check are again per card, on the fitted angles
    of the group sorted at once. :func:`place_card` is this function with one card.

    Parameters
    ----------
    mechanism : Mechanism
        The unit the cards were measured on.
    cards : sequence of CardSamples
        For each card the keywords of :func:`place_card` (``load`` [N], ``crank_angle``
        [rad], ``position`` [m], ``time`` [s], ``source``, ``position_unit``, ``reversed``,
        ``warnings``).

    Returns
    -------
    list of PlacedCard or CardError
        For each card, in order, what :func:`place_card` returns for it, or the
        :class:`~pumpjack_cli.errors.CardError` it raises (so that a bad card does not stop
        the others).

    References
    ----------
    [Takacs2016], [SK8Rotation2013] (see :mod:`pumpjack_cli.core.beam.card`).
    """
    prepared = _prepared_all(mechanism, cards)
    groups: dict[int, dict[int, _TimeCard]] = {}
    for k, card in enumerate(prepared):
        if isinstance(card, _TimeCard):
            groups.setdefault(card.time.size, {})[k] = card
    fitted: dict[int, PlacedCard | CardError] = {}
    for group in groups.values():
        time_cards = list(group.values())
        fitted.update(zip(group, _finished_all(mechanism, time_cards, _fits(mechanism, time_cards))))
    return [fitted[k] if isinstance(card, _TimeCard) else card for k, card in enumerate(prepared)]


@dataclass(frozen=True)
class _TimeCard:
    """A time card checked, oriented and scaled (``scaled`` [m] from the bottom of the unit's
    stroke), waiting for its fit; ``notes`` the warnings so far."""

    load: np.ndarray
    position: np.ndarray
    time: np.ndarray
    scaled: np.ndarray
    source: str
    position_unit: tuple[str, float]
    notes: tuple[str, ...]
    reversed: bool


_Placed = TypeVar("_Placed")


def _caught(place: Callable[..., _Placed], *args: object) -> _Placed | CardError:
    """``place(*args)``, or the :class:`CardError` it raises."""
    try:
        return place(*args)
    except CardError as error:
        return error


def _prepared_all(mechanism: Mechanism, cards: Sequence[CardSamples]) -> list[PlacedCard | _TimeCard | CardError]:
    """Each card as :func:`_prepared` makes it (or the :class:`CardError` it raises): the plain time
    cards (:func:`_plain`) of as many samples checked together by :func:`_plain_time_cards`, every
    other card, and a plain one those checks single out, by :func:`_prepared` alone."""
    prepared: list[PlacedCard | _TimeCard | CardError | None] = [None] * len(cards)
    plain: dict[int, dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]]] = {}
    for k, card in enumerate(cards):
        columns = _plain(card)
        if columns is None:
            prepared[k] = _caught(_prepared, mechanism, card)
        else:
            plain.setdefault(columns[0].size, {})[k] = columns
    for group in plain.values():
        for k, found in zip(group, _plain_time_cards(mechanism, [cards[k] for k in group], list(group.values()))):
            prepared[k] = _caught(_prepared, mechanism, cards[k]) if found is None else found
    return [found for found in prepared if found is not None]


def _plain(card: CardSamples) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """The load, position and time of a time card that has them as 1-D float arrays of one length (at
    least 3) and has no crank angles; None for any other card."""
    load, position, time = card["load"], card.get("position"), card.get("time")
    if card.get("crank_angle") is not None or not isinstance(position, np.ndarray) or not isinstance(time, np.ndarray):
        return None
    if not isinstance(load, np.ndarray) or load.ndim != 1 or load.size < 3 or not load.shape == position.shape == time.shape:
        return None
    return (load, position, time) if load.dtype == position.dtype == time.dtype == np.float64 else None


def _plain_time_cards(mechanism: Mechanism, cards: list[CardSamples],
                      columns: list[tuple[np.ndarray, np.ndarray, np.ndarray]]) -> list[_TimeCard | None]:
    """Plain time cards of as many samples (their :func:`_plain` columns) ready for their fit, as
    :func:`_prepared` makes them, with its checks made for all of them at once (the rod moves both
    ways, the stroke within :data:`STROKE_WARNING` of the unit's, the loop work not reversed); None
    for a card that fails one of them or draws a warning, which :func:`_prepared` then takes alone
    to say so."""
    load, position = np.stack([load for load, _, _ in columns]), np.stack([position for _, position, _ in columns])
    steps = np.diff(position, axis=1)
    bottom = position.min(axis=1)
    card_stroke = position.max(axis=1) - bottom
    stroke = mechanism.dead_positions().stroke
    work = np.sum(0.5 * (load + ahead(load)) * (ahead(position) - position), axis=1)  # loop_work of each row
    plain = (np.any(steps, axis=1) & ~(steps.min(axis=1) >= 0) & ~(steps.max(axis=1) <= 0)
             & ~(np.abs(card_stroke / stroke - 1.0) > STROKE_WARNING)
             & ~(work < -WORK_TOLERANCE * card_stroke * (load.max(axis=1) - load.min(axis=1))))
    scaled = (position - bottom[:, None]) * np.divide(stroke, card_stroke, out=np.zeros_like(card_stroke), where=plain)[:, None]
    return [_TimeCard(*columns[k], scaled[k], card.get("source", "the card"), card.get("position_unit", ("m", 1.0)),
                      tuple(card.get("warnings", ())), card.get("reversed", False)) if plain[k] else None
            for k, card in enumerate(cards)]


def _prepared(mechanism: Mechanism, card: CardSamples) -> PlacedCard | _TimeCard:
    """An angle or position card placed, or a time card ready for its fit."""
    load, crank_angle, position, time = card["load"], card.get("crank_angle"), card.get("position"), card.get("time")
    source, reversed = card.get("source", "the card"), card.get("reversed", False)
    if crank_angle is not None:
        theta = wrapped(crank_angle)
        if np.all(theta == theta[0]):
            raise CardError(f"{source}: every crank angle is {math.degrees(theta[0]):.6g} deg; a card covers a whole cycle")
        _check_coverage(theta, source, "crank angles")
        placed = card_from_angles(theta, load)
        swept = mechanism.rod_position(placed.crank_angle)
        work = loop_work(swept, placed.load)
        if work < -WORK_TOLERANCE * float(np.ptp(swept)) * float(np.ptp(load)):
            raise CardError(f"{source}: on these crank angles the rods do {-work:.4g} J of work on the unit per "
                            f"cycle; a pumping unit does positive work: crank angles measured against the rotation, "
                            f"or a sign inverted?")
        return PlacedCard(placed, source, tuple(card.get("warnings", ())), load, theta, reversed=reversed)
    if position is None:
        raise CardError(f"{source}: a card has crank angles or polished-rod positions; this one has neither")
    unit, factor = position_unit = card.get("position_unit", ("m", 1.0))
    steps = np.diff(position)
    if np.all(steps == 0):
        raise CardError(f"{source}: the polished rod does not move (every position is {position[0] / factor:.6g} {unit}); "
                        f"a card covers a whole cycle")
    if np.all(steps >= 0) or np.all(steps <= 0):
        raise CardError(f"{source}: the polished rod moves only {'up' if steps.sum() > 0 else 'down'}; "
                        f"a card covers a whole cycle")
    stroke = mechanism.dead_positions().stroke
    card_stroke = float(position.max() - position.min())
    mismatch = card_stroke / stroke - 1.0
    message = (f"{source}: card stroke {card_stroke / factor:.4g} {unit} differs from the unit's exact stroke "
               f"{stroke / factor:.4g} {unit} by {100 * mismatch:+.1f} %")
    notes = list(card.get("warnings", ()))
    if abs(mismatch) > STROKE_ERROR:
        raise CardError(f"{message}; {position_slip(card_stroke / stroke, unit) or 'wrong unit, crank hole or position units?'}")
    if abs(mismatch) > STROKE_WARNING:
        notes.append(f"{message}; positions scaled to the unit's stroke")
    work = loop_work(position, load)
    if work < -WORK_TOLERANCE * card_stroke * float(np.ptp(load)):
        if time is not None:
            raise CardError(f"{source}: in time order the rods do {-work:.4g} J of work on the unit per cycle; a pumping "
                            f"unit does positive work: rows reversed against their time stamps, or a sign inverted?")
        reversed = True
        position, load = position[::-1], load[::-1]
        notes.append(f"{source}: listed in reverse (the rods would do {-work:.4g} J of work on the unit per cycle; "
                     f"a pumping unit lifts them on the high load); read in reverse order")
    scaled = (position - position.min()) * (stroke / card_stroke)
    if time is None:
        theta = crank_angle_from_position(mechanism, scaled, upstroke_points(scaled))
        _check_coverage(theta, source, "positions")
        return PlacedCard(card_from_angles(theta, load), source, tuple(notes), load, theta, position, reversed=reversed)
    time, scaled = time_samples(time, scaled)
    return _TimeCard(load, position, time, scaled, source, position_unit, tuple(notes), reversed)


def _fits(mechanism: Mechanism, cards: list[_TimeCard]) -> list[RotationFit | CardError]:
    """The rotations of time cards of as many samples, fitted together; a card the fit refuses gets its error."""
    time, scaled = np.stack([card.time for card in cards]), np.stack([card.scaled for card in cards])
    harmonics = harmonics_for(time.shape[1])
    errors = fit_input_errors(time, scaled, harmonics)
    fine = [k for k, error in enumerate(errors) if not error]
    fits = iter(fit_rotations(mechanism, time[fine], scaled[fine], harmonics))
    return [CardError(error) if error else next(fits) for error in errors]


def _finished_all(mechanism: Mechanism, cards: list[_TimeCard],
                  fits: list[RotationFit | CardError]) -> list[PlacedCard | CardError]:
    """Time cards of as many samples placed by their fits, each once the fit's checks pass
    (:func:`_rotation`) and its samples cover the revolution, or the error that says why not; the
    fitted angles of all of them wrapped, sorted and made cards at once
    (:func:`~pumpjack_cli.core.beam.card.cards_from_angles`)."""
    good = {k: fit for k, fit in enumerate(fits) if isinstance(fit, RotationFit)}
    done: dict[int, PlacedCard | CardError] = {}
    if good:
        theta = np.stack([fit.crank_angle for fit in good.values()]) % (2.0 * math.pi)
        slowest = np.min(np.stack([fit.crank_speed for fit in good.values()]), axis=1)
        placed, gaps = cards_from_angles(theta, np.stack([cards[k].load for k in good]))
        stroke = mechanism.dead_positions().stroke
    for row, (k, fit) in enumerate(good.items()):
        card = cards[k]
        try:
            notes = [*card.notes, *_rotation(mechanism, fit, float(slowest[row]), card.time, card.scaled,
                                             card.position_unit, card.source)]
            _check_speed(fit.speed * 30.0 / math.pi, card.source)
            _check_gap(float(gaps[row]), theta.shape[1], card.source,
                       f"samples at the fitted {fit.speed * 30.0 / math.pi:.4g} strokes/min")
        except CardError as error:
            done[k] = error
            continue
        done[k] = PlacedCard(placed[row], card.source, tuple(notes), card.load, theta[row], card.position, card.time,
                             fit.speed, fit.crank_speed, fit.crank_acceleration, fit.rms, fit.rms / stroke, card.reversed)
    return [fit if isinstance(fit, CardError) else done[k] for k, fit in enumerate(fits)]


def _check_speed(spm: float, source: str) -> None:
    """Refuse a card whose time stamps give a pumping speed outside :data:`SPM_RANGE` (no beam unit's
    card: a time column in other units than seconds, or written wrong)."""
    if not SPM_RANGE[0] <= spm <= SPM_RANGE[1]:
        raise CardError(f"{source}: its time stamps give {spm:.4g} strokes/min, outside {SPM_RANGE[0]:g} .. "
                        f"{SPM_RANGE[1]:g}; is the time column in seconds?")


#: Lengths a position column is commonly written in [m], for naming a slip.
LENGTH_UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}


def position_slip(ratio: float, written: str) -> str:
    """The unit slip that makes a card's stroke ``ratio`` times the unit's when its positions are
    labelled ``written`` (numbers in another length unit), said as a question, or '' when no
    unit of :data:`LENGTH_UNITS` is within :data:`STROKE_ERROR`.

    >>> position_slip(1000.0, "m"), position_slip(1 / 0.0254 * 1.01, "m"), position_slip(1e-3, "in")
    ('positions in mm written as m?', 'positions in in written as m?', '')
    """
    read = LENGTH_UNITS.get(written)
    for true, size in LENGTH_UNITS.items():
        if read is not None and true != written and abs(ratio / (read / size) - 1.0) <= STROKE_ERROR:
            return f"positions in {true} written as {written}?"
    return ""


def _check_coverage(theta: np.ndarray, source: str, what: str) -> None:
    _check_gap(largest_gap(theta), theta.size, source, what)


def _check_gap(gap: float, samples: int, source: str, what: str) -> None:
    """Refuse a card whose ``samples`` crank angles leave ``gap`` [rad] of the revolution without a sample."""
    if gap > max(MAX_GAP, 4.0 * math.pi / samples):
        raise CardError(f"{source}: the {what} leave {math.degrees(gap):.0f} deg of the crank's revolution without "
                        f"a sample; a card covers a whole cycle")


def harmonics_for(samples: int) -> int:
    """Harmonics fitted to a time card of ``samples`` samples: :data:`HARMONICS`, or as many
    as leave four samples per angle parameter (2 + 2K).

    >>> harmonics_for(180), harmonics_for(24), harmonics_for(8)
    (6, 2, 0)
    """
    return max(0, min(HARMONICS, (samples // 4 - 2) // 2))


def _rotation(mechanism: Mechanism, fit: RotationFit, slowest: float, time: np.ndarray, scaled: np.ndarray,
              position_unit: tuple[str, float], source: str) -> list[str]:
    """The time fit's checks (``slowest`` the least of its crank speeds [rad/s]), and its warnings;
    the other rotation direction is fitted only when the uniform fit is not near exact."""
    stroke = mechanism.dead_positions().stroke
    relative = fit.rms / stroke
    unit, factor = position_unit
    residual = f"RMS position error {fit.rms / factor:.3g} {unit}, {100 * relative:.2g} % of the stroke"
    if relative > FIT_ERROR:
        raise CardError(f"{source}: the time stamps do not fit this unit's motion ({residual}); "
                        f"wrong columns or a card from another unit?")
    if slowest <= 0.0:
        raise CardError(f"{source}: the crank angles fitted to the time stamps turn backwards at times "
                        f"(crank speed {slowest:.3g} rad/s); wrong columns or a card from another unit?")
    if fit.uniform_rms > ROTATION_EVIDENCE * stroke:
        other = fit_rotation(mechanism.turned(), time, scaled)
        if other.uniform_rms < 0.5 * fit.uniform_rms:
            own_name, other_name = _ROTATION_NAMES[mechanism.rotation], _ROTATION_NAMES[-mechanism.rotation]
            return [(f"{source}: at a steady crank speed the time stamps fit {other_name} rotation better than "
                     f"the unit's {own_name} (RMS position error {100 * other.uniform_rms / stroke:.2g} % of the "
                     f"stroke against {100 * fit.uniform_rms / stroke:.2g} %); check the unit's rotation")]
    if relative > FIT_WARNING:
        return [(f"{source}: the time stamps fit this unit's motion only roughly ({residual}); "
                 f"the fitted crank angles are used")]
    return []
