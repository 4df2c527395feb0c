"""The solver behind :mod:`.predict`: the well reduced to modal kernels, the periodic
fields for given inputs, and the pump marched cycle by cycle to the periodic state.

See :mod:`.predict` for the model and :mod:`.predict_modes` for the modal form of the
wave equation ([Gibbs1963]).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import TypeVar

import numpy as np

from ...errors import PredictionError
from ..constants import STANDARD_GRAVITY, STEEL_DENSITY
from .predict_modes import RodModes, StepResponse, periodic_states, rod_modes, step_response
from .pump import Pump, PumpChamber
from .string import RodString

#: Largest modes x samples the kernels may hold (complex arrays of this size are kept).
MAX_KERNEL_SIZE = 10_000_000
#: Share of the held rod end's slide fed back to the pump at each step (PumpMarch).
STEERING = 0.5
#: Modes are kept up to this multiple of the Nyquist frequency pi / h; above, quasi-statically
#: (none at all when the cycle is slow against the rods' periods: the quasi-static limit).
MODE_CUTOFF = 2.0


@dataclass(frozen=True)
class Convergence:
    """How the periodic state was found: cycles marched, the largest change per cycle
    (pump load / F_o and plunger position / polished-rod stroke), the tolerance, modes kept,
    and the strokes after which the state repeats (1; 2 to :data:`LONGEST_REPEAT` when the
    pump settles into a cycle of alternating strokes, the last change then being the one over
    that many strokes)."""

    cycles: int
    changes: tuple[float, ...]
    tolerance: float
    modes: int
    strokes: int = 1

    @property
    def change(self) -> float:
        """Largest relative change of the last cycle."""
        return self.changes[-1]


@dataclass(frozen=True)
class WellModel:
    """The rod string, pump and fluid of one well, reduced to what the solvers need (SI).

    modes of the string; response: exact steps of length ``response.step`` [s];
    velocity_kernel[n] [m/(s N)] and position_kernel[n] [m/N]: the rod end's downward
    velocity (limit from the left) and displacement at lag n after a unit hat-shaped
    pump-load sample, residual compliance included;
    buoyant_weight W_rf [N]; weight_below [N]: buoyant weight below each joint (top .. pump).
    """

    rods: RodString
    pump: Pump
    modes: RodModes
    response: StepResponse
    velocity_kernel: np.ndarray
    position_kernel: np.ndarray
    buoyant_weight: float
    weight_below: np.ndarray

    @property
    def tubing_rate(self) -> float:
        """1 / (k_t h) [m/(s N)]: the barrel's velocity per unit change of pump load in one step."""
        return 1.0 / (self.pump.tubing_stiffness * self.response.step)

    @property
    def compliance(self) -> float:
        """Plunger travel relative to the barrel per unit pump load within one step, h (Y_0 + 1/(k_t h)) [m/N]."""
        return self.response.step * (float(self.velocity_kernel[0]) + self.tubing_rate)


def modal_velocity(modes: RodModes, states: np.ndarray) -> np.ndarray:
    """Modal velocities q_k' = Re(eta_k) - (c/2) Im(eta_k) / omega_dk from the complex states (modes x samples),
    computed in the one array returned (the states of a whole cycle are large)."""
    velocity = np.multiply(0.5 * modes.damping, states.imag)
    np.divide(velocity, modes.damped_frequency[:, None], out=velocity)
    return np.subtract(states.real, velocity, out=velocity)


def well_model(rods: RodString, pump: Pump, *, damping: float, step: float, samples: int,
               fluid_density: float, rod_density: float = STEEL_DENSITY,
               gravity: float = STANDARD_GRAVITY) -> WellModel:
    """Modes, exact steps and the static datum of a well, for a time step [s] and ``samples`` steps.

    damping: Gibbs' nu [-]; densities [kg/m^3] of the fluid and of the rod material (for
    the buoyant weight W_rf = g sum m_i L_i (1 - rho_f / rho_r), [Gibbs1963]).
    """
    pump.check()
    if not (np.isfinite(damping) and damping > 0):
        raise PredictionError(f"damping factor must be positive and finite, got {damping}")
    if not (np.isfinite(fluid_density) and 0 <= fluid_density < rod_density):
        raise PredictionError(f"fluid density {fluid_density} kg/m³ must lie between 0 and the rod density {rod_density}")
    modes = rod_modes(rods, damping, MODE_CUTOFF * np.pi / step)
    if modes.count * (samples + 1) > MAX_KERNEL_SIZE:
        raise PredictionError(
            f"{samples} samples per cycle keep {modes.count} modes of this string, more than the solver's "
            f"{MAX_KERNEL_SIZE:.0e} kernel entries: use fewer samples per cycle")
    masses = rods.mass_per_length * rods.length * gravity * (1.0 - fluid_density / rod_density)
    below = np.append(np.cumsum(masses[::-1])[::-1], 0.0)
    return with_step(WellModel(rods, pump, modes, step_response(modes, step, 1), np.zeros(2), np.zeros(2),
                               float(below[0]), below), step, samples)


