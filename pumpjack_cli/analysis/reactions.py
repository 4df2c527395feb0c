"""Joint reactions and balancing torque from a dynamometer card: `reactions` and `compare-redundancy`."""

from __future__ import annotations

from pathlib import Path

from pydantic import ValidationError

from ..core.beam.reactions import joint_reactions
from ..core.sampling import largest_magnitude, signed_extremes
from ..errors import PumpjackError
from ..results import Column, Panel, Result, Scalar
from .card_runs import CardRun, card_run
from .inputs import require
from .machine import mass_model

#: Reaction vectors of the output: name, description.
REACTIONS = {
    "r12": "crank on pitman 2 at crank pin A",
    "r13": "crank on pitman 3 at crank pin A1",
    "r24": "pitman 2 on equalizer at B",
    "r34": "pitman 3 on equalizer at B1",
    "r45": "equalizer on beam at D",
    "r05": "frame on beam at centre bearing C",
    "r01": "frame on crank at the shaft bearings O, O1",
}
BEARING_MOMENTS = {"m05": "bearing moment of the frame on the beam at C",
                   "m01": "bearing moment of the frame on the crank"}
JOINT_MOMENTS = {"m12": "crank on pitman 2 at A", "m13": "crank on pitman 3 at A1",
                 "m24": "pitman 2 on equalizer at B", "m34": "pitman 3 on equalizer at B1"}
#: Deviation options: field of [deviations], dimension of its value.
DEVIATIONS = {
    "crank_phase": "angle",
    "crank_radius": "length",
    "pitman_length": "length",
    "crank_pin_tilt_radial": "angle",
    "crank_pin_tilt_tangential": "angle",
    "equalizer_pin_roll": "angle",
    "equalizer_pin_yaw": "angle",
}


def _run_columns(run: CardRun) -> list[Column]:
    return [
        Column("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation", run.crank_angle),
        Column("time", "time", "time from crank angle 0", run.time),
        Column("crank_speed", "angular_velocity", "crank angular velocity omega1", run.omega),
        Column("crank_acceleration", "angular_acceleration", "crank angular acceleration epsilon1", run.epsilon),
        Column("rod_load", "force", "polished-rod load from the card", run.load),
    ]


def reactions(unit, card: Path, card_units: str, spm: float | None, steps: int, rotation: str, *,
              weights: bool = True, inertia: bool = True, counterweight_count: int | None = None,
              counterweight_radius: float | None = None) -> Result:
    """The rational mechanism's reactions, bearing moments and balancing torque under a card."""
    masses = mass_model(unit, counterweight_count, counterweight_radius)
    spatial = unit.geometry.spatial(unit.name)
    run = card_run(unit, spatial.planar, card, card_units, spm, steps, rotation)
    r = joint_reactions("rational", spatial, masses, run.crank_angle, run.omega, run.epsilon, run.load,
                        weights=weights, inertia=inertia).reactions
    theta = run.crank_angle
    columns = _run_columns(run)
    summary = [Scalar("mean_crank_speed", "angular_velocity", run.mean_crank_speed, "2 pi / cycle time"),
               Scalar("max_rod_load", "force", float(run.load.max()), "peak polished-rod load"),
               Scalar("min_rod_load", "force", float(run.load.min()), "minimum polished-rod load")]
    for name, what in (REACTIONS | BEARING_MOMENTS).items():
        vector, is_moment = getattr(r, name), name in BEARING_MOMENTS
        quantity = "torque" if is_moment else "force"
        columns += [Column(f"{name}_{axis}", quantity, f"{what}, {axis}", vector[:, i])
                    for i, axis in enumerate("xy" if is_moment else "xyz")]
        peak = largest_magnitude(theta, vector)
        summary += [Scalar(f"peak_{name}", quantity, peak.value, f"peak |{name.upper()}|: {what}"),
                    Scalar(f"peak_{name}_crank_angle", "angle", peak.crank_angle, f"crank angle of peak |{name.upper()}|")]
    columns.append(Column("balancing_torque", "torque", "M_z: gearbox torque on the crank, + driving",
                          r.balancing_torque))
    for label, extreme in zip(("max", "min"), signed_extremes(theta, r.balancing_torque)):
        summary += [Scalar(f"{label}_balancing_torque", "torque", extreme.value, f"{label} M_z (net gearbox torque)"),
                    Scalar(f"{label}_balancing_torque_crank_angle", "angle", extreme.crank_angle,
                           f"crank angle of {label} M_z")]
    summary.append(Scalar("equilibrium_residual", "ratio", float(r.residual.max()),
                          "max |E x - f| of the group 2-3-4-5 / largest load"))
    panels = (
        Panel("rod load", ("rod_load",)),
        Panel("pitman reactions", ("r12_x", "r12_y", "r13_x", "r13_y")),
        Panel("beam reactions", ("r45_y", "r05_x", "r05_y")),
        Panel("balancing torque", ("balancing_torque",)),
    )
    title = f"{unit.name}: reactions and balancing torque, card {card.name}, {rotation} rotation"
    return Result(title, tuple(summary), tuple(columns), panels)


