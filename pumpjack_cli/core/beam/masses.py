"""Mass properties of the moving links of a beam pumping unit (SI), shared by the
kinetostatics and the equation of motion."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class MassModel:
    """Mass properties of the moving links, SI (kg, m, kg·m^2, rad).

    Crank arm and counterweights: values for one arm and for all blocks together
    (shared equally between the two arms); centres of mass along the crank arm
    (counterweights at ``counterweight_phase`` from the crank pin, in the direction of
    rotation). Pitman: centre of mass at ``pitman_cg`` from the crank pin along AB,
    moment of inertia across its axis (the axial one does no work: the pitman's spin
    is an idle freedom). Equalizer: centre of mass at D, inertia about its pin line and
    across it. Beam body and horsehead: centres of mass on the beam line at signed
    distances from C, towards the well positive.
    """

    crank_arm_mass: float
    crank_arm_cg: float
    crank_arm_inertia: float
    counterweight_mass: float
    counterweight_radius: float
    counterweight_phase: float
    pitman_mass: float
    pitman_cg: float
    pitman_inertia: float
    equalizer_mass: float
    equalizer_inertia: float
    equalizer_transverse_inertia: float
    beam_mass: float
    beam_cg: float
    beam_inertia: float
    horsehead_mass: float
    horsehead_cg: float
    horsehead_inertia: float


def counterweight_set_mass(block_mass: float, count: int) -> float:
    """Mass of all counterweight blocks on both crank arms [kg]: block mass [kg] x count."""
    return block_mass * count
