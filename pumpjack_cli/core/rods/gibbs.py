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
state of the trigonometric interpolant of the samples.
"""

from __future__ import annotations

import numpy as np

from .string import RodString


def _section_matrix(omega: np.ndarray, length: float, wave_speed: float, stiffness: float,
                    damping: float | np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """cosh(beta l), sinh(beta l)/(E A beta) and E A beta sinh(beta l) per harmonic, the
    hyperbolic functions from one complex exponential (Re z >= 0 here, so e^-z does not
    overflow; sinh z / z near z = 0, where the difference of exponentials cancels, from its
    series 1 + z^2/6 + z^4/120, whose next term is below 1e-16 for |z| < 1e-3)."""
    beta = np.sqrt((-(omega**2) + 1j * omega * damping).astype(complex)) / wave_speed
    z = beta * length
    grows = np.exp(z)
    decays = 1.0 / grows
    cosh, sinh = 0.5 * (grows + decays), 0.5 * (grows - decays)
    small = np.abs(z) < 1e-3
    with np.errstate(invalid="ignore", divide="ignore"):
        sinhc = sinh / np.where(small, 1.0, z)
    if np.any(small):
        near = z[small]
        sinhc[small] = 1.0 + near * near / 6.0 + near**4 / 120.0
    return cosh, length * sinhc / stiffness, stiffness * z * sinh / length


def march(string: RodString, period: float | np.ndarray, position: np.ndarray, load: np.ndarray, damping: float | np.ndarray,
          harmonics: int | None = None, bottom_only: bool = False) -> tuple[np.ndarray, np.ndarray]:
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

    bottom_only : bool
        Only the bottom of the last section transformed back (what a search on the pump card needs).

    Returns
    -------
    position, load : numpy.ndarray
        Shape (..., S + 1, N): index 0 the top, index S the bottom of the last section; with
        ``bottom_only``, shape (..., N), the bottom alone.

    References
    ----------
    [Gibbs1963], [GibbsNeely1966].
    """
    samples = position.shape[-1]
    highest = (samples - 1) // 2 if harmonics is None else min(int(harmonics), (samples - 1) // 2)
    omega = 2.0 * np.pi * np.arange(highest + 1) / np.asarray(period, dtype=float)[..., None]
    w = np.fft.rfft(position, axis=-1)[..., : highest + 1]
    f = np.fft.rfft(load, axis=-1)[..., : highest + 1]
    shape = np.broadcast_shapes(w.shape, f.shape, np.shape(damping))
    w, f = np.broadcast_to(w, shape), np.broadcast_to(f, shape)
    ends_w, ends_f = [w], [f]
    stiffness = string.youngs_modulus * string.area
    for length, speed, ea in zip(string.length, string.wave_speed, stiffness):
        cosh, compliance, rigidity = _section_matrix(omega, length, speed, ea, damping)
        w, f = cosh * w - compliance * f, cosh * f - rigidity * w
        ends_w.append(w)
        ends_f.append(f)
    if bottom_only:
        return np.fft.irfft(w, n=samples, axis=-1), np.fft.irfft(f, n=samples, axis=-1)
    return (np.fft.irfft(np.stack(ends_w, axis=-2), n=samples, axis=-1),
            np.fft.irfft(np.stack(ends_f, axis=-2), n=samples, axis=-1))