def deviations(unit, given: dict[str, float]):
    """The unit's [deviations] with the values given on the command line (SI) replacing them."""
    try:
        return type(unit.deviations).model_validate(unit.deviations.model_dump() | given)
    except ValidationError as exc:
        first = exc.errors()[0]
        raise PumpjackError(f"--{first['loc'][0].replace('_', '-')}: {first['msg']}") from None


def compare_redundancy(unit, card: Path, card_units: str, spm: float | None, steps: int, rotation: str,
                       given_deviations: dict[str, float]) -> Result:
    """The real mechanism (revolute pins, elastic pitmans, errors) beside the rational one under a card."""
    require(unit, "pitman_section", "the real mechanism needs the pitman's stiffness")
    errors = deviations(unit, given_deviations)
    masses = mass_model(unit)
    ideal = unit.geometry.spatial(unit.name)
    run = card_run(unit, ideal.planar, card, card_units, spm, steps, rotation)
    motion = (ideal, masses, run.crank_angle, run.omega, run.epsilon, run.load)
    rational = joint_reactions("rational", *motion).reactions
    solution = joint_reactions("real", *motion, actual=errors.apply(ideal), tilts=errors.tilts(),
                               section=unit.pitman_section.model())
    real, joints = solution.reactions, solution.joint_moments
    theta = run.crank_angle
    columns = [Column("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation", theta),
               Column("rod_load", "force", "polished-rod load from the card", run.load)]
    for name, what in REACTIONS.items():
        for i, axis in enumerate("xyz"):
            a, b = getattr(rational, name)[:, i], getattr(real, name)[:, i]
            columns += [Column(f"{name}_{axis}_{label}", "force", f"{what}, {axis}: {label}", values)
                        for label, values in (("rational", a), ("real", b), ("difference", b - a))]
    torque_difference = real.balancing_torque - rational.balancing_torque
    columns += [Column(f"balancing_torque_{label}", "torque", f"M_z: {label}", values)
                for label, values in (("rational", rational.balancing_torque), ("real", real.balancing_torque),
                                      ("difference", torque_difference))]
    for name, what in JOINT_MOMENTS.items():
        columns += [Column(f"{name}_{axis}", "torque", f"joint moment M_R{name[1:]}: {what}, {axis}",
                           getattr(joints, name)[:, i]) for i, axis in enumerate("xyz")]
    for side in ("2", "3"):
        columns.append(Column(f"torsion_{side}", "torque", f"torque of pitman {side} about its axis",
                              getattr(joints, f"torsion{side}")))

    fields = type(unit.deviations).model_fields
    summary = [Scalar(f"deviation_{field}", kind, getattr(errors, field),
                      "deviation: " + fields[field].description.rsplit(" [", 1)[0])
               for field, kind in DEVIATIONS.items()]
    dead = ideal.planar.dead_positions()
    summary += [Scalar("crank_angle_bottom", "angle", dead.crank_angle_bottom, "bottom dead position"),
                Scalar("crank_angle_top", "angle", dead.crank_angle_top, "top dead position")]

    def peak(name: str, values, quantity: str, what: str) -> None:
        extreme = largest_magnitude(theta, values)
        summary.extend([Scalar(name, quantity, extreme.value, what),
                        Scalar(f"{name}_crank_angle", "angle", extreme.crank_angle, f"crank angle of {name}")])

    def series(name: str):
        return next(c.values for c in columns if c.name == name)

    peak("peak_difference_r12_y", series("r12_y_difference"), "force", "max |dR12y|, real - rational")
    peak("peak_difference_r13_y", series("r13_y_difference"), "force", "max |dR13y|, real - rational")
    peak("peak_pitman_split_y", real.r12[:, 1] - real.r13[:, 1], "force", "max |R12y - R13y| in the real mechanism")
    peak("peak_difference_r12_x", series("r12_x_difference"), "force", "max |dR12x|, real - rational")
    peak("peak_difference_r13_x", series("r13_x_difference"), "force", "max |dR13x|, real - rational")
    peak("peak_difference_balancing_torque", torque_difference, "torque", "max |dM_z|")
    peak("peak_torsion_2", joints.torsion2, "torque", "max |torque| of pitman 2 about its axis")
    peak("peak_torsion_3", joints.torsion3, "torque", "max |torque| of pitman 3 about its axis")
    for name in JOINT_MOMENTS:
        peak(f"peak_{name}", getattr(joints, name), "torque", f"max |M_R{name[1:]}|")
    summary.append(Scalar("equilibrium_residual", "ratio", float(real.residual.max()),
                          "real mechanism: max |E X - f| / largest load"))
    panels = (
        Panel("R12 y ([Spatial7SK12] fig. 11)", ("r12_y_real",), ("r12_y_rational",)),
        Panel("R13 y ([Spatial7SK12] fig. 12)", ("r13_y_real",), ("r13_y_rational",)),
        Panel("R12, R13 x ([Spatial7SK12] fig. 13)", ("r12_x_real", "r13_x_real"), ("r12_x_rational",)),
        Panel("balancing torque ([Spatial7SK12] fig. 14)", ("balancing_torque_real",), ("balancing_torque_rational",)),
    )
    title = f"{unit.name}: real against rational mechanism, card {card.name}, {rotation} rotation"
    return Result(title, tuple(summary), tuple(columns), panels)
