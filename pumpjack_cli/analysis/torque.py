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

import functools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..core.beam.balance import balance_criteria, recommend_counterbalance
from ..core.beam.card import Card
from ..core.beam.counterbalance import (
    Counterbalance,
    CounterbalanceModel,
    counterbalance_effect,
    counterweight_placement,
    upstroke_test_angle,
)
from ..core.beam.loading import card_work, cyclic_load_factor
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
from ..core.sampling import extremes, peak
from ..errors import PumpjackError, warn
from ..results import Column, Panel, Result, Scalar
from .card_runs import CardRun, CardSource, card_runs
from .inputs import crank_columns, extreme_scalars

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


def _torques(unit: UnitConfig, linkage, spatial_masses, masses, balance: CounterbalanceModel, run: CardRun,
             method: str) -> _Torques:
    """The torque terms of a run; the exact net torque too when ``spatial_masses`` (the masses of
    a unit with the spatial model) are given."""
    parts = torque_components(linkage, run.crank_angle, run.load, balance,
                              beam_inertia=beam_group_inertia(linkage, masses) if masses else 0.0,
                              rotary_inertia=crank_group_inertia(masses) if masses else 0.0,
                              crank_speed=run.crank_speed, crank_acceleration=run.crank_acceleration)
    api = (parts.rod_load + parts.structural + parts.counterbalance + parts.articulating_inertia
           + parts.rotary_inertia)
    exact = None
    if spatial_masses is not None:
        basis = _exact_basis(unit.spatial(), spatial_masses, run.crank_angle.tobytes())
        exact = basis.torque(run.load, run.crank_speed, run.crank_acceleration)
    return _Torques(run, parts, api, exact, exact if method == "exact" else api)


@functools.lru_cache(maxsize=32)
def _exact_basis(spatial, masses, crank_angle: bytes) -> ExactTorqueBasis:
    """The unit's exact-torque responses on a crank grid, computed once for all its cards."""
    return exact_torque_basis(spatial, masses, np.frombuffer(crank_angle))


def torque(unit: UnitConfig, card: CardSource, spm: float | None, steps: int, crank_motion: str, method: str, criterion: str,
           drive_efficiency: float = 1.0) -> Result:
    """The torque analysis of one card (see the module docstring)."""
    check_options(method, criterion)
    reading, runs = card_runs(unit, unit.geometry.mechanism(), card, spm, (steps, SUMMARY_STEPS), crank_motion)
    found = card_torque(unit, reading.card, runs, method, criterion, drive_efficiency)
    title = (f"{unit.name}: gearbox torque ({method} method), card {card.name}, {runs[0].crank_motion} crank_motion, "
             f"balance {criterion}")
    return Result(title, found.card_summary + found.summary, found.columns, found.panels)


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
    recommended one when the present counterbalance is unknown), its largest magnitude [N·m] on
    the summary grid, and the gearbox rating's lines for a torque plot."""

    card_summary: tuple[Scalar, ...]
    summary: tuple[Scalar, ...]
    columns: tuple[Column, ...]
    panels: tuple[Panel, ...]
    net_torque: Column
    peak_net_torque: float
    rating_levels: tuple[tuple[str, float], ...]


