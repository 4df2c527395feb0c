"""The machine and the rod string of a deviated well in one time march.

The machine is :mod:`.coupled`'s equation of motion reduced to the crank (links and drive
only, [SK8Rotation2013] eq. 1),

    I(theta) epsilon + 1/2 I'(theta) omega^2 = M_drive(omega) - M_gravity(theta) - P(t) TF(theta),

and the rods are the time march of :mod:`pumpjack_cli.core.rods.deviated_predict` (gravity
along the hole, Coulomb drag, the pump's valves). P = W + F_1/2 + f_0 + m_0 (a + c v): the
first spring's force and the top half cell's drag, known once the rods have stepped, and
the top half cell's inertia, which moves with the polished rod and joins the machine's
inertia (m_0 TF^2). Each step is the machine's trapezoidal rule (Newton on omega) and a
rod step driven by the polished rod's motion s(theta), TF omega, TF' omega^2 + TF epsilon,
repeated once with the corrected motion (the rods' answer to a change of the crank angle
moves the machine by a share (h^2 k TF^2 / 4 I) of about 1e-3 per pass). As in
:mod:`.coupled`, the step is rescaled after each revolution so that N steps span one
revolution from crank angle 0, and the march stops when pump load, plunger position, crank
speed and step repeat to the tolerance.
"""

from __future__ import annotations

import numpy as np

from ...errors import PredictionError
from ..rods.deviated import DEFAULT_REGULARISATION, MAX_SEGMENT
from ..rods.deviated_predict import (DEFAULT_TOLERANCE, SPECTRAL_RADIUS, Cycle, DeviatedPrediction, Recorder, StringMarch,
                                     TopMotion, assemble_deviated, cycle_change, deviated_grid, steady_state,
                                     top_motion)
from ..rods.path import WellPath
from ..rods.predict_solver import Convergence
from ..rods.pump import Pump
from ..rods.string import RodString
from .coefficients import Machine
from .coupled import MAX_REVOLUTIONS, STALL_FRACTION, CoupledPrediction, _positions, _Tables, machine_result

#: Newton steps at most in the machine's implicit step.
_NEWTON = 12


def predict_coupled_deviated(machine: Machine, rods: RodString, path: WellPath, pump: Pump, *, damping: float,
                             fluid_density: float, friction_coefficient: float, samples: int = 1024,
                             tolerance: float = DEFAULT_TOLERANCE, max_revolutions: int = MAX_REVOLUTIONS,
                             regularisation: float = DEFAULT_REGULARISATION, max_segment: float = MAX_SEGMENT,
                             spectral_radius: float = SPECTRAL_RADIUS) -> tuple[CoupledPrediction, DeviatedPrediction]:
    """Crank motion, torques and cards of a unit and its deviated well solved together (module
    docstring); the machine's side as :func:`.coupled.predict_coupled` returns it, and the
    deviated string's cards, profile and drag (:class:`~..rods.deviated_predict.DeviatedPrediction`).

    Parameters are those of :func:`.coupled.predict_coupled` and of
    :func:`~..rods.deviated_predict.predict_deviated` (``path``, ``friction_coefficient``,
    ``regularisation``, ``max_segment``, ``spectral_radius``).

    References
    ----------
    [SK8Rotation2013] eq. 1; [Gibbs1963]; [JohancsikSPE11380]; [ChungHulbert1993].
    """
    if not 64 <= samples <= 1 << 16:
        raise PredictionError(f"samples per revolution must lie in 64 .. 65536, got {samples}")
    if not max_revolutions >= 2:
        raise PredictionError(f"at least 2 revolutions are needed to see the state repeat, got {max_revolutions}")
    pump.check()
    tables = _Tables(machine)
    position = _positions(tables, samples)
    a_u, b_u2 = machine.motor.a * machine.drive_ratio, machine.motor.b * machine.drive_ratio**2

    def uniform(period: float, tolerance: float) -> tuple[StringMarch, Cycle, TopMotion]:
        step = period / samples
        grid = deviated_grid(rods, path, step, damping=damping, fluid_density=fluid_density, max_segment=max_segment)
        top = top_motion(position, period)
        march = StringMarch(grid, pump, step, friction_coefficient,
                            regularisation * float(np.max(np.abs(top.velocity))), spectral_radius)
        march.start(top, pump.fluid_load if top.velocity[0] > 0 else 0.0)
        cycle, _ = steady_state(march, top, tolerance, 400)
        return march, cycle, top

    march, cycle, top = uniform(2.0 * np.pi / machine.rated_crank_speed, 1e-4)
    work = float(np.sum(0.5 * (cycle.top_load + np.roll(cycle.top_load, -1)) * (np.roll(top.position, -1) - top.position)))
    omega = (work / (2.0 * np.pi) - a_u) / b_u2
    if not omega > 0:
        raise PredictionError(
            f"the well needs a mean crank torque of {work / (2 * np.pi):.6g} N·m, more than the motor's linear "
            f"characteristic gives at standstill ({a_u:.6g} N·m at the crank)")
    march, cycle, top = uniform(2.0 * np.pi / omega, 1e-4)
    return _Coupled(machine, tables, march, samples, omega).run(tolerance, max_revolutions)


