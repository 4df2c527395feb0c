"""Gearbox torque, counterbalance and loading from a dynamometer card: the result of `pumpjack torque`.

The API 11E torque-factor method ([API11E], [Rowlan2004]) needs only the geometry,
the card and the counterbalance (B, M, tau from ``[counterbalance]`` or from the
masses); the exact method is the spatial kinetostatics of `pumpjack reactions` with
link weights and inertia ([Spatial7SK12]). The net torque is decomposed as
[Takacs2016] does, with the crank's speed and acceleration from the card's time stamps
(``--crank-motion card``, the default for a time-stamped card), uniform, or from the
machine's equation of motion. The counterbalance that meets a balance criterion, the
loading against the ratings of the unit's designation and the permissible load diagram
([GaultSWPSC]) follow.
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..core.beam.balance import balance_criteria, recommend_counterbalances
from ..core.beam.card import Card
from ..core.beam.counterbalance import (
    Counterbalance,
    CounterbalanceModel,
    counterbalance_effect,
    counterweight_placement,
    upstroke_mask,
    upstroke_test_angle,
)
from ..core.beam.loading import card_works, cyclic_load_factor, driving_work, stroke_peaks
from ..core.beam.torque import (
    ExactTorqueBasis,
    TorqueComponents,
    beam_group_inertia,
    crank_group_inertia,
    exact_torque_basis,
    permissible_load,
    torque_components,
    torque_methods,
)
from ..core.designations import Ratings
from ..core.motors import nema_motor_size
from ..core.sampling import Extreme, extremes_of, peaks_of
from ..errors import BalanceError, PumpjackError, collected_warnings, warn
from ..quantities import DAY, HORSEPOWER, INCH
from ..results import Column, Curve, Panel, Result, Scalar
from .card_runs import CardRun, CardSource, alone, card_runs, each_card
from .inputs import crank_columns, dead_position_marks, extreme_scalars

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: Crank positions of the grid on which the summary's extremes, balance and loading are computed.
SUMMARY_STEPS = 3600
#: Largest counterweight radius considered when the unit gives no slot range [m] (the schema's limit).
MAX_RADIUS = 5.0
@dataclass(frozen=True)
class _Torques:
    """Torque terms [N·m] on one crank-angle grid and the net torque of the chosen method."""

    run: CardRun
    components: TorqueComponents
    api: np.ndarray
    exact: np.ndarray | None
    net: np.ndarray


def _torques(context: _TorqueContext, run: CardRun) -> _Torques:
    """The torque terms of a run; the exact net torque too for a unit with the spatial model and masses."""
    parts = _components(context, run.crank_angle, run.load, run.crank_speed, run.crank_acceleration)
    api = parts.net
    exact = _exact_torque(context, run.crank_angle, run.load, run.crank_speed, run.crank_acceleration)
    return _Torques(run, parts, api, exact, exact if context.method == "exact" else api)


def _components(context: _TorqueContext, theta: np.ndarray, load: np.ndarray, speed: np.ndarray,
                acceleration: np.ndarray) -> TorqueComponents:
    """The torque terms [N·m] of loads on the crank grid ``theta`` (one card (N,) or K cards (K, N))."""
    masses = context.masses
    return torque_components(context.linkage, theta, load, context.balance,
                             beam_inertia=beam_group_inertia(context.linkage, masses) if masses else 0.0,
                             rotary_inertia=crank_group_inertia(masses) if masses else 0.0,
                             crank_speed=speed, crank_acceleration=acceleration)


def _exact_torque(context: _TorqueContext, theta: np.ndarray, load: np.ndarray, speed: np.ndarray,
                  acceleration: np.ndarray) -> np.ndarray | None:
    """The exact net torque [N·m] (None without the spatial model and masses), shaped as ``load``."""
    if context.spatial_masses is None:
        return None
    return _exact_basis(context.unit.spatial(), context.spatial_masses, theta.tobytes()).torque(load, speed,
                                                                                                   acceleration)


@functools.lru_cache(maxsize=32)
def _exact_basis(spatial, masses, crank_angle: bytes) -> ExactTorqueBasis:
    """The unit's exact-torque responses on a crank grid, computed once for all its cards."""
    return exact_torque_basis(spatial, masses, np.frombuffer(crank_angle))


