"""Accuracy of approximate inertia-force laws ([InertiaUNB600A]): the result tables of `pumpjack inertia-error`.

For a slider-crank unit (kind ``slider-crank``): the exact piston acceleration and
inertia force against the sinusoidal law, the first approximation and further terms
of the series; or the friction caused by the redundant supports of its stepped slider.
For a beam unit: the polished rod against the elementary, refined and arc-as-chord laws.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..core.beam.inertia_laws import beam_inertia_laws
from ..core.sampling import crank_grid, signed_extremes, uniform_time
from ..core.slider_crank.mechanism import (
    InertiaComparison,
    inertia_force,
    slider_inertia_laws,
    travel_from_outer_dead_centre,
)
from ..core.slider_crank.support_friction import (
    reduction_coefficients,
    redundant_support_friction,
    solid_round_second_moment,
)
from ..errors import PumpjackError
from ..quantities import parse_quantity
from ..results import Column, Mark, Panel, Result, Scalar
from .inputs import dead_centre_marks, dead_position_marks

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig
    from ..config.slider_crank import SliderCrankConfig

def _comparison(title: str, c: InertiaComparison, crank_speed: float, mass: float | None,
                extra: tuple[Scalar, ...] = (), marks: tuple[Mark, ...] = ()) -> Result:
    """A law comparison: accelerations always, inertia forces -m a when a mass is known."""
    summary = [
        Scalar("crank_speed", crank_speed),
        Scalar("strokes_per_minute", crank_speed),
        Scalar("stroke", c.stroke),
        *extra,
        Scalar("peak_acceleration", c.peak),
        Scalar("peak_crank_angle", c.peak_crank_angle),
    ]
    if mass is not None:
        summary.append(Scalar("peak_inertia_force", abs(inertia_force(mass, c.peak))))
    for name, error in c.errors.items():
        summary += [
            Scalar(f"{name}_peak_acceleration", error.peak),
            *([Scalar(f"{name}_peak_inertia_force", abs(inertia_force(mass, error.peak)))]
              if mass is not None else []),
            Scalar(f"{name}_peak_error", error.peak_error),
            Scalar(f"{name}_peak_error_of_law", error.peak_error_of_law),
            Scalar(f"{name}_max_deviation", error.max_deviation),
            Scalar(f"{name}_rms_deviation", error.rms_deviation),
        ]
    columns = [
        Column("crank_angle", c.crank_angle),
        Column("time", uniform_time(c.crank_angle, crank_speed)),
        Column("position", c.position),
        Column("velocity", c.velocity),
        Column("acceleration", c.acceleration),
    ]
    if mass is not None:
        columns.append(Column("inertia_force", inertia_force(mass, c.acceleration)))
    for name, values in c.laws.items():
        columns += [
            Column(f"acceleration_{name}", values),
            Column(f"deviation_{name}", values - c.acceleration),
        ]
        if mass is not None:
            columns.append(Column(f"inertia_force_{name}", inertia_force(mass, values)))
    names = tuple(c.laws)
    panels = [
        Panel("acceleration", ("acceleration",), tuple(f"acceleration_{n}" for n in names)),
        Panel("law - exact", tuple(f"deviation_{n}" for n in names)),
    ]
    if mass is not None:
        panels.insert(1, Panel("inertia force", ("inertia_force",), tuple(f"inertia_force_{n}" for n in names)))
    return Result(title, tuple(summary), tuple(columns), tuple(panels), marks)


def support_friction(unit: SliderCrankConfig, steps: int) -> Result:
    """Reactions and friction of the redundant supports of the stepped slider over one revolution."""
    slider = unit.stepped_slider
    if slider is None:
        raise PumpjackError(f"unit {unit.name} has no [stepped_slider] section: --support-friction needs one")
    mechanism = unit.geometry.slider_crank()
    theta = crank_grid(steps)
    support = slider.intermediate_support
    second_moments = [solid_round_second_moment(section.diameter) for section in slider.sections]

    def reactions(travel: np.ndarray):
        return redundant_support_friction(
            [section.length for section in slider.sections], second_moments, slider.elastic_modulus,
            slider.guide_length, slider.friction_coefficient, slider.settlement, slider.turn, travel,
            support.position if support else None, support.offset if support else 0.0,
        )

    travel = travel_from_outer_dead_centre(mechanism, theta)
    result = reactions(travel)
    at_dead = reactions(np.array([0.0, mechanism.stroke]))
    summary = [
        Scalar("slider_length", slider.length),
        *(Scalar(f"alpha_{i}", alpha)
          for i, alpha in enumerate(reduction_coefficients(second_moments), start=1)),
        Scalar("guide_friction_outer_dead_centre", at_dead.guide_friction[0]),
        Scalar("guide_friction_inner_dead_centre", at_dead.guide_friction[1]),
        Scalar("total_friction_outer_dead_centre", at_dead.total_friction[0]),
        Scalar("total_friction_inner_dead_centre", at_dead.total_friction[1]),
    ]
    for label, extreme in zip(("max", "min"), signed_extremes(theta, result.guide_friction)):
        summary += [
            Scalar(f"{label}_guide_friction", extreme.value),
            Scalar(f"{label}_guide_friction_crank_angle", extreme.crank_angle),
        ]
    columns = [
        Column("crank_angle", theta),
        Column("travel", travel),
        Column("guide_force", result.force),
        Column("guide_moment", result.moment),
        Column("outer_edge_reaction", result.outer_edge),
        Column("inner_edge_reaction", result.inner_edge),
        Column("guide_friction", result.guide_friction),
    ]
    reaction_curves, friction_curves = ("outer_edge_reaction", "inner_edge_reaction"), ("guide_friction",)
    if support is not None:
        columns += [
            Column("support_position", support.position - travel),
            Column("support_reaction", result.intermediate),
            Column("support_friction", result.intermediate_friction),
            Column("total_friction", result.total_friction),
        ]
        reaction_curves += ("support_reaction",)
        friction_curves += ("total_friction",)
    return Result(f"{unit.name}: friction from redundant supports of the stepped slider", tuple(summary),
                  tuple(columns),
                  (Panel("friction", friction_curves), Panel("reactions", reaction_curves), Panel("travel", ("travel",))),
                  dead_centre_marks(mechanism))


def inertia_error(unit: UnitConfig | SliderCrankConfig, spm: float | None, mass: float | None, support: bool, steps: int) -> Result:
    """The comparison (or, with ``support``, the stepped slider's support friction) for a unit of any kind."""
    if mass is not None and not mass > 0:
        raise PumpjackError(f"--mass must be positive, got {mass} kg")
    from ..config.slider_crank import MASS_LIMIT   # the unit file's own bound (its schema is loaded already)

    if mass is not None and mass > MASS_LIMIT:
        raise PumpjackError(f"--mass must be at most {MASS_LIMIT:g} kg (as a unit file's mass), got {mass:g} kg")
    if unit.kind == "slider-crank":
        omega = parse_quantity(f"{spm} rpm", "rotational_speed") if spm is not None else unit.reciprocating.crank_speed
        if support:
            return support_friction(unit, steps)
        mechanism = unit.geometry.slider_crank()
        return _comparison(
            f"{unit.name}: inertia force, exact and approximate laws",
            slider_inertia_laws(mechanism, omega, crank_grid(steps)), omega,
            unit.reciprocating.mass if mass is None else mass,
            (Scalar("crank_to_rod_ratio", mechanism.crank_ratio),
             Scalar("offset", unit.geometry.offset)), dead_centre_marks(mechanism),
        )
    if support:
        raise PumpjackError(f"unit {unit.name} is a beam pumping unit: --support-friction needs a slider-crank unit")
    omega = unit.crank_speed(spm)
    return _comparison(f"{unit.name}: polished-rod inertia, exact and approximate laws",
                       beam_inertia_laws(unit.geometry.mechanism(), omega, crank_grid(steps)), omega, mass,
                       marks=dead_position_marks(unit.geometry.mechanism()))
