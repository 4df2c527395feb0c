"""The engineer's report of one well on one page: `pumpjack report UNIT --card FILE`.

It runs what `pumpjack torque` and `pumpjack downhole` run on the same card with the same
options (the page's numbers are their ``-f json`` summaries, keyed by command) and lays
them out as a :class:`~pumpjack_cli.page.Page` in the order a production engineer
reads: the unit and the well, the cards, the gearbox torque against the ratings, the
balance recommendation, the rod loading (modified Goodman, [API11BR]), the pump condition
and its evidence, production and fluid level, the warnings, and the provenance (tool
version, input files' SHA-256, options). The pump condition with its evidence and the
production figures are those of the downhole result (:data:`.downhole.CONDITION_NAMES`,
:data:`.downhole.PRODUCTION_NAMES`); a rate per day needs the runtime (``--runtime``). A unit
without ``[well]`` gets the torque sections only, and says why.
"""

from __future__ import annotations

import datetime
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from .. import __version__
from ..errors import PumpjackError, collected_warnings, warn
from ..quantities import KWH
from ..page import Figure, Note, Page, Quantities, Section, SideBySide, Table, Values
from ..results import Result
from .batch.keys import file_sha256
from .card_runs import CardSource

if TYPE_CHECKING:
    from ..config.beam_unit import UnitConfig

#: The page's sections: anchor and heading, in order (``tests/commands/test_report_cli.py`` reads them).
SECTIONS = (("unit", "Unit and well"), ("cards", "Cards"), ("torque", "Gearbox torque and ratings"),
            ("balance", "Balance recommendation"), ("rods", "Rod loading (modified Goodman)"),
            ("condition", "Pump condition and evidence"), ("production", "Production and fluid level"),
            ("warnings", "Warnings"), ("provenance", "Provenance"))
NOT_AVAILABLE = "not available"


@dataclass(frozen=True)
class ReportOptions:
    """What `pumpjack report` passes to the analyses it runs (those of `torque` and `downhole`)."""

    spm: float | None = None
    crank_motion: str = "auto"
    method: str = "api"
    balance: str = "equal-peaks"
    damping: float | None = None
    downhole_method: str | None = None
    steps: int = 360
    samples: int | None = None
    service_factor: float = 1.0
    energy: object | None = None
    system: str = "si"
    runtime: float | None = None


def report(unit: UnitConfig, unit_file: Path, card: CardSource, options: ReportOptions) -> tuple[Page, dict]:
    """The page and the results it shows by command (``{"torque": Result, "downhole": Result}``)."""
    from .downhole import DEFAULT_SAMPLES, Production, downhole
    from .torque import Energy, torque

    if str(card.path) == "-":
        raise PumpjackError("--card -: the report needs a card file (its SHA-256 goes into the provenance)")
    energy = options.energy or Energy()
    with collected_warnings() as noted:
        torque_result = torque(unit, card, options.spm, options.steps, options.crank_motion, options.method,
                               options.balance, energy.drive_efficiency, energy)
        downhole_result = None
        if unit.well is not None:
            downhole_result = downhole(unit, card, options.spm, options.crank_motion, options.downhole_method,
                                       options.damping, options.samples or DEFAULT_SAMPLES, options.service_factor,
                                       production=Production(runtime=options.runtime))
    warnings = tuple(dict.fromkeys(noted))
    for text in warnings:   # the CLI prints them too
        warn(text)
    results = {"torque": torque_result, **({"downhole": downhole_result} if downhole_result is not None else {})}
    sections = [
        _unit_section(unit, torque_result),
        _cards_section(torque_result, downhole_result),
        _torque_section(torque_result),
        _balance_section(torque_result, downhole_result, options.balance),
        _rods_section(downhole_result),
        _condition_section(downhole_result),
        _production_section(downhole_result),
        Section("warnings", dict(SECTIONS)["warnings"],
                tuple(Note(text, "warning") for text in warnings) or (Note("none"),)),
        _provenance_section(unit, unit_file, card, options),
    ]
    title = f"{unit.name}: well report, card {card.name}"
    subtitle = (f"pumpjack {__version__}; {options.method.upper() if options.method == 'api' else options.method} "
                f"torque, balance {options.balance}")
    return Page(title, subtitle, tuple(sections)), results


def _names(result: Result | None) -> set[str]:
    return set() if result is None else {s.name for s in result.summary}


def _counterbalance_given(unit: UnitConfig) -> str:
    given = unit.counterbalance
    if given is not None and given.counterbalance_effect is not None:
        return "measured counterbalance effect ([counterbalance] counterbalance_effect)"
    if given is not None and given.moment is not None:
        return "moment ([counterbalance] moment)"
    _, known = unit.counterbalance_model()
    if known:
        return "from the unit file's counterbalance (masses or the kind's own keys)"
    return "unknown: only the recommended counterbalance is reported"


