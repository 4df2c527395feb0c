"""The pump card from a surface card through the rod string's wave equation: `pumpjack downhole`.

The card is put on a uniform time grid over one period (its time stamps, or the unit's
exact kinematics and crank speed for a card of positions only); the damped wave
equation of the tapered string turns it into the pump card ([Gibbs1963],
[EverittJennings1992]); the pump card is read for strokes, fillage and fluid load, the
rods for stresses and Goodman loading ([API11BR]), the pump's condition with its evidence
(:mod:`pumpjack_cli.core.rods.diagnosis`), and the well's production, intake pressure,
fluid level and energy per day (:mod:`pumpjack_cli.core.rods.production`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..core.beam.counterbalance import rp11l_counterbalance_effect
from ..core.rods.analysis import (
    PumpCardSummary,
    TaperLoads,
    card_work,
    displacement_rate,
    intake_pressure,
    plunger_area,
    summarise_pump_card,
    taper_loads,
)
from ..core.rods.diagnosis import balanced_dampings, diagnose, hanging_depth
from ..core.rods.downhole import (
    DEFAULT_DAMPING_FACTOR,
    downhole_methods,
    pump_card,
)
from ..core.rods.deviated_diagnostic import deviated_pump_card
from ..core.rods.plausibility import PARTED_FLATNESS, free_end
from ..core.rods.production import (energy_per_day, fluid_above_pump, inferred_production,
                                    intake_pressure_from_load, slippage_rate)
from ..core.rods.pump import discharge_pressure
from ..errors import DownholeError, PumpjackError, collected_warnings, warn
from ..results import Column, Curve, Panel, Result, Scalar
from .card_runs import CardSource, alone, time_cards
from .deviated import (Deviation, deviated_path, friction_coefficient, method_for, profile_result, survey_summary,
                       surveyed, with_survey)
from .inputs import dead_position_marks
from .rods import TaperRows, goodman_panel

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: Samples per period of the surface card on its uniform time grid.
DEFAULT_SAMPLES = 360


@dataclass(frozen=True)
class Production:
    """What turns a pump card into the office's numbers: the share of the day the unit runs
    (None: no rate is given), a stated pump efficiency (None: the slippage from the plunger's
    clearance, if the well gives it), the system's efficiency (supply to polished rod) and a price of energy per J (None:
    no cost)."""

    runtime: float | None = None
    pump_efficiency: float | None = None
    system_efficiency: float = 1.0
    electricity_price: float | None = None


def fluid_load_of(unit: UnitConfig) -> float | None:
    """F_o = (p_d - p_i) A_p [N] from the well's pressures at the pump, None without them."""
    found = unit.pump_pressures()
    if found is None:
        return None
    return (found[0] - found[1]) * plunger_area(unit.require_well().plunger_diameter)


def damping_factors(unit: UnitConfig, given: float | None, rod_string, cards: list, method: str,
                    solve=None) -> list[tuple[float, str]]:
    """Gibbs' nu of each surface card (:class:`~.card_runs.TimeCard`) and the warning that goes
    with it (empty for none): the option's, the unit file's, or the energy balance's with the
    well's fluid load ([Gibbs1963], [EverittJennings1992]), the cards' balances solved together
    (:func:`~pumpjack_cli.core.rods.diagnosis.balanced_dampings`; ``solve``, for one card: the
    transfer of a deviated well)."""
    well = unit.require_well()
    if given is not None:
        return [(given, "")] * len(cards)
    if well.damping_factor is not None:
        return [(well.damping_factor, "")] * len(cards)
    fluid_load = fluid_load_of(unit)
    if fluid_load is None:
        return [(DEFAULT_DAMPING_FACTOR, f"unit {unit.name}: no fluid level or intake pressure for the energy "
                                         f"balance; damping factor {DEFAULT_DAMPING_FACTOR:g} assumed (give --damping)")
                ] * len(cards)
    found = balanced_dampings(rod_string, np.array([c.period for c in cards]), np.array([c.position for c in cards]),
                              np.array([c.load for c in cards]), fluid_load, fluid_density=well.fluid_density,
                              fallback=DEFAULT_DAMPING_FACTOR, method=method, solve=solve)
    return [(nu, f"unit {unit.name}: {reason}; damping factor {DEFAULT_DAMPING_FACTOR:g} assumed (give --damping)"
             if reason else "") for nu, reason in found]


