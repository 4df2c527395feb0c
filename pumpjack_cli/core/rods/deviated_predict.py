"""Predicted cards of a deviated well: the rod string marched in time with gravity along the
hole, Coulomb drag and the pump's valves.

The string is :class:`~.deviated.StringGrid`'s (nodes along measured depth, lumped masses,
springs, the cells' weight along the hole and side-load coefficients), moved at the top by
the polished rod and held at the bottom by the pump of :mod:`.pump` (valves, fillage, gas,
tubing stretch: its :class:`~.pump.PumpChamber`, stepped as the modal solver steps it). Per
node (up positive, dynamic forces, the static tension along the hole taken out as in
:mod:`.deviated`):

    m_i (a_i + c v_i) + (K w)_i + f_i(v_i) + [i = M] F_p = [i = 1] k_1/2 w_0,

f_i = mu N_i l_i sgn_eps(v_i) the drag of node i's cell. Time integration: the
generalized-alpha method of [ChungHulbert1993] (second order, unconditionally stable,
high-frequency damping set by the spectral radius rho_inf; 1 is the trapezoidal rule),
implicit in the new positions: each step is a tridiagonal system (springs, masses,
damping) plus the drag, a monotone diagonal function of the node velocities (the band of
the regularised sign is linear, outside it the drag is constant), solved by an active-set
iteration (each node's regime, band or sliding up or down, guessed from the last step,
the system solved, the regimes corrected until they hold: a semismooth Newton method for a
piecewise-linear monotone system), and the pump: with the regimes fixed the plunger's
position is affine in the new pump load, which the chamber's valve laws then set. The drag
magnitude takes the side load of the last step's tension (one step behind: first order in
the step for the drag's size only). Being implicit, the step is free of the wave speed's
limit, so slow pumping (quasi-static rods) costs no more steps than fast.

Periodic steady state: cycles are marched until the pump load and the plunger position
repeat to ``tolerance``. Energy per cycle: polished-rod work = pump work + damping
dissipation + drag work + what the integrator's own damping takes (reported in the
residual; it vanishes as the step shrinks).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import lapack

from ...errors import PredictionError
from ..constants import STANDARD_GRAVITY
from .deviated import DEFAULT_REGULARISATION, MAX_SEGMENT, DepthProfile, StringGrid, friction_sign, string_grid
from .path import WellPath
from ..mechanism import Mechanism
from .predict import Prediction, PredictionSummary, card_extreme, crank_samples, thinned
from .predict_solver import Convergence, spectral_derivatives
from .pump import Pump, PumpChamber
from .string import RodString

#: Largest relative change of pump load and plunger position between two cycles.
DEFAULT_TOLERANCE = 1e-6
#: Cycles marched at most.
MAX_CYCLES = 400
#: Spectral radius of the generalized-alpha method at infinite frequency.
SPECTRAL_RADIUS = 0.8
#: Active-set passes of one step at most.
_PASSES = 30
#: Rows of :attr:`StringMarch.rows`: node position, velocity, acceleration, the springs' force
#: (K w)_i = k_i (w_i - w_{i+1}) - k_{i-1} (w_{i-1} - w_i) (unknown nodes), tension, side load.
_W, _V, _A, _ELASTIC, _TENSION, _SIDE = range(6)
_ROWS = 6
#: Steps a :class:`Recorder` holds before folding them into its envelopes.
_BLOCK = 64


@dataclass(frozen=True)
class DeviatedPrediction:
    """Predicted cards of a deviated well (:class:`~.predict.Prediction`, its buoyant weight the
    weight along the hole W, the load datum), the string's profile over the cycle
    (:class:`~.deviated.DepthProfile`), the drag's work per cycle [J] and the grid."""

    cards: Prediction
    profile: DepthProfile
    friction_work: float
    grid: StringGrid


@dataclass(frozen=True)
class Alpha:
    """The generalized-alpha method's parameters for a spectral radius rho_inf in [0, 1]
    ([ChungHulbert1993] eqs. 25, 17, 20)."""

    alpha_m: float
    alpha_f: float
    gamma: float
    beta: float

    @classmethod
    def of(cls, rho: float) -> Alpha:
        if not 0.0 <= rho <= 1.0:
            raise PredictionError(f"spectral radius must lie in [0, 1], got {rho}")
        alpha_m, alpha_f = (2.0 * rho - 1.0) / (rho + 1.0), rho / (rho + 1.0)
        return cls(alpha_m, alpha_f, 0.5 - alpha_m + alpha_f, 0.25 * (1.0 - alpha_m + alpha_f) ** 2)


