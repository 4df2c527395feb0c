"""The pump card from a surface card through the rod string's wave equation: `pumpjack downhole`.

The card is put on a uniform time grid over one period (its time stamps, or the unit's
exact kinematics and crank speed for a card of positions only); the damped wave
equation of the tapered string turns it into the pump card ([Gibbs1963],
[EverittJennings1992]); the pump card is read for strokes, fillage and fluid load, the
rods for stresses and Goodman loading ([API11BR]).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..core.beam.counterbalance import rp11l_counterbalance_effect
from ..core.rods.analysis import (
    card_work,
    displacement_rate,
    intake_pressure,
    summarise_pump_card,
    taper_loads,
)
from ..core.rods.downhole import (
    DEFAULT_DAMPING_FACTOR,
    damping_from_fluid_load,
    downhole_methods,
    pump_card,
)
from ..core.rods.deviated_diagnostic import deviated_pump_card
from ..errors import DownholeError, PumpjackError, warn
from ..results import Column, Curve, Panel, Result, Scalar
from .card_runs import CardSource, time_card
from .deviated import (Deviation, deviated_path, friction_coefficient, method_for, profile_result, survey_summary,
                       surveyed, with_survey)
from .inputs import dead_position_marks
from .rods import goodman_panel, taper_summary

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: Samples per period of the surface card on its uniform time grid.
DEFAULT_SAMPLES = 360


def damping_factor(unit: UnitConfig, given: float | None, rod_string, card, method: str,
                   solve=None) -> tuple[float, str]:
    """Gibbs' nu and where it comes from: the option, the unit file, or the energy balance
    with the well's fluid load ([Gibbs1963], [EverittJennings1992]; ``solve``: the transfer
    of a deviated well, :func:`~pumpjack_cli.core.rods.downhole.damping_from_fluid_load`)."""
    well = unit.require_well()
    if given is not None:
        return given, "--damping"
    if well.damping_factor is not None:
        return well.damping_factor, "well.damping_factor"
    found = unit.pump_pressures()
    if found is None:
        warn(f"unit {unit.name}: no fluid level or intake pressure for the energy balance; damping factor "
             f"{DEFAULT_DAMPING_FACTOR:g} assumed (give --damping)")
        return DEFAULT_DAMPING_FACTOR, "assumed"
    fluid_load = (found[0] - found[1]) * math.pi * well.plunger_diameter**2 / 4.0
    nu = damping_from_fluid_load(rod_string, card.period, card.position, card.load, fluid_load,
                                 fluid_density=well.fluid_density, method=method, solve=solve)
    return nu, "energy balance"


def downhole(unit: UnitConfig, card: CardSource, spm: float | None, crank_motion: str, method: str | None,
             damping: float | None, samples: int = DEFAULT_SAMPLES, service_factor: float = 1.0,
             deviation: Deviation = Deviation()) -> Result:
    """Pump card, pump-card figures and rod stresses of one surface card; in a deviated well
    (``deviation``'s survey or the unit's) with the drag and gravity along the hole
    (:mod:`.deviated`), method None choosing."""
    unit = with_survey(unit, deviation.survey, deviation.friction, deviation.guide_limit)
    method = method_for(unit, method)
    if method not in downhole_methods():
        raise PumpjackError(f"--method {method}: use one of {', '.join(downhole_methods())}")
    well = unit.require_well()
    string = unit.rods()
    linkage = unit.geometry.mechanism()
    reading, surface = time_card(unit, linkage, card, spm, samples, crank_motion)
    path, deviated = deviated_path(unit), None
    try:
        if path is None:
            nu, source = damping_factor(unit, damping, string, surface, method)
            pump = pump_card(string, surface.period, surface.position, surface.load, fluid_density=well.fluid_density,
                             damping_factor=nu, method=method)
        else:
            mu = friction_coefficient(unit)

            def transfer(nu: float, mu: float = mu):
                return deviated_pump_card(string, path, surface.period, surface.position, surface.load,
                                          fluid_density=well.fluid_density, damping_factor=nu, friction_coefficient=mu)

            nu, source = damping_factor(unit, damping, string, surface, method, lambda nu: transfer(nu).card)
            deviated = transfer(nu)
            pump = deviated.card
    except DownholeError as exc:
        raise PumpjackError(f"{card.name} on the rods of unit {unit.name}: {exc}") from None
    figures = summarise_pump_card(pump.pump_position, pump.pump_load)
    loads = taper_loads(string, pump.joint_load)
    surface_work = float(card_work(surface.position, surface.load))
    pump_work = float(card_work(pump.pump_position, pump.pump_load))
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
    found = unit.pump_pressures()
    if found is not None:
        summary.append(Scalar("pump_intake_pressure", float(intake_pressure(figures.fluid_load, well.plunger_diameter, found[0]))))
    summary += taper_summary(string, loads, service_factor)
    columns = (
        Column("time", surface.time),
        Column("crank_angle", surface.crank_angle),
        Column("position", surface.position),
        Column("rod_load", surface.load),
        Column("pump_position", pump.pump_position),
        Column("pump_load", pump.pump_load),
    )
    curves = (Curve("surface card", "position", "rod_load"), Curve("pump card", "pump_position", "pump_load"))
    title = f"{unit.name}: pump card ({method}, damping {nu:.3g}), card {card.name}"
    if surveyed(unit):
        extra, more_columns, more_curves = deviated_rows(unit, string, surface, nu, deviated)
        summary += extra
        columns += more_columns
        curves += more_curves
        title += f", survey {Path(well.survey).name}" + (f", friction {deviated.friction_coefficient:g}"
                                                         if deviated is not None else "")
    panels: tuple[Panel, ...] = (Panel("load", (), curves=curves, x_label="position"),
                                 goodman_panel(string, loads, service_factor))
    if deviation.profile:
        profile = deviated.profile if deviated is not None else deviated_pump_card(
            string, well.path(), surface.period, surface.position, surface.load, fluid_density=well.fluid_density,
            damping_factor=nu, friction_coefficient=0.0).profile
        columns, panels = profile_result(unit, profile)
    return Result(title, tuple(summary), columns, panels, dead_position_marks(linkage))


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