def downhole(unit: UnitConfig, card: CardSource, spm: float | None, crank_motion: str, method: str | None,
             damping: float | None, samples: int = DEFAULT_SAMPLES, service_factor: float = 1.0,
             deviation: Deviation = Deviation(), production: Production = Production()) -> Result:
    """Pump card, pump-card figures, the pump's condition, rod stresses and the well's production
    of one surface card: :func:`downholes` of one card."""
    return alone(downholes(unit, [card], spm, crank_motion, method, damping, samples, service_factor, deviation,
                           production))


def downholes(unit: UnitConfig, cards: list, spm: float | None, crank_motion: str, method: str | None,
              damping: float | None, samples: int = DEFAULT_SAMPLES, service_factor: float = 1.0,
              deviation: Deviation = Deviation(), production: Production = Production(), tables: bool = True
              ) -> list[tuple[Result | PumpjackError, tuple[str, ...]]]:
    """Pump card, pump-card figures, the pump's condition, rod stresses and the well's production
    of each of K surface cards (:class:`~.card_runs.CardSource`) of one unit, with the warnings
    of each; a card that cannot be analysed gets its error. In a vertical well the cards'
    dampings, pump cards, pump-card figures, works, rod loads and conditions are each one array
    computation (every card as alone); in a deviated well (``deviation``'s survey or the unit's)
    each card is marched with the drag and gravity along the hole (:mod:`.deviated`), method
    None choosing. ``tables`` False: the summaries alone, without columns or plots (a batch
    stores summaries). The summaries too are made once for the unit and as arrays for the cards
    (:class:`CardSummaries`). Problems of the unit or the options are raised for all."""
    unit = with_survey(unit, deviation.survey, deviation.friction, deviation.guide_limit)
    method = method_for(unit, method)
    if method not in downhole_methods():
        raise PumpjackError(f"--method {method}: use one of {', '.join(downhole_methods())}")
    unit.require_well()
    string = unit.rods()
    linkage = unit.geometry.mechanism()
    surfaces, found, said = time_cards(unit, linkage, cards, spm, samples, crank_motion)
    path = deviated_path(unit)
    if path is None:
        pumps = _vertical_pumps(unit, string, cards, surfaces, damping, method, said)
    else:
        pumps = {k: _deviated_pump(unit, string, path, cards[k], surfaces[k][1], damping, method, said[k])
                 for k in surfaces}
    for k, pump in pumps.items():
        if isinstance(pump, PumpjackError):
            found[k] = pump
    good = sorted(k for k in pumps if not isinstance(pumps[k], PumpjackError))
    if not good:
        return [(result, tuple(notes)) for result, notes in zip(found, said)]
    position = np.array([pumps[k][1].pump_position for k in good])
    load = np.array([pumps[k][1].pump_load for k in good])
    figures = summarise_pump_card(position, load)
    conditions = diagnose(position, load, reference_fluid_load(unit))
    works = card_work(np.array([surfaces[k][1].position for k in good]), np.array([surfaces[k][1].load for k in good]))
    pump_works = card_work(position, load)
    backwards = _backwards_pump_cards(cards, surfaces, pumps, good, pump_works, conditions.label)
    if backwards:
        for k, error in backwards.items():
            found[k] = error
        keep = [i for i, k in enumerate(good) if k not in backwards]
        good = [good[i] for i in keep]
        if not good:
            return [(result, tuple(notes)) for result, notes in zip(found, said)]
        position, load, works, pump_works = position[keep], load[keep], works[keep], pump_works[keep]
        figures = summarise_pump_card(position, load)
        conditions = diagnose(position, load, reference_fluid_load(unit))
    loads = taper_loads(string, np.array([pumps[k][1].joint_load for k in good]))
    rows = CardSummaries(unit, string, [surfaces[k] for k in good], [pumps[k] for k in good], load, figures, conditions,
                         (works, pump_works), loads, service_factor, production, path)
    marks = dead_position_marks(linkage)
    for i, k in enumerate(good):
        with collected_warnings() as noted:
            points = surfaces[k][0].load.size
            if points < CONDITION_POINTS:
                warn(f"{cards[k].name}: {points} points a stroke are too few to read the pump's condition at the "
                     f"stroke's ends (tagging, valve leaks; at least {CONDITION_POINTS}): pump_condition "
                     f"{conditions.label[i]} rests on a card that does not resolve them")
            found[k] = _downhole_result(unit, cards[k], surfaces[k][1], pumps[k], string, method, rows, i, deviation,
                                        marks if tables else None)
        said[k] += noted
    return [(result, tuple(notes)) for result, notes in zip(found, said)]


