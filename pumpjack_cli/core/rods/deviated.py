"""The rod string in a deviated hole: nodes along measured depth, gravity along the hole,
the soft-string side load, Coulomb drag and the rod-guide advice.

Model (derivation and sources in ``docs/deviated.md``). s is the measured depth from the
polished rod down the rods, w(s, t) the rods' displacement along the hole (up positive,
as a card's position), T the effective tension (true axial force plus the hydrostatic
pressure on the section, so that buoyancy is the buoyant weight per length
q = g m (1 - rho_f / rho_r), [Gibbs1963]), phi the inclination, psi the azimuth. The force
balance of a rod element along the hole is

    m (w_tt + c w_t) = -T_s - q cos(phi) - mu N sgn(w_t),

with Gibbs' viscous damping c [Gibbs1963] and the Coulomb drag of rods and couplings on the
tubing, opposing the motion, from the soft-string side load per length ([JohancsikSPE11380])

    N = sqrt((T phi' - q sin(phi))^2 + (T psi' sin(phi))^2),

phi' and psi' per measured depth going down: in a build (phi' > 0) the tension pulls the
string to the high side and its weight to the low side. The static effective tension of a
frictionless string hanging in the hole, T_0(s) = int_s^L q cos(phi) ds (zero at the pump,
the datum of the pump load), carries the weight along the hole; the dynamic force
F = T - T_0 = -E A w_s then obeys the damped wave equation with the drag as a load:

    m (w_tt + c w_t) = (E A w_s)_s - mu N(T_0 + F) sgn(w_t).

Discretisation (shared by the space march of :mod:`.deviated_diagnostic` and the time march
of :mod:`.deviated_predict`): nodes along each taper, lumped masses, a spring per segment;
each node's cell [s_i - dx_above/2, s_i + dx_below/2] carries the cell's weight along the
hole g_i = int q cos(phi) ds and its side load as the soft-string formula integrated over the
cell, N_i l_i = |T_i (t(s_i + dx_below/2) - t(s_i - dx_above/2)) - int q up_perp ds| (t the
hole's unit tangent, up_perp the part of the upward unit vector across the hole, whose
length is sin(phi)): the tension's pull on the cell's turn, less the cell's weight across
the hole. As the cell shrinks it is l_i times the formula above; over a kink it is the
pulley's resultant 2 T sin(angle / 2).

The sign function is regularised on a velocity band that scales with the speed of the
problem (``band`` = eta times the polished rod's peak speed): sgn_eps(v) = clip(v / band,
-1, 1), so held rods creep by at most the band, which vanishes with eta (``docs/deviated.md``
shows the convergence); eta = 0 is the exact sign.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import DownholeError
from ..constants import STANDARD_GRAVITY
from .path import WellPath
from .string import RodString

#: Coulomb friction coefficient of rods and couplings on the tubing, dimensionless, when the
#: well gives none. The issue's value; the only printed coefficients we could read are
#: [JohancsikSPE11380]'s 0.25-0.40 for drill pipe in water-base mud (produced oil lubricates
#: the contact more); set it per well (docs/deviated.md).
DEFAULT_FRICTION_COEFFICIENT = 0.2
#: Half-width of the sign function's linear band as a share of the polished rod's peak speed.
DEFAULT_REGULARISATION = 0.01
#: Longest segment between nodes [m] whatever the time step: resolves the hole's curvature
#: (survey stations are 10-30 m apart) and the side load along it.
MAX_SEGMENT = 15.0
#: Length of one API rod between couplings [m]: 25 ft ([PetroWikiRods]; 30 ft rods exist too).
ROD_JOINT_LENGTH = 7.62
#: Simpson's points per half cell for the cell integrals of the hole's geometry.
_SIMPSON = np.array([0.0, 0.5, 1.0])
_SIMPSON_WEIGHTS = np.array([1.0, 4.0, 1.0]) / 6.0


def side_load_per_length(tension: Any, weight: Any, inclination: Any, inclination_rate: Any,
                         azimuth_rate: Any) -> np.ndarray:
    """Soft-string side load per length N [N/m] of a string in tension T [N] with buoyant weight
    per length q [N/m] at inclination phi [rad], its rate phi' and the azimuth's rate psi' [rad/m]
    going down ([JohancsikSPE11380]):

        N = sqrt((T phi' - q sin(phi))^2 + (T psi' sin(phi))^2).

    Examples
    --------
    A straight slant at 60 degrees rests on the low side with its weight across the hole,
    q sin(phi): 20 N/m x 0.866 = 17.32 N/m. A vertical build of 3 deg/30 m under 50 kN is
    pulled to the high side with T phi' = 50 000 x 0.001745 = 87.27 N/m.

    >>> float(np.round(side_load_per_length(1e4, 20.0, np.radians(60.0), 0.0, 0.0), 2))
    17.32
    >>> float(np.round(side_load_per_length(5e4, 20.0, 0.0, np.radians(3.0) / 30.0, 0.0), 2))
    87.27
    """
    phi = np.asarray(inclination, dtype=float)
    lateral = np.asarray(tension) * np.asarray(inclination_rate) - np.asarray(weight) * np.sin(phi)
    across = np.asarray(tension) * np.asarray(azimuth_rate) * np.sin(phi)
    return np.hypot(lateral, across)


def friction_sign(velocity: Any, band: float) -> np.ndarray:
    """sgn_eps(v) = clip(v / band, -1, 1) [-] (module docstring); the exact sign for band 0."""
    v = np.asarray(velocity, dtype=float)
    if band <= 0.0:
        return np.sign(v)
    return np.clip(v / band, -1.0, 1.0)


def _tangents(path: WellPath, s: np.ndarray) -> np.ndarray:
    """Unit tangents (north, east, down) of the path at the measured depths ``s`` (..., 3)."""
    phi, psi = path.inclination(s), path.azimuth(s)
    return np.stack([np.sin(phi) * np.cos(psi), np.sin(phi) * np.sin(psi), np.cos(phi)], axis=-1)


@dataclass(frozen=True)
class StringGrid:
    """The rod string on nodes 0 (polished rod) .. M (pump) along measured depth (module docstring), SI.

    depth s_i [m] (M + 1); segment: length dx [m], stiffness k = E A / dx [N/m], section
    index of each segment (M); node: mass [kg] (half of each adjacent segment's m dx), cell
    length l_i [m], buoyant weight per length of the cell q_i [N/m] (mean), weight along the
    hole g_i = int q cos(phi) ds [N] (M + 1); the side-load coefficients of each cell
    A_i = |dt_i|^2, B_i = dt_i . G_i, C_i = |G_i|^2 (dt_i the turn of the tangent across the
    cell, G_i = int q up_perp ds [N]), so that N_i l_i = sqrt(A T^2 - 2 B T + C); static
    effective tension: at the segments T_0 = the weight along the hole of the nodes below [N]
    (M), at the nodes the mean of the forces on the cell's two faces (M + 1); joints: index of
    the node at each section end (S + 1), damping c [1/s] from Gibbs' nu.
    """

    depth: np.ndarray
    segment_length: np.ndarray
    segment_stiffness: np.ndarray
    segment_section: np.ndarray
    node_mass: np.ndarray
    cell_length: np.ndarray
    cell_weight_per_length: np.ndarray
    axial_weight: np.ndarray
    side_a: np.ndarray
    side_b: np.ndarray
    side_c: np.ndarray
    static_segment: np.ndarray
    static_node: np.ndarray
    joints: np.ndarray
    damping: float

    @property
    def nodes(self) -> int:
        return int(self.depth.size)

    @property
    def hanging_weight(self) -> float:
        """W = int_0^L q cos(phi) ds [N]: the rods' buoyant weight along the hole, the polished rod's
        static load of a frictionless string (the datum of the dynamic loads)."""
        return float(self.static_node[0] + 0.5 * self.axial_weight[0])

    def side_force(self, tension: Any, out: np.ndarray | None = None) -> np.ndarray:
        """N_i l_i [N] of each cell for the node tensions ``tension`` [N] (nodes on the last axis
        or the first: broadcast against the node arrays as given); into ``out`` when given (a
        time march's buffer, the same operations in place)."""
        t = np.asarray(tension, dtype=float)
        side = np.multiply(self.side_a, t, out=out)
        side *= t
        side -= (2.0 * self.side_b) * t
        side += self.side_c
        np.maximum(side, 0.0, out=side)
        return np.sqrt(side, out=side)


def grid_segments(rods: RodString, time_step: float, max_segment: float = MAX_SEGMENT) -> np.ndarray:
    """Segments per section: at least ceil(L_s / (a_s dt)) (the space march's stability,
    dx <= a dt [EverittJennings1992]) and ceil(L_s / max_segment) (the hole's curvature)."""
    if not (math.isfinite(max_segment) and max_segment > 0):
        raise DownholeError(f"largest segment must be positive, got {max_segment:g} m")
    wave = np.ceil(rods.length / (rods.wave_speed * time_step) * (1.0 - 1e-12))
    geometry = np.ceil(rods.length / max_segment * (1.0 - 1e-12))
    return np.maximum(1, np.maximum(wave, geometry)).astype(int)


def string_grid(rods: RodString, path: WellPath, segments: np.ndarray, *, fluid_density: float,
                damping_factor: float, gravity: float = STANDARD_GRAVITY) -> StringGrid:
    """The string's nodes, masses, springs, weights along the hole and side-load coefficients
    (:class:`StringGrid`) with ``segments[s]`` equal segments in section s (top first)."""
    segments = np.asarray(segments, dtype=int)
    if segments.shape != rods.length.shape or np.any(segments < 1):
        raise DownholeError("one positive segment count per rod section is needed")
    section = np.repeat(np.arange(rods.length.size), segments)
    dx = np.repeat(rods.length / segments, segments)
    depth = np.concatenate([[0.0], np.cumsum(dx)])
    depth[-1] = rods.total_length
    stiffness = (rods.youngs_modulus * rods.area)[section] / dx
    mass = rods.mass_per_length[section] * dx
    q = rods.buoyant_weight_per_length(fluid_density, gravity)[section]
    zero = np.zeros(1)
    above, below = np.concatenate([zero, dx]) / 2.0, np.concatenate([dx, zero]) / 2.0
    q_above, q_below = np.concatenate([zero, q]), np.concatenate([q, zero])
    node_mass = np.concatenate([zero, mass]) / 2.0 + np.concatenate([mass, zero]) / 2.0
    cell = above + below
    # Simpson's rule on each half cell (the hole's tangent is smooth there; curvature may jump at stations)
    up = np.array([0.0, 0.0, -1.0])
    axial = np.zeros(depth.size)
    lateral = np.zeros((depth.size, 3))
    for half, weight, sign in ((above, q_above, -1.0), (below, q_below, 1.0)):
        s = depth[:, None] + sign * half[:, None] * _SIMPSON[None, :]
        t = _tangents(path, s)
        cos_phi = t[..., 2]
        across = up + cos_phi[..., None] * t  # up minus its component along the hole (cos(phi) t, as up . t = -cos(phi))
        axial += weight * half * (_SIMPSON_WEIGHTS * cos_phi).sum(axis=-1)
        lateral += (weight * half)[:, None] * np.einsum("k,ikj->ij", _SIMPSON_WEIGHTS, across)
    turn = _tangents(path, depth + below) - _tangents(path, depth - above)
    static_segment = np.cumsum(axial[::-1])[::-1][1:]
    faces_above = np.concatenate([[float(np.sum(axial))], static_segment])
    faces_below = np.concatenate([static_segment, zero])
    with np.errstate(invalid="ignore", divide="ignore"):
        per_length = np.where(cell > 0, (q_above * above + q_below * below) / cell, 0.0)
    joints = np.concatenate([[0], np.cumsum(segments)])
    return StringGrid(
        depth=depth, segment_length=dx, segment_stiffness=stiffness, segment_section=section, node_mass=node_mass,
        cell_length=cell, cell_weight_per_length=per_length, axial_weight=axial,
        side_a=np.sum(turn * turn, axis=-1), side_b=np.sum(turn * lateral, axis=-1),
        side_c=np.sum(lateral * lateral, axis=-1), static_segment=static_segment,
        static_node=0.5 * (faces_above + faces_below), joints=joints,
        damping=rods.damping_coefficient(damping_factor))


@dataclass(frozen=True)
class DepthProfile:
    """The string along the hole over one cycle, at the grid's nodes (SI).

    depth (measured) [m]; max_tension and min_tension: the effective axial force's envelope
    [N]; max_side_load: the largest side load per length over the cycle [N/m], from the
    dynamic effective tension; friction_work per cell and cycle [J].
    """

    depth: np.ndarray
    max_tension: np.ndarray
    min_tension: np.ndarray
    max_side_load: np.ndarray
    friction_work: np.ndarray

    @property
    def largest_side_load(self) -> tuple[float, float]:
        """The largest side load per length [N/m] over depth and cycle, and its measured depth [m]."""
        i = int(np.argmax(self.max_side_load))
        return float(self.max_side_load[i]), float(self.depth[i])


@dataclass(frozen=True)
class GuideAdvice:
    """Rod guides for a side-load limit per contact: per node of the profile, the side load per
    rod N l_r [N] (carried by one coupling without guides) and the guides per rod that bring the
    load per contact under the limit, ceil(N l_r / limit) - 1; the depth intervals [m] (top,
    bottom) where guides are needed and the most guides per rod in each."""

    side_load_per_rod: np.ndarray
    guides_per_rod: np.ndarray
    intervals: tuple[tuple[float, float, int], ...]


def guide_advice(depth: np.ndarray, side_load: np.ndarray, limit: float, rod_length: float = ROD_JOINT_LENGTH
                 ) -> GuideAdvice:
    """Where couplings alone carry more side load than ``limit`` [N] per contact, and how many
    guides per rod bring it under: the side load per length ``side_load`` [N/m] at ``depth`` [m]
    over one rod of ``rod_length`` [m] is shared by its coupling and its g guides, so
    g = ceil(N l_r / limit) - 1 (docs/deviated.md).

    >>> advice = guide_advice(np.array([0.0, 100.0, 200.0, 300.0]), np.array([5.0, 40.0, 40.0, 5.0]), 150.0)
    >>> advice.guides_per_rod.tolist(), advice.intervals
    ([0, 2, 2, 0], ((100.0, 200.0, 2),))
    """
    if not (math.isfinite(limit) and limit > 0):
        raise DownholeError(f"the side-load limit per contact must be positive, got {limit:g} N")
    per_rod = np.asarray(side_load, dtype=float) * rod_length
    guides = np.maximum(np.ceil(per_rod / limit * (1.0 - 1e-12)) - 1.0, 0.0).astype(int)
    intervals = []
    start = None
    for i, count in enumerate(guides):
        if count > 0 and start is None:
            start = i
        if start is not None and (count == 0 or i == guides.size - 1):
            stop = i if count > 0 else i - 1
            intervals.append((float(depth[start]), float(depth[stop]), int(guides[start:stop + 1].max())))
            start = None
    return GuideAdvice(per_rod, guides, tuple(intervals))


def axial_weight(rods: RodString, path: WellPath, fluid_density: float, gravity: float = STANDARD_GRAVITY,
                 max_segment: float = MAX_SEGMENT) -> float:
    """W = int_0^L q cos(phi) ds [N]: the rods' buoyant weight along the hole (Simpson's rule on
    segments of at most ``max_segment``), what a frictionless string hangs on the polished rod.

    >>> from pumpjack_cli.core.rods.path import VerticalPath
    >>> rods = RodString([1000.0], [2.85e-4], [2.05e11], [2.43])
    >>> round(axial_weight(rods, VerticalPath(), 1000.0) / rods.buoyant_weight(1000.0), 12)
    1.0
    """
    grid = string_grid(rods, path, np.ceil(rods.length / max_segment).astype(int), fluid_density=fluid_density,
                       damping_factor=0.0, gravity=gravity)
    return grid.hanging_weight
