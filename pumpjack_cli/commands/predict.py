"""`pumpjack predict`: surface and pump cards from the design, at uniform speed or coupled with the machine."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import typer

from ..analysis.deviated import profile_shown
from ..analysis.predict import DEFAULT_SAMPLES, Faults, WellOverrides
from ..analysis.predict import predict as run
from ..config import load_unit
from ..errors import PumpjackError
from ..options import (FormatOption, Output, OutputOption, PlotOption, ServiceFactorOption, SpmOption, UnitArgument, UnitsOption,
                       UnitSystem, finite, positive, quantity)
from ..options import What, WhatOption
from ..options import FrictionCoefficientOption, GuideLimitOption, ProfileOption, SurveyOption, deviation
from ..options import CatalogueOption

SHOWN = ("time", "position", "rod_load", "pump_position", "pump_load")


class CrankMotion(str, Enum):
    uniform = "uniform"
    dynamic = "dynamic"


def _well(help_text: str, **kwargs):
    return typer.Option(help=f"{help_text} [default: the unit's [well]]", **kwargs)


def _fault(help_text: str):
    return typer.Option(help=f"simulate {help_text} [default: a sound pump; uniform rotation only]")


def predict(
    unit: UnitArgument,
    spm: SpmOption = None,
    crank_motion: Annotated[CrankMotion, typer.Option(
        help="uniform: constant crank speed (--spm or the motor's rated speed); dynamic: the crank speed from the "
             "machine's equation of motion solved together with the rods")] = CrankMotion.uniform,
    damping: Annotated[float | None, typer.Option(
        help="Gibbs' dimensionless damping factor nu of the rods, above 0 (undamped rods never settle to a "
             "steady state) [default: the unit file's, else 0.05]",
        max=2.0, callback=positive)] = None,
    submergence: Annotated[str | None, _well("fluid level above the pump, with its unit ('100 m')")] = None,
    intake_pressure: Annotated[str | None, _well("pump intake pressure, with its unit ('0.8 MPa')")] = None,
    tubing_head_pressure: Annotated[str | None, _well("tubing head pressure, with its unit ('10 bar')")] = None,
    casing_head_pressure: Annotated[str | None, _well("casing head pressure, with its unit ('5 bar')")] = None,
    fluid_density: Annotated[str | None, _well("produced fluid density, with its unit ('850 kg/m3')")] = None,
    fillage: Annotated[str | None, _well("share of the barrel filled with liquid ('80 %')")] = None,
    gas_exponent: Annotated[float | None, _well(
        "polytropic exponent of the gas in the unfilled barrel (1: isothermal); none: vapour, fluid pound",
        callback=finite)] = None,
    unanchored_tubing: Annotated[str | None, _fault(
        "unanchored tubing of this API size (2-3/8, 2-7/8 or 3-1/2): it stretches under the fluid load")] = None,
    travelling_valve_leak: Annotated[str | None, _fault(
        "a leaking travelling valve: its leak at the full fluid-load pressure difference, a rate ('5 m3/d', "
        "'30 bbl/d') or a share of the pump's displacement ('100 %')")] = None,
    standing_valve_leak: Annotated[str | None, _fault("a leaking standing valve, as --travelling-valve-leak")] = None,
    tag_bottom: Annotated[str | None, _fault(
        "a pump tagging down: the plunger meets the pump's bottom this far above the lowest point of its free "
        "stroke ('5 cm')")] = None,
    tag_top: Annotated[str | None, _fault(
        "a pump tagging up: the plunger meets the barrel's top this far below the highest point of its free "
        "stroke ('5 cm')")] = None,
    parted_at: Annotated[str | None, _fault(
        "a parted rod string: the break's depth along the rods ('800 m') or share of the pump depth ('55 %'); "
        "nothing hangs on the free end")] = None,
    samples: Annotated[int, typer.Option(help="time samples per cycle", min=64, max=20_000)] = DEFAULT_SAMPLES,
    service_factor: ServiceFactorOption = 1.0,
    survey: SurveyOption = None,
    friction_coefficient: FrictionCoefficientOption = None,
    guide_limit: GuideLimitOption = None,
    profile: ProfileOption = False,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Surface and pump cards predicted from unit, rods, pump and fluid level.

    The rods' damped wave equation driven by the exact polished-rod motion, the pump's
    valves at the bottom; loads, strokes, displacement, rod stresses, gearbox torque."""
    sink = Output(fmt, units, out, plot, what)
    overrides = WellOverrides(
        submergence=quantity(submergence, "length", "--submergence"),
        intake_pressure=quantity(intake_pressure, "pressure", "--intake-pressure"),
        tubing_head_pressure=quantity(tubing_head_pressure, "pressure", "--tubing-head-pressure"),
        casing_head_pressure=quantity(casing_head_pressure, "pressure", "--casing-head-pressure"),
        fluid_density=quantity(fluid_density, "density", "--fluid-density"),
        fillage=quantity(fillage, "fraction", "--fillage"),
        gas_exponent=gas_exponent,
        tubing_size=unanchored_tubing,
    )
    leaks = [_leak(text, option) for text, option in ((travelling_valve_leak, "--travelling-valve-leak"),
                                                        (standing_valve_leak, "--standing-valve-leak"))]
    parted = _share_or(parted_at, "length", "--parted-at")
    faults = Faults(leaks[0][0], leaks[1][0], (leaks[0][1], leaks[1][1]),
                    quantity(tag_bottom, "length", "--tag-bottom"), quantity(tag_top, "length", "--tag-top"),
                    parted[0], parted[1])
    result = run(load_unit(unit, catalogue), spm, crank_motion.value, samples, damping, overrides, service_factor,
                 deviation=deviation(survey, friction_coefficient, guide_limit, profile), faults=faults)
    if profile:
        sink.emit(result, profile_shown(result.columns))
        return
    torque = "net_torque" if any(c.name == "net_torque" for c in result.columns) else "recommended_net_torque"
    sink.emit(result, (*SHOWN, torque))


def _share_or(text: str | None, dimension: str, option: str) -> tuple[float | None, float | None]:
    """An option given as a quantity of ``dimension`` or as a percentage: (value, None) or (None, share)."""
    if text is None:
        return None, None
    if text.strip().endswith("%"):
        share = quantity(text, "fraction", option)
        if not 0.0 < share:
            raise PumpjackError(f"{option}: {text!r} must be above 0 %")
        return None, share
    value = quantity(text, dimension, option)
    if not value > 0.0:
        raise PumpjackError(f"{option}: {text!r} must be above 0")
    return value, None


def _leak(text: str | None, option: str) -> tuple[float | None, float | None]:
    """A valve's leak: a rate at the full fluid-load pressure difference, or a share of the displacement."""
    return _share_or(text, "flow_rate", option)
