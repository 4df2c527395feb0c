"""Surface and pump cards predicted from the design: `pumpjack predict` and `dynamics --well-model wave`.

The rod string of the unit's ``[well]`` as a damped wave equation driven at the top by
the unit's exact polished-rod motion, with the pump's valves at the bottom
([Gibbs1963]; :mod:`pumpjack_cli.core.rods.predict`), at uniform crank speed or solved
together with the machine's equation of motion ([SK8Rotation2013] eq. 1;
:mod:`pumpjack_cli.core.dynamics.coupled`). The predicted surface card then goes
through the torque analysis of `pumpjack torque` ([API11E]), and the rods through the
stress and Goodman summary of `pumpjack downhole` ([API11BR]).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..config.files import error_message
from ..core.beam.card import Card, card_load
from ..core.beam.counterbalance import rp11l_counterbalance_effect
from ..core.rods.analysis import taper_loads
from ..core.rods.downhole import DEFAULT_DAMPING_FACTOR
from ..core.rods.deviated_predict import predict_deviated, predict_deviated_cards
from ..core.rods.predict import Prediction, predict_cards
from ..core.rods.pump_faults import hanging_pump, parted_damping, parted_string, tag_stops
from ..core.sampling import crank_grid, cycle_period, uniform_time
from ..errors import BalanceError, PredictionError, PumpjackError, warn
from ..results import Column, Curve, Panel, Result, Scalar
from .card_runs import CardRun
from .deviated import (Deviation, deviated_path, friction_coefficient, profile_result, survey_summary, surveyed,
                       with_survey)
from .inputs import crank_columns, dead_position_marks, extreme_scalars, motor_levels
from .rods import goodman_panel, taper_summary
from .torque import SUMMARY_STEPS, card_torque

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: Time samples per cycle of the predicted cards.
DEFAULT_SAMPLES = 360
#: CrankMotion models of a prediction.
CRANK_MOTIONS = ("uniform", "dynamic")


@dataclass(frozen=True)
class WellOverrides:
    """Well data given as options, SI; None keeps the unit file's value. The fluid level
    (submergence) and the intake pressure replace each other."""

    submergence: float | None = None
    intake_pressure: float | None = None
    tubing_head_pressure: float | None = None
    casing_head_pressure: float | None = None
    fluid_density: float | None = None
    fillage: float | None = None
    gas_exponent: float | None = None
    survey: str | None = None
    friction_coefficient: float | None = None
    guide_limit: float | None = None
    #: An API tubing size ("2-7/8"): the tubing unanchored, stretching under the fluid load.
    tubing_size: str | None = None


#: Override field -> (the well's field, the option that sets it).
_OVERRIDES = {
    "submergence": ("pump_submergence", "--submergence"),
    "intake_pressure": ("pump_intake_pressure", "--intake-pressure"),
    "tubing_head_pressure": ("tubing_head_pressure", "--tubing-head-pressure"),
    "casing_head_pressure": ("casing_head_pressure", "--casing-head-pressure"),
    "fluid_density": ("fluid_density", "--fluid-density"),
    "fillage": ("pump_fillage", "--fillage"),
    "gas_exponent": ("gas_exponent", "--gas-exponent"),
    "survey": ("survey", "--survey"),
    "friction_coefficient": ("rod_friction_coefficient", "--friction-coefficient"),
    "guide_limit": ("rod_guide_side_load_limit", "--guide-limit"),
    "tubing_size": ("tubing_size", "--unanchored-tubing"),
}


def with_overrides(unit: UnitConfig, overrides: WellOverrides):
    """The unit with its ``[well]`` changed by the options, validated by the well's schema
    (a value out of range is refused naming its option)."""
    from pydantic import ValidationError

    if overrides.submergence is not None and overrides.intake_pressure is not None:
        raise PumpjackError("--submergence and --intake-pressure: give one of them; each sets the pump's intake "
                            "pressure")
    well = unit.require_well()
    data = well.model_dump()
    for name, (field, _) in _OVERRIDES.items():
        value = getattr(overrides, name)
        if value is not None:
            data[field] = value
    if overrides.submergence is not None:
        data["pump_intake_pressure"] = None
    if overrides.intake_pressure is not None:
        data["pump_submergence"] = None
    if overrides.tubing_size is not None:
        data["tubing_anchored"] = False
    try:
        changed = type(well).model_validate(data)
    except ValidationError as exc:
        error = exc.errors()[0]
        if error["loc"]:
            field = str(error["loc"][0])
            where = next((option for f, option in _OVERRIDES.values() if f == field), f"well.{field}")
        else:   # the well as a whole (its fields together): the options given, with the unit's [well]
            given = [option for name, (_, option) in _OVERRIDES.items() if getattr(overrides, name) is not None]
            where = f"{', '.join(given)} with the unit's [well]" if given else "well"
        raise PumpjackError(f"{where}: {error_message(error, type(well))}") from None
    return unit.model_copy(update={"well": changed})


@dataclass(frozen=True)
class Faults:
    """Pump faults to simulate (:mod:`pumpjack_cli.core.rods.pump_faults`), SI; None: none. A valve's
    leak at the full fluid-load pressure difference [m^3/s], or as a share of the pump's
    displacement rate (A_p S N with the polished-rod stroke S); the interference of a stop at
    the bottom or top [m]: how far short of the end of its free stroke the plunger meets it;
    the depth along the rods [m] or the share of the pump depth where the string is parted."""

    travelling_valve_leak: float | None = None
    standing_valve_leak: float | None = None
    leak_shares: tuple[float | None, float | None] = (None, None)
    tag_bottom: float | None = None
    tag_top: float | None = None
    parted_at: float | None = None
    parted_share: float | None = None

    @property
    def any(self) -> bool:
        """True when a fault is asked for."""
        return any(value is not None for value in (self.travelling_valve_leak, self.standing_valve_leak,
                                                   *self.leak_shares, self.tag_bottom, self.tag_top,
                                                   self.parted_at, self.parted_share))

    def words(self) -> str:
        """The faults for a title: "travelling valve leak, tagging down"."""
        found = [name for name, on in (
            ("travelling valve leak", self.travelling_valve_leak is not None or self.leak_shares[0] is not None),
            ("standing valve leak", self.standing_valve_leak is not None or self.leak_shares[1] is not None),
            ("tagging down", self.tag_bottom is not None), ("tagging up", self.tag_top is not None),
            ("parted rods", self.parted_at is not None or self.parted_share is not None)) if on]
        return ", ".join(found)


def _faulty(unit: UnitConfig, string, well_pump, omega: float, nu: float, samples: int, faults: Faults):
    """The rods, pump and damping of the well with the faults (a parted string keeps the damping
    force per length of the whole string), and its cards ([Gibbs1963]; :mod:`~pumpjack_cli.core.rods.pump_faults`)."""
    well, mechanism = unit.well, unit.geometry.mechanism()

    def cards(rods, pump, damping):
        return predict_cards(mechanism, omega, rods, pump, damping=damping, fluid_density=well.fluid_density,
                             samples=samples, rod_density=well.rod_density)

    depth = faults.parted_at if faults.parted_share is None else faults.parted_share * string.total_length
    if depth is not None:
        if faults.words() != "parted rods":
            raise PumpjackError("--parted-at: nothing hangs on a parted string's free end; no other pump fault "
                                "applies")
        try:
            hanging = parted_string(string, depth)
        except PredictionError as exc:
            raise PumpjackError(f"--parted-at: {exc}") from None
        return hanging, cards(hanging, hanging_pump(well_pump), parted_damping(string, hanging, nu))
    displacement = well_pump.plunger_area * mechanism.stroke * omega / (2.0 * np.pi)
    leaks = [rate if share is None else share * displacement
             for rate, share in zip((faults.travelling_valve_leak, faults.standing_valve_leak), faults.leak_shares)]
    pump = replace(well_pump, travelling_valve_leak=leaks[0] or 0.0, standing_valve_leak=leaks[1] or 0.0)
    if faults.tag_bottom is not None or faults.tag_top is not None:
        free = cards(string, pump, nu)
        bottom, top = tag_stops(free.plunger_position, free.pump_load, pump, faults.tag_bottom, faults.tag_top)
        pump = replace(pump, bottom_stop=bottom, top_stop=top)
    return string, cards(string, pump, nu)


def damping_factor(unit: UnitConfig, given: float | None) -> float:
    """Gibbs' nu: the option, else the unit file's, else the default with a warning ([Gibbs1963])."""
    if given is not None:
        return given
    if unit.well.damping_factor is not None:
        return unit.well.damping_factor
    warn(f"unit {unit.name}: no well.damping_factor; damping factor {DEFAULT_DAMPING_FACTOR:g} assumed "
         f"(give --damping)")
    return DEFAULT_DAMPING_FACTOR


@dataclass(frozen=True)
class Predicted:
    """A prediction with the crank's motion at its samples (uniform: constant speed, zero
    acceleration) and, for the coupled solution, the machine's torques."""

    cards: Prediction
    crank_speed: np.ndarray
    crank_acceleration: np.ndarray
    coupled: object | None
    damping: float
    #: In a deviated well, the profile, drag and grid (:class:`~pumpjack_cli.core.rods.deviated_predict.DeviatedPrediction`).
    deviated: object | None = None
    #: The rods the cards hang from (a parted string's: those above the break); None: the unit's.
    rods: object | None = None


