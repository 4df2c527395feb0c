"""Joint reactions and balancing torque of a beam unit: competing mechanism models behind one entry point.

* ``rational``: spherical pins at A, A1, B, B1, statically determinate
  (:func:`.kinetostatics.rational_mechanism`; [Spatial7SK12], [PopovychSenchishak]);
* ``real``: revolute pins, four redundant constraints, elastic pitmans and
  manufacturing errors (:func:`.redundancy.real_mechanism`; [Spatial7SK12]).

:func:`reaction_methods` lists them; :func:`joint_reactions` picks one by name.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .kinetostatics import Reactions, rational_mechanism
from .masses import MassModel
from .redundancy import JointCompliance, JointMoments, PinTilts, PitmanSection, real_mechanism
from .spatial import SpatialLinkage, SpatialMotion

_METHODS = ("rational", "real")


def reaction_methods() -> tuple[str, ...]:
    """Names of the mechanism models, the statically determinate one first.

    Returns
    -------
    tuple of str
        ``"rational"`` ([Spatial7SK12], [PopovychSenchishak]) and ``"real"``
        ([Spatial7SK12]).

    Examples
    --------
    >>> reaction_methods()
    ('rational', 'real')
    """
    return _METHODS


@dataclass(frozen=True)
class ReactionSolution:
    """Motion, reactions and, for the real mechanism, the joint moments of its revolute pins.

    Attributes
    ----------
    motion : SpatialMotion
        Positions [m], angular velocities [1/s] and accelerations [1/s²].
    reactions : Reactions
        Reactions [N], moments and balancing torque [N·m].
    joint_moments : JointMoments or None
        Moments of the revolute pins [N·m] (``real`` only).
    """

    motion: SpatialMotion
    reactions: Reactions
    joint_moments: JointMoments | None = None


def joint_reactions(
    method: str,
    spatial: SpatialLinkage,
    masses: MassModel,
    crank_angle: np.ndarray,
    crank_speed: np.ndarray | float,
    crank_acceleration: np.ndarray | float,
    rod_load: np.ndarray,
    *,
    actual: SpatialLinkage | None = None,
    tilts: PinTilts = PinTilts(),
    section: PitmanSection | None = None,
    joints: JointCompliance = JointCompliance(),
    weights: bool = True,
    inertia: bool = True,
) -> ReactionSolution:
    """Reactions of the mechanism model ``method`` (see :func:`reaction_methods`).

    Parameters
    ----------
    method : str
        ``"rational"`` (:func:`.kinetostatics.rational_mechanism`) or ``"real"``
        (:func:`.redundancy.real_mechanism`).
    spatial : SpatialLinkage
        The error-free unit [m].
    masses : MassModel
        Masses [kg], centres [m], inertias [kg·m²].
    crank_angle : numpy.ndarray
        theta [rad].
    crank_speed, crank_acceleration : float or numpy.ndarray
        Crank speed [1/s] and acceleration [1/s²] in the direction of rotation.
    rod_load : numpy.ndarray
        Polished-rod load at each crank angle [N].
    actual : SpatialLinkage, optional
        ``real`` only: the unit with the side-3 deviations [m, rad] (default: none).
    tilts : PinTilts
        ``real`` only: the pin-bore errors [rad].
    section : PitmanSection, optional
        ``real`` only (required): the pitman's elastic section [Pa, m², m⁴].
    joints : JointCompliance
        ``real`` only: stiffness [N·m/rad] and clearance [rad] of the pins (default rigid).
    weights, inertia : bool
        Include the links' weights, their inertia forces and moments.

    Returns
    -------
    ReactionSolution
        Motion, reactions [N, N·m] and, for ``real``, the joint moments [N·m].

    Raises
    ------
    ValueError
        Unknown ``method``, or ``real`` without a ``section``.

    References
    ----------
    [Spatial7SK12], [PopovychSenchishak].
    """
    if method == "rational":
        motion, reactions = rational_mechanism(spatial, masses, crank_angle, crank_speed, crank_acceleration, rod_load,
                                               weights=weights, inertia=inertia)
        return ReactionSolution(motion, reactions)
    if method == "real":
        if section is None:
            raise ValueError("the real mechanism needs the pitman's elastic section")
        motion, moments, reactions = real_mechanism(spatial, actual or spatial, tilts, section, masses, crank_angle,
                                                    crank_speed, crank_acceleration, rod_load, weights=weights, inertia=inertia,
                                                    joints=joints)
        return ReactionSolution(motion, reactions, moments)
    raise ValueError(f"unknown mechanism model {method!r}; use one of {', '.join(_METHODS)}")
