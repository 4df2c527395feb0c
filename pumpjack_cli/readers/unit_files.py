"""Unit files as plain data: bounded TOML, YAML and JSON, the bundled units, and what a unit spec names.

A unit file is UTF-8 text of at most :data:`MAX_BYTES`, parsed with duplicate keys and
YAML aliases refused and nested at most :data:`MAX_DEPTH` deep; nothing is validated
here (the schemas are :mod:`pumpjack_cli.config`). :func:`unit_source` is the one place
that turns what a user writes for a unit (a bundled unit's name, a file path or a unit of
an operator's catalogue, :mod:`.catalogue`) into a file or a catalogue row, for loading it
and for the content keys of `pumpjack batch` alike.
"""

from __future__ import annotations

import difflib
import importlib
import json
import os
import re
import tomllib
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..errors import ConfigError
from ..text_input import digit_limit, read_text
if TYPE_CHECKING:  # an operator's catalogue is read only when a command is given one
    from .catalogue import Catalogue, CatalogueRow

BUNDLED_PACKAGE = "pumpjack_cli.configs"
SUFFIXES = (".toml", ".yaml", ".yml", ".json")
#: Largest unit file read [bytes]; the bundled ones are 2-5 kB.
MAX_BYTES = 1 << 20
#: Deepest nesting of tables and lists in a unit file (the schema needs 4).
MAX_DEPTH = 8