def predicted(unit: UnitConfig, spm: float | None, crank_motion: str, samples: int, damping: float | None,
              faults: Faults = Faults()) -> Predicted:
    """Solve the well at uniform crank speed (``--spm`` or the drive) or coupled with the machine."""
    if crank_motion not in CRANK_MOTIONS:
        raise PumpjackError(f"--crank-motion {crank_motion}: use one of {', '.join(CRANK_MOTIONS)}")
    string, well_pump, well = unit.rods(), unit.pump(), unit.well
    path = deviated_path(unit)
    if crank_motion == "uniform":
        omega = unit.crank_speed(spm)
        nu = damping_factor(unit, damping)
        if faults.any:
            if path is not None:
                raise PumpjackError(f"{faults.words()}: the pump faults are simulated on the rods of a vertical well; "
                                    f"this one has a deviation survey")
            rods, cards = _faulty(unit, string, well_pump, omega, nu, samples, faults)
            return Predicted(cards, np.full(samples, omega), np.zeros(samples), None, nu, rods=rods)
        if path is not None:
            found = predict_deviated_cards(unit.geometry.mechanism(), omega, string, path, well_pump, damping=nu,
                                           fluid_density=well.fluid_density, samples=samples,
                                           friction_coefficient=friction_coefficient(unit))
            return Predicted(found.cards, np.full(samples, omega), np.zeros(samples), None, nu, deviated=found)
        cards = predict_cards(unit.geometry.mechanism(), omega, string, well_pump, damping=nu,
                              fluid_density=well.fluid_density, samples=samples, rod_density=well.rod_density)
        return Predicted(cards, np.full(samples, omega), np.zeros(samples), None, nu)
    if faults.any:
        raise PumpjackError(f"{faults.words()}: the pump faults are simulated at uniform crank speed "
                            f"(--crank-motion uniform)")
    if spm is not None:
        raise PumpjackError("--spm sets a uniform crank speed; with --crank-motion dynamic the motor sets the speed")
    for section in ("masses", "drive"):
        unit.require(section, "--crank-motion dynamic solves the machine's equation of motion")
    nu = damping_factor(unit, damping)
    deviated = None
    if path is not None:
        from ..core.dynamics.coupled_deviated import predict_coupled_deviated

        both, deviated = predict_coupled_deviated(unit.machine(elastic_rods=True), string, path, well_pump, damping=nu,
                                                  fluid_density=well.fluid_density, samples=samples,
                                                  friction_coefficient=friction_coefficient(unit))
    else:
        from ..core.dynamics.coupled import predict_coupled

        both = predict_coupled(unit.machine(elastic_rods=True), string, well_pump, damping=nu,
                               fluid_density=well.fluid_density, rod_density=well.rod_density, samples=samples)
    margin = both.summary.breakdown_torque_margin
    if margin < 1.0:
        warn(f"unit {unit.name}: the motor would need {1.0 / margin:.3g} x its pull-out torque; the linear motor "
             f"characteristic is used beyond its validity (the motor would stall)")
    return Predicted(both.cards, both.crank_speed, both.crank_acceleration, both, nu, deviated=deviated)


