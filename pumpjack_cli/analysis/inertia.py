"""Accuracy of approximate inertia-force laws ([InertiaUNB600A]): the result tables of `pumpjack inertia-error`.

For a slider-crank unit (kind ``slider-crank``): the exact piston acceleration and
inertia force against the sinusoidal law, the first approximation and further terms
of the series; or the friction caused by the redundant supports of its stepped slider.
For a beam unit: the polished rod against the elementary, refined and arc-as-chord laws.
"""

from __future__ import annotations

import numpy as np

from ..core.beam.inertia_laws import beam_inertia_laws
from ..core.sampling import crank_grid, signed_extremes, uniform_time
from ..core.slider_crank.mechanism import (InertiaComparison, inertia_force, slider_inertia_laws,
                                           travel_from_outer_dead_centre)
from ..core.slider_crank.support_friction import (reduction_coefficients, redundant_support_friction,
                                                  solid_round_second_moment)
from ..errors import PumpjackError
from ..quantities import parse_quantity
from ..results import Column, Panel, Result, Scalar
from .inputs import crank_speed

#: Law names in output columns and what they are.
SLIDER_LAWS = {
    "harmonic": "sinusoidal law, [InertiaUNB600A] eq. 3",
    "two_term": "first approximation cos phi + lambda cos 2phi, [InertiaUNB600A] eq. 4",
    "series4": "trigonometric series to the 4th harmonic",
    "series6": "trigonometric series to the 6th harmonic",
}
BEAM_LAWS = {
    "harmonic": "elementary theory (harmonic)",
    "two_term": "refined theory (two-term)",
    "chord": "horsehead arc taken as its chord, [InertiaUNB600A] eq. 7",
}


def _comparison(title: str, c: InertiaComparison, omega: float, mass: float | None, laws: dict[str, str],
                extra: tuple[Scalar, ...] = ()) -> Result:
    """A law comparison: accelerations always, inertia forces -m a when a mass is known."""
    summary = [
        Scalar("crank_speed", "angular_velocity", omega, "crank angular velocity omega"),
        Scalar("strokes_per_minute", "stroke_rate", omega, "double strokes (crank revolutions) per minute"),
        Scalar("stroke", "length", c.stroke, "stroke, exact"),
        *extra,
        Scalar("peak_acceleration", "acceleration", c.peak, "max |a| over the cycle, exact"),
        Scalar("peak_crank_angle", "angle", c.peak_crank_angle, "crank angle of the exact max |a|"),
    ]
    if mass is not None:
        summary.append(Scalar("peak_inertia_force", "force", abs(inertia_force(mass, c.peak)),
                              "max |Phi| = m max |a|, exact"))
    for name, error in c.errors.items():
        law = laws[name]
        summary += [
            Scalar(f"{name}_peak_acceleration", "acceleration", error.peak, f"{law}: max |a|"),
            *([Scalar(f"{name}_peak_inertia_force", "force", abs(inertia_force(mass, error.peak)), f"{law}: max |Phi|")]
              if mass is not None else []),
            Scalar(f"{name}_peak_error", "percent", error.peak_error,
                   f"{law}: |1 - max|Phi| / exact max|Phi|| ([InertiaUNB600A] delta)"),
            Scalar(f"{name}_peak_error_of_law", "percent", error.peak_error_of_law,
                   f"{law}: |1 - exact max|Phi| / max|Phi||"),
            Scalar(f"{name}_max_deviation", "percent", error.max_deviation,
                   f"{law}: max |Phi - exact Phi| / exact max|Phi|"),
            Scalar(f"{name}_rms_deviation", "percent", error.rms_deviation,
                   f"{law}: rms(Phi - exact Phi) / rms(exact Phi)"),
        ]
    columns = [
        Column("crank_angle", "angle", "crank angle", c.crank_angle),
        Column("time", "time", "time from crank angle 0", uniform_time(c.crank_angle, omega)),
        Column("position", "length", "from the inner dead centre (slider) or the bottom (polished rod), exact",
               c.position),
        Column("velocity", "velocity", "velocity along the same axis, exact", c.velocity),
        Column("acceleration", "acceleration", "acceleration along the same axis, exact", c.acceleration),
    ]
    if mass is not None:
        columns.append(Column("inertia_force", "force", "inertia force -m a, exact", inertia_force(mass, c.acceleration)))
    for name, values in c.laws.items():
        columns += [
            Column(f"acceleration_{name}", "acceleration", f"acceleration, {laws[name]}", values),
            Column(f"deviation_{name}", "acceleration", f"acceleration of the law minus exact, {laws[name]}",
                   values - c.acceleration),
        ]
        if mass is not None:
            columns.append(Column(f"inertia_force_{name}", "force", f"inertia force -m a, {laws[name]}",
                                  inertia_force(mass, values)))
    names = tuple(c.laws)
    panels = [
        Panel("acceleration", ("acceleration",), tuple(f"acceleration_{n}" for n in names)),
        Panel("law - exact", tuple(f"deviation_{n}" for n in names)),
    ]
    if mass is not None:
        panels.insert(1, Panel("inertia force", ("inertia_force",), tuple(f"inertia_force_{n}" for n in names)))
    return Result(title, tuple(summary), tuple(columns), tuple(panels))