def _unit_section(unit: UnitConfig, torque_result: Result) -> Section:
    rows: list[tuple[str, float | str, str]] = [
        ("unit", unit.name, "text"),
        ("designation", unit.designation or unit.name, "text"),
        ("kind of unit", unit.geometry.unit_class, "text"),
        ("rotation (well to the right)", unit.geometry.rotation, "text"),
        ("counterbalance given as", _counterbalance_given(unit), "text"),
    ]
    well = unit.well
    if well is not None:
        rows += [("pump depth", well.pump_depth, "depth"), ("plunger diameter", well.plunger_diameter, "length")]
        depth = well.pump_depth
        for i, section in enumerate(well.rod_string, start=1):
            share = section.fraction if section.fraction is not None else section.length / depth
            rows += [(f"rod taper {i}: diameter", section.diameter, "length"),
                     (f"rod taper {i}: share of the string", share, "percent")]
        rows.append(("fluid density", well.fluid_density, "density"))
        if well.pump_submergence is not None:
            rows.append(("pump submergence (below the fluid level)", well.pump_submergence, "depth"))
        rows.append(("tubing", "anchored" if well.tubing_anchored else "not anchored", "text"))
    blocks: list[object] = [Quantities(tuple(rows)),
                            Values("torque", torque_result, ("stroke", "max_stroke", "stroke_loading", "gearbox_rating",
                                                             "structure_rating", "structural_unbalance",
                                                             "crank_offset"))]
    if well is None:
        blocks.append(Note(f"unit {unit.name} has no [well]: no pump card, rod loading or production "
                           "(docs/unit-files.md lists its keys)", "missing"))
    return Section("unit", dict(SECTIONS)["unit"], tuple(blocks))


def _cards_section(torque_result: Result, downhole_result: Result | None) -> Section:
    blocks: list[object] = []
    if downhole_result is not None:
        blocks.append(Figure(downhole_result, ("load",)))
    else:
        blocks.append(Figure(torque_result, ("card", "card and permissible loads")))
    blocks.append(Values("torque", torque_result, ("strokes_per_minute", "max_rod_load", "min_rod_load", "card_work",
                                                   "polished_rod_power")))
    if downhole_result is not None:
        blocks.append(Values("downhole", downhole_result, ("buoyant_rod_weight", "fluid_load", "gross_pump_stroke",
                                                           "net_pump_stroke", "max_pump_load", "min_pump_load",
                                                           "damping_factor")))
    return Section("cards", dict(SECTIONS)["cards"], tuple(blocks))


#: The duty rows of the present and the recommended counterbalance: label, present, recommended.
DUTY = (
    ("peak net torque", "peak_net_torque", "recommended_peak_net_torque"),
    ("upstroke peak torque", "upstroke_peak_torque", "recommended_upstroke_peak_torque"),
    ("downstroke peak torque", "downstroke_peak_torque", "recommended_downstroke_peak_torque"),
    ("gearbox loading", "gearbox_loading", "recommended_gearbox_loading"),
    ("equivalent (RMS) torque", "rms_net_torque", "recommended_rms_net_torque"),
    ("cyclic load factor", "cyclic_load_factor", "recommended_cyclic_load_factor"),
    ("motor power (RMS rule)", "rms_motor_power", "recommended_rms_motor_power"),
    ("NEMA motor size that covers it", "nema_motor_size", "recommended_nema_motor_size"),
    ("motor energy a day", "motor_energy", "recommended_motor_energy"),
    ("energy cost a day", "energy_cost", "recommended_energy_cost"),
)


def _torque_section(torque_result: Result) -> Section:
    names = _names(torque_result)
    panels = tuple(p.title for p in torque_result.panels if p.title in ("card and permissible loads", "card",
                                                                        "net torque"))
    blocks: list[object] = [Figure(torque_result, panels),
                            Values("torque", torque_result, ("peak_net_torque_crank_angle", "gearbox_rating",
                                                             "structure_loading", "structure_rating"))]
    rows = tuple(row for row in DUTY if row[1] in names or row[2] in names)
    blocks.append(SideBySide("torque", torque_result, ("present counterbalance", "recommended counterbalance"), rows))
    if "peak_net_torque" not in names:
        blocks.append(Note("the present counterbalance is unknown (no [counterbalance] moment or "
                           "counterbalance_effect, no [masses]): the duty is shown for the recommended one", "missing"))
    return Section("torque", dict(SECTIONS)["torque"], tuple(blocks))


