"""Joint reactions and balancing torque from a dynamometer card: `reactions` and `compare-redundancy`."""

from __future__ import annotations

import numpy as np
from pydantic import ValidationError

from ..core.beam.reactions import joint_reactions
from ..core.sampling import extremes, peak
from ..config.files import error_message
from ..errors import PumpjackError
from ..results import Column, Panel, Result, Scalar
from .card_runs import CardRun, CardSource, card_runs
from .inputs import crank_columns, require
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
#: Crank positions of the grid on which `reactions` finds its summary's extremes.
SUMMARY_STEPS = 3600
#: The same for `compare-redundancy` (each position costs a small least-squares solve).
REDUNDANCY_SUMMARY_STEPS = 720
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
    return [*crank_columns(run.crank_angle, run.time, run.omega, run.epsilon),
            Column("rod_load", "force", "polished-rod load from the card", run.load)]


def _peak(summary: list[Scalar], name: str, theta, values, quantity: str, what: str) -> None:
    """A peak (largest magnitude) and its crank angle, refined on the summary grid."""
    found = peak(theta, values)
    summary += [Scalar(name, quantity, found.value, what),
                Scalar(f"{name}_crank_angle", "angle", found.crank_angle, f"crank angle of {name}")]


def reactions(unit, card: CardSource, spm: float | None, steps: int, rotation: str, *,
              weights: bool = True, inertia: bool = True, counterweight_count: int | None = None,
              counterweight_radius: float | None = None) -> Result:
    """The rational mechanism's reactions, bearing moments and balancing torque under a card.

    The columns are on ``steps`` crank angles; the summary's extremes on a fixed grid of
    :data:`SUMMARY_STEPS`, refined between its points, whatever ``steps``.
    """
    masses = mass_model(unit, counterweight_count, counterweight_radius)
    spatial = unit.geometry.spatial(unit.name)
    reading, runs = card_runs(unit, spatial.planar, card, spm, (steps, SUMMARY_STEPS), rotation)
    r, dense = (joint_reactions("rational", spatial, masses, run.crank_angle, run.omega, run.epsilon, run.load,
                                weights=weights, inertia=inertia).reactions for run in runs)
    run, theta = runs[0], runs[1].crank_angle
    columns = _run_columns(run)
    summary = [Scalar("mean_crank_speed", "angular_velocity", run.mean_crank_speed, "2 pi / cycle time"),
               Scalar("max_rod_load", "force", float(reading.card.load.max()), "peak polished-rod load of the card"),
               Scalar("min_rod_load", "force", float(reading.card.load.min()), "minimum polished-rod load of the card")]
    for name, what in (REACTIONS | BEARING_MOMENTS).items():
        vector, is_moment = getattr(r, name), name in BEARING_MOMENTS
        quantity = "torque" if is_moment else "force"
        columns += [Column(f"{name}_{axis}", quantity, f"{what}, {axis}", vector[:, i])
                    for i, axis in enumerate("xy" if is_moment else "xyz")]
        _peak(summary, f"peak_{name}", theta, getattr(dense, name), quantity, f"peak |{name.upper()}|: {what}")
    columns.append(Column("balancing_torque", "torque", "M_z: gearbox torque on the crank, + driving",
                          r.balancing_torque))
    for label, extreme in zip(("max", "min"), extremes(theta, dense.balancing_torque)):
        summary += [Scalar(f"{label}_balancing_torque", "torque", extreme.value, f"{label} M_z (net gearbox torque)"),
                    Scalar(f"{label}_balancing_torque_crank_angle", "angle", extreme.crank_angle,
                           f"crank angle of {label} M_z")]
    summary.append(Scalar("equilibrium_residual", "ratio", float(max(r.residual.max(), dense.residual.max())),
                          "max |E x - f| of the group 2-3-4-5 / largest load"))
    panels = (
        Panel("rod load", ("rod_load",)),
        Panel("pitman reactions", ("r12_x", "r12_y", "r13_x", "r13_y")),
        Panel("beam reactions", ("r45_y", "r05_x", "r05_y")),
        Panel("balancing torque", ("balancing_torque",)),
    )
    title = f"{unit.name}: reactions and balancing torque, card {card.name}, {rotation} rotation"
    return Result(title, tuple(summary), tuple(columns), panels)


def with_options(section, given: dict):
    """A unit's section ([deviations], [joints]) with the values given on the command line (SI)
    replacing its own, validated by its schema (a bad value named by its option)."""
    try:
        return type(section).model_validate(section.model_dump() | given)
    except ValidationError as exc:
        first = exc.errors()[0]
        raise PumpjackError(f"--{first['loc'][0].replace('_', '-')}: {error_message(first, type(section))}") from None