@dataclass(frozen=True)
class TopMotion:
    """The polished rod's position [m], velocity [m/s] and acceleration [m/s^2] (up) at the steps."""

    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray


class StringMarch:
    """The string and pump stepped in time (module docstring): state of the nodes (position,
    velocity, acceleration, up), the pump load and chamber, each node's drag regime, and the
    node tensions the side loads are taken from.

    The nodes' state is one array ``rows`` (rows :data:`_W` .. :data:`_SIDE`, a column per
    node), a new one each step: besides position, velocity and acceleration it holds what the
    next step and the recorder take from the positions (the springs' net force on each unknown
    node, the tensions and the cells' side loads), computed once per step rather than where
    each is used.
    """

    def __init__(self, grid: StringGrid, pump: Pump, step: float, friction_coefficient: float, band: float,
                 rho: float = SPECTRAL_RADIUS):
        if not band > 0.0:
            raise PredictionError("the time march needs a positive velocity band of the drag's sign function")
        self.grid, self.pump, self.mu, self.band = grid, pump, friction_coefficient, band
        self.alpha = Alpha.of(rho)
        self.k, self.m = grid.segment_stiffness, grid.node_mass
        self.columns = np.zeros((grid.nodes - 1, 2), order="F")  # right-hand sides: known forces, unit pump load
        self.columns[-1, 1] = -(1.0 - self.alpha.alpha_f)
        self.first_pull = (1.0 - self.alpha.alpha_f) * self.k[0]
        self.rubbing = (friction_coefficient > 0.0) & ((grid.side_a > 0.0) | (grid.side_c > 0.0))
        self.top_mass, self.top_rubs = float(grid.node_mass[0]), bool(self.rubbing[0])
        self.drag_scale = friction_coefficient * self.rubbing[1:]  # mu where the unknown node's cell rubs, else 0
        self.mode = np.zeros(grid.nodes - 1)
        self.chamber: PumpChamber | None = None
        self.set_step(step)

    def set_step(self, step: float) -> None:
        """The time step h [s] and the integrator's coefficients that depend on it."""
        alpha, h, m, k, c = self.alpha, step, self.m, self.k, self.grid.damping
        self.step = h
        self.c_a = (1.0 - alpha.alpha_m) / (alpha.beta * h * h)
        self.c_v = (1.0 - alpha.alpha_f) * alpha.gamma / (alpha.beta * h)
        spring = np.concatenate([k, [0.0]])
        self.diagonal = m[1:] * (self.c_a + c * self.c_v) + (1.0 - alpha.alpha_f) * (k + spring[1:])
        self.off = -(1.0 - alpha.alpha_f) * k[1:]
        # a_known + c v_known and v_known as combinations of w, v, a of the unknown nodes (generalized alpha):
        # a_known = -(1 - am)/(b h^2) w - (1 - am)/(b h) v + (am - (1 - am)(1/(2b) - 1)) a,
        # v_known = (1 - af)(-g/(b h) w + (1 - g/b) v + h (1 - g/(2b)) a) + af v
        am, af, b, g = alpha.alpha_m, alpha.alpha_f, alpha.beta, alpha.gamma
        a_w, a_v, a_a = -(1.0 - am) / (b * h * h), -(1.0 - am) / (b * h), am - (1.0 - am) * (0.5 / b - 1.0)
        v_w, v_v, v_a = -(1.0 - af) * g / (b * h), (1.0 - af) * (1.0 - g / b) + af, (1.0 - af) * h * (1.0 - 0.5 * g / b)
        mass = m[1:]
        # the known forces (less the springs' share alpha_f of the last step) and v_known in one product and sum
        # over the rows w, v, a, elastic of the unknown nodes
        self.combine = np.zeros((4, 2, mass.size))
        self.combine[:3, 0] = -mass * (a_w + c * v_w), -mass * (a_v + c * v_v), -mass * (a_a + c * v_a)
        self.combine[3, 0] = -af
        self.combine[:3, 1] = np.reshape((v_w, v_v, v_a), (3, 1))
        self.stiffening = self.c_v / self.band
        self.newmark = (h, b * h * h, 0.5 / b - 1.0, 1.0 - g, g)

    @property
    def w(self) -> np.ndarray:
        """Node positions [m]."""
        return self.rows[_W]

    def state(self) -> tuple:
        """What a step changes, to :meth:`restore` it (for a step tried again)."""
        assert self.chamber is not None
        return self.rows, self.load, self.top_dynamic, self.mode, dict(self.chamber.__dict__)

    def restore(self, state: tuple) -> None:
        """The march as :meth:`state` saved it."""
        assert self.chamber is not None
        self.rows, self.load, self.top_dynamic, self.mode, chamber = state
        self.chamber.__dict__.update(chamber)

    def start(self, top: TopMotion, load: float) -> None:
        """The string hanging still from the polished rod's first position with the pump load
        ``load`` [N] on it; the chamber at the plunger's position."""
        grid = self.grid
        stretch = np.concatenate([[0.0], np.cumsum(1.0 / grid.segment_stiffness)])
        self.rows = np.zeros((_ROWS, grid.nodes))
        self.rows[_W] = top.position[0] - load * stretch
        self.rows[_V] = top.velocity[0]
        self.load = float(load)
        self._settle(self.rows, self.load, top, 0)
        f_o, k_t = self.pump.fluid_load, self.pump.tubing_stiffness
        self.chamber = PumpChamber(self.pump, 0.0, float(self.w[-1]) + (f_o - load) / k_t)

    def top_force(self, w: np.ndarray, top: TopMotion, n: int) -> float:
        """The polished rod's dynamic load P - W [N] at step ``n``: the first spring, the top half
        cell's inertia and damping and its drag."""
        return self._top_force(self.grid.segment_stiffness[0] * (w[0] - w[1]), top, n)

    def _top_force(self, spring: float, top: TopMotion, n: int) -> float:
        """:meth:`top_force` with the first spring's force ``spring`` [N] given."""
        force = spring + self.top_mass * (float(top.acceleration[n]) + self.grid.damping * float(top.velocity[n]))
        return float(force + self.top_drag(force, top, n))

    def top_drag(self, force: float, top: TopMotion, n: int) -> float:
        """The drag of the top half cell [N] at step ``n`` (its tension about W + ``force``)."""
        grid = self.grid
        if not self.top_rubs:
            return 0.0
        size = self.mu * float(np.sqrt(max(grid.side_a[0] * (grid.static_node[0] + force) ** 2
                                           - 2.0 * grid.side_b[0] * (grid.static_node[0] + force) + grid.side_c[0], 0.0)))
        return size * float(friction_sign(top.velocity[n], self.band))

    def _settle(self, rows: np.ndarray, load: float, top: TopMotion, n: int) -> None:
        """Fill ``rows``' springs' net force, tensions and side loads from its positions, the pump
        load ``load`` [N] and the polished rod at step ``n``; set ``top_dynamic``, the polished
        rod's dynamic load P - W [N] (:meth:`top_force`).

        Node tensions: static along the hole plus the mean dynamic force on the cell's faces; side
        loads: :meth:`~.deviated.StringGrid.side_force` of them.
        """
        grid, w = self.grid, rows[_W]
        force = np.subtract(w[:-1], w[1:])
        force *= self.k
        elastic = rows[_ELASTIC]
        elastic[0] = 0.0
        np.subtract(force[1:], force[:-1], out=elastic[1:-1])
        elastic[-1] = 0.0 - force[-1]
        self.top_dynamic = self._top_force(force[0], top, n)
        tension = rows[_TENSION]
        np.add(force[:-1], force[1:], out=tension[1:-1])
        tension[0], tension[-1] = self.top_dynamic + force[0], force[-1] + load
        tension *= 0.5
        tension += grid.static_node
        grid.side_force(tension, out=rows[_SIDE])

    def advance(self, top: TopMotion, n: int) -> tuple[float, float, np.ndarray, np.ndarray]:
        """One step to step ``n`` (from n - 1): the new pump load [N] and plunger position relative
        to the barrel [m], the drag [N] and the velocities [m/s] of the unknown nodes at the
        generalized midpoint (for the work of drag and damping)."""
        old = self.rows
        rhs, v_known = np.add.reduce(self.combine * old[:_TENSION, None, 1:], axis=0)
        rhs[0] += self.first_pull * top.position[n]
        rhs[-1] -= self.alpha.alpha_f * self.load
        drag_size = old[_SIDE, 1:] * self.drag_scale
        rubs = drag_size != 0.0
        stiff = drag_size * self.stiffening
        held = drag_size * v_known
        held /= self.band
        f_o, give = self.pump.fluid_load, 1.0 / self.pump.tubing_stiffness
        mode, chamber, columns = self.mode, self.chamber, self.columns
        assert chamber is not None
        saved = dict(chamber.__dict__)
        rows = np.empty_like(old)
        x, velocity = rows[_W, 1:], np.empty(v_known.size)
        for _ in range(_PASSES):
            band = mode == 0.0
            np.subtract(rhs, np.where(band, held, drag_size * mode), out=columns[:, 0])
            solved = lapack.dgtsv(self.off, self.diagonal + stiff * band, self.off, columns)[3]
            per_load = solved[:, 1]
            chamber.compliance = give - float(per_load[-1])
            load, zeta = chamber.step(float(solved[-1, 0]) + f_o * give)
            np.multiply(per_load, load, out=x)
            x += solved[:, 0]
            np.multiply(x, self.c_v, out=velocity)
            velocity += v_known
            found = self._regimes(velocity, mode, rubs)
            if not (found != mode).any():
                break
            mode = found
            chamber.__dict__.update(saved)
        else:
            band = mode == 0.0
        self.mode = mode
        drag = np.where(band, velocity / self.band, mode)
        drag *= drag_size
        self._move(old, rows, top, n)
        self._settle(rows, load, top, n)
        self.rows, self.load = rows, load
        return load, zeta, drag, velocity

    def _regimes(self, velocity: np.ndarray, mode: np.ndarray, rubs: np.ndarray) -> np.ndarray:
        """Each node's drag regime for its ``velocity`` after the step solved with ``mode``: 0 in
        the band (|v| <= band), the sign of v sliding; sliding nodes that stop pass through the
        band, never straight to the other direction; 0 where the cell does not rub (``rubs``)."""
        sliding = np.abs(velocity) > self.band
        sliding &= rubs
        found = np.copysign(sliding, velocity)
        found *= found * mode >= 0.0
        return found

    def _move(self, old: np.ndarray, rows: np.ndarray, top: TopMotion, n: int) -> None:
        """The generalized-alpha update of ``rows``' velocities and accelerations from the state
        ``old`` and ``rows``' new positions of the unknown nodes; the top node follows ``top``."""
        h, beta_hh, back, keep, gamma = self.newmark
        w, v, a = old[_W, 1:], old[_V, 1:], old[_A, 1:]
        rows[_W, 0], rows[_V, 0], rows[_A, 0] = top.position[n], top.velocity[n], top.acceleration[n]
        acceleration, velocity = rows[_A, 1:], rows[_V, 1:]
        np.subtract(rows[_W, 1:], w, out=acceleration)
        acceleration -= np.multiply(v, h, out=velocity)
        acceleration /= beta_hh
        acceleration -= np.multiply(a, back, out=velocity)
        np.multiply(a, keep, out=velocity)
        velocity += gamma * acceleration
        velocity *= h
        velocity += v


