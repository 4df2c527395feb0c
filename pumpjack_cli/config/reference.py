"""The reference of the unit-file keys, generated from the schema: ``docs/unit-files.md``.

Every section and key of both machine kinds, each kind's ``[geometry]`` of
:data:`~.unit_classes.UNIT_CLASSES` included, with its unit kind (the dimension a value
with a unit is parsed as, and the SI unit it is converted to), default, bounds, an
example and the commands that read it. The page's generated part is exactly what
:func:`unit_file_reference` returns (``tests/config/test_unit_file_reference.py``);
regenerate it with ``python -m pumpjack_cli.config.reference --write``.

Examples are taken from the bundled unit files (``configs/``) where one gives the key,
else from :data:`EXAMPLES`; a key without either is an error, as is a section without the
commands that use it (:data:`USED_BY`).
"""

from __future__ import annotations

import functools
import math
import re
import sys
import tomllib
import types
import typing
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel

from ..quantities import SI_LABELS
from .geometry_names import GEOMETRY_ALIASES
from .quantities import dimension_of

#: The page and the markers of its generated part.
PAGE = Path(__file__).resolve().parents[2] / "docs" / "unit-files.md"
BEGIN = "<!-- generated from the schema by python -m pumpjack_cli.config.reference --write; do not edit by hand -->"
END = "<!-- end of the generated reference -->"
CONFIGS = Path(__file__).resolve().parents[2] / "configs"

