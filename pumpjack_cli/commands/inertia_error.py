"""`pumpjack inertia-error`: accuracy of the approximate inertia-force laws (seed 001).

For a slider-crank unit (kind = "slider-crank", e.g. ``unb-600a``): the exact piston
acceleration and inertia force against the sinusoidal law, the first approximation and
further terms of the trigonometric series; with ``--support-friction`` instead the
friction in the crosshead guide caused by redundant supports of the stepped slider.
For a beam pumping unit: the exact polished-rod acceleration against the elementary,
refined and arc-as-chord laws. Definitions: ``docs/inertia-error.md``.
"""

from __future__ import annotations

from typing import Annotated

import numpy as np
import typer

from ..config import SliderCrankConfig, UnitConfig, load_any_unit
from ..core.beam.inertia_laws import beam_inertia_laws
from ..core.sampling import crank_grid
from ..core.slider_crank.geometry import dead_centres
from ..core.slider_crank.mechanism import InertiaComparison, exact_motion, slider_inertia_laws
from ..core.slider_crank.support_friction import SupportReactions, reduction_coefficients, redundant_support_friction
from ..errors import PumpjackError
from ..render import Column, Panel, Report, Scalar
from ..units import parse_quantity
from .common import FormatOption, OutputOption, PlotOption, UnitArgument, UnitsOption, output
from .kinematics import crank_speed

#: Law names in output columns and what they are.
SLIDER_LAWS = {
    "harmonic": "sinusoidal law, seed 001 eq. 3",
    "two_term": "first approximation cos phi + lambda cos 2phi, seed 001 eq. 4",
    "series4": "trigonometric series to the 4th harmonic",
    "series6": "trigonometric series to the 6th harmonic",
}
BEAM_LAWS = {
    "harmonic": "elementary theory (harmonic)",
    "two_term": "refined theory (two-term)",
    "chord": "horsehead arc taken as its chord, seed 001 eq. 7",
}


def inertia_report(title: str, comparison: InertiaComparison, omega: float, mass: float | None,
                   laws: dict[str, str], extra: tuple[Scalar, ...] = ()) -> Report:
    """Tabulate a law comparison: accelerations always, inertia forces -m a when a mass is known."""
    c = comparison
    summary = [
        Scalar("crank_speed", "angular_velocity", omega, "crank angular velocity omega"),
        Scalar("strokes_per_minute", "stroke_rate", omega, "double strokes (crank revolutions) per minute"),
        Scalar("stroke", "length", c.stroke, "stroke, exact"),
        *extra,
        Scalar("peak_acceleration", "acceleration", c.peak, "max |a| over the cycle, exact"),
        Scalar("peak_crank_angle", "angle", c.peak_crank_angle, "crank angle of the exact max |a|"),
    ]
    if mass is not None:
        summary.append(Scalar("peak_inertia_force", "force", mass * c.peak, "max |Phi| = m max |a|, exact"))
    for name, error in c.errors.items():
        law = laws[name]
        summary += [
            Scalar(f"{name}_peak_acceleration", "acceleration", error.peak, f"{law}: max |a|"),
            *([Scalar(f"{name}_peak_inertia_force", "force", mass * error.peak, f"{law}: max |Phi|")]
              if mass is not None else []),
            Scalar(f"{name}_peak_error", "percent", error.peak_error,
                   f"{law}: |1 - max|Phi| / exact max|Phi|| (seed 001 delta)"),
            Scalar(f"{name}_peak_error_of_law", "percent", error.peak_error_of_law,
                   f"{law}: |1 - exact max|Phi| / max|Phi||"),
            Scalar(f"{name}_max_deviation", "percent", error.max_deviation,
                   f"{law}: max |Phi - exact Phi| / exact max|Phi|"),
            Scalar(f"{name}_rms_deviation", "percent", error.rms_deviation,
                   f"{law}: rms(Phi - exact Phi) / rms(exact Phi)"),
        ]
    columns = [
        Column("crank_angle", "angle", "crank angle"),
        Column("time", "time", "time from crank angle 0"),
        Column("position", "length", "from the inner dead centre (slider) or the bottom (polished rod), exact"),
        Column("velocity", "velocity", "velocity along the same axis, exact"),
        Column("acceleration", "acceleration", "acceleration along the same axis, exact"),
    ]
    series = {
        "crank_angle": c.crank_angle,
        "time": c.crank_angle / omega,
        "position": c.position,
        "velocity": c.velocity,
        "acceleration": c.acceleration,
    }
    if mass is not None:
        columns.append(Column("inertia_force", "force", "inertia force -m a, exact"))
        series["inertia_force"] = -mass * c.acceleration
    for name, values in c.laws.items():
        columns += [
            Column(f"acceleration_{name}", "acceleration", f"acceleration, {laws[name]}", brief=False),
            Column(f"deviation_{name}", "acceleration", f"acceleration of the law minus exact, {laws[name]}", brief=False),
        ]
        series[f"acceleration_{name}"] = values
        series[f"deviation_{name}"] = values - c.acceleration
        if mass is not None:
            columns.append(Column(f"inertia_force_{name}", "force", f"inertia force -m a, {laws[name]}", brief=False))
            series[f"inertia_force_{name}"] = -mass * values
    names = tuple(c.laws)
    panels = [
        Panel("acceleration", ("acceleration",), tuple(f"acceleration_{n}" for n in names)),
        Panel("law - exact", tuple(f"deviation_{n}" for n in names)),
    ]
    if mass is not None:
        panels.insert(1, Panel("inertia force", ("inertia_force",), tuple(f"inertia_force_{n}" for n in names)))
    return Report(title=title, summary=tuple(summary), columns=tuple(columns), series=series, panels=tuple(panels))