def top_motion(position: np.ndarray, period: float) -> TopMotion:
    """The polished rod's position [m] with its velocity and acceleration by FFT (periodic samples)."""
    velocity, acceleration = spectral_derivatives(position, period)
    return TopMotion(position, velocity, acceleration)


@dataclass
class Cycle:
    """What one marched cycle records at its steps (pump load [N], plunger position relative to
    the barrel and absolute [m], polished-rod load [N], joint tensions [N]), the node tensions'
    envelope (max, min) [N], the largest side load per length [N/m], the drag's work per cell
    and the damping's work [J], and the liquid discharged [m^3]."""

    pump_load: np.ndarray
    relative: np.ndarray
    plunger: np.ndarray
    top_load: np.ndarray
    tension: np.ndarray
    joint_tension: np.ndarray
    side: np.ndarray
    drag_work: np.ndarray
    damping_work: float
    discharged: float


class Recorder:
    """Collects a cycle of steps of a :class:`StringMarch` into a :class:`Cycle`."""

    def __init__(self, march: StringMarch, steps: int):
        grid = march.grid
        assert march.chamber is not None
        self.march, self.steps, self.start = march, steps, march.chamber.discharge
        self.hanging_weight = grid.hanging_weight
        self.masses, self.top_mass = grid.node_mass[1:], grid.node_mass[0]
        self.pump_load, self.relative, self.plunger, self.top_load = (np.empty(steps) for _ in range(4))
        self.joint_tension = np.empty((grid.joints.size, steps))
        self.high = np.full(grid.nodes, -np.inf)
        self.low = np.full(grid.nodes, np.inf)
        self.side = np.zeros(grid.nodes)
        self.drag_work = np.zeros(grid.nodes)
        self.damping_work = 0.0
        self.held: list[np.ndarray] = []
        self.samples: list[int] = []

    def record(self, k: int, top: TopMotion, n: int, load: float, zeta: float, drag: np.ndarray,
               velocity: np.ndarray) -> None:
        """The state after a step as sample ``k``, the step driven by ``top`` at index ``n`` (the
        march's last :meth:`~StringMarch.advance`, whose polished-rod load and side loads it takes)."""
        march = self.march
        grid, h = march.grid, march.step
        top_force = march.top_dynamic
        self.pump_load[k], self.relative[k], self.plunger[k] = load, zeta, march.w[-1]
        self.top_load[k] = self.hanging_weight + top_force
        self.held.append(march.rows)
        self.samples.append(k)
        if len(self.held) == _BLOCK:
            self._fold()
        self.drag_work[1:] += drag * velocity * h
        if march.top_rubs:
            self.drag_work[0] += march.top_drag(top_force, top, n) * top.velocity[n] * h
        self.damping_work += grid.damping * h * (float(np.dot(self.masses, velocity * velocity))
                                                 + self.top_mass * top.velocity[n] ** 2)

    def _fold(self) -> None:
        """The held steps' tensions and side loads into the envelopes and the joint tensions (a
        block of steps at a time: fewer, larger array operations than one step at a time)."""
        if not self.held:
            return
        rows = np.array(self.held)
        tension = rows[:, _TENSION]
        np.maximum(self.high, tension.max(axis=0), out=self.high)
        np.minimum(self.low, tension.min(axis=0), out=self.low)
        np.maximum(self.side, rows[:, _SIDE].max(axis=0), out=self.side)
        self.joint_tension[:, self.samples] = tension[:, self.march.grid.joints].T
        self.held.clear()
        self.samples.clear()

    def finish(self) -> Cycle:
        self._fold()
        joint_tension = self.joint_tension
        joint_tension[0], joint_tension[-1] = self.top_load, self.pump_load
        assert self.march.chamber is not None
        return Cycle(self.pump_load, self.relative, self.plunger, self.top_load, np.vstack([self.high, self.low]),
                     joint_tension, self.side / self.march.grid.cell_length, self.drag_work, self.damping_work,
                     self.march.chamber.discharge - self.start)


