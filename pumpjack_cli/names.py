"""The catalogue of output names: every column and summary name, declared once.

Each :class:`Entry` gives a name (or a family of names), its quantity kind (a key of
:data:`pumpjack_cli.quantities.OUTPUT_QUANTITIES`, or ``text``) and its meaning; the
results (:class:`~pumpjack_cli.results.Scalar`, :class:`~pumpjack_cli.results.Column`)
take their quantity and description from here by name, so one name has one meaning in
every command. A family is written with placeholders in braces, each a key of
:data:`VOCABULARY`: ``{extreme}_rod_load`` is ``max_rod_load`` ("largest polished-rod
load") and ``min_rod_load``. The output-name sections of ``docs/glossary.md`` are
generated from this catalogue (:func:`glossary_sections`; ``tests/architecture/test_glossary.py``
compares them).

Adding an output name is one entry here (``docs/architecture.md``). Pure Python: the
renderer and ``pumpjack units`` use it at start-up.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass
from functools import cache

#: Quantity kind of a text value (a label, a designation): no unit, no conversion.
TEXT = "text"

#: The alternatives of each placeholder: spelling in a name -> words in a meaning.
VOCABULARY: dict[str, dict[str, str]] = {
    "extreme": {"max": "largest", "min": "smallest"},
    "approximation": {"harmonic": "elementary theory (harmonic)", "two_term": "refined theory (two-term)"},
    "law": {"harmonic": "harmonic law (elementary theory, [InertiaUNB600A] eq. 3)",
            "two_term": "two-term law (refined theory, cos phi + lambda cos 2 phi, [InertiaUNB600A] eq. 4)",
            "series4": "trigonometric series to the 4th harmonic", "series6": "trigonometric series to the 6th harmonic",
            "chord": "chord law (horsehead arc taken as its chord, [InertiaUNB600A] eq. 7)"},
    "axis": {"x": "x (towards the well)", "y": "y (up)", "z": "z (along the crank shaft)"},
    "planar_axis": {"x": "about x (towards the well)", "y": "about y (up)"},
    "reaction": {"r12": "R12, crank on pitman 2 at crank pin A", "r13": "R13, crank on pitman 3 at crank pin A1",
                 "r24": "R24, pitman 2 on the equalizer at B", "r34": "R34, pitman 3 on the equalizer at B1",
                 "r45": "R45, equalizer on the beam at D", "r05": "R05, frame on the beam at the centre bearing C",
                 "r01": "R01, frame on the crank at the shaft bearings"},
    "pitman_force": {"r12": "R12", "r13": "R13"},
    "bearing": {"m05": "M_R05, frame on the beam at the centre bearing", "m01": "M_R01, frame on the crank at the shaft bearings"},
    "joint": {"m12": "M_R12, crank pin A", "m13": "M_R13, crank pin A1", "m24": "M_R24, equalizer pin B",
              "m34": "M_R34, equalizer pin B1"},
    "side": {"2": "pitman 2 (AB)", "3": "pitman 3 (A1B1)"},
    "mechanism": {"ideal": "error-free rational mechanism", "rational": "rational mechanism with the same errors",
                  "real": "real mechanism (revolute pins, elastic pitmans, errors)",
                  "kinematic": "rational with the errors minus error-free (the errors' kinematic part)",
                  "difference": "real minus rational with the same errors (the redundancy part)"},
    "angular_deviation": {"crank_phase": "crank pin A1 ahead of A in the direction of rotation",
                  "crank_pin_tilt_radial": "pin A1 bore turned about the arm's radial line",
                  "crank_pin_tilt_tangential": "pin A1 bore turned about the arm's tangent",
                  "equalizer_pin_roll": "pin B1 bore turned about the beam's long axis",
                  "equalizer_pin_yaw": "pin B1 bore turned about the vertical across the beam"},
    "length_deviation": {"crank_radius": "crank radius of A1 minus that of A",
                         "pitman_length": "pitman A1B1 minus pitman AB"},
    "pin": {"crank": "crank pins A, A1", "equalizer": "equalizer pins B, B1"},
    "dead_centre": {"outer": "outer", "inner": "inner"},
    "section": {str(n): str(n) for n in range(1, 5)},
    "taper": {str(n): str(n) for n in range(1, 21)},
    "end": {"top": "top", "bottom": "bottom"},
    "stroke_part": {"upstroke": "upstroke", "downstroke": "downstroke"},
    "analysis": {"torque": "torque", "downhole": "downhole"},
}
_PLACEHOLDER = re.compile(r"\{(\w+)\}")


@dataclass(frozen=True)
class Entry:
    """An output name or a family of them: ``pattern`` (placeholders in braces, keys of
    :data:`VOCABULARY`), its quantity kind, its meaning (placeholders filled with the
    words of each alternative) and its symbol in the literature (for the glossary)."""

    pattern: str
    quantity: str
    meaning: str
    symbol: str = ""

    def expand(self) -> dict[str, tuple[str, str]]:
        """Every name of the family -> (quantity, meaning)."""
        keys = _PLACEHOLDER.findall(self.pattern)
        found = {}
        for combo in itertools.product(*(VOCABULARY[key].items() for key in keys)):
            name, meaning = self.pattern, self.meaning
            for key, (spelling, words) in zip(keys, combo):
                name = name.replace("{" + key + "}", spelling, 1)
                meaning = meaning.replace("{" + key + "}", words, 1)
            found[name] = (self.quantity, meaning)
        return found

    @property
    def glossary_name(self) -> str:
        """The family in the glossary's brace notation: ``{max,min}_rod_load``."""
        return _PLACEHOLDER.sub(lambda m: "{" + ",".join(VOCABULARY[m.group(1)]) + "}", self.pattern)