#: The commands that read each section (a section's keys inherit it unless :data:`KEY_USES` says otherwise).
USED_BY: dict[str, str] = {
    "": "every command (`units` lists name, description and the stroke)",
    "rating": "torque, predict, report, batch run",
    "counterbalance": "torque, predict, report, batch run",
    "geometry": "every command",
    "geometry.air_cylinder": "torque, predict, report, batch run",
    "masses": "reactions, compare-redundancy, dynamics, torque (inertia, --method exact, counterweight radius), "
              "predict, report, batch run",
    "drive": "kinematics, dynamics, predict (speed and --crank-motion dynamic), torque and downhole (speed of a card "
             "without time stamps), report",
    "drive.motor": "dynamics, predict --crank-motion dynamic, kinematics (rated speed)",
    "well": "downhole, predict, dynamics (well model), torque (card plausibility), report, batch run",
    "well.rod_string": "downhole, predict, dynamics (well model), torque (card plausibility), report, batch run",
    "pitman_section": "compare-redundancy",
    "deviations": "compare-redundancy",
    "joints": "compare-redundancy",
    "slider-crank": "inertia-error, kinematics",
    "slider-crank.geometry": "inertia-error, kinematics",
    "slider-crank.reciprocating": "inertia-error",
    "slider-crank.stepped_slider": "inertia-error --support-friction",
    "slider-crank.stepped_slider.sections": "inertia-error --support-friction",
    "slider-crank.stepped_slider.intermediate_support": "inertia-error --support-friction",
}
#: Keys read by fewer commands than their section.
KEY_USES: dict[str, str] = {
    "geometry.crank_half_spacing": "reactions, compare-redundancy, torque --method exact",
    "geometry.equalizer_half_length": "reactions, compare-redundancy, torque --method exact",
    "well.plunger_clearance": "dynamics (rigid-rod well model)",
    "well.tubing_inner_diameter": "dynamics (rigid-rod well model)",
    "well.fluid_kinematic_viscosity": "dynamics (rigid-rod well model)",
    "well.rod_density": "dynamics (rigid-rod well model)",
    "designation": "torque, predict, report (ratings); the kind of unit",
    "masses.counterweights.radius_range": "torque (recommended counterweight radius)",
}
#: Examples of keys that no bundled unit file gives (TOML values).
EXAMPLES: dict[str, str] = {
    "kind": '"beam-pump"',
    "description": '"API 11E conventional unit, 228 000 lbf·in, 21 300 lbf, 86 in"',
    "sources": '["catalogue of the manufacturer, 2019", "counterbalance measured 2024-05-02"]',
    "slider-crank.description": '"drill pump of [InertiaUNB600A]"',
    "slider-crank.sources": '["[InertiaUNB600A]"]',
    "rating.gearbox_torque": '"228000 lbf*in"',
    "rating.structure_load": '"21300 lbf"',
    "rating.max_stroke": '"86 in"',
    "counterbalance.moment": '"130000 lbf*in"',
    "counterbalance.counterbalance_effect": '"12577 lbf"',
    "counterbalance.counterbalance_effect_angle": '"90 deg"',   # the default of a conventional unit
    "geometry.crank_half_spacing": '"0.6 m"',
    "geometry.equalizer_half_length": '"0.6 m"',
    "geometry.beam_counterweight": '"4000 lbf"',
    "geometry.beam_counterweight_arm": '"60 in"',
    "geometry.air_cylinder.piston_area": '"300 in2"',
    "geometry.air_cylinder.piston_diameter": '"20 in"',
    "geometry.air_cylinder.bottom_volume": '"8 ft3"',
    "geometry.air_cylinder.clearance": '"150 %"',
    "geometry.air_cylinder.exponent": "1.3",
    "geometry.air_cylinder.pressure": '"250 psi"',
    "geometry.air_cylinder.pressure_position": '"0 in"',
    "masses.counterweights.radius_range": '["0.3 m", "0.95 m"]',
    "masses.counterweights.phase": '"0 deg"',
    "well.fluid_kinematic_viscosity": '"5 mm2/s"',
    "well.survey": '"j-well-survey.csv"',
    "well.plunger_length": '"4 ft"',
    "well.rod_friction_coefficient": "0.2",
    "well.rod_guide_side_load_limit": '"500 lbf"',
    "well.rod_joint_length": '"25 ft"',
    "well.tubing_size": '"2-7/8"',
    "well.tubing_anchored": "false",
    "well.tubing_head_pressure": '"100 psi"',
    "well.casing_head_pressure": '"50 psi"',
    "well.plunger_clearance": '"0.1 mm"',
    "well.pump_intake_pressure": '"150 psi"',
    "well.pump_fillage": '"85 %"',
    "well.gas_exponent": "1.2",
    "well.damping_factor": "0.1",
    "well.rod_density": '"7850 kg/m3"',
    "well.rod_string.length": '"1200 m"',
    "well.rod_string.kind": '"sinker"',
    "well.rod_string.youngs_modulus": '"30.5e6 psi"',
    "well.rod_string.weight_per_length": '"2.904 lb/ft"',
    "well.rod_string.tensile_strength": '"115000 psi"',
    "deviations.crank_phase": '"0.1 deg"',
    "deviations.crank_radius": '"1 mm"',
    "deviations.pitman_length": '"2 mm"',
    "deviations.crank_pin_tilt_radial": '"1 mrad"',
    "deviations.crank_pin_tilt_tangential": '"1 mrad"',
    "deviations.equalizer_pin_roll": '"1 mrad"',
    "deviations.equalizer_pin_yaw": '"1 mrad"',
    "deviations.crank_phase_mode": '"whole-arm"',
    "joints.crank_pin_stiffness": '"5e7 N*m/rad"',
    "joints.equalizer_pin_stiffness": '"5e7 N*m/rad"',
    "joints.crank_pin_clearance": '"1 mrad"',
    "joints.equalizer_pin_clearance": '"1 mrad"',
    "slider-crank.stepped_slider.intermediate_support.position": '"1.2 m"',
    "slider-crank.stepped_slider.intermediate_support.offset": '"0.1 mm"',
}


def _origin_args(annotation: Any) -> tuple[Any, tuple]:
    return typing.get_origin(annotation), typing.get_args(annotation)


def _optional(annotation: Any) -> tuple[Any, bool]:
    """The annotation without ``| None`` and whether None was allowed."""
    origin, args = _origin_args(annotation)
    if origin in (typing.Union, types.UnionType) and type(None) in args:
        rest = [a for a in args if a is not type(None)]
        return (rest[0] if len(rest) == 1 else typing.Union[tuple(rest)]), True
    return annotation, False


def _metadata(annotation: Any) -> list:
    """The validators and constraints inside ``Annotated`` layers."""
    found = []
    while typing.get_origin(annotation) is typing.Annotated:
        found += list(annotation.__metadata__)
        annotation = typing.get_args(annotation)[0]
    return found