def _runs(found: Predicted, steps: int) -> tuple[Card, list[CardRun]]:
    """The predicted surface card on the crank-angle axis, run on the output grid (the
    prediction's own crank angles) and on the torque summary's grid."""
    cards = found.cards
    card = Card(cards.crank_angle, cards.polished_rod_load)
    period = cards.summary.period
    if found.coupled is None:
        omega = float(found.crank_speed[0])
        runs = [CardRun(theta, uniform_time(theta, omega), np.full(theta.size, omega), np.zeros(theta.size),
                        card_load(card, theta), cycle_period(omega), "uniform")
                for theta in (cards.crank_angle, crank_grid(steps))]
        return card, runs

    def run(theta):
        angle = np.append(cards.crank_angle, 2.0 * np.pi)
        return CardRun(theta, np.interp(theta, angle, np.append(cards.time, period)),
                       np.interp(theta, cards.crank_angle, found.crank_speed, period=2.0 * np.pi),
                       np.interp(theta, cards.crank_angle, found.crank_acceleration, period=2.0 * np.pi),
                       card_load(card, theta), period, "dynamic")

    return card, [CardRun(cards.crank_angle, cards.time, found.crank_speed, found.crank_acceleration,
                          cards.polished_rod_load, period, "dynamic"), run(crank_grid(steps))]


