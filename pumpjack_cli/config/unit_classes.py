"""The kinds of beam pumping unit a unit file can describe: the registry of ``[geometry] class``.

Each kind is a schema module under :mod:`pumpjack_cli.config` whose ``[geometry]`` model
builds the kind's mechanism (``mechanism()``, a :class:`~pumpjack_cli.core.mechanism.Mechanism`),
the designation letters that name it (``C-228D-213-86`` is conventional; a maker's own
letters, such as Lufkin's RM, are declared here and nowhere else), and the
exact stroke of a raw ``[geometry]`` table computed without pydantic (``pumpjack units``).
Adding a kind is its mechanism module in :mod:`pumpjack_cli.core.beam` (unless it shares
one), its schema module here, and one line in :data:`UNIT_CLASSES`
(``docs/architecture.md``).

The class is the file's ``[geometry] class`` key; without it, the designation's letters
decide, else the unit is conventional; a key that contradicts the designation is an error.
Pure Python: ``pumpjack units`` reads it at start-up.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..core.designations import API_TYPES
from .geometry_names import linkage_of


@dataclass(frozen=True)
class UnitClass:
    """A kind of beam unit: its ``[geometry]`` schema (``module:Class`` under this package), the
    designation letters that name it ([API11E]), and the exact stroke [m] of a raw
    ``[geometry]`` table."""

    schema: str
    letters: tuple[str, ...]
    stroke: Callable[[dict], float]

    def model(self) -> type:
        module, name = self.schema.split(":")
        return getattr(importlib.import_module(f".{module}", __package__), name)


def four_bar_stroke(geometry: dict) -> float:
    """The exact stroke [m] of a beam unit's letters: the class I four-bar's, which is also the
    class III four-bar's of the same letters (the mirror identity,
    :mod:`pumpjack_cli.core.beam.class_three`)."""
    return linkage_of(geometry).stroke


#: The kinds of beam unit, by their ``[geometry] class``.
UNIT_CLASSES: dict[str, UnitClass] = {
    "conventional": UnitClass("conventional:ConventionalGeometry", ("C",), four_bar_stroke),
    "mark-ii": UnitClass("mark_ii:MarkIIGeometry", ("M",), four_bar_stroke),
    "reverse-mark": UnitClass("reverse_mark:ReverseMarkGeometry", ("RM",), four_bar_stroke),  # [LufkinRM]
    "air-balanced": UnitClass("air_balanced:AirBalancedGeometry", ("A",), four_bar_stroke),
    "beam-balanced": UnitClass("beam_balanced:BeamBalancedGeometry", ("B",), four_bar_stroke),
}
DEFAULT_CLASS = "conventional"


def designation_types() -> dict[str, str]:
    """The designation letters of every kind and the kind each names
    (:func:`pumpjack_cli.core.designations.parse_designation`'s ``types``)."""
    return {letter: name for name, kind in UNIT_CLASSES.items() for letter in kind.letters}


def _designation_class(designation: str | None) -> str | None:
    """The kind an API designation's type letters name, None for a GOST designation or none.

    >>> _designation_class("C-228D-213-86"), _designation_class("SK8-3,5-4000"), _designation_class(None)
    ('conventional', None, None)
    """
    if designation is None:
        return None
    head = designation.strip().upper().split("-", 1)[0].strip()
    types = designation_types()
    if head in types:
        return types[head]
    if head in API_TYPES:
        raise ValueError(f"the designation {designation!r} names a {API_TYPES[head]} unit, a kind of unit this "
                         f"version does not model (kinds: {', '.join(UNIT_CLASSES)})")
    return None


def unit_class(geometry: Any, designation: str | None) -> str:
    """The ``[geometry] class`` of a unit: the key, else the designation's, else conventional.

    Raises ValueError for an unknown class or one the designation contradicts.
    """
    named = _designation_class(designation)
    given = geometry.get("class") if isinstance(geometry, dict) else None
    if given is None:
        return named or DEFAULT_CLASS
    if given not in UNIT_CLASSES:
        raise ValueError(f"class {given!r} is not a kind of unit; use one of {', '.join(UNIT_CLASSES)}")
    if named is not None and named != given:
        raise ValueError(f"class {given!r} contradicts the designation {designation!r}, which names a {named} unit")
    return given


def raw_stroke(geometry: dict, designation: str | None) -> float:
    """The exact stroke [m] of a raw ``[geometry]`` table, by its kind (no model built)."""
    return UNIT_CLASSES[unit_class(geometry, designation)].stroke(geometry)
