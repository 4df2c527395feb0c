"""The well of a unit as the rod-string models need it: the tapered string, the pump and its pressures.

Rod sections come from the unit's ``[well]`` (by length or by share of the pump depth);
their weight with couplings and modulus from the API tables by diameter unless given
([API11L], [API11B]); steel displaces the fluid with the well's ``rod_density``, as in
the rigid-rod well model. A section whose diameter is an API rod size is a steel rod, any
other a sinker bar, unless its ``kind`` says otherwise.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.constants import STANDARD_GRAVITY
from ..core.rods.pump import Pump, pump_pressures, tubing_stiffness
from ..core.rods.string import RodString
from ..core.rods.tables import RodSection, rod_string, steel_rod
from ..core.rods.analysis import goodman_allowable_stress, goodman_loading
from ..errors import DownholeError, PumpjackError, warn
from ..results import Curve, Panel, Scalar
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


def taper_summary(string, loads, service_factor: float) -> list[Scalar]:
    """Per taper (top first): extreme stresses at its ends and its Goodman loading ([API11BR])."""
    found = []
    graded = not np.isnan(string.tensile_strength).any()
    if not graded:
        warn("a rod section has no grade or tensile_strength: the Goodman loading is left out")
    goodman = goodman_loading(string, loads, service_factor) if graded else np.full(len(string.length), np.nan)
    for i in range(1, len(string.length) + 1):
        for end in ("top", "bottom"):
            for label in ("max", "min"):
                found.append(Scalar(f"taper_{i}_{end}_{label}_stress",
                                    float(getattr(loads, f"{end}_{label}_stress")[i - 1])))
        if math.isfinite(float(goodman[i - 1])):
            found.append(Scalar(f"taper_{i}_goodman_loading", float(goodman[i - 1])))
    return found


def goodman_panel(string, loads, service_factor: float) -> Panel:
    """The modified Goodman diagram ([API11BR]): the (S_min, S_max) of each taper's top and
    bottom, the allowable line of each grade and the line S_max = S_min below which no
    point can lie."""
    curves = []
    for i in range(len(string.length)):
        for end, marker in (("top", "o"), ("bottom", "s")):
            low, high = float(getattr(loads, f"{end}_min_stress")[i]), float(getattr(loads, f"{end}_max_stress")[i])
            curves.append(Curve(f"taper {i + 1} {end}", (low,), (high,), quantity="stress", style=marker))
    strengths = sorted({float(t) for t in string.tensile_strength if math.isfinite(float(t))})
    for strength in strengths:
        span = np.array([0.0, strength / 2.0])
        allowable = goodman_allowable_stress(strength, span, service_factor)
        curves.append(Curve(f"allowable S_A, T = {strength / 1e6:.0f} MPa", tuple(span), tuple(allowable),
                            quantity="stress", style="--"))
    if strengths:
        span = (0.0, strengths[-1] / 2.0)
        curves.append(Curve("S_max = S_min", span, span, quantity="stress", style=":"))
    return Panel("max stress", (), curves=tuple(curves), x_label="min stress (modified Goodman diagram)")