@dataclass(frozen=True)
class Section:
    """A group of entries as the glossary shows them: a title and an introduction."""

    title: str
    introduction: str
    entries: tuple[Entry, ...]


E = Entry
SECTIONS: tuple[Section, ...] = (
    Section("Bundled units (`units`)", "", (
        E("name", TEXT, "name to give to the commands (file stem)"),
        E("kind", TEXT, "machine kind: beam-pump or slider-crank"),
        E("designation", TEXT, "unit designation, e.g. SK8-3,5-4000"),
        E("description", TEXT, "one line about the file"),
    )),
    Section("Kinematics (`kinematics`, and columns shared by other commands)",
            "Beam units' crank angle is measured from 12 o'clock in the direction of rotation ([API11E]).", (
        E("crank_angle", "angle", "crank angle (beam units: from 12 o'clock in the direction of rotation; "
          "slider-crank machines: from the line of stroke)", "θ ([API11E]), φ1 (seeds)"),
        E("time", "time", "time from crank angle 0", "t"),
        E("crank_speed", "angular_velocity", "crank angular velocity (summary: the uniform speed)", "ω1"),
        E("crank_acceleration", "angular_acceleration", "crank angular acceleration", "ε1"),
        E("strokes_per_minute", "stroke_rate", "pumping speed, 60 ω1 / 2π (the mean for non-uniform rotation)", "N"),
        E("period", "time", "time of one stroke cycle, 2π / ω1 (mean speed for non-uniform rotation)", "T"),
        E("stroke", "length", "exact stroke of the polished rod (or the piston of a slider-crank machine)", "S"),
        E("crank_angle_bottom", "angle", "crank angle of the bottom dead position (start of the upstroke)"),
        E("crank_angle_top", "angle", "crank angle of the top dead position (start of the downstroke)"),
        E("{stroke_part}_crank_travel", "angle", "crank rotation during the {stroke_part}"),
        E("position", "length", "polished-rod position above the bottom of the stroke (slider-crank machines: "
          "the slider's from its inner dead centre)", "s_E"),
        E("velocity", "velocity", "polished-rod velocity, up positive (slider-crank machines: the slider's)", "v_E"),
        E("acceleration", "acceleration", "polished-rod acceleration, up positive (slider-crank machines: the "
          "slider's)", "a_E"),
        E("torque_factor", "length", "API 11E torque factor ds/dθ: crank torque per unit polished-rod load; "
          "TF·ω1 = v_E", "TF ([API11E])"),
        E("beam_angle", "angle", "front arm above horizontal", "ψ (φ3)"),
        E("beam_angular_velocity", "angular_velocity", "dψ/dt, front arm up positive", "ω5 (ω3 in [SK8Rotation2013])"),
        E("beam_angular_acceleration", "angular_acceleration", "d²ψ/dt²", "ε5"),
        E("pitman_angle", "angle", "direction crank pin → equalizer bearing above horizontal", "χ (φ2)"),
        E("pitman_angular_velocity", "angular_velocity", "dχ/dt, counterclockwise positive", "ω2"),
        E("pitman_angular_acceleration", "angular_acceleration", "d²χ/dt²", "ε2"),
        E("position_{approximation}", "length", "polished-rod position by the {approximation} ([Aliverdizade1951], "
          "[NUNG])"),
        E("velocity_{approximation}", "velocity", "polished-rod velocity by the {approximation}"),
        E("{extreme}_velocity", "velocity", "{extreme} polished-rod velocity over the cycle"),
        E("{extreme}_acceleration", "acceleration", "{extreme} polished-rod acceleration over the cycle"),
        E("{extreme}_torque_factor", "length", "{extreme} torque factor over the cycle"),
        E("{extreme}_velocity_crank_angle", "angle", "crank angle of the {extreme} polished-rod velocity"),
        E("{extreme}_acceleration_crank_angle", "angle", "crank angle of the {extreme} polished-rod acceleration"),
        E("{extreme}_torque_factor_crank_angle", "angle", "crank angle of the {extreme} torque factor"),
        E("{approximation}_position_error", "percent", "{approximation}: max |Δs| / stroke"),
        E("{approximation}_velocity_error", "percent", "{approximation}: max |Δv| / max |v|"),
        E("{approximation}_acceleration_error", "percent", "{approximation}: max |Δa| / max |a|"),
        E("{approximation}_peak_acceleration_error", "percent", "{approximation}: max |a| of the law / exact "
          "max |a| − 1"),
    )),
    Section("Reactions and moments (`reactions`, `compare-redundancy`)",
            "Link numbering of [Spatial7SK12] / [PopovychSenchishak]; R_ij is the force of link i on link j.", (
        E("rod_load", "force", "polished-rod load", "W, F_sht"),
        E("{reaction}_{axis}", "force", "{reaction}, component {axis}", "R12 … R01"),
        E("{bearing}_{planar_axis}", "torque", "{bearing}, bearing moment {planar_axis}", "M_R05, M_R01"),
        E("net_torque", "torque", "net gearbox torque on the crank, + when the gearbox drives the crank in its "
          "direction of rotation (the balancing torque M_z of the seeds)", "T, M_z"),
        E("{extreme}_net_torque", "torque", "{extreme} net gearbox torque over the cycle"),
        E("{extreme}_net_torque_crank_angle", "angle", "crank angle of the {extreme} net gearbox torque"),
        E("peak_{reaction}", "force", "largest magnitude of {reaction}"),
        E("peak_{reaction}_crank_angle", "angle", "crank angle of the largest magnitude of {reaction}"),
        E("peak_{bearing}", "torque", "largest magnitude of {bearing}"),
        E("peak_{bearing}_crank_angle", "angle", "crank angle of the largest magnitude of {bearing}"),
        E("mean_crank_speed", "angular_velocity", "mean crank speed, 2π / cycle time"),
        E("equilibrium_residual", "ratio", "max |E x − f| of the equilibrium equations / largest load"),
        E("{joint}_{axis}", "torque", "joint moment {joint} of the real mechanism, {axis}", "M_R12 … M_R34"),
        E("torsion_{side}", "torque", "torque of {side} about its own axis", "M_kp2, M_kp3"),
        E("{reaction}_{axis}_{mechanism}", "force", "{reaction}, {axis}: {mechanism}"),
        E("net_torque_{mechanism}", "torque", "net gearbox torque M_z: {mechanism}"),
        E("peak_kinematic_{pitman_force}_y", "force", "largest |Δ{pitman_force}y|, rational with the errors − "
          "error-free (the kinematic part)"),
        E("peak_kinematic_{pitman_force}_y_crank_angle", "angle", "crank angle of the largest kinematic part of "
          "{pitman_force}y"),
        E("peak_kinematic_net_torque", "torque", "largest |ΔM_z|, rational with the errors − error-free (the "
          "kinematic part)"),
        E("peak_kinematic_net_torque_crank_angle", "angle", "crank angle of the largest kinematic part of M_z"),
        E("peak_total_difference_net_torque", "torque", "largest |ΔM_z|, real mechanism with the errors − "
          "error-free rational (both parts)"),
        E("peak_total_difference_net_torque_crank_angle", "angle", "crank angle of the largest total difference "
          "of M_z"),
        E("peak_rational_pitman_split_y", "force", "largest |R12y − R13y| in the rational mechanism with the errors"),
        E("peak_rational_pitman_split_y_crank_angle", "angle", "crank angle of the largest |R12y − R13y| in the "
          "rational mechanism with the errors"),
        E("peak_difference_{pitman_force}_{axis}", "force", "largest |Δ{pitman_force}| {axis}, real − rational "
          "with the same errors (the redundancy part)"),
        E("peak_difference_{pitman_force}_{axis}_crank_angle", "angle", "crank angle of the largest redundancy "
          "part of {pitman_force} {axis}"),
        E("peak_difference_net_torque", "torque", "largest |ΔM_z|, real − rational with the same errors (the "
          "redundancy part)"),
        E("peak_difference_net_torque_crank_angle", "angle", "crank angle of the largest redundancy part of M_z"),
        E("peak_pitman_split_y", "force", "largest |R12y − R13y| in the real mechanism"),
        E("peak_pitman_split_y_crank_angle", "angle", "crank angle of the largest |R12y − R13y| in the real "
          "mechanism"),
        E("peak_torsion_{side}", "torque", "largest |torque| of {side} about its axis"),
        E("peak_torsion_{side}_crank_angle", "angle", "crank angle of the largest torque of {side} about its axis"),
        E("peak_{joint}", "torque", "largest magnitude of {joint}"),
        E("peak_{joint}_crank_angle", "angle", "crank angle of the largest magnitude of {joint}"),
        E("deviation_{angular_deviation}", "angle", "error of side 3 used: {angular_deviation}"),
        E("deviation_{length_deviation}", "length", "error of side 3 used: {length_deviation}"),
        E("compatibility_residual", "ratio", "real mechanism: Menabrea's condition |A y − b + gᵀλ| / |b|"),
        E("contact_residual", "ratio", "real mechanism: largest violation of the joints' contact conditions, "
          "relative to the moments' scale"),
        E("contact_iterations", "count", "most active-set iterations at one crank angle (1 without clearance)"),
        E("{pin}_pin_stiffness", "rotational_stiffness", "rotational stiffness of the {pin} across their axes"),
        E("{pin}_pin_clearance", "angle", "free tilt of the {pin}: radial clearance / bearing width"),
    )),
    Section("Dynamics (`dynamics`)", "The machine's equation of motion ([SK8Rotation2013]).", (
        E("motor_speed", "angular_velocity", "motor shaft speed"),
        E("motor_torque", "torque", "motor shaft torque (linear characteristic)"),
        E("motor_power", "power", "motor shaft power"),
        E("velocity_uniform", "velocity", "polished-rod velocity at uniform rotation at the rated crank speed"),
        E("acceleration_uniform", "acceleration", "polished-rod acceleration at uniform rotation at the rated "
          "crank speed"),
        E("inertia_torque", "torque", "torque spent accelerating the moving masses of links and drive, "
          "I ε1 + ½ I′ ω1²", "I ε1 + ½ I′ ω1²"),
        E("constant_inertia_torque", "torque", "I_const ε1 (M_i1 of [SK8Rotation2013])", "M_i1"),
        E("rod_load_torque", "torque", "torque of the polished-rod load, TF W", "TF W"),
        E("gravity_torque", "torque", "torque of the links' weights and counterweights"),
        E("reduced_inertia", "moment_of_inertia", "reduced moment of inertia", "I"),
        E("reduced_inertia_rate", "moment_of_inertia", "dI/dθ, per radian", "dI/dθ"),
        E("rated_crank_speed", "angular_velocity", "crank speed at the motor's rated speed"),
        E("start_crank_speed", "angular_velocity", "crank speed at the start of the upstroke"),
        E("{extreme}_crank_speed", "angular_velocity", "{extreme} crank speed over the cycle"),
        E("{extreme}_crank_speed_crank_angle", "angle", "crank angle of the {extreme} crank speed"),
        E("{extreme}_crank_acceleration", "angular_acceleration", "{extreme} crank acceleration over the cycle"),
        E("{extreme}_crank_acceleration_crank_angle", "angle", "crank angle of the {extreme} crank acceleration"),
        E("{extreme}_motor_torque", "torque", "{extreme} motor torque over the cycle (negative: generating)"),
        E("{extreme}_motor_torque_crank_angle", "angle", "crank angle of the {extreme} motor torque"),
        E("{extreme}_motor_power", "power", "{extreme} motor power over the cycle (negative: generating)"),
        E("{extreme}_motor_power_crank_angle", "angle", "crank angle of the {extreme} motor power"),
        E("max_static_torque", "torque", "largest crank torque of load and weights without inertia"),
        E("max_static_torque_crank_angle", "angle", "crank angle of the largest static crank torque"),
        E("speed_fluctuation", "percent", "coefficient of speed fluctuation (ω_max − ω_min) / ω_mean", "δ"),
        E("energy_per_cycle", "energy", "energy the motor delivers per cycle"),
        E("rod_work_per_cycle", "energy", "work of the polished-rod load per cycle"),
        E("mean_motor_power", "power", "mean motor power over the cycle"),
        E("constant_inertia", "moment_of_inertia", "constant part of the reduced inertia: drive, crank arms and "
          "counterweights", "I0 + I_dr + m_pr r_pr²"),
        E("starting_torque", "torque", "motor starting torque reduced to the crank"),
        E("breakdown_torque_margin", "ratio", "motor pull-out torque / largest motor torque"),
        E("shooting_iterations", "count", "integrations of the cycle to find the periodic start speed"),
        E("periodicity_error", "ratio", "how far the computed cycle is from periodic: relative change over the last "
          "cycle (crank speed of the rigid-rod model; pump card of the wave model)"),
        E("rtol", "ratio", "relative tolerance of the integration (DOP853)"),
        E("{stroke_part}_rod_load", "force", "polished-rod load of the rigid-rod well model on the {stroke_part}"),
        E("rod_weight", "force", "weight of the rods in the well fluid (rigid-rod well model)"),
        E("fluid_load", "force", "fluid load on the plunger, (p_d − p_i) A_p; from a pump card, its upstroke minus "
          "downstroke load level", "F_o"),
        E("plunger_friction", "force", "plunger-barrel friction (rigid-rod well model)"),
        E("tubing_friction", "force", "hydraulic loss of the fluid in the tubing on the upstroke (rigid-rod well "
          "model)"),
        E("rod_friction", "force", "viscous drag of the rods on the downstroke (rigid-rod well model)"),
    )),
    Section("Inertia-force laws (`inertia-error`)",
            "Laws: `harmonic` (sinusoidal), `two_term` (first approximation), `series4`, `series6` "
            "(slider-crank), `chord` (beam unit: arc taken as its chord).", (
        E("inertia_force", "force", "inertia force −m a, exact"),
        E("acceleration_{law}", "acceleration", "acceleration by the {law} (`kinematics`: the polished rod's)"),
        E("deviation_{law}", "acceleration", "acceleration of the {law} minus the exact"),
        E("inertia_force_{law}", "force", "inertia force −m a by the {law}"),
        E("peak_acceleration", "acceleration", "exact max |a| over the cycle"),
        E("peak_crank_angle", "angle", "crank angle of the exact max |a|"),
        E("peak_inertia_force", "force", "m max |a|, exact"),
        E("{law}_peak_acceleration", "acceleration", "{law}: max |a|"),
        E("{law}_peak_inertia_force", "force", "{law}: max |Φ|"),
        E("{law}_peak_error", "percent", "{law}: |1 − max |Φ| / exact max |Φ|| (δ of [InertiaUNB600A])"),
        E("{law}_peak_error_of_law", "percent", "{law}: |1 − exact max |Φ| / max |Φ||"),
        E("{law}_max_deviation", "percent", "{law}: max |Φ − exact Φ| / exact max |Φ|"),
        E("{law}_rms_deviation", "percent", "{law}: rms(Φ − exact Φ) / rms(exact Φ)"),
        E("crank_to_rod_ratio", "ratio", "λ = r / l2"),
        E("offset", "length", "e: line of stroke above the crank shaft"),
        E("travel", "length", "slider travel from the outer dead centre towards the crank"),
        E("slider_length", "length", "L: clamped end A to guide B"),
        E("alpha_{section}", "ratio", "α_{section} = J_{section} / J_0, J_0 the smallest section"),
        E("guide_force", "force", "R_B: force of guide B on the slider, up positive"),
        E("guide_moment", "torque", "M_B: moment of guide B on the slider, counterclockwise positive"),
        E("outer_edge_reaction", "force", "R′: reaction at the outer edge of guide B"),
        E("inner_edge_reaction", "force", "R″: reaction at the inner edge of guide B"),
        E("guide_friction", "force", "friction in guide B, f (|R′| + |R″|)"),
        E("support_position", "length", "z_C: intermediate support from the clamped end A"),
        E("support_reaction", "force", "Y_C: force of the intermediate support on the slider"),
        E("support_friction", "force", "f |Y_C|, friction at the intermediate support"),
        E("total_friction", "force", "friction in guide B and at the intermediate support"),
        E("{extreme}_guide_friction", "force", "{extreme} friction in guide B over the cycle"),
        E("{extreme}_guide_friction_crank_angle", "angle", "crank angle of the {extreme} friction in guide B"),
        E("guide_friction_{dead_centre}_dead_centre", "force", "friction in guide B at the {dead_centre} dead centre"),
        E("total_friction_{dead_centre}_dead_centre", "force", "friction in guide B and at the intermediate "
          "support at the {dead_centre} dead centre"),
    )),
    Section("Gearbox torque and counterbalance (`torque`)",
            "API 11E symbols: TF torque factor, W polished-rod load, B structural unbalance, M maximum "
            "counterbalance moment, τ crank offset, CBE counterbalance effect, T net torque ([API11E], "
            "[Rowlan2004]); the component names follow [Takacs2016].", (
        E("structural_unbalance", "force", "force at the polished rod that holds the beam level with the pitmans "
          "off the crank pins, downward positive", "B"),
        E("counterbalance_moment", "torque", "present counterbalance: largest moment of cranks and counterweights",
          "M"),
        E("crank_offset", "angle", "lag of the counterweights' resultant behind the crank pin", "τ"),
        E("counterbalance_effect", "force", "present counterbalance effect: the polished-rod load the "
          "counterbalance holds with the cranks horizontal, B + M sin(90° − τ)/TF(90°)", "CBE"),
        E("structural_torque", "torque", "torque of the structural unbalance, −TF B", "−TF B"),
        E("counterbalance_torque", "torque", "torque of the counterbalance, −M sin(θ − τ)", "−M sin(θ − τ)"),
        E("articulating_inertia_torque", "torque", "inertia torque of the beam group (through TF) ([Takacs2016])"),
        E("rotary_inertia_torque", "torque", "inertia torque of cranks and counterweights, I_r α ([Takacs2016])"),
        E("api_net_torque", "torque", "net gearbox torque by the API 11E torque-factor method"),
        E("exact_net_torque", "torque", "net gearbox torque by the spatial kinetostatics"),
        E("exact_minus_api_torque", "torque", "exact minus API net gearbox torque"),
        E("recommended_net_torque", "torque", "net gearbox torque with the recommended counterbalance"),
        E("permissible_load_{extreme}", "force", "{extreme} polished-rod load that keeps |T| within the gearbox "
          "rating (permissible load diagram, [GaultSWPSC])"),
        E("peak_net_torque", "torque", "largest |net gearbox torque| over the cycle"),
        E("peak_net_torque_crank_angle", "angle", "crank angle of the largest |net gearbox torque|"),
        E("recommended_counterbalance_moment", "torque", "the counterbalance moment M that meets the balance "
          "criterion (--balance)"),
        E("recommended_counterbalance_effect", "force", "counterbalance effect of the recommended counterbalance, "
          "cranks horizontal"),
        E("recommended_peak_net_torque", "torque", "largest |net gearbox torque| with the recommended "
          "counterbalance"),
        E("recommended_{stroke_part}_peak_torque", "torque", "largest net gearbox torque of the {stroke_part} with "
          "the recommended counterbalance"),
        E("recommended_counterweight_radius", "length", "radius of the present blocks that gives the recommended "
          "moment"),
        E("recommended_counterweight_mass", "mass", "mass of all blocks at the present radius that gives the "
          "recommended moment"),
        E("card_work", "energy", "work on the rods per cycle (the card's area)"),
        E("polished_rod_power", "power", "polished-rod power: card work × cycles per second", "PRHP"),
        E("rms_net_torque", "torque", "RMS (equivalent) net gearbox torque over time", "T_rms"),
        E("cyclic_load_factor", "ratio", "T_rms / T_mean ([DurhamLockard1988])", "CLF"),
        E("rms_motor_power", "power", "motor power for the RMS net torque at the mean speed, over the drive "
          "efficiency ([DurhamLockard1988])"),
        E("gearbox_rating", "torque", "gearbox peak torque rating (designation or [rating])"),
        E("structure_rating", "force", "structure (polished-rod load) rating (designation or [rating])"),
        E("max_stroke", "length", "maximum stroke of the unit (designation or [rating])"),
        E("gearbox_loading", "percent", "peak |T| / gearbox rating, present counterbalance"),
        E("recommended_gearbox_loading", "percent", "peak |T| / gearbox rating, recommended counterbalance"),
        E("structure_loading", "percent", "peak polished-rod load / structure rating"),
        E("stroke_loading", "percent", "stroke / maximum stroke"),
        E("peak_exact_minus_api_torque", "torque", "largest |exact − API net gearbox torque|"),
    )),
    Section("Rod string and pump card (`downhole`)",
            "Symbols of [Gibbs1963], [EverittJennings1992] and [API11L]; definitions in `docs/downhole.md`. The "
            "surface card's columns are `time`, `crank_angle`, `position` and `rod_load`, as in the other commands.", (
        E("pump_position", "length", "plunger position, up positive (datums in docs/downhole.md and "
          "docs/predict.md)"),
        E("pump_load", "force", "net plunger load: rod tension at the pump above the buoyant-weight datum, "
          "(p_d − p_chamber) A_p"),
        E("damping_factor", "ratio", "Gibbs' dimensionless damping factor of the rods, c = π a ν / (2 L)", "ν"),
        E("buoyant_rod_weight", "force", "weight of the rods with couplings in the well fluid: the pump card's "
          "datum", "W_rf"),
        E("gross_pump_stroke", "length", "plunger travel", "S_g"),
        E("net_pump_stroke", "length", "plunger travel through liquid: the liquid discharged per stroke over the "
          "plunger area", "S_n"),
        E("pump_fillage", "percent", "net over gross pump stroke (predict: the liquid fillage simulated)"),
        E("rp11l_counterbalance_effect", "force", "design counterbalance effect of API RP 11L, 1.06 (W_rf + F_o/2) "
          "([API11L])", "CBE"),
        E("{extreme}_pump_load", "force", "{extreme} net plunger load (a negative minimum is compression at the "
          "pump)"),
        E("surface_card_work", "energy", "work of the surface card per cycle (its loop area)"),
        E("pump_card_work", "energy", "work of the pump card per cycle: the work on the fluid"),
        E("pump_displacement", "flow_rate", "liquid the pump discharges per unit time: net stroke × plunger area × "
          "strokes per unit time", "Q"),
        E("pump_intake_pressure", "pressure", "discharge pressure at the pump minus fluid load / plunger area",
          "p_i"),
        E("taper_{taper}_{end}_{extreme}_stress", "stress", "{extreme} stress (load over metal area) at the {end} "
          "of taper {taper}, top taper first"),
        E("taper_{taper}_goodman_loading", "percent", "modified Goodman loading of taper {taper}: stress range over "
          "the allowable range ([API11BR])"),
    )),
    Section("Predicted cards (`predict`, `dynamics --well-model wave`)",
            "The rods as a damped wave equation driven by the exact polished-rod motion, the pump's valves at the "
            "bottom ([Gibbs1963]); definitions in `docs/predict.md`. Card columns and pump-card names as in "
            "`downhole`; the torque names as in `torque`.", (
        E("{extreme}_rod_load", "force", "{extreme} polished-rod load of the cycle (PPRL, MPRL)", "PPRL, MPRL"),
        E("{extreme}_rod_load_crank_angle", "angle", "crank angle of the {extreme} polished-rod load"),
        E("chamber_pressure", "pressure", "pressure in the pump chamber below the plunger", "p_c"),
        E("static_stretch", "length", "F_o times the compliance of rods and (unanchored) tubing"),
        E("damping_dissipation", "energy", "work of the rods' damping per cycle, ∫∫ c m u_t² dx dt"),
        E("rod_energy_residual", "ratio", "(surface card work − pump card work − damping dissipation) / surface "
          "card work"),
        E("machine_energy_residual", "ratio", "(motor work − polished-rod work) / motor work over a cycle of the "
          "coupled solution"),
        E("cycles", "count", "cycles marched to the periodic state"),
        E("revolutions", "count", "revolutions of the coupled solution marched to the periodic state"),
        E("{extreme}_inertia_torque", "torque", "{extreme} inertia torque of links and drive over the cycle"),
        E("{extreme}_inertia_torque_crank_angle", "angle", "crank angle of the {extreme} inertia torque"),
        E("uniform_{extreme}_rod_load", "force", "{extreme} polished-rod load of the same well at uniform rotation "
          "at the coupled solution's mean speed"),
        E("uniform_peak_net_torque", "torque", "largest |net gearbox torque| at uniform rotation at the coupled "
          "solution's mean speed"),
        E("rigid_rod_speed_fluctuation", "percent", "speed fluctuation of the rigid-rod model of [SK8Rotation2013] "
          "(`pumpjack dynamics`)"),
        E("rigid_rod_max_motor_torque", "torque", "largest motor torque of the rigid-rod model"),
        E("rigid_rod_peak_inertia_torque", "torque", "largest |inertia torque| of the rigid-rod model"),
        E("rigid_rod_{extreme}_rod_load", "force", "{extreme} polished-rod load of the rigid-rod model"),
    )),
    Section("Results store (`batch run`, `batch export`, `batch trend`)",
            "A row per card and analysis; the summary values are the analysis' own names with their SI suffix, as "
            "its single command prints them with `-f json`.", (
        E("well", TEXT, "the manifest's well"),
        E("card", TEXT, "the card file"),
        E("timestamp", TEXT, "the manifest's time stamp of the card"),
        E("unit", TEXT, "the manifest's unit (bundled name or file)"),
        E("card_sha256", TEXT, "SHA-256 of the card file's bytes"),
        E("analysis", TEXT, "`torque` or `downhole`"),
        E("options_sha256", TEXT, "hash of what makes the result: analysis, its options, the unit file's content, "
          "the row's overrides"),
        E("options", TEXT, "what makes the result, the JSON text hashed in `options_sha256`; in `trend`, what "
          "differs between the results of a card (`--method exact`)"),
        E("status", TEXT, "`ok` or `error`"),
        E("error", TEXT, "the one-line message the single command prints"),
        E("warnings", TEXT, "the analysis' warnings, joined by ` | `"),
        E("{analysis}_status", TEXT, "(`trend`) the status of the {analysis} analysis of the card"),
    )),
)
del E