def support_friction(unit, steps: int) -> Result:
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
        Scalar("slider_length", "length", slider.length, "L: clamped end A to guide B"),
        *(Scalar(f"alpha_{i}", "ratio", alpha, f"alpha_{i} = J_{i} / J_0, J_0 the smallest section")
          for i, alpha in enumerate(reduction_coefficients(second_moments), start=1)),
        Scalar("guide_friction_outer_dead_centre", "force", at_dead.guide_friction[0],
               "F = f (|R'| + |R''|) in guide B at the outer dead centre"),
        Scalar("guide_friction_inner_dead_centre", "force", at_dead.guide_friction[1],
               "F in guide B at the inner dead centre"),
        Scalar("total_friction_outer_dead_centre", "force", at_dead.total_friction[0],
               "guide B and intermediate support, outer dead centre"),
        Scalar("total_friction_inner_dead_centre", "force", at_dead.total_friction[1],
               "guide B and intermediate support, inner dead centre"),
    ]
    for label, extreme in zip(("max", "min"), signed_extremes(theta, result.guide_friction)):
        summary += [
            Scalar(f"{label}_guide_friction", "force", extreme.value, f"{label} F in guide B over the cycle"),
            Scalar(f"{label}_guide_friction_crank_angle", "angle", extreme.crank_angle, f"crank angle of the {label} F"),
        ]
    columns = [
        Column("crank_angle", "angle", "crank angle from the line of stroke", theta),
        Column("travel", "length", "s: slider travel from the outer dead centre towards the crank", travel),
        Column("guide_force", "force", "R_B: force of guide B on the slider, up positive", result.force),
        Column("guide_moment", "torque", "M_B: moment of guide B on the slider, counterclockwise positive",
               result.moment),
        Column("outer_edge_reaction", "force", "R': reaction at the outer edge of guide B", result.outer_edge),
        Column("inner_edge_reaction", "force", "R'': reaction at the inner edge of guide B", result.inner_edge),
        Column("guide_friction", "force", "F = f (|R'| + |R''|), friction in guide B", result.guide_friction),
    ]
    reaction_curves, friction_curves = ("outer_edge_reaction", "inner_edge_reaction"), ("guide_friction",)
    if support is not None:
        columns += [
            Column("support_position", "length", "z_C: intermediate support from the clamped end A",
                   support.position - travel),
            Column("support_reaction", "force", "Y_C: force of the intermediate support on the slider",
                   result.intermediate),
            Column("support_friction", "force", "f |Y_C|, friction at the intermediate support",
                   result.intermediate_friction),
            Column("total_friction", "force", "friction in guide B and at the intermediate support",
                   result.total_friction),
        ]
        reaction_curves += ("support_reaction",)
        friction_curves += ("total_friction",)
    return Result(f"{unit.name}: friction from redundant supports of the stepped slider", tuple(summary),
                  tuple(columns),
                  (Panel("friction", friction_curves), Panel("reactions", reaction_curves), Panel("travel", ("travel",))))


def inertia_error(unit, spm: float | None, mass: float | None, support: bool, steps: int) -> Result:
    """The comparison (or, with ``support``, the stepped slider's support friction) for a unit of any kind."""
    if mass is not None and not mass > 0:
        raise PumpjackError(f"--mass must be positive, got {mass} kg")
    if unit.kind == "slider-crank":
        omega = parse_quantity(f"{spm} rpm", "rotational_speed") if spm is not None else unit.reciprocating.crank_speed
        if support:
            return support_friction(unit, steps)
        mechanism = unit.geometry.slider_crank()
        return _comparison(
            f"{unit.name}: inertia force, exact and approximate laws",
            slider_inertia_laws(mechanism, omega, crank_grid(steps)), omega,
            unit.reciprocating.mass if mass is None else mass, SLIDER_LAWS,
            (Scalar("crank_to_rod_ratio", "ratio", mechanism.crank_ratio, "lambda = r / l2"),
             Scalar("offset", "length", unit.geometry.offset, "e: line of stroke above the crank shaft")),
        )
    if support:
        raise PumpjackError(f"unit {unit.name} is a beam pumping unit: --support-friction needs a slider-crank unit")
    omega = crank_speed(unit, spm)
    return _comparison(f"{unit.name}: polished-rod inertia, exact and approximate laws",
                       beam_inertia_laws(unit.geometry.linkage(), omega, crank_grid(steps)), omega, mass, BEAM_LAWS)