def with_step(model: WellModel, step: float, samples: int) -> WellModel:
    """The same well (same modes) stepped with ``step`` [s] for ``samples`` steps. The
    residual compliance responds to the pump load's slope, C_rem (F_n - F_{n-1}) / h."""
    modes = model.modes
    response = step_response(modes, step, samples)
    kernel = modes.bottom**2 @ modal_velocity(modes, response.hat)
    kernel[0] += modes.residual_compliance / step
    kernel[1] -= modes.residual_compliance / step
    position = (modes.bottom**2 / modes.damped_frequency) @ response.hat.imag
    position[0] += modes.residual_compliance
    return replace(model, response=response, velocity_kernel=kernel, position_kernel=position)


def carried_response(modes: RodModes, carry: np.ndarray,
                     powers: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The rod end's downward velocity [m/s] and displacement [m] and the dynamic force at the
    top [N] at the samples of ``powers`` (modes x samples, e^{lambda_k h n}) from the modal
    states ``carry`` at the first: the sums over the modes of modal_velocity, q = Im / omega_dk
    and omega_k^2 q, weighted by the modes' values at the joints, as one product of the powers."""
    weights = np.stack([modes.bottom, modes.bottom / modes.damped_frequency,
                        modes.participation * modes.frequency**2 / modes.damped_frequency]) * carry
    free, moved, top = weights @ powers
    return free.real - 0.5 * modes.damping * moved.imag, moved.imag, top.imag


def spectral_derivatives(values: np.ndarray, period: float) -> tuple[np.ndarray, np.ndarray]:
    """First and second time derivatives of periodic samples on t_k = k T / N, by FFT
    (exact for a trigonometric polynomial; the Nyquist term is dropped from the first)."""
    n = values.size
    spectrum = np.fft.rfft(values)
    omega = 2.0 * np.pi * np.fft.rfftfreq(n, period / n)
    first = 1j * omega * spectrum
    if n % 2 == 0:
        first[-1] = 0.0
    return np.fft.irfft(first, n), np.fft.irfft(-omega**2 * spectrum, n)


@dataclass(frozen=True)
class Fields:
    """The periodic solution at the samples: dynamic joint forces [N], shape (joints, N),
    the rod end's downward displacement [m] and velocity [m/s], damping dissipation per cycle [J]."""

    joint_force: np.ndarray
    plunger_down: np.ndarray
    plunger_velocity_down: np.ndarray
    dissipation: float


def periodic_fields(model: WellModel, pump_load: np.ndarray, top_down: np.ndarray, top_velocity_down: np.ndarray,
                    top_drive: np.ndarray) -> Fields:
    """Joint forces, plunger motion and damping dissipation per cycle for periodic inputs.

    top_down u_top [m], its velocity [m/s] and top_drive a = u_top'' + c u_top' [m/s^2],
    all down positive; pump_load F_L [N]. Dissipation int int c m u_t^2 dx dt [J] with
    u_t = u_top' + sum phi_k q_k' (the residual modes' share, of order (omega / omega_cut)^2,
    left out); the sum over a cycle of samples is exact for a trigonometric polynomial.
    """
    m = model.modes
    forcing = m.bottom[:, None] * pump_load[None, :]
    forcing -= m.participation[:, None] * top_drive[None, :]
    states = periodic_states(model.response, forcing)
    q = states.imag / m.damped_frequency[:, None]
    qdot = modal_velocity(m, states)
    joint = (np.outer(m.residual_transmission, pump_load) - np.outer(m.residual_mass, top_drive)
             + (m.joint_participation * m.frequency**2) @ q)
    plunger = top_down + m.bottom @ q + m.residual_compliance * pump_load
    slope = (pump_load - np.roll(pump_load, 1)) / model.response.step
    velocity = top_velocity_down + m.bottom @ qdot + m.residual_compliance * slope
    total_mass = float(np.sum(model.rods.mass_per_length * model.rods.length))
    power = m.damping * (total_mass * top_velocity_down**2 + 2.0 * top_velocity_down * (m.participation @ qdot)
                         + np.sum(qdot**2, axis=0))
    return Fields(joint, plunger, velocity, float(np.sum(power) * model.response.step))


class PumpMarch:
    """The pump marched against the rods, one cycle of N samples at a time (module docstring).

    At each sample the rod end's left-limit velocity is affine in the new pump load,
    v = known - Y_0 F. The pump predicts the plunger position relative to the barrel,
    zeta_n = zeta_{n-1} + h zeta'_n (backward Euler), and applies its valve laws: held
    still, the plunger's velocity is zero (a position constraint on the samples alone
    would ring: a load alternating from sample to sample moves a wave-like rod end by
    nothing there, the trapezoidal rule's weakness on constraints [HairerWanner1996]).
    Between samples the held rod end still slides a little; half of the difference
    between the exact position of the last sample and the pump's own is fed back at each
    step (``STEERING``, a constraint stabilisation after [Baumgarte1972]), which keeps the
    slide second order in the step; a full correction rings in long, lightly damped holds.
    Holds the modal states carried from earlier cycles (``carry``), the last pump load,
    the rod end's last exact downward position and the chamber.
    """

    def __init__(self, model: WellModel, chamber: PumpChamber, carry: np.ndarray, last_load: float,
                 last_position: float):
        self.model, self.chamber, self.carry = model, chamber, carry
        self.last_load, self.last_position = last_load, last_position
        n = model.response.hat.shape[1] - 1
        # the velocity and position kernels of the past samples, reversed, in two rows: one
        # product with the cycle's loads so far gives both sums of a step; the views of step k
        # (kernels of lags k .. 1, the loads before k) are made once, not at every step
        past = np.stack([model.velocity_kernel[n:0:-1], model.position_kernel[n:0:-1]])
        self.load = np.zeros(n)
        self.kernels = [past[:, n - k:] for k in range(n)]
        self.loads = [self.load[:k] for k in range(n)]
        self.tail = model.response.hat[:, n:0:-1].copy()
        self.samples = n

    def carried(self) -> tuple[np.ndarray, np.ndarray]:
        """Downward velocity [m/s] and displacement [m] of the rod end at the cycle's samples
        due to earlier pump loads."""
        velocity, position, _ = carried_response(self.model.modes, self.carry,
                                                 self.model.response.powers[:, :self.samples])
        return velocity, position

    def cycle(self, known_velocity: np.ndarray, known_position: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Pump load [N] and plunger position relative to the barrel [m] over one cycle;
        ``known_velocity`` and ``known_position`` are the rod end's downward velocity [m/s] and
        displacement [m] due to the top motion."""
        n, model = self.samples, self.model
        h, tubing = model.response.step, model.tubing_rate
        carried_velocity, carried_position = self.carried()
        velocity = known_velocity + carried_velocity
        velocity[0] -= model.modes.residual_compliance / h * self.last_load
        velocity, position_base = velocity.tolist(), (known_position + carried_position).tolist()
        chamber, p0, steering = self.chamber, float(model.position_kernel[0]), STEERING
        stretch, give = model.pump.fluid_load / model.pump.tubing_stiffness, 1.0 / model.pump.tubing_stiffness
        load, kernels, loads, step = self.load, self.kernels, self.loads, chamber.step
        load.fill(0.0)
        position = [0.0] * n
        previous, down = self.last_load, self.last_position
        for k in range(n):
            v_past, p_past = (kernels[k] @ loads[k]).tolist()
            rate = tubing * previous - velocity[k] - v_past
            at = chamber.position
            previous, position[k] = step(at + steering * (stretch - give * previous - down - at) + h * rate)
            load[k] = previous
            down = position_base[k] + p_past + p0 * previous
        load = load.copy()
        m = model.modes
        self.carry = model.response.powers[:, n] * self.carry + m.bottom * (self.tail @ load)
        self.last_load, self.last_position = previous, down
        return load, np.array(position)


def periodic_carry(model: WellModel, pump_load: np.ndarray) -> np.ndarray:
    """Modal states at the first sample from the pump-load samples before it, if the pump load
    ``pump_load`` had always repeated."""
    m = model.modes
    states = periodic_states(model.response, m.bottom[:, None] * pump_load[None, :])
    return states[:, 0] - model.response.hat[:, 0] * m.bottom * pump_load[0]


#: A stroke (or revolution) marched, as :func:`shortest_repeat` compares them.
T = TypeVar("T")
#: Most strokes after which a pump's marched state may repeat and be taken as its periodic state.
LONGEST_REPEAT = 4
#: Smallest change over one stroke [-] for a state repeating after several strokes to be taken
#: as such: below it the strokes are one converging state, marched on to the tolerance.
DISTINCT_STROKES = 1e-4
#: Largest change [-] of a state that keeps changing from stroke to stroke once every transient
#: has died away, for it to be taken as the periodic state (and said): a pump's events snap to
#: the samples, and a fluid hit that moves by a sample from stroke to stroke changes the load of
#: that one sample by up to a share of F_o that the step sets, while the card does not change.
USABLE_CHANGE = 1e-2


def shortest_repeat(marched: Sequence[T], change: Callable[[T, T], float], last_change: float,
                    tolerance: float) -> tuple[int, float] | None:
    """The fewest strokes k after which the last of ``marched`` (the strokes or revolutions marched,
    at most :data:`LONGEST_REPEAT` + 1 of them) repeats to ``tolerance``, with the change over them:
    1 when the last repeats the one before (``last_change``, ``change(last, before)``); else 2 or more
    when the strokes differ from each other by more than :data:`DISTINCT_STROKES`; None when none does."""
    if last_change <= tolerance:
        return 1, last_change
    if last_change > DISTINCT_STROKES:
        for k in range(2, len(marched)):
            value = change(marched[-1], marched[-1 - k])
            if value <= tolerance:
                return k, value
    return None


def converge(march: PumpMarch, known: Fields, load_scale: float, position_scale: float, tolerance: float,
             max_cycles: int) -> tuple[np.ndarray, np.ndarray, tuple[float, ...], Convergence]:
    """March cycles until the pump load and plunger position repeat to ``tolerance`` (largest
    relative change), after one stroke or, failing that, after 2 to :data:`LONGEST_REPEAT`
    strokes that differ from each other by more than :data:`DISTINCT_STROKES`
    (:func:`shortest_repeat`): a pump that pounds fluid can settle into alternating strokes, each
    hitting the fluid where the rods' vibration from the stroke before leaves it, and then has no
    state repeating every stroke.

    After ``max_cycles``, when the rods' transient has decayed below the tolerance (every mode
    decays as e^{-c t / 2}: e^{-c T max_cycles / 2} <= tolerance) and each of the last
    2 x :data:`LONGEST_REPEAT` strokes has repeated the one before within :data:`USABLE_CHANGE`, the
    last stroke is the state, its change (above the tolerance) in the returned :class:`Convergence`
    (strokes nearly alike that repeat only after several are such a state too, not a cycle of
    unlike strokes).

    Returns the pump load and plunger position of the repeating strokes (strokes x samples),
    the liquid each discharged [m^3], and how."""
    if not max_cycles >= 2:
        raise PredictionError(f"at least 2 cycles are needed to see the state repeat, got max_cycles {max_cycles}")
    changes: list[float] = []
    marched: list[tuple[np.ndarray, np.ndarray, float]] = []

    def change(later: tuple, earlier: tuple) -> float:
        shift = later[1] - earlier[1]
        return max(float(np.max(np.abs(later[0] - earlier[0]))) / load_scale,
                   float(np.max(np.abs(shift - np.mean(shift)))) / position_scale)

    def state(strokes: int, value: float) -> tuple[np.ndarray, np.ndarray, tuple[float, ...], Convergence]:
        last = marched[-strokes:]
        return (np.stack([row[0] for row in last]), np.stack([row[1] for row in last]), tuple(row[2] for row in last),
                Convergence(len(changes) + 1, (*changes[:-1], value), tolerance, march.model.modes.count, strokes))

    for _ in range(max_cycles):
        discharged = march.chamber.discharge
        load, position = march.cycle(known.plunger_velocity_down, known.plunger_down)
        marched = [*marched[-LONGEST_REPEAT:], (load, position, march.chamber.discharge - discharged)]
        if len(marched) > 1:
            changes.append(change(marched[-1], marched[-2]))
            found = shortest_repeat(marched, change, changes[-1], tolerance)
            if found is not None:
                return state(*found)
        if march.model.pump.gas_exponent is not None:
            march.chamber.rebase(float(position.min()))
    period = march.model.response.step * march.samples
    if (np.exp(-0.5 * march.model.modes.damping * period * max_cycles) <= tolerance
            and max(changes[-2 * LONGEST_REPEAT:]) <= USABLE_CHANGE):
        return state(1, changes[-1])
    raise PredictionError(
        f"the periodic pump cycle did not converge in {max_cycles} cycles (last change {changes[-1]:.3g}, "
        f"tolerance {tolerance:g}, no repeat within {LONGEST_REPEAT} strokes either); raise the damping factor "
        f"or the samples per cycle, or loosen the tolerance"
    )
