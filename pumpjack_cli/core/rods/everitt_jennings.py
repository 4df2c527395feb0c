"""Everitt & Jennings' finite-difference march in space, periodic in time.

The same equation as :mod:`.gibbs` (w up positive, x down, F = -E A w_x):

    m (w_tt + c w_t) = (E A w_x)_x

is discretised on the card's own time grid (t_k = k T / N, periodic) and on nodes
x_i down each section, dx = L_s / M_s with M_s = ceil(L_s / (a_s dt)) so that
dx <= a dt, the stability limit of a march in space [EverittJennings1992]. Because
every time level at a node is known when the march reaches it, the time differences
are central and periodic:

    D(w)_k = (w_{k+1} - 2 w_k + w_{k-1}) / dt^2 + c (w_{k+1} - w_{k-1}) / (2 dt)

(Everitt & Jennings use a forward difference for the damping term, first order in dt;
the central one used here is second order and keeps the scheme explicit). With
k_s = E_s A_s / dx_s and mu_s = m_s dx_s, the balance of node masses gives

* top node, half cell: (mu/2) D(w_0) = F_0 + k (w_1 - w_0), so
  w_1 = w_0 + ((mu/2) D(w_0) - F_0) / k;
* interior node: w_{i+1} = 2 w_i - w_{i-1} + (mu / k) D(w_i);
* joint between sections a (above) and b (below), lumped mass (mu_a + mu_b)/2:
  k_b (w_{J+1} - w_J) = k_a (w_J - w_{J-1}) + (mu_a + mu_b)/2 D(w_J), and the
  tension there F_J = (mu_b/2) D(w_J) - k_b (w_{J+1} - w_J);
* bottom node, half cell: F_L = -k (w_M - w_{M-1}) - (mu/2) D(w_M).

Every relation is a force balance, so with c = 0 the discrete energy flux
(k Im(conj(W_i) W_{i+1}) per harmonic) is the same at every node and the pump card's
work equals the surface card's to rounding.
"""

from __future__ import annotations

import numpy as np

from .string import RodString


def segments(string: RodString, time_step: float) -> np.ndarray:
    """M_s = ceil(L_s / (a_s dt)) >= 1 space steps per section, so that dx_s <= a_s dt."""
    ratio = string.length / (string.wave_speed * time_step)
    return np.maximum(1, np.ceil(ratio * (1.0 - 1e-12))).astype(int)


def march(string: RodString, period: float, position: np.ndarray, load: np.ndarray,
          damping: float) -> tuple[np.ndarray, np.ndarray]:
    """Displacement and dynamic tension at every section end from those at the top.

    Parameters
    ----------
    string : RodString
        Sections in marching order (the top one first).
    period : float
        T [s] of the card.
    position : numpy.ndarray
        w(0, t_k) [m], shape (..., N), uniform periodic grid, up positive.
    load : numpy.ndarray
        Dynamic tension F(0, t_k) [N], same shape.
    damping : float
        c [1/s].

    Returns
    -------
    position, load : numpy.ndarray
        Shape (..., S + 1, N): index 0 the top, index S the bottom of the last section.

    References
    ----------
    [EverittJennings1992]; derivation in ``docs/downhole.md``.
    """
    dt = period / position.shape[-1]

    def operator(w: np.ndarray) -> np.ndarray:
        ahead, behind = np.roll(w, -1, axis=-1), np.roll(w, 1, axis=-1)
        return (ahead - 2.0 * w + behind) / dt**2 + damping * (ahead - behind) / (2.0 * dt)

    steps = segments(string, dt)
    dx = string.length / steps
    spring = string.youngs_modulus * string.area / dx
    node_mass = string.mass_per_length * dx
    ends_w, ends_f = [position], [load]
    previous, current = position, position + (0.5 * node_mass[0] * operator(position) - load) / spring[0]
    last = len(steps) - 1
    for s in range(last + 1):
        for _ in range(steps[s] - 1):
            previous, current = current, 2.0 * current - previous + node_mass[s] / spring[s] * operator(current)
        acceleration = operator(current)
        ends_w.append(current)
        if s == last:
            ends_f.append(-spring[s] * (current - previous) - 0.5 * node_mass[s] * acceleration)
            break
        below = current + (spring[s] * (current - previous)
                           + 0.5 * (node_mass[s] + node_mass[s + 1]) * acceleration) / spring[s + 1]
        ends_f.append(0.5 * node_mass[s + 1] * acceleration - spring[s + 1] * (below - current))
        previous, current = current, below
    return np.stack(ends_w, axis=-2), np.stack(ends_f, axis=-2)