def _card_summary(cards: Prediction, nu: float, fillage: float) -> list[Scalar]:
    s = cards.summary
    high, low = s.peak_polished_rod_load, s.minimum_polished_rod_load
    c = s.convergence
    return [
        Scalar("strokes_per_minute", 2.0 * np.pi / s.period),
        Scalar("period", s.period),
        Scalar("damping_factor", nu),
        Scalar("max_rod_load", high.value),
        Scalar("max_rod_load_crank_angle", high.crank_angle),
        Scalar("min_rod_load", low.value),
        Scalar("min_rod_load_crank_angle", low.crank_angle),
        Scalar("buoyant_rod_weight", s.buoyant_rod_weight),
        Scalar("fluid_load", s.fluid_load),
        Scalar("rp11l_counterbalance_effect", rp11l_counterbalance_effect(s.buoyant_rod_weight, s.fluid_load)),
        Scalar("stroke", s.polished_rod_stroke),
        Scalar("gross_pump_stroke", s.gross_plunger_stroke),
        Scalar("net_pump_stroke", s.net_plunger_stroke),
        Scalar("pump_fillage", fillage),
        Scalar("static_stretch", s.static_stretch),
        Scalar("pump_displacement", s.pump_rate),
        Scalar("surface_card_work", s.surface_card_work),
        Scalar("pump_card_work", s.pump_card_work),
        Scalar("damping_dissipation", s.damping_dissipation),
        Scalar("rod_energy_residual", s.energy_residual),
        Scalar("polished_rod_power", s.polished_rod_power),
        Scalar("cycles", c.cycles),
        Scalar("repeat_strokes", c.strokes),
        Scalar("periodicity_error", c.change),
    ]


