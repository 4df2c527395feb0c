"""Every number in the tables of docs/ is produced by a command here, or the table says why not.

Each table of results in docs/ is declared below by its header line and rebuilt from the
``-f json`` output of the commands it reports (run in-process, each argument list once):
the document's rows must be exactly the rebuilt rows, so that a number can no longer go
stale. A table of another kind (definitions, limits, a source's data, test tolerances,
timings) is listed in :data:`EXEMPT` with the reason; a new table with digits that is in
neither list fails :func:`test_every_table_with_numbers_is_accounted_for`.

``python tests/architecture/test_doc_tables.py --write`` rewrites the declared tables of the
documents from the commands (the tests themselves never write).
"""

from __future__ import annotations

import contextlib
import io
import json
import re
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))   # helpers, also when run as a script
from helpers import REPO_ROOT  # noqa: E402

DOCS = REPO_ROOT / "docs"
_RUNS: dict[tuple[str, ...], dict] = {}


def run(*argv: str) -> dict:
    """A command's ``-f json`` document, run once per argument list (from the repository root)."""
    import os

    from pumpjack_cli.cli import main

    if argv not in _RUNS:
        out, err = io.StringIO(), io.StringIO()
        here = os.getcwd()
        os.chdir(REPO_ROOT)
        try:
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                code = main([*argv, "-f", "json"])
        finally:
            os.chdir(here)
        assert code == 0, (argv, err.getvalue())
        _RUNS[argv] = json.loads(out.getvalue())
    return _RUNS[argv]


def s(*argv: str) -> dict:
    return run(*argv, "--what", "summary")["summary"]


def n(value: float, decimals: int = 0) -> str:
    """A number as the documents write them: digit groups of three separated by spaces, a minus sign."""
    text = f"{value:,.{decimals}f}".replace(",", " ")
    return text.replace("-", "−") if text.startswith("-") and float(text.replace(" ", "")) != 0 else text.lstrip("-")


def f(value: float, decimals: int = 1) -> str:
    """Fixed decimals, a typographic minus sign."""
    text = f"{value:.{decimals}f}"
    return "−" + text[1:] if text.startswith("-") and float(text) != 0 else text.lstrip("-")


def card(unit: str) -> str:
    return f"samples/{unit}-card.csv"


# --- the tables -------------------------------------------------------------------------------------------------

def reactions_radius() -> list[str]:
    rows = []
    for label, extra in (("0.83 m (unit)", ()), ("1.0 m", ("--counterweight-radius", "1.0 m")),
                         ("1.1 m", ("--counterweight-radius", "1.1 m")), ("1.2 m", ("--counterweight-radius", "1.2 m")),
                         ("1.4 m", ("--counterweight-radius", "1.4 m"))):
        x = s("reactions", "sk8-3.5-4000", "--card", card("sk8-3.5-4000"), *extra)
        rows.append(f"| {label} | {n(x['max_net_torque_n_m'])} | {n(x['min_net_torque_n_m']).replace('−', '-')} |")
    return rows


UNITS = (("sk8-3.5-4000", "SK8-3,5-4000"), ("7sk12-2.5-5600", "7SK12-2,5-5600"), ("c-114d-133-54", "C-114D-133-54"))


def torque_balance() -> list[str]:
    rows = []
    for unit, shown in UNITS:
        cells = []
        for criterion in ("equal-peaks", "min-peak", "min-rms"):
            x = s("torque", unit, "--card", card(unit), "--crank-motion", "uniform", "--balance", criterion)
            cells.append(", ".join(n(x[k]) for k in ("recommended_counterbalance_moment_n_m",
                                                     "recommended_peak_net_torque_n_m",
                                                     "recommended_counterbalance_effect_n")))
        rows.append(f"| {shown} | {n(x['counterbalance_moment_n_m'])} | {' | '.join(cells)} |")
    return rows


