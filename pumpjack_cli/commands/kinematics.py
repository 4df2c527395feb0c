"""`pumpjack kinematics`: exact polished-rod and link kinematics for uniform crank rotation."""

from __future__ import annotations

from typing import Annotated

import typer

from ..config import UnitConfig, load_unit
from ..core.beam.kinematics import KinematicsResult, uniform_kinematics
from ..errors import PumpjackError
from ..render import Column, Panel, Report, Scalar
from ..units import parse_quantity
from .common import FormatOption, OutputOption, PlotOption, UnitArgument, UnitsOption, output

#: Approximation names in output columns and their descriptions.
APPROXIMATION_LABELS = {"harmonic": "elementary theory (harmonic)", "two_term": "refined theory (two-term)"}


def crank_speed(config: UnitConfig, spm: float | None) -> float:
    """Crank speed [1/s]: from ``--spm`` if given, else the motor's rated speed through the drive."""
    if spm is not None:
        return parse_quantity(f"{spm} spm", "rotational_speed")
    if config.drive is None:
        raise PumpjackError(f"unit {config.name} has no [drive] section: give the speed with --spm")
    return config.drive.rated_crank_speed


def kinematics_report(config: UnitConfig, result: KinematicsResult) -> Report:
    """Tabulate a kinematics result: which series and summary values, with units and meaning."""
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
    for label, extreme, quantity in (
        ("max_velocity", s.max_velocity, "velocity"),
        ("min_velocity", s.min_velocity, "velocity"),
        ("max_acceleration", s.max_acceleration, "acceleration"),
        ("min_acceleration", s.min_acceleration, "acceleration"),
        ("max_torque_factor", s.max_torque_factor, "length"),
        ("min_torque_factor", s.min_torque_factor, "length"),
    ):
        what = label.replace("_", " ", 1).replace("_", " ")
        summary.append(Scalar(label, quantity, extreme.value, f"{what} of the polished rod"))
        summary.append(Scalar(f"{label}_crank_angle", "angle", extreme.crank_angle, f"crank angle of the {what}"))
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
        Column("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation"),
        Column("time", "time", "time from crank angle 0"),
        Column("position", "length", "polished-rod position above the bottom of the stroke"),
        Column("velocity", "velocity", "polished-rod velocity, up positive"),
        Column("acceleration", "acceleration", "polished-rod acceleration, up positive"),
        Column("torque_factor", "length", "API 11E torque factor = d(position)/d(crank angle)"),
        Column("beam_angle", "angle", "front arm above horizontal", brief=False),
        Column("beam_angular_velocity", "angular_velocity", "beam angular velocity, front arm up positive", brief=False),
        Column("beam_angular_acceleration", "angular_acceleration", "beam angular acceleration", brief=False),
        Column("pitman_angle", "angle", "direction of crank pin -> equalizer bearing above horizontal", brief=False),
        Column("pitman_angular_velocity", "angular_velocity", "pitman angular velocity, counterclockwise positive", brief=False),
        Column("pitman_angular_acceleration", "angular_acceleration", "pitman angular acceleration", brief=False),
    ]
    series = {
        "crank_angle": result.crank_angle,
        "time": result.time,
        "position": result.rod.position,
        "velocity": result.rod.velocity,
        "acceleration": result.rod.acceleration,
        "torque_factor": result.torque_factor,
        "beam_angle": result.beam_angle,
        "beam_angular_velocity": result.beam_angular_velocity,
        "beam_angular_acceleration": result.beam_angular_acceleration,
        "pitman_angle": result.pitman_angle,
        "pitman_angular_velocity": result.pitman_angular_velocity,
        "pitman_angular_acceleration": result.pitman_angular_acceleration,
    }
    for name, motion in result.approximations.items():
        law = APPROXIMATION_LABELS[name]
        for quantity, kind, values in (("position", "length", motion.position), ("velocity", "velocity", motion.velocity),
                                       ("acceleration", "acceleration", motion.acceleration)):
            columns.append(Column(f"{quantity}_{name}", kind, f"polished-rod {quantity}, {law}", brief=False))
            series[f"{quantity}_{name}"] = values
    approx = tuple(result.approximations)
    panels = tuple(
        Panel(quantity.replace("_", " "), (quantity,), tuple(f"{quantity}_{name}" for name in approx))
        for quantity in ("position", "velocity", "acceleration")
    ) + (Panel("torque factor", ("torque_factor",)),)
    return Report(
        title=f"{config.name}: kinematics, uniform rotation",
        summary=tuple(summary),
        columns=tuple(columns),
        series=series,
        panels=panels,
    )


def kinematics(
    unit: UnitArgument,
    spm: Annotated[float | None, typer.Option(help="pumping speed, strokes/min [default: from motor and drive]", min=0.1, max=60)] = None,
    steps: Annotated[int, typer.Option(help="crank positions per revolution", min=4, max=10_000_000)] = 360,
    fmt: FormatOption = None,
    units: UnitsOption = "si",
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Exact kinematics of the polished rod, beam and pitman for uniform crank rotation.

    The elementary and refined textbook approximations are printed beside it."""
    config = load_unit(unit)
    result = uniform_kinematics(config.geometry.linkage(), crank_speed(config, spm), steps)
    output(kinematics_report(config, result), fmt, units, out, plot)
