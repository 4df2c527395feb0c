"""Unit files: reading TOML, YAML and JSON, the bundled units, and the registry of machine kinds.

A file's top-level ``kind`` key picks its schema (default ``beam-pump``); the schema
module is imported only when a file of that kind is read, so a run builds the pydantic
models of the files it reads and no others. :func:`unit_listing` describes the bundled
units (name, kind, designation, exact stroke) without building any model, for
``pumpjack units``.
"""

from __future__ import annotations

import importlib
import json
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, Callable

from ..errors import ConfigError
from .geometry_names import linkage_of, slider_crank_of

BUNDLED_PACKAGE = "pumpjack_cli.configs"
SUFFIXES = (".toml", ".yaml", ".yml", ".json")


@dataclass(frozen=True)
class Kind:
    """A machine kind: the schema class (``module:Class`` under this package), the exact
    stroke [m] of a file's raw ``[geometry]`` table computed without the schema, and
    whether it is a beam pumping unit (a linkage driving a polished rod, which the
    beam-unit commands accept)."""

    schema: str
    stroke: Callable[[dict], float]
    beam_unit: bool

    def model(self) -> type:
        module, name = self.schema.split(":")
        return getattr(importlib.import_module(f".{module}", __package__), name)


#: Machine kinds a file can describe, by its top-level ``kind`` key (default beam-pump).
UNIT_KINDS: dict[str, Kind] = {
    "beam-pump": Kind("beam_unit:UnitConfig", lambda geometry: linkage_of(geometry).stroke, beam_unit=True),
    "slider-crank": Kind("slider_crank:SliderCrankConfig", lambda geometry: slider_crank_of(**geometry).stroke,
                         beam_unit=False),
}
DEFAULT_KIND = "beam-pump"


def _parse_text(path: Path, text: str) -> Any:
    suffix = path.suffix.lower()
    try:
        if suffix == ".toml":
            return tomllib.loads(text)
        if suffix == ".json":
            return json.loads(text)
        if suffix in (".yaml", ".yml"):
            import yaml

            return yaml.safe_load(text)
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: not valid TOML: {exc}") from None
    except json.JSONDecodeError as exc:
        raise ConfigError(f"{path}: not valid JSON: {exc.msg} at line {exc.lineno}") from None
    except Exception as exc:  # yaml.YAMLError; yaml is imported lazily
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark is not None else ""
        raise ConfigError(f"{path}: not valid YAML: {getattr(exc, 'problem', exc)}{where}") from None
    raise ConfigError(f"{path}: unknown file type {suffix!r}; use one of {', '.join(SUFFIXES)}")


def format_validation_error(source: str, error) -> str:
    """One line naming the file, the field and what is wrong with it (a pydantic ValidationError)."""
    first = error.errors()[0]
    where = ".".join(str(part) for part in first["loc"]) or "(top level)"
    message = first["msg"].removeprefix("Value error, ")
    if first["type"] == "extra_forbidden":
        message = "unknown key"
    more = len(error.errors()) - 1
    tail = f" (and {more} more problem{'s' if more > 1 else ''})" if more else ""
    return f"{source}: {where}: {message}{tail}"


def _kind(data: Any, source: str) -> Kind:
    if not isinstance(data, dict):
        raise ConfigError(f"{source}: expected a table of sections at the top level")
    kind = data.get("kind", DEFAULT_KIND)
    if kind not in UNIT_KINDS:
        raise ConfigError(f"{source}: kind: unknown machine kind {kind!r}; use one of {', '.join(UNIT_KINDS)}")
    return UNIT_KINDS[kind]


def parse_unit(data: Any, source: str):
    """Validate parsed file contents; ``source`` names the file in error messages."""
    from pydantic import ValidationError

    model = _kind(data, source).model()
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        raise ConfigError(format_validation_error(source, exc)) from None


def _read(path: Path) -> Any:
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise ConfigError(f"{path}: cannot read: {exc.strerror}") from None
    return _parse_text(path, text)


def read_unit_file(path: Path):
    """Read and validate one unit file."""
    return parse_unit(_read(path), str(path))


def bundled_units() -> dict[str, Path]:
    """Bundled unit files by name (file stem), sorted."""
    folder = resources.files(BUNDLED_PACKAGE)
    return {
        Path(entry.name).stem: Path(str(entry))
        for entry in sorted(folder.iterdir(), key=lambda e: e.name)
        if Path(entry.name).suffix in SUFFIXES
    }


def unit_listing() -> list[dict[str, Any]]:
    """The bundled units as rows (name, kind, designation, stroke [m], description), read
    from the files without building their models (the files are validated by the tests)."""
    rows = []
    for name, path in bundled_units().items():
        data = _read(path)
        kind = _kind(data, str(path))
        rows.append({"name": name, "kind": data.get("kind", DEFAULT_KIND), "designation": data["name"],
                     "stroke": kind.stroke(data["geometry"]), "description": data.get("description", "")})
    return rows


def load_any_unit(spec: str):
    """A unit of any kind by bundled name (case-insensitive, ``sk8-3.5-4000``) or by file path."""
    path = Path(spec)
    if path.suffix.lower() in SUFFIXES or path.exists():
        if not path.exists():
            raise ConfigError(f"{spec}: no such file")
        return read_unit_file(path)
    units = bundled_units()
    key = spec.lower().replace(",", ".")
    if key not in units:
        raise ConfigError(f"unknown unit {spec!r}: give a file path or one of {', '.join(units)}")
    return read_unit_file(units[key])


def load_unit(spec: str):
    """A beam pumping unit by bundled name or file path; other machine kinds are an error."""
    config = load_any_unit(spec)
    if not UNIT_KINDS[config.kind].beam_unit:
        raise ConfigError(f"{spec}: is a {config.kind} machine, not a beam pumping unit")
    return config