def torque_real_run() -> list[str]:
    a = s("torque", "sk8-3.5-4000", "--card", card("sk8-3.5-4000"))
    e = s("torque", "sk8-3.5-4000", "--card", card("sk8-3.5-4000"), "--method", "exact")
    rating = a["gearbox_rating_n_m"]
    return [
        f"| `peak_net_torque` | {n(a['peak_net_torque_n_m'])} N·m | {n(e['peak_net_torque_n_m'])} N·m |",
        f"| `gearbox_loading` (rating 4000 kgf·m = {n(rating)} N·m) | {a['gearbox_loading_percent']:.1f} % | "
        f"{e['gearbox_loading_percent']:.1f} % |",
        f"| `structural_unbalance` (from the masses) | {n(a['structural_unbalance_n'])} N | |",
        f"| `counterbalance_moment`, `counterbalance_effect` | {n(a['counterbalance_moment_n_m'])} N·m, "
        f"{n(a['counterbalance_effect_n'], 0)} N | |",
        f"| `recommended_counterbalance_moment` (equal-peaks) | {n(a['recommended_counterbalance_moment_n_m'])} N·m | "
        f"{n(e['recommended_counterbalance_moment_n_m'])} N·m |",
        "| `recommended_peak_net_torque`, `recommended_gearbox_loading` | "
        f"{n(a['recommended_peak_net_torque_n_m'])} N·m, {a['recommended_gearbox_loading_percent']:.1f} % | "
        f"{n(e['recommended_peak_net_torque_n_m'])} N·m, {e['recommended_gearbox_loading_percent']:.1f} % |",
        f"| `recommended_counterweight_radius` (8 blocks) | {a['recommended_counterweight_radius_m']:.2f} m | "
        f"{e['recommended_counterweight_radius_m']:.2f} m |",
        "| `structure_loading`, `polished_rod_power`, `cyclic_load_factor` | "
        f"{a['structure_loading_percent']:.1f} %, {a['polished_rod_power_w'] / 1e3:.2f} kW, "
        f"{a['cyclic_load_factor']:.2f} | {e['structure_loading_percent']:.1f} %, "
        f"{e['polished_rod_power_w'] / 1e3:.2f} kW, {e['cyclic_load_factor']:.2f} |",
        "| `rms_net_torque`, `recommended_rms_net_torque` | "
        f"{n(a['rms_net_torque_n_m'])} N·m, {n(a['recommended_rms_net_torque_n_m'])} N·m | "
        f"{n(e['rms_net_torque_n_m'])} N·m, {n(e['recommended_rms_net_torque_n_m'])} N·m |",
        "| `rms_motor_power`, `nema_motor_size` (present; recommended) | "
        f"{a['rms_motor_power_w'] / 1e3:.1f} kW, {a['nema_motor_size_w'] / 745.69987158227022:g} hp; "
        f"{a['recommended_rms_motor_power_w'] / 1e3:.1f} kW, {a['recommended_nema_motor_size_w'] / 745.69987158227022:g} hp"
        f" | {e['rms_motor_power_w'] / 1e3:.1f} kW, {e['nema_motor_size_w'] / 745.69987158227022:g} hp; "
        f"{e['recommended_rms_motor_power_w'] / 1e3:.1f} kW, {e['recommended_nema_motor_size_w'] / 745.69987158227022:g} hp |",
        f"| `motor_energy` (present; recommended) | {a['motor_energy_kwh_d']:.0f} kWh/d; "
        f"{a['recommended_motor_energy_kwh_d']:.0f} kWh/d | {e['motor_energy_kwh_d']:.0f} kWh/d; "
        f"{e['recommended_motor_energy_kwh_d']:.0f} kWh/d |",
    ]


def torque_methods() -> list[str]:
    rows = []
    for unit, shown in UNITS:
        common = ("--card", card(unit), "--crank-motion", "uniform", "--steps", "3600")
        exact = run("torque", unit, *common, "--method", "exact")
        static = run("reactions", unit, *common, "--no-inertia")["series"]["net_torque_n_m"]
        beam = run("kinematics", unit, "--steps", "3600", "--spm", "1")["series"]["beam_angle_deg"]
        t = exact["series"]
        api_static = [a - ai - ri for a, ai, ri in zip(t["api_net_torque_n_m"], t["articulating_inertia_torque_n_m"],
                                                       t["rotary_inertia_torque_n_m"])]
        peak = max(map(abs, api_static))
        d_static = max(abs(x - y) for x, y in zip(static, api_static))
        d_speed = max(abs(x - y) for x, y in zip(t["exact_net_torque_n_m"], api_static))
        d_full = exact["summary"]["peak_exact_minus_api_torque_n_m"]
        speed = exact["summary"]["strokes_per_minute_spm"] * 2 * 3.141592653589793 / 60
        rows.append(f"| {shown} ({speed:.4f} 1/s) | {n(min(beam), 1)}°…{n(max(beam), 1)}° | {n(peak)} | "
                    f"{n(d_static)} N·m ({100 * d_static / peak:.2f} %) | {n(d_speed)} N·m ({100 * d_speed / peak:.1f} %) | "
                    f"{n(d_full)} N·m |")
    return rows


