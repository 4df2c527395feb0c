"""From a validated unit and the options to the core's inputs, decided once for every analysis.

The crank speed (``--spm``, or the motor's rated speed through belt and gearbox) and
the sections a unit must have: every command that needs one of these gets it here.
The dynamometer card on a crank-angle grid is :mod:`.card_runs`; the machine of the
equation of motion, the well load and the masses are :mod:`.machine`.
"""

from __future__ import annotations

from ..errors import PumpjackError
from ..quantities import parse_quantity
from ..results import Column, Scalar


def require(unit, section: str, purpose: str) -> None:
    """Refuse a unit without the config section an analysis needs, saying what it is needed for."""
    if getattr(unit, section) is None:
        raise PumpjackError(f"unit {unit.name} has no [{section}] section; {purpose}")


def crank_speed(unit, spm: float | None) -> float:
    """Crank speed [1/s]: from ``--spm`` (strokes per minute) if given, else the motor's rated speed through the drive."""
    if spm is not None:
        return parse_quantity(f"{spm} spm", "rotational_speed")
    if unit.drive is None:
        raise PumpjackError(f"unit {unit.name} has no [drive] section: give the speed with --spm")
    return unit.drive.rated_crank_speed


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