@dataclass(frozen=True)
class Energy:
    """How the torque becomes energy and money: the efficiencies of the drive (belt and gearbox)
    and of the motor, and the price of electricity per joule (None: no cost reported)."""

    drive_efficiency: float = 1.0
    motor_efficiency: float = 1.0
    price: float | None = None


def torque(unit: UnitConfig, card: CardSource, spm: float | None, steps: int | None, crank_motion: str, method: str,
           criterion: str, drive_efficiency: float = 1.0, energy: Energy | None = None) -> Result:
    """The torque analysis of one card (see the module docstring): :func:`torques` of one card."""
    return alone(torques(unit, [card], spm, steps, crank_motion, method, criterion, drive_efficiency, energy))


def torques(unit: UnitConfig, cards: list, spm: float | None, steps: int | None, crank_motion: str, method: str,
            criterion: str, drive_efficiency: float = 1.0,
            energy: Energy | None = None) -> list[tuple[Result | PumpjackError, tuple[str, ...]]]:
    """The torque analysis of each of K cards (:class:`.card_runs.CardSource`) of one unit, with
    the warnings of each, the cards' torques, duties and loadings one array computation
    (:func:`card_torques`); a card that cannot be analysed gets its error. ``energy`` (its drive
    efficiency replaced by ``drive_efficiency``) for the energy per day and its cost; ``steps``
    None for the summary alone (no per-angle table or plot: a batch stores summaries).
    Problems of the unit or the options are raised for all."""
    check_options(method, criterion)
    energy = dataclasses.replace(energy or Energy(), drive_efficiency=drive_efficiency)
    grids = (SUMMARY_STEPS,) if steps is None else (steps, SUMMARY_STEPS)
    mechanism = unit.geometry.mechanism()
    readings, found, said = each_card(cards, lambda card: card_runs(unit, mechanism, card, spm, grids, crank_motion))
    keys = sorted(readings)
    analysed = card_torques(unit, [readings[k][0].card for k in keys], [readings[k][1] for k in keys], method,
                            criterion, energy) if keys else []
    marks = dead_position_marks(mechanism)
    for k, (result, noted) in zip(keys, analysed):
        said[k] += noted
        if isinstance(result, PumpjackError):
            found[k] = result
            continue
        runs = readings[k][1]
        title = (f"{unit.name}: gearbox torque ({method} method), card {cards[k].name}, {runs[0].crank_motion} crank "
                 f"motion, balance {criterion}")
        found[k] = Result(title, result.card_summary + result.summary, result.columns, result.panels, marks)
    return [(result, tuple(notes)) for result, notes in zip(found, said)]


def check_options(method: str, criterion: str) -> None:
    """Refuse an unknown torque method or balance criterion, listing the valid ones."""
    if method not in torque_methods():
        raise PumpjackError(f"--method {method}: use one of {', '.join(torque_methods())}")
    if criterion not in balance_criteria():
        raise PumpjackError(f"--balance {criterion}: use one of {', '.join(balance_criteria())}")


@dataclass(frozen=True)
class CardTorque:
    """The torque analysis of a card: the card's own figures (speed, work, polished-rod
    power), the torque summary, columns on the output grid, plot panels, and what other
    analyses read of it: the net torque column of the present counterbalance (of the
    recommended one when the present counterbalance is unknown; None, as the columns and
    panels, for the summary alone), its largest magnitude [N·m] on the summary grid, and the
    gearbox rating's lines for a torque plot."""

    card_summary: tuple[Scalar, ...]
    summary: tuple[Scalar, ...]
    columns: tuple[Column, ...]
    panels: tuple[Panel, ...]
    net_torque: Column | None
    peak_net_torque: float
    rating_levels: tuple[tuple[str, float], ...]


def card_torque(unit: UnitConfig, card: Card, runs: list[CardRun], method: str, criterion: str,
                energy: Energy = Energy()) -> CardTorque:
    """Net torque, balance and loading of one card: :func:`card_torques` of one card."""
    return alone(card_torques(unit, [card], [runs], method, criterion, energy))


