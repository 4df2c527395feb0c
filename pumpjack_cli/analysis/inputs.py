"""Result pieces shared by the analyses: the crank-motion columns and the summary of extremes.

The core's objects of a unit (mechanism, masses, rods, pump, machine) are built by its
config (:class:`~pumpjack_cli.config.beam_unit.UnitConfig`); the dynamometer card on a
crank-angle grid is :mod:`.card_runs`.
"""

from __future__ import annotations

from ..results import Column, Scalar


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

