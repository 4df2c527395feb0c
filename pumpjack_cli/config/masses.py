"""Schema of a unit file's ``[masses]``: masses, centres of mass and inertias of the moving links,
and the core's mass model built from them (:class:`~pumpjack_cli.core.beam.masses.MassModel`)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from pydantic import Field

if TYPE_CHECKING:  # the mass model is imported when a command uses it
    from ..core.beam.masses import MassModel
from .quantities import Angle, Count, Length, Mass, MomentOfInertia, Section


class CrankArm(Section):
    """One of the two crank arms of the double crank (link 1), without counterweights."""

    mass: Mass = Field(gt=0, le=2e4, description="one crank arm (m_kr, m_1) [kg]")
    cg_radius: Length = Field(
        ge=0, le=5, description="crank shaft to the arm's centre of mass, towards the crank pin (OS_1) [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about its centre of mass, axis along the crank shaft [kg·m²]"
    )


class Counterweights(Section):
    """Counterweight blocks on the crank arms, treated as point masses at their centre of mass."""

    radius_range: tuple[Length, Length] | None = Field(
        default=None, description="smallest and largest radius the blocks can be set to in the crank's slots [m]")

    mass: Mass = Field(ge=0, le=5e3, description="one block (m_pr1) [kg]")
    count: Count = Field(ge=0, le=16, description="number of blocks on both arms together (shared equally)")
    radius: Length = Field(ge=0, le=5, description="crank shaft to the blocks' centre of mass (r_pr, OS_pr) [m]")
    phase: Angle = Field(
        default=0.0, gt=-math.pi, le=math.pi,
        description="angle from the crank pin direction to the blocks' centre of mass, in the direction of "
        "rotation; 0 on conventional units, whose blocks sit on the crank arm in line with the pin [rad]",
    )


class Pitman(Section):
    """One pitman (links 2 and 3 are equal)."""

    mass: Mass = Field(gt=0, le=5e3, description="one pitman (m_2) [kg]")
    cg_from_crank_pin: Length = Field(
        ge=0, le=20, description="crank pin A to the centre of mass, along the pitman (AS_2) [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about its centre of mass, across the pitman (J_S2) [kg·m²]"
    )


class Equalizer(Section):
    """Equalizer (cross-yoke, link 4); centre of mass at its bearing D on the beam."""

    mass: Mass = Field(ge=0, le=2e4, description="equalizer (m_tr, m_4) [kg]")
    inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about D, axis along the crank shaft (its pin line BB1) [kg·m²]"
    )
    transverse_inertia: MomentOfInertia = Field(
        ge=0, le=1e5, description="moment of inertia about D, axes across the pin line [kg·m²]"
    )


class BeamPart(Section):
    """The walking beam body or the horsehead; centre of mass on the beam line D-C-E."""

    mass: Mass = Field(ge=0, le=5e4, description="mass [kg]")
    cg: Length = Field(
        ge=-20, le=20, description="centre bearing C to the centre of mass along the beam, towards the well positive [m]"
    )
    inertia: MomentOfInertia = Field(
        ge=0, le=1e6, description="moment of inertia about its centre of mass, axis along the crank shaft [kg·m²]"
    )


class Masses(Section):
    """Masses, centres of mass and inertias of the moving links.

    The names in parentheses in the descriptions are those of [Spatial7SK12],
    [PopovychSenchishak] and [SK8Rotation2013].
    """

    crank_arm: CrankArm
    counterweights: Counterweights
    pitman: Pitman
    equalizer: Equalizer
    beam: BeamPart = Field(description="walking beam body (m_b, m_bal)")
    horsehead: BeamPart = Field(description="horsehead (m_gb)")

    def model(self, counterweight_count: int | None = None, counterweight_radius: float | None = None) -> MassModel:
        """The numerical core's view of the masses, with the number of counterweight blocks or
        their radius [m] replaced if given."""
        from ..core.beam.masses import MassModel, counterweight_set_mass

        count = self.counterweights.count if counterweight_count is None else counterweight_count
        return MassModel(
            crank_arm_mass=self.crank_arm.mass,
            crank_arm_cg=self.crank_arm.cg_radius,
            crank_arm_inertia=self.crank_arm.inertia,
            counterweight_mass=counterweight_set_mass(self.counterweights.mass, count),
            counterweight_radius=self.counterweights.radius if counterweight_radius is None else counterweight_radius,
            counterweight_phase=self.counterweights.phase,
            pitman_mass=self.pitman.mass,
            pitman_cg=self.pitman.cg_from_crank_pin,
            pitman_inertia=self.pitman.inertia,
            equalizer_mass=self.equalizer.mass,
            equalizer_inertia=self.equalizer.inertia,
            equalizer_transverse_inertia=self.equalizer.transverse_inertia,
            beam_mass=self.beam.mass,
            beam_cg=self.beam.cg,
            beam_inertia=self.beam.inertia,
            horsehead_mass=self.horsehead.mass,
            horsehead_cg=self.horsehead.cg,
            horsehead_inertia=self.horsehead.inertia,
        )
