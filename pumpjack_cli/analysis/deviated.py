"""Deviated wells in the run layer: the survey and friction options, the solvers a deviated well
needs, its summary figures and the depth profile (``--profile``), with the rod-guide advice.

A unit whose ``[well]`` has a ``survey`` (or ``--survey``) that is not vertical is diagnosed by
the Everitt-Jennings march with gravity along the hole and Coulomb drag
(:mod:`~pumpjack_cli.core.rods.deviated_diagnostic`) and predicted by the time march of
:mod:`~pumpjack_cli.core.rods.deviated_predict`, coupled with the machine by
:mod:`~pumpjack_cli.core.dynamics.coupled_deviated`; a vertical survey runs the vertical
methods, whose physics it is (no side load, no drag), with its figures. Model and sources:
``docs/deviated.md`` ([JohancsikSPE11380], [EverittJennings1992], [Gibbs1963]).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..core.rods.deviated import DepthProfile, guide_advice
from ..errors import PumpjackError, warn
from ..quantities import FOOT
from ..results import Column, Panel, Scalar

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig
    from ..core.rods.path import WellPath

#: The profile's columns a terminal table shows (``--profile``).
PROFILE_SHOWN = ("measured_depth", "true_vertical_depth", "inclination", "dogleg_severity", "side_load",
                 "side_load_per_rod", "max_axial_load", "min_axial_load")
@dataclass(frozen=True)
class Deviation:
    """The options of a deviated well: the survey file (None: the unit's), the friction
    coefficient mu [-] and the side-load limit per contact [N] (None: the unit's), and whether the
    output is the depth profile instead of the cards."""

    survey: Path | None = None
    friction: float | None = None
    guide_limit: float | None = None
    profile: bool = False




def with_survey(unit: UnitConfig, survey: Path | None = None, friction: float | None = None,
                guide_limit: float | None = None) -> UnitConfig:
    """The unit with its ``[well]``'s survey file, friction coefficient and guide limit replaced by the
    options (None keeps the file's), validated by the well's schema (a value out of range is
    refused naming its option: :func:`.predict.with_overrides`)."""
    if survey is None and friction is None and guide_limit is None:
        return unit
    from .predict import WellOverrides, with_overrides   # its import takes scipy: only when there is an option

    return with_overrides(unit, WellOverrides(survey=None if survey is None else str(Path(survey).absolute()),
                                              friction_coefficient=friction, guide_limit=guide_limit))


def surveyed(unit: UnitConfig) -> bool:
    """Whether the unit's well has a survey (a deviated or a vertical one)."""
    return unit.well is not None and unit.well.survey is not None


def deviated_path(unit: UnitConfig) -> WellPath | None:
    """The hole of a unit whose survey leaves the vertical, else None (the vertical methods serve)."""
    if not surveyed(unit):
        return None
    path = unit.require_well().path()
    return None if getattr(path, "vertical", False) else path


def friction_coefficient(unit: UnitConfig) -> float:
    """mu of the well: the option's or the file's, else the default with a warning."""
    well = unit.require_well()
    mu = well.friction_coefficient()
    if well.rod_friction_coefficient is None:
        warn(f"unit {unit.name}: no well.rod_friction_coefficient; {mu:g} assumed for rods and couplings on the "
             f"tubing (give --friction-coefficient; docs/deviated.md)")
    return mu


def survey_summary(unit: UnitConfig, profile: DepthProfile | None, friction_work: float, mu: float,
                   axial_weight: float) -> list[Scalar]:
    """The figures a deviated well adds to a summary: the pump's true vertical depth, the rods'
    weight along the hole, mu, the drag's work, the largest side load and where, and the rod-guide
    advice when a limit is given (``profile`` None: a vertical survey, no side load)."""
    well = unit.require_well()
    largest, depth = profile.largest_side_load if profile is not None else (0.0, 0.0)
    rows = [Scalar("pump_true_vertical_depth", well.pump_vertical_depth()),
            Scalar("axial_rod_weight", axial_weight),
            Scalar("friction_coefficient", mu),
            Scalar("friction_work_per_cycle", friction_work),
            Scalar("max_side_load", largest),
            Scalar("max_side_load_depth", depth),
            Scalar("max_side_load_per_rod", largest * well.rod_joint_length)]
    limit = well.rod_guide_side_load_limit
    if limit is not None and profile is not None:
        rows += _guide_rows(profile, limit, well.rod_joint_length)
    elif limit is not None:
        rows += [Scalar("rod_guide_side_load_limit", limit), Scalar("rods_with_guides", 0.0),
                 Scalar("rod_guides_total", 0.0), Scalar("rod_guide_intervals", "none")]
    return rows


def _guide_rows(profile: DepthProfile, limit: float, rod_length: float) -> list[Scalar]:
    advice = guide_advice(profile.depth, profile.max_side_load, limit, rod_length)
    cell = _cells(profile.depth)
    rods = cell / rod_length
    needing = float(np.sum(rods[advice.guides_per_rod > 0]))
    total = float(np.sum(rods * advice.guides_per_rod))
    text = "; ".join(f"{top:.0f}-{bottom:.0f} m ({top / FOOT:.0f}-{bottom / FOOT:.0f} ft): {count} per rod"
                     for top, bottom, count in advice.intervals) or "none"
    return [Scalar("rod_guide_side_load_limit", limit), Scalar("rods_with_guides", float(math.ceil(needing))),
            Scalar("rod_guides_total", float(math.ceil(total))), Scalar("rod_guide_intervals", text)]


def _cells(depth: np.ndarray) -> np.ndarray:
    """Length of hole [m] each node of a profile stands for (half of each adjacent segment)."""
    segment = np.diff(depth)
    return np.concatenate([[0.0], segment]) / 2.0 + np.concatenate([segment, [0.0]]) / 2.0


def profile_result(unit: UnitConfig, profile: DepthProfile) -> tuple[tuple[Column, ...], tuple[Panel, ...]]:
    """The depth profile's columns (one row per node) and its plots: the well path in vertical
    section coloured by side load, the side load and the axial load envelope along the hole."""
    well = unit.require_well()
    path = well.path()
    depth = profile.depth
    phi = path.inclination(depth)
    curvature = np.hypot(path.inclination_rate(depth), path.azimuth_rate(depth) * np.sin(phi))
    north_east = path.north_east(depth)
    columns = [
        Column("measured_depth", depth),
        Column("true_vertical_depth", path.vertical_depth(depth)),
        Column("inclination", phi),
        Column("azimuth", path.azimuth(depth)),
        Column("dogleg_severity", curvature),
        Column("north", north_east[..., 0]),
        Column("east", north_east[..., 1]),
        Column("horizontal_displacement", np.hypot(north_east[..., 0], north_east[..., 1])),
        Column("side_load", profile.max_side_load),
        Column("side_load_per_rod", profile.max_side_load * well.rod_joint_length),
        Column("max_axial_load", profile.max_tension),
        Column("min_axial_load", profile.min_tension),
        Column("drag_work", profile.friction_work),
    ]
    if well.rod_guide_side_load_limit is not None:
        advice = guide_advice(depth, profile.max_side_load, well.rod_guide_side_load_limit, well.rod_joint_length)
        columns.insert(10, Column("rod_guides", advice.guides_per_rod.astype(float)))
    panels = (
        Panel("true vertical depth", ("true_vertical_depth",), x="horizontal_displacement", colour="side_load",
              y_down=True),
        Panel("side load", ("side_load",), x="measured_depth"),
        Panel("axial load", ("max_axial_load",), ("min_axial_load",), x="measured_depth"),
    )
    return tuple(columns), panels


def profile_shown(result_columns: tuple[Column, ...]) -> tuple[str, ...]:
    """The profile's columns a terminal table shows, with the guides per rod when advised."""
    names = {c.name for c in result_columns}
    return PROFILE_SHOWN + (("rod_guides",) if "rod_guides" in names else ())


def method_for(unit: UnitConfig, method: str | None) -> str:
    """The diagnostic method: the one asked for, else Gibbs' in a vertical hole and the
    Everitt-Jennings march in a deviated one (Gibbs' frequency-domain solution cannot carry
    the drag, which is not linear in the card)."""
    deviated = deviated_path(unit) is not None
    if method is None:
        return "everitt-jennings" if deviated else "gibbs"
    if deviated and method != "everitt-jennings":
        raise PumpjackError(f"--method {method}: the survey makes the well deviated, and Gibbs' frequency-domain "
                            f"solution cannot carry the rods' friction on the tubing; use everitt-jennings (the "
                            f"default with a survey)")
    return method
