"""The machine and the elastic rod string in one time march: crank speed and cards together.

[SK8Rotation2013] solves the unit's equation of motion with rigid rods (their mass in the
reduced inertia, the well's load by stroke); here the rods are the damped wave equation
of :mod:`pumpjack_cli.core.rods.predict` and the machine is the equation of motion of
:mod:`.coefficients` with the reduced inertia of the links and drive only:

    I(theta) epsilon + 1/2 I'(theta) omega^2 = M_drive(omega) - M_gravity(theta) - P(t) TF(theta),

P = W_rf + F(0, t) the polished-rod load of the rods' solution, whose top moves with
s(theta(t)): velocity TF omega, acceleration TF' omega^2 + TF epsilon. The rods' top force
depends on the current top acceleration through the quasi-static high modes (a mass
m_rem moving with the polished rod, [Craig2006]) and on the history through the modal
states, so each time step solves the machine (trapezoidal rule, fixed point on epsilon)
and the pump together. The time step is adjusted from one revolution to the next so
that N steps span exactly one revolution, starting at crank angle 0; the periodic
steady state is reached when the pump load, plunger position, crank speed and the step
repeat to the tolerance. Energy per cycle: the motor's work equals the polished-rod
work (weights and kinetic energy return), a check reported in the summary.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ...errors import PredictionError
from ..constants import STEEL_DENSITY
from ..rods.predict import DEFAULT_TOLERANCE, CardExtreme, Prediction, assemble, card_extreme, predict
from ..rods.predict_modes import periodic_states, step_response
from ..rods.predict_solver import (LONGEST_REPEAT, STEERING, Convergence, WellModel, carried_response,
                                   modal_velocity, shortest_repeat, spectral_derivatives, well_model, with_step)
from ..rods.pump import Pump, PumpChamber
from ..rods.string import RodString
from .coefficients import Machine, gravity_torque, reduced_inertia

#: Crank positions of the machine's coefficient tables (linear interpolation between them).
TABLE_STEPS = 8192
#: Revolutions marched at most.
MAX_REVOLUTIONS = 200
#: The crank counts as stalled below this fraction of the speed the revolution started with.
STALL_FRACTION = 1e-3
#: Newton steps at most in the machine's implicit step.
_PASSES = 12
#: One turn [rad].
_TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class CoupledSummary:
    """Scalar results of the coupled solution (SI; extremes with time [s] and crank angle [rad]).

    mean_speed 2 pi / period [1/s]; speed_fluctuation (max - min) / mean; torques [N·m]
    at the motor shaft (motor_torque) and on the crank shaft from the gearbox
    (net_torque = M_drive - I_drive epsilon); inertia torque I epsilon + 1/2 I' omega^2
    of links and drive; motor_work and polished_rod_work per cycle [J] and their relative
    difference energy_residual; breakdown_torque_margin = pull-out torque / largest motor
    torque (below 1 the linear motor characteristic is used beyond its validity: the motor
    would stall); revolutions marched and their largest relative change.
    """

    mean_speed: float
    max_speed: CardExtreme
    min_speed: CardExtreme
    speed_fluctuation: float
    max_acceleration: CardExtreme
    min_acceleration: CardExtreme
    peak_motor_torque: CardExtreme
    min_motor_torque: CardExtreme
    max_net_torque: CardExtreme
    min_net_torque: CardExtreme
    peak_inertia_torque: CardExtreme
    min_inertia_torque: CardExtreme
    period: float
    motor_work: float
    polished_rod_work: float
    energy_residual: float
    breakdown_torque_margin: float
    convergence: Convergence


@dataclass(frozen=True)
class CoupledPrediction:
    """Cards (on t_k = k T / N from crank angle 0) and the machine's motion and torques at the same samples.

    crank_speed omega [1/s], crank_acceleration epsilon [1/s^2]; motor_torque [N·m] at
    the motor shaft; net_torque, rod_load_torque P TF, gravity_torque, inertia_torque
    [N·m] on the crank shaft.
    """

    cards: Prediction
    crank_speed: np.ndarray
    crank_acceleration: np.ndarray
    motor_torque: np.ndarray
    net_torque: np.ndarray
    rod_load_torque: np.ndarray
    gravity_torque: np.ndarray
    inertia_torque: np.ndarray
    summary: CoupledSummary


class _Tables:
    """s, TF, TF', I, I', M_gravity on a uniform crank-angle grid, interpolated linearly (Python floats).

    ``intervals`` holds, per grid interval, the six values at its start and their increments
    over it: :meth:`at` and the march's lookup, written out in its loop, take one list item per
    evaluation.
    """

    def __init__(self, machine: Machine):
        theta = np.linspace(0.0, 2.0 * np.pi, TABLE_STEPS + 1)
        linkage = machine.linkage
        m = linkage.motion(theta)
        inertia, rate = reduced_inertia(linkage, machine.masses, m, 0.0, machine.constant_inertia)
        columns = np.stack([m.rod_position, m.torque_factor, m.torque_factor_rate, inertia, rate,
                            gravity_torque(linkage, machine.masses, m, machine.gravity)], axis=1)
        if not (np.all(np.isfinite(columns)) and np.all(inertia > 0)):
            raise PredictionError("the machine's inertia or gravity torque is not finite and positive; check the unit data")
        self.intervals = np.concatenate([columns[:-1], np.diff(columns, axis=0)], axis=1).tolist()
        self.scale = TABLE_STEPS / (2.0 * np.pi)

    def at(self, theta: float) -> tuple[float, float, float, float, float, float]:
        x = (theta % _TWO_PI) * self.scale
        i = min(int(x), TABLE_STEPS - 1)
        f = x - i
        s, t, d, inertia, r, g, ds, dt, dd, di, dr, dg = self.intervals[i]
        return s + f * ds, t + f * dt, d + f * dd, inertia + f * di, r + f * dr, g + f * dg


class _Channels:
    """Scalar kernels of one step size: the rod end's downward velocity and displacement and the
    top's dynamic force per unit hat-shaped sample of pump load F and top drive a, and the
    modal bookkeeping."""

    def __init__(self, model: WellModel, step: float, samples: int):
        m = model.modes
        response = step_response(m, step, samples)
        qd = modal_velocity(m, response.hat)
        q = response.hat.imag / m.damped_frequency[:, None]
        stiffness = m.participation * m.frequency**2
        self.response, self.step = response, step
        self.velocity_load = m.bottom**2 @ qd
        self.velocity_load[0] += m.residual_compliance / step
        self.velocity_load[1] -= m.residual_compliance / step
        self.velocity_drive = -(m.bottom * m.participation) @ qd
        self.force_load = (stiffness * m.bottom) @ q
        self.force_load[0] += m.residual_transmission[0]
        self.force_drive = -(stiffness * m.participation) @ q
        self.force_drive[0] -= m.residual_mass[0]
        self.position_load = m.bottom**2 @ q
        self.position_load[0] += m.residual_compliance
        self.position_drive = -(m.bottom * m.participation) @ q
        # The kernels of the past samples, reversed and interleaved (load, drive, load, ...) in
        # rows of velocity, force and position: one product with the interleaved history of
        # the block gives the three sums of a step.
        self.past = np.stack([np.stack([load, drive], axis=1).ravel() for load, drive in (
            (self.velocity_load[samples:0:-1], self.velocity_drive[samples:0:-1]),
            (self.force_load[samples:0:-1], self.force_drive[samples:0:-1]),
            (self.position_load[samples:0:-1], self.position_drive[samples:0:-1]))])
        self.tail = response.hat[:, samples:0:-1].copy()

    def carried(self, model: WellModel, carry: np.ndarray, samples: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Rod-end velocity and displacement and top force at the block's samples from the modal states carried in."""
        return carried_response(model.modes, carry, self.response.powers[:, :samples])