def compare_redundancy(unit, card: CardSource, spm: float | None, steps: int, rotation: str,
                       given_deviations: dict, given_joints: dict | None = None) -> Result:
    """The real mechanism (revolute pins, elastic pitmans, errors) beside the rational one under a card.

    Like with like ([Spatial7SK12] compares the two mechanisms with the same errors): the
    rational mechanism is solved on the erroneous geometry too, and on the error-free
    one; every difference from the error-free unit splits into its **kinematic** part
    (rational with errors - error-free rational: the errors change the motion) and its
    **redundancy** part (real - rational, same errors: the self-stress the redundant
    constraints cause), columns ``_kinematic`` and ``_difference``. The columns are on
    ``steps`` crank angles; the summary's peaks on a fixed grid of
    :data:`REDUNDANCY_SUMMARY_STEPS`, refined between its points, whatever ``steps``.
    """
    require(unit, "pitman_section", "the real mechanism needs the pitman's stiffness")
    errors = with_options(unit.deviations, given_deviations)
    pins = with_options(unit.joints, given_joints or {})
    masses = mass_model(unit)
    ideal = unit.geometry.spatial(unit.name)
    actual = errors.apply(ideal)
    _, runs = card_runs(unit, ideal.planar, card, spm, (steps, REDUNDANCY_SUMMARY_STEPS), rotation)

    def solve(run: CardRun):
        motion = (masses, run.crank_angle, run.omega, run.epsilon, run.load)
        real = joint_reactions("real", ideal, *motion, actual=actual, tilts=errors.tilts(),
                               section=unit.pitman_section.model(), joints=pins.model())
        return (joint_reactions("rational", ideal, *motion).reactions, joint_reactions("rational", actual, *motion).reactions,
                real.reactions, real.joint_moments)

    (ideal_r, rational, real, joints), (d_ideal, d_rational, d_real, d_joints) = (solve(run) for run in runs)
    run, theta = runs[0], runs[1].crank_angle
    columns = [Column("crank_angle", "angle", "crank angle from 12 o'clock in the direction of rotation",
                      run.crank_angle),
               Column("rod_load", "force", "polished-rod load from the card", run.load)]

    def split(label: str, quantity: str, what: str, get) -> list[Column]:
        a, b, c = get(ideal_r), get(rational), get(real)
        return [Column(f"{label}_{part}", quantity, f"{what}: {meaning}", values) for part, meaning, values in (
            ("ideal", "rational mechanism, no errors", a), ("rational", "rational mechanism, same errors", b),
            ("real", "real mechanism", c), ("kinematic", "rational with errors - without (the errors' kinematic part)",
                                            b - a),
            ("difference", "real - rational, same errors (the redundancy part)", c - b))]

    for name, what in REACTIONS.items():
        for i, axis in enumerate("xyz"):
            columns += split(f"{name}_{axis}", "force", f"{what}, {axis}", lambda r, n=name, k=i: getattr(r, n)[:, k])
    columns += split("balancing_torque", "torque", "M_z", lambda r: r.balancing_torque)
    for name, what in JOINT_MOMENTS.items():
        columns += [Column(f"{name}_{axis}", "torque", f"joint moment M_R{name[1:]}: {what}, {axis}",
                           getattr(joints, name)[:, i]) for i, axis in enumerate("xyz")]
    for side in ("2", "3"):
        columns.append(Column(f"torsion_{side}", "torque", f"torque of pitman {side} about its axis",
                              getattr(joints, f"torsion{side}")))
    contact, d_contact = joints.contact, d_joints.contact
    columns += [Column("compatibility_residual", "ratio", "|A y - b + g^T lambda| / |b|: Menabrea's condition",
                       contact.compatibility_residual),
                Column("contact_residual", "ratio", "largest violation of the joints' contact conditions, "
                       "relative to the moments' scale", contact.contact_residual)]

    fields = type(unit.deviations).model_fields
    summary = [Scalar(f"deviation_{field}", kind, getattr(errors, field),
                      "deviation: " + fields[field].description.rsplit(" [", 1)[0])
               for field, kind in DEVIATIONS.items()]
    dead = ideal.planar.dead_positions()
    summary += [Scalar("crank_angle_bottom", "angle", dead.crank_angle_bottom, "bottom dead position"),
                Scalar("crank_angle_top", "angle", dead.crank_angle_top, "top dead position")]
    for name, values, quantity, what in (
        ("peak_difference_r12_y", d_real.r12[:, 1] - d_rational.r12[:, 1], "force",
         "max |dR12y|, real - rational with the same errors (redundancy part)"),
        ("peak_difference_r13_y", d_real.r13[:, 1] - d_rational.r13[:, 1], "force",
         "max |dR13y|, real - rational with the same errors (redundancy part)"),
        ("peak_pitman_split_y", d_real.r12[:, 1] - d_real.r13[:, 1], "force", "max |R12y - R13y| in the real mechanism"),
        ("peak_rational_pitman_split_y", d_rational.r12[:, 1] - d_rational.r13[:, 1], "force",
         "max |R12y - R13y| in the rational mechanism with the same errors"),
        ("peak_difference_r12_x", d_real.r12[:, 0] - d_rational.r12[:, 0], "force", "max |dR12x|, redundancy part"),
        ("peak_difference_r13_x", d_real.r13[:, 0] - d_rational.r13[:, 0], "force", "max |dR13x|, redundancy part"),
        ("peak_difference_balancing_torque", d_real.balancing_torque - d_rational.balancing_torque, "torque",
         "max |dM_z|, real - rational with the same errors (redundancy part)"),
        ("peak_kinematic_r12_y", d_rational.r12[:, 1] - d_ideal.r12[:, 1], "force",
         "max |dR12y|, rational with errors - without (kinematic part)"),
        ("peak_kinematic_r13_y", d_rational.r13[:, 1] - d_ideal.r13[:, 1], "force",
         "max |dR13y|, rational with errors - without (kinematic part)"),
        ("peak_kinematic_balancing_torque", d_rational.balancing_torque - d_ideal.balancing_torque, "torque",
         "max |dM_z|, rational with errors - without (kinematic part)"),
        ("peak_total_difference_balancing_torque", d_real.balancing_torque - d_ideal.balancing_torque, "torque",
         "max |dM_z|, real with errors - error-free rational (both parts)"),
        ("peak_torsion_2", d_joints.torsion2, "torque", "max |torque| of pitman 2 about its axis"),
        ("peak_torsion_3", d_joints.torsion3, "torque", "max |torque| of pitman 3 about its axis"),
        *((f"peak_{name}", getattr(d_joints, name), "torque", f"max |M_R{name[1:]}|") for name in JOINT_MOMENTS),
    ):
        _peak(summary, name, theta, values, quantity, what)
    summary.append(Scalar("equilibrium_residual", "ratio", float(max(real.residual.max(), d_real.residual.max())),
                          "real mechanism: max |E X - f| / largest load"))
    model = pins.model()
    for name, value, kind in (("crank_pin_stiffness", model.crank_pin_stiffness, "rotational_stiffness"),
                              ("equalizer_pin_stiffness", model.equalizer_pin_stiffness, "rotational_stiffness"),
                              ("crank_pin_clearance", model.crank_pin_clearance, "angle"),
                              ("equalizer_pin_clearance", model.equalizer_pin_clearance, "angle")):
        if np.isfinite(value):
            summary.append(Scalar(name, kind, value, type(unit.joints).model_fields[name].description.split(" [")[0]))
    summary += [
        Scalar("compatibility_residual", "ratio", float(max(contact.compatibility_residual.max(),
                                                            d_contact.compatibility_residual.max())),
               "real mechanism: max |A y - b + g^T lambda| / |b| (Menabrea's condition)"),
        Scalar("contact_residual", "ratio", float(max(contact.contact_residual.max(), d_contact.contact_residual.max())),
               "real mechanism: largest violation of the joints' contact conditions"),
        Scalar("contact_iterations", "count", float(max(contact.iterations.max(), d_contact.iterations.max())),
               "most active-set iterations at one crank angle (1: no clearance)"),
    ]
    panels = (
        Panel("R12 y ([Spatial7SK12] fig. 11)", ("r12_y_real",), ("r12_y_rational",)),
        Panel("R13 y ([Spatial7SK12] fig. 12)", ("r13_y_real",), ("r13_y_rational",)),
        Panel("R12, R13 x ([Spatial7SK12] fig. 13)", ("r12_x_real", "r13_x_real"), ("r12_x_rational",)),
        Panel("balancing torque ([Spatial7SK12] fig. 14)", ("balancing_torque_real",), ("balancing_torque_rational",)),
    )
    title = (f"{unit.name}: real against rational mechanism (same errors; crank phase of the "
             f"{errors.crank_phase_mode.replace('-', ' ')}), card {card.name}, {rotation} rotation")
    return Result(title, tuple(summary), tuple(columns), panels)
