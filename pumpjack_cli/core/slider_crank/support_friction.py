"""Friction in a prismatic pair loaded by redundant supports of a stepped slider ([InertiaUNB600A], part 2).

Model (our reading of [InertiaUNB600A], figs. 1-4; the printed equations are lost in the
extracted text, so they are re-derived here with the force method):

* The reciprocating link (piston, rod, extension rod, crosshead) is a straight beam of
  n sections, section i of length l_i and second moment of area J_i, numbered from end A.
  z runs along the link from A (z = 0) to B (z = L = sum l_i).
* End A is clamped: deflection and slope zero; its guide defines the reference axis.
* At end B the link sits in a guide of length l_n whose axis has settled by Delta_B and
  turned by theta_B relative to A's axis ([InertiaUNB600A]: "support B has shifted relative to A by
  Delta_B and its line of symmetry has turned by theta_B"). The guide imposes
  w(L) = Delta_B + theta_B s and w'(L) = theta_B, where s is the travel of the link
  along the guide from the reference position (a turned guide is a sloping line, so
  the height under B changes as B slides along it). The guide's reactions are a force
  R_B and a moment M_B at B, or two edge forces R' (outer edge, z = L + l_n/2) and R''
  (inner edge, z = L - l_n/2) with R' + R'' = R_B, (R' - R'') l_n/2 = M_B:
  R' = R_B/2 + M_B/l_n, R'' = R_B/2 - M_B/l_n ([InertiaUNB600A], text after fig. 2).
* Optionally an intermediate support C fixed to the frame (a seal or gland on the rod)
  at height delta_C off A's axis ([InertiaUNB600A] fig. 4: "not on one level"), touching the link at
  z_C = z_C0 - s, so it moves along the link as the link travels; it gives a force Y_C.
* Friction in the guide B: F = f (|R'| + |R''|) ([InertiaUNB600A], formula after fig. 2); at C
  f |Y_C|. Weights are neglected and contacts have no clearance (the paper's assumptions).

Stepped sections are reduced to an equivalent beam of constant section J_0 with the
coefficients alpha_i = J_i / J_0 ([InertiaUNB600A], after fig. 3): in every flexibility integral
dz / (E J_i) = dz / (E J_0 alpha_i). The unknowns R_B, M_B, Y_C follow from the
compatibility conditions of the force method (Maxwell-Mohr):

    sum_j delta_ij X_j = prescribed displacement i,  delta_ij = int m_i m_j dz / (E J(z)),

with the primary system the cantilever clamped at A and m_i the bending moment of a
unit redundant: a unit force at z = a gives m(z) = a - z for z < a (0 beyond), a unit
moment at B gives m(z) = 1. (Force method: e.g. [NPTEL105101085], module 5 "Force
method"; [OkonkwoLibreTexts], ch. 10 "Force method of analysis of indeterminate
structures".)
Sign convention: w up, moments counterclockwise, forces up on the link.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


def reduction_coefficients(second_moments: np.ndarray) -> np.ndarray:
    """Reduction coefficients alpha_i = J_i / J_0 of a stepped beam, J_0 the smallest section.

    [InertiaUNB600A] takes J_0 = J_2, the piston rod, which is the smallest section of its slider;
    any choice gives the same reactions, since E J_0 alpha_i = E J_i.

    Parameters
    ----------
    second_moments : numpy.ndarray
        J_i of the sections [m⁴].

    Returns
    -------
    numpy.ndarray
        alpha_i (dimensionless).

    References
    ----------
    [InertiaUNB600A] (after fig. 3).

    Examples
    --------
    >>> reduction_coefficients(np.array([4.0, 1.0, 2.0])).tolist()
    [4.0, 1.0, 2.0]
    """
    j = np.asarray(second_moments, dtype=float)
    return j / np.min(j)


def _integrals(bounds: np.ndarray, alphas: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """I_k = int_0^upper z^k / alpha(z) dz for k = 0, 1, 2; shape (3, *upper.shape).

    alpha(z) is piecewise constant, alpha_i on [bounds[i], bounds[i+1]].
    """
    lo, hi = bounds[:-1], bounds[1:]
    top = np.clip(np.asarray(upper, dtype=float)[..., None], lo, hi)
    return np.stack([np.sum((top ** (k + 1) - lo ** (k + 1)) / (k + 1) / alphas, axis=-1) for k in range(3)])


def flexibility_matrix(lengths: np.ndarray, second_moments: np.ndarray, elastic_modulus: float,
                       support_position: np.ndarray | None = None) -> np.ndarray:
    """Flexibility matrix of the redundants (R_B, M_B[, Y_C]) of the cantilever clamped at A.

    Rows: w(L), w'(L)[, w(c)] per unit redundant. Entries (Maxwell-Mohr integrals, each
    over E J_0 alpha(z) dz): d_LL = int_0^L (L - z)^2, d_LM = int_0^L (L - z),
    d_MM = int_0^L 1, and with an intermediate support at c also
    d_Lc = int_0^c (L - z)(c - z), d_Mc = int_0^c (c - z), d_cc = int_0^c (c - z)^2;
    symmetric by Maxwell's reciprocity.

    Parameters
    ----------
    lengths : numpy.ndarray
        Section lengths l_i from A [m].
    second_moments : numpy.ndarray
        Section second moments of area J_i [m⁴].
    elastic_modulus : float
        E [Pa].
    support_position : numpy.ndarray, optional
        Intermediate support positions c from A, (N,) [m], or None.

    Returns
    -------
    numpy.ndarray
        Shape (2, 2) without a support, (N, 3, 3) with one; entries [m/N] (deflection
        per force), [1/N] (slope per force = deflection per moment), [1/(N·m)] (slope
        per moment).

    References
    ----------
    [NPTEL105101085], module 5 (force method); [InertiaUNB600A] (reduction coefficients).

    Examples
    --------
    A uniform cantilever of length L = 2 m with EI = 1 N·m²: L³/3EI, L²/2EI, L/EI.

    >>> flexibility_matrix([2.0], [1.0], 1.0).tolist()   # cantilever: L^3/3, L^2/2, L
    [[2.6666666666666665, 2.0], [2.0, 2.0]]
    """
    lengths = np.asarray(lengths, dtype=float)
    alphas = reduction_coefficients(second_moments)
    ej0 = elastic_modulus * np.min(np.asarray(second_moments, dtype=float))
    bounds = np.concatenate([[0.0], np.cumsum(lengths)])
    span = bounds[-1]
    i0, i1, i2 = _integrals(bounds, alphas, np.array(span))
    d_ll = span * span * i0 - 2.0 * span * i1 + i2
    d_lm = span * i0 - i1
    if support_position is None:
        return np.array([[d_ll, d_lm], [d_lm, i0]]) / ej0
    c = np.atleast_1d(np.asarray(support_position, dtype=float))
    j0, j1, j2 = _integrals(bounds, alphas, c)
    d_lc = span * c * j0 - (span + c) * j1 + j2
    d_mc = c * j0 - j1
    d_cc = c * c * j0 - 2.0 * c * j1 + j2
    rows = [
        np.stack([np.full(c.shape, d_ll), np.full(c.shape, d_lm), d_lc], axis=-1),
        np.stack([np.full(c.shape, d_lm), np.full(c.shape, i0), d_mc], axis=-1),
        np.stack([d_lc, d_mc, d_cc], axis=-1),
    ]
    return np.stack(rows, axis=-2) / ej0


@dataclass(frozen=True)
class SupportReactions:
    """Reactions of the redundant supports on the link, per link position.

    Attributes
    ----------
    force, moment : numpy.ndarray
        R_B [N] and M_B [N·m] of guide B.
    outer_edge, inner_edge : numpy.ndarray
        Edge forces R' (outer edge) and R'' (inner edge) [N].
    intermediate : numpy.ndarray
        Y_C [N] (zero without an intermediate support).
    guide_friction, intermediate_friction, total_friction : numpy.ndarray
        Friction in guide B, at C, and their sum [N].

    References
    ----------
    [InertiaUNB600A] (part 2).
    """

    force: np.ndarray
    moment: np.ndarray
    outer_edge: np.ndarray
    inner_edge: np.ndarray
    intermediate: np.ndarray
    guide_friction: np.ndarray
    intermediate_friction: np.ndarray
    total_friction: np.ndarray


def guide_edge_reactions(force: np.ndarray, moment: np.ndarray, guide_length: float) -> tuple[np.ndarray, np.ndarray]:
    """Edge forces of a guide of length l_n carrying R_B and M_B, R' = R_B/2 + M_B/l_n, R'' = R_B/2 - M_B/l_n.

    Same sign when |M_B| <= R_B l_n / 2; otherwise opposite, and the friction
    f(|R'| + |R''|) = 2 f |M_B| / l_n exceeds f |R_B| by the factor 2 |M_B| / (l_n |R_B|)
    (the remark of [InertiaUNB600A]).

    Parameters
    ----------
    force : numpy.ndarray
        R_B [N].
    moment : numpy.ndarray
        M_B [N·m].
    guide_length : float
        l_n, distance between the edge contacts [m].

    Returns
    -------
    tuple of numpy.ndarray
        R' (outer edge) and R'' (inner edge) [N].

    References
    ----------
    [InertiaUNB600A] (after fig. 2).

    Examples
    --------
    100 N and 5 N·m over 0.2 m: 50 + 25 and 50 - 25 N.

    >>> guide_edge_reactions(np.array([100.0]), np.array([5.0]), 0.2)
    (array([75.]), array([25.]))
    """
    half = 0.5 * np.asarray(force, dtype=float)
    couple = np.asarray(moment, dtype=float) / guide_length
    return half + couple, half - couple


def redundant_support_friction(
    lengths: np.ndarray, second_moments: np.ndarray, elastic_modulus: float, guide_length: float,
    friction_coefficient: float, settlement: float, turn: float, travel: np.ndarray,
    support_position: float | None = None, support_offset: float = 0.0,
) -> SupportReactions:
    """Reactions and friction forces of the redundant supports for each link travel.

    Solves, per position, the force-method system D X = (Delta_B + theta_B s, theta_B,
    delta_C) for X = (R_B, M_B, Y_C) in one batched solve (D from
    :func:`flexibility_matrix`, the intermediate support at z_C = z_C0 - s), or the 2x2
    system without Y_C when there is no intermediate support; then the edge forces
    (:func:`guide_edge_reactions`) and the friction f (|R'| + |R''|) + f |Y_C|.

    Parameters
    ----------
    lengths : numpy.ndarray
        Section lengths from the clamped end A [m].
    second_moments : numpy.ndarray
        Section second moments of area [m⁴].
    elastic_modulus : float
        E [Pa].
    guide_length : float
        l_n, distance between the edge contacts of guide B [m].
    friction_coefficient : float
        f, sliding friction in the guides (dimensionless).
    settlement : float
        Delta_B, guide B's axis off A's axis at s = 0 [m].
    turn : float
        theta_B, angle of guide B's axis to A's axis [rad].
    travel : numpy.ndarray
        s, travel of the link from the reference position, towards B [m].
    support_position : float, optional
        z_C0 from A at s = 0 [m], or None without an intermediate support.
    support_offset : float
        delta_C, height of the intermediate support off A's axis [m].

    Returns
    -------
    SupportReactions
        Forces [N] and moments [N·m] per travel.

    References
    ----------
    [InertiaUNB600A] (part 2); [NPTEL105101085] (force method).

    Examples
    --------
    One section clamped at both ends (L = 1 m, EI = 12 N·m²), end B settled by 1 m: the
    fixed-end reactions 12 EI Delta / L^3 and -6 EI Delta / L^2 ([NPTEL105101085],
    module 5, example 5.5).

    >>> r = redundant_support_friction([1.0], [1.0], 12.0, 0.5, 0.1, 1.0, 0.0, np.array([0.0]))
    >>> r.force.tolist(), r.moment.tolist()   # fixed-fixed beam, end settled: 12 EI D/L^3, -6 EI D/L^2
    ([144.0], [-72.0])
    """
    s = np.atleast_1d(np.asarray(travel, dtype=float))
    if support_position is None:
        matrix = np.broadcast_to(flexibility_matrix(lengths, second_moments, elastic_modulus), (s.size, 2, 2))
        prescribed = np.stack([settlement + turn * s, np.full(s.shape, turn)], axis=-1)
    else:
        matrix = flexibility_matrix(lengths, second_moments, elastic_modulus, support_position - s)
        prescribed = np.stack([settlement + turn * s, np.full(s.shape, turn), np.full(s.shape, support_offset)], axis=-1)
    unknowns = np.linalg.solve(matrix, prescribed[..., None])[..., 0]
    force, moment = unknowns[:, 0], unknowns[:, 1]
    intermediate = unknowns[:, 2] if support_position is not None else np.zeros(s.shape)
    outer, inner = guide_edge_reactions(force, moment, guide_length)
    guide = friction_coefficient * (np.abs(outer) + np.abs(inner))
    at_support = friction_coefficient * np.abs(intermediate)
    return SupportReactions(
        force=force,
        moment=moment,
        outer_edge=outer,
        inner_edge=inner,
        intermediate=intermediate,
        guide_friction=guide,
        intermediate_friction=at_support,
        total_friction=guide + at_support,
    )


def slider_length(section_lengths) -> float:
    """Length of the slider from the clamped end A to guide B, L = sum l_i.

    Parameters
    ----------
    section_lengths : iterable of float
        l_i [m].

    Returns
    -------
    float
        L [m].

    Examples
    --------
    The estimated UNB-600A slider (piston, rod, extension rod, crosshead):

    >>> round(slider_length([0.12, 1.0, 0.7, 0.2]), 12)
    2.02
    """
    return sum(section_lengths)


def solid_round_second_moment(diameter):
    """Second moment of area of a solid circle, J = pi d^4 / 64.

    Parameters
    ----------
    diameter : float
        d [m].

    Returns
    -------
    float
        J [m⁴].

    Examples
    --------
    >>> round(solid_round_second_moment(0.1) * 1e8, 4)   # pi 1e-4 / 64 m^4
    490.8739
    """
    return math.pi * diameter**4 / 64.0
