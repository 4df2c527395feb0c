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
from .rods import goodman_panel, taper_summary

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
    stores summaries). Problems of the unit or the options are raised for all."""
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
    loads = taper_loads(string, np.array([pumps[k][1].joint_load for k in good]))
    marks = dead_position_marks(linkage)
    for i, k in enumerate(good):
        with collected_warnings() as noted:
            found[k] = _downhole_result(unit, cards[k], surfaces[k], pumps[k], string, path, method, figures.card(i),
                                        conditions.card(i), (float(works[i]), float(pump_works[i]), loads.card(i)),
                                        service_factor, deviation, production, marks if tables else None)
        said[k] += noted
    return [(result, tuple(notes)) for result, notes in zip(found, said)]


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


def _downhole_result(unit: UnitConfig, card, reading_surface, found, string, path, method: str,
                     figures: PumpCardSummary, condition, works: tuple, service_factor: float, deviation: Deviation,
                     production: Production, marks: tuple | None) -> Result:
    """The result of one card from its pump card (``found``: nu, the pump card, the deviated
    march or None), the well's deviated path (None in a vertical well), its figures, its
    condition, and its works (surface and pump card [J]) and rod loads; with the dead
    positions' ``marks`` its columns and plots, without them (None) the summary alone."""
    well = unit.require_well()
    reading, surface = reading_surface
    nu, pump, deviated = found
    surface_work, pump_work, loads = works
    summary = [
        Scalar("strokes_per_minute", 2.0 * np.pi / surface.period),
        Scalar("damping_factor", nu),
        Scalar("max_rod_load", float(reading.card.load.max())),
        Scalar("min_rod_load", float(reading.card.load.min())),
        Scalar("buoyant_rod_weight", pump.buoyant_weight if path is None else string.buoyant_weight(well.fluid_density)),
        Scalar("gross_pump_stroke", float(figures.gross_stroke)),
        Scalar("net_pump_stroke", float(figures.net_stroke)),
        Scalar("pump_fillage", float(figures.fillage)),
        Scalar("fluid_load", float(figures.fluid_load)),
        Scalar("rp11l_counterbalance_effect", rp11l_counterbalance_effect(pump.buoyant_weight, float(figures.fluid_load))),
        Scalar("max_pump_load", float(figures.peak_load)),
        Scalar("min_pump_load", float(figures.minimum_load)),
        Scalar("surface_card_work", surface_work),
        Scalar("pump_card_work", pump_work),
        Scalar("pump_displacement", float(displacement_rate(figures.net_stroke, surface.period,
                                                                         well.plunger_diameter))),
    ]
    found_pressures = unit.pump_pressures()
    if found_pressures is not None:
        summary.append(Scalar("pump_intake_pressure", float(intake_pressure(figures.fluid_load, well.plunger_diameter,
                                                                            found_pressures[0]))))
    summary += condition_summary(unit, surface, condition, string)
    summary += well_summary(unit, figures, pump, surface_work / surface.period, surface.period, production,
                            intake_known=found_pressures is not None)
    summary += taper_summary(string, loads, service_factor)
    title = f"{unit.name}: pump card ({method}, damping {nu:.3g}), card {card.name}"
    columns: tuple[Column, ...] = ()
    panels: tuple[Panel, ...] = ()
    if marks is not None:
        columns = (
            Column("time", surface.time),
            Column("crank_angle", surface.crank_angle),
            Column("position", surface.position),
            Column("rod_load", surface.load),
            Column("pump_position", pump.pump_position),
            Column("pump_load", pump.pump_load),
        )
    curves = (Curve("surface card", "position", "rod_load"), Curve("pump card", "pump_position", "pump_load"))
    if surveyed(unit):
        extra, more_columns, more_curves = deviated_rows(unit, string, surface, nu, deviated)
        summary += extra
        columns += more_columns if marks is not None else ()
        curves += more_curves
        title += f", survey {Path(well.survey).name}" + (f", friction {deviated.friction_coefficient:g}"
                                                         if deviated is not None else "")
    if marks is None:
        return Result(title, tuple(summary), ())
    f_o = float(condition.features.reference_load[0])   # the reference load lines of [Rowlan2008] on both cards
    lines = (("W_rf", pump.buoyant_weight), ("W_rf + F_o", pump.buoyant_weight + f_o), ("F_o (pump card)", f_o),
             ("", 0.0))
    panels = (Panel("load", (), curves=curves, x_label="position", levels=lines),
              goodman_panel(string, loads, service_factor))
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