def coupled_summary(s) -> list[Scalar]:
    """The machine's side of a coupled solution (:class:`~pumpjack_cli.core.dynamics.coupled.CoupledSummary`)."""
    rows = [Scalar("mean_crank_speed", s.mean_speed),
            Scalar("speed_fluctuation", s.speed_fluctuation)]
    rows += extreme_scalars((
        ("max_crank_speed", s.max_speed),
        ("min_crank_speed", s.min_speed),
        ("max_crank_acceleration", s.max_acceleration),
        ("min_crank_acceleration", s.min_acceleration),
        ("max_motor_torque", s.peak_motor_torque),
        ("min_motor_torque", s.min_motor_torque),
        ("max_inertia_torque", s.peak_inertia_torque),
        ("min_inertia_torque", s.min_inertia_torque),
    ))
    rows += [Scalar("energy_per_cycle", s.motor_work),
             Scalar("rod_work_per_cycle", s.polished_rod_work),
             Scalar("machine_energy_residual", s.energy_residual),
             Scalar("breakdown_torque_margin", s.breakdown_torque_margin),
             Scalar("revolutions", s.convergence.cycles)]
    return rows


def _comparison(unit: UnitConfig, found: Predicted, samples: int) -> list[Scalar]:
    """How the coupled solution differs from uniform rotation at its mean speed and from the
    rigid-rod model of [SK8Rotation2013]."""
    from ..core.dynamics.periodic import steady_state

    cards = found.cards.summary
    if found.deviated is not None:
        uniform = predict_deviated_cards(unit.geometry.mechanism(), 2.0 * np.pi / cards.period, unit.rods(),
                                         unit.well.path(), unit.pump(), damping=found.damping,
                                         fluid_density=unit.well.fluid_density, samples=samples,
                                         friction_coefficient=unit.well.friction_coefficient()).cards
    else:
        uniform = predict_cards(unit.geometry.mechanism(), 2.0 * np.pi / cards.period, unit.rods(), unit.pump(),
                                damping=found.damping, fluid_density=unit.well.fluid_density, samples=samples,
                                rod_density=unit.well.rod_density)
    uniform_found = Predicted(uniform, np.full(samples, 2.0 * np.pi / cards.period), np.zeros(samples), None,
                              found.damping)
    card, runs = _runs(uniform_found, SUMMARY_STEPS)
    method = "exact" if unit.masses is not None else "api"
    uniform_peak = card_torque(unit, card, runs, method, "equal-peaks").peak_net_torque
    rigid = steady_state(unit.machine(), crank_grid(SUMMARY_STEPS))
    rigid_load = rigid.rod_load
    rows = [
        Scalar("uniform_max_rod_load", uniform.summary.peak_polished_rod_load.value),
        Scalar("uniform_min_rod_load", uniform.summary.minimum_polished_rod_load.value),
        Scalar("uniform_peak_net_torque", uniform_peak),
        Scalar("rigid_rod_speed_fluctuation", rigid.summary.speed_fluctuation),
        Scalar("rigid_rod_max_motor_torque", rigid.summary.max_motor_torque.value),
        Scalar("rigid_rod_peak_inertia_torque", float(np.max(np.abs(rigid.inertia_torque)))),
        Scalar("rigid_rod_max_rod_load", float(np.max(rigid_load))),
        Scalar("rigid_rod_min_rod_load", float(np.min(rigid_load))),
    ]
    return rows


def _warn_periodic_state(name: str, summary) -> None:
    """Say so when the pump's state repeats only after several strokes, or only to more than the
    tolerance (:func:`~pumpjack_cli.core.rods.predict_solver.converge`)."""
    c = summary.convergence
    if c.strokes > 1:
        peaks = ", ".join(f"{peak / 1e3:.4g}" for peak in summary.stroke_peak_loads)
        volumes = ", ".join(f"{volume * 1e3:.4g}" for volume in summary.stroke_displacements)
        warn(f"unit {name}: the pump settles into a cycle of {c.strokes} unlike strokes (fluid pound: each stroke "
             f"meets the fluid where the rods' vibration from the one before leaves the plunger), peak polished-rod "
             f"loads {peaks} kN, pump displacements {volumes} l; the cards are those of the highest load, the works, "
             f"power and production the means of the {c.strokes} strokes")
    if c.change > c.tolerance:
        warn(f"unit {name}: the pump's state repeats to {c.change:.2g} of the fluid load (its largest change at one "
             f"sample), not to the tolerance {c.tolerance:g}, once the rods' transient has died away: a valve event "
             f"moves by a sample from stroke to stroke (periodicity_error); a finer --samples or a higher damping "
             f"settles it")


