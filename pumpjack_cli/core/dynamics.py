"""Non-uniform crank rotation: the equation of motion of the unit reduced to the crank shaft.

Seed 004 eq. 1 (Lagrange's equation of a one-degree-of-freedom machine, with the
crank angle theta as generalised coordinate; Artobolevsky, Teoriya mekhanizmov i
mashin, 1951, ref. [2] of seed 004):

    I(theta) d(omega)/dt + 1/2 omega^2 dI/dtheta = M_drive(omega) - M_load(theta) - M_gravity(theta)

* I, the reduced moment of inertia (kinetic energy T = 1/2 I omega^2), seed 004 eq. 9:
  the drive (motor rotor, sheaves, gearbox) and the crank with its counterweights
  (constant), the pitmans, the beam with horsehead and equalizer, and the masses moving
  with the polished rod (rods, and the fluid on the upstroke only);
* M_drive = (a + b u omega) u, the motor's linear working characteristic reduced to
  the crank through the total ratio u (seed 004 eqs. 25-26);
* M_load = P(theta) TF(theta): polished-rod load times the torque factor A psi'
  (seed 004 eqs. 19-23; P from :mod:`.well` or from a dynamometer card);
* M_gravity = dV/dtheta: derivative of the potential energy of crank arms,
  counterweights, pitmans, beam, horsehead and equalizer (seed 004 eq. 18).

The positions and transfer functions (psi', psi'', chi', chi'') come from the exact
closed form of :mod:`.linkage`, for whole arrays of crank angles. The equation is
integrated in the crank angle, d(omega)/dtheta = (M_drive - M_load - M_gravity -
1/2 omega^2 I')/(I omega), dt/dtheta = 1/omega, over the upstroke and then the
downstroke (seed 004 eqs. 27 and 29), with scipy's DOP853 at a relative tolerance
``rtol`` and absolute tolerances rtol x the scale of each state. The coefficients I,
I' and M_load + M_gravity are tabulated exactly on 4096 crank angles per revolution
and interpolated by cubic splines within each stroke (error ~1e-11 relative, below
the default rtol = 1e-10), which makes one periodic solve take milliseconds.

Periodic steady state (seed 004): the speed omega_0 at the start of the upstroke is
the root of R(omega_0) = omega_end(omega_0) - omega_0, found by secant iteration from
the mean speed of the energy balance (a u + b u^2 <omega>_theta = E / 2 pi).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from ..errors import DynamicsError
from .card import Card, card_load
from .kinematics import Extreme, RodMotion, extremes, crank_grid, rod_motion
from .kinetostatics import STANDARD_GRAVITY, MassModel
from .linkage import DeadPositions, Linkage, Motion, dead_positions, motion

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
#: The reduced inertia must stay above this fraction of its maximum (it vanishes only
#: at a dead position of a machine without crank and drive inertia: no solution there).
INERTIA_FLOOR = 1e-6


class RodLoad(Protocol):
    """Polished-rod load [N] by crank angle and stroke direction, and the masses [kg]
    that move with the polished rod on each stroke (they enter the reduced inertia)."""

    mass_upstroke: float
    mass_downstroke: float

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray: ...


@dataclass(frozen=True)
class CardLoad:
    """Polished-rod load from a dynamometer card.

    A measured card already holds the weights of rods and fluid, friction and the rods'
    inertia, so no mass moves with the polished rod in the reduced inertia.
    """

    card: Card
    mass_upstroke: float = 0.0
    mass_downstroke: float = 0.0

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
        return card_load(self.card, crank_angle)


@dataclass(frozen=True)
class MotorCharacteristic:
    """Linear working branch M = a + b omega of an induction motor, at the motor shaft.

    a [N·m], b [N·m·s]; torques [N·m] and speeds [rad/s] of the nameplate.
    """

    a: float
    b: float
    rated_torque: float
    starting_torque: float
    breakdown_torque: float
    synchronous_speed: float
    rated_speed: float

    def torque(self, speed: np.ndarray | float) -> np.ndarray | float:
        """Motor torque [N·m] at motor speed [rad/s] on the linear branch."""
        return self.a + self.b * speed


def motor_characteristic(rated_power: float, synchronous_speed: float, rated_speed: float,
                         starting_torque_ratio: float, breakdown_torque_ratio: float) -> MotorCharacteristic:
    """The straight line through (synchronous speed, 0) and (rated speed, rated torque).

    Seed 004 eq. 25 with speeds n in rpm: a = M_n n_s / (n_s - n_n),
    b = -30 M_n / (pi (n_s - n_n)), M_n = P / omega_n; in rad/s the same line is
    a = M_n w_s / (w_s - w_n), b = -M_n / (w_s - w_n). rated_power P [W]; speeds [rad/s].

    Motor 4AR180M4U3 of seed 004 (30 kW, 1500/1460 rpm): M_n = 30000 / (1460 pi/30)
    = 196.22 N·m, a = 196.22 · 1500/40 = 7358.2 N·m, b = -30 · 196.22 / (40 pi) = -46.84 N·m·s.

    >>> rpm = np.pi / 30
    >>> m = motor_characteristic(30e3, 1500 * rpm, 1460 * rpm, 2.0, 2.2)
    >>> round(m.rated_torque, 2), round(m.a, 1), round(m.b, 2)
    (196.22, 7358.2, -46.84)
    """
    if not 0 < rated_speed < synchronous_speed:
        raise DynamicsError(f"motor rated speed {rated_speed:.6g} rad/s must lie between 0 and the "
                            f"synchronous speed {synchronous_speed:.6g} rad/s")
    rated_torque = rated_power / rated_speed
    slip_speed = synchronous_speed - rated_speed
    return MotorCharacteristic(
        a=rated_torque * synchronous_speed / slip_speed,
        b=-rated_torque / slip_speed,
        rated_torque=rated_torque,
        starting_torque=starting_torque_ratio * rated_torque,
        breakdown_torque=breakdown_torque_ratio * rated_torque,
        synchronous_speed=synchronous_speed,
        rated_speed=rated_speed,
    )


def drive_inertia(motor_shaft: float, gearbox_input: float, crank_shaft: float,
                  belt_ratio: float, gearbox_ratio: float) -> float:
    """Moment of inertia of the drive reduced to the crank shaft [kg·m^2].

    Equal kinetic energy (Artobolevsky 1951, reduction of masses): a part turning u_k
    times faster than the crank counts u_k^2 times, so
    I = J_motor (u_b u_r)^2 + J_gearbox_input u_r^2 + J_crank_shaft, with J_motor the
    rotor and motor sheave, J_gearbox_input the driven sheave and the gearbox parts
    referred to its input shaft, belt_ratio u_b, gearbox_ratio u_r.

    Seed 004's rotor alone (0.232 kg·m^2, u = 37.18 · 900/250):

    >>> round(drive_inertia(0.232, 0.0, 0.0, 3.6, 37.18), 1)
    4156.3
    """
    return motor_shaft * (belt_ratio * gearbox_ratio) ** 2 + gearbox_input * gearbox_ratio**2 + crank_shaft


@dataclass(frozen=True)
class Machine:
    """Everything the equation of motion needs, SI.

    linkage: the planar four-bar; masses: the moving links (per arm / per pitman, as
    :class:`~.kinetostatics.MassModel`); drive_inertia [kg·m^2]: rotor, sheaves and
    gearbox reduced to the crank shaft (:func:`drive_inertia`); drive_ratio u: motor
    speed / crank speed; motor: its characteristic at the motor shaft; rod_load: the
    polished-rod load model (:class:`~.well.WellLoad` or :class:`CardLoad`).
    """

    linkage: Linkage
    masses: MassModel
    drive_inertia: float
    drive_ratio: float
    motor: MotorCharacteristic
    rod_load: RodLoad
    gravity: float = STANDARD_GRAVITY

    @property
    def crank_inertia(self) -> float:
        """Both crank arms and all counterweights about the shaft [kg·m^2] (parallel axes)."""
        m = self.masses
        return 2.0 * (m.crank_arm_inertia + m.crank_arm_mass * m.crank_arm_cg**2) + \
            m.counterweight_mass * m.counterweight_radius**2

    @property
    def constant_inertia(self) -> float:
        """The constant part of the reduced inertia, I_0 + I_dr + m_pr r_pr^2 of seed 004 eq. 9 [kg·m^2]."""
        return self.drive_inertia + self.crank_inertia

    @property
    def rated_crank_speed(self) -> float:
        """omega_1 = omega_n / u [1/s] (seed 004: pi n_n / (30 u_r u_belt))."""
        return self.motor.rated_speed / self.drive_ratio

    def drive_torque(self, omega: np.ndarray | float) -> np.ndarray | float:
        """Motor torque reduced to the crank, (a + b u omega) u [N·m] (seed 004 eq. 26)."""
        return self.motor.torque(self.drive_ratio * omega) * self.drive_ratio


@dataclass(frozen=True)
class Coefficients:
    """The coefficients of the equation of motion at given crank angles (arrays).

    inertia I [kg·m^2] and inertia_rate dI/dtheta [kg·m^2/rad]; gravity_torque
    M_gravity, load_torque M_load = P TF [N·m]; rod_load P [N]; torque_factor TF [m];
    upstroke mask; the four-bar motion.
    """

    inertia: np.ndarray
    inertia_rate: np.ndarray
    gravity_torque: np.ndarray
    load_torque: np.ndarray
    rod_load: np.ndarray
    torque_factor: np.ndarray
    upstroke: np.ndarray
    motion: Motion


def _pitman_cg_derivatives(linkage: Linkage, masses: MassModel, m: Motion) -> tuple[np.ndarray, np.ndarray]:
    """dS/dtheta and d2S/dtheta2 of the pitman's centre of mass S = (1 - f) A + f B, f = AS / P.

    A = O + R (s sin theta, cos theta) (crank pin), B = -C (cos psi, sin psi) (equalizer
    bearing); differentiated with psi(theta) from the four-bar. Shape (2, N) each [m/rad, m/rad^2].
    """
    theta, psi, d1, d2 = m.crank_angle, m.beam_angle, m.beam_rate, m.beam_rate2
    r, c, s = linkage.crank_radius, linkage.rear_arm, linkage.rotation
    f = masses.pitman_cg / linkage.pitman
    a1 = r * np.stack([s * np.cos(theta), -np.sin(theta)])
    a2 = -r * np.stack([s * np.sin(theta), np.cos(theta)])
    across = np.stack([np.sin(psi), -np.cos(psi)])
    along = np.stack([np.cos(psi), np.sin(psi)])
    b1 = c * d1 * across
    b2 = c * (d2 * across + d1**2 * along)
    return (1.0 - f) * a1 + f * b1, (1.0 - f) * a2 + f * b2


def reduced_inertia(linkage: Linkage, masses: MassModel, m: Motion, rod_mass: np.ndarray | float,
                    constant: float) -> tuple[np.ndarray, np.ndarray]:
    """Reduced moment of inertia I(theta) [kg·m^2] and dI/dtheta (seed 004 eq. 9).

    I = constant + 2 [m_2 |dS_2/dtheta|^2 + J_2 chi'^2] + I_C psi'^2 + m_rod (A psi')^2,
    with the two pitmans (mass m_2, centroidal inertia J_2, centre S_2), the beam group
    about the centre bearing I_C = J_beam + m_beam x_beam^2 + J_head + m_head x_head^2
    + J_eq + m_eq C^2 (equalizer at D, turning with the beam), and rod_mass [kg] the
    mass moving with the polished rod. constant [kg·m^2]: drive, crank arms and
    counterweights. dI/dtheta differentiates each square: d(x^2)/dtheta = 2 x x'.
    """
    s1, s2 = _pitman_cg_derivatives(linkage, masses, m)
    beam = (masses.beam_inertia + masses.beam_mass * masses.beam_cg**2
            + masses.horsehead_inertia + masses.horsehead_mass * masses.horsehead_cg**2
            + masses.equalizer_inertia + masses.equalizer_mass * linkage.rear_arm**2)
    rod = rod_mass * linkage.front_arm**2
    inertia = (constant + 2.0 * (masses.pitman_mass * np.sum(s1 * s1, axis=0) + masses.pitman_inertia * m.pitman_rate**2)
               + (beam + rod) * m.beam_rate**2)
    rate = (4.0 * (masses.pitman_mass * np.sum(s1 * s2, axis=0) + masses.pitman_inertia * m.pitman_rate * m.pitman_rate2)
            + 2.0 * (beam + rod) * m.beam_rate * m.beam_rate2)
    return inertia, rate


def gravity_torque(linkage: Linkage, masses: MassModel, m: Motion, gravity: float = STANDARD_GRAVITY) -> np.ndarray:
    """M_gravity = dV/dtheta [N·m] of all links (seed 004 eq. 18).

    V = g [2 m_1 r_1 cos theta + m_cw r_cw cos(theta + phase) + 2 m_2 y_S2
    + (m_beam x_beam + m_head x_head - m_eq C) sin psi]: crank arms and counterweights at
    their radii (heights from the shaft), pitmans at their centres, the beam group on
    the beam line (equalizer at D, a distance C behind the centre bearing).
    """
    theta = m.crank_angle
    s1, _ = _pitman_cg_derivatives(linkage, masses, m)
    beam_moment = (masses.beam_mass * masses.beam_cg + masses.horsehead_mass * masses.horsehead_cg
                   - masses.equalizer_mass * linkage.rear_arm)
    return gravity * (
        -2.0 * masses.crank_arm_mass * masses.crank_arm_cg * np.sin(theta)
        - masses.counterweight_mass * masses.counterweight_radius * np.sin(theta + masses.counterweight_phase)
        + 2.0 * masses.pitman_mass * s1[1]
        + beam_moment * np.cos(m.beam_angle) * m.beam_rate
    )


def coefficients(machine: Machine, crank_angle: np.ndarray, upstroke: np.ndarray) -> Coefficients:
    """All coefficients of the equation of motion at the given crank angles [rad], one array pass."""
    theta = np.asarray(crank_angle, dtype=float)
    up = np.asarray(upstroke, dtype=bool)
    m = motion(machine.linkage, theta)
    load = machine.rod_load
    rod_mass = np.where(up, load.mass_upstroke, load.mass_downstroke)
    inertia, rate = reduced_inertia(machine.linkage, machine.masses, m, rod_mass, machine.constant_inertia)
    tf = machine.linkage.front_arm * m.beam_rate
    force = np.asarray(load.force(theta, up), dtype=float)
    return Coefficients(
        inertia=inertia,
        inertia_rate=rate,
        gravity_torque=gravity_torque(machine.linkage, machine.masses, m, machine.gravity),
        load_torque=force * tf,
        rod_load=force,
        torque_factor=tf,
        upstroke=up,
        motion=m,
    )


def mean_rod_speeds(linkage: Linkage, omega: float) -> tuple[float, float]:
    """Mean polished-rod speeds [m/s] of the upstroke and the downstroke at uniform crank speed omega [1/s]:
    stroke / time of the stroke, the time being the stroke's crank travel / omega."""
    dead = dead_positions(linkage)
    stroke = linkage.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom)
    up = (dead.crank_angle_top - dead.crank_angle_bottom) % (2.0 * np.pi)
    return stroke * omega / up, stroke * omega / (2.0 * np.pi - up)


# --- the periodic solution -------------------------------------------------------


@dataclass(frozen=True)
class _Stroke:
    """One stroke: its crank-angle span (unwrapped) and the spline of (I, I', M_load + M_gravity)."""

    start: float
    travel: float
    spline: object


@dataclass(frozen=True)
class Convergence:
    """How the shooting went: start speeds tried [1/s] and their residuals
    omega_end - omega_start [1/s], integrator tolerances and right-hand-side evaluations."""

    start_speeds: tuple[float, ...]
    residuals: tuple[float, ...]
    rtol: float
    evaluations: int

    @property
    def iterations(self) -> int:
        return len(self.start_speeds)

    @property
    def periodicity_error(self) -> float:
        """|omega_end - omega_start| / omega_start of the accepted solution."""
        return abs(self.residuals[-1]) / self.start_speeds[-1]


@dataclass(frozen=True)
class DynamicsSummary:
    """Scalar results of the periodic solution (SI, angles in rad)."""

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


@dataclass(frozen=True)
class SteadyState:
    """Per-crank-angle periodic motion of the unit (SI, arrays on ``crank_angle``).

    time from crank angle 0; omega, epsilon: crank speed [1/s] and acceleration
    [1/s^2]; motor_speed [rad/s], motor_torque [N·m], power [W] at the motor shaft;
    load_torque M_load and gravity_torque M_gravity [N·m]; inertia_torque
    I epsilon + 1/2 I' omega^2 [N·m], the torque spent on accelerating the moving
    masses (the d'Alembert inertia moment on the crank shaft is its negative);
    constant_inertia_torque I_const epsilon (seed 004's M_i1); rod: polished-rod motion
    with this rotation, rod_uniform: with uniform rotation at the rated crank speed.
    """

    crank_angle: np.ndarray
    time: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    motor_speed: np.ndarray
    motor_torque: np.ndarray
    power: np.ndarray
    rod_load: np.ndarray
    load_torque: np.ndarray
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

    up_travel = (dead.crank_angle_top - dead.crank_angle_bottom) % (2.0 * np.pi)
    strokes = []
    for start, travel, upstroke in ((dead.crank_angle_bottom, up_travel, True),
                                    (dead.crank_angle_top, 2.0 * np.pi - up_travel, False)):
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
        table = np.stack([r.inertia, r.inertia_rate, r.load_torque + r.gravity_torque], axis=1)
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
        self.atol = rtol * np.array([scale, 2.0 * np.pi / scale, max(abs(energy), 1.0)])
        self.floor = STALL_FRACTION * scale
        self.evaluations = 0

    def run(self, omega0: float):
        """States (omega, t, E) at the end of the cycle and the two strokes' dense solutions."""
        from scipy.integrate import solve_ivp

        machine = self.machine
        a_u, b_u2 = machine.motor.a * machine.drive_ratio, machine.motor.b * machine.drive_ratio**2

        def stalled(theta, y):
            return y[0] - self.floor

        stalled.terminal = True
        y = np.array([omega0, 0.0, 0.0])
        solutions = []
        for stroke in self.strokes:
            spline = stroke.spline

            def rhs(theta, y, spline=spline):
                inertia, rate, torque = spline(theta)
                w = y[0]
                drive = a_u + b_u2 * w
                return [(drive - torque - 0.5 * w * w * rate) / (inertia * w), 1.0 / w, drive]

            sol = solve_ivp(rhs, (stroke.start, stroke.start + stroke.travel), y, method="DOP853",
                            rtol=self.rtol, atol=self.atol, dense_output=True, events=stalled)
            self.evaluations += sol.nfev
            if sol.status == 1:
                raise DynamicsError(
                    f"the crank stalls (omega1 below {self.floor:.3g} 1/s at crank angle "
                    f"{np.degrees(sol.t_events[0][0]) % 360:.1f}°) when the upstroke starts at {omega0:.6g} 1/s: "
                    f"the motor cannot turn the unit"
                )
            if not sol.success:
                raise DynamicsError(f"integration failed from omega1 = {omega0:.6g} 1/s: {sol.message}")
            y = sol.y[:, -1]
            solutions.append(sol)
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
        out[:, mask] = sol.sol(np.minimum(local, stroke.start + stroke.travel))
    return out


def _upstroke_mask(strokes: tuple[_Stroke, _Stroke], theta: np.ndarray) -> np.ndarray:
    up = strokes[0]
    return (theta - up.start) % (2.0 * np.pi) <= up.travel


def steady_state(machine: Machine, crank_angle: np.ndarray | None = None, *, rtol: float = DEFAULT_RTOL,
                 max_iterations: int = MAX_ITERATIONS) -> SteadyState:
    """The periodic motion of the unit under its motor, load and weights.

    crank_angle [rad]: where to report (default 360 steps from 0); rtol: relative
    tolerance of the integration and of the periodicity |omega_end - omega_0| <= rtol
    omega_0. Raises :class:`~pumpjack_cli.errors.DynamicsError` for a non-positive
    reduced inertia, a load the motor cannot carry (stall, or a torque beyond its
    pull-out torque), a load that takes energy out of the unit over a cycle, or a
    shooting that does not converge in ``max_iterations``.
    """
    if not 1e-13 <= rtol <= 1e-3:
        raise DynamicsError(f"rtol {rtol:g} is outside 1e-13 .. 1e-3")
    theta_out = crank_grid(360) if crank_angle is None else np.asarray(crank_angle, dtype=float)
    dead = dead_positions(machine.linkage)
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
    shooter = _Shooter(machine, strokes, rtol, guess, work)
    end, solutions, convergence = _shoot(shooter, guess, max_iterations)
    period = float(end[1])

    def at(theta: np.ndarray):
        states = _evaluate(strokes, solutions, theta)
        r = coefficients(machine, theta, _upstroke_mask(strokes, theta))
        omega = states[0]
        drive = machine.drive_torque(omega)
        epsilon = (drive - r.load_torque - r.gravity_torque - 0.5 * omega**2 * r.inertia_rate) / r.inertia
        return states, r, omega, epsilon, drive

    states, r, omega, epsilon, drive = at(theta_out)
    time_zero = _evaluate(strokes, solutions, np.zeros(1))[1, 0]
    m = r.motion
    u = machine.drive_ratio
    motor_speed = u * omega
    motor_torque = drive / u
    rod = rod_motion(machine.linkage, m.beam_angle, m.beam_rate, m.beam_rate2, dead.beam_angle_bottom, omega, epsilon)
    rod_uniform = rod_motion(machine.linkage, m.beam_angle, m.beam_rate, m.beam_rate2, dead.beam_angle_bottom,
                             machine.rated_crank_speed)
    summary = _summary(machine, strokes, solutions, at, period, float(end[2]), work, convergence)
    return SteadyState(
        crank_angle=theta_out,
        time=(states[1] - time_zero) % period,
        omega=omega,
        epsilon=epsilon,
        motor_speed=motor_speed,
        motor_torque=motor_torque,
        power=motor_torque * motor_speed,
        rod_load=r.rod_load,
        load_torque=r.load_torque,
        gravity_torque=r.gravity_torque,
        reduced_inertia=r.inertia,
        reduced_inertia_rate=r.inertia_rate,
        inertia_torque=r.inertia * epsilon + 0.5 * r.inertia_rate * omega**2,
        constant_inertia_torque=machine.constant_inertia * epsilon,
        rod=rod,
        rod_uniform=rod_uniform,
        summary=summary,
    )


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
    static_max, _ = extremes(theta, r.load_torque + r.gravity_torque)
    peak = max(t_max.value, -t_min.value)
    if peak > motor.breakdown_torque:
        where = t_max if t_max.value >= -t_min.value else t_min
        raise DynamicsError(
            f"the motor is too weak: the load needs {where.value:.1f} N·m at the motor shaft "
            f"({where.value / motor.rated_torque:.2f} x rated) at crank angle {np.degrees(where.crank_angle):.1f}°, "
            f"more than its pull-out torque {motor.breakdown_torque:.1f} N·m "
            f"({motor.breakdown_torque / motor.rated_torque:.2f} x rated {motor.rated_torque:.1f} N·m)"
        )
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