def march_cycle(march: StringMarch, top: TopMotion) -> Cycle:
    """Steps 1 .. N of one cycle of the polished rod's motion ``top`` (N samples; step N is the
    next cycle's step 0), recorded so that sample k is at t_k."""
    steps = top.position.size
    recorder = Recorder(march, steps)
    extended = TopMotion(*(np.append(x, x[0]) for x in (top.position, top.velocity, top.acceleration)))
    for n in range(1, steps + 1):
        recorder.record(n % steps, extended, n, *march.advance(extended, n))
    return recorder.finish()


def cycle_change(cycle: Cycle, previous: Cycle, load_scale: float, position_scale: float) -> float:
    """Largest change of pump load (over ``load_scale`` [N]) and plunger position apart from a shift
    (over ``position_scale`` [m]) from one cycle to the next."""
    shift = cycle.relative - previous.relative
    return max(float(np.max(np.abs(cycle.pump_load - previous.pump_load))) / load_scale,
               float(np.max(np.abs(shift - np.mean(shift)))) / position_scale)


def steady_state(march: StringMarch, top: TopMotion, tolerance: float, max_cycles: int) -> tuple[Cycle, Convergence]:
    """Cycles of ``top`` until the pump's load and plunger position repeat to ``tolerance``."""
    if not max_cycles >= 2:
        raise PredictionError(f"at least 2 cycles are needed to see the state repeat, got max_cycles {max_cycles}")
    pump, stroke = march.pump, float(np.ptp(top.position))
    changes: list[float] = []
    previous = None
    for _ in range(max_cycles):
        cycle = march_cycle(march, top)
        if previous is not None:
            changes.append(cycle_change(cycle, previous, max(pump.fluid_load, 1.0), stroke))
            if changes[-1] <= tolerance:
                return cycle, Convergence(len(changes) + 1, tuple(changes), tolerance, 0)
        if pump.gas_exponent is not None:
            assert march.chamber is not None
            march.chamber.rebase(float(cycle.relative.min()))
        previous = cycle
    raise PredictionError(
        f"the periodic pump cycle of the deviated well did not converge in {max_cycles} cycles (last change "
        f"{changes[-1]:.3g}, tolerance {tolerance:g}); raise the damping factor or loosen the tolerance")


