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
from .redundancy import JointMoments, PinTilts, PitmanSection, real_mechanism
from .spatial import SpatialLinkage, SpatialMotion

_METHODS = ("rational", "real")


def reaction_methods() -> tuple[str, ...]:
    """Names of the mechanism models, the statically determinate one first."""
    return _METHODS


@dataclass(frozen=True)
class ReactionSolution:
    """Motion, reactions and, for the real mechanism, the joint moments of its revolute pins."""

    motion: SpatialMotion
    reactions: Reactions
    joint_moments: JointMoments | None = None


def joint_reactions(
    method: str,
    spatial: SpatialLinkage,
    masses: MassModel,
    crank_angle: np.ndarray,
    omega1: np.ndarray | float,
    epsilon1: np.ndarray | float,
    rod_load: np.ndarray,
    *,
    actual: SpatialLinkage | None = None,
    tilts: PinTilts = PinTilts(),
    section: PitmanSection | None = None,
    weights: bool = True,
    inertia: bool = True,
) -> ReactionSolution:
    """Reactions of the mechanism model ``method`` (see :func:`reaction_methods`).

    ``spatial`` is the error-free unit; for ``real``, ``actual`` is the unit with the
    side-3 deviations (default: none), ``tilts`` the pin-bore errors and ``section``
    the pitman's elastic section (required). ``omega1`` [1/s], ``epsilon1`` [1/s^2]:
    crank speed and acceleration in the direction of rotation; ``rod_load`` [N].
    """
    if method == "rational":
        motion, reactions = rational_mechanism(spatial, masses, crank_angle, omega1, epsilon1, rod_load,
                                               weights=weights, inertia=inertia)
        return ReactionSolution(motion, reactions)
    if method == "real":
        if section is None:
            raise ValueError("the real mechanism needs the pitman's elastic section")
        motion, moments, reactions = real_mechanism(spatial, actual or spatial, tilts, section, masses, crank_angle,
                                                    omega1, epsilon1, rod_load, weights=weights, inertia=inertia)
        return ReactionSolution(motion, reactions, moments)
    raise ValueError(f"unknown mechanism model {method!r}; use one of {', '.join(_METHODS)}")