def card_torque(unit: UnitConfig, card: Card, runs: list[CardRun], method: str, criterion: str,
                drive_efficiency: float = 1.0) -> CardTorque:
    """Net torque, balance and loading of a card (load at crank angles) run on the output grid
    ``runs[0]`` and the summary grid ``runs[1]`` (:data:`SUMMARY_STEPS` points): the
    analysis of a measured card and of a predicted one alike."""
    check_options(method, criterion)
    rated = unit.ratings()
    linkage = unit.geometry.mechanism()
    masses = unit.mass_model() if unit.masses is not None else None
    if method == "exact" and masses is None:
        raise PumpjackError(f"unit {unit.name} has no [masses] section; --method exact needs the link masses "
                            f"(--method api needs only [counterbalance])")
    spatial = hasattr(unit.geometry, "spatial")
    if method == "exact" and masses is not None:
        unit.spatial()          # refuses a kind without the spatial model
    balance, balance_known = unit.counterbalance_model()
    test_angle = upstroke_test_angle(linkage)
    out, dense = (_torques(unit, linkage, masses if spatial else None, masses, balance, run, method) for run in runs)
    theta = dense.run.crank_angle
    dt = 1.0 / dense.run.crank_speed  # time share of each point of the uniform crank-angle grid
    parts = dense.components
    recommendation = recommend_counterbalance(
        criterion, linkage, theta, dense.run.load, balance, weights=dt, test_angle=test_angle,
        extra_torque=dense.net - parts.rod_load - parts.structural - parts.counterbalance)
    if recommendation.value is None:
        raise PumpjackError(f"--balance {criterion}: {recommendation.note}; try --balance min-peak or min-rms")

    def shifted(t: _Torques, value: float) -> np.ndarray:
        """The net torque with the balancing variable at ``value`` (its torque is affine in it)."""
        return t.net + (value - balance.value) * balance.torque_per_value(linkage.motion(t.run.crank_angle))

    work = card_work(linkage, card)
    frequency = 1.0 / out.run.period
    summary = [Scalar(name, value) for name, value in balance.summary()]
    current = dense.net if balance_known else None
    if balance_known:
        found = peak(theta, current)
        summary += [Scalar(balance.variable, balance.value),
                    Scalar("counterbalance_effect",
                           counterbalance_effect(linkage.motion(np.array([test_angle])), balance)),
                    Scalar("peak_net_torque", found.value),
                    Scalar("peak_net_torque_crank_angle", found.crank_angle)]
        summary += extreme_scalars(zip(("max_net_torque", "min_net_torque"), extremes(theta, current)))
    recommended = shifted(dense, recommendation.value)
    summary += [
        Scalar("recommended_" + balance.variable, recommendation.value),
        Scalar("recommended_counterbalance_effect", recommendation.counterbalance_effect),
        Scalar("recommended_peak_net_torque", peak(theta, recommended).value),
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
    base = current if current is not None else recommended
    clf = cyclic_load_factor(base, dt)
    mean = float(np.sum(base * dt) / np.sum(dt))
    rms = clf * mean
    summary += [
        Scalar("rms_net_torque", rms),
        Scalar("cyclic_load_factor", clf),
        Scalar("rms_motor_power", rms * 2.0 * np.pi * frequency / drive_efficiency),
    ]
    summary += _loading(rated, card.load.max(), linkage.stroke, current, recommended, theta)
    if dense.exact is not None:
        summary.append(Scalar("peak_exact_minus_api_torque", peak(theta, dense.exact - dense.api).value))
    columns = _columns(linkage, out, balance_known, shifted(out, recommendation.value), rated)
    headline = next(c for c in columns if c.name == ("net_torque" if balance_known else "recommended_net_torque"))
    levels = _rating_levels(rated)
    card_summary = (Scalar("strokes_per_minute", 2.0 * np.pi * frequency), Scalar("card_work", work),
                    Scalar("polished_rod_power", work * frequency))
    return CardTorque(card_summary, tuple(summary), tuple(columns), _panels(columns, levels, balance_known), headline,
                      peak(theta, base).value, levels)


def _loading(rated: Ratings, peak_load: float, stroke: float, current, recommended, theta) -> list[Scalar]:
    """Loading against the ratings that are known (fractions, shown in %)."""
    found = []
    if rated.gearbox_torque is not None:
        found.append(Scalar("gearbox_rating", rated.gearbox_torque))
        if current is not None:
            found.append(Scalar("gearbox_loading", peak(theta, current).value / rated.gearbox_torque))
        found.append(Scalar("recommended_gearbox_loading", peak(theta, recommended).value / rated.gearbox_torque))
    if rated.structure_load is not None:
        found += [Scalar("structure_rating", rated.structure_load),
                  Scalar("structure_loading", peak_load / rated.structure_load)]
    if rated.max_stroke is not None:
        found += [Scalar("max_stroke", rated.max_stroke),
                  Scalar("stroke_loading", stroke / rated.max_stroke)]
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


def _panels(columns: list[Column], levels: tuple[tuple[str, float], ...], balance_known: bool) -> tuple[Panel, ...]:
    names = {c.name for c in columns}
    panels = []
    if "permissible_load_min" in names:
        panels.append(Panel("card and permissible loads", ("rod_load",), ("permissible_load_min", "permissible_load_max"),
                            x="position", clip=True))
    else:
        panels.append(Panel("card", ("rod_load",), x="position"))
    panels.append(Panel("net torque", ("net_torque",) if balance_known else ("recommended_net_torque",),
                        ("recommended_net_torque",) if balance_known else (), levels=levels))
    panels.append(Panel("torque components", ("rod_load_torque", "structural_torque", "articulating_inertia_torque",
                                              "rotary_inertia_torque")
                        + (("counterbalance_torque",) if balance_known else ())))
    return tuple(panels)