def deviated_grid(rods: RodString, path: WellPath, step: float, *, damping: float, fluid_density: float,
                  max_segment: float = MAX_SEGMENT, segments: np.ndarray | None = None,
                  gravity: float = STANDARD_GRAVITY) -> StringGrid:
    """The time march's grid: ceil(L_s / min(a_s h, max_segment)) segments per section (the
    implicit march has no wave-speed limit; a segment per step's travel keeps the waves as
    sharp as the step allows) unless ``segments`` are given."""
    if not (np.isfinite(damping) and damping > 0):
        raise PredictionError(f"damping factor must be positive and finite, got {damping}")
    if segments is None:
        segments = np.maximum(1, np.ceil(rods.length / np.minimum(rods.wave_speed * step, max_segment)
                                         * (1.0 - 1e-12))).astype(int)
    return string_grid(rods, path, segments, fluid_density=fluid_density, damping_factor=damping, gravity=gravity)


def predict_deviated(rods: RodString, path: WellPath, pump: Pump, position: np.ndarray, period: float, *,
                     damping: float, fluid_density: float, friction_coefficient: float,
                     crank_angle: np.ndarray | None = None, regularisation: float = DEFAULT_REGULARISATION,
                     tolerance: float = DEFAULT_TOLERANCE, max_cycles: int = MAX_CYCLES,
                     max_segment: float = MAX_SEGMENT, spectral_radius: float = SPECTRAL_RADIUS,
                     segments: np.ndarray | None = None, gravity: float = STANDARD_GRAVITY) -> DeviatedPrediction:
    """Surface and pump cards of a deviated well at uniform crank speed (module docstring).

    Parameters
    ----------
    rods : RodString
        Tapers from the top down; their lengths are measured depths.
    path : WellPath
        The hole.
    pump : Pump
        Plunger, pressures (at the pump's true vertical depth), fillage, gas, tubing.
    position : numpy.ndarray
        Polished-rod position s(t_k) [m], up, on t_k = k T / N: one step of the march per sample.
    period : float
        T [s].
    damping : float
        Gibbs' nu [-] ([Gibbs1963]).
    fluid_density : float
        [kg/m^3], for the buoyant weight.
    friction_coefficient : float
        mu [-] of rods and couplings on the tubing.
    regularisation : float
        eta > 0 [-]: the drag's sign function is linear within eta times the polished rod's peak speed.
    max_segment : float
        Longest segment [m] (the wave speed sets no limit on an implicit march: the segments
        are ceil(L_s / min(a_s T / N, max_segment)) per section); ``segments`` replaces the rule.
    spectral_radius : float
        rho_inf of the generalized-alpha method.

    Returns
    -------
    DeviatedPrediction

    References
    ----------
    [Gibbs1963], [JohancsikSPE11380], [ChungHulbert1993]; docs/deviated.md.
    """
    s = np.asarray(position, dtype=float)
    if s.ndim != 1 or s.size < 16 or not np.all(np.isfinite(s)):
        raise PredictionError("polished-rod position must be a 1-D array of at least 16 finite samples")
    if not (np.isfinite(period) and period > 0):
        raise PredictionError(f"period must be positive and finite, got {period} s")
    if not 0 < tolerance < 1e-2:
        raise PredictionError(f"tolerance must lie in (0, 0.01), got {tolerance}")
    if not (np.isfinite(friction_coefficient) and 0 <= friction_coefficient <= 1):
        raise PredictionError(f"friction coefficient must lie in [0, 1], got {friction_coefficient}")
    if not (np.isfinite(regularisation) and regularisation > 0):
        raise PredictionError(f"the drag's regularisation must be positive, got {regularisation}")
    pump.check()
    samples = s.size
    angle = np.full(samples, np.nan) if crank_angle is None else np.asarray(crank_angle, dtype=float)
    if not np.ptp(s) > 0:
        raise PredictionError("the polished rod does not move")
    grid = deviated_grid(rods, path, period / samples, damping=damping, fluid_density=fluid_density,
                         max_segment=max_segment, segments=segments, gravity=gravity)
    top = top_motion(s, period)
    march = StringMarch(grid, pump, period / samples, friction_coefficient,
                        regularisation * float(np.max(np.abs(top.velocity))), spectral_radius)
    march.start(top, pump.fluid_load if top.velocity[0] > 0 else 0.0)
    cycle, convergence = steady_state(march, top, tolerance, max_cycles)
    return assemble_deviated(grid, pump, cycle, top, angle, period, convergence)


