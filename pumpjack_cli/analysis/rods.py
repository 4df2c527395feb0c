"""The well of a unit as the rod-string models need it: the tapered string, the pump and its pressures.

Rod sections come from the unit's ``[well]`` (by length or by share of the pump depth);
their weight with couplings and modulus from the API tables by diameter unless given
([API11L], [API11B]); steel displaces the fluid with the well's ``rod_density``, as in
the rigid-rod well model. A section whose diameter is an API rod size is a steel rod, any
other a sinker bar, unless its ``kind`` says otherwise.
"""

from __future__ import annotations

import math

from ..core.constants import STANDARD_GRAVITY
from ..core.rods.pump import Pump, pump_pressures, tubing_stiffness
from ..core.rods.string import RodString
from ..core.rods.tables import RodSection, rod_string, steel_rod
from ..errors import DownholeError, PumpjackError
from .inputs import require


def well_of(unit):
    """The unit's ``[well]``, required."""
    require(unit, "well", "the rod-string models need the pump depth, the plunger and the rod string")
    return unit.well


def _kind(section) -> str:
    if section.kind is not None:
        return section.kind
    try:
        steel_rod(section.diameter)
    except DownholeError:
        return "sinker"
    return "steel"


def rods(unit) -> RodString:
    """The tapered rod string of the unit's ``[well]``, top section first."""
    well = well_of(unit)
    sections = []
    for section in well.rod_string:
        length = section.length if section.length is not None else section.fraction * well.pump_depth
        mass = None if section.weight_per_length is None else section.weight_per_length / STANDARD_GRAVITY
        kind = _kind(section)
        sections.append(RodSection(section.diameter, length, kind=kind, grade=section.grade,
                                   youngs_modulus=section.youngs_modulus, mass_per_length=mass,
                                   tensile_strength=section.tensile_strength,
                                   material_density=None if kind == "fibreglass" else well.rod_density))
    try:
        return rod_string(sections)
    except DownholeError as exc:
        raise PumpjackError(f"unit {unit.name}: well.rod_string: {exc}") from None


def pressures(unit) -> tuple[float, float] | None:
    """Discharge and intake pressure at the pump [Pa], or None when the well gives neither its
    fluid level (pump submergence) nor its intake pressure."""
    well = well_of(unit)
    if well.pump_submergence is None and well.pump_intake_pressure is None:
        return None
    return pump_pressures(well.pump_depth, well.fluid_density, submergence=well.pump_submergence,
                          intake_pressure=well.pump_intake_pressure, tubing_head_pressure=well.tubing_head_pressure,
                          casing_head_pressure=well.casing_head_pressure)


def pump(unit) -> Pump:
    """The pump of the unit's ``[well]`` with its valves' pressures, fillage, gas and tubing."""
    well = well_of(unit)
    found = pressures(unit)
    if found is None:
        raise PumpjackError(f"unit {unit.name}: the well needs pump_submergence (fluid level above the pump) or "
                            f"pump_intake_pressure for the pump's valves")
    stiffness = math.inf
    if not well.tubing_anchored:
        if well.tubing_size is None:
            raise PumpjackError(f"unit {unit.name}: well.tubing_size is needed for an unanchored tubing's stretch")
        stiffness = tubing_stiffness(well.tubing_size, well.pump_depth)
    return Pump(math.pi * well.plunger_diameter**2 / 4.0, found[0], found[1], fillage=well.pump_fillage,
                gas_exponent=well.gas_exponent, tubing_stiffness=stiffness)
