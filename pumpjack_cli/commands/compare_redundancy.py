"""`pumpjack compare-redundancy`: the real mechanism (redundant constraints, elastic
pitmans, manufacturing errors) against the rational one, from a dynamometer card."""

from __future__ import annotations

from typing import Annotated

import numpy as np
import typer
from pydantic import ValidationError

from ..config import Deviations, UnitConfig, load_unit
from ..core.beam.kinetostatics import Reactions, rational_mechanism
from ..core.beam.geometry import dead_positions
from ..core.beam.redundancy import JointMoments, real_mechanism
from ..errors import PumpjackError
from ..render import Column, Panel, Report, Scalar
from ..units import parse_quantity
from .common import (
    CardUnitsOption,
    FormatOption,
    OutputOption,
    PlotOption,
    UnitArgument,
    UnitsOption,
    UnitSystem,
    output,
)
from .reactions import (
    REACTIONS,
    CardOption,
    CardRun,
    Rotation,
    RotationOption,
    SpmOption,
    StepsOption,
    card_run,
    require_masses,
)

#: Deviation options: field of [deviations], dimension of its value.
DEVIATION_OPTIONS = {
    "crank_phase": "angle",
    "crank_radius": "length",
    "pitman_length": "length",
    "crank_pin_tilt_radial": "angle",
    "crank_pin_tilt_tangential": "angle",
    "equalizer_pin_roll": "angle",
    "equalizer_pin_yaw": "angle",
}


def deviations_with_options(config: UnitConfig, given: dict[str, str | None]) -> Deviations:
    """The unit's [deviations] with the values given on the command line replacing them."""
    update = {}
    for field, text in given.items():
        if text is None:
            continue
        option = "--" + field.replace("_", "-")
        try:
            update[field] = parse_quantity(text, DEVIATION_OPTIONS[field])
        except ValueError as exc:
            raise PumpjackError(f"{option}: {exc}") from None
    merged = config.deviations.model_dump() | update
    try:
        return Deviations.model_validate(merged)
    except ValidationError as exc:
        first = exc.errors()[0]
        raise PumpjackError(f"--{first['loc'][0].replace('_', '-')}: {first['msg']}") from None


def comparison_report(config: UnitConfig, run: CardRun, rational: Reactions, real: Reactions,
                      joints: JointMoments, deviations: Deviations, title: str) -> Report:
    """Both mechanisms side by side, their differences, the joint moments and the seed 000 summary."""
    theta, load = run.crank_angle, run.load
    columns = [Column("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation"),
               Column("rod_load", "force", "polished-rod load from the card", brief=False)]
    series: dict[str, np.ndarray] = {"crank_angle": theta, "rod_load": load}
    for name, what in REACTIONS.items():
        for i, axis in enumerate("xyz"):
            brief = name in ("r12", "r13") and axis == "y"
            for label, values in (("rational", getattr(rational, name)[:, i]), ("real", getattr(real, name)[:, i]),
                                  ("difference", getattr(real, name)[:, i] - getattr(rational, name)[:, i])):
                key = f"{name}_{axis}_{label}"
                columns.append(Column(key, "force", f"{what}, {axis}: {label}", brief and label != "difference"))
                series[key] = values
    for label, values in (("rational", rational.balancing_torque), ("real", real.balancing_torque),
                          ("difference", real.balancing_torque - rational.balancing_torque)):
        columns.append(Column(f"balancing_torque_{label}", "torque", f"M_z: {label}", label == "real"))
        series[f"balancing_torque_{label}"] = values
    joint_text = {"m12": "crank on pitman 2 at A", "m13": "crank on pitman 3 at A1",
                  "m24": "pitman 2 on equalizer at B", "m34": "pitman 3 on equalizer at B1"}
    for name, what in joint_text.items():
        for i, axis in enumerate("xyz"):
            columns.append(Column(f"{name}_{axis}", "torque", f"joint moment M_R{name[1:]}: {what}, {axis}", False))
            series[f"{name}_{axis}"] = getattr(joints, name)[:, i]
    for name in ("torsion2", "torsion3"):
        columns.append(Column(name, "torque", f"torque of pitman {name[-1]} about its axis", False))
        series[name] = getattr(joints, name)

    summary = [Scalar(f"deviation_{field}", DEVIATION_OPTIONS[field], getattr(deviations, field),
                      "deviation: " + Deviations.model_fields[field].description.rsplit(" [", 1)[0])
               for field in DEVIATION_OPTIONS]
    dead = dead_positions(config.geometry.linkage())
    summary += [Scalar("crank_angle_bottom", "angle", dead.crank_angle_bottom, "bottom dead position"),
                Scalar("crank_angle_top", "angle", dead.crank_angle_top, "top dead position")]

    def peak(name: str, values: np.ndarray, quantity: str, what: str) -> None:
        i = int(np.argmax(np.abs(values)))
        summary.extend([Scalar(name, quantity, float(np.abs(values[i])), what),
                        Scalar(f"{name}_crank_angle", "angle", float(theta[i]), f"crank angle of {name}")])

    peak("max_difference_r12_y", series["r12_y_difference"], "force", "max |dR12y|, real - rational")
    peak("max_difference_r13_y", series["r13_y_difference"], "force", "max |dR13y|, real - rational")
    peak("max_pitman_split_y", real.r12[:, 1] - real.r13[:, 1], "force", "max |R12y - R13y| in the real mechanism")
    peak("max_difference_r12_x", series["r12_x_difference"], "force", "max |dR12x|, real - rational")
    peak("max_difference_r13_x", series["r13_x_difference"], "force", "max |dR13x|, real - rational")
    peak("max_difference_balancing_torque", series["balancing_torque_difference"], "torque", "max |dM_z|")
    peak("max_torsion_2", joints.torsion2, "torque", "max |torque| of pitman 2 about its axis")
    peak("max_torsion_3", joints.torsion3, "torque", "max |torque| of pitman 3 about its axis")
    for name in joint_text:
        peak(f"max_{name}", np.linalg.norm(getattr(joints, name), axis=-1), "torque", f"max |M_R{name[1:]}|")
    summary.append(Scalar("equilibrium_residual", "ratio", float(real.residual.max()),
                          "real mechanism: max |E X - f| / largest load"))
    panels = (
        Panel("R12 y (seed fig. 11)", ("r12_y_real",), ("r12_y_rational",)),
        Panel("R13 y (seed fig. 12)", ("r13_y_real",), ("r13_y_rational",)),
        Panel("R12, R13 x (seed fig. 13)", ("r12_x_real", "r13_x_real"), ("r12_x_rational",)),
        Panel("balancing torque (seed fig. 14)", ("balancing_torque_real",), ("balancing_torque_rational",)),
    )
    return Report(title=title, summary=tuple(summary), columns=tuple(columns), series=series, panels=panels)