#: Fewest points of a surface card per stroke for its pump's condition to be read without a word: the
#: ends of the stroke, where tagging and leaks show (a tenth of the travel each, about a fifth of the
#: cycle), need five points each (a spike's 3-point mean with a neighbour either side); a 16-point
#: card's Fourier ringing at the load's pickup read as a tag.
CONDITION_POINTS = 25
#: A pump card may do no less work on the fluid than minus this share of (surface stroke x surface load
#: range): a pump takes no energy from the fluid column, and below it the damping or the card is wrong.
#: The margin leaves a card of little work (a pump nearly off, gas-locked) to its diagnosis when a
#: given damping factor slightly overshoots its dissipation.
PUMP_WORK_TOLERANCE = 0.1


def _backwards_pump_cards(cards: list, surfaces: dict, pumps: dict, good: list[int], pump_works: np.ndarray,
                          labels: np.ndarray) -> dict[int, PumpjackError]:
    """The cards whose pump card does work on the rods (index -> the error saying so); a parted
    string's card is not among them: its free end carries no pump, and it is labelled, never refused
    (the damping of the whole string over the part that hangs makes its work a little negative)."""
    found = {}
    for i, k in enumerate(good):
        if labels[i] == "rod_part":
            continue
        surface = surfaces[k][1]
        scale = float(np.ptp(surface.position)) * float(np.ptp(surface.load))
        if pump_works[i] < -PUMP_WORK_TOLERANCE * scale:
            nu = pumps[k][0]
            found[k] = PumpjackError(
                f"{cards[k].name}: its pump card does {pump_works[i]:.4g} J of work on the fluid per cycle; a pump "
                f"does none negative: the damping factor {nu:.4g} takes more energy from the rods than the surface "
                f"card gives them, or the card is not a pumping well's")
    return found


def _vertical_pumps(unit: UnitConfig, string, cards: list, surfaces: dict, damping: float | None, method: str,
                    said: list[list[str]]) -> dict:
    """The pump cards of the vertical well's surface cards (index -> (nu, DownholeCard, None) or the
    error), their dampings and transfers each one array computation."""
    keys = sorted(surfaces)
    if not keys:
        return {}
    surface = [surfaces[k][1] for k in keys]
    nus = damping_factors(unit, damping, string, surface, method)
    for k, (_, note) in zip(keys, nus):
        if note:
            said[k].append(note)
    try:
        pumps = pump_card(string, np.array([s.period for s in surface]), np.array([s.position for s in surface]),
                          np.array([s.load for s in surface]), fluid_density=unit.require_well().fluid_density,
                          damping_factor=np.array([nu for nu, _ in nus]), method=method)
    except DownholeError:     # a card the transfer refuses: each card alone, for its own message
        return {k: _vertical_pump(unit, string, cards[k], surfaces[k][1], nu, method)
                for k, (nu, _) in zip(keys, nus)}
    return {k: (nu, pumps.card(i), None) for i, (k, (nu, _)) in enumerate(zip(keys, nus))}


def _vertical_pump(unit: UnitConfig, string, card, surface, nu: float, method: str):
    """One card's pump card in a vertical well, or the transfer's refusal as an error."""
    try:
        return nu, pump_card(string, surface.period, surface.position, surface.load,
                             fluid_density=unit.require_well().fluid_density, damping_factor=nu, method=method), None
    except DownholeError as exc:
        return PumpjackError(f"{card.name} on the rods of unit {unit.name}: {exc}")