def condition_summary(unit: UnitConfig, surface, found, string) -> list[Scalar]:
    """The pump's condition ([Rowlan2008], docs/diagnosis.md) of one card's diagnosis (``found``,
    :func:`~pumpjack_cli.core.rods.diagnosis.diagnose` of its pump card): the label, its confidence,
    the second-best label, and the evidence; a parted string's break depth from the wave
    equation's free end on the surface card (:func:`~pumpjack_cli.core.rods.plausibility.free_end`),
    else from the hanging weight."""
    well = unit.require_well()
    ft = found.features
    label = str(found.label[0])
    rows = [Scalar("pump_condition", label),
            Scalar("pump_condition_confidence", float(found.confidence[0])),
            Scalar("pump_condition_second", str(found.second[0])),
            Scalar("reference_fluid_load", float(ft.reference_load[0]))]
    for name in CARD_EVIDENCE:
        value = float(getattr(ft, name)[0])
        if math.isfinite(value):      # a point the card never reaches is left out, not printed as NaN
            rows.append(Scalar(name, value))
    rows.append(Scalar("card_area_ratio", float(ft.area_ratio[0])))
    if label == "rod_part":
        depth, off = free_end(surface.load, surface.position, surface.period, string, well.fluid_density)
        if not off <= PARTED_FLATNESS:
            depth = float(hanging_depth(string, float(np.mean(surface.load)), well.fluid_density))
        rows.append(Scalar("rod_break_depth", depth))
    return rows


def well_summary(unit: UnitConfig, figures, pump, polished_rod_power: float, period: float, production: Production,
                 intake_known: bool) -> list[Scalar]:
    """Intake pressure, fluid level, production and energy per day from the pump card ([Rowlan2009PIP],
    [Wang2019]); a rate or an energy only with a runtime."""
    well = unit.require_well()
    area = plunger_area(well.plunger_diameter)
    depth = well.pump_vertical_depth()
    outlet = discharge_pressure(depth, well.fluid_density, well.tubing_head_pressure)
    intake = float(intake_pressure_from_load(float(figures.fluid_load), area, outlet))
    rows = [Scalar("discharge_pressure", outlet)]
    if not intake_known:
        rows.append(Scalar("pump_intake_pressure", intake))
    above = float(fluid_above_pump(intake, well.casing_head_pressure, well.fluid_density))
    if not 0.0 <= above <= depth:
        warn(f"unit {unit.name}: the card's fluid load {float(figures.fluid_load) / 1e3:.4g} kN puts the fluid level "
             f"{'below the pump' if above < 0 else 'above the surface'} (intake pressure {intake / 1e6:.4g} MPa, "
             f"casing-head pressure {well.casing_head_pressure / 1e6:.4g} MPa): the level is clipped")
        above = min(max(above, 0.0), depth)
    rows += [Scalar("pump_submergence", above), Scalar("fluid_level_depth", depth - above)]
    if production.runtime is None:
        return rows
    rows.append(Scalar("runtime", production.runtime))
    slip: float | None = None
    if production.pump_efficiency is not None:
        rows.append(Scalar("pump_efficiency", production.pump_efficiency))
    elif None in (well.plunger_clearance, well.plunger_length, well.fluid_kinematic_viscosity):
        warn(f"unit {unit.name}: no slippage deducted from the inferred production: give --pump-efficiency, or the "
             f"well's plunger_clearance, plunger_length and fluid_kinematic_viscosity")
    else:
        slip = float(slippage_rate(well.plunger_diameter, well.plunger_clearance, well.plunger_length,
                                   well.fluid_kinematic_viscosity * well.fluid_density,
                                   max(float(figures.fluid_load), 0.0) / area))
    middle = 0.5 * (float(figures.upstroke_load) + float(figures.downstroke_load))
    loaded = float(np.mean(np.asarray(pump.pump_load) > middle))
    if slip is not None:
        rows.append(Scalar("pump_slippage", slip * loaded * production.runtime))
    rows.append(Scalar("inferred_production", float(inferred_production(
        float(figures.net_stroke), area, period, production.runtime,
        pump_efficiency=production.pump_efficiency or 1.0, slippage=slip or 0.0, loaded_share=loaded))))
    energy = float(energy_per_day(max(polished_rod_power, 0.0), production.system_efficiency, production.runtime))
    rows += [Scalar("system_efficiency", production.system_efficiency), Scalar("energy_per_day", energy)]
    if production.electricity_price is not None:
        rows.append(Scalar("electricity_cost", energy * production.electricity_price))
    return rows