def _unique_pairs(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """A JSON object that refuses a key given twice (json keeps the last one silently)."""
    seen: dict[str, Any] = {}
    for key, value in pairs:
        if key in seen:
            raise ConfigError(f"key {key!r} is given twice")
        seen[key] = value
    return seen


def _yaml_loader():
    """A safe YAML loader that refuses duplicate keys and aliases (a small file with
    nested aliases can expand beyond any memory)."""
    import yaml

    class Loader(yaml.SafeLoader):
        def compose_node(self, parent, index):
            if self.check_event(yaml.AliasEvent):
                mark = self.peek_event().start_mark
                raise yaml.YAMLError(f"aliases (*name) are not accepted, at line {mark.line + 1}")
            return super().compose_node(parent, index)

        def construct_mapping(self, node, deep=False):
            keys = [self.construct_object(key, deep=deep) for key, _ in node.value]
            for i, key in enumerate(keys):
                if key in keys[:i]:
                    line = node.value[i][0].start_mark.line + 1
                    raise yaml.YAMLError(f"key {key!r} is given twice, at line {line}")
            return super().construct_mapping(node, deep=deep)

    return Loader


def _depth(value: Any) -> int:
    if isinstance(value, dict):
        return 1 + max(map(_depth, value.values()), default=0)
    if isinstance(value, list):
        return 1 + max(map(_depth, value), default=0)
    return 0


def _flow_depth(text: str) -> int:
    """The deepest nesting of YAML flow collections (``[``, ``{``) outside quotes and comments:
    the YAML parser's scanner is quadratic in it, so a file nested far deeper than a unit file
    can be is refused before it is parsed (``[`` x 5000 took seconds)."""
    depth = deepest = 0
    quote = ""
    for line in text.splitlines():
        for char in line:
            if quote:
                quote = "" if char == quote else quote
            elif char in "'\"":
                quote = char
            elif char == "#":
                break
            elif char in "[{":
                depth += 1
                deepest = max(deepest, depth)
            elif char in "]}":
                depth -= 1
    return deepest


def parse_table(path: Path, text: str) -> Any:
    """The parsed content of a unit file's ``text`` (``path``: its name, whose suffix says the
    format), not validated: :func:`read_table` without the reading."""
    suffix = path.suffix.lower()
    formats = {".toml": "TOML", ".json": "JSON", ".yaml": "YAML", ".yml": "YAML"}
    if suffix not in formats:
        raise ConfigError(f"{path}: unknown file type {suffix!r}; use one of {', '.join(SUFFIXES)}")
    name = formats[suffix]
    try:
        if name == "TOML":
            data = tomllib.loads(text)
        elif name == "JSON":
            data = json.loads(text, object_pairs_hook=_unique_pairs)
        else:
            import yaml

            if _flow_depth(text) > 4 * MAX_DEPTH:
                raise RecursionError
            try:
                data = yaml.load(text, Loader=_yaml_loader())  # noqa: S506 - a SafeLoader subclass
            except yaml.YAMLError as exc:
                mark = getattr(exc, "problem_mark", None)
                where = f" at line {mark.line + 1}" if mark is not None else ""
                raise ConfigError(f"{path}: not valid YAML: {getattr(exc, 'problem', None) or exc}{where}") from None
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: not valid TOML: {exc}") from None
    except json.JSONDecodeError as exc:
        raise ConfigError(f"{path}: not valid JSON: {exc.msg} at line {exc.lineno}") from None
    except ConfigError as exc:
        if str(exc).startswith(f"{path}: "):   # said whole already (a YAML error with its line)
            raise
        raise ConfigError(f"{path}: not valid {name}: {exc}") from None
    except ValueError as exc:
        what = digit_limit(exc)
        if what is None:
            raise
        raise ConfigError(f"{path}: not valid {name}: {what}") from None
    except RecursionError:
        raise ConfigError(f"{path}: not valid {name}: nested too deep") from None
    if _depth(data) > MAX_DEPTH:
        raise ConfigError(f"{path}: nested {_depth(data)} levels deep; a unit file has at most {MAX_DEPTH}")
    return data


def read_unit_text(path: Path) -> str:
    """The text of a unit file (bounded, UTF-8)."""
    return read_text(path, MAX_BYTES, "unit file", ConfigError)


def read_table(path: Path) -> Any:
    """The parsed content of a TOML, YAML or JSON file of the unit-file kind (bounded, UTF-8,
    duplicate keys refused), not validated."""
    return parse_table(path, read_unit_text(path))


def bundled_units() -> dict[str, Path]:
    """Bundled unit files by name (file stem), sorted."""
    folder = Path(next(iter(importlib.import_module(BUNDLED_PACKAGE).__path__)))
    return {entry.stem: entry for entry in sorted(folder.iterdir(), key=lambda e: e.name) if entry.suffix in SUFFIXES}


#: A unit spec naming a crank hole of a catalogue's unit: ``DESIGNATION/HOLE``.
HOLE_SPEC = re.compile(r"^(?P<designation>[^/\\]+)/(?P<hole>[0-9]+)$")


def designation_key(text: str) -> str:
    """A designation as names are compared: case-insensitive, a decimal comma read as a point."""
    return text.strip().lower().replace(",", ".")


def names_a_crank_hole(spec: str) -> bool:
    """Whether a unit spec is written ``DESIGNATION/HOLE`` (``C-228D-213-86/3``)."""
    return HOLE_SPEC.match(spec.strip()) is not None


def names_a_file(spec: str) -> bool:
    """Whether a unit spec is written as a file (a unit-file suffix or a folder in it) rather
    than as a bundled unit's name or a catalogue's ``DESIGNATION/HOLE``."""
    return Path(spec).suffix.lower() in SUFFIXES or (os.sep in spec and not names_a_crank_hole(spec))


def unit_source(spec: str, catalogue: Catalogue | None = None) -> Path | CatalogueRow:
    """What a unit spec names: a file path (written as one, or an existing file), else a
    bundled unit by name, case-insensitive and with the GOST decimal comma
    (``SK8-3,5-4000`` is ``sk8-3.5-4000``), else a row of the ``catalogue``
    (``DESIGNATION/HOLE``, :meth:`~.catalogue.Catalogue.find`); an unknown name is a
    :class:`ConfigError` listing the names close to it."""
    if names_a_file(spec) or os.path.lexists(spec):
        return Path(spec)
    units = bundled_units()
    key = designation_key(spec)
    if key in units:
        return units[key]
    row = catalogue.find(spec) if catalogue is not None else None
    if row is None:
        raise _unknown(spec, list(units), catalogue)
    return row


def _unknown(spec: str, bundled: list[str], catalogue: Catalogue | None) -> ConfigError:
    """The error of a unit spec that names nothing: the bundled units, or the names close to it."""
    if catalogue is None:
        hint = "; DESIGNATION/HOLE names a unit of --catalogue FILE" if names_a_crank_hole(spec) else ""
        return ConfigError(f"unknown unit {spec!r}: give a file path or one of {', '.join(bundled)}{hint}")
    names = {designation_key(name): name for name in [*bundled, *(row.name for row in catalogue.rows)]}
    close = [names[key] for key in difflib.get_close_matches(designation_key(spec), names, n=6)]
    listed = f"close: {', '.join(close)}" if close else f"`pumpjack units --catalogue {catalogue.source}` lists its units"
    return ConfigError(f"unknown unit {spec!r}: not a file, a bundled unit or a unit of {catalogue.source}; {listed}")
