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

from .quantities import UNIT_SYSTEMS, output_unit

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
    "balance": {"": "present", "recommended_": "recommended"},
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
    Section("Units (`units`, `units --catalogue`)",
            "The bundled units, or the rows of an operator's catalogue ([catalogue.md](catalogue.md)).", (
        E("name", TEXT, "name to give to the commands (a bundled unit's file stem, a catalogue's DESIGNATION/HOLE)"),
        E("kind", TEXT, "machine kind: beam-pump or slider-crank"),
        E("designation", TEXT, "unit designation, e.g. SK8-3,5-4000"),
        E("description", TEXT, "one line about the file"),
        E("crank_hole", TEXT, "crank hole of a catalogue row, 1 for the longest stroke"),
        E("unit_class", TEXT, "kind of beam unit, its [geometry] class: conventional, mark-ii, ..."),
        E("published_stroke", "length", "stroke the catalogue gives for the crank hole (empty if none)"),
        E("stroke_difference", "length", "exact stroke minus the published stroke"),
        E("stroke_check", TEXT, "ok, differs (by more than 0.5 in) or not published"),
        E("source", TEXT, "where a catalogue row's data come from"),
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
          "cycle (crank speed of the rigid-rod model; pump card of the wave model, over the repeat_strokes last "
          "strokes)"),
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
        E("crank_offset", "angle", "crank offset: the lead of the counterweights' resultant ahead of the crank pin "
          "(class I) or of the crank's tail (class III), in the direction of rotation; negative a lag "
          "(docs/conventions.md)", "τ"),
        E("beam_counterweight", "force", "present weight of the beam counterweight (beam-balanced unit)", "W_cb"),
        E("beam_counterweight_arm", "length", "the beam counterweight's distance from the centre bearing along "
          "the beam, towards the well positive"),
        E("air_pressure", "pressure", "present gauge pressure of the air cylinder at its stated position "
          "(air-balanced unit)", "p_r"),
        E("air_piston_area", "area", "piston area of the air cylinder", "A_c"),
        E("air_bottom_volume", "gas_volume", "gas volume of the air cylinder at the bottom of the stroke", "V_b"),
        E("air_cylinder_lever", "length", "the air cylinder's pin on the beam from the centre bearing, towards "
          "the well positive", "d"),
        E("air_exponent", "ratio", "polytropic exponent of the air cylinder's gas", "n"),
        E("counterbalance_effect", "force", "present counterbalance effect: the polished-rod load the "
          "structure and counterbalance hold with the cranks horizontal on the upstroke (90°, a Mark II's 270°): "
          "−(T_s + T_c)/TF there; for class I crank counterweights B + M sin(90° + τ)/TF(90°)", "CBE"),
        E("structural_torque", "torque", "torque of the structural unbalance, −TF B", "−TF B"),
        E("counterbalance_torque", "torque", "torque of the counterbalance: crank counterweights −M sin(θ + τ) "
          "(class III: +M sin(θ + τ)), a beam counterweight or an air cylinder through TF", "T_c"),
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
        E("recommended_beam_counterweight", "force", "the beam counterweight that meets the balance criterion "
          "(--balance)"),
        E("recommended_air_pressure", "pressure", "the air cylinder's gauge pressure at its stated position that "
          "meets the balance criterion (--balance)"),
        E("recommended_counterbalance_effect", "force", "counterbalance effect of the recommended counterbalance, "
          "cranks horizontal on the upstroke"),
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
        E("{stroke_part}_peak_torque", "torque", "largest net gearbox torque of the {stroke_part}, present "
          "counterbalance"),
        E("{balance}rms_net_torque", "torque", "RMS (equivalent) net gearbox torque over time, {balance} "
          "counterbalance", "T_rms"),
        E("{balance}cyclic_load_factor", "ratio", "T_rms / T_mean, {balance} counterbalance ([DurhamLockard1988])",
          "CLF"),
        E("{balance}rms_motor_power", "power", "motor power for the RMS net torque at the mean speed, over the drive "
          "efficiency, {balance} counterbalance ([DurhamLockard1988])"),
        E("{balance}nema_motor_size", "power", "the smallest standard NEMA motor rating that covers the motor power "
          "by the RMS rule, {balance} counterbalance ([NEMAMG1])"),
        E("{balance}motor_energy", "daily_energy", "energy the motor gives a day (over the motor efficiency: takes), "
          "{balance} counterbalance: the work the gearbox does while it drives the unit, nothing credited back "
          "while the unit drives it"),
        E("{balance}energy_cost", "daily_cost", "cost of the motor energy a day at --electricity-price, {balance} "
          "counterbalance"),
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
          "datum in a vertical well", "W_rf"),
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
    Section("Pump condition, production and fluid level (`downhole`)",
            "What the pump card says ([Rowlan2008], [McCoyRowlanPodio], [EchometerLeakValve]); rules, sources and "
            "the accuracy study in `docs/diagnosis.md`. Positions along the stroke are shares of the gross pump "
            "stroke from its bottom; loads on the pump card are shares of the card's fluid load.", (
        E("pump_condition", TEXT, "condition of the pump read off the pump card: full, fluid_pound, gas_interference, "
          "travelling_valve_leak, standing_valve_leak, tagging_down, tagging_up, unanchored_tubing or rod_part"),
        E("pump_condition_confidence", "ratio", "0..1: the score of the condition's rule less half the next best"),
        E("pump_condition_second", TEXT, "the next best condition where its score reaches 0.25, else empty"),
        E("reference_fluid_load", "force", "F_o line of the pump card, (p_d − p_i) A_p from the well's fluid level "
          "(with none, the fluid level at the pump) ([Rowlan2008])", "F_o"),
        E("travelling_valve_closing", "percent", "where the load has risen 10 % of the fluid load on the upstroke: "
          "the travelling valve has closed"),
        E("standing_valve_opening", "percent", "where the load has risen 90 % of the fluid load on the upstroke: the "
          "standing valve opens"),
        E("standing_valve_closing", "percent", "where the load has fallen 10 % of the fluid load on the downstroke: "
          "the standing valve has closed"),
        E("travelling_valve_opening", "percent", "where the load has fallen 90 % of the fluid load on the "
          "downstroke: the travelling valve opens (on a gas card, the liquid and the gas compressed to p_d)"),
        E("pickup_travel", "length", "plunger travel from the travelling valve's closing to the standing valve's "
          "opening (the load-transfer slope is 0.8 F_o over it)"),
        E("unloading_travel", "length", "plunger travel from the standing valve's closing to the travelling valve's "
          "opening"),
        E("slow_upstroke_load", "percent", "mean load of the plunger rising slowly near the top (15-50 % of its mean "
          "speed, top quarter of the stroke); below 100 %: the load leaves before the top (a leaking travelling "
          "valve)"),
        E("slow_downstroke_load", "percent", "mean load of the plunger falling slowly near the bottom; above 0: the "
          "load comes back before the bottom (a leaking standing valve)"),
        E("bottom_spike", "percent", "how far the load falls below the downstroke level in the lowest 10 % of the "
          "stroke (tagging down)"),
        E("top_spike", "percent", "how far the load rises above the upstroke level in the highest 10 % of the "
          "stroke (tagging up)"),
        E("card_area_ratio", "percent", "pump card work / (reference fluid load × gross pump stroke): the card "
          "against the ideal rectangle"),
        E("rod_break_depth", "depth", "depth along the rods of a parted string's break: the free end the wave "
          "equation finds (`docs/cards.md`), else where the rods above weigh the card's mean load"),
        E("discharge_pressure", "pressure", "pressure above the plunger: tubing-head pressure + fluid gradient × "
          "the pump's true vertical depth", "p_d"),
        E("pump_submergence", "depth", "producing fluid level above the pump from the card's intake pressure and "
          "the casing-head pressure, gas-free gradient, (p_i − p_c)/(rho g)", "h"),
        E("fluid_level_depth", "depth", "producing fluid level below the surface, true vertical: pump true vertical "
          "depth − pump_submergence"),
        E("runtime", "percent", "share of the day the unit runs (--runtime, the manifest's runtime)"),
        E("pump_slippage", "flow_rate", "liquid slipping past the plunger, laminar flow through its clearance while "
          "it carries the load ([Wang2019]), averaged over the day's running time"),
        E("pump_efficiency", "percent", "stated volumetric efficiency of the pump (--pump-efficiency), instead of "
          "the slippage"),
        E("inferred_production", "flow_rate", "liquid produced per day: net stroke × plunger area × strokes per day "
          "× runtime, less slippage (or × the stated pump efficiency)", "Q"),
        E("system_efficiency", "ratio", "efficiency from the electricity supply to the polished rod "
          "(--system-efficiency; 1: the polished rod's own energy)", "η_s"),
        E("energy_per_day", "daily_energy", "energy the well takes from the supply per day: polished-rod power / "
          "system efficiency × 24 h × runtime"),
        E("electricity_cost", "daily_cost", "cost of the energy per day at --electricity-price, in its currency"),
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
        E("rod_energy_residual", "ratio", "(surface card work − pump card work − damping dissipation − drag work "
          "in a deviated well) / surface card work"),
        E("machine_energy_residual", "ratio", "(motor work − polished-rod work) / motor work over a cycle of the "
          "coupled solution"),
        E("cycles", "count", "cycles marched to the periodic state"),
        E("repeat_strokes", "count", "strokes after which the predicted state repeats: 1, or 2 to 4 when a pump "
          "pounding fluid settles into unlike strokes (the cards are the one of the highest load)"),
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
    Section("Deviated wells (`--survey` of `downhole`, `predict`, `dynamics --well-model wave`)",
            "The rods along a surveyed hole: gravity along the hole, the soft-string side load and Coulomb drag "
            "([JohancsikSPE11380]); definitions in `docs/deviated.md`. Depths are measured along the hole from the "
            "wellhead; the profile (`--profile`) has one row per node of the rod string.", (
        E("pump_true_vertical_depth", "depth", "true vertical depth of the pump: the head of the fluid columns",
          "TVD"),
        E("axial_rod_weight", "force", "buoyant weight of the rods along the hole, ∫ q cos φ ds: the polished rod's "
          "static load of a frictionless string, the pump card's datum", "W"),
        E("friction_coefficient", "ratio", "Coulomb friction coefficient of rods and couplings on the tubing", "μ"),
        E("friction_work_per_cycle", "energy", "work of the rod-tubing drag per cycle, ∫∫ μ N |u_t| ds dt"),
        E("max_side_load", "force_per_length", "largest side load per length over depth and cycle (soft-string, "
          "from the dynamic effective tension)", "N"),
        E("max_side_load_depth", "depth", "measured depth of the largest side load per length"),
        E("max_side_load_per_rod", "force", "largest side load of one rod between couplings (what one coupling "
          "carries without guides)"),
        E("rod_guide_side_load_limit", "force", "side load one coupling or guide may carry (--guide-limit or "
          "well.rod_guide_side_load_limit)"),
        E("rods_with_guides", "count", "rods that need guides to keep every contact under the limit"),
        E("rod_guides_total", "count", "guides on those rods, all together"),
        E("rod_guide_intervals", TEXT, "measured-depth intervals that need guides, with the most guides per rod "
          "in each"),
        E("pump_card_work_without_friction", "energy", "work of the pump card of a diagnosis that ignores the "
          "drag (the vertical model's along the hole)"),
        E("pump_position_without_friction", "length", "plunger position of a diagnosis that ignores the drag"),
        E("pump_load_without_friction", "force", "net plunger load of a diagnosis that ignores the drag"),
        E("measured_depth", "depth", "depth along the hole from the wellhead (the rods' length to here)", "MD"),
        E("true_vertical_depth", "depth", "depth below the wellhead", "TVD"),
        E("inclination", "angle", "angle of the hole from the vertical", "φ"),
        E("azimuth", "angle", "direction of the hole clockwise from north", "ψ"),
        E("dogleg_severity", "dogleg_severity", "curvature of the hole (minimum curvature between the stations)",
          "DLS"),
        E("north", "length", "the hole's displacement north of the wellhead"),
        E("east", "length", "the hole's displacement east of the wellhead"),
        E("horizontal_displacement", "length", "the hole's horizontal distance from the wellhead"),
        E("side_load", "force_per_length", "largest side load per length over the cycle at this depth", "N"),
        E("side_load_per_rod", "force", "largest side load of one rod between couplings at this depth"),
        E("rod_guides", "count", "guides per rod that keep each contact under the side-load limit"),
        E("{extreme}_axial_load", "force", "{extreme} effective axial load over the cycle at this depth"),
        E("drag_work", "energy", "work of the drag per cycle on the node's share of the string"),
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
        E("sequence_condition", TEXT, "(`trend`) what the well's consecutive cards say together: pump_off (the "
          "load-transfer point marches one way), gas_interference (it jumps back and forth), steady; empty for the "
          "first two cards"),
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


def suffixed(name: str, quantity: str, system: str) -> str:
    """An output name as ``-f csv`` and ``-f json`` write it: with the unit suffix of the unit
    system, none for text or a pure number.

    >>> suffixed("rod_load", "force", "si"), suffixed("rod_load", "force", "field")
    ('rod_load_n', 'rod_load_lbf')
    """
    if quantity == TEXT:
        return name
    suffix = output_unit(quantity, system).suffix
    return f"{name}_{suffix}" if suffix else name


@cache
def written_names() -> dict[str, tuple[str, str, str]]:
    """Every name this tool writes in ``-f csv`` and ``-f json`` (suffixed, in both unit
    systems) -> (output name, quantity kind, unit system), so that a reader knows the tool's
    own files: ``position_in`` -> ``("position", "length", "field")``."""
    return {suffixed(name, quantity, system): (name, quantity, system)
            for name, (quantity, _) in catalogue().items() for system in UNIT_SYSTEMS}


#: Abbreviations and symbols a name spells in lower case, as words write them.
_SPELLED = {"rms": "RMS", "api": "API", "cbe": "CBE", "nema": "NEMA", "spm": "SPM", "m05": "M_R05", "m01": "M_R01",
            "m12": "M_R12", "m13": "M_R13", "m24": "M_R24", "m34": "M_R34", "omega1": "ω1", "two": "two-",
            "series4": "series to the 4th harmonic", "series6": "series to the 6th harmonic"}


def words(name: str) -> str:
    """An output name in words for a legend or an axis: underscores as spaces, symbols as
    written (R12, RMS, M_R05).

    >>> words("r12_y_rational"), words("recommended_net_torque"), words("velocity_two_term")
    ('R12 y rational', 'recommended net torque', 'velocity two-term')
    """
    parts = []
    for part in name.split("_"):
        if re.fullmatch(r"r\d\d", part):
            parts.append(part.upper())
        else:
            parts.append(_SPELLED.get(part, part))
    return " ".join(parts).replace("two- term", "two-term")


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
