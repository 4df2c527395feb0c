"""Kinematics of a beam unit for uniform crank rotation: the result table of `pumpjack kinematics`."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..core.beam.kinematics import APPROXIMATIONS, uniform_kinematics
from ..results import Column, Panel, Result, Scalar
from .inputs import dead_position_marks

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: Quantities whose extremes the summary gives.
_EXTREMES = ("velocity", "acceleration", "torque_factor")


def kinematics(unit: UnitConfig, spm: float | None, steps: int) -> Result:
    """Exact polished-rod, beam and pitman kinematics with the textbook approximations beside it."""
    result = uniform_kinematics(unit.geometry.mechanism(), unit.crank_speed(spm), steps)
    s = result.summary
    summary = [
        Scalar("crank_speed", s.crank_speed),
        Scalar("strokes_per_minute", s.crank_speed),
        Scalar("period", s.period),
        Scalar("stroke", s.stroke),
        Scalar("crank_angle_bottom", s.crank_angle_bottom),
        Scalar("crank_angle_top", s.crank_angle_top),
        Scalar("upstroke_crank_travel", s.upstroke_crank_travel),
        Scalar("downstroke_crank_travel", s.downstroke_crank_travel),
    ]
    for quantity in _EXTREMES:
        for label in ("max", "min"):
            extreme = getattr(s, f"{label}_{quantity}")
            summary.append(Scalar(f"{label}_{quantity}", extreme.value))
            summary.append(Scalar(f"{label}_{quantity}_crank_angle", extreme.crank_angle))
    for name, error in s.approximation_errors.items():
        summary += [
            Scalar(f"{name}_position_error", error.position),
            Scalar(f"{name}_velocity_error", error.velocity),
            Scalar(f"{name}_acceleration_error", error.acceleration),
            Scalar(f"{name}_peak_acceleration_error", error.peak_acceleration),
        ]
    columns = [
        Column("crank_angle", result.crank_angle),
        Column("time", result.time),
        Column("position", result.rod.position),
        Column("velocity", result.rod.velocity),
        Column("acceleration", result.rod.acceleration),
        Column("torque_factor", result.torque_factor),
        Column("beam_angle", result.beam_angle),
        Column("beam_angular_velocity", result.beam_angular_velocity),
        Column("beam_angular_acceleration", result.beam_angular_acceleration),
        Column("pitman_angle", result.pitman_angle),
        Column("pitman_angular_velocity", result.pitman_angular_velocity),
        Column("pitman_angular_acceleration", result.pitman_angular_acceleration),
    ]
    for name, motion in result.approximations.items():
        for quantity in ("position", "velocity", "acceleration"):
            columns.append(Column(f"{quantity}_{name}", getattr(motion, quantity)))
    panels = tuple(
        Panel(quantity.replace("_", " "), (quantity,), tuple(f"{quantity}_{name}" for name in APPROXIMATIONS))
        for quantity in ("position", "velocity", "acceleration")
    ) + (Panel("torque factor", ("torque_factor",)),)
    return Result(f"{unit.name}: kinematics, uniform rotation", tuple(summary), tuple(columns), panels,
                  dead_position_marks(unit.geometry.mechanism()))