class _Coupled:
    """The coupled march: crank angle, speed, acceleration and the string's march."""

    def __init__(self, machine: Machine, tables: _Tables, march: StringMarch, samples: int, omega: float):
        self.machine, self.tables, self.march, self.samples = machine, tables, march, samples
        self.theta, self.omega, self.epsilon = 0.0, omega, 0.0
        self.mean = omega

    def run(self, tolerance: float, max_revolutions: int) -> tuple[CoupledPrediction, DeviatedPrediction]:
        changes: list[float] = []
        previous = None
        pump = self.march.pump
        for revolution in range(max_revolutions):
            block = self._revolution(revolution)
            if previous is not None:
                changes.append(max(cycle_change(block["cycle"], previous["cycle"], max(pump.fluid_load, 1.0),
                                                self.machine.linkage.stroke),
                                   float(np.max(np.abs(block["omega"] - previous["omega"]))) / self.mean,
                                   abs(block["step"] - previous["step"]) / block["step"]))
                if changes[-1] <= tolerance:
                    return self._result(block, Convergence(len(changes) + 1, tuple(changes), tolerance, 0))
            previous = block
        raise PredictionError(
            f"the coupled machine and deviated well did not reach a periodic state in {max_revolutions} revolutions "
            f"(last change {changes[-1]:.3g}, tolerance {tolerance:g})")

    def _revolution(self, revolution: int) -> dict:
        """N steps from the current state, then the step that makes the next N end at crank angle
        2 pi (revolution + 2)."""
        n_steps, march, machine, tables = self.samples, self.march, self.machine, self.tables
        h = march.step
        grid = march.grid
        m0, c = float(grid.node_mass[0]), grid.damping
        a_u, b_u2 = machine.motor.a * machine.drive_ratio, machine.motor.b * machine.drive_ratio**2
        recorder = Recorder(march, n_steps)
        rows = np.empty((n_steps, 6))
        theta_p, omega_p, eps_p = self.theta, self.omega, self.epsilon
        s_p = tables.at(theta_p)[0]
        start = theta_p
        for n in range(1, n_steps + 1):
            saved = march.state()
            omega, eps = omega_p + h * eps_p, eps_p
            for attempt in range(2):
                if attempt:
                    march.restore(saved)
                theta = theta_p + 0.5 * h * (omega_p + omega)
                s, tf, tf1, *_ = tables.at(theta)
                top = TopMotion(np.array([s_p, s]), np.array([0.0, tf * omega]),
                                np.array([0.0, tf1 * omega * omega + tf * eps]))
                load, zeta, drag, velocity = march.advance(top, 1)
                rest = grid.hanging_weight + march.top_force(march.w, top, 1) - m0 * (top.acceleration[1]
                                                                                       + c * top.velocity[1])
                omega, eps, theta = self._machine_step(theta_p, omega_p, eps_p, omega, rest, m0, c, a_u, b_u2)
            if not omega > STALL_FRACTION * self.mean:
                raise PredictionError(
                    f"the crank stalls (omega1 {omega:.3g} 1/s at crank angle {np.degrees(theta) % 360:.1f} deg): "
                    f"the motor cannot turn the unit with this well")
            recorder.record(n % n_steps, top, 1, load, zeta, drag, velocity)
            rows[n % n_steps] = (theta, omega, eps, s, top.velocity[1], top.acceleration[1])
            theta_p, omega_p, eps_p, s_p = theta, omega, eps, s
        self.theta, self.omega, self.epsilon = theta_p, omega_p, eps_p
        target = 2.0 * np.pi * (revolution + 2) - theta_p
        new_step = h * target / (theta_p - start)
        march.set_step(new_step)
        return {"cycle": recorder.finish(), "rows": rows, "omega": rows[:, 1], "step": h}

    def _machine_step(self, theta_p: float, omega_p: float, eps_p: float, omega: float, rest: float, m0: float,
                      c: float, a_u: float, b_u2: float) -> tuple[float, float, float]:
        """The trapezoidal rule for omega with the rods' load ``rest`` [N] (all but the top half
        cell's inertia m0 [kg], which joins the machine's): (omega, epsilon, theta) of the new step."""
        h = self.march.step
        eps = eps_p
        theta = theta_p
        for _ in range(_NEWTON):
            theta = theta_p + 0.5 * h * (omega_p + omega)
            _, tf, tf1, inertia, rate, grav = self.tables.at(theta)
            mass = inertia + m0 * tf * tf
            force = rest + m0 * (tf1 * omega * omega + c * tf * omega)
            eps = (a_u + b_u2 * omega - grav - tf * force - 0.5 * rate * omega * omega) / mass
            slope = (b_u2 - tf * m0 * (2.0 * tf1 * omega + c * tf) - rate * omega) / mass
            residual = omega - omega_p - 0.5 * h * (eps_p + eps)
            omega -= residual / (1.0 - 0.5 * h * slope)
            if abs(residual) <= 1e-14 * abs(omega):
                break
        omega = omega_p + 0.5 * h * (eps_p + eps)
        return omega, eps, theta_p + 0.5 * h * (omega_p + omega)

    def _result(self, block: dict, convergence: Convergence) -> tuple[CoupledPrediction, DeviatedPrediction]:
        n = self.samples
        h = block["step"]
        rows = block["rows"]
        theta, omega, eps = rows[:, 0], rows[:, 1], rows[:, 2]
        top = TopMotion(rows[:, 3], rows[:, 4], rows[:, 5])
        deviated = assemble_deviated(self.march.grid, self.march.pump, block["cycle"], top, theta % (2.0 * np.pi),
                                     n * h, convergence)
        return machine_result(self.machine, self.tables, deviated.cards, theta, omega, eps, h, convergence), deviated