#: Samples of the uniform prediction that gives the first guess of the mean crank speed.
START_SAMPLES = 256


def predict_coupled(machine: Machine, rods: RodString, pump: Pump, *, damping: float, fluid_density: float,
                    rod_density: float = STEEL_DENSITY, samples: int = 1024, tolerance: float = DEFAULT_TOLERANCE,
                    max_revolutions: int = MAX_REVOLUTIONS, resolution: int = 1024) -> CoupledPrediction:
    """Cards, crank speed and torques of a unit and its well solved together (module docstring).

    Parameters
    ----------
    machine : Machine
        Linkage, masses, drive inertia, ratio and motor; ``machine.rod_load`` is not used
        (the rods and the fluid load are modelled here) and its reduced inertia holds no
        rod or fluid mass.
    rods, pump : RodString, Pump
        The well (:func:`pumpjack_cli.core.rods.predict.predict`).
    damping : float
        Gibbs' damping factor nu [-].
    fluid_density, rod_density : float
        [kg/m^3].
    samples : int
        Time samples per revolution N returned; the march takes N k steps per revolution, k the
        smallest factor reaching ``resolution`` (the grid of the uniform-rotation prediction,
        :func:`~pumpjack_cli.core.rods.predict.predict_cards`), and every k-th sample is
        returned (the summary keeps the fine grid's values).

    References
    ----------
    [SK8Rotation2013] eq. 1 (equation of motion); [Gibbs1963] (rods).
    """
    if not 64 <= samples <= 1 << 16:
        raise PredictionError(f"samples per revolution must lie in 64 .. 65536, got {samples}")
    factor = max(1, -(-resolution // samples))
    fine = _solve_coupled(machine, rods, pump, damping, fluid_density, rod_density, samples * factor, tolerance,
                          max_revolutions)
    return fine if factor == 1 else _every(fine, factor)


def _every(fine: CoupledPrediction, factor: int) -> CoupledPrediction:
    """Every ``factor``-th sample of a coupled prediction (from the first), the summary kept."""
    pick = slice(None, None, factor)
    c = fine.cards
    columns = ("time", "crank_angle", "polished_rod_position", "polished_rod_velocity", "polished_rod_load",
               "plunger_position", "pump_load", "chamber_pressure")
    cards = replace(c, **{name: getattr(c, name)[pick] for name in columns},
                    taper_top_load=c.taper_top_load[:, pick], taper_bottom_load=c.taper_bottom_load[:, pick])
    return replace(fine, cards=cards, **{name: getattr(fine, name)[pick] for name in (
        "crank_speed", "crank_acceleration", "motor_torque", "net_torque", "rod_load_torque", "gravity_torque",
        "inertia_torque")})


def _solve_coupled(machine: Machine, rods: RodString, pump: Pump, damping: float, fluid_density: float,
                   rod_density: float, samples: int, tolerance: float, max_revolutions: int) -> CoupledPrediction:
    """The coupled march on ``samples`` steps per revolution (:func:`predict_coupled`)."""
    tables = _Tables(machine)
    a_u, b_u2 = machine.motor.a * machine.drive_ratio, machine.motor.b * machine.drive_ratio**2
    # the first guess of the mean speed needs only the card's work: a coarse grid does
    coarse = min(samples, START_SAMPLES)
    start = predict(rods, pump, _positions(tables, coarse), 2.0 * np.pi / machine.rated_crank_speed,
                    damping=damping, fluid_density=fluid_density, rod_density=rod_density, tolerance=1e-4)
    omega = (start.summary.surface_card_work / (2.0 * np.pi) - a_u) / b_u2
    if not omega > 0:
        raise PredictionError(
            f"the well needs a mean crank torque of {start.summary.surface_card_work / (2 * np.pi):.6g} N·m, more "
            f"than the motor's linear characteristic gives at standstill ({a_u:.6g} N·m at the crank)")
    period = 2.0 * np.pi / omega
    uniform = predict(rods, pump, _positions(tables, samples), period, damping=damping, fluid_density=fluid_density,
                      rod_density=rod_density, crank_angle=np.arange(samples) * (2.0 * np.pi / samples),
                      tolerance=1e-4)
    model = well_model(rods, pump, damping=damping, step=period / samples, samples=samples,
                       fluid_density=fluid_density, rod_density=rod_density)
    march = _CoupledMarch(machine, model, tables, samples, uniform, omega)
    return march.run(tolerance, max_revolutions)


def _shape_change(position: np.ndarray, previous: np.ndarray) -> float:
    """Largest change of a position record apart from a constant shift (the pump's valve laws
    depend on position differences only, so its integrated position may drift by a constant)."""
    change = position - previous
    return float(np.max(np.abs(change - np.mean(change))))


def _positions(tables: _Tables, samples: int) -> np.ndarray:
    """Polished-rod position [m] at uniform crank angles from 0."""
    return np.array([tables.at(t)[0] for t in (np.arange(samples) * (2.0 * np.pi / samples)).tolist()])


class _CoupledMarch:
    """State carried between revolutions: crank angle, speed and acceleration, modal states,
    the last pump load, the rod end's last exact position, the chamber and the time step."""

    def __init__(self, machine: Machine, model: WellModel, tables: _Tables, samples: int, uniform: Prediction,
                 omega: float):
        self.machine, self.model, self.tables, self.samples = machine, model, tables, samples
        m = model.modes
        period = uniform.time[1] * samples
        velocity, acceleration = spectral_derivatives(uniform.polished_rod_position, period)
        drive = -(acceleration + m.damping * velocity)
        load = uniform.pump_load
        forcing = m.bottom[:, None] * load[None, :] - m.participation[:, None] * drive[None, :]
        states = periodic_states(model.response, forcing)
        self.carry = states[:, 1] - model.response.hat[:, 0] * forcing[:, 1]
        self.last_load, self.last_position = float(load[0]), -float(uniform.plunger_position[0])
        f_o = model.pump.fluid_load
        if model.pump.faulty:
            raise PredictionError("valve leaks and stops are modelled at uniform crank speed (predict), not coupled "
                                  "with the machine")
        # the state is kept in Python floats: the march's per-step arithmetic on numpy scalars costs
        # several times more
        self.chamber = PumpChamber(model.pump, 0.0, float((f_o - load[0]) / model.pump.tubing_stiffness
                                                          + uniform.plunger_position[0]))
        self.theta, self.omega, self.epsilon = 0.0, float(omega), 0.0
        self.step = float(period / samples)

    def run(self, tolerance: float, max_revolutions: int) -> CoupledPrediction:
        if not max_revolutions >= 2:
            raise PredictionError(f"at least 2 revolutions are needed to see the state repeat, got {max_revolutions}")
        changes: list[float] = []
        blocks: list["_Revolution"] = []
        f_o = max(self.model.pump.fluid_load, 1.0)
        stroke = self.machine.linkage.stroke

        def change(block: "_Revolution", previous: "_Revolution") -> float:
            return max(float(np.max(np.abs(block.load - previous.load))) / f_o,
                       _shape_change(block.relative, previous.relative) / stroke,
                       float(np.max(np.abs(block.omega - previous.omega))) / self.omega,
                       abs(block.step - previous.step) / block.step)

        volumes: list[float] = []
        for revolution in range(max_revolutions):
            discharged = self.chamber.discharge
            block = self._revolution(revolution)
            blocks = [*blocks[-LONGEST_REPEAT:], block]
            volumes = [*volumes[-LONGEST_REPEAT:], self.chamber.discharge - discharged]
            if len(blocks) > 1:
                changes.append(change(block, blocks[-2]))
                found = shortest_repeat(blocks, change, changes[-1], tolerance)
                if found is not None:
                    k, value = found
                    convergence = Convergence(len(changes) + 1, (*changes[:-1], value), tolerance,
                                              self.model.modes.count, k)
                    return self._result(blocks[-k:], volumes[-k:], convergence)
        raise PredictionError(
            f"the coupled machine and rods did not reach a periodic state in {max_revolutions} revolutions "
            f"(last change {changes[-1]:.3g}, tolerance {tolerance:g})")

    def _revolution(self, revolution: int) -> "_Revolution":
        """March N steps from the current state, then set the step so that the next N steps end
        at crank angle 2 pi (revolution + 2), at the mean speed of this revolution.

        The steps work on Python floats, with the lookup of :meth:`_Tables.at` written out (the
        same arithmetic) and the constants of a step taken out of the loops."""
        n, h = self.samples, self.step
        model, machine, tables = self.model, self.machine, self.tables
        m = model.modes
        ch = _Channels(model, h, n)
        tubing = 1.0 / (model.pump.tubing_stiffness * h)
        self.chamber.compliance = h * (float(ch.velocity_load[0]) + tubing)
        carry_velocity, carry_position, carry_force = ch.carried(model, self.carry, n)
        carry_velocity[0] -= m.residual_compliance / h * self.last_load
        carry_velocity, carry_position = carry_velocity.tolist(), carry_position.tolist()
        carry_force = (carry_force + model.buoyant_weight).tolist()
        past = ch.past
        pl0, pd0 = float(ch.position_load[0]), float(ch.position_drive[0])
        stretch, give = model.pump.fluid_load / model.pump.tubing_stiffness, 1.0 / model.pump.tubing_stiffness
        vd0, fl0, fd0 = float(ch.velocity_drive[0]), float(ch.force_load[0]), float(ch.force_drive[0])
        c = m.damping
        a_u, b_u2 = machine.motor.a * machine.drive_ratio, machine.motor.b * machine.drive_ratio**2
        history = np.zeros(2 * n)   # pump load and top drive of the block's samples so far, interleaved
        rows: list[tuple[float, ...]] = []
        theta_p, omega_p, eps_p, load_p, down = self.theta, self.omega, self.epsilon, self.last_load, self.last_position
        start = theta_p
        chamber = self.chamber
        step_chamber = chamber.step
        intervals, scale, last, two_pi, passes = tables.intervals, tables.scale, TABLE_STEPS - 1, _TWO_PI, _PASSES
        append = rows.append
        half = 0.5 * h
        stall = STALL_FRACTION * self.omega
        for k in range(n):
            v_past, f_past, p_past = (past[:, 2 * (n - k):] @ history[:2 * k]).tolist()
            v_known = carry_velocity[k] + v_past
            f_known = carry_force[k] + f_past
            omega = omega_p + h * eps_p
            f_k = load_p
            for sweep in range(2):
                known_force = f_known + fl0 * f_k
                for _ in range(passes):
                    theta = theta_p + half * (omega_p + omega)
                    x = (theta % two_pi) * scale
                    i = int(x)
                    if i > last:
                        i = last
                    f = x - i
                    s0, tf, tf1, inertia, rate, grav, ds, dtf, dtf1, dinertia, drate, dgrav = intervals[i]
                    tf, tf1, inertia, rate, grav = (tf + f * dtf, tf1 + f * dtf1, inertia + f * dinertia,
                                                    rate + f * drate, grav + f * dgrav)
                    mass = inertia - fd0 * tf * tf
                    force = known_force - fd0 * (tf1 * omega * omega + c * tf * omega)
                    eps = (a_u + b_u2 * omega - grav - tf * force - 0.5 * rate * omega * omega) / mass
                    slope = (b_u2 + tf * fd0 * (2.0 * tf1 * omega + c * tf) - rate * omega) / mass
                    residual = omega - omega_p - half * (eps_p + eps)
                    omega -= residual / (1.0 - half * slope)
                    if abs(residual) <= 1e-14 * omega:
                        break
                omega = omega_p + half * (eps_p + eps)
                theta = theta_p + half * (omega_p + omega)
                a_k = -(tf1 * omega * omega + tf * eps + c * tf * omega)
                if sweep == 0:
                    rate_zeta = tubing * load_p - (v_known - tf * omega + vd0 * a_k)
                    exact = stretch - give * load_p - down
                    position = chamber.position
                    f_k, zeta = step_chamber(position + STEERING * (exact - position) + h * rate_zeta)
            if not omega > stall:
                raise PredictionError(
                    f"the crank stalls (omega1 {omega:.3g} 1/s at crank angle {np.degrees(theta) % 360:.1f} deg): "
                    f"the motor cannot turn the unit with this well")
            s = s0 + f * ds
            history[2 * k], history[2 * k + 1] = f_k, a_k
            down = carry_position[k] - s + p_past + pl0 * f_k + pd0 * a_k
            append((theta, omega, eps, s, tf * omega, f_known + fl0 * f_k + fd0 * a_k, zeta, grav))
            theta_p, omega_p, eps_p, load_p = theta, omega, eps, f_k
        load, drive = history[0::2], history[1::2]
        forcing_sum = m.bottom * (ch.tail @ load) - m.participation * (ch.tail @ drive)
        self.carry = ch.response.powers[:, n] * self.carry + forcing_sum
        self.theta, self.omega, self.epsilon, self.last_load, self.last_position = theta_p, omega_p, eps_p, load_p, down
        target = 2.0 * np.pi * (revolution + 2) - theta_p
        self.step = h * target / (theta_p - start)
        return _Revolution(h, np.array(rows), load, drive)

    def _result(self, blocks: list["_Revolution"], volumes: list[float],
                convergence: Convergence) -> CoupledPrediction:
        """Cards on the revolutions' samples (shifted to start at crank angle 0), machine outputs and
        summary: of the one revolution that repeats, or of the one of the highest polished-rod load
        among revolutions that repeat together (their rods' response periodic over all of them, at
        their mean step, :func:`~pumpjack_cli.core.rods.predict.assemble`)."""
        model, n = self.model, self.samples
        h = float(np.mean([block.step for block in blocks]))
        # the revolutions in turn, each from crank angle 0: the state there is the one the revolution
        # before ended with (the cycle's last for the first)
        rows = np.roll(np.concatenate([block.rows for block in blocks]), 1, axis=0)
        theta, omega, eps, position, velocity = rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4]
        time = np.concatenate([np.arange(n) * block.step for block in blocks])
        drive = np.roll(np.concatenate([block.drive for block in blocks]), 1)
        load = np.roll(np.concatenate([block.load for block in blocks]), 1).reshape(len(blocks), n)
        cards = assemble(with_step(model, h, n), time, theta % (2.0 * np.pi), position, velocity, drive, load,
                         tuple(volumes), n * h, convergence)
        shown = int(np.argmax(cards.summary.stroke_peak_loads))
        window = slice(shown * n, (shown + 1) * n)
        return machine_result(self.machine, self.tables, cards, theta[window], omega[window], eps[window],
                              blocks[shown].step, convergence, end_speed=float(omega[window.stop % omega.size]))


def machine_result(machine: Machine, tables: _Tables, cards: Prediction, theta: np.ndarray, omega: np.ndarray,
                   eps: np.ndarray, h: float, convergence: Convergence,
                   end_speed: float | None = None) -> CoupledPrediction:
    """The machine's side of a coupled solution from its cards and crank motion at the samples
    (crank angle theta [rad], speed omega [1/s], acceleration eps [1/s^2], on a time grid of step h [s]):
    motor, gearbox, load, gravity and inertia torques and the summary. ``end_speed`` [1/s]: the
    crank's speed at the revolution's end when it differs from its start (revolutions that repeat
    together): the machine's kinetic energy then changes over it, 1/2 I(theta_0) (end^2 - omega_0^2),
    and the energy residual is the motor's work less the polished rod's and that change."""
    n = theta.size
    period = n * h
    angle = theta % (2.0 * np.pi)
    time = np.arange(n) * h
    velocity = cards.polished_rod_velocity
    table = np.array([tables.at(t) for t in theta.tolist()])
    tf, inertia, rate, gravity = table[:, 1], table[:, 3], table[:, 4], table[:, 5]
    drive_torque = np.asarray(machine.drive_torque(omega))
    rod_load_torque = cards.polished_rod_load * tf
    inertia_torque = inertia * eps + 0.5 * rate * omega**2
    gearbox = drive_torque - machine.drive_inertia * eps
    motor_work = float(np.sum(drive_torque * omega) * h)
    end = float(omega[0]) if end_speed is None else end_speed
    kinetic = 0.5 * float(inertia[0]) * (end**2 - float(omega[0]) ** 2)
    rod_work = float(np.sum(cards.polished_rod_load * velocity) * h)
    mean = 2.0 * np.pi / period
    summary = CoupledSummary(
        mean_speed=mean,
        max_speed=card_extreme(omega, time, angle, np.argmax),
        min_speed=card_extreme(omega, time, angle, np.argmin),
        speed_fluctuation=float(np.ptp(omega)) / mean,
        max_acceleration=card_extreme(eps, time, angle, np.argmax),
        min_acceleration=card_extreme(eps, time, angle, np.argmin),
        peak_motor_torque=card_extreme(drive_torque / machine.drive_ratio, time, angle, np.argmax),
        min_motor_torque=card_extreme(drive_torque / machine.drive_ratio, time, angle, np.argmin),
        max_net_torque=card_extreme(gearbox, time, angle, np.argmax),
        min_net_torque=card_extreme(gearbox, time, angle, np.argmin),
        peak_inertia_torque=card_extreme(inertia_torque, time, angle, np.argmax),
        min_inertia_torque=card_extreme(inertia_torque, time, angle, np.argmin),
        period=period,
        motor_work=motor_work,
        polished_rod_work=rod_work,
        energy_residual=(motor_work - rod_work - kinetic) / motor_work,
        breakdown_torque_margin=machine.motor.breakdown_torque / float(np.max(np.abs(drive_torque)) / machine.drive_ratio),
        convergence=convergence,
    )
    return CoupledPrediction(cards, omega, eps, drive_torque / machine.drive_ratio, gearbox, rod_load_torque,
                             gravity, inertia_torque, summary)


@dataclass(frozen=True)
class _Revolution:
    """One marched revolution: step [s]; rows of (theta, omega, epsilon, s, s', P, zeta, M_gravity);
    pump load [N] and top drive [m/s^2] samples."""

    step: float
    rows: np.ndarray
    load: np.ndarray
    drive: np.ndarray

    @property
    def omega(self) -> np.ndarray:
        return self.rows[:, 1]

    @property
    def relative(self) -> np.ndarray:
        return self.rows[:, 6]
