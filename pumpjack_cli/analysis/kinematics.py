"""Kinematics of a beam unit for uniform crank rotation: the result table of `pumpjack kinematics`."""

from __future__ import annotations

from ..core.beam.kinematics import APPROXIMATIONS, uniform_kinematics
from ..results import Column, Panel, Result, Scalar
from .inputs import crank_speed

#: Approximation names in output columns and their descriptions ([Aliverdizade1951], [NUNG]).
APPROXIMATION_LABELS = {"harmonic": "elementary theory (harmonic)", "two_term": "refined theory (two-term)"}
#: Summary extremes: name, quantity kind, what.
_EXTREMES = (("velocity", "velocity"), ("acceleration", "acceleration"), ("torque_factor", "length"))


def kinematics(unit, spm: float | None, steps: int) -> Result:
    """Exact polished-rod, beam and pitman kinematics with the textbook approximations beside it."""
    result = uniform_kinematics(unit.geometry.linkage(), crank_speed(unit, spm), steps)
    s = result.summary
    summary = [
        Scalar("crank_speed", "angular_velocity", s.crank_speed, "crank angular velocity omega1"),
        Scalar("strokes_per_minute", "stroke_rate", s.crank_speed, "pumping speed N"),
        Scalar("period", "time", s.period, "time of one stroke cycle"),
        Scalar("stroke", "length", s.stroke, "polished-rod stroke, exact"),
        Scalar("crank_angle_bottom", "angle", s.crank_angle_bottom, "crank angle at the bottom of the stroke"),
        Scalar("crank_angle_top", "angle", s.crank_angle_top, "crank angle at the top of the stroke"),
        Scalar("upstroke_crank_travel", "angle", s.upstroke_crank_travel, "crank rotation during the upstroke"),
        Scalar("downstroke_crank_travel", "angle", s.downstroke_crank_travel, "crank rotation during the downstroke"),
    ]
    for quantity, kind in _EXTREMES:
        for label in ("max", "min"):
            extreme = getattr(s, f"{label}_{quantity}")
            what = f"{label} {quantity.replace('_', ' ')}"
            summary.append(Scalar(f"{label}_{quantity}", kind, extreme.value, f"{what} of the polished rod"))
            summary.append(Scalar(f"{label}_{quantity}_crank_angle", "angle", extreme.crank_angle,
                                  f"crank angle of the {what}"))
    for name, error in s.approximation_errors.items():
        law = APPROXIMATION_LABELS[name]
        summary += [
            Scalar(f"{name}_position_error", "percent", error.position, f"{law}: max |ds| / stroke"),
            Scalar(f"{name}_velocity_error", "percent", error.velocity, f"{law}: max |dv| / max |v|"),
            Scalar(f"{name}_acceleration_error", "percent", error.acceleration, f"{law}: max |da| / max |a|"),
            Scalar(f"{name}_peak_acceleration_error", "percent", error.peak_acceleration,
                   f"{law}: max |a| of the law / exact max |a| - 1"),
        ]
    columns = [
        Column("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation", result.crank_angle),
        Column("time", "time", "time from crank angle 0", result.time),
        Column("position", "length", "polished-rod position above the bottom of the stroke", result.rod.position),
        Column("velocity", "velocity", "polished-rod velocity, up positive", result.rod.velocity),
        Column("acceleration", "acceleration", "polished-rod acceleration, up positive", result.rod.acceleration),
        Column("torque_factor", "length", "API 11E torque factor = d(position)/d(crank angle)", result.torque_factor),
        Column("beam_angle", "angle", "front arm above horizontal", result.beam_angle),
        Column("beam_angular_velocity", "angular_velocity", "beam angular velocity, front arm up positive",
               result.beam_angular_velocity),
        Column("beam_angular_acceleration", "angular_acceleration", "beam angular acceleration",
               result.beam_angular_acceleration),
        Column("pitman_angle", "angle", "direction of crank pin -> equalizer bearing above horizontal",
               result.pitman_angle),
        Column("pitman_angular_velocity", "angular_velocity", "pitman angular velocity, counterclockwise positive",
               result.pitman_angular_velocity),
        Column("pitman_angular_acceleration", "angular_acceleration", "pitman angular acceleration",
               result.pitman_angular_acceleration),
    ]
    for name, motion in result.approximations.items():
        law = APPROXIMATION_LABELS[name]
        for quantity, kind in (("position", "length"), ("velocity", "velocity"), ("acceleration", "acceleration")):
            columns.append(Column(f"{quantity}_{name}", kind, f"polished-rod {quantity}, {law}", getattr(motion, quantity)))
    panels = tuple(
        Panel(quantity.replace("_", " "), (quantity,), tuple(f"{quantity}_{name}" for name in APPROXIMATIONS))
        for quantity in ("position", "velocity", "acceleration")
    ) + (Panel("torque factor", ("torque_factor",)),)
    return Result(f"{unit.name}: kinematics, uniform rotation", tuple(summary), tuple(columns), panels)
