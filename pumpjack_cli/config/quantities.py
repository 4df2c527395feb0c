"""Field types of unit files: SI floats parsed once from numbers or strings with units.

Every physical field of a unit file is one of these annotated types; the conversion is
:func:`pumpjack_cli.quantities.parse_quantity`, so ``"3500 mm"``, ``"137.5 in"`` and
``3.5`` all become 3.5 (metres) here and everything downstream is SI.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel, BeforeValidator, ConfigDict, Strict

from ..quantities import parse_quantity


def _quantity(dimension: str) -> BeforeValidator:
    """The validator of a field of ``dimension``: a plain one-argument function (pydantic
    inspects each validator's signature, and a partial's costs start-up time)."""

    def parse(value: Any) -> float:
        return parse_quantity(value, dimension)

    parse.dimension = dimension  # type: ignore[attr-defined]  # read by dimension_of
    return BeforeValidator(parse)


def dimension_of(metadata: Iterable[Any]) -> str | None:
    """The dimension a field's metadata items parse its value as (the first quantity validator
    among them), else None."""
    return next((item.func.dimension for item in metadata if hasattr(getattr(item, "func", None), "dimension")), None)


def _printable(text: str) -> str:
    """Text shown on a terminal (a unit's name, description, designation): no control characters,
    which would move the cursor or recolour the terminal when a message or table prints them."""
    if not text.isprintable():
        raise ValueError("must be printable text, without control characters (escape sequences, tabs, line breaks)")
    return text


#: Text of a unit file that the commands print.
Text = Annotated[str, AfterValidator(_printable)]

Length = Annotated[float, _quantity("length")]
Mass = Annotated[float, _quantity("mass")]
MomentOfInertia = Annotated[float, _quantity("moment_of_inertia")]
RotationalSpeed = Annotated[float, _quantity("rotational_speed")]
Power = Annotated[float, _quantity("power")]
Density = Annotated[float, _quantity("density")]
KinematicViscosity = Annotated[float, _quantity("kinematic_viscosity")]
Fraction = Annotated[float, _quantity("fraction")]
Angle = Annotated[float, _quantity("angle")]
Pressure = Annotated[float, _quantity("pressure")]
Force = Annotated[float, _quantity("force")]
Torque = Annotated[float, _quantity("torque")]
WeightPerLength = Annotated[float, _quantity("weight_per_length")]
AreaMoment = Annotated[float, _quantity("area_moment")]
Area = Annotated[float, _quantity("area")]
Volume = Annotated[float, _quantity("volume")]
RotationalStiffness = Annotated[float, _quantity("rotational_stiffness")]
#: Plain numbers without a unit; strict so that ``true`` is not read as 1.
Number = Annotated[float, Strict()]
Count = Annotated[int, Strict()]


def at_least(minimum: float, shown: str) -> AfterValidator:
    """A physical floor for a positive field: smaller values (down to the subnormal
    1e-320) would make the computation overflow instead of being refused by name."""

    def check(value: float) -> float:
        if 0 < value < minimum:
            raise ValueError(f"{value:.3g} is too small: give at least {shown} (SI {minimum:g})")
        return value

    check.minimum, check.shown = minimum, shown  # read by docs/unit-files.md's generator (.reference)
    return AfterValidator(check)


class Section(BaseModel):
    """A table of a unit file: unknown keys are errors, values are immutable."""

    model_config = ConfigDict(extra="forbid", frozen=True, populate_by_name=True)