def _balance_section(torque_result: Result, downhole_result: Result | None, criterion: str) -> Section:
    names = [s.name for s in torque_result.summary]
    variable = next((n.removeprefix("recommended_") for n in names if n.startswith("recommended_") and n in (
        "recommended_counterbalance_moment", "recommended_beam_counterweight", "recommended_air_pressure")), None)
    shown = tuple(n for n in (variable, "counterbalance_effect", f"recommended_{variable}",
                              "recommended_counterbalance_effect", "recommended_counterweight_radius",
                              "recommended_counterweight_mass") if n)
    blocks: list[object] = [Note(f"criterion: {criterion} (--balance); the recommendation keeps the structure and "
                                 "the crank offset, and changes only the balancing variable"),
                            Values("torque", torque_result, shown)]
    if downhole_result is not None:
        blocks.append(Values("downhole", downhole_result, ("rp11l_counterbalance_effect",)))
    return Section("balance", dict(SECTIONS)["balance"], tuple(blocks))


def _rods_section(downhole_result: Result | None) -> Section:
    if downhole_result is None:
        return Section("rods", dict(SECTIONS)["rods"], (Note(f"{NOT_AVAILABLE}: the unit has no [well]", "missing"),))
    names = tuple(s.name for s in downhole_result.summary if s.name.startswith("taper_"))
    return Section("rods", dict(SECTIONS)["rods"],
                   (Figure(downhole_result, ("max stress",)), Values("downhole", downhole_result, names)))


def _condition_section(downhole_result: Result | None) -> Section:
    """The pump's condition, its confidence, the second label and the card's evidence
    (:data:`.downhole.CONDITION_NAMES`, those the card gives)."""
    from .downhole import CONDITION_NAMES

    found = {s.name for s in downhole_result.summary} if downhole_result is not None else set()
    names = tuple(n for n in CONDITION_NAMES if n in found)
    if not names:
        return Section("condition", dict(SECTIONS)["condition"],
                       (Note(f"pump condition: {NOT_AVAILABLE} (the unit has no [well])", "missing"),))
    return Section("condition", dict(SECTIONS)["condition"], (Values("downhole", downhole_result, names),))


def _production_section(downhole_result: Result | None) -> Section:
    """Pump displacement, intake pressure, fluid level, production and energy
    (:data:`.downhole.PRODUCTION_NAMES`, those the analysis gives: a rate only with a runtime)."""
    from .downhole import PRODUCTION_NAMES

    if downhole_result is None:
        return Section("production", dict(SECTIONS)["production"],
                       (Note(f"{NOT_AVAILABLE}: the unit has no [well]", "missing"),))
    found = {s.name for s in downhole_result.summary}
    blocks: list[object] = [Values("downhole", downhole_result, tuple(n for n in PRODUCTION_NAMES if n in found))]
    if "inferred_production" not in found:
        blocks.append(Note("inferred production: give the unit's runtime (--runtime) for a rate per day", "missing"))
    return Section("production", dict(SECTIONS)["production"], tuple(blocks))


def _options_text(card: CardSource, options: ReportOptions, system: str) -> str:
    """The options that made the numbers, in words (the defaults said as such)."""
    from .torque import Energy

    energy = options.energy or Energy()
    price = "none" if energy.price is None else f"{energy.price * KWH:g} per kWh"
    parts = [f"units {system}", f"torque method {options.method}", f"balance {options.balance}",
             f"crank motion {options.crank_motion}",
             f"spm {'from the card' if options.spm is None else format(options.spm, 'g')}",
             f"steps {options.steps}",
             f"downhole method {options.downhole_method or 'the default (gibbs; everitt-jennings in a deviated well)'}",
             f"damping {'from the unit file or the energy balance' if options.damping is None else format(options.damping, 'g')}",
             f"samples {'the default' if options.samples is None else options.samples}",
             f"service factor {options.service_factor:g}", f"drive efficiency {energy.drive_efficiency:g}",
             f"motor efficiency {energy.motor_efficiency:g}", f"electricity price {price}",
             f"card stroke {card.stroke}"]
    parts += [f"card {name} {value}" for name, value in (("units", card.units), ("format", card.format),
                                                         ("points", card.points)) if value is not None]
    if card.columns:
        parts.append("card columns " + ",".join(f"{k}={v}" for k, v in card.columns.items()))
    return "; ".join(parts)


def _provenance_section(unit: UnitConfig, unit_file: Path, card: CardSource, options: ReportOptions) -> Section:
    now = datetime.datetime.now(datetime.timezone.utc).replace(microsecond=0).isoformat()
    rows = (("tool", f"pumpjack {__version__}"), ("unit", unit.name),
            ("unit file (or catalogue)", str(unit_file)), ("its SHA-256", file_sha256(unit_file)),
            ("card file", str(card.path)), ("card file SHA-256", file_sha256(card.path)),
            ("options", _options_text(card, options, options.system)), ("generated (UTC)", now))
    return Section("provenance", dict(SECTIONS)["provenance"],
                   (Table((("item", "text"), ("value", "text")), rows),))