def predict_sk8() -> list[str]:
    rigid = s("dynamics", "sk8-3.5-4000")
    rigid_series = run("dynamics", "sk8-3.5-4000", "--steps", "3600")["series"]
    uniform = [s("predict", "sk8-3.5-4000", "--damping", nu) for nu in ("0.05", "0.1", "0.2")]
    coupled = [s("predict", "sk8-3.5-4000", "--damping", nu, "--crank-motion", "dynamic") for nu in ("0.05", "0.1", "0.2")]
    pull_out = rigid["max_motor_torque_n_m"] * rigid["breakdown_torque_margin"]

    def each(rows, key, scale=1.0, decimals=1):
        return " / ".join(f(x[key] * scale, decimals) for x in rows)

    speeds = " / ".join(f"{2 * 3.141592653589793 / x['period_s']:.4f}" for x in coupled)
    inertia = rigid_series["inertia_torque_n_m"]
    # the gearbox torque of the rigid model: rod load and gravity torques and the inertia torque
    net = [a + b + c for a, b, c in zip(rigid_series["rod_load_torque_n_m"], rigid_series["gravity_torque_n_m"], inertia)]
    gearbox = [max(net), min(net)]
    return [
        f"| mean crank speed [1/s] | {rigid['mean_crank_speed_rad_s']:.4f} | "
        f"{2 * 3.141592653589793 / uniform[0]['period_s']:.4f} (rated) | {speeds} |",
        f"| speed fluctuation (max − min)/mean | {rigid['speed_fluctuation_percent']:.1f} % | 0 | "
        f"{each(coupled, 'speed_fluctuation_percent')} % |",
        f"| PPRL [kN] | {rigid['upstroke_rod_load_n'] / 1e3:.1f} (P_up; + rod inertia in I) | "
        f"{each(uniform, 'max_rod_load_n', 1e-3)} | {each(coupled, 'max_rod_load_n', 1e-3)} |",
        f"| MPRL [kN] | {rigid['downstroke_rod_load_n'] / 1e3:.1f} (P_down) | {each(uniform, 'min_rod_load_n', 1e-3)} | "
        f"{each(coupled, 'min_rod_load_n', 1e-3)} |",
        f"| peak gearbox torque [kN·m] | {gearbox[0] / 1e3:.1f} | {each(uniform, 'max_net_torque_n_m', 1e-3)} | "
        f"{each(coupled, 'max_net_torque_n_m', 1e-3)} |",
        f"| min gearbox torque [kN·m] | {f(gearbox[1] / 1e3)} | {each(uniform, 'min_net_torque_n_m', 1e-3)} | "
        f"{each(coupled, 'min_net_torque_n_m', 1e-3)} |",
        f"| inertia torque I ε + ½ I′ω² [kN·m] | {f(min(inertia) / 1e3)} … +{f(max(inertia) / 1e3)} | — | "
        + " / ".join(f"{f(x['min_inertia_torque_n_m'] / 1e3)} … +{f(x['max_inertia_torque_n_m'] / 1e3)}"
                     for x in coupled) + " |",
        f"| peak motor torque [N·m] (pull-out {pull_out:.1f}) | {rigid['max_motor_torque_n_m']:.0f} | — | "
        f"{each(coupled, 'max_motor_torque_n_m', 1.0, 0)} |",
        f"| energy per cycle [kJ] | {rigid['energy_per_cycle_j'] / 1e3:.1f} | "
        f"{each(uniform, 'surface_card_work_j', 1e-3)} | {each(coupled, 'energy_per_cycle_j', 1e-3)} |",
        f"| net plunger stroke [m] | {s('kinematics', 'sk8-3.5-4000')['stroke_m']:.3f} (rigid) | "
        f"{each(uniform, 'net_pump_stroke_m', 1.0, 3)} | {each(coupled, 'net_pump_stroke_m', 1.0, 3)} |",
    ]