def _deviated_pump(unit: UnitConfig, string, path, card, surface, damping: float | None, method: str,
                   said: list[str]):
    """One card's pump card in a deviated well, marched with the drag ([Gibbs1963] damping from
    the energy balance with the drag taking its share), or the error."""
    well = unit.require_well()
    mu = friction_coefficient(unit)

    def transfer(nu: float, mu: float = mu):
        return deviated_pump_card(string, path, surface.period, surface.position, surface.load,
                                  fluid_density=well.fluid_density, damping_factor=nu, friction_coefficient=mu)

    try:
        ((nu, note),) = damping_factors(unit, damping, string, [surface], method, lambda nu: transfer(nu).card)
        if note:
            said.append(note)
        deviated = transfer(nu)
    except DownholeError as exc:
        return PumpjackError(f"{card.name} on the rods of unit {unit.name}: {exc}")
    return nu, deviated.card, deviated


def _downhole_result(unit: UnitConfig, card, surface, found, string, method: str, rows: CardSummaries, index: int,
                     deviation: Deviation, marks: tuple | None) -> Result:
    """The result of card ``index`` of ``rows`` from its time card ``surface`` and its pump card
    (``found``: nu, the pump card, the deviated march or None); with the dead positions' ``marks``
    its columns and plots, without them (None) the summary alone."""
    well = unit.require_well()
    nu, pump, deviated = found
    summary = rows.card(index, surface)
    title = f"{unit.name}: pump card ({method}, damping {nu:.3g}), card {card.name}"
    more_columns: tuple[Column, ...] = ()
    more_curves: tuple[Curve, ...] = ()
    if surveyed(unit):
        extra, more_columns, more_curves = deviated_rows(unit, string, surface, nu, deviated)
        summary += extra
        title += f", survey {Path(well.survey).name}" + (f", friction {deviated.friction_coefficient:g}"
                                                         if deviated is not None else "")
    if marks is None:
        return Result(title, tuple(summary), ())
    columns = (
        Column("time", surface.time),
        Column("crank_angle", surface.crank_angle),
        Column("position", surface.position),
        Column("rod_load", surface.load),
        Column("pump_position", pump.pump_position),
        Column("pump_load", pump.pump_load),
        *more_columns,
    )
    curves = (Curve("surface card", "position", "rod_load"), Curve("pump card", "pump_position", "pump_load"),
              *more_curves)
    f_o = rows.conditions.reference[index]   # the reference load lines of [Rowlan2008] on both cards
    lines = (("W_rf", pump.buoyant_weight), ("W_rf + F_o", pump.buoyant_weight + f_o), ("F_o (pump card)", f_o),
             ("", 0.0))
    panels: tuple[Panel, ...] = (Panel("load", (), curves=curves, x_label="position", levels=lines),
                                 goodman_panel(string, rows.loads.card(index), rows.service_factor))
    if deviation.profile:
        profile = deviated.profile if deviated is not None else deviated_pump_card(
            string, well.path(), surface.period, surface.position, surface.load, fluid_density=well.fluid_density,
            damping_factor=nu, friction_coefficient=0.0).profile
        columns, panels = profile_result(unit, profile)
    return Result(title, tuple(summary), columns, panels, marks)


def deviated_rows(unit: UnitConfig, string, surface, nu: float, found) -> tuple[list[Scalar], tuple, tuple]:
    """What a survey adds to `downhole`: its figures, and in a deviated well the pump card of a
    diagnosis that ignores the drag (columns and a dashed curve), to show what the drag takes."""
    well = unit.require_well()
    if found is None:  # a vertical survey: no side load, no drag
        return survey_summary(unit, None, 0.0, well.friction_coefficient(), string.buoyant_weight(well.fluid_density)), \
            (), ()
    bare = deviated_pump_card(string, well.path(), surface.period, surface.position, surface.load,
                              fluid_density=well.fluid_density, damping_factor=nu, friction_coefficient=0.0).card
    rows = survey_summary(unit, found.profile, found.friction_work, found.friction_coefficient, found.grid.hanging_weight)
    rows.append(Scalar("pump_card_work_without_friction", float(card_work(bare.pump_position, bare.pump_load))))
    columns = (Column("pump_position_without_friction", bare.pump_position),
               Column("pump_load_without_friction", bare.pump_load))
    curve = Curve("pump card ignoring friction", "pump_position_without_friction", "pump_load_without_friction",
                  style="--")
    return rows, columns, (curve,)


