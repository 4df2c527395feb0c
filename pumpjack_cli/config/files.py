"""Unit files: the registry of machine kinds, validation, and loading a unit by name or path.

The files are read (bounded TOML, YAML and JSON, the bundled-unit folder, what a unit
spec names) by :mod:`pumpjack_cli.readers.unit_files`. A file's top-level ``kind`` key
picks its schema (default ``beam-pump``); the schema module is imported only when a file
of that kind is read, so a run builds the pydantic models of the files it reads and no
others. :func:`unit_listing` describes the bundled
units (name, kind, designation, exact stroke) without building any model, for
``pumpjack units``.
"""

from __future__ import annotations

import functools
import importlib
import math
import typing
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable

from ..errors import ConfigError
from ..quantities import SI_LABELS, parse_quantity
from ..readers.unit_files import bundled_units, parse_table, read_table, read_unit_text, unit_source
from .geometry_names import slider_crank_of
from .unit_classes import UNIT_CLASSES, raw_stroke

if TYPE_CHECKING:  # an operator's catalogue is read only when a command is given one
    from ..readers.catalogue import Catalogue


@dataclass(frozen=True)
class Kind:
    """A machine kind: the schema class (``module:Class`` under this package), the exact
    stroke [m] of a file's raw ``[geometry]`` table computed without the schema, and
    whether it is a beam pumping unit (a linkage driving a polished rod, which the
    beam-unit commands accept)."""

    schema: str
    stroke: Callable[[dict, str | None], float]
    beam_unit: bool

    def model(self) -> type:
        module, name = self.schema.split(":")
        return getattr(importlib.import_module(f".{module}", __package__), name)


#: Machine kinds a file can describe, by its top-level ``kind`` key (default beam-pump).
UNIT_KINDS: dict[str, Kind] = {
    "beam-pump": Kind("beam_unit:UnitConfig", raw_stroke, beam_unit=True),
    "slider-crank": Kind("slider_crank:SliderCrankConfig", lambda geometry, _: slider_crank_of(**geometry).stroke,
                         beam_unit=False),
}
DEFAULT_KIND = "beam-pump"


#: pydantic's error types of a number outside a field's range.
RANGE_ERRORS = ("greater_than", "greater_than_equal", "less_than", "less_than_equal")


def _inside(annotation: Any) -> list[Any]:
    """The types and metadata an annotation holds (unions, Annotated, tuples), flattened."""
    found = [annotation]
    for part in typing.get_args(annotation):
        found += _inside(part)
    return found


def field_path(loc: tuple) -> str:
    """A pydantic error location as a unit file's key path (``geometry.pitman``)."""
    return ".".join(str(part) for part in loc)


def _geometry_with(key: str) -> Any:
    """The ``[geometry]`` schema of the first kind of unit that has ``key`` (a key means one
    quantity in every kind that has it), None if none has."""
    return next((model for model in (kind.model() for kind in UNIT_CLASSES.values()) if key in model.model_fields),
                None)


def _dimension(model: Any, loc: tuple) -> str | None:
    """The physical dimension of the field at ``loc`` of a unit-file model, if it is a quantity."""
    from .quantities import dimension_of

    names = [part for part in loc if isinstance(part, str)]
    for depth, name in enumerate(names):
        field = getattr(model, "model_fields", {}).get(name)
        if field is None:
            return None
        parts = [*field.metadata, *_inside(field.annotation)]
        if depth == len(names) - 1:
            return dimension_of(parts)
        model = next((part for part in parts if isinstance(part, type) and hasattr(part, "model_fields")), None)
        if name == "geometry" and names[depth + 1] not in getattr(model, "model_fields", {}):
            model = _geometry_with(names[depth + 1])  # a beam unit's: its kind's own schema validates it
    return None


def error_message(error: dict, model: Any = None) -> str:
    """What is wrong, from one pydantic error of ``model``: a quantity out of range is
    shown in SI with its unit ("... less than or equal to 20 m; got 72 m")."""
    message = error["msg"].removeprefix("Value error, ")
    if error["type"] == "extra_forbidden":
        return "unknown key"
    dimension = _dimension(model, error["loc"]) if error["type"] in RANGE_ERRORS else None
    if dimension is None:
        return message
    try:
        value = parse_quantity(error["input"], dimension)
    except ValueError:
        return message
    unit = f" {SI_LABELS[dimension]}" if SI_LABELS[dimension] else ""
    if dimension == "angle":  # radians, and the degrees a unit file or an option is written in
        limit = next(iter(error.get("ctx", {}).values()), None)
        shown = "" if not isinstance(limit, (int, float)) else f" ({math.degrees(limit):.4g} deg)"
        return f"{message} rad{shown}; got {value:.6g} rad ({math.degrees(value):.6g} deg)"
    return f"{message}{unit}; got {value:.6g}{unit}"