REDUNDANCY = (
    ('`--crank-phase "0.1 deg"`', ("--crank-phase", "0.1 deg")),
    ('`--crank-phase "0.2 deg"`', ("--crank-phase", "0.2 deg")),
    ('`--crank-phase "0.1 deg" --crank-phase-mode whole-arm`', ("--crank-phase", "0.1 deg", "--crank-phase-mode",
                                                                 "whole-arm")),
    ('`--crank-radius "1 mm"`', ("--crank-radius", "1 mm")),
    ('`--crank-radius "2 mm"`', ("--crank-radius", "2 mm")),
    ('`--pitman-length "1 mm"`', ("--pitman-length", "1 mm")),
    ('`--pitman-length "2 mm"`', ("--pitman-length", "2 mm")),
    ('`--equalizer-pin-roll "1 mrad"`', ("--equalizer-pin-roll", "1 mrad")),
    ('`--crank-phase "0.1 deg" --pitman-length "1 mm"`', ("--crank-phase", "0.1 deg", "--pitman-length", "1 mm")),
)


def redundancy() -> list[str]:
    rows = []
    for label, options in REDUNDANCY:
        x = s("compare-redundancy", "7sk12-2.5-5600", "--card", card("7sk12-2.5-5600"), "--spm", "8", *options)
        rows.append(
            f"| {label} | {x['peak_difference_r12_y_n'] / 1e3:.2f} | {x['peak_difference_r13_y_n'] / 1e3:.2f} | "
            f"{x['peak_pitman_split_y_n'] / 1e3:.2f} | {x['peak_difference_r12_x_n'] / 1e3:.2f} "
            f"({x['peak_difference_r12_x_crank_angle_deg']:.0f}°) | {x['peak_difference_net_torque_n_m']:.1f} | "
            f"{x['peak_kinematic_net_torque_n_m']:.1f} | {x['peak_total_difference_net_torque_n_m']:.1f} |")
    return rows


LAWS = (("sinusoidal (`harmonic`)", "harmonic"), ("first approximation (`two_term`)", "two_term"),
        ("series to 4φ (`series4`)", "series4"), ("series to 6φ (`series6`)", "series6"))


def _zero(value: float) -> str:
    return "zero" if abs(value) < 1e-9 else f"{value:.6g} %"


def inertia_unb600a() -> list[str]:
    x = s("inertia-error", "unb-600a")
    rows = [f"| exact | – | – | – | – | {x['peak_inertia_force_n']:.6g} N ({x['peak_acceleration_m_s2']:.6g} m/s² at "
            f"φ = {x['peak_crank_angle_deg']:.0f}) |"]
    for label, law in LAWS:
        rows.append(f"| {label} | {_zero(x[law + '_peak_error_percent'])} | {_zero(x[law + '_peak_error_of_law_percent'])} | "
                    f"{x[law + '_max_deviation_percent']:.6g} % | {x[law + '_rms_deviation_percent']:.6g} % | "
                    f"{x[law + '_peak_inertia_force_n']:.6g} N |")
    return rows


def inertia_beam_units() -> list[str]:
    rows = []
    for unit, shown, extra in (("sk8-3.5-4000", "SK8-3,5-4000 (10.9 spm, drive)", ()),
                               ("7sk12-2.5-5600", "7SK12-2,5-5600 (`--spm 8`)", ("--spm", "8")),
                               ("c-114d-133-54", "C-114D-133-54 (`--spm 8`)", ("--spm", "8"))):
        x = s("inertia-error", unit, *extra)
        for i, (law, name) in enumerate((("harmonic", "harmonic"), ("two_term", "two-term"), ("chord", "chord"))):
            rows.append(f"| {shown if i == 0 else ''}{' ' if i == 0 else ''}| {name} | {x[law + '_peak_error_percent']:.6g} % | "
                        f"{x[law + '_peak_error_of_law_percent']:.6g} % | {x[law + '_max_deviation_percent']:.6g} % | "
                        f"{x[law + '_rms_deviation_percent']:.6g} % |")
    return rows


