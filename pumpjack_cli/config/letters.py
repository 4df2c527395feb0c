"""The API Spec 11E letters every beam unit's ``[geometry]`` has: the four-bar and its rotation.

:class:`BeamLetters` is the base of each kind's schema (:mod:`.unit_classes`): the lengths
A, C, R, P, I and H - G (or K) written with the GOST names or the letters ([API11E];
:mod:`.geometry_names`) and the rotation. A kind adds its ``class`` tag, its counterbalance
keys and ``mechanism()`` (its :class:`~pumpjack_cli.core.mechanism.Mechanism`), and the
unit is refused when that mechanism cannot turn.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from ..errors import GeometryError
from .geometry_names import canonical_geometry
from .quantities import Length, Section, at_least


class BeamLetters(Section):
    """The four-bar of a beam unit, rotation direction included."""

    front_arm: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=20, description="k1 / A: centre bearing to horsehead arc [m]")
    rear_arm: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=20, description="k / C: centre bearing to equalizer bearing [m]")
    crank_radius: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=5, description="r / R: crank shaft to crank pin [m]")
    pitman: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=20, description="l / P: crank pin to equalizer bearing [m]")
    horizontal_offset: Length = Field(
        ge=0, le=20, description="l1 / I: horizontal distance crank shaft - centre bearing [m]"
    )
    vertical_offset: Annotated[Length, at_least(0.01, "10 mm")] = Field(
        gt=0, le=20, description="l2 / H-G: height of the centre bearing above the crank shaft [m]"
    )
    rotation: Literal["clockwise", "counterclockwise"] = Field(
        description="crank rotation seen with the well to the right"
    )

    @model_validator(mode="before")
    @classmethod
    def _names(cls, data: Any) -> Any:
        """Map GOST names and API letters to field names; reject double definitions."""
        return canonical_geometry(data) if isinstance(data, dict) else data

    @model_validator(mode="after")
    def _assembles(self) -> "BeamLetters":
        try:
            self.mechanism().check()
        except GeometryError as exc:
            raise ValueError(str(exc)) from None
        return self

    def mechanism(self) -> Any:
        """The kind's mechanism (each kind's schema defines it)."""
        raise NotImplementedError