def assemble_deviated(grid: StringGrid, pump: Pump, cycle: Cycle, top: TopMotion, angle: np.ndarray, period: float,
              convergence: Convergence) -> DeviatedPrediction:
    """Cards, summary and profile of the last cycle."""
    samples = top.position.size
    time = np.arange(samples) * (period / samples)

    def loop_work(load: np.ndarray, place: np.ndarray) -> float:
        return float(np.sum(0.5 * (load + np.roll(load, -1)) * (np.roll(place, -1) - place)))

    surface = loop_work(cycle.top_load, top.position)
    pump_work = loop_work(cycle.pump_load, cycle.plunger)
    friction = float(np.sum(cycle.drag_work))
    f_o = pump.fluid_load
    compliance = float(np.sum(1.0 / grid.segment_stiffness))
    summary = PredictionSummary(
        peak_polished_rod_load=card_extreme(cycle.top_load, time, angle, np.argmax),
        minimum_polished_rod_load=card_extreme(cycle.top_load, time, angle, np.argmin),
        buoyant_rod_weight=grid.hanging_weight,
        fluid_load=f_o,
        polished_rod_stroke=float(np.ptp(top.position)),
        gross_plunger_stroke=float(np.ptp(cycle.plunger)),
        net_plunger_stroke=cycle.discharged / pump.plunger_area,
        static_stretch=f_o * (compliance + 1.0 / pump.tubing_stiffness),
        pump_displacement=cycle.discharged,
        pump_rate=cycle.discharged / period,
        surface_card_work=surface,
        pump_card_work=pump_work,
        damping_dissipation=cycle.damping_work,
        energy_residual=(surface - pump_work - cycle.damping_work - friction) / surface if surface != 0 else 0.0,
        polished_rod_power=surface / period,
        period=period,
        convergence=convergence,
    )
    cards = Prediction(
        time=time, crank_angle=angle, polished_rod_position=top.position, polished_rod_velocity=top.velocity,
        polished_rod_load=cycle.top_load, plunger_position=cycle.plunger, pump_load=cycle.pump_load,
        chamber_pressure=pump.discharge_pressure - cycle.pump_load / pump.plunger_area,
        taper_top_load=cycle.joint_tension[:-1], taper_bottom_load=cycle.joint_tension[1:], summary=summary)
    profile = DepthProfile(grid.depth, cycle.tension[0], cycle.tension[1], cycle.side, cycle.drag_work)
    return DeviatedPrediction(cards, profile, friction, grid)