def support_friction_report(config: SliderCrankConfig, omega: float, steps: int) -> Report:
    """Reactions and friction of the redundant supports of the stepped slider over one revolution."""
    slider = config.stepped_slider
    if slider is None:
        raise PumpjackError(f"unit {config.name} has no [stepped_slider] section: --support-friction needs one")
    mechanism = config.geometry.slider_crank()
    dead = dead_centres(mechanism)
    theta = crank_grid(steps)
    support = slider.intermediate_support
    second_moments = [section.second_moment for section in slider.sections]

    def reactions(travel: np.ndarray) -> SupportReactions:
        return redundant_support_friction(
            [section.length for section in slider.sections], second_moments, slider.elastic_modulus,
            slider.guide_length, slider.friction_coefficient, slider.settlement, slider.turn, travel,
            support.position if support else None, support.offset if support else 0.0,
        )

    travel = dead.position_outer - exact_motion(mechanism, theta, omega).position
    result = reactions(travel)
    at_dead = reactions(np.array([0.0, config.stroke()]))
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
    for label, index in (("max", int(np.argmax(result.guide_friction))), ("min", int(np.argmin(result.guide_friction)))):
        summary += [
            Scalar(f"{label}_guide_friction", "force", result.guide_friction[index], f"{label} F in guide B over the cycle"),
            Scalar(f"{label}_guide_friction_crank_angle", "angle", theta[index], f"crank angle of the {label} F"),
        ]
    columns = [
        Column("crank_angle", "angle", "crank angle from the line of stroke"),
        Column("travel", "length", "s: slider travel from the outer dead centre towards the crank"),
        Column("guide_force", "force", "R_B: force of guide B on the slider, up positive", brief=False),
        Column("guide_moment", "torque", "M_B: moment of guide B on the slider, counterclockwise positive", brief=False),
        Column("outer_edge_reaction", "force", "R': reaction at the outer edge of guide B"),
        Column("inner_edge_reaction", "force", "R'': reaction at the inner edge of guide B"),
        Column("guide_friction", "force", "F = f (|R'| + |R''|), friction in guide B"),
    ]
    series = {
        "crank_angle": theta,
        "travel": travel,
        "guide_force": result.force,
        "guide_moment": result.moment,
        "outer_edge_reaction": result.outer_edge,
        "inner_edge_reaction": result.inner_edge,
        "guide_friction": result.guide_friction,
    }
    reaction_curves = ("outer_edge_reaction", "inner_edge_reaction")
    friction_curves = ("guide_friction",)
    if support is not None:
        columns += [
            Column("support_position", "length", "z_C: intermediate support from the clamped end A", brief=False),
            Column("support_reaction", "force", "Y_C: force of the intermediate support on the slider"),
            Column("support_friction", "force", "f |Y_C|, friction at the intermediate support", brief=False),
            Column("total_friction", "force", "friction in guide B and at the intermediate support"),
        ]
        series |= {
            "support_position": support.position - travel,
            "support_reaction": result.intermediate,
            "support_friction": result.intermediate_friction,
            "total_friction": result.total_friction,
        }
        reaction_curves += ("support_reaction",)
        friction_curves += ("total_friction",)
    return Report(
        title=f"{config.name}: friction from redundant supports of the stepped slider",
        summary=tuple(summary),
        columns=tuple(columns),
        series=series,
        panels=(Panel("friction", friction_curves), Panel("reactions", reaction_curves), Panel("travel", ("travel",))),
    )