def _base(annotation: Any) -> Any:
    while typing.get_origin(annotation) is typing.Annotated:
        annotation = typing.get_args(annotation)[0]
    return annotation


def _dimension(annotation: Any) -> str | None:
    """The dimension a value is parsed as (the quantity validator among its metadata)."""
    return dimension_of(_metadata(annotation))


def _floor(annotation: Any) -> str | None:
    for item in _metadata(annotation):
        shown = getattr(getattr(item, "func", None), "shown", None)
        if shown is not None:
            return shown
    return None


def _model(annotation: Any) -> type[BaseModel] | None:
    base = _base(_optional(annotation)[0])
    return base if isinstance(base, type) and issubclass(base, BaseModel) else None


def _tables_of(annotation: Any) -> type[BaseModel] | None:
    """The model of a list of tables (``tuple[RodSection, ...]``)."""
    base = _base(_optional(annotation)[0])
    origin, args = _origin_args(base)
    if origin is tuple and args and args[-1] is Ellipsis:
        return _model(args[0])
    return None


def _field_dimension(field) -> str | None:
    """The dimension of a field: pydantic keeps an ``Annotated`` field's validators in its
    metadata, an optional field's inside the annotation."""
    return _dimension(typing.Annotated[(float, *field.metadata)]) if field.metadata and \
        _dimension(typing.Annotated[(float, *field.metadata)]) else _dimension(_optional(field.annotation)[0])


def _field_floor(field) -> str | None:
    found = _floor(typing.Annotated[(float, *field.metadata)]) if field.metadata else None
    return found or _floor(_optional(field.annotation)[0])


def _kind(field) -> str:
    """The unit kind of a key as the page shows it."""
    annotation = _optional(field.annotation)[0]
    dimension = _field_dimension(field)
    if dimension is not None:
        si = SI_LABELS[dimension]
        return f"{dimension.replace('_', ' ')} [{si}]" if si else dimension.replace("_", " ") + " [1, or %]"
    base = _base(annotation)
    origin, args = _origin_args(base)
    if origin is Literal:
        return "one of " + ", ".join(f"`{a}`" for a in args)
    if origin is tuple:
        inner = [a for a in args if a is not Ellipsis]
        if len(inner) == 2 and all(_dimension(a) for a in inner):
            return f"two {_dimension(inner[0])}s [{SI_LABELS[_dimension(inner[0])]}]"
        if args and args[-1] is Ellipsis and _base(args[0]) is str:
            return "list of text"
    if base is bool:
        return "true or false"
    if base is int:
        return "integer"
    if base is float:
        return "number"
    if base is str:
        return "text"
    return str(base)


def _number(value: float) -> str:
    return f"{value:.6g}"


def _shown(value: Any, dimension: str | None) -> str:
    """A default as the page shows it (SI, angles also in degrees)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        if dimension == "angle" and value != 0:
            return f"{_number(value)} rad ({_number(math.degrees(value))}°)"
        unit = SI_LABELS.get(dimension or "", "")
        return f"{_number(value)} {unit}".strip()
    if isinstance(value, tuple) and not value:
        return "empty"
    if isinstance(value, str):
        return f'`"{value}"`' if value else '`""`'
    return str(value)


def _default(field) -> str:
    if field.is_required():
        return "required"
    value = field.default
    if value is None:
        return "none"
    if isinstance(value, BaseModel):
        return "its defaults"
    return _shown(value, _field_dimension(field))


def _bounds(field) -> str:
    """The range a value must lie in (SI), from the field's constraints and its physical floor."""
    dimension = _field_dimension(field)
    unit = "" if dimension is None else SI_LABELS[dimension]
    text = _base(_optional(field.annotation)[0]) is str
    parts = []
    for item in field.metadata:
        for attr, sign in (("gt", ">"), ("ge", "≥"), ("lt", "<"), ("le", "≤")):
            value = getattr(item, attr, None)
            if value is not None:
                shown = _shown(float(value), dimension) if dimension == "angle" and value != 0 else \
                    f"{_number(float(value))} {unit}".strip()
                parts.append(f"{sign} {shown}")
        for attr, words in (("min_length", "at least {} {}"), ("max_length", "at most {} {}")):
            value = getattr(item, attr, None)
            if value is not None:
                parts.append(words.format(value, "character" if text else "entries").replace(
                    "1 entries", "1 entry"))
    floor = _field_floor(field)
    if floor is not None:
        if any(p.startswith("≥ 0") for p in parts):
            parts.append(f"0 or at least {floor}")
        else:
            parts = [f"≥ {floor}"] + [p for p in parts if not p.startswith("> 0")]
    return ", ".join(parts) or "—"


