"""Slider-crank (reciprocating pump) motion: exact, textbook approximations, and their errors.

Mechanism: crank O-A of radius r turning at uniform angular velocity omega, connecting
rod A-B of length l ([InertiaUNB600A]: l2), slider B on a straight line of stroke at distance e
(the offset; e = 0 for a centric mechanism) from the crank shaft O.

Frame (used for every function here): x along the line of stroke from O towards the
slider; y across it, oriented so that the crank pin is at A = r (cos phi, sin phi) with the
crank angle phi growing with time. The slider runs on y = e, so e is measured on the
side the crank pin swings into first. phi = 0 puts the crank pin on the x axis pointing
at the slider (for e = 0 the outer dead centre, where the inertia force is largest).

Exact slider position (loop closure A + (B - A) = B with |B - A| = l):

    x = r cos phi + sqrt(l^2 - (r sin phi - e)^2)

([InertiaUNB600A] eq. 1, its ref. 3, is the case e = 0). Velocity and
acceleration are its first two time derivatives at uniform rotation; the inertia force
of the reciprocating mass m (piston, rod and crosshead) is Phi = -m a (d'Alembert),
positive away from the crank: Phi = m r omega^2 (1 + lambda) at phi = 0 ([InertiaUNB600A] eq. 2).

Approximate laws (centric mechanism, lambda = r/l), all of the form
a = -r omega^2 [cos phi + sum_j c_j cos 2j phi]:

* ``harmonic``: c = 0, the sinusoidal law ([InertiaUNB600A] eq. 3, Phi_c = m r omega^2);
* ``two_term``: c_1 = lambda, the first approximation of the trigonometric series
  ([InertiaUNB600A] eq. 4, Phi_1 = m r omega^2 (1 + lambda));
* ``series4``, ``series6``: the next terms of the same series, harmonics up to 4 phi and
  6 phi (see :func:`series_coefficients`; [NPTEL112101096]).

For an offset mechanism the approximate laws are the centric ones with the same r and l
(what the textbook formulas give); their error then includes the neglected offset.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from math import comb

import numpy as np

from ..sampling import crank_grid, largest_magnitude
from .geometry import SliderCrank, check_slider_crank, dead_centres


@dataclass(frozen=True)
class SliderMotion:
    """Slider motion along the line of stroke, positive away from the crank.

    Attributes
    ----------
    position : numpy.ndarray
        x, from the crank shaft [m].
    velocity : numpy.ndarray
        [m/s].
    acceleration : numpy.ndarray
        [m/s²].
    """

    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray


def exact_motion(mechanism: SliderCrank, crank_angle: np.ndarray, crank_speed: float) -> SliderMotion:
    """Exact slider motion for uniform crank rotation.

    With u = r sin phi - e, u' = r cos phi, q = sqrt(l^2 - u^2):

        x = r cos phi + q,  dx/dphi = -r sin phi - u u'/q,
        d2x/dphi2 = -r cos phi - (u'^2 - u r sin phi)/q - u^2 u'^2/q^3,

    v = omega dx/dphi, a = omega^2 d2x/dphi2 (chain rule, uniform rotation).
    For e = 0 this is the classical exact acceleration

        a = -r omega^2 [cos phi + lambda cos 2phi / s + lambda^3 sin^2 2phi / (4 s^3)],
        s = sqrt(1 - lambda^2 sin^2 phi).

    Parameters
    ----------
    mechanism : SliderCrank
        r, l, e [m].
    crank_angle : numpy.ndarray
        phi [rad].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    SliderMotion
        x [m], v [m/s], a [m/s²].

    Raises
    ------
    GeometryError
        The crank cannot turn.

    References
    ----------
    [InertiaUNB600A] eq. 1 (e = 0).

    Examples
    --------
    UNB-600A ([InertiaUNB600A], r = 0.2 m, l = 1.19 m) at omega = 1 1/s: at the dead centres
    a = -r omega^2 (1 + r/l) = -0.233613 and r omega^2 (1 - r/l) = 0.166387 m/s².

    >>> m = exact_motion(SliderCrank(0.2, 1.19), np.array([0.0, np.pi]), 1.0)
    >>> [round(v, 6) for v in m.acceleration.tolist()]   # -r(1 + r/l), r(1 - r/l)
    [-0.233613, 0.166387]
    """
    check_slider_crank(mechanism)
    phi = np.asarray(crank_angle, dtype=float)
    r, l = mechanism.crank_radius, mechanism.rod_length
    sin, cos = np.sin(phi), np.cos(phi)
    u = r * sin - mechanism.offset
    du = r * cos
    q = np.sqrt(l * l - u * u)
    return SliderMotion(
        position=r * cos + q,
        velocity=crank_speed * (-r * sin - u * du / q),
        acceleration=crank_speed**2 * (-r * cos - (du * du - u * r * sin) / q - (u * du) ** 2 / q**3),
    )


def travel_from_outer_dead_centre(mechanism: SliderCrank, crank_angle: np.ndarray) -> np.ndarray:
    """Slider travel from the outer dead centre towards the crank, s = x_outer - x(phi).

    Parameters
    ----------
    mechanism : SliderCrank
        r, l, e [m].
    crank_angle : numpy.ndarray
        phi [rad].

    Returns
    -------
    numpy.ndarray
        s [m].

    Examples
    --------
    A centric drive travels the whole stroke 2r from phi = 0 to phi = pi:

    >>> travel_from_outer_dead_centre(SliderCrank(0.2, 1.19), np.array([0.0, np.pi])).round(12).tolist()
    [0.0, 0.4]
    """
    return dead_centres(mechanism).position_outer - exact_motion(mechanism, crank_angle, 1.0).position


def inertia_force(mass: float, acceleration):
    """d'Alembert inertia force Phi = -m a, positive along the axis of the acceleration.

    Parameters
    ----------
    mass : float
        m [kg].
    acceleration : float or numpy.ndarray
        a [m/s²].

    Returns
    -------
    float or numpy.ndarray
        Phi [N].

    References
    ----------
    [InertiaUNB600A] eqs. 1-2.

    Examples
    --------
    The largest force of [InertiaUNB600A] eq. 2, Phi_max = m omega^2 (r + r^2/l2), for UNB-600A with
    the estimated 240 kg at 65 rpm (omega = 6.8068 1/s): 240 x 46.332 x 0.233613 = 2597.7 N.

    >>> omega = 65 * np.pi / 30
    >>> round(float(inertia_force(240.0, -omega**2 * (0.2 + 0.2**2 / 1.19))), 1)
    2597.7
    """
    return -mass * acceleration


def series_coefficients(crank_ratio: float, terms: int) -> np.ndarray:
    """Coefficients c_1..c_terms of the even-harmonic series a = -r omega^2 [cos phi + sum_j c_j cos 2j phi].

    The series comes from expanding the radical of the exact position,
    l sqrt(1 - lambda^2 sin^2 phi) = l sum_k binom(1/2, k) (-lambda^2 sin^2 phi)^k,
    keeping k = 1..``terms``, and writing each power as a cosine sum,
    sin^2k phi = 4^-k [binom(2k, k) + 2 sum_{j=1..k} (-1)^j binom(2k, k - j) cos 2j phi].
    Differentiating twice gives

        c_j = (2j)^2 (-1)^(k+j) 2 binom(1/2, k) binom(2k, k - j) lambda^(2k-1) / 4^k,

    summed over k = j..terms. ``terms`` = 1 is the first approximation c_1 = lambda
    ([InertiaUNB600A] eq. 4); ``terms`` = 3 gives the textbook harmonic coefficients
    A2 = lambda + lambda^3/4 + 15 lambda^5/128, A4 = lambda^3/4 + 3 lambda^5/16,
    A6 = 9 lambda^5/128 as c = (A2, -A4, A6) (the standard even-harmonic series of the
    reciprocating mass, e.g. [NPTEL112101096], module 4 lecture 1, which derives the
    first term and notes the higher harmonics).

    Parameters
    ----------
    crank_ratio : float
        lambda = r / l (dimensionless).
    terms : int
        Number of terms k of the binomial series kept.

    Returns
    -------
    numpy.ndarray
        c_1 .. c_terms (dimensionless).

    References
    ----------
    [InertiaUNB600A] eq. 4; [NPTEL112101096].

    Examples
    --------
    >>> series_coefficients(0.5, 2).tolist()   # A2 = 0.5 + 0.125/4, -A4 = -0.125/4
    [0.53125, -0.03125]
    """
    c = np.zeros(terms)
    for k in range(1, terms + 1):
        binomial_half = np.prod([0.5 - i for i in range(k)]) / np.prod(np.arange(1, k + 1))
        for j in range(1, k + 1):
            c[j - 1] += (2 * j) ** 2 * (-1) ** (k + j) * 2 * binomial_half * comb(2 * k, k - j) * crank_ratio ** (2 * k - 1) / 4**k
    return c


#: Approximate laws of the slider acceleration: name -> number of series terms kept.
LAW_TERMS: dict[str, int] = {"harmonic": 0, "two_term": 1, "series4": 2, "series6": 3}


def law_methods() -> tuple[str, ...]:
    """Names of the approximate slider laws, simplest first.

    Returns
    -------
    tuple of str
        ``harmonic`` ([InertiaUNB600A] eq. 3), ``two_term`` (eq. 4), ``series4``, ``series6``.

    Examples
    --------
    >>> law_methods()
    ('harmonic', 'two_term', 'series4', 'series6')
    """
    return tuple(LAW_TERMS)


def approximate_acceleration(method: str, mechanism: SliderCrank, crank_angle: np.ndarray, crank_speed: float) -> np.ndarray:
    """Slider acceleration by an approximate law of :func:`law_methods`.

        a = -r omega^2 [cos phi + sum_j c_j cos 2j phi]

    with c from :func:`series_coefficients` (no terms: the sinusoidal law).

    Parameters
    ----------
    method : str
        A name of :func:`law_methods`.
    mechanism : SliderCrank
        r, l [m] (the offset is ignored: the laws are those of the centric drive).
    crank_angle : numpy.ndarray
        phi [rad].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    numpy.ndarray
        a [m/s²].

    Raises
    ------
    ValueError
        Unknown ``method``.

    References
    ----------
    [InertiaUNB600A] eqs. 3-4; [NPTEL112101096].

    Examples
    --------
    >>> a = approximate_acceleration("two_term", SliderCrank(0.2, 1.0), np.array([0.0, np.pi]), 1.0)
    >>> [round(v, 12) for v in a.tolist()]   # -r (1 + lambda), r (1 - lambda)
    [-0.24, 0.16]
    """
    if method not in LAW_TERMS:
        raise ValueError(f"unknown slider law {method!r}; use one of {', '.join(LAW_TERMS)}")
    phi = np.asarray(crank_angle, dtype=float)
    c = series_coefficients(mechanism.crank_ratio, LAW_TERMS[method])
    harmonics = 2.0 * np.arange(1, c.size + 1)
    series = np.cos(phi[..., None] * harmonics) @ c if c.size else 0.0
    return -mechanism.crank_radius * crank_speed**2 * (np.cos(phi) + series)


@dataclass(frozen=True)
class LawError:
    """Error of an approximate acceleration (or inertia-force) law against the exact one.

    All errors are dimensionless fractions (printed in %); P = max |a| over the cycle.

    Attributes
    ----------
    peak : float
        P_law [m/s²].
    peak_crank_angle : float
        Where the law peaks [rad].
    peak_error : float
        |1 - P_law / P_exact|, the definition of [InertiaUNB600A],
        delta = 100 |1 - Phi_approx,max / Phi_exact,max|.
    peak_error_of_law : float
        |1 - P_exact / P_law|, the same difference as a share of the approximate peak.
    max_deviation : float
        max |a_law - a| / P_exact over the cycle.
    rms_deviation : float
        rms(a_law - a) / rms(a) over the cycle (uniform rotation, so the mean over equal
        crank steps is the time mean).

    References
    ----------
    [InertiaUNB600A] (the error delta at the maximum).
    """

    peak: float
    peak_crank_angle: float
    peak_error: float
    peak_error_of_law: float
    max_deviation: float
    rms_deviation: float


def law_errors(crank_angle: np.ndarray, exact: np.ndarray, laws: Mapping[str, np.ndarray]) -> dict[str, LawError]:
    """:class:`LawError` of each law, from samples over one uniform revolution.

    Inertia forces are -m times the accelerations, so the errors are the same for both.

    Parameters
    ----------
    crank_angle : numpy.ndarray
        Uniform grid over one revolution [rad].
    exact : numpy.ndarray
        Exact acceleration on it [m/s²] (or any quantity proportional to it).
    laws : mapping of str to numpy.ndarray
        Each law's acceleration on the same grid [m/s²].

    Returns
    -------
    dict of str to LawError
        Dimensionless errors and the law's peak [m/s²] at [rad].

    Examples
    --------
    A law that is 10 % low everywhere: 10 % at the peak, 1/0.9 - 1 of its own peak.

    >>> theta = np.linspace(0.0, 2 * np.pi, 8, endpoint=False)
    >>> e = law_errors(theta, np.cos(theta), {"low": 0.9 * np.cos(theta)})["low"]
    >>> round(e.peak_error, 12), round(e.peak_error_of_law, 6), round(e.rms_deviation, 12)
    (0.1, 0.111111, 0.1)
    """
    exact_peak = largest_magnitude(crank_angle, exact).value
    exact_rms = np.sqrt(np.mean(exact**2))
    errors = {}
    for name, values in laws.items():
        law_peak = largest_magnitude(crank_angle, values)
        deviation = values - exact
        errors[name] = LawError(
            peak=law_peak.value,
            peak_crank_angle=law_peak.crank_angle,
            peak_error=abs(1.0 - law_peak.value / exact_peak),
            peak_error_of_law=abs(1.0 - exact_peak / law_peak.value),
            max_deviation=float(np.max(np.abs(deviation)) / exact_peak),
            rms_deviation=float(np.sqrt(np.mean(deviation**2)) / exact_rms),
        )
    return errors


@dataclass(frozen=True)
class InertiaComparison:
    """Exact motion and approximate accelerations on an output grid, with errors.

    ``position`` is measured from the reference dead position (slider: inner dead
    centre, away from the crank positive; beam unit: bottom of the stroke, up positive);
    velocity and acceleration are along the same axis, so the inertia force is
    Phi = -m a. ``errors`` and the exact peak come from a fixed dense grid of
    :data:`DENSE_STEPS` crank positions, so they do not depend on the output resolution.

    Attributes
    ----------
    crank_angle : numpy.ndarray
        Output grid [rad].
    position, velocity, acceleration : numpy.ndarray
        Exact motion [m, m/s, m/s²].
    laws : dict of str to numpy.ndarray
        Acceleration of each approximate law on the output grid [m/s²].
    stroke : float
        [m].
    peak, peak_crank_angle : float
        Exact max |a| [m/s²] and where [rad].
    errors : dict of str to LawError
        Per law (dimensionless).
    """

    crank_angle: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    laws: dict[str, np.ndarray]
    stroke: float
    peak: float
    peak_crank_angle: float
    errors: dict[str, LawError]


#: Crank positions per revolution for peaks and errors. The slider peaks lie on grid
#: points (phi = 0 for e = 0); elsewhere a peak is found to O(h^2), about 1e-7 relative.
DENSE_STEPS = 7200


def slider_inertia_laws(mechanism: SliderCrank, crank_speed: float, crank_angle: np.ndarray) -> InertiaComparison:
    """Exact slider motion and every approximate law, with their errors, for uniform rotation.

    Position is x - x_inner, from the inner dead centre, away from the crank positive,
    so at phi = 0 the inertia force -m a is Phi_max = m omega^2 (r + r^2/l2)
    ([InertiaUNB600A] eq. 2). Peaks and errors are taken on the dense grid.

    Parameters
    ----------
    mechanism : SliderCrank
        r, l, e [m].
    crank_speed : float
        Crank speed [1/s], positive.
    crank_angle : numpy.ndarray
        Output grid [rad].

    Returns
    -------
    InertiaComparison
        Exact motion [m, m/s, m/s²], each law's acceleration [m/s²], errors
        (dimensionless).

    Raises
    ------
    ValueError
        ``omega`` is not positive.

    References
    ----------
    [InertiaUNB600A] eqs. 1-4.

    Examples
    --------
    For lambda = 0.2 the exact peak is r omega^2 (1 + lambda) and the sinusoidal law
    misses it by lambda / (1 + lambda):

    >>> c = slider_inertia_laws(SliderCrank(0.2, 1.0), 1.0, crank_grid(4))
    >>> round(c.peak, 12), round(c.errors["harmonic"].peak_error, 12)   # r(1 + lambda), lambda/(1 + lambda)
    (0.24, 0.166666666667)
    """
    if not crank_speed > 0:
        raise ValueError(f"crank speed must be positive, got {crank_speed} 1/s")
    dead = dead_centres(mechanism)
    exact = exact_motion(mechanism, crank_angle, crank_speed)
    dense = crank_grid(DENSE_STEPS)
    dense_exact = exact_motion(mechanism, dense, crank_speed).acceleration
    exact_peak = largest_magnitude(dense, dense_exact)
    return InertiaComparison(
        crank_angle=np.asarray(crank_angle, dtype=float),
        position=exact.position - dead.position_inner,
        velocity=exact.velocity,
        acceleration=exact.acceleration,
        laws={name: approximate_acceleration(name, mechanism, crank_angle, crank_speed) for name in LAW_TERMS},
        stroke=dead.stroke,
        peak=exact_peak.value,
        peak_crank_angle=exact_peak.crank_angle,
        errors=law_errors(
            dense, dense_exact, {name: approximate_acceleration(name, mechanism, dense, crank_speed) for name in LAW_TERMS}
        ),
    )