def card_torques(unit: UnitConfig, cards: list[Card], runs: list[list[CardRun]], method: str, criterion: str,
                 energy: Energy = Energy()) -> list[tuple[CardTorque | PumpjackError, tuple[str, ...]]]:
    """Net torque, balance and loading of K cards (loads at crank angles), each run on the output
    grid ``runs[k][0]`` and the summary grid ``runs[k][-1]`` (:data:`SUMMARY_STEPS` points; a run
    on the summary grid alone gives the summary alone): the analysis of measured cards and of
    predicted ones alike, with the warnings of each. The duty (stroke peaks, RMS torque, cyclic
    load factor, motor power, NEMA size, energy per day) is reported for the present
    counterbalance, when known, and for the recommended one. The torques, peaks and duties of
    the cards on the summary grid are each one array computation (in blocks of :data:`BLOCK`
    cards), the balance each card's own; if one card's figures cannot be made (a balance
    criterion it cannot meet, no mean torque), every card of its block is analysed alone, so
    that each gets its own answer."""
    check_options(method, criterion)
    if len(cards) > BLOCK:
        return [found for start in range(0, len(cards), BLOCK)
                for found in card_torques(unit, cards[start:start + BLOCK], runs[start:start + BLOCK], method,
                                          criterion, energy)]
    context = _TorqueContext.of(unit, method)
    try:
        figures = _dense_figures(context, cards, runs, criterion)
    except PumpjackError as exc:
        if len(cards) == 1:
            return [(exc, ())]
        return [card_torques(unit, [card], [run], method, criterion, energy)[0] for card, run in zip(cards, runs)]
    out = []
    for k, card in enumerate(cards):
        with collected_warnings() as noted:
            try:
                result: CardTorque | PumpjackError = _card_result(context, card, runs[k], figures, k, criterion,
                                                                  energy)
            except PumpjackError as exc:
                result = exc
        out.append((result, tuple(noted)))
    return out


#: Cards whose torques on the summary grid are one array computation: a block's arrays of
#: 32 x 3600 doubles (0.9 MB) stay in a core's cache while the torque, its balance and its duty
#: are made of them (measured: 0.49 ms of CPU a card in blocks of 32, 0.66 ms in blocks of 64).
BLOCK = 32


@dataclass(frozen=True)
class _TorqueContext:
    """What the torque analysis of a unit's cards shares: the unit, its mechanism, masses,
    counterbalance (and its effect at the test angle, when the present one is known) and ratings."""

    unit: UnitConfig
    method: str
    linkage: object
    masses: object
    spatial_masses: object
    balance: CounterbalanceModel
    balance_known: bool
    rated: Ratings
    test_angle: float
    effect: float | None

    @classmethod
    def of(cls, unit: UnitConfig, method: str) -> _TorqueContext:
        masses = unit.mass_model() if unit.masses is not None else None
        if method == "exact" and masses is None:
            raise PumpjackError(f"unit {unit.name} has no [masses] section; --method exact needs the link masses "
                                f"(--method api needs only [counterbalance])")
        spatial = hasattr(unit.geometry, "spatial")
        if method == "exact" and masses is not None:
            unit.spatial()          # refuses a kind without the spatial model
        balance, balance_known = unit.counterbalance_model()
        linkage = unit.geometry.mechanism()
        test_angle = upstroke_test_angle(linkage)
        effect = counterbalance_effect(linkage.motion(np.array([test_angle])), balance) if balance_known else None
        return cls(unit, method, linkage, masses, masses if spatial else None, balance, balance_known, unit.ratings(),
                   test_angle, effect)


@dataclass(frozen=True)
class _DenseFigures:
    """What is read of the K cards' torques on the summary grid, and their works per cycle,
    arrays (K, ...)."""

    works: np.ndarray
    frequency: np.ndarray
    recommendations: list
    duty: dict
    peaks: dict
    strokes: tuple | None
    extremes: tuple | None