@functools.cache
def _bundled() -> list[dict]:
    """The bundled unit files as parsed TOML, by name (deterministic order)."""
    return [tomllib.loads(path.read_text(encoding="utf-8")) for path in sorted(CONFIGS.glob("*.toml"))]


def _lookup(data: Any, path: list[str]) -> Any:
    for part in path:
        if isinstance(data, list):
            data = next((item[part] for item in data if isinstance(item, dict) and part in item), None)
        elif isinstance(data, dict):
            data = data.get(part)
        else:
            return None
        if data is None:
            return None
    return data


def _designated(data: dict) -> str:
    """The class a bundled file's designation names (its letters), conventional by default."""
    from .unit_classes import unit_class

    try:
        return unit_class({}, data.get("designation"))
    except ValueError:
        return "conventional"


def _toml(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return '"' + value.replace('"', '\\"') + '"'
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, float) and value.is_integer():
        return repr(value)
    return str(value)


def _example(path: str, key_path: list[str], kind_of_unit: str | None) -> str:
    """A TOML value of the key from a bundled unit file of the same kind (and class), else EXAMPLES."""
    if path in EXAMPLES:
        return EXAMPLES[path]
    machine, _, unit_class = (kind_of_unit or "").partition(":")
    if path == "geometry.class" and unit_class:
        return f'"{unit_class}"'

    def rank(data: dict) -> int:   # files of the same class first, then of the same machine kind
        same_kind = data.get("kind", "beam-pump") == machine
        same_class = data.get("geometry", {}).get("class", _designated(data)) == unit_class
        return 0 if same_kind and same_class else 1 if same_kind else 2

    for data in sorted(_bundled(), key=rank):
        if rank(data) == 2:
            break
        names = (key_path[-1], *(GEOMETRY_ALIASES.get(key_path[-1], ()) if key_path[0] == "geometry" else ()))
        value = next((v for v in (_lookup(data, key_path[:-1] + [n]) for n in names) if v is not None), None)
        if value is not None and not isinstance(value, dict):
            if isinstance(value, list) and value and isinstance(value[0], dict):
                continue
            return _toml(value)
    raise KeyError(f"no example for {path}: give one in a bundled unit file or in EXAMPLES")


def _uses(section: str, key: str) -> str:
    path = f"{section}.{key}" if section else key
    if path in KEY_USES:
        return KEY_USES[path]
    probe = section
    while probe not in USED_BY:
        if "." not in probe:
            raise KeyError(f"no USED_BY entry for the section [{section}]")
        probe = probe.rsplit(".", 1)[0]
    return USED_BY[probe]


def _cell(text: str) -> str:
    return " ".join(text.replace("|", "\\|").split())


def _aliases(key: str) -> str:
    names = GEOMETRY_ALIASES.get(key)
    if key == "vertical_offset":
        return " (`l2`, or API `H` and `G`: H − G, or `K`: √(K² − I²))"
    return f" (`{'`, `'.join(names)}`)" if names else ""