def predict_deviated_cards(linkage: Mechanism, crank_speed: float, rods: RodString, path: WellPath, pump: Pump, *,
                           damping: float, fluid_density: float, friction_coefficient: float, samples: int = 360,
                           resolution: int = 1024, **options) -> DeviatedPrediction:
    """Cards of a beam unit turning uniformly over a deviated well, on ``samples`` points of one
    cycle from crank angle 0, solved on samples x k steps (k the smallest factor reaching
    ``resolution``, as :func:`.predict.predict_cards`); ``options`` go to :func:`predict_deviated`."""
    if not 16 <= samples <= 1 << 16:
        raise PredictionError(f"samples per cycle must lie in 16 .. 65536, got {samples}")
    if not (np.isfinite(crank_speed) and crank_speed > 0):
        raise PredictionError(f"crank speed must be positive and finite, got {crank_speed} 1/s")
    factor, theta = crank_samples(samples, resolution)
    fine = predict_deviated(rods, path, pump, linkage.rod_position(theta), 2.0 * np.pi / crank_speed, damping=damping,
                            fluid_density=fluid_density, friction_coefficient=friction_coefficient, crank_angle=theta,
                            **options)
    return DeviatedPrediction(thinned(fine.cards, factor), fine.profile, fine.friction_work, fine.grid)