class CardSummaries:
    """The summary rows of K cards of one unit, each card's as :func:`downhole` reports it alone:
    what is the same for every card (the well's pressures, plunger area and pump depth, the
    string's grades) found once, each figure of the K cards one array computation, and a card's
    rows (:meth:`card`) made of plain floats.

    ``readings`` are the cards' (reading, time card), ``pumps`` their (nu, pump card, deviated
    march or None), ``pump_load`` the pump cards' loads (K, N), ``figures``, ``conditions``
    and ``loads`` the K cards' pump-card figures, diagnosis and taper loads, ``works`` the
    surface and pump cards' works (K,) [J]; ``path`` the deviated well's path, or None."""

    def __init__(self, unit: UnitConfig, string, readings: list, pumps: list, pump_load: np.ndarray,
                 figures: PumpCardSummary, conditions, works: tuple[np.ndarray, np.ndarray], loads: TaperLoads,
                 service_factor: float, production: Production, path) -> None:
        well = unit.require_well()
        periods = np.array([surface.period for _, surface in readings])
        raw = [reading.card.load for reading, _ in readings]     # each card's loads as read: its extremes
        raw_loads, starts = np.concatenate(raw), np.cumsum([0] + [load.size for load in raw[:-1]])
        weights = [pump.buoyant_weight for _, pump, _ in pumps]
        fluid = figures.fluid_load.tolist()
        found_pressures = unit.pump_pressures()
        columns = [(2.0 * np.pi / periods).tolist(), [nu for nu, _, _ in pumps],
                   np.maximum.reduceat(raw_loads, starts).tolist(), np.minimum.reduceat(raw_loads, starts).tolist(),
                   weights if path is None else [string.buoyant_weight(well.fluid_density)] * len(pumps),
                   figures.gross_stroke.tolist(), figures.net_stroke.tolist(), figures.fillage.tolist(), fluid,
                   [rp11l_counterbalance_effect(weight, load) for weight, load in zip(weights, fluid)],
                   figures.peak_load.tolist(), figures.minimum_load.tolist(), works[0].tolist(), works[1].tolist(),
                   displacement_rate(figures.net_stroke, periods, well.plunger_diameter).tolist()]
        if found_pressures is not None:
            columns.append(intake_pressure(figures.fluid_load, well.plunger_diameter, found_pressures[0]).tolist())
        self._names = PUMP_CARD_NAMES + (("pump_intake_pressure",) if found_pressures is not None else ())
        self._values = list(zip(*columns))
        self.conditions = ConditionRows(unit, conditions, string)
        self._well = WellRows(unit, figures, pump_load, works[0] / periods, periods, production,
                              intake_known=found_pressures is not None)
        self._tapers = TaperRows(string, loads, service_factor)
        self.loads, self.service_factor = loads, service_factor     # a card's Goodman diagram

    def card(self, index: int, surface) -> list[Scalar]:
        """The summary of card ``index`` (``surface`` its time card): the pump card's figures, the
        pump's condition, the well's production and the rods' stresses, with their warnings."""
        rows = list(map(Scalar, self._names, self._values[index]))
        rows += self.conditions.card(index, surface)
        rows += self._well.card(index)
        rows += self._tapers.card(index)
        return rows


#: The summary names of a card's speed, damping, loads, pump-card figures and works, in the order
#: a result gives them (the pump's intake pressure after them when the well gives its pressures).
PUMP_CARD_NAMES = ("strokes_per_minute", "damping_factor", "max_rod_load", "min_rod_load", "buoyant_rod_weight",
                   "gross_pump_stroke", "net_pump_stroke", "pump_fillage", "fluid_load", "rp11l_counterbalance_effect",
                   "max_pump_load", "min_pump_load", "surface_card_work", "pump_card_work", "pump_displacement")