def _dense_figures(context: _TorqueContext, cards: list[Card], runs: list[list[CardRun]],
                   criterion: str) -> _DenseFigures:
    """The torques of K cards on the summary grid, their balances and duties (raises for a card
    whose figures cannot be made)."""
    linkage, balance = context.linkage, context.balance
    dense = [run[-1] for run in runs]
    theta = dense[0].crank_angle
    load = np.array([run.load for run in dense])
    speed = np.array([run.crank_speed for run in dense])
    acceleration = np.array([run.crank_acceleration for run in dense])
    parts = _components(context, theta, load, speed, acceleration)
    api = parts.net
    exact = _exact_torque(context, theta, load, speed, acceleration)
    net = exact if context.method == "exact" else api
    dt = 1.0 / speed                                     # time share of each point of the uniform grid
    frequency = np.array([1.0 / run.period for run in dense])
    recommendations = recommend_counterbalances(
        criterion, linkage, theta, load, balance, weights=dt, test_angle=context.test_angle,
        extra_torque=net - parts.rod_load - parts.structural - parts.counterbalance)
    for found in recommendations:
        if found.value is None:
            raise BalanceError(f"--balance {criterion}: {found.note}; try --balance min-peak or min-rms", found.note)
    values = np.array([r.value for r in recommendations])
    recommended = _with_value(balance, linkage, theta, net, values[:, None])
    current = net if context.balance_known else None
    duty = {"recommended_": _duty_of(recommended, dt, frequency)}
    peaks = {"recommended": peaks_of(theta, recommended)}
    strokes = extremes = None
    if current is not None:
        duty[""] = _duty_of(current, dt, frequency)
        peaks["current"] = peaks_of(theta, current)
        strokes = stroke_peaks(linkage, theta, current)
        extremes = extremes_of(theta, current)
    if exact is not None:
        peaks["exact"] = peaks_of(theta, exact - api)
    return _DenseFigures(card_works(linkage, cards), frequency, recommendations, duty, peaks, strokes, extremes)


def _with_value(balance: CounterbalanceModel, linkage, crank_angle: np.ndarray, net: np.ndarray, value) -> np.ndarray:
    """The net torque ``net`` [N·m] at ``crank_angle`` with the balancing variable at ``value``
    (its torque is affine in it): a value, or one per cycle of ``net`` (K, 1)."""
    return net + (value - balance.value) * balance.torque_per_value(linkage.motion(crank_angle))


def _duty_of(net: np.ndarray, dt: np.ndarray, frequency: np.ndarray) -> tuple[np.ndarray, ...]:
    """Cyclic load factor, mean torque [N·m] and driving work per revolution [J] of K cycles."""
    clf = cyclic_load_factor(net, dt)
    mean = np.sum(net * dt, axis=-1) / np.sum(dt, axis=-1)
    return clf, mean, driving_work(net)


def _card_result(context: _TorqueContext, card: Card, runs: list[CardRun], figures: _DenseFigures, k: int,
                 criterion: str, energy: Energy) -> CardTorque:
    """Card ``k``'s torque analysis from the K cards' figures."""
    unit, linkage, balance, rated, masses = context.unit, context.linkage, context.balance, context.rated, context.masses
    recommendation = figures.recommendations[k]
    frequency = float(figures.frequency[k])

    work = float(figures.works[k])
    summary = [Scalar(name, value) for name, value in balance.summary()]
    if context.balance_known:
        top, bottom = figures.extremes
        summary += [Scalar(balance.variable, balance.value),
                    Scalar("counterbalance_effect", context.effect),
                    Scalar("peak_net_torque", float(figures.peaks["current"][0][k])),
                    Scalar("peak_net_torque_crank_angle", float(figures.peaks["current"][1][k]))]
        summary += extreme_scalars((("max_net_torque", Extreme(float(top[0][k]), float(top[1][k]))),
                                    ("min_net_torque", Extreme(float(bottom[0][k]), float(bottom[1][k])))))
        summary += [Scalar("upstroke_peak_torque", float(figures.strokes[0][k])),
                    Scalar("downstroke_peak_torque", float(figures.strokes[1][k]))]
        summary += _duty("", figures.duty[""], k, frequency, energy)
    summary += [
        Scalar("recommended_" + balance.variable, recommendation.value),
        Scalar("recommended_counterbalance_effect", recommendation.counterbalance_effect),
        Scalar("recommended_peak_net_torque", float(figures.peaks["recommended"][0][k])),
        Scalar("recommended_upstroke_peak_torque", recommendation.upstroke_peak),
        Scalar("recommended_downstroke_peak_torque", recommendation.downstroke_peak),
    ]
    if masses is not None and isinstance(balance, Counterbalance):
        placement = counterweight_placement(recommendation.value, masses,
                                            unit.masses.counterweights.radius_range or (0.0, MAX_RADIUS))
        if placement.radius is not None:
            summary.append(Scalar("recommended_counterweight_radius", placement.radius))
        if placement.mass is not None:
            summary.append(Scalar("recommended_counterweight_mass", placement.mass))
        if placement.note:
            warn(placement.note)
    summary += _duty("recommended_", figures.duty["recommended_"], k, frequency, energy)
    current_peak = float(figures.peaks["current"][0][k]) if context.balance_known else None
    summary += _loading(unit.name, rated, card.load.max(), linkage.stroke, current_peak,
                        float(figures.peaks["recommended"][0][k]))
    if "exact" in figures.peaks:
        summary.append(Scalar("peak_exact_minus_api_torque", float(figures.peaks["exact"][0][k])))
    levels = _rating_levels(rated)
    columns, panels, headline = [], (), None
    if len(runs) == 2:
        out = _torques(context, runs[0])
        columns = _columns(linkage, out, context.balance_known, _with_value(balance, linkage, out.run.crank_angle, out.net, recommendation.value), rated)
        headline = next(c for c in columns
                        if c.name == ("net_torque" if context.balance_known else "recommended_net_torque"))
        panels = _panels(linkage, out.run, columns, levels, context.balance_known)
    high, low = int(np.argmax(card.load)), int(np.argmin(card.load))
    card_summary = (Scalar("strokes_per_minute", 2.0 * np.pi * frequency),
                    Scalar("max_rod_load", float(card.load[high])),
                    Scalar("max_rod_load_crank_angle", float(card.crank_angle[high])),
                    Scalar("min_rod_load", float(card.load[low])),
                    Scalar("min_rod_load_crank_angle", float(card.crank_angle[low])),
                    Scalar("card_work", work),
                    Scalar("polished_rod_power", work * frequency))
    base = current_peak if current_peak is not None else float(figures.peaks["recommended"][0][k])
    return CardTorque(card_summary, tuple(summary), tuple(columns), panels, headline, base, levels)


