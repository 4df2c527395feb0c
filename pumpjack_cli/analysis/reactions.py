"""Joint reactions and net gearbox torque from a dynamometer card: `reactions` and `compare-redundancy`."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from pydantic import ValidationError

from ..config.files import error_message
from ..core.beam.reactions import joint_reactions
from ..core.sampling import extremes, peak
from ..errors import PumpjackError
from ..results import Column, Panel, Result, Scalar
from .card_runs import CardRun, CardSource, card_runs
from .inputs import crank_columns, dead_position_marks

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ..config.beam_unit import UnitConfig

#: Reaction vectors, bearing moments and joint moments of the output (their meanings: the catalogue).
REACTIONS = ("r12", "r13", "r24", "r34", "r45", "r05", "r01")
BEARING_MOMENTS = ("m05", "m01")
JOINT_MOMENTS = ("m12", "m13", "m24", "m34")
#: Crank positions of the grid on which `reactions` finds its summary's extremes.
SUMMARY_STEPS = 3600
#: The same for `compare-redundancy` (each position costs a small least-squares solve).
REDUNDANCY_SUMMARY_STEPS = 720
#: Deviation options: field of [deviations], dimension of its value (for the options' units).
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
    return [*crank_columns(run.crank_angle, run.time, run.crank_speed, run.crank_acceleration),
            Column("rod_load", run.load)]


def _peak(summary: list[Scalar], name: str, theta, values) -> None:
    """A peak (largest magnitude) and its crank angle, refined on the summary grid."""
    found = peak(theta, values)
    summary += [Scalar(name, found.value),
                Scalar(f"{name}_crank_angle", found.crank_angle)]


def reactions(unit: UnitConfig, card: CardSource, spm: float | None, steps: int, crank_motion: str, *,
              weights: bool = True, inertia: bool = True, counterweight_count: int | None = None,
              counterweight_radius: float | None = None) -> Result:
    """The rational mechanism's reactions, bearing moments and balancing torque under a card.

    The columns are on ``steps`` crank angles; the summary's extremes on a fixed grid of
    :data:`SUMMARY_STEPS`, refined between its points, whatever ``steps``.
    """
    masses = unit.mass_model(counterweight_count, counterweight_radius)
    spatial = unit.spatial()
    reading, runs = card_runs(unit, spatial.planar, card, spm, (steps, SUMMARY_STEPS), crank_motion)
    r, dense = (joint_reactions("rational", spatial, masses, run.crank_angle, run.crank_speed, run.crank_acceleration, run.load,
                                weights=weights, inertia=inertia).reactions for run in runs)
    run, theta = runs[0], runs[1].crank_angle
    columns = _run_columns(run)
    summary = [Scalar("mean_crank_speed", run.mean_crank_speed),
               Scalar("max_rod_load", float(reading.card.load.max())),
               Scalar("min_rod_load", float(reading.card.load.min()))]
    for name in REACTIONS + BEARING_MOMENTS:
        vector = getattr(r, name)
        columns += [Column(f"{name}_{axis}", vector[:, i])
                    for i, axis in enumerate("xy" if name in BEARING_MOMENTS else "xyz")]
        _peak(summary, f"peak_{name}", theta, getattr(dense, name))
    columns.append(Column("net_torque", r.net_torque))
    for label, extreme in zip(("max", "min"), extremes(theta, dense.net_torque)):
        summary += [Scalar(f"{label}_net_torque", extreme.value),
                    Scalar(f"{label}_net_torque_crank_angle", extreme.crank_angle)]
    summary.append(Scalar("equilibrium_residual", float(max(r.residual.max(), dense.residual.max()))))
    panels = (
        Panel("rod load", ("rod_load",)),
        Panel("pitman reactions", ("r12_x", "r12_y", "r13_x", "r13_y")),
        Panel("beam reactions", ("r45_y", "r05_x", "r05_y")),
        Panel("net gearbox torque", ("net_torque",)),
    )
    title = f"{unit.name}: reactions and net gearbox torque, card {card.name}, {crank_motion} rotation"
    return Result(title, tuple(summary), tuple(columns), panels, dead_position_marks(unit.geometry.mechanism()))


def with_options(section, given: dict):
    """A unit's section ([deviations], [joints]) with the values given on the command line (SI)
    replacing its own, validated by its schema (a bad value named by its option)."""
    try:
        return type(section).model_validate(section.model_dump() | given)
    except ValidationError as exc:
        first = exc.errors()[0]
        raise PumpjackError(f"--{first['loc'][0].replace('_', '-')}: {error_message(first, type(section))}") from None


def compare_redundancy(unit: UnitConfig, card: CardSource, spm: float | None, steps: int, crank_motion: str,
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
    unit.require("pitman_section", "the real mechanism needs the pitman's stiffness")
    errors = with_options(unit.deviations, given_deviations)
    pins = with_options(unit.joints, given_joints or {})
    masses = unit.mass_model()
    ideal = unit.spatial()
    actual = errors.apply(ideal)
    _, runs = card_runs(unit, ideal.planar, card, spm, (steps, REDUNDANCY_SUMMARY_STEPS), crank_motion)

    def solve(run: CardRun):
        motion = (masses, run.crank_angle, run.crank_speed, run.crank_acceleration, run.load)
        real = joint_reactions("real", ideal, *motion, actual=actual, tilts=errors.tilts(),
                               section=unit.pitman_section.model(), joints=pins.model())
        return (joint_reactions("rational", ideal, *motion).reactions, joint_reactions("rational", actual, *motion).reactions,
                real.reactions, real.joint_moments)

    (ideal_r, rational, real, joints), (d_ideal, d_rational, d_real, d_joints) = (solve(run) for run in runs)
    run, theta = runs[0], runs[1].crank_angle
    columns = [Column("crank_angle", run.crank_angle),
               Column("rod_load", run.load)]

    def split(label: str, get) -> list[Column]:
        a, b, c = get(ideal_r), get(rational), get(real)
        return [Column(f"{label}_{part}", values) for part, values in (
            ("ideal", a), ("rational", b), ("real", c), ("kinematic", b - a), ("difference", c - b))]

    for name in REACTIONS:
        for i, axis in enumerate("xyz"):
            columns += split(f"{name}_{axis}", lambda r, n=name, k=i: getattr(r, n)[:, k])
    columns += split("net_torque", lambda r: r.net_torque)
    for name in JOINT_MOMENTS:
        columns += [Column(f"{name}_{axis}", getattr(joints, name)[:, i]) for i, axis in enumerate("xyz")]
    for side in ("2", "3"):
        columns.append(Column(f"torsion_{side}", getattr(joints, f"torsion{side}")))
    contact, d_contact = joints.contact, d_joints.contact
    columns += [Column("compatibility_residual", contact.compatibility_residual),
                Column("contact_residual", contact.contact_residual)]

    summary = [Scalar(f"deviation_{field}", getattr(errors, field)) for field in DEVIATIONS]
    dead = ideal.planar.dead_positions()
    summary += [Scalar("crank_angle_bottom", dead.crank_angle_bottom),
                Scalar("crank_angle_top", dead.crank_angle_top)]
    for name, values in (
        ("peak_difference_r12_y", d_real.r12[:, 1] - d_rational.r12[:, 1]),
        ("peak_difference_r13_y", d_real.r13[:, 1] - d_rational.r13[:, 1]),
        ("peak_pitman_split_y", d_real.r12[:, 1] - d_real.r13[:, 1]),
        ("peak_rational_pitman_split_y", d_rational.r12[:, 1] - d_rational.r13[:, 1]),
        ("peak_difference_r12_x", d_real.r12[:, 0] - d_rational.r12[:, 0]),
        ("peak_difference_r13_x", d_real.r13[:, 0] - d_rational.r13[:, 0]),
        ("peak_difference_net_torque", d_real.net_torque - d_rational.net_torque),
        ("peak_kinematic_r12_y", d_rational.r12[:, 1] - d_ideal.r12[:, 1]),
        ("peak_kinematic_r13_y", d_rational.r13[:, 1] - d_ideal.r13[:, 1]),
        ("peak_kinematic_net_torque", d_rational.net_torque - d_ideal.net_torque),
        ("peak_total_difference_net_torque", d_real.net_torque - d_ideal.net_torque),
        ("peak_torsion_2", d_joints.torsion2),
        ("peak_torsion_3", d_joints.torsion3),
        *((f"peak_{name}", getattr(d_joints, name)) for name in JOINT_MOMENTS),
    ):
        _peak(summary, name, theta, values)
    summary.append(Scalar("equilibrium_residual", float(max(real.residual.max(), d_real.residual.max()))))
    model = pins.model()
    for name, value in (("crank_pin_stiffness", model.crank_pin_stiffness),
                        ("equalizer_pin_stiffness", model.equalizer_pin_stiffness),
                        ("crank_pin_clearance", model.crank_pin_clearance),
                        ("equalizer_pin_clearance", model.equalizer_pin_clearance)):
        if np.isfinite(value):
            summary.append(Scalar(name, value))
    summary += [
        Scalar("compatibility_residual", float(max(contact.compatibility_residual.max(),
                                                            d_contact.compatibility_residual.max()))),
        Scalar("contact_residual", float(max(contact.contact_residual.max(), d_contact.contact_residual.max()))),
        Scalar("contact_iterations", float(max(contact.iterations.max(), d_contact.iterations.max()))),
    ]
    panels = (
        Panel("R12 y ([Spatial7SK12] fig. 11)", ("r12_y_real",), ("r12_y_rational",)),
        Panel("R13 y ([Spatial7SK12] fig. 12)", ("r13_y_real",), ("r13_y_rational",)),
        Panel("R12, R13 x ([Spatial7SK12] fig. 13)", ("r12_x_real", "r13_x_real"), ("r12_x_rational",)),
        Panel("net gearbox torque M_z ([Spatial7SK12] fig. 14)", ("net_torque_real",), ("net_torque_rational",)),
    )
    title = (f"{unit.name}: real against rational mechanism (same errors; crank phase of the "
             f"{errors.crank_phase_mode.replace('-', ' ')}), card {card.name}, {crank_motion} rotation")
    return Result(title, tuple(summary), tuple(columns), panels, dead_position_marks(unit.geometry.mechanism()))
