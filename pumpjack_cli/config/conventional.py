"""Schema of the ``[geometry]`` of a conventional (class I, crank-balanced) unit, and its mechanism.

The four-bar of :class:`~pumpjack_cli.core.beam.geometry.Linkage`, written with the GOST
names or the API Spec 11E letters ([API11E]; :mod:`.geometry_names`); the spatial model
of the six-link mechanism ([Spatial7SK12]) when the pin spacings are given.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field

from ..core.beam.geometry import Linkage, beam_linkage
from ..errors import ConfigError
from .geometry_names import ROTATION_SIGNS
from .letters import BeamLetters
from .quantities import Angle, Length, at_least

if TYPE_CHECKING:  # the core's models are imported when a command uses them
    from ..core.beam.counterbalance import Counterbalance
    from ..core.mechanism import Mechanism
    from ..core.beam.masses import MassModel
    from ..core.beam.spatial import SpatialLinkage
    from .beam_unit import CounterbalanceConfig


#: Largest difference between the crank offset of the counterweight blocks and the one stated [rad].
OFFSET_TOLERANCE = math.radians(0.5)


class ConventionalGeometry(BeamLetters):
    """Four-bar geometry of a conventional (class I) unit, rotation direction included."""

    unit_class: Literal["conventional"] = Field(
        default="conventional", alias="class",
        description="kind of unit (config/unit_classes.py): conventional, the crank-balanced class I lever")

    crank_half_spacing: Annotated[Length, at_least(0.01, "10 mm")] | None = Field(
        default=None, gt=0, le=5,
        description="spatial model: crank shaft mid-plane to each crank pin, along the shaft [m]",
    )
    equalizer_half_length: Annotated[Length, at_least(0.01, "10 mm")] | None = Field(
        default=None, gt=0, le=5, description="spatial model: equalizer bearing D to each pin, BD = DB1 [m]"
    )

    def mechanism(self) -> Linkage:
        """The numerical core's planar four-bar (:func:`~pumpjack_cli.core.beam.geometry.beam_linkage`)."""
        return beam_linkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                            self.vertical_offset, ROTATION_SIGNS[self.rotation], self.crank_half_spacing,
                            self.equalizer_half_length)

    def counterbalance(self, given: CounterbalanceConfig | None, masses: MassModel | None) -> tuple[Counterbalance, bool]:
        """Crank counterweights (B, M, tau of the API method) and whether M is known
        (:func:`crank_counterweights`)."""
        return crank_counterweights(self.mechanism(), given, masses)

    def spatial(self, source: str = "unit") -> SpatialLinkage:
        """The spatial model; needs crank_half_spacing and equalizer_half_length."""
        if self.crank_half_spacing is None or self.equalizer_half_length is None:
            raise ConfigError(
                f"{source}: geometry: the spatial model needs crank_half_spacing and equalizer_half_length"
            )
        from ..core.beam.spatial import SpatialLinkage

        return SpatialLinkage(self.mechanism(), self.crank_half_spacing, self.equalizer_half_length)


class PhasedCrankGeometry(BeamLetters):
    """The letters of a kind whose crank counterweights are phased by a crank offset (Mark II,
    reverse-mark): ``crank_offset`` and the counterweights it places."""

    crank_offset: Angle = Field(
        ge=-1.0, le=1.0, description="tau: crank offset angle as catalogues print it, the lead of the "
        "counterweights' resultant ahead of the arm they ride on, in the direction of rotation (negative: a lag): "
        "on class I units ahead of the crank pin in T = TF (W - B) - M sin(theta + tau), on class III units ahead "
        "of the crank's tail in T = TF (W - B) + M sin(theta + tau) (docs/units.md) [rad]")

    def counterbalance(self, given: CounterbalanceConfig | None, masses: MassModel | None) -> tuple[Counterbalance, bool]:
        """Crank counterweights with the crank offset (:func:`crank_counterweights`)."""
        return crank_counterweights(self.mechanism(), given, masses, self.crank_offset)


def crank_counterweights(mechanism: Mechanism, given: CounterbalanceConfig | None, masses: MassModel | None,
                         offset: float | None = None) -> tuple[Counterbalance, bool]:
    """Crank counterweights of a crank-balanced kind and whether M is known: the unit file's
    ``[counterbalance]`` if given (tau its ``phase``, or ``offset`` [rad], the kind's
    ``crank_offset``), else from the link masses
    (:func:`~pumpjack_cli.core.beam.counterbalance.counterbalance_from_masses`). On a class III
    mechanism the counterweights ride on the crank's tail
    (:class:`~pumpjack_cli.core.beam.counterbalance.Counterbalance`)."""
    from ..core.beam.counterbalance import Counterbalance, counterbalance_from_masses

    if given is not None:
        if offset is not None and given.phase != 0.0:
            raise ConfigError("[counterbalance] phase: this kind's crank offset is [geometry] crank_offset")
        tau = given.phase if offset is None else offset
        return (Counterbalance(given.structural_unbalance, given.moment or 0.0, tau, mechanism.lever_class == "III"),
                given.moment is not None)
    if masses is not None:
        found = counterbalance_from_masses(mechanism, masses)
        if offset is not None and abs(math.remainder(found.offset - offset, 2.0 * math.pi)) > OFFSET_TOLERANCE:
            raise ConfigError(f"[masses] counterweights put the crank offset at {math.degrees(found.offset):.4g} deg, "
                              f"[geometry] crank_offset says {math.degrees(offset):.4g} deg: give the blocks' phase "
                              f"that matches (docs/units.md)")
        return found, True
    raise ConfigError("neither [counterbalance] nor [masses]: give at least [counterbalance] structural_unbalance "
                      "(and moment for the present net torque)")