#: The features of the pump card a label rests on, by their output names ([Rowlan2008], docs/diagnosis.md).
CARD_EVIDENCE = ("travelling_valve_closing", "standing_valve_opening", "standing_valve_closing",
                 "travelling_valve_opening", "pickup_travel", "unloading_travel", "slow_upstroke_load",
                 "slow_downstroke_load", "bottom_spike", "top_spike")
#: The summary names of the pump's condition and its evidence, in the order a page shows them.
CONDITION_NAMES = ("pump_condition", "pump_condition_confidence", "pump_condition_second", "reference_fluid_load",
                   *CARD_EVIDENCE, "card_area_ratio", "rod_break_depth")
#: The summary names of the well's production, fluid level and energy, in the order a page shows them.
PRODUCTION_NAMES = ("pump_displacement", "pump_fillage", "net_pump_stroke", "discharge_pressure",
                    "pump_intake_pressure", "pump_submergence", "fluid_level_depth", "runtime", "pump_efficiency",
                    "pump_slippage", "inferred_production", "system_efficiency", "energy_per_day", "electricity_cost")


def reference_fluid_load(unit: UnitConfig) -> float:
    """F_o of the pump card's reference lines [N] ([Rowlan2008]): from the well's fluid level or intake
    pressure, else with the fluid level at the pump (the intake at the casing-head pressure)."""
    found = fluid_load_of(unit)
    if found is not None:
        return found
    well = unit.require_well()
    return (discharge_pressure(well.pump_vertical_depth(), well.fluid_density, well.tubing_head_pressure)
            - well.casing_head_pressure) * plunger_area(well.plunger_diameter)


class ConditionRows:
    """The pump's condition ([Rowlan2008], docs/diagnosis.md) of K cards from their diagnosis
    (``found``, :func:`~pumpjack_cli.core.rods.diagnosis.diagnose` of their pump cards), taken
    out of its arrays once: a card's rows (:meth:`card`) are the label, its confidence, the
    second-best label and the evidence."""

    def __init__(self, unit: UnitConfig, found, string) -> None:
        self._well, self._string = unit.require_well(), string
        ft = found.features
        self._label, self._second = found.label.tolist(), found.second.tolist()
        self._confidence = found.confidence.tolist()
        self.reference = ft.reference_load.tolist()     # F_o of each card [N], also its pump card's reference line
        self._evidence = np.stack([getattr(ft, name) for name in CARD_EVIDENCE], axis=-1).tolist()
        self._area_ratio = ft.area_ratio.tolist()

    def card(self, index: int, surface) -> list[Scalar]:
        """The condition of card ``index``; a parted string's break depth from the wave equation's
        free end on its surface card ``surface`` (:func:`~pumpjack_cli.core.rods.plausibility.free_end`),
        else from the hanging weight. A point the card never reaches is left out, not given as NaN."""
        label = str(self._label[index])
        rows = [Scalar("pump_condition", label),
                Scalar("pump_condition_confidence", self._confidence[index]),
                Scalar("pump_condition_second", str(self._second[index])),
                Scalar("reference_fluid_load", self.reference[index])]
        rows += [Scalar(name, value) for name, value in zip(CARD_EVIDENCE, self._evidence[index])
                 if math.isfinite(value)]
        rows.append(Scalar("card_area_ratio", self._area_ratio[index]))
        if label == "rod_part":
            fluid_density = self._well.fluid_density
            depth, off = free_end(surface.load, surface.position, surface.period, self._string, fluid_density)
            if not off <= PARTED_FLATNESS:
                depth = float(hanging_depth(self._string, float(np.mean(surface.load)), fluid_density))
            rows.append(Scalar("rod_break_depth", depth))
        return rows


