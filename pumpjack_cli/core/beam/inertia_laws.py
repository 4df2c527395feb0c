"""Inertia-force laws of the polished rod of a beam pumping unit ([InertiaUNB600A] eqs. 5-7).

Exact: the polished rod moves with the horsehead arc, s = A (psi - psi_bottom)
(:mod:`pumpjack_cli.core.beam.kinematics`; [InertiaUNB600A] eqs. 5-6 write the same exact
force with the rocker arms l31 = A and l32 = C). Approximations compared with it:

* ``harmonic`` and ``two_term``: the elementary and refined textbook theories of
  :func:`pumpjack_cli.core.beam.kinematics.approximate_motion` ([Aliverdizade1951],
  [NUNG]);
* ``chord``: the equalizer bearing B is taken to move along the chord of its arc
  between the two dead positions instead of the arc ([InertiaUNB600A]: "the motion of
  the suspension point along the arc is neglected, it is taken to move along the
  chord", its ref. 1), and the polished rod moves A/C times as far. The crank, pitman
  and the chord then form an offset slider-crank (:mod:`pumpjack_cli.core.slider_crank`)
  whose line of stroke is the chord, inclined to the frame. Eq. 7 of [InertiaUNB600A]
  (with the tilt psi of the post of length l0) is illegible in the extracted text; this
  is our reconstruction of the same assumption, exact for the chord so that only the
  arc-to-chord step is approximated.
"""

from __future__ import annotations

import numpy as np

from ..sampling import crank_grid, largest_magnitude
from ..slider_crank.mechanism import DENSE_STEPS, InertiaComparison, exact_motion, law_errors
from .kinematics import APPROXIMATIONS, RodMotion, approximate_motion, rod_motion
from ..mechanism import Mechanism
from .geometry import Linkage  # noqa: F401 (the docstrings' examples build one)


def chord_motion(linkage: Mechanism, crank_angle: np.ndarray, crank_speed: float) -> RodMotion:
    """Polished-rod motion under the chord law for uniform crank rotation.

        s = (A/C) d (x(phi) - x(phi_bottom)),  v = (A/C) d dx/dt,  a = (A/C) d d2x/dt2,

    from the exact offset slider-crank
    (:func:`pumpjack_cli.core.slider_crank.mechanism.exact_motion`) with
    phi = phase + theta (so d/dt = omega d/dphi), d the ``direction`` of
    :meth:`Mechanism.chord_slider_crank <pumpjack_cli.core.mechanism.Mechanism.chord_slider_crank>`. The stroke is (A/C) times the chord,
    2 A sin((psi_top - psi_bottom)/2).

    Parameters
    ----------
    linkage : Mechanism
        The unit [m].
    crank_angle : numpy.ndarray
        theta [rad].
    crank_speed : float
        Crank speed [1/s].

    Returns
    -------
    RodMotion
        s [m], v [m/s], a [m/s²].

    References
    ----------
    [InertiaUNB600A] eq. 7 (the assumption; reconstructed here).

    Examples
    --------
    SK8-3,5-4000: the beam swings 47.68 degrees, so the chord stroke is
    2 x 3.5 x sin(23.84 deg) = 2.829 m, against the exact 2.913 m; the chord joins the
    exact dead positions.

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> dead = sk8.dead_positions()
    >>> s = chord_motion(sk8, np.array([dead.crank_angle_bottom, dead.crank_angle_top]), 1.0).position
    >>> [round(abs(float(x)), 3) for x in s]
    [0.0, 2.829]
    """
    chord = linkage.chord_slider_crank()
    theta = np.asarray(crank_angle, dtype=float)
    phi = chord.phase + theta
    bottom = chord.phase + linkage.dead_positions().crank_angle_bottom
    slider = exact_motion(chord.slider, phi, crank_speed)
    start = exact_motion(chord.slider, np.array(bottom), crank_speed).position
    scale = chord.scale
    return RodMotion(
        position=scale * (slider.position - start),
        velocity=scale * slider.velocity,
        acceleration=scale * slider.acceleration,
    )


#: Approximate polished-rod laws: the textbook ones and the chord law.
BEAM_LAWS = (*APPROXIMATIONS, "chord")


def _rod_laws(linkage: Mechanism, crank_angle: np.ndarray, crank_speed: float) -> tuple[RodMotion, dict[str, np.ndarray]]:
    """Exact polished-rod motion and the acceleration of every law of :data:`BEAM_LAWS`."""
    dead = linkage.dead_positions()
    m = linkage.motion(crank_angle)
    exact = rod_motion(m, crank_speed)
    from_bottom = crank_angle - dead.crank_angle_bottom
    laws = {name: approximate_motion(name, linkage, from_bottom, crank_speed).acceleration for name in APPROXIMATIONS}
    laws["chord"] = chord_motion(linkage, crank_angle, crank_speed).acceleration
    return exact, laws


def beam_inertia_laws(linkage: Mechanism, crank_speed: float, crank_angle: np.ndarray) -> InertiaComparison:
    """Exact polished-rod motion and every law of :data:`BEAM_LAWS`, with their errors.

    The inertia force of a mass m moving with the polished rod is -m a for every law,
    so the errors of :func:`~pumpjack_cli.core.slider_crank.mechanism.law_errors` are
    the same for accelerations and forces. Peaks and errors are taken on a dense grid of
    :data:`~pumpjack_cli.core.slider_crank.mechanism.DENSE_STEPS` positions.

    Parameters
    ----------
    linkage : Mechanism
        The unit [m].
    crank_speed : float
        Crank speed [1/s], positive (uniform rotation).
    crank_angle : numpy.ndarray
        Output crank angles [rad].

    Returns
    -------
    InertiaComparison
        Exact position [m] from the bottom, velocity [m/s], acceleration [m/s²], each
        law's acceleration [m/s²], stroke [m], exact peak [m/s²] and its angle [rad],
        errors (dimensionless fractions).

    Raises
    ------
    ValueError
        ``omega`` is not positive.

    References
    ----------
    [InertiaUNB600A] eqs. 5-7; [Aliverdizade1951], [NUNG].

    Examples
    --------
    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> c = beam_inertia_laws(sk8, 1.1422, crank_grid(12))
    >>> round(c.stroke, 4), sorted(c.errors)
    (2.9128, ['chord', 'harmonic', 'two_term'])
    """
    if not crank_speed > 0:
        raise ValueError(f"crank speed must be positive, got {crank_speed} 1/s")
    theta = np.asarray(crank_angle, dtype=float)
    dead = linkage.dead_positions()
    exact, laws = _rod_laws(linkage, theta, crank_speed)
    dense = crank_grid(DENSE_STEPS)
    dense_exact, dense_laws = _rod_laws(linkage, dense, crank_speed)
    exact_peak = largest_magnitude(dense, dense_exact.acceleration)
    return InertiaComparison(
        crank_angle=theta,
        position=exact.position,
        velocity=exact.velocity,
        acceleration=exact.acceleration,
        laws=laws,
        stroke=dead.stroke,
        peak=exact_peak.value,
        peak_crank_angle=exact_peak.crank_angle,
        errors=law_errors(dense, dense_exact.acceleration, dense_laws),
    )