def inertia_error(
    unit: UnitArgument,
    spm: Annotated[float | None, typer.Option(
        "--spm", "--rpm", min=0.1, max=1000,
        help="crank speed, revolutions (double strokes) per minute [default: slider-crank: from its file; "
             "beam unit: from motor and drive]",
    )] = None,
    mass: Annotated[float | None, typer.Option(
        help="reciprocating (suspended) mass in kg for the inertia forces [default: slider-crank: from its file; "
             "beam unit: none, accelerations only]",
    )] = None,
    support_friction: Annotated[bool, typer.Option(
        "--support-friction",
        help="slider-crank only: friction in the crosshead guide from the redundant supports of the stepped slider",
    )] = False,
    steps: Annotated[int, typer.Option(help="crank positions per revolution", min=4, max=10_000_000)] = 360,
    fmt: FormatOption = None,
    units: UnitsOption = "si",
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Error of the approximate inertia-force laws against the exact motion (seed 001).

    Errors at the peak and over the cycle, for slider-crank and beam pumping units."""
    if mass is not None and not mass > 0:
        raise PumpjackError(f"--mass must be positive, got {mass} kg")
    config = load_any_unit(unit)
    if isinstance(config, SliderCrankConfig):
        omega = parse_quantity(f"{spm} rpm", "rotational_speed") if spm is not None else config.reciprocating.crank_speed
        if support_friction:
            report = support_friction_report(config, omega, steps)
        else:
            mechanism = config.geometry.slider_crank()
            report = inertia_report(
                f"{config.name}: inertia force, exact and approximate laws",
                slider_inertia_laws(mechanism, omega, crank_grid(steps)), omega,
                config.reciprocating.mass if mass is None else mass, SLIDER_LAWS,
                (Scalar("crank_to_rod_ratio", "ratio", mechanism.crank_ratio, "lambda = r / l2"),
                 Scalar("offset", "length", config.geometry.offset, "e: line of stroke above the crank shaft")),
            )
    elif isinstance(config, UnitConfig):
        if support_friction:
            raise PumpjackError(f"unit {config.name} is a beam pumping unit: --support-friction needs a slider-crank unit")
        omega = crank_speed(config, spm)
        report = inertia_report(
            f"{config.name}: polished-rod inertia, exact and approximate laws",
            beam_inertia_laws(config.geometry.linkage(), omega, crank_grid(steps)), omega, mass, BEAM_LAWS,
        )
    else:
        raise PumpjackError(f"unit {config.name}: inertia-error does not handle {config.kind} machines")
    output(report, fmt, units, out, plot)