def predict(unit: UnitConfig, spm: float | None, crank_motion: str, samples: int, damping: float | None,
            overrides: WellOverrides = WellOverrides(), service_factor: float = 1.0,
            steps: int = SUMMARY_STEPS, deviation: Deviation = Deviation(), faults: Faults = Faults()) -> Result:
    """The result of `pumpjack predict` (module docstring); a survey (``deviation`` or the unit's)
    adds the deviated well's figures (:mod:`.deviated`)."""
    unit = with_survey(with_overrides(unit, overrides), deviation.survey, deviation.friction, deviation.guide_limit)
    found = predicted(unit, spm, crank_motion, samples, damping, faults)
    cards = found.cards
    low = cards.summary.minimum_polished_rod_load
    if low.value < 0.0:
        warn(f"unit {unit.name}: the predicted polished-rod load falls to {low.value / 1e3:.4g} kN at "
             f"{np.degrees(low.crank_angle):.4g} deg, below zero: the rods would push the carrier bar, which cannot "
             f"hold them down (rod float: the clamp lifts off); the card beyond that is not what the unit would see. "
             f"Slow the unit down")
    _warn_periodic_state(unit.name, cards.summary)
    if cards.summary.pump_displacement < 0.0:
        warn(f"unit {unit.name}: the pump's valves leak more than it lifts, and the tubing drains back into the well "
             f"through it ({cards.summary.pump_rate * 86400.0:.4g} m³/d, a negative pump_displacement): with the "
             f"tubing's pressure held, as the model holds it; in a well the fluid column falls until the leaks stop")
    summary = _card_summary(cards, found.damping, unit.well.pump_fillage)
    if found.deviated is not None:  # the cards' datum is the weight along the hole; W_rf stays the whole string's
        whole = unit.rods().buoyant_weight(unit.well.fluid_density)
        summary = [Scalar(s.name, whole) if s.name == "buoyant_rod_weight" else s for s in summary]
    if faults.parted_at is not None or faults.parted_share is not None:   # no pump hangs on a parted string
        summary = [Scalar(s.name, 0.0) if s.name in ("net_pump_stroke", "pump_displacement") else s for s in summary]
    summary += _survey_rows(unit, found)
    string = unit.rods() if found.rods is None else found.rods
    joint = np.vstack([cards.taper_top_load, cards.taper_bottom_load[-1:]])
    loads = taper_loads(string, joint)
    summary += taper_summary(string, loads, service_factor)
    card, runs = _runs(found, steps)
    method = "exact" if unit.masses is not None else "api"
    try:
        torque = card_torque(unit, card, runs, method, "equal-peaks")
    except BalanceError as exc:
        warn(f"unit {unit.name}: the predicted card cannot be balanced by equal peaks ({exc.note}); the recommended "
             f"counterbalance is the one of the least peak torque (min-peak)")
        torque = card_torque(unit, card, runs, method, "min-peak")
    summary += [s for s in torque.summary if s.name != "stroke"]   # the cards' own stroke is printed above
    columns = [
        *crank_columns(cards.crank_angle, cards.time, found.crank_speed, found.crank_acceleration),
        Column("position", cards.polished_rod_position),
        Column("velocity", cards.polished_rod_velocity),
        Column("rod_load", cards.polished_rod_load),
        Column("pump_position", cards.plunger_position),
        Column("pump_load", cards.pump_load),
        Column("chamber_pressure", cards.chamber_pressure),
        torque.net_torque,
    ]
    if found.coupled is not None:
        both = found.coupled
        columns += [Column("motor_torque", both.motor_torque), Column("inertia_torque", both.inertia_torque)]
        summary += coupled_summary(both.summary)
        summary += _comparison(unit, found, samples)
    panels = [Panel("load", (), curves=(Curve("surface card", "position", "rod_load"),
                                        Curve("pump card", "pump_position", "pump_load")), x_label="position"),
              Panel("net torque", (torque.net_torque.name,), x="crank_angle", levels=torque.rating_levels),
              goodman_panel(string, loads, service_factor)]
    if found.coupled is not None:
        panels.insert(1, Panel("crank speed", ("crank_speed",), x="crank_angle"))
        panels.insert(2, Panel("motor torque", ("motor_torque",), x="crank_angle",
                               levels=motor_levels(unit.machine(elastic_rods=True).motor)))
    title = (f"{unit.name}: predicted cards, {crank_motion} rotation at {60.0 / cards.summary.period:.4g} strokes/min, "
             f"damping {found.damping:.3g}" + (f", {faults.words()}" if faults.any else ""))
    if surveyed(unit):
        title += f", survey {Path(unit.well.survey).name}"
    if deviation.profile:
        columns, panels = profile_result(unit, _profile(unit, found))
    return Result(title, tuple(summary), tuple(columns), tuple(panels), dead_position_marks(unit.geometry.mechanism()))


