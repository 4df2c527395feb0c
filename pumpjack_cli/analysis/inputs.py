"""Result pieces shared by the analyses: the crank-motion columns and the summary of extremes.

The core's objects of a unit (mechanism, masses, rods, pump, machine) are built by its
config (:class:`~pumpjack_cli.config.beam_unit.UnitConfig`); the dynamometer card on a
crank-angle grid is :mod:`.card_runs`.
"""

from __future__ import annotations

from ..results import Column, Mark, Scalar


def crank_columns(crank_angle, time, speed, acceleration) -> list[Column]:
    """The crank's motion at each row: angle [rad], time [s], speed [1/s] and acceleration [1/s²],
    the first columns of every per-angle table."""
    return [
        Column("crank_angle", crank_angle),
        Column("time", time),
        Column("crank_speed", speed),
        Column("crank_acceleration", acceleration),
    ]


def extreme_scalars(rows) -> list[Scalar]:
    """Summary values of extremes and where they occur: for each (name, extreme with
    ``value`` and ``crank_angle`` [rad]), ``name`` and ``name_crank_angle``."""
    found = []
    for name, extreme in rows:
        found += [Scalar(name, extreme.value),
                  Scalar(f"{name}_crank_angle", extreme.crank_angle)]
    return found


def dead_position_marks(mechanism) -> tuple[Mark, ...]:
    """The dead positions of a unit as plot marks: their crank angles on panels against the
    crank angle, the ends of the stroke (0 and S) on panels against the polished-rod position."""
    dead = mechanism.dead_positions()
    return (Mark("bottom dead position", "crank_angle", dead.crank_angle_bottom),
            Mark("top dead position", "crank_angle", dead.crank_angle_top),
            Mark("bottom dead position", "position", 0.0),
            Mark("top dead position", "position", dead.stroke))


def motor_levels(motor) -> tuple[tuple[str, float], ...]:
    """The motor's rated and pull-out (breakdown) torques [N·m] at its shaft as the lines of a
    motor-torque panel (:class:`~pumpjack_cli.core.dynamics.drive.MotorCharacteristic`)."""
    return (("rated motor torque", motor.rated_torque), ("pull-out torque", motor.breakdown_torque))


def dead_centre_marks(mechanism) -> tuple[Mark, ...]:
    """The dead centres of a slider-crank machine as plot marks against the crank angle."""
    dead = mechanism.dead_positions()
    return (Mark("outer dead centre", "crank_angle", dead.crank_angle_outer),
            Mark("inner dead centre", "crank_angle", dead.crank_angle_inner))