def dynamics_rtol() -> list[str]:
    rows = []
    for rtol in ("1e-6", "1e-8", "1e-10", "1e-12"):
        document = run("dynamics", "sk8-3.5-4000", "--rtol", rtol, "--steps", "4")
        x, series = document["summary"], document["series"]
        at_90 = series["crank_speed_rad_s"][series["crank_angle_deg"].index(90.0)]
        rows.append(f"| {rtol} | {x['start_crank_speed_rad_s']:.10f} | {at_90:.10f} | {n(x['energy_per_cycle_j'], 6)} | "
                    f"{x['periodicity_error']:.1e} |")
    return rows


def dynamics_forces() -> list[str]:
    x = s("dynamics", "sk8-3.5-4000")
    text = (DOCS / "dynamics.md").read_text(encoding="utf-8")
    header = "| force | formula | source | SK8 well |"
    body = _table_at(text, header)[2:]
    keys = ("rod_weight_n", "fluid_load_n", "plunger_friction_n", "tubing_friction_n", "rod_friction_n")
    return [row.rsplit("|", 2)[0] + f"| {n(x[key])} N |" for row, key in zip(body, keys)]


def batch_tasks() -> list[str]:
    """The tasks a field is cut into (``analysis.batch.run.task_sizes``: a rule, not a command's output)."""
    from pumpjack_cli.analysis.batch.run import chunk_size, task_sizes

    fields = ((40, 2), (1000, 2), (10_000, 2), (100_000, 2), (100_000, 64))
    return [f"| {n(cards)} cards | {workers} | {chunk_size(cards, workers)} | {len(task_sizes(cards, workers))} | "
            f"{task_sizes(cards, workers)[-1]} |" for cards, workers in fields]


#: Declared tables: (document, header line) -> the rows' builder.
TABLES: dict[tuple[str, str], Callable[[], list[str]]] = {
    ("reactions.md", "| `--counterweight-radius` | max M_z [N·m] | min M_z [N·m] |"): reactions_radius,
    ("torque.md", "| unit | configured M | equal-peaks | min-peak | min-rms |"): torque_balance,
    ("torque.md", "| summary | API method | exact method |"): torque_real_run,
    ("torque.md", "| unit | ψ range | peak T_api,static [N·m] | max \\|T_exact,static − T_api,static\\| | "
                  "max \\|T_exact − T_api,static\\| at pumping speed | max \\|T_exact − T_api\\| (API with its inertia "
                  "components) |"): torque_methods,
    ("predict.md", "| | rigid (seed model) | wave, uniform ν 0.05 / 0.1 / 0.2 | wave, coupled ν 0.05 / 0.1 / 0.2 |"):
        predict_sk8,
    ("redundancy.md", "| deviation | dR12y | dR13y | R12y − R13y | dR12x (crank angle) | dM_z redundancy | "
                      "dM_z kinematic | dM_z total |"): redundancy,
    ("inertia-error.md", "| law | peak error (δ of [InertiaUNB600A]) | peak error of law | max deviation | "
                         "RMS deviation | max \\|Φ\\| |"): inertia_unb600a,
    ("inertia-error.md", "| unit | law | peak error (δ of [InertiaUNB600A]) | peak error of law | max deviation | "
                         "RMS deviation |"): inertia_beam_units,
    ("dynamics.md", "| rtol | start ω1 [1/s] | ω1 at 90° [1/s] | energy per cycle [J] | periodicity error |"):
        dynamics_rtol,
    ("dynamics.md", "| force | formula | source | SK8 well |"): dynamics_forces,
    ("batch.md", "| field | workers | cards per task | tasks | the last task |"): batch_tasks,
}