def _duty(prefix: str, duty: tuple[np.ndarray, ...], k: int, frequency: float, energy: Energy) -> list[Scalar]:
    """Card ``k``'s duty of a net torque on the summary grid (:func:`_duty_of`): RMS (equivalent)
    torque, cyclic load factor, motor power by the RMS-equivalent rule and the NEMA size that
    covers it, energy per day and its cost; names with ``prefix`` (``recommended_`` for the
    recommended counterbalance)."""
    clf, mean = float(duty[0][k]), float(duty[1][k])
    rms = clf * mean
    power = rms * 2.0 * np.pi * frequency / energy.drive_efficiency
    found = [Scalar(prefix + "rms_net_torque", rms), Scalar(prefix + "cyclic_load_factor", clf),
             Scalar(prefix + "rms_motor_power", power)]
    size = nema_motor_size(power)
    if size is None:
        warn(f"the motor power {power / HORSEPOWER:.4g} hp{' (recommended counterbalance)' if prefix else ''} is "
             f"beyond the largest standard NEMA rating, 500 hp")
    else:
        found.append(Scalar(prefix + "nema_motor_size", size))
    daily = float(duty[2][k]) * frequency * DAY / (energy.drive_efficiency * energy.motor_efficiency)
    found.append(Scalar(prefix + "motor_energy", daily))
    if energy.price is not None:
        found.append(Scalar(prefix + "energy_cost", daily * energy.price))
    return found


#: Stroke loading above 100 % by more than this share is explained by a warning.
STROKE_NOTE = 5e-4


def _loading(name: str, rated: Ratings, peak_load: float, stroke: float, current: float | None,
             recommended: float) -> list[Scalar]:
    """Loading against the ratings that are known (fractions, shown in %); a warning when the
    geometry's exact stroke exceeds the rated maximum stroke."""
    found = [Scalar("stroke", stroke)]
    if rated.gearbox_torque is not None:
        found.append(Scalar("gearbox_rating", rated.gearbox_torque))
        if current is not None:
            found.append(Scalar("gearbox_loading", current / rated.gearbox_torque))
        found.append(Scalar("recommended_gearbox_loading", recommended / rated.gearbox_torque))
    if rated.structure_load is not None:
        found += [Scalar("structure_rating", rated.structure_load),
                  Scalar("structure_loading", peak_load / rated.structure_load)]
    if rated.max_stroke is not None:
        found += [Scalar("max_stroke", rated.max_stroke),
                  Scalar("stroke_loading", stroke / rated.max_stroke)]
        if stroke > rated.max_stroke * (1.0 + STROKE_NOTE):
            warn(f"unit {name}: stroke loading {100.0 * stroke / rated.max_stroke:.4g} %: the geometry's exact stroke "
                 f"{stroke / INCH:.4g} in ({stroke:.4g} m) is longer than the rated maximum {rated.max_stroke / INCH:.4g} "
                 f"in ({rated.max_stroke:.4g} m); a designation states the stroke rounded, the letters give it "
                 f"exactly: check the crank hole and the letters")
    return found


