"""The periodic motion of a beam pumping unit under its motor, load and weights.

The equation of motion and its coefficients are :mod:`.coefficients`. It is
integrated in the crank angle, d(omega)/dtheta = (M_drive - M_load - M_gravity -
1/2 omega^2 I')/(I omega), dt/dtheta = 1/omega, over the upstroke and then the
downstroke ([SK8Rotation2013] eqs. 27 and 29), with the DOP853 of :mod:`.dop853` at a relative tolerance
``rtol`` and absolute tolerances rtol x the scale of each state. The coefficients I,
I' and M_load + M_gravity are tabulated exactly on 4096 crank angles per revolution
and interpolated by cubic splines within each stroke (error ~1e-11 relative, below
the default rtol = 1e-10), which makes one periodic solve take milliseconds.

Periodic steady state ([SK8Rotation2013]): the speed omega_0 at the start of the upstroke is
the root of R(omega_0) = omega_end(omega_0) - omega_0, found by secant iteration from
the mean speed of the energy balance (a u + b u^2 <omega>_theta = E / 2 pi).
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from ...errors import DynamicsError
from ..beam.kinematics import RodMotion, rod_motion
from ..mechanism import DeadPositions
from ..sampling import Extreme, crank_grid, extremes
from .coefficients import Machine, coefficients
from .dop853 import integrate

if TYPE_CHECKING:  # scipy is imported when a solution is computed
    from scipy.interpolate import CubicSpline

#: Default relative tolerance of the integration; absolute tolerances are rtol x state scale.
DEFAULT_RTOL = 1e-10
#: Coefficient table points per revolution (cubic-spline interpolation within a stroke).
TABLE_STEPS = 4096
#: Crank positions on which the summary's extremes are located.
SUMMARY_STEPS = 3600
#: Bound on the secant iterations of the shooting.
MAX_ITERATIONS = 30
#: The crank counts as stalled below this fraction of the mean-speed estimate.
STALL_FRACTION = 1e-3
#: Tolerance of the first, coarse periodic solution: it tells a load beyond the motor's
#: pull-out torque in a fraction of the fine solution's time. (The fine shooting starts
#: from the mean-torque guess, not from the coarse start speed: a secant step between two
#: start speeds that close follows the integration's noise on a card's kinks.)
COARSE_RTOL = 1e-6
#: The cycle is integrated to this share of the periodicity tolerance rtol: the state at its
#: end then carries an integration error well below rtol, and the secant iteration on
#: omega_end - omega_0 ends in a few steps instead of wandering in the integration's noise
#: (which, integrated to rtol itself, is some 10 rtol on a card's kinks).
INTEGRATION_SHARE = 1e-2
#: Tightest integration tolerance asked of DOP853 (a hundred machine epsilons: below it the
#: error estimate is rounding noise and the step control stalls).
INTEGRATION_FLOOR = 1e-13
#: A coarse solution's motor torque may exceed the pull-out torque by this share before the
#: load is refused: its torque is off by about rtol / slip (1e-6 / 0.03), far less.
PULL_OUT_MARGIN = 1e-3
#: The reduced inertia must stay above this fraction of its maximum (it vanishes only
#: at a dead position of a machine without crank and drive inertia: no solution there).
INERTIA_FLOOR = 1e-6


# --- the periodic solution -------------------------------------------------------


@dataclass(frozen=True)
class _Stroke:
    """One stroke: its crank-angle span (unwrapped) and the spline of (I, I', M_load + M_gravity)."""

    start: float
    travel: float
    spline: CubicSpline

    @cached_property
    def at(self) -> Callable[[float], tuple[float, float, float]]:
        """The spline at one crank angle in plain floats: its own cubic pieces by Horner's rule
        (scipy's call checks its argument for some 10 µs, and the integration asks for every
        right-hand side); made once per stroke for all the shots."""
        breaks = self.spline.x.tolist()
        # [piece][c3, c2, c1, c0 of each column in turn], one flat row a piece (one unpacking a call);
        # a contiguous copy first: tolist walks it in a third of the time
        c = self.spline.c
        pieces = np.ascontiguousarray(np.transpose(c, (1, 2, 0))).reshape(c.shape[1], -1).tolist()
        last = len(pieces) - 1

        def at(theta: float) -> tuple[float, float, float]:
            i = bisect_right(breaks, theta) - 1
            if i < 0:
                i = 0
            elif i > last:
                i = last
            x = theta - breaks[i]
            a3, a2, a1, a0, b3, b2, b1, b0, c3, c2, c1, c0 = pieces[i]
            return (((a3 * x + a2) * x + a1) * x + a0, ((b3 * x + b2) * x + b1) * x + b0,
                    ((c3 * x + c2) * x + c1) * x + c0)

        return at

    def rhs(self, a_u: float, b_u2: float) -> Callable[[float, Sequence[float]], tuple[float, float, float]]:
        """The equation of motion over this stroke ([SK8Rotation2013] eqs. 27 and 29) for the
        drive torque a_u + b_u2 omega: (d(omega)/dtheta, dt/dtheta, dE/dtheta) at crank angle
        theta and state (omega, t, E)."""
        at = self.at

        def rhs(theta: float, y: Sequence[float]) -> tuple[float, float, float]:
            inertia, rate, torque = at(theta)
            w = y[0]
            drive = a_u + b_u2 * w
            return (drive - torque - 0.5 * w * w * rate) / (inertia * w), 1.0 / w, drive

        return rhs


@dataclass(frozen=True)
class Convergence:
    """How the shooting went.

    Attributes
    ----------
    start_speeds : tuple of float
        Start speeds omega_0 tried [1/s].
    residuals : tuple of float
        Their residuals omega_end - omega_0 [1/s].
    rtol : float
        Relative tolerance of the integration and of the periodicity (dimensionless).
    evaluations : int
        Right-hand-side evaluations of the integrator.
    """

    start_speeds: tuple[float, ...]
    residuals: tuple[float, ...]
    rtol: float
    evaluations: int

    @property
    def iterations(self) -> int:
        """Number of shots (start speeds tried)."""
        return len(self.start_speeds)

    @property
    def periodicity_error(self) -> float:
        """|omega_end - omega_start| / omega_start of the accepted solution (dimensionless)."""
        return abs(self.residuals[-1]) / self.start_speeds[-1]


@dataclass(frozen=True)
class DynamicsSummary:
    """Scalar results of the periodic solution.

    Attributes
    ----------
    start_speed : float
        omega_1 at the start of the upstroke [1/s].
    mean_speed : float
        2 pi / period [1/s].
    max_speed, min_speed : Extreme
        omega_1 [1/s] at crank angle [rad].
    speed_fluctuation : float
        delta = (omega_max - omega_min) / omega_mean (dimensionless).
    max_acceleration, min_acceleration : Extreme
        epsilon_1 [1/s²] at [rad].
    max_motor_torque, min_motor_torque : Extreme
        At the motor shaft [N·m] at [rad].
    max_power, min_power : Extreme
        Motor power [W] at [rad].
    period : float
        Cycle time [s].
    energy_per_cycle : float
        Motor energy per cycle [J].
    rod_work_per_cycle : float
        Cycle work of M_load + M_gravity [J].
    rated_crank_speed : float
        omega_n / u [1/s].
    constant_inertia : float
        Constant part of the reduced inertia [kg·m²].
    peak_static_torque : Extreme
        Largest M_load + M_gravity [N·m] at [rad].
    starting_torque : float
        Motor starting torque reduced to the crank [N·m].
    breakdown_torque_margin : float
        Pull-out torque / peak motor torque (dimensionless).
    convergence : Convergence
        The shooting record.

    References
    ----------
    [SK8Rotation2013].
    """

    start_speed: float
    mean_speed: float
    max_speed: Extreme
    min_speed: Extreme
    speed_fluctuation: float
    max_acceleration: Extreme
    min_acceleration: Extreme
    max_motor_torque: Extreme
    min_motor_torque: Extreme
    max_power: Extreme
    min_power: Extreme
    period: float
    energy_per_cycle: float
    rod_work_per_cycle: float
    rated_crank_speed: float
    constant_inertia: float
    peak_static_torque: Extreme
    starting_torque: float
    breakdown_torque_margin: float
    convergence: Convergence

    @property
    def mean_power(self) -> float:
        """Mean motor power over the cycle, energy per cycle / cycle time [W]."""
        return self.energy_per_cycle / self.period


@dataclass(frozen=True)
class SteadyState:
    """Per-crank-angle periodic motion of the unit (arrays on ``crank_angle``).

    Attributes
    ----------
    crank_angle : numpy.ndarray
        theta [rad].
    time : numpy.ndarray
        From crank angle 0 [s].
    omega, epsilon : numpy.ndarray
        Crank speed [1/s] and acceleration [1/s²].
    motor_speed, motor_torque, power : numpy.ndarray
        At the motor shaft [rad/s], [N·m], [W].
    rod_load : numpy.ndarray
        P [N].
    rod_load_torque, gravity_torque : numpy.ndarray
        M_load, M_gravity [N·m].
    reduced_inertia, reduced_inertia_rate : numpy.ndarray
        I [kg·m²], dI/dtheta [kg·m²/rad].
    inertia_torque : numpy.ndarray
        I epsilon + 1/2 I' omega^2 [N·m], the torque spent on accelerating the moving
        masses (the d'Alembert inertia moment on the crank shaft is its negative).
    constant_inertia_torque : numpy.ndarray
        I_const epsilon [N·m] (M_i1 of [SK8Rotation2013]).
    rod : RodMotion
        Polished-rod motion with this rotation [m, m/s, m/s²].
    rod_uniform : RodMotion
        The same with uniform rotation at the rated crank speed.
    summary : DynamicsSummary
        Extremes, energies and the motor checks.
    """

    crank_angle: np.ndarray
    time: np.ndarray
    crank_speed: np.ndarray
    crank_acceleration: np.ndarray
    motor_speed: np.ndarray
    motor_torque: np.ndarray
    power: np.ndarray
    rod_load: np.ndarray
    rod_load_torque: np.ndarray
    gravity_torque: np.ndarray
    reduced_inertia: np.ndarray
    reduced_inertia_rate: np.ndarray
    inertia_torque: np.ndarray
    constant_inertia_torque: np.ndarray
    rod: RodMotion
    rod_uniform: RodMotion
    summary: DynamicsSummary


def _strokes(machine: Machine, dead: DeadPositions) -> tuple[_Stroke, _Stroke]:
    """Tabulate the coefficients exactly over each stroke and spline them."""
    from scipy.interpolate import CubicSpline

    strokes = []
    for start, travel, upstroke in ((dead.crank_angle_bottom, dead.upstroke_crank_travel, True),
                                    (dead.crank_angle_top, dead.downstroke_crank_travel, False)):
        theta = start + np.linspace(0.0, travel, max(64, int(np.ceil(TABLE_STEPS * travel / (2.0 * np.pi)))) + 1)
        r = coefficients(machine, theta, np.full(theta.shape, upstroke))
        bad = ~(r.inertia > INERTIA_FLOOR * np.max(np.abs(r.inertia))) | ~np.isfinite(r.inertia)
        if np.any(bad):
            i = int(np.argmax(bad))
            raise DynamicsError(
                f"the reduced moment of inertia is {r.inertia[i]:.6g} kg·m² at crank angle "
                f"{np.degrees(theta[i]) % 360:.2f}°; it must stay positive (the drive and the crank need inertia): "
                f"check the masses, inertias and drive inertias"
            )
        table = np.stack([r.inertia, r.inertia_rate, r.rod_load_torque + r.gravity_torque], axis=1)
        if not np.all(np.isfinite(table)):
            raise DynamicsError("the load or gravity torque is not finite; check the unit data")
        strokes.append(_Stroke(start, travel, CubicSpline(theta, table)))
    return strokes[0], strokes[1]


def _cycle_work(strokes: tuple[_Stroke, _Stroke]) -> float:
    """Work of M_load + M_gravity over the cycle [J]: the splines integrated exactly.

    Gravity's share is zero (the potential energy is periodic), so this is the work the
    polished-rod load takes from the unit, the cycle integral of P ds.
    """
    return sum(float(s.spline.integrate(s.start, s.start + s.travel)[2]) for s in strokes)


class _Shooter:
    """Integrates one cycle from the start of the upstroke for a given start speed."""

    def __init__(self, machine: Machine, strokes: tuple[_Stroke, _Stroke], rtol: float, scale: float, energy: float):
        self.machine, self.strokes, self.rtol = machine, strokes, rtol
        self.integration_rtol = max(INTEGRATION_SHARE * rtol, INTEGRATION_FLOOR)
        self.atol = [self.integration_rtol * a for a in (scale, 2.0 * np.pi / scale, max(abs(energy), 1.0))]
        self.floor = STALL_FRACTION * scale
        self.evaluations = 0
        a_u, b_u2 = machine.motor.a * machine.drive_ratio, machine.motor.b * machine.drive_ratio**2
        self.rhs = [stroke.rhs(a_u, b_u2) for stroke in strokes]

    def run(self, omega0: float):
        """States (omega, t, E) at the end of the cycle and the two strokes' dense solutions."""
        floor = self.floor
        y = [omega0, 0.0, 0.0]
        solutions = []
        for stroke, rhs in zip(self.strokes, self.rhs):
            try:
                sol = integrate(rhs, stroke.start, stroke.start + stroke.travel, y, self.integration_rtol, self.atol,
                                event=lambda theta, y: y[0] - floor)
            except DynamicsError as e:
                raise DynamicsError(f"integration failed from omega1 = {omega0:.6g} 1/s: {e}") from None
            self.evaluations += sol.evaluations
            if sol.stopped_at is not None:
                raise DynamicsError(
                    f"the crank stalls (omega1 below {floor:.3g} 1/s at crank angle "
                    f"{np.degrees(sol.stopped_at) % 360:.1f}°) when the upstroke starts at {omega0:.6g} 1/s: "
                    f"the motor cannot turn the unit"
                )
            y = sol.end
            solutions.append(sol.trajectory)
        return y, solutions


def _shoot(shooter: _Shooter, guess: float, max_iterations: int):
    """Secant iteration on R(omega_0) = omega_end - omega_0, starting with one fixed-point step."""
    speeds, residuals = [], []
    x = guess
    for _ in range(max_iterations):
        end, solutions = shooter.run(x)
        speeds.append(x)
        residuals.append(end[0] - x)
        if abs(residuals[-1]) <= shooter.rtol * x:
            return end, solutions, Convergence(tuple(speeds), tuple(residuals), shooter.rtol, shooter.evaluations)
        if len(speeds) == 1 or residuals[-1] == residuals[-2]:
            step = residuals[-1]
        else:
            step = -residuals[-1] * (speeds[-1] - speeds[-2]) / (residuals[-1] - residuals[-2])
        x = max(x + step, 0.5 * x)
    tried = ", ".join(f"{w:.10g}" for w in speeds[-4:])
    misses = ", ".join(f"{r:.3g}" for r in residuals[-4:])
    raise DynamicsError(
        f"the periodic solution did not converge in {max_iterations} secant iterations of the shooting "
        f"(last start speeds {tried} 1/s, end - start {misses} 1/s, rtol {shooter.rtol:g}); "
        f"loosen --rtol or check the unit data"
    )


def _evaluate(strokes: tuple[_Stroke, _Stroke], solutions, theta: np.ndarray) -> np.ndarray:
    """States (omega, t, E) at crank angles [rad] (any order), shape (3, N)."""
    out = np.empty((3, theta.size))
    up = _upstroke_mask(strokes, theta)
    for stroke, sol, mask in zip(strokes, solutions, (up, ~up)):
        if not mask.any():
            continue
        local = stroke.start + (theta[mask] - stroke.start) % (2.0 * np.pi)
        out[:, mask] = sol(np.minimum(local, stroke.start + stroke.travel))
    return out


def _upstroke_mask(strokes: tuple[_Stroke, _Stroke], theta: np.ndarray) -> np.ndarray:
    up = strokes[0]
    return (theta - up.start) % (2.0 * np.pi) <= up.travel


def steady_state(machine: Machine, crank_angle: np.ndarray | None = None, *, rtol: float = DEFAULT_RTOL,
                 max_iterations: int = MAX_ITERATIONS) -> SteadyState:
    """The periodic motion of the unit under its motor, load and weights.

    Integrates, over the upstroke and then the downstroke,

        d(omega)/dtheta = (M_drive - M_load - M_gravity - 1/2 omega^2 I') / (I omega),
        dt/dtheta = 1/omega,

    and finds the start speed omega_0 with omega_end = omega_0 by secant iteration from
    the mean speed of the energy balance, <omega>_theta = (E / 2 pi - a u) / (b u^2).

    Parameters
    ----------
    machine : Machine
        The unit, its drive and its rod load (SI).
    crank_angle : numpy.ndarray, optional
        Where to report [rad] (default 360 steps from 0).
    rtol : float
        Relative tolerance of the integration and of the periodicity
        |omega_end - omega_0| <= rtol omega_0 (dimensionless), 1e-13 to 1e-3.
    max_iterations : int
        Bound on the secant iterations.

    Returns
    -------
    SteadyState
        The periodic motion [rad, s, 1/s, 1/s², N·m, W, kg·m²] and its summary.

    Raises
    ------
    DynamicsError
        ``rtol`` out of range, a non-positive reduced inertia, a load the motor cannot
        carry (stall, or a torque beyond its pull-out torque), a load that takes energy
        out of the unit over a cycle, or a shooting that does not converge in
        ``max_iterations``.

    References
    ----------
    [SK8Rotation2013] eqs. 1, 27 and 29 (the equation of motion and its periodic
    solution); [Artobolevsky1951].
    """
    if not 1e-13 <= rtol <= 1e-3:
        raise DynamicsError(f"rtol {rtol:g} is outside 1e-13 .. 1e-3")
    theta_out = crank_grid(360) if crank_angle is None else np.asarray(crank_angle, dtype=float)
    dead = machine.linkage.dead_positions()
    strokes = _strokes(machine, dead)
    work = _cycle_work(strokes)
    if not work > 0:
        raise DynamicsError(
            f"the polished-rod load does {-work:.6g} J of work on the unit per cycle instead of taking work from "
            f"it: the card does not fit this unit (strokes swapped, or another unit's card?)"
        )
    a_u, b_u2 = machine.motor.a * machine.drive_ratio, machine.motor.b * machine.drive_ratio**2
    guess = (work / (2.0 * np.pi) - a_u) / b_u2
    if not guess > 0:
        raise DynamicsError(
            f"the load needs a mean crank torque of {work / (2 * np.pi):.6g} N·m, more than the motor's linear "
            f"characteristic gives even at standstill ({a_u:.6g} N·m at the crank): the motor is too weak"
        )
    if rtol < COARSE_RTOL:
        _, coarse, _ = _shoot(_Shooter(machine, strokes, COARSE_RTOL, guess, work), guess, max_iterations)
        theta = crank_grid(SUMMARY_STEPS)
        motor = np.asarray(machine.drive_torque(_evaluate(strokes, coarse, theta)[0])) / machine.drive_ratio
        _check_pull_out(machine, theta, motor, 1.0 + PULL_OUT_MARGIN)
    shooter = _Shooter(machine, strokes, rtol, guess, work)
    end, solutions, convergence = _shoot(shooter, guess, max_iterations)
    period = float(end[1])

    def at(theta: np.ndarray):
        states = _evaluate(strokes, solutions, theta)
        r = coefficients(machine, theta, _upstroke_mask(strokes, theta))
        omega = states[0]
        drive = machine.drive_torque(omega)
        epsilon = (drive - r.rod_load_torque - r.gravity_torque - 0.5 * omega**2 * r.inertia_rate) / r.inertia
        return states, r, omega, epsilon, drive

    states, r, omega, epsilon, drive = at(theta_out)
    time_zero = _evaluate(strokes, solutions, np.zeros(1))[1, 0]
    m = r.motion
    u = machine.drive_ratio
    motor_speed = u * omega
    motor_torque = drive / u
    rod = rod_motion(m, omega, epsilon)
    rod_uniform = rod_motion(m, machine.rated_crank_speed)
    summary = _summary(machine, strokes, solutions, at, period, float(end[2]), work, convergence)
    return SteadyState(
        crank_angle=theta_out,
        time=(states[1] - time_zero) % period,
        crank_speed=omega,
        crank_acceleration=epsilon,
        motor_speed=motor_speed,
        motor_torque=motor_torque,
        power=motor_torque * motor_speed,
        rod_load=r.rod_load,
        rod_load_torque=r.rod_load_torque,
        gravity_torque=r.gravity_torque,
        reduced_inertia=r.inertia,
        reduced_inertia_rate=r.inertia_rate,
        inertia_torque=r.inertia * epsilon + 0.5 * r.inertia_rate * omega**2,
        constant_inertia_torque=machine.constant_inertia * epsilon,
        rod=rod,
        rod_uniform=rod_uniform,
        summary=summary,
    )


def _check_pull_out(machine: Machine, theta: np.ndarray, torque: np.ndarray, margin: float = 1.0) -> float:
    """The largest |motor torque| [N·m] over the crank angles [rad]; a DynamicsError when it is
    beyond ``margin`` times the motor's pull-out torque (the linear characteristic's limit)."""
    motor = machine.motor
    t_max, t_min = extremes(theta, torque)
    peak = max(t_max.value, -t_min.value)
    if peak > margin * motor.breakdown_torque:
        where = t_max if t_max.value >= -t_min.value else t_min
        raise DynamicsError(
            f"the motor is too weak: the load needs {where.value:.1f} N·m at the motor shaft "
            f"({where.value / motor.rated_torque:.2f} x rated) at crank angle {np.degrees(where.crank_angle):.1f}°, "
            f"more than its pull-out torque {motor.breakdown_torque:.1f} N·m "
            f"({motor.breakdown_torque / motor.rated_torque:.2f} x rated {motor.rated_torque:.1f} N·m)"
        )
    return peak


def _summary(machine: Machine, strokes, solutions, at, period: float, energy: float, work: float,
             convergence: Convergence) -> DynamicsSummary:
    """Extremes on a dense grid, energies, and the motor checks (pull-out is an error)."""
    theta = crank_grid(SUMMARY_STEPS)
    _, r, omega, epsilon, drive = at(theta)
    motor = machine.motor
    u = machine.drive_ratio
    torque = drive / u
    power = torque * u * omega
    w_max, w_min = extremes(theta, omega)
    e_max, e_min = extremes(theta, epsilon)
    p_max, p_min = extremes(theta, power)
    t_max, t_min = extremes(theta, torque)
    static_max, _ = extremes(theta, r.rod_load_torque + r.gravity_torque)
    peak = _check_pull_out(machine, theta, torque)
    mean = 2.0 * np.pi / period
    return DynamicsSummary(
        start_speed=convergence.start_speeds[-1],
        mean_speed=mean,
        max_speed=w_max,
        min_speed=w_min,
        speed_fluctuation=(w_max.value - w_min.value) / mean,
        max_acceleration=e_max,
        min_acceleration=e_min,
        max_motor_torque=t_max,
        min_motor_torque=t_min,
        max_power=p_max,
        min_power=p_min,
        period=period,
        energy_per_cycle=energy,
        rod_work_per_cycle=work,
        rated_crank_speed=machine.rated_crank_speed,
        constant_inertia=machine.constant_inertia,
        peak_static_torque=static_max,
        starting_torque=motor.starting_torque * u,
        breakdown_torque_margin=motor.breakdown_torque / peak,
        convergence=convergence,
    )