#: Tables whose numbers are not results of a command, by (document, header line): why.
EXEMPT: dict[tuple[str, str], str] = {
    ("architecture.md", "| a new ... | files that change |"): "file lists (numbered steps)",
    ("batch.md", "| column | required | meaning |"): "manifest format",
    ("batch.md", "| column | a card | stroke 7 of a recording |"): "the key format of a stored row",
    ("batch.md", "| column | meaning |"): "store format",
    ("batch.md", "| what | result |"): "timings (docs/performance.md)",
    ("batch.md", "| cards | wall time | cards/s | peak RSS, all processes (sum) | batch process | each worker | "
                 "workers' CPU a card |"): "timings and memory measured (benchmarks/bench_dask.py)",
    ("batch.md", "| what happens | what the run does |"): "behaviour under faults (tests/commands/test_batch_faults.py)",
    ("cards.md", "| format | module | an example | recognised by content | file name endings |"): "formats",
    ("cards.md", "| option | meaning |"): "options",
    ("cards.md", "| layout | columns | how it reaches the crank-angle axis |"): "layouts",
    ("cards.md", "| key (case, spaces, dots, dashes, `/` and `_` alike) | metadata | value |"): "preamble keys",
    ("cards.md", "| limit | value | why |"): "input limits (constants of the readers)",
    ("cards.md", "| refused when | threshold | why |"): "input limits (constants of the readers)",
    ("cards.md", "| file | layout | read with |"): "sample files",
    ("conventions.md", "| φ1 of [SK8Rotation2013] | crank travel from bottom | θ here |"):
        "angle conventions converted by hand (checked by tests/validation/test_sk8rotation2013.py)",
    ("downhole.md", "| N per stroke | 1530 m 25/22/19 mm: stroke, max load error / card load range | 5000 ft 4 "
                    "tapers with sinker bars |"):
        "convergence of the core's finite-difference march, measured by tests/core/rods/test_rods_downhole.py",
    ("downhole.md", "| claim | test |"): "test list",
    ("diagnosis.md", "| option | meaning |"): "options",
    ("diagnosis.md", "| label | what the pump does | what the pump card shows | sources |"): "definitions and sources",
    ("diagnosis.md", "| feature (output name) | definition |"): "definitions",
    ("diagnosis.md", "| label | score (evidence 0..1 each) | thresholds | source |"):
        "the rules' constants (pumpjack_cli/core/rods/diagnosis.py) and their sources",
    ("diagnosis.md", "| feature | condition: smallest (1st percentile) | the others: largest (99th percentile) | rule |"):
        "margins of the rules measured by benchmarks/diagnosis_study.py",
    ("diagnosis.md", "| output | formula | source |"): "formulas",
    ("diagnosis.md", "| option | model |"): "options",
    ("diagnosis.md", "| simulated \\ labelled | full | fluid pound | gas interference | travelling valve leak | "
                     "standing valve leak | tagging down | tagging up | unanchored tubing | rod part | recall |"):
        "the confusion matrix of benchmarks/diagnosis_study.py (about 90 s); the tests check a smaller corpus",
    ("diagnosis.md", "| claim | test |"): "test list",
    ("deviated.md", "| claim | test | measured |"): "test list with the tolerances the tests measure",
    ("deviated.md", "| | pump-card work | plunger position | upstroke level | downstroke level | rms load error | "
                    "drag work |"): "the round trip measured by tests/core/rods/test_deviated_round_trip.py",
    ("deviated.md", "| steps | nodes | PPRL [kN] | MPRL [kN] | pump work [kJ] | drag work [kJ] | energy residual |"):
        "convergence study of the core's time march, benchmarks/deviated_convergence.py",
    ("deviated.md", "| η | PPRL [kN] | MPRL [kN] | drag work [kJ] | rms change of the polished-rod load from the η "
                    "above [% of F_o] |"): "convergence study of the drag's band, benchmarks/deviated_convergence.py",
    ("deviated.md", "| diagnostic η | segments at most [m] | pump work | plunger position [% of stroke] | upstroke level "
                    "| downstroke level | rms load error | drag work |"):
        "convergence study of the diagnostic march, benchmarks/deviated_convergence.py",
    ("deviated.md", "| | value | source |"): "model settings and their sources",
    ("dynamics.md", "| part | inertia on its shaft | at the crank | source |"): "input data of the unit and its sources",
    ("dynamics.md", "| quantity | [SK8Rotation2013] | here |"):
        "prose comparison with the source; its numbers are the console example's (test_docs_commands.py)",
    ("dynamics.md", "| code / column | [SK8Rotation2013] | meaning |"): "names",
    ("inertia-error.md", "| law (column suffix) | slider acceleration a | source |"): "formulas",
    ("inertia-error.md", "| summary name | definition | meaning |"): "definitions",
    ("inertia-error.md", "| hypothesis | sinusoidal | first approx. |"):
        "hypotheses about the source's definition computed by hand (tests/validation/test_inertia_unb600a.py)",
    ("inertia-error.md", "| quantity | outer dead centre (φ = 0) | inner dead centre (φ = 180°) |"):
        "checked by tests/validation/test_inertia_unb600a.py on the estimated slider",
    ("performance.md", None): "timings",
    ("predict.md", "| test | what it shows | measured |"): "test list with the tolerances the tests measure",
    ("predict.md", "| motion | ν | PPRL [lb] | MPRL [lb] | Sp [in] | PRHP [hp] |"):
        "made by tests/validation/test_rp11lxls.py: a unit scaled to 86 in and a harmonic motion, no command",
    ("predict.md", "| run | time |"): "timings",
    ("redundancy.md", "| option / field | meaning |"): "options",
    ("redundancy.md", "| crank phase | 0.05° | 0.1° | 0.2° | 0.3° | 0.4° |"):
        "clearance study of the core (tests/core/beam/test_redundancy.py); no command option sets pin clearance",
    ("redundancy.md", "| pitman-length error | 1 mm | 2 mm | 3 mm | 4 mm |"):
        "clearance study of the core (tests/core/beam/test_redundancy.py)",
    ("torque.md", "| module | what |"): "module list",
    ("torque.md", "| claim | check | test |"): "test list",
    ("validation.md", None): "what each test checks against which source",
    ("README.md", "| bundled unit | source |"): "unit names and sources",
    ("report.md", "| section | what it shows | from |"): "the page's layout",
    ("catalogue.md", "| column | needed | unit | meaning | in the unit file |"): "catalogue format",
    ("units.md", "| kind | `class` | designation | lever | rotation | counterbalance | `torque` recommends |"):
        "the kinds of unit (names and letters)",
    ("units.md", "| key | GOST name | meaning |"): "unit-file keys",
    ("units.md", "| key | meaning | kinds |"): "unit-file keys",
    ("units.md", "| key | meaning |"): "unit-file keys",
}