class WellRows:
    """Intake pressure, fluid level, production and energy per day of K cards from their pump
    cards ([Rowlan2009PIP], [Wang2019]), a rate or an energy only with a runtime: the well's
    plunger area, pump depth and discharge pressure found once, each figure of the K cards one
    array computation (``figures`` of :func:`summarise_pump_card`, the pump cards' loads
    ``pump_load`` (K, N), the polished-rod powers ``power`` [W] and the periods [s], (K,)); a
    card's rows (:meth:`card`) with its warnings."""

    def __init__(self, unit: UnitConfig, figures: PumpCardSummary, pump_load: np.ndarray, power: np.ndarray,
                 period: np.ndarray, production: Production, intake_known: bool) -> None:
        well = self._well = unit.require_well()
        self._unit, self._production, self._intake_known = unit.name, production, intake_known
        area = plunger_area(well.plunger_diameter)
        self._depth = well.pump_vertical_depth()
        self._outlet = discharge_pressure(self._depth, well.fluid_density, well.tubing_head_pressure)
        intake = intake_pressure_from_load(figures.fluid_load, area, self._outlet)
        self._fluid, self._intake = figures.fluid_load.tolist(), intake.tolist()
        self._above = fluid_above_pump(intake, well.casing_head_pressure, well.fluid_density).tolist()
        if production.runtime is None:
            return
        slip = None
        if production.pump_efficiency is None and None not in (well.plunger_clearance, well.plunger_length,
                                                               well.fluid_kinematic_viscosity):
            slip = slippage_rate(well.plunger_diameter, well.plunger_clearance, well.plunger_length,
                                 well.fluid_kinematic_viscosity * well.fluid_density,
                                 _not_below_zero(figures.fluid_load) / area)
        middle = 0.5 * (figures.upstroke_load + figures.downstroke_load)
        loaded = np.mean(pump_load > middle[:, None], axis=-1)
        self._slip = None if slip is None else (slip * loaded * production.runtime).tolist()
        self._production_rate = inferred_production(
            figures.net_stroke, area, period, production.runtime, pump_efficiency=production.pump_efficiency or 1.0,
            slippage=0.0 if slip is None else slip, loaded_share=loaded).tolist()
        self._energy = energy_per_day(_not_below_zero(power), production.system_efficiency, production.runtime).tolist()

    def card(self, index: int) -> list[Scalar]:
        """The rows of card ``index``; a fluid level below the pump or above the surface is clipped, with a warning."""
        well, production, depth = self._well, self._production, self._depth
        rows = [Scalar("discharge_pressure", self._outlet)]
        intake = self._intake[index]
        if not self._intake_known:
            rows.append(Scalar("pump_intake_pressure", intake))
        above = self._above[index]
        if not 0.0 <= above <= depth:
            warn(f"unit {self._unit}: the card's fluid load {self._fluid[index] / 1e3:.4g} kN puts the fluid level "
                 f"{'below the pump' if above < 0 else 'above the surface'} (intake pressure {intake / 1e6:.4g} MPa, "
                 f"casing-head pressure {well.casing_head_pressure / 1e6:.4g} MPa): the level is clipped")
            above = min(max(above, 0.0), depth)
        rows += [Scalar("pump_submergence", above), Scalar("fluid_level_depth", depth - above)]
        if production.runtime is None:
            return rows
        rows.append(Scalar("runtime", production.runtime))
        if production.pump_efficiency is not None:
            rows.append(Scalar("pump_efficiency", production.pump_efficiency))
        elif self._slip is None:
            warn(f"unit {self._unit}: no slippage deducted from the inferred production: give --pump-efficiency, or "
                 f"the well's plunger_clearance, plunger_length and fluid_kinematic_viscosity")
        if self._slip is not None:
            rows.append(Scalar("pump_slippage", self._slip[index]))
        rows.append(Scalar("inferred_production", self._production_rate[index]))
        energy = self._energy[index]
        rows += [Scalar("system_efficiency", production.system_efficiency), Scalar("energy_per_day", energy)]
        if production.electricity_price is not None:
            rows.append(Scalar("electricity_cost", energy * production.electricity_price))
        return rows


def _not_below_zero(values: np.ndarray) -> np.ndarray:
    """max(x, 0.0) of each value as Python's ``max`` gives it: a negative zero kept (``numpy.maximum``
    makes it +0.0), so that every card's figure is the one it has alone."""
    return np.where(values < 0.0, 0.0, values)
