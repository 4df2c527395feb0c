"""The pump card of a deviated well: Everitt & Jennings' march in depth with gravity along the
hole and Coulomb drag.

Gibbs' per-harmonic solution cannot carry the drag (it is not linear in the card), so a
deviated well is diagnosed by the finite-difference march of :mod:`.everitt_jennings`
([EverittJennings1992]) on the nodes of :class:`~.deviated.StringGrid`, every time level of
a node known when the march reaches it (periodic central differences,
D(w) = w_tt + c w_t). With the dynamic forces F of the segments (F = T - T_0, T_0 the
static tension along the hole) and the drag f_i = mu N_i l_i sgn_eps(w_t) of node i's cell
(opposing the motion):

* top half cell: F_1/2 = (P - W) - m_0 D(w_0) - f_0, P the polished-rod load and W the rods'
  weight along the hole (:attr:`~.deviated.StringGrid.hanging_weight`);
* node i: F_i+1/2 = F_i-1/2 - m_i D(w_i) - f_i, then w_i+1 = w_i - F_i+1/2 / k_i+1/2;
* pump node: the pump load F_p = F_M-1/2 - m_M D(w_M) - f_M.

The side load N_i of a cell takes the node's tension T_i = T_0,i + (F_i-1/2 + F_i+1/2) / 2,
which itself holds f_i / 2: two fixed-point passes (the second changes N by
(mu dN/dT / 2)^2, far below the scheme's error). The velocity in the sign function is the
central difference of the node's positions. In a vertical hole N = 0 and the march is
:func:`.everitt_jennings.march`'s, term by term.

Where the rods stick (|w_t| within the band) the drag is whatever holds them, which the
surface card does not tell sample by sample: the regularised law then passes the
positions' small errors on as drag; ``docs/deviated.md`` measures what that costs.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ...errors import DownholeError
from ..constants import STANDARD_GRAVITY
from .analysis import as_cards
from .deviated import (DEFAULT_REGULARISATION, MAX_SEGMENT, DepthProfile, StringGrid, friction_sign, grid_segments,
                       string_grid)
from .downhole import DownholeCard, damping_from_fluid_load
from .path import WellPath
from .string import RodString


@dataclass(frozen=True)
class DeviatedCard:
    """A pump card of a deviated well: the card (:class:`~.downhole.DownholeCard`, its
    ``buoyant_weight`` the weight along the hole W, the load datum), the string's profile over
    the cycle (:class:`~.deviated.DepthProfile`), the drag's work per cycle [J], the grid and
    the friction coefficient mu [-]."""

    card: DownholeCard
    profile: DepthProfile
    friction_work: float
    grid: StringGrid
    friction_coefficient: float


def march(grid: StringGrid, period: float, position: np.ndarray, dynamic_load: np.ndarray,
          friction_coefficient: float, band: float) -> dict[str, np.ndarray]:
    """Positions, tensions and drag at every node from the polished rod's position [m] (up) and
    dynamic load P - W [N] (module docstring); arrays (..., N) in, (..., M + 1, N) out (keys
    ``position``, ``tension``, ``drag``, ``velocity``) and the pump's dynamic load (..., N)
    (``pump_load``); ``band`` [m/s] of the sign function."""
    dt = period / position.shape[-1]
    c = grid.damping

    def rates(w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ahead, behind = np.roll(w, -1, axis=-1), np.roll(w, 1, axis=-1)
        velocity = (ahead - behind) / (2.0 * dt)
        return (ahead - 2.0 * w + behind) / dt**2 + c * velocity, velocity

    mass, stiffness, static = grid.node_mass, grid.segment_stiffness, grid.static_node
    a, b, cc = grid.side_a, grid.side_b, grid.side_c
    positions, tensions, drags, velocities = [], [], [], []
    w, above = position, dynamic_load
    last = grid.nodes - 1
    for i in range(grid.nodes):
        accel, velocity = rates(w)
        inertia = mass[i] * accel
        base = static[i] + above - 0.5 * inertia
        drag = np.zeros_like(base)
        if friction_coefficient > 0.0 and (a[i] > 0.0 or cc[i] > 0.0):
            sign = friction_coefficient * friction_sign(velocity, band)
            for _ in range(2):
                tension = base - 0.5 * drag
                drag = sign * np.sqrt(np.maximum(a[i] * tension * tension - 2.0 * b[i] * tension + cc[i], 0.0))
        below = above - inertia - drag
        positions.append(w)
        tensions.append(base - 0.5 * drag)
        drags.append(drag)
        velocities.append(velocity)
        if i < last:
            w = w - below / stiffness[i]
        above = below
    stack = functools.partial(np.stack, axis=-2)
    return {"position": stack(positions), "tension": stack(tensions), "drag": stack(drags),
            "velocity": stack(velocities), "pump_load": above}


def deviated_pump_card(rods: RodString, path: WellPath, period: float, position, load, *, fluid_density: float,
                       damping_factor: float, friction_coefficient: float,
                       regularisation: float = DEFAULT_REGULARISATION, max_segment: float = MAX_SEGMENT,
                       segments: np.ndarray | None = None, gravity: float = STANDARD_GRAVITY) -> DeviatedCard:
    """Pump card, profile and drag of a deviated well from its surface card (module docstring).

    Parameters
    ----------
    rods : RodString
        The tapers, top first; their lengths are measured depths.
    path : WellPath
        The hole (:mod:`.path`, :mod:`.survey_path`).
    period : float
        T [s]; the card is sampled at t_k = k T / N.
    position, load : array_like
        Polished-rod position [m] (up) and load [N], shape (N,) or (B, N).
    fluid_density : float
        rho_f [kg/m^3].
    damping_factor : float
        Gibbs' nu [-] ([Gibbs1963]).
    friction_coefficient : float
        mu [-] of rods and couplings on the tubing.
    regularisation : float
        eta [-]: the sign function's band is eta times the polished rod's peak speed.
    max_segment : float
        Longest segment [m]; ``segments`` (one count per section) replaces the rule of
        :func:`.deviated.grid_segments`.

    Returns
    -------
    DeviatedCard

    References
    ----------
    [EverittJennings1992] (march), [Gibbs1963] (damping), [JohancsikSPE11380] (side load).
    """
    position, load = as_cards(position, load, "surface card")
    if not (np.isfinite(period) and period > 0):
        raise DownholeError(f"card period must be finite and positive, got {period:g} s")
    for name, value in (("friction coefficient", friction_coefficient), ("regularisation", regularisation)):
        if not (np.isfinite(value) and value >= 0):
            raise DownholeError(f"{name} must be finite and not negative, got {value:g}")
    dt = period / position.shape[-1]
    if segments is None:
        segments = grid_segments(rods, dt, max_segment)
    grid = string_grid(rods, path, segments, fluid_density=fluid_density, damping_factor=damping_factor,
                       gravity=gravity)
    speed = np.abs(np.roll(position, -1, axis=-1) - np.roll(position, 1, axis=-1)).max() / (2.0 * dt)
    result = march(grid, period, position, load - grid.hanging_weight, friction_coefficient, regularisation * speed)
    w, tension, drag = result["position"], result["tension"], result["drag"]
    pump_load = result["pump_load"]
    joints = grid.joints
    joint_load = tension[..., joints, :].copy()
    joint_load[..., 0, :], joint_load[..., -1, :] = load, pump_load
    card = DownholeCard(method="everitt-jennings", period=float(period), damping_factor=float(damping_factor),
                        damping_coefficient=grid.damping, buoyant_weight=grid.hanging_weight, surface_position=position,
                        surface_load=load, pump_position=w[..., -1, :], pump_load=pump_load,
                        joint_position=w[..., joints, :], joint_load=joint_load)
    work = np.sum(drag * result["velocity"], axis=-1) * dt
    side = grid.side_force(tension.swapaxes(-1, -2)).swapaxes(-1, -2) / grid.cell_length[:, None]
    profile = DepthProfile(grid.depth, tension.max(axis=-1), tension.min(axis=-1), side.max(axis=-1), work)
    return DeviatedCard(card, profile, float(np.sum(work)) if work.ndim == 1 else np.sum(work, axis=-1), grid,
                        float(friction_coefficient))


def deviated_damping_from_fluid_load(rods: RodString, path: WellPath, period: float, position, load,
                                     fluid_load: float, *, fluid_density: float, friction_coefficient: float,
                                     regularisation: float = DEFAULT_REGULARISATION, largest: float = 2.0,
                                     gravity: float = STANDARD_GRAVITY) -> float:
    """Gibbs' nu that closes the rods' energy balance with the drag: the pump card's work equals
    the hydraulic work F_o S_n ([Gibbs1963]), the surface work less the drag's and the damping's
    (:func:`.downhole.damping_from_fluid_load` with this march)."""
    position, load = as_cards(position, load, "surface card")

    def solve(nu: float) -> DownholeCard:
        return deviated_pump_card(rods, path, period, position, load, fluid_density=fluid_density, damping_factor=nu,
                                  friction_coefficient=friction_coefficient, regularisation=regularisation,
                                  gravity=gravity).card

    return damping_from_fluid_load(rods, period, position, load, fluid_load, fluid_density=fluid_density,
                                   largest=largest, solve=solve)