def _table_at(text: str, header: str) -> list[str]:
    lines = text.splitlines()
    start = lines.index(header)
    end = start
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    return lines[start:end]


def _tables(path: Path):
    """(header line, body lines) of every Markdown table of a document that has a digit in its body."""
    lines = path.read_text(encoding="utf-8").splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("|") and i + 1 < len(lines) and re.match(r"^\|[-| :]+\|$", lines[i + 1]):
            j = i + 2
            while j < len(lines) and lines[j].startswith("|"):
                j += 1
            if any(re.search(r"\d", line) for line in lines[i + 2:j]):
                yield lines[i], lines[i + 2:j]
            i = j
        else:
            i += 1


def test_every_table_with_numbers_is_accounted_for():
    for path in [*sorted(DOCS.glob("*.md")), REPO_ROOT / "README.md"]:
        if path.name in ("glossary.md", "unit-files.md"):   # generated from the catalogue and the schema, tested
            continue
        for header, _ in _tables(path):
            key = (path.name, header)
            assert key in TABLES or key in EXEMPT or (path.name, None) in EXEMPT, \
                f"{path.name}: table {header!r} is neither produced by a command here nor exempt with a reason"


@pytest.mark.parametrize("key", TABLES, ids=[f"{d}: {h[:50]}" for d, h in TABLES])
def test_a_table_holds_what_the_commands_print(key):
    document, header = key
    body = _table_at((DOCS / document).read_text(encoding="utf-8"), header)[2:]
    assert body == TABLES[key](), (f"docs/{document} is stale: run python tests/architecture/test_doc_tables.py "
                                   f"--write")


def write() -> None:
    for (document, header), build in TABLES.items():
        path = DOCS / document
        text = path.read_text(encoding="utf-8")
        old = "\n".join(_table_at(text, header)[2:])
        path.write_text(text.replace(old, "\n".join(build()), 1), encoding="utf-8")


if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        write()