def _columns(linkage, t: _Torques, balance_known: bool, recommended, rated: Ratings):
    run, parts = t.run, t.components
    m = linkage.motion(run.crank_angle)
    columns = [
        *crank_columns(run.crank_angle, run.time, run.crank_speed, run.crank_acceleration),
        Column("position", m.rod_position),
        Column("rod_load", run.load),
        Column("torque_factor", m.torque_factor),
        Column("rod_load_torque", parts.rod_load),
        Column("structural_torque", parts.structural),
        Column("articulating_inertia_torque", parts.articulating_inertia),
        Column("rotary_inertia_torque", parts.rotary_inertia),
    ]
    if balance_known:
        columns += [Column("counterbalance_torque", parts.counterbalance),
                    Column("net_torque", t.net)]
    if t.exact is not None:
        columns += [Column("api_net_torque", t.api),
                    Column("exact_net_torque", t.exact),
                    Column("exact_minus_api_torque", t.exact - t.api)]
    columns.append(Column("recommended_net_torque", recommended))
    if rated.gearbox_torque is not None and balance_known:
        low, high = permissible_load(m.torque_factor, parts.structural + parts.counterbalance, rated.gearbox_torque)
        columns += [Column("permissible_load_min", _clip(low, run.load)),
                    Column("permissible_load_max", _clip(high, run.load))]
    return columns


def _clip(bound: np.ndarray, load: np.ndarray) -> np.ndarray:
    """A permissible-load bound kept finite for output: near a dead position (TF -> 0) it
    grows without limit; it is cut at ten times the card's load range from the card."""
    span = 10.0 * (np.max(load) - np.min(load) + 1.0)
    return np.clip(bound, np.min(load) - span, np.max(load) + span)


def _rating_levels(rated: Ratings) -> tuple[tuple[str, float], ...]:
    """The gearbox rating's lines on a net-torque plot (none without a rating)."""
    return () if rated.gearbox_torque is None else (("gearbox rating", rated.gearbox_torque),
                                                    ("", -rated.gearbox_torque))


def _permissible_branches(linkage, run: CardRun, columns: list[Column]) -> tuple[Curve, ...]:
    """The permissible load diagram ([GaultSWPSC]) against the polished-rod position, in its
    upstroke and downstroke branches (NaN off the branch), each with its upper and lower bound."""
    by_name = {c.name: c.values for c in columns}
    position = linkage.motion(run.crank_angle).rod_position
    up = upstroke_mask(linkage, run.crank_angle)
    curves = []
    for stroke, mask, colour in (("upstroke", up, "tab:green"), ("downstroke", ~up, "tab:orange")):
        x = tuple(np.where(mask, position, np.nan).tolist())
        for bound, style, words in (("max", "--", "largest"), ("min", ":", "smallest")):
            y = tuple(np.where(mask, by_name[f"permissible_load_{bound}"], np.nan).tolist())
            curves.append(Curve(f"{stroke}: {words} permissible load", x, y, quantity="length", y_quantity="force",
                                style=style, color=colour))
    return tuple(curves)


def _panels(linkage, run: CardRun, columns: list[Column], levels: tuple[tuple[str, float], ...],
            balance_known: bool) -> tuple[Panel, ...]:
    names = {c.name for c in columns}
    panels = []
    if "permissible_load_min" in names:
        panels.append(Panel("card and permissible loads", ("rod_load",), x="position", clip=True,
                            curves=_permissible_branches(linkage, run, columns), labels=(("rod_load", "card"),)))
    else:
        panels.append(Panel("card", ("rod_load",), x="position", labels=(("rod_load", "card"),)))
    panels.append(Panel("net torque", ("net_torque",) if balance_known else ("recommended_net_torque",),
                        ("recommended_net_torque",) if balance_known else (), levels=levels))
    panels.append(Panel("torque components", ("rod_load_torque", "structural_torque", "articulating_inertia_torque",
                                              "rotary_inertia_torque")
                        + (("counterbalance_torque",) if balance_known else ())))
    return tuple(panels)
