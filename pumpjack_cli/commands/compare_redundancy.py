"""`pumpjack compare-redundancy`: the real mechanism (redundant constraints, elastic
pitmans, manufacturing errors) against the rational one, from a dynamometer card."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import typer

from ..analysis.reactions import DEVIATIONS
from ..analysis.reactions import compare_redundancy as run
from ..config import load_unit
from ..options import (CardColumnsOption, CardOption, CardUnitsOption, FormatOption, OutputOption, PlotOption, CrankMotion, CrankMotionOption,
                     CardSpmOption, StepsOption, UnitArgument, UnitsOption, UnitSystem, Output, card_source, quantity)
from ..options import What, WhatOption
from ..options import CatalogueOption
from ..options import CardFormatOption, CardPointsOption, StrokeOption

class PhaseMode(str, Enum):
    pin_bore = "pin-bore"
    whole_arm = "whole-arm"


SHOWN = ("crank_angle", "r12_y_rational", "r12_y_real", "r13_y_rational", "r13_y_real", "net_torque_real")


def _deviation(help_text: str):
    return typer.Option(help=f"{help_text} [default: the unit's [deviations], else zero]")


def _joint(help_text: str):
    return typer.Option(help=f"{help_text} [default: the unit's [joints], else rigid without clearance]")


#: Joint options and their quantities.
JOINTS = {"crank_pin_stiffness": "rotational_stiffness", "equalizer_pin_stiffness": "rotational_stiffness",
          "crank_pin_clearance": "angle", "equalizer_pin_clearance": "angle"}


def compare_redundancy(
    unit: UnitArgument,
    card: CardOption,
    card_units: CardUnitsOption = None,
    card_columns: CardColumnsOption = None,
    card_format: CardFormatOption = None,
    card_points: CardPointsOption = None,
    stroke: StrokeOption = None,
    spm: CardSpmOption = None,
    steps: StepsOption = 360,
    crank_motion: CrankMotionOption = CrankMotion.uniform,
    crank_phase: Annotated[str | None, _deviation("crank pin A1 ahead of A, e.g. '0.5 deg'")] = None,
    crank_radius: Annotated[str | None, _deviation("crank radius of A1 minus that of A, e.g. '2 mm'")] = None,
    pitman_length: Annotated[str | None, _deviation("pitman A1B1 minus AB, e.g. '2 mm'")] = None,
    crank_pin_tilt_radial: Annotated[str | None, _deviation("pin A1 bore turned about the arm's radius")] = None,
    crank_pin_tilt_tangential: Annotated[str | None, _deviation("pin A1 bore turned about the arm's tangent")] = None,
    equalizer_pin_roll: Annotated[str | None, _deviation("pin B1 bore turned about the beam axis")] = None,
    equalizer_pin_yaw: Annotated[str | None, _deviation("pin B1 bore turned about the vertical")] = None,
    crank_pin_stiffness: Annotated[str | None, _joint("rotational stiffness of the crank pins, e.g. '3e6 N*m/rad'")
                                   ] = None,
    equalizer_pin_stiffness: Annotated[str | None, _joint(
        "rotational stiffness of the equalizer pins and bearing, e.g. '2.5e7 N*m/rad'")] = None,
    crank_pin_clearance: Annotated[str | None, _joint(
        "free tilt of the crank pins, radial clearance over width, e.g. '1 mrad'")] = None,
    equalizer_pin_clearance: Annotated[str | None, _joint("free tilt of the equalizer pins, e.g. '1 mrad'")] = None,
    crank_phase_mode: Annotated[PhaseMode | None, _deviation(
        "what --crank-phase turns: pin-bore (pin A1 alone) or whole-arm (side 3's arm with its counterweights)")
    ] = None,
    catalogue: CatalogueOption = None,
    fmt: FormatOption = None,
    what: WhatOption = What.columns,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Real mechanism (redundant constraints, elastic pitmans, errors) against the rational one.

    Reactions, joint moments and balancing torque of both from a dynamometer card."""
    sink = Output(fmt, units, out, plot, what)
    texts = {"crank_phase": crank_phase, "crank_radius": crank_radius, "pitman_length": pitman_length,
             "crank_pin_tilt_radial": crank_pin_tilt_radial, "crank_pin_tilt_tangential": crank_pin_tilt_tangential,
             "equalizer_pin_roll": equalizer_pin_roll, "equalizer_pin_yaw": equalizer_pin_yaw}
    given = {field: quantity(text, DEVIATIONS[field], "--" + field.replace("_", "-"))
             for field, text in texts.items() if text is not None}
    if crank_phase_mode is not None:
        given["crank_phase_mode"] = crank_phase_mode.value
    pins = {"crank_pin_stiffness": crank_pin_stiffness, "equalizer_pin_stiffness": equalizer_pin_stiffness,
            "crank_pin_clearance": crank_pin_clearance, "equalizer_pin_clearance": equalizer_pin_clearance}
    given_joints = {field: quantity(text, JOINTS[field], "--" + field.replace("_", "-"))
                    for field, text in pins.items() if text is not None}
    source = card_source(card, card_units, card_columns, card_format, card_points, stroke)
    sink.emit(run(load_unit(unit, catalogue), source, spm, steps, crank_motion.value,
                  given, given_joints), SHOWN)