@cache
def catalogue() -> dict[str, tuple[str, str]]:
    """Every output name -> (quantity kind, meaning); a name declared twice is an error."""
    found: dict[str, tuple[str, str]] = {}
    for section in SECTIONS:
        for entry in section.entries:
            for name, value in entry.expand().items():
                if name in found:
                    raise ValueError(f"output name {name!r} is declared twice in the catalogue")
                found[name] = value
    return found


def lookup(name: str) -> tuple[str, str]:
    """(quantity kind, meaning) of an output name; KeyError for a name not in the catalogue.

    >>> lookup("max_rod_load")
    ('force', 'largest polished-rod load of the cycle (PPRL, MPRL)')
    """
    try:
        return catalogue()[name]
    except KeyError:
        raise KeyError(f"output name {name!r} is not in the catalogue (pumpjack_cli/names.py)") from None


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def glossary_sections() -> str:
    """The output-name sections of ``docs/glossary.md``, as Markdown, from the catalogue."""
    blocks = []
    for section in SECTIONS:
        lines = [f"## {section.title}", ""]
        if section.introduction:
            lines += [section.introduction, ""]
        lines += ["| name | symbol | quantity | meaning |", "|---|---|---|---|"]
        for entry in section.entries:
            keys = _PLACEHOLDER.findall(entry.pattern)
            meaning = entry.meaning
            for key in keys:
                words = VOCABULARY[key].values()
                shown = " / ".join(words) if len(VOCABULARY[key]) <= 3 else f"each of the {key.replace('_', ' ')}s"
                meaning = meaning.replace("{" + key + "}", shown, 1)
            lines.append(f"| `{entry.glossary_name}` | {_cell(entry.symbol)} | {entry.quantity.replace('_', ' ')} | "
                         f"{_cell(meaning)} |")
        blocks.append("\n".join(lines))
    return "\n\n".join(blocks) + "\n"


if __name__ == "__main__":
    print(glossary_sections(), end="")