def _deviation_option(help_text: str):
    return typer.Option(help=help_text + " [default: the unit's [deviations], zero]")


def compare_redundancy(
    unit: UnitArgument,
    card: CardOption,
    card_units: CardUnitsOption = UnitSystem.si,
    spm: SpmOption = None,
    steps: StepsOption = 360,
    rotation: RotationOption = Rotation.uniform,
    crank_phase: Annotated[str | None, _deviation_option("crank pin A1 ahead of A, e.g. '0.5 deg'")] = None,
    crank_radius: Annotated[str | None, _deviation_option("crank radius of A1 minus that of A, e.g. '2 mm'")] = None,
    pitman_length: Annotated[str | None, _deviation_option("pitman A1B1 minus AB, e.g. '2 mm'")] = None,
    crank_pin_tilt_radial: Annotated[str | None, _deviation_option("pin A1 bore turned about the arm's radius")] = None,
    crank_pin_tilt_tangential: Annotated[str | None, _deviation_option("pin A1 bore turned about the arm's tangent")] = None,
    equalizer_pin_roll: Annotated[str | None, _deviation_option("pin B1 bore turned about the beam axis")] = None,
    equalizer_pin_yaw: Annotated[str | None, _deviation_option("pin B1 bore turned about the vertical")] = None,
    fmt: FormatOption = None,
    units: UnitsOption = UnitSystem.si,
    out: OutputOption = None,
    plot: PlotOption = None,
) -> None:
    """Real mechanism (redundant constraints, elastic pitmans, errors) against the rational one.

    Reactions, joint moments and balancing torque of both from a dynamometer card."""
    config = load_unit(unit)
    require_masses(config)
    if config.pitman_section is None:
        raise PumpjackError(f"unit {config.name} has no [pitman_section]; the real mechanism needs the pitman's stiffness")
    deviations = deviations_with_options(config, {
        "crank_phase": crank_phase, "crank_radius": crank_radius, "pitman_length": pitman_length,
        "crank_pin_tilt_radial": crank_pin_tilt_radial, "crank_pin_tilt_tangential": crank_pin_tilt_tangential,
        "equalizer_pin_roll": equalizer_pin_roll, "equalizer_pin_yaw": equalizer_pin_yaw,
    })
    ideal = config.geometry.spatial(config.name)
    masses = config.masses.model()
    run = card_run(config, ideal.planar, card, card_units, spm, steps, rotation)
    motion = (run.crank_angle, run.omega, run.epsilon, run.load)
    _, rational = rational_mechanism(ideal, masses, *motion)
    _, joints, real = real_mechanism(ideal, deviations.apply(ideal), deviations.tilts(),
                                     config.pitman_section.model(), masses, *motion)
    title = f"{config.name}: real against rational mechanism, card {card.name}, {rotation.value} rotation"
    output(comparison_report(config, run, rational, real, joints, deviations, title), fmt, units, out, plot)