def _table(model: type[BaseModel], title: str, section: str, doc_path: str, kind_of_unit: str | None,
           geometry: bool = False) -> list[str]:
    """The heading, introduction and key table of one section, then its subsections."""
    lines = [f"### `{title}`", ""]
    intro = (model.__doc__ or "").strip().split("\n\n")[0]
    if intro:
        lines += [" ".join(intro.split()), ""]
    rows, subsections = [], []
    for key, field in model.model_fields.items():
        name = field.alias or key
        sub, tables = _model(field.annotation), _tables_of(field.annotation)
        if sub is not None or tables is not None:
            subsections.append((name, sub or tables, tables is not None))
            continue
        path = f"{doc_path}.{name}" if doc_path else name
        toml_path = ([] if not section else section.split(".")) + [name]
        meaning = _cell(field.description or "")
        if geometry:
            meaning += _aliases(key)
        rows.append(f"| `{name}` | {_cell(_kind(field))} | {_cell(_default(field))} | "
                    f"{_cell(_bounds(field))} | `{_example(path, toml_path, kind_of_unit)}` | "
                    f"{_cell(_uses(doc_path, name))} | {meaning} |")
    if rows:
        lines += ["| key | unit kind [SI] | default | bounds (SI) | example | used by | meaning |",
                  "|---|---|---|---|---|---|---|", *rows, ""]
    for name, sub, many in subsections:
        sub_title = f"[{title.strip('[]')}.{name}]" if not many else f"[[{title.strip('[]')}.{name}]]"
        lines += _table(sub, sub_title, f"{section}.{name}" if section else name,
                        f"{doc_path}.{name}" if doc_path else name, kind_of_unit)
    return lines


def unit_file_reference() -> str:
    """The generated part of ``docs/unit-files.md``."""
    from .beam_unit import UnitConfig
    from .slider_crank import SliderCrankConfig
    from .unit_classes import UNIT_CLASSES

    lines = ["## Beam pumping units (`kind = \"beam-pump\"`, the default)", ""]
    top = {k: f for k, f in UnitConfig.model_fields.items() if _model(f.annotation) is None and k != "geometry"}
    lines += ["### Top-level keys", "", "| key | unit kind [SI] | default | bounds (SI) | example | used by | meaning |",
              "|---|---|---|---|---|---|---|"]
    for key, field in top.items():
        lines.append(f"| `{key}` | {_cell(_kind(field))} | {_cell(_default(field))} | "
                     f"{_cell(_bounds(field))} | `{_example(key, [key], 'beam-pump')}` | {_cell(_uses('', key))} | "
                     f"{_cell(field.description or '')} |")
    lines.append("")
    lines += ["### `[geometry]`, by kind of unit", "",
              "The kind is `[geometry] class`, else the designation's letters, else `conventional` "
              f"(`config/unit_classes.py`): {', '.join(f'`{name}`' for name in UNIT_CLASSES)}. Every kind "
              "takes the four-bar's lengths with the field name, the GOST name or the API 11E letter ([API11E]).", ""]
    for name, kind in UNIT_CLASSES.items():
        body = _table(kind.model(), "[geometry]", "geometry", "geometry", f"beam-pump:{name}", geometry=True)
        body[0] = f"#### `[geometry]` of a `{name}` unit"
        body = [line.replace("### `[geometry.", "#### `[geometry.") for line in body]
        lines += body
    for key, field in UnitConfig.model_fields.items():
        model = _model(field.annotation)
        if model is None or key == "geometry":
            continue
        lines += _table(model, f"[{key}]", key, key, "beam-pump")
    lines += ["## Slider-crank machines (`kind = \"slider-crank\"`)", ""]
    lines += ["### Top-level keys", "", "| key | unit kind [SI] | default | bounds (SI) | example | used by | meaning |",
              "|---|---|---|---|---|---|---|"]
    for key, field in SliderCrankConfig.model_fields.items():
        if _model(field.annotation) is not None:
            continue
        lines.append(f"| `{key}` | {_cell(_kind(field))} | {_cell(_default(field))} | "
                     f"{_cell(_bounds(field))} | `{_example('slider-crank.' + key, [key], 'slider-crank')}` | "
                     f"{_cell(_uses('slider-crank', key))} | {_cell(field.description or '')} |")
    lines.append("")
    for key, field in SliderCrankConfig.model_fields.items():
        model = _model(field.annotation)
        if model is not None:
            lines += _table(model, f"[{key}]", key, f"slider-crank.{key}", "slider-crank")
    text = "\n".join(lines)
    return re.sub(r"\n{3,}", "\n\n", text).rstrip("\n") + "\n"


def _write() -> None:
    text = PAGE.read_text(encoding="utf-8")
    start, end = text.index(BEGIN) + len(BEGIN), text.index(END)
    PAGE.write_text(text[:start] + "\n\n" + unit_file_reference() + "\n" + text[end:], encoding="utf-8")


if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        _write()
    else:
        print(unit_file_reference(), end="")