def _survey_rows(unit: UnitConfig, found: Predicted) -> list[Scalar]:
    """A survey's figures for `predict` and `dynamics --well-model wave`; in a deviated well the
    cards' datum is the weight along the hole, and buoyant_rod_weight stays the whole string's."""
    if not surveyed(unit):
        return []
    well = unit.well
    whole = unit.rods().buoyant_weight(well.fluid_density)
    if found.deviated is None:
        return survey_summary(unit, None, 0.0, well.friction_coefficient(), whole)
    deviated = found.deviated
    return survey_summary(unit, deviated.profile, deviated.friction_work, well.friction_coefficient(),
                          deviated.grid.hanging_weight)


def _profile(unit: UnitConfig, found: Predicted):
    """The depth profile of a prediction: the deviated march's, or in a vertical hole the same
    march's along the vertical (its cards are the modal solution's)."""
    if found.deviated is not None:
        return found.deviated.profile
    well = unit.well
    return predict_deviated(unit.rods(), well.path(), unit.pump(), found.cards.polished_rod_position,
                            found.cards.summary.period, damping=found.damping, fluid_density=well.fluid_density,
                            friction_coefficient=0.0).profile


def wave_dynamics(unit: UnitConfig, samples: int, damping: float | None, deviation: Deviation = Deviation()) -> Result:
    """`pumpjack dynamics --well-model wave`: the machine's periodic motion with the elastic rods
    of the unit's ``[well]`` instead of the rigid-rod model ([SK8Rotation2013], [Gibbs1963]), along
    the hole of a survey (:mod:`.deviated`)."""
    unit = with_survey(unit, deviation.survey, deviation.friction, deviation.guide_limit)
    found = predicted(unit, None, "dynamic", samples, damping)
    both, cards = found.coupled, found.cards
    _warn_periodic_state(unit.name, cards.summary)
    summary = [Scalar("damping_factor", found.damping),
               Scalar("period", cards.summary.period),
               Scalar("strokes_per_minute", 2.0 * np.pi / cards.summary.period),
               *coupled_summary(both.summary),
               Scalar("max_rod_load", cards.summary.peak_polished_rod_load.value),
               Scalar("min_rod_load", cards.summary.minimum_polished_rod_load.value),
               *_survey_rows(unit, found)]
    columns = (
        *crank_columns(cards.crank_angle, cards.time, both.crank_speed, both.crank_acceleration),
        Column("motor_torque", both.motor_torque),
        Column("velocity", cards.polished_rod_velocity),
        Column("inertia_torque", both.inertia_torque),
        Column("rod_load", cards.polished_rod_load),
        Column("rod_load_torque", both.rod_load_torque),
        Column("gravity_torque", both.gravity_torque),
        Column("net_torque", both.net_torque),
    )
    panels = (Panel("crank speed ω1", ("crank_speed",)),
              Panel("motor torque", ("motor_torque",), levels=motor_levels(unit.machine(elastic_rods=True).motor)),
              Panel("polished-rod load", ("rod_load",)))
    return Result(f"{unit.name}: dynamics, elastic rods (wave model), damping {found.damping:.3g}",
                  tuple(summary), columns, panels, dead_position_marks(unit.geometry.mechanism()))