def format_validation_error(source: str, error, model: Any = None,
                            place: Callable[[tuple], str] = field_path) -> str:
    """One line naming the file, the field and what is wrong with it (a pydantic
    ValidationError of ``model``); ``place`` names the field of an error location (default
    its key path, ``geometry.pitman``)."""
    first = error.errors()[0]
    where = place(first["loc"]) or "(top level)"
    more = len(error.errors()) - 1
    tail = f" (and {more} more problem{'s' if more > 1 else ''})" if more else ""
    return f"{source}: {where}: {error_message(first, model)}{tail}"


def _kind(data: Any, source: str) -> Kind:
    if not isinstance(data, dict):
        raise ConfigError(f"{source}: expected a table of sections at the top level")
    kind = data.get("kind", DEFAULT_KIND)
    if not isinstance(kind, str):
        raise ConfigError(f"{source}: kind: must be text, one of {', '.join(UNIT_KINDS)}; got {kind!r}")
    if kind not in UNIT_KINDS:
        raise ConfigError(f"{source}: kind: unknown machine kind {kind!r}; use one of {', '.join(UNIT_KINDS)}")
    return UNIT_KINDS[kind]


def parse_unit(data: Any, source: str, place: Callable[[tuple], str] = field_path, *, folder: Path | None = None):
    """Validate parsed file contents; ``source`` names the file in error messages and ``place``
    the field (:func:`format_validation_error`); ``folder`` is the one files named in it (a well's
    survey) are relative to."""
    from pydantic import ValidationError

    model = _kind(data, source).model()
    try:
        return model.model_validate(data, context={"folder": folder})
    except ValidationError as exc:
        raise ConfigError(format_validation_error(source, exc, model, place)) from None


def read_unit_file(path: Path):
    """Read and validate one unit file (read each time; validated once per text, :func:`_unit_of_text`)."""
    return _unit_of_text(path, read_unit_text(path))


@functools.lru_cache(maxsize=64)
def _unit_of_text(path: Path, text: str):
    """The validated unit of a file's ``text``, kept for the next time the same file holds the
    same text: a unit config is frozen and depends on nothing else (a survey it names is a path
    beside the file, read where it is used), and parsing and validating a unit file costs about a
    millisecond, which a batch's or a library user's repeated loads of one unit would pay each time."""
    return parse_unit(parse_table(path, text), str(path), folder=path.parent)


def unit_listing() -> list[dict[str, Any]]:
    """The bundled units as rows (name, kind, designation, stroke [m], description), read
    from the files without building their models (the files are validated by the tests)."""
    rows = []
    for name, path in bundled_units().items():
        data = read_table(path)
        kind = _kind(data, str(path))
        rows.append({"name": name, "kind": data.get("kind", DEFAULT_KIND), "designation": data["name"],
                     "stroke": kind.stroke(data["geometry"], data.get("designation")),
                     "description": data.get("description", "")})
    return rows


def load_any_unit(spec: str, catalogue: Catalogue | Path | None = None):
    """A unit of any kind by bundled name (case-insensitive, ``sk8-3.5-4000``), by file path, or
    as ``DESIGNATION/HOLE`` of an operator's ``catalogue`` (read, or its file; docs/catalogue.md)."""
    if isinstance(catalogue, Path):
        from ..readers.catalogue import read_catalogue

        catalogue = read_catalogue(catalogue)
    found = unit_source(spec, catalogue)
    if isinstance(found, Path):
        return read_unit_file(found)
    from .catalogue import catalogue_unit

    return catalogue_unit(found)


def load_unit(spec: str, catalogue: Catalogue | Path | None = None):
    """A beam pumping unit by bundled name, file path or catalogue name (:func:`load_any_unit`);
    other machine kinds are an error."""
    config = load_any_unit(spec, catalogue)
    if not UNIT_KINDS[config.kind].beam_unit:
        raise ConfigError(f"{spec}: is a {config.kind} machine, not a beam pumping unit")
    return config
