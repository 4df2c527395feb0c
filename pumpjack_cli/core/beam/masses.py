"""Mass properties of the moving links of a beam pumping unit (SI), shared by the
kinetostatics and the equation of motion."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class MassModel:
    """Mass properties of the moving links, SI.

    Crank arm and counterweights: values for one arm and for all blocks together
    (shared equally between the two arms); centres of mass along the crank arm
    (counterweights at ``counterweight_phase`` from the crank pin, in the direction of
    rotation). Pitman: centre of mass at ``pitman_cg`` from the crank pin along AB,
    moment of inertia across its axis (the axial one does no work: the pitman's spin
    is an idle freedom). Equalizer: centre of mass at D, inertia about its pin line and
    across it. Beam body and horsehead: centres of mass on the beam line at signed
    distances from C, towards the well positive. The names in brackets in the unit
    files are those of [Spatial7SK12], [PopovychSenchishak] and [SK8Rotation2013].

    Attributes
    ----------
    crank_arm_mass, crank_arm_cg, crank_arm_inertia : float
        One crank arm: mass [kg], shaft to its centre of mass [m], moment of inertia
        about that centre, axis along the shaft [kg·m²].
    counterweight_mass, counterweight_radius, counterweight_phase : float
        All blocks: mass [kg], shaft to their centre of mass [m], angle from the crank
        pin direction in the direction of rotation [rad].
    pitman_mass, pitman_cg, pitman_inertia : float
        One pitman: mass [kg], crank pin to its centre of mass [m], centroidal moment
        of inertia across the pitman [kg·m²].
    equalizer_mass, equalizer_inertia, equalizer_transverse_inertia : float
        Mass [kg]; moments of inertia about D, about the pin line and across it [kg·m²].
    beam_mass, beam_cg, beam_inertia : float
        Beam body: mass [kg], signed distance of its centre from C [m], centroidal
        moment of inertia [kg·m²].
    horsehead_mass, horsehead_cg, horsehead_inertia : float
        Horsehead, likewise [kg, m, kg·m²].
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
    """Mass of all counterweight blocks on both crank arms: block mass x count.

    Parameters
    ----------
    block_mass : float
        One block [kg].
    count : int
        Number of blocks on both arms together (dimensionless).

    Returns
    -------
    float
        Total [kg].

    References
    ----------
    [SK8Rotation2013] (SK8-3,5-4000: 8 blocks of 650 kg, 5200 kg in all).

    Examples
    --------
    >>> counterweight_set_mass(650.0, 8)
    5200.0
    """
    return block_mass * count
