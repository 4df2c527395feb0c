"""Gibbs' frequency-domain solution of the damped wave equation, marched through the tapers.

Displacement w(x, t) is positive UP and x is measured down the string; the dynamic
tension is F = -E A dw/dx. In every section

    m w_tt = E A w_xx - c m w_t,      a^2 = E A / m                        [Gibbs1963]

For the harmonic e^{i omega t} the amplitude obeys W'' = beta^2 W with
beta^2 = (-omega^2 + i omega c) / a^2, so over a section of length l

    W(l) = cosh(beta l) W(0) - sinh(beta l) / (E A beta) F(0)
    F(l) = -E A beta sinh(beta l) W(0) + cosh(beta l) F(0)

(determinant 1; every entry is even in beta, so the branch of the square root does not
matter). Displacement and force are continuous at each joint, so the sections chain as
a product of these matrices [GibbsNeely1966]. The surface card enters as the Fourier
series of its position and dynamic load; the result is exact for the periodic steady
state of the trigonometric interpolant of the samples. A search over the damping (the
energy balance of :mod:`.downhole`) takes the series once (:func:`series`) and chains the
matrices at each damping (:func:`transfer`).
"""

from __future__ import annotations

import numpy as np

from .string import RodString


def _propagation(omega: np.ndarray, damping: float | np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s = a beta = sqrt(-omega^2 + i omega c) per harmonic, the same in every section (beta = s / a_i),
    1 / s (0 where s = 0) and the mask of s = 0: once per damping for all the sections, from real
    square roots without cancellation, |s|^2 = omega sqrt(omega^2 + c^2), Im s = sqrt((|s|^2 + omega^2) / 2),
    Re s = omega c / (2 Im s) (the principal root, Re s >= 0 for c >= 0)."""
    squared = omega * omega
    modulus = omega * np.sqrt(squared + damping * damping)
    imaginary = np.sqrt(0.5 * (modulus + squared))
    moving = modulus > 0.0
    root = np.zeros(modulus.shape, dtype=complex)
    np.divide(omega * damping, 2.0 * imaginary, out=root.real, where=moving)
    root.imag = imaginary
    inverse = np.zeros(modulus.shape, dtype=complex)
    np.divide(root.real, modulus, out=inverse.real, where=moving)
    np.divide(-imaginary, modulus, out=inverse.imag, where=moving)
    return root, inverse, ~moving


def _section_matrix(propagation: tuple[np.ndarray, np.ndarray, np.ndarray], length: float, wave_speed: float,
                    stiffness: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """cosh(beta l), sinh(beta l)/(E A beta) and E A beta sinh(beta l) per harmonic from
    :func:`_propagation`'s s: z = beta l = s l / a = x + i y, cosh z = cosh x cos y + i sinh x sin y,
    sinh z = sinh x cos y + i cosh x sin y, and sinh z / (E A beta) = (a / E A) sinh z / s. cos y and
    sin y come from the tangent of the half angle, t = tan(y / 2), cos y = (1 - t^2) / (1 + t^2),
    sin y = 2 t / (1 + t^2): numpy vectorises tan, while its float64 sin and cos cost about ten times
    as much. No difference of exponentials cancels, so this holds to rounding however small z is;
    at s = 0 (the mean, n = 0) sinh z / (E A beta) is its limit, the static compliance l / (E A)."""
    root, inverse, resting = propagation
    travel = length / wave_speed
    x = root.real * travel
    half = np.tan(root.imag * (0.5 * travel))
    squared = half * half
    scale = 1.0 / (1.0 + squared)
    cosh_x, sinh_x, cos_y, sin_y = np.cosh(x), np.sinh(x), (1.0 - squared) * scale, 2.0 * half * scale
    cosh, sinh = np.empty(root.shape, dtype=complex), np.empty(root.shape, dtype=complex)
    np.multiply(cosh_x, cos_y, out=cosh.real)
    np.multiply(sinh_x, sin_y, out=cosh.imag)
    np.multiply(sinh_x, cos_y, out=sinh.real)
    np.multiply(cosh_x, sin_y, out=sinh.imag)
    compliance = sinh * inverse * (wave_speed / stiffness)
    np.copyto(compliance, length / stiffness, where=resting)
    return cosh, compliance, sinh * root * (stiffness / wave_speed)


def series(period: float | np.ndarray, position: np.ndarray, load: np.ndarray,
           harmonics: int | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """omega_n = 2 pi n / T [rad/s] and the Fourier coefficients (``numpy.fft.rfft``, n = 0 to the
    highest harmonic kept) of the cards' position and load at the top, what :func:`transfer` takes;
    parameters as :func:`march`."""
    samples = position.shape[-1]
    highest = (samples - 1) // 2 if harmonics is None else min(int(harmonics), (samples - 1) // 2)
    omega = 2.0 * np.pi * np.arange(highest + 1) / np.asarray(period, dtype=float)[..., None]
    return omega, np.fft.rfft(position, axis=-1)[..., : highest + 1], np.fft.rfft(load, axis=-1)[..., : highest + 1]


def transfer(string: RodString, omega: np.ndarray, position: np.ndarray, load: np.ndarray,
             damping: float | np.ndarray, bottom_only: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The Fourier coefficients of the displacement and dynamic tension at every section end, shape
    (..., S + 1, H) with index 0 the top, from those at the top (:func:`series`): the section
    matrices chained down the string [Gibbs1963], [GibbsNeely1966]; ``damping`` as :func:`march`.
    With ``bottom_only``, shape (..., H), the bottom of the last section alone (what a search on the
    pump card needs)."""
    shape = np.broadcast_shapes(position.shape, load.shape, np.shape(damping))
    w, f = np.broadcast_to(position, shape), np.broadcast_to(load, shape)
    ends_w, ends_f = [w], [f]
    propagation = _propagation(omega, damping)
    for length, speed, ea in zip(string.length, string.wave_speed, string.youngs_modulus * string.area):
        cosh, compliance, rigidity = _section_matrix(propagation, length, speed, ea)
        w, f = cosh * w - compliance * f, cosh * f - rigidity * w
        ends_w.append(w)
        ends_f.append(f)
    if bottom_only:
        return w, f
    return np.stack(ends_w, axis=-2), np.stack(ends_f, axis=-2)


def march(string: RodString, period: float | np.ndarray, position: np.ndarray, load: np.ndarray, damping: float | np.ndarray,
          harmonics: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Displacement and dynamic tension at every section end from those at the top.

    Parameters
    ----------
    string : RodString
        Sections in marching order (the top one first).
    period : float or numpy.ndarray
        T [s] of the card; an array of shape (...,) gives each card its own (its axes
        broadcast against the cards' leading ones).
    position : numpy.ndarray
        w(0, t_k) [m], shape (..., N), uniform grid t_k = k T / N, up positive.
    load : numpy.ndarray
        Dynamic tension F(0, t_k) [N], same shape.
    damping : float or numpy.ndarray
        c [1/s]; an array of shape (..., 1) solves for several dampings at once (its axes
        broadcast against the cards').
    harmonics : int, optional
        Highest harmonic kept; default (N - 1) // 2, every harmonic the grid resolves
        (the Nyquist term of an even N is dropped: its sine part is not sampled).

    Returns
    -------
    position, load : numpy.ndarray
        Shape (..., S + 1, N): index 0 the top, index S the bottom of the last section.

    References
    ----------
    [Gibbs1963], [GibbsNeely1966].
    """
    samples = position.shape[-1]
    w, f = transfer(string, *series(period, position, load, harmonics), damping)
    return np.fft.irfft(w, n=samples, axis=-1), np.fft.irfft(f, n=samples, axis=-1)
