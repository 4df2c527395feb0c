"""The damped wave equation of a tapered rod string in modal form, for the predictive solver.

The dynamic axial displacement u(x, t) (down positive; x down from the polished rod)
of each taper obeys ``u_tt = a_i^2 u_xx - c u_t`` ([Gibbs1963]), displacement and force
EA u_x continuous at the joints. With the polished rod's dynamic displacement u_top(t)
imposed at x = 0 and the pump's pull F_L(t) at x = L, write
``u = u_top(t) + sum_k phi_k(x) q_k(t)`` over the modes phi_k of the string fixed at the
top and free at the bottom (mass-normalised, int m phi_k phi_j dx = delta_kj, stiffness
omega_k^2). Because the damping is proportional to the mass, the modes decouple
exactly ([Meirovitch1967], modal analysis of continuous systems):

    q_k'' + c q_k' + omega_k^2 q_k = b_k F_L(t) - g_k a(t),
    b_k = phi_k(L),  g_k = int_0^L m phi_k dx,  a = u_top'' + c u_top'.

The modes are exact (cosines and sines per taper, frequencies from the transfer
matrices); the modes above a cut-off omega_cut respond quasi-statically and are kept
as residual compliances and masses (the mode-acceleration method of [Craig2006]): the
plunger displacement is ``u_L = u_top + sum_k b_k q_k + C_rem F_L`` with
C_rem = sum_i L_i/(E_i A_i) - sum_k b_k^2/omega_k^2, and the force at a joint x_j is
the force balance of the rods below it,

    F(x_j) = F_L (1 - sum_k G_kj b_k) - a (m_j - sum_k G_kj g_k) + sum_k G_kj omega_k^2 q_k,

G_kj = int_{x_j}^L m phi_k dx and m_j the mass below x_j. Both sums converge like
(input frequency / omega_cut)^2.

Time stepping: the inputs F_L and a are sampled on a uniform time grid and linear
between samples (hat functions); the complex modal coordinate
eta_k = q_k' - conj(lambda_k) q_k, lambda_k = -c/2 + i omega_dk, obeys
eta' = lambda eta + f(t), whose step is exact for a linear f:
eta(t + h) = e^{lambda h} eta(t) + I0 f(t) + I1 f(t + h). So the response at the samples
is exact for hat-shaped inputs, whatever the step, and q_k = Im(eta_k) / omega_dk,
q_k' = Re(eta_k) - (c/2) q_k.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...errors import PredictionError
from .string import RodString

#: Frequency scan step as a fraction of the mean spacing pi / tau of the modes.
SCAN_FRACTION = 1.0 / 64.0
#: Bisection steps refining each mode frequency (2^-60 of the scan step).
BISECTION_STEPS = 60


@dataclass(frozen=True)
class RodModes:
    """The modes of a tapered string, top fixed and bottom free, and its residuals (SI).

    frequency omega_k [rad/s], damped frequency omega_dk [rad/s], eigenvalue lambda_k
    = -c/2 + i omega_dk [1/s]; bottom value b_k = phi_k(L) [1/sqrt(kg)]; participation
    g_k [sqrt(kg)]; joint participations G[j, k] = int_{x_j}^L m phi_k dx for the
    joints j = 0 (top) .. n (pump) [sqrt(kg)]; mass_below m_j [kg]; damping c [1/s];
    static_compliance sum L_i/(E_i A_i) [m/N]; residual_compliance C_rem [m/N];
    residual_transmission 1 - sum_k G_kj b_k [-] and residual_mass m_j - sum_k G_kj g_k
    [kg] per joint.
    """

    frequency: np.ndarray
    damped_frequency: np.ndarray
    eigenvalue: np.ndarray
    bottom: np.ndarray
    participation: np.ndarray
    joint_participation: np.ndarray
    mass_below: np.ndarray
    damping: float
    static_compliance: float
    residual_compliance: float
    residual_transmission: np.ndarray
    residual_mass: np.ndarray

    @property
    def count(self) -> int:
        return int(self.frequency.size)


def travel_time(rods: RodString) -> float:
    """One-way travel time of a stress wave from the polished rod to the pump, tau = sum L_i / a_i [s]."""
    return float(np.sum(rods.length / rods.wave_speed))


def damping_coefficient(rods: RodString, damping: float) -> float:
    """Gibbs' damping coefficient c = pi a nu / (2 L) [1/s] from the dimensionless factor nu ([Gibbs1963]).

    For a tapered string L / a is the travel time tau = sum L_i / a_i, so c = pi nu / (2 tau);
    nu / 2 is then the damping ratio c / (2 omega_1) of the first mode of a uniform string.

    >>> rods = RodString(np.array([1000.0]), np.array([2.85e-4]), np.array([2.05e11]), np.array([2.0]))
    >>> round(damping_coefficient(rods, 0.1) * 1000.0 / float(rods.wave_speed[0]), 6)   # pi nu / 2
    0.15708
    """
    return float(np.pi * damping / (2.0 * travel_time(rods)))


def _transfer(rods: RodString, omega: np.ndarray) -> tuple[list[np.ndarray], list[np.ndarray], np.ndarray, np.ndarray]:
    """Undamped mode shape for phi(0) = 0, EA phi'(0) = 1 at the frequencies omega: the values
    (phi, N = EA phi') at the top of each taper, and phi, N at the bottom of the string."""
    phi = np.zeros_like(omega)
    force = np.ones_like(omega)
    tops_phi, tops_force = [], []
    for length, ea, speed in zip(rods.length, rods.youngs_modulus * rods.area, rods.wave_speed):
        tops_phi.append(phi)
        tops_force.append(force)
        k = omega / speed
        c, s = np.cos(k * length), np.sin(k * length)
        phi, force = phi * c + force * s / (ea * k), -phi * ea * k * s + force * c
    return tops_phi, tops_force, phi, force


def _frequencies(rods: RodString, omega_cut: float) -> np.ndarray:
    """The roots of N(L; omega) = 0 (free end) up to omega_cut [rad/s], by a fine scan and bisection.

    A bracket's lower end keeps the sign of N it started with, so that sign is taken once. A step
    that moves no bracket end (every midpoint is an end: the ends are adjacent numbers) leaves the
    steps after it the same midpoints and nothing to move either, so the bisection stops there,
    with the roots that all ``BISECTION_STEPS`` steps would give."""
    tau = travel_time(rods)
    step = SCAN_FRACTION * np.pi / tau
    grid = np.arange(1, int(np.ceil(omega_cut / step)) + 2) * step
    value = _transfer(rods, grid)[3]
    sign = np.signbit(value)
    brackets = np.flatnonzero(sign[:-1] != sign[1:])
    lo, hi = grid[brackets], grid[brackets + 1]
    sign_lo = np.signbit(_transfer(rods, lo)[3])
    for _ in range(BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        left = np.signbit(_transfer(rods, mid)[3]) == sign_lo
        new_lo, new_hi = np.where(left, mid, lo), np.where(left, hi, mid)
        if np.array_equal(new_lo, lo) and np.array_equal(new_hi, hi):
            break
        lo, hi = new_lo, new_hi
    roots = 0.5 * (lo + hi)
    return roots[roots <= omega_cut]


def rod_modes(rods: RodString, damping: float, omega_cut: float) -> RodModes:
    """The modes of the string up to omega_cut [rad/s] with Gibbs damping nu (module docstring);
    none if omega_cut is below the first: the string is then quasi-static.

    Each taper's shape is phi = A cos(k xi) + B sin(k xi), k = omega / a_i, xi from the
    taper top; the integrals int m phi^2 and int m phi over a taper are elementary.

    >>> rods = RodString(np.array([1000.0]), np.array([2.85e-4]), np.array([2.05e11]), np.array([2.0]))
    >>> m = rod_modes(rods, 0.1, 100.0)
    >>> a = float(rods.wave_speed[0])
    >>> [round(float(w) * 2 * 1000.0 / (np.pi * a), 9) for w in m.frequency[:3]]   # (2k - 1) pi a / (2 L)
    [1.0, 3.0, 5.0]
    """
    c = damping_coefficient(rods, damping)
    # one scan finds the first mode and the kept ones: up to either cut-off, the roots of the longer
    # scan are those of the shorter one (the same grid points, brackets and bisection steps)
    first_cut = 4.0 * np.pi / travel_time(rods)
    roots = _frequencies(rods, max(omega_cut, first_cut))
    first = float(roots[roots <= first_cut][0])
    if not first > 0.5 * c:
        raise PredictionError(
            f"damping factor {damping:g} is too large: c = {c:.4g} 1/s makes the first mode "
            f"({first:.4g} rad/s) overdamped (needs c / 2 < omega_1)"
        )
    omega = roots[roots <= omega_cut]
    tops_phi, tops_force, bottom_phi, _ = _transfer(rods, omega)
    norm = np.zeros_like(omega)
    taper_integrals = []
    for i, (length, ea, mass, speed) in enumerate(zip(rods.length, rods.youngs_modulus * rods.area,
                                                      rods.mass_per_length, rods.wave_speed)):
        k = omega / speed
        a_coef, b_coef = tops_phi[i], tops_force[i] / (ea * k)
        kl = k * length
        s2, c1, s1 = np.sin(2.0 * kl), np.cos(kl), np.sin(kl)
        norm += mass * (a_coef**2 * (0.5 * length + s2 / (4.0 * k)) + b_coef**2 * (0.5 * length - s2 / (4.0 * k))
                        + a_coef * b_coef * s1**2 / k)
        taper_integrals.append(mass * (a_coef * s1 + b_coef * (1.0 - c1)) / k)
    scale = 1.0 / np.sqrt(norm)
    per_taper = np.array(taper_integrals) * scale
    joints = np.vstack([np.cumsum(per_taper[::-1], axis=0)[::-1], np.zeros((1, omega.size))])
    bottom = bottom_phi * scale
    participation = joints[0]
    masses = rods.mass_per_length * rods.length
    mass_below = np.append(np.cumsum(masses[::-1])[::-1], 0.0)
    static = float(np.sum(rods.length / (rods.youngs_modulus * rods.area)))
    residual = static - float(np.sum(bottom**2 / omega**2))
    damped = np.sqrt(omega**2 - 0.25 * c * c)
    return RodModes(
        frequency=omega,
        damped_frequency=damped,
        eigenvalue=-0.5 * c + 1j * damped,
        bottom=bottom,
        participation=participation,
        joint_participation=joints,
        mass_below=mass_below,
        damping=c,
        static_compliance=static,
        residual_compliance=max(residual, 0.0),
        residual_transmission=1.0 - joints @ bottom,
        residual_mass=mass_below - joints @ participation,
    )


@dataclass(frozen=True)
class StepResponse:
    """Exact response of the modes on a uniform grid of step h [s] (module docstring).

    powers[k, n] = e^{lambda_k h n}; hat[k, n]: state of mode k at sample n after a unit
    hat-shaped forcing sample at 0 (hat[:, 0] = I1, hat[:, n] = e^{lambda h (n-1)}
    (e^{lambda h} I1 + I0)), n = 0 .. samples. ``spectra`` keeps the kernel's spectra of
    :meth:`periodic_spectrum` by period: the solvers find several periodic states with one
    response, each needing the same spectrum.
    """

    step: float
    powers: np.ndarray
    hat: np.ndarray
    spectra: dict[int, np.ndarray] = field(default_factory=dict, init=False, repr=False, compare=False)

    def periodic_spectrum(self, samples: int) -> np.ndarray:
        """FFT over n of the kernel of a forcing repeating every N = ``samples`` samples: hat[:, n]
        with the past periods' hat[:, n + p N] added (:func:`periodic_states`), taken once (read-only)."""
        spectrum = self.spectra.get(samples)
        if spectrum is None:
            kernel = self.hat
            closure = 1.0 / (1.0 - self.powers[:, samples])
            wrapped = kernel[:, :samples] * closure[:, None]
            wrapped[:, 0] = kernel[:, 0] + kernel[:, samples] * closure
            spectrum = self.spectra[samples] = np.fft.fft(wrapped, axis=1)
            spectrum.flags.writeable = False
        return spectrum


def step_response(modes: RodModes, step: float, samples: int) -> StepResponse:
    """Kernels of the exact steps for ``samples`` steps of ``step`` [s] (module docstring)."""
    lam = modes.eigenvalue
    lh = lam * step
    em1 = np.expm1(lh)
    growth = em1 + 1.0
    i1 = -1.0 / lam + em1 / (lam * lh)
    i0 = growth / lam - em1 / (lam * lh)
    powers = np.exp(np.outer(lh, np.arange(samples + 1)))
    hat = np.empty_like(powers)
    hat[:, 0] = i1
    np.multiply(powers[:, :-1], (growth * i1 + i0)[:, None], out=hat[:, 1:])
    return StepResponse(step, powers, hat)


def periodic_states(response: StepResponse, forcing: np.ndarray) -> np.ndarray:
    """Periodic modal states eta[k, n] for periodic hat-shaped forcing samples f[k, n], n = 0 .. N-1.

    Past periods add hat[:, n + p N] = e^{lambda h p N} hat[:, n] for n >= 1 (and
    hat[:, N] e^{lambda h (p-1) N} at n = 0): a geometric series closed with
    1 / (1 - e^{lambda h N}); the circular convolution is done by FFT, with the kernel's
    spectrum kept by the response (:meth:`StepResponse.periodic_spectrum`).
    """
    states = np.fft.fft(forcing, axis=1)
    np.multiply(response.periodic_spectrum(forcing.shape[1]), states, out=states)
    return np.fft.ifft(states, axis=1, out=states)
