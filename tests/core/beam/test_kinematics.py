"""Tests of pumpjack_cli.core.beam.kinematics: exact polished-rod motion and approximations.

Reference values are derivatives computed here by central finite differences, the
textbook closed forms (harmonic motion; slider-crank displacement), and dense-grid /
scalar-optimizer extremes -- never numbers taken from the package's own output.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from pumpjack_cli.core.beam.kinematics import harmonic_motion, rod_motion, two_term_motion, uniform_kinematics

from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.beam.geometry import COUNTERCLOCKWISE, Linkage, dead_positions
from pumpjack_cli.core.beam.linkage import motion

from helpers import INCH, SK8_CRANK_SPEED, SK8_LINKAGE

# C-114D-133-54, Guo, Lyons & Ghalambor 2007 [Guo2007], Table 12.1: A, C, R, P, I, H - G in inches
C114_CCW = Linkage(72 * INCH, 64 * INCH, 24 * INCH, 74.5 * INCH, 64 * INCH, 75 * INCH, COUNTERCLOCKWISE)

# SK8-3,5-4000 with the dimensions of [SK8Rotation2013].
UNITS = {"SK8": SK8_LINKAGE, "C114-ccw": C114_CCW}
# The crank speed of the SK8 example of [SK8Rotation2013] (about 10.9 strokes/min); any
# positive value would do, the identities tested hold for every omega.
OMEGA = SK8_CRANK_SPEED


def _exact(lk: Linkage, theta, omega, epsilon=0.0):
    """Polished-rod motion at arbitrary crank angles via motion() + rod_motion()."""
    m = motion(lk, np.asarray(theta, dtype=float))
    return rod_motion(m, omega, epsilon)


# --- exact motion: derivatives ------------------------------------------------------


@pytest.mark.parametrize("name", UNITS)
def test_torque_factor_is_derivative_of_position(name):
    """TF = ds/dtheta (torque factor of [API11E]). Central difference with h = 1e-5 rad
    on separately computed crank angles: truncation h^2/6 |s'''| ~ 2e-11 m, rounding
    ~ 1e-16 * 3 m / 1e-5 = 3e-11 m, so the bound 1e-6 relative (to max |TF|, because TF
    crosses zero at the dead positions) is three orders above both."""
    lk = UNITS[name]
    kin = uniform_kinematics(lk, OMEGA, steps=360)
    h = 1e-5
    fd = (_exact(lk, kin.crank_angle + h, OMEGA).position - _exact(lk, kin.crank_angle - h, OMEGA).position) / (2 * h)
    scale = np.max(np.abs(kin.torque_factor))
    np.testing.assert_allclose(kin.torque_factor, fd, rtol=0, atol=1e-6 * scale)
    # and TF has units of length: it is of the order of the stroke / 2 (sanity on scale)
    assert 0.2 * kin.summary.stroke < scale < kin.summary.stroke


@pytest.mark.parametrize("name", UNITS)
def test_velocity_and_acceleration_are_time_derivatives(name):
    """Uniform rotation: t = theta / omega, so v = ds/dt and a = dv/dt. Central
    differences in time with dt = 1e-5 s; tolerance 1e-6 of the peak value (same error
    budget as the torque-factor test, scaled by omega)."""
    lk = UNITS[name]
    omega = 2.3
    kin = uniform_kinematics(lk, omega, steps=240)
    t = kin.time
    np.testing.assert_allclose(t, kin.crank_angle / omega, rtol=1e-15)
    dt = 1e-5
    plus, minus = _exact(lk, omega * (t + dt), omega), _exact(lk, omega * (t - dt), omega)
    v_fd = (plus.position - minus.position) / (2 * dt)
    a_fd = (plus.velocity - minus.velocity) / (2 * dt)
    np.testing.assert_allclose(kin.rod.velocity, v_fd, rtol=0, atol=1e-6 * np.max(np.abs(v_fd)))
    np.testing.assert_allclose(kin.rod.acceleration, a_fd, rtol=0, atol=1e-6 * np.max(np.abs(a_fd)))
    # beam and pitman angular velocities/accelerations likewise
    m_plus, m_minus = motion(lk, omega * (t + dt)), motion(lk, omega * (t - dt))
    w_fd = (m_plus.beam_angle - m_minus.beam_angle) / (2 * dt)
    np.testing.assert_allclose(kin.beam_angular_velocity, w_fd, rtol=0, atol=1e-6 * np.max(np.abs(w_fd)))
    e_fd = (m_plus.pitman_rate * omega - m_minus.pitman_rate * omega) / (2 * dt)
    np.testing.assert_allclose(kin.pitman_angular_acceleration, e_fd, rtol=0, atol=1e-6 * np.max(np.abs(e_fd)))


@pytest.mark.parametrize("name", UNITS)
def test_rod_motion_chain_rule_nonuniform_rotation(name):
    """Non-uniform crank rotation theta(t) = w0 t + 0.1 sin t (a prescribed law, as in
    [SK8Rotation2013]'s non-uniform rotation study): omega = w0 + 0.1 cos t, epsilon = -0.1 sin t.
    Then v(t) = ds/dt and a(t) = dv/dt must hold with the package's chain rule
    a = A (psi'' omega^2 + psi' epsilon). Finite differences in t, dt = 1e-5 s,
    tolerance 1e-6 of the peak (truncation ~1e-10, rounding ~1e-11 relative)."""
    lk = UNITS[name]
    w0 = 1.2

    def theta(t):
        return w0 * t + 0.1 * np.sin(t)

    def omega(t):
        return w0 + 0.1 * np.cos(t)

    def epsilon(t):
        return -0.1 * np.sin(t)

    def at(t):
        return _exact(lk, theta(t), omega(t), epsilon(t))

    t = np.linspace(0.0, 12.0, 400)
    dt = 1e-5
    now, plus, minus = at(t), at(t + dt), at(t - dt)
    v_fd = (plus.position - minus.position) / (2 * dt)
    a_fd = (plus.velocity - minus.velocity) / (2 * dt)
    np.testing.assert_allclose(now.velocity, v_fd, rtol=0, atol=1e-6 * np.max(np.abs(v_fd)))
    np.testing.assert_allclose(now.acceleration, a_fd, rtol=0, atol=1e-6 * np.max(np.abs(a_fd)))
    # the epsilon term matters here: dropping it would miss by far more than the tolerance
    uniform_only = _exact(lk, theta(t), omega(t), 0.0)
    assert np.max(np.abs(uniform_only.acceleration - a_fd)) > 1e-3 * np.max(np.abs(a_fd))


def test_rod_motion_position_measured_from_bottom():
    """s = 0 at the bottom dead position and s = stroke at the top."""
    dead = dead_positions(SK8_LINKAGE)
    rm = _exact(SK8_LINKAGE, [dead.crank_angle_bottom, dead.crank_angle_top], OMEGA)
    assert rm.position[0] == pytest.approx(0.0, abs=1e-12)
    assert rm.position[1] == pytest.approx(SK8_LINKAGE.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom), rel=1e-12)


# --- approximations -----------------------------------------------------------------


def test_harmonic_motion_textbook_values_and_derivatives():
    """Simple harmonic motion s = r (1 - cos wt): s = 0, r, 2r at phi = 0, pi/2, pi;
    v = ds/dt and a = dv/dt by central differences (dt = 1e-5 s, tolerance 1e-7 of peak:
    truncation dt^2/6 r w^3 ~ 1e-10 r w^3)."""
    r, w = 0.73, 1.9
    m = harmonic_motion(r, np.array([0.0, np.pi / 2, np.pi, 3 * np.pi / 2]), w)
    np.testing.assert_allclose(m.position, [0.0, r, 2 * r, r], atol=1e-15)
    np.testing.assert_allclose(m.velocity, [0.0, r * w, 0.0, -r * w], atol=1e-15)
    # acceleration at the bottom is +r w^2 (upwards, the rod is pulled up from rest)
    np.testing.assert_allclose(m.acceleration, [r * w**2, 0.0, -r * w**2, 0.0], atol=1e-14)
    t = np.linspace(0.0, 2 * np.pi / w, 97)
    dt = 1e-5
    now = harmonic_motion(r, w * t, w)
    plus, minus = harmonic_motion(r, w * (t + dt), w), harmonic_motion(r, w * (t - dt), w)
    np.testing.assert_allclose(now.velocity, (plus.position - minus.position) / (2 * dt), atol=1e-7 * r * w)
    np.testing.assert_allclose(now.acceleration, (plus.velocity - minus.velocity) / (2 * dt), atol=1e-7 * r * w**2)


@pytest.mark.parametrize("lam", [0.1, 0.25, 0.4])
def test_two_term_motion_derivatives(lam):
    """Velocity and acceleration of the two-term law are its time derivatives (same
    finite-difference budget as for harmonic motion, scaled by 1 + lambda)."""
    r, w = 0.61, 1.3
    t = np.linspace(0.0, 2 * np.pi / w, 97)
    dt = 1e-5
    now = two_term_motion(r, lam, w * t, w)
    plus, minus = two_term_motion(r, lam, w * (t + dt), w), two_term_motion(r, lam, w * (t - dt), w)
    np.testing.assert_allclose(now.velocity, (plus.position - minus.position) / (2 * dt), atol=1e-7 * r * w)
    np.testing.assert_allclose(now.acceleration, (plus.velocity - minus.velocity) / (2 * dt), atol=1e-7 * r * w**2)
    # stroke of the two-term law is still 2 r (sin^2 = 0 at both ends)
    ends = two_term_motion(r, lam, np.array([0.0, np.pi]), w)
    np.testing.assert_allclose(ends.position, [0.0, 2 * r], atol=1e-15)


@pytest.mark.parametrize("lam", [0.02, 0.05, 0.1])
def test_two_term_is_series_of_exact_slider_crank(lam):
    """In-line slider-crank, slider displacement from the dead centre (Pythagoras on the
    crank-rod triangle: the rod's projection on the line of stroke is
    L sqrt(1 - lam^2 sin^2 phi)): x = R(1 - cos phi) + L(1 - sqrt(1 - lam^2 sin^2 phi)).
    Expanding the square root, x = R[(1 - cos phi) + (lam/2) sin^2 phi] + R lam^3 sin^4(phi)/8
    + O(lam^5): the two-term law is the first-order series ([NUNG] eqs. 5.12-5.13 per the
    module docstring). Tolerance: the first neglected term R lam^3/8, times 1.1 for the
    O(lam^5) rest."""
    r_crank = 1.0
    length = r_crank / lam
    phi = np.linspace(0.0, 2 * np.pi, 721)
    exact = r_crank * (1 - np.cos(phi)) + length * (1 - np.sqrt(1 - lam**2 * np.sin(phi) ** 2))
    approx = two_term_motion(r_crank, lam, phi, 1.0).position
    bound = 1.1 * r_crank * lam**3 / 8
    assert np.max(np.abs(approx - exact)) <= bound
    # ... and it is a genuine improvement on the harmonic law (error O(lam) there)
    harm = harmonic_motion(r_crank, phi, 1.0).position
    assert np.max(np.abs(harm - exact)) > 0.4 * r_crank * lam


def test_two_term_with_zero_ratio_is_harmonic():
    phi = np.linspace(-1.0, 8.0, 301)
    a = two_term_motion(0.8, 0.0, phi, 1.7)
    b = harmonic_motion(0.8, phi, 1.7)
    for x, y in ((a.position, b.position), (a.velocity, b.velocity), (a.acceleration, b.acceleration)):
        np.testing.assert_allclose(x, y, rtol=1e-15, atol=1e-15)


def _small_crank_unit(ratio: float) -> Linkage:
    """Crank much shorter than pitman and frame, I = C and H - G = P so that the pitman
    is vertical and the beam horizontal at mid-stroke: the exact motion then tends to
    simple harmonic motion of amplitude R A / C ([NUNG] textbook, elementary theory)."""
    c, p = 2.5, 3.0
    return Linkage(front_arm=3.5, rear_arm=c, crank_radius=ratio * p, pitman=p, horizontal_offset=c, vertical_offset=p)


def _harmonic_errors(lk: Linkage):
    omega = 1.0
    kin = uniform_kinematics(lk, omega, steps=720)
    dead = dead_positions(lk)
    harm = harmonic_motion(lk.crank_radius * lk.front_arm / lk.rear_arm, kin.crank_angle - dead.crank_angle_bottom, omega)
    exact = kin.rod
    return (
        np.max(np.abs(harm.position - exact.position)) / kin.summary.stroke,
        np.max(np.abs(harm.acceleration - exact.acceleration)) / np.max(np.abs(exact.acceleration)),
    )


def test_exact_motion_tends_to_harmonic_for_small_crank():
    """With R/P = 0.001 the exact law differs from the harmonic one by O(R/P) ~ 0.1 %
    (second-harmonic term lam cos 2 phi of the slider-crank); assert < 1 %. The error
    must also shrink roughly in proportion to R/P: going from R/P = 0.01 to 0.001 it
    must drop by at least a factor 5 (first-order theory predicts 10)."""
    pos_small, acc_small = _harmonic_errors(_small_crank_unit(0.001))
    pos_big, acc_big = _harmonic_errors(_small_crank_unit(0.01))
    assert acc_small < 0.01
    assert pos_small < 0.01
    assert acc_small < acc_big / 5
    assert pos_small < pos_big / 5


def test_summary_harmonic_error_matches_independent_grid():
    """summary.approximation_errors['harmonic'] (computed on the package's 7200-point
    grid) agrees with the same definitions evaluated on our own 9973-point grid; the
    difference is only the sampling of smooth maxima: a sampled maximum is low by at most
    1/2 |f''/f| (h/2)^2 relative, ~1e-6 for h = 8.7e-4 rad and |f''/f| <= 10 (curves
    with up to the third harmonic of the crank angle), so 1e-5 is a safe bound."""
    lk = SK8_LINKAGE
    kin = uniform_kinematics(lk, OMEGA)
    dead = dead_positions(lk)
    theta = np.arange(9973) * 2 * np.pi / 9973
    exact = _exact(lk, theta, OMEGA)
    amp = lk.crank_radius * lk.front_arm / lk.rear_arm
    for name, approx in (
        ("harmonic", harmonic_motion(amp, theta - dead.crank_angle_bottom, OMEGA)),
        ("two_term", two_term_motion(amp, lk.crank_radius / lk.pitman, theta - dead.crank_angle_bottom, OMEGA)),
    ):
        err = kin.summary.approximation_errors[name]
        stroke = lk.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom)
        assert err.position == pytest.approx(np.max(np.abs(approx.position - exact.position)) / stroke, rel=1e-5)
        assert err.velocity == pytest.approx(
            np.max(np.abs(approx.velocity - exact.velocity)) / np.max(np.abs(exact.velocity)), rel=1e-5)
        assert err.acceleration == pytest.approx(
            np.max(np.abs(approx.acceleration - exact.acceleration)) / np.max(np.abs(exact.acceleration)), rel=1e-5)
        peak = np.max(np.abs(approx.acceleration)) / np.max(np.abs(exact.acceleration)) - 1
        assert err.peak_acceleration == pytest.approx(peak, abs=1e-5)


def test_approximations_in_result_use_crank_travel_from_bottom():
    """result.approximations are evaluated at phi = theta - theta_bottom with amplitude
    R A / C and lambda = R / P (module docstring)."""
    lk = SK8_LINKAGE
    kin = uniform_kinematics(lk, OMEGA, steps=180)
    dead = dead_positions(lk)
    amp = lk.crank_radius * lk.front_arm / lk.rear_arm
    phi = kin.crank_angle - dead.crank_angle_bottom
    h = harmonic_motion(amp, phi, OMEGA)
    np.testing.assert_allclose(kin.approximations["harmonic"].position, amp * (1 - np.cos(phi)), atol=1e-14)
    np.testing.assert_allclose(kin.approximations["harmonic"].acceleration, h.acceleration, atol=1e-14)
    lam = lk.crank_radius / lk.pitman
    np.testing.assert_allclose(kin.approximations["two_term"].acceleration,
                               amp * OMEGA**2 * (np.cos(phi) + lam * np.cos(2 * phi)), atol=1e-13)


# --- summary ------------------------------------------------------------------------


def _true_extreme(f, theta_guess: float, h: float) -> tuple[float, float]:
    """Maximum of f near theta_guess by bounded Brent search (xatol 1e-10 rad)."""
    res = minimize_scalar(lambda x: -f(x), bounds=(theta_guess - 2 * h, theta_guess + 2 * h), method="bounded",
                          options={"xatol": 1e-10})
    return -res.fun, res.x


@pytest.mark.parametrize("name", UNITS)
def test_summary_stroke_and_travel(name):
    lk = UNITS[name]
    s = uniform_kinematics(lk, OMEGA).summary
    n = 9973
    h = 2 * np.pi / n
    theta = np.arange(n) * h
    pos = _exact(lk, theta, OMEGA).position
    # sampled range is within 1/2 max|s''| (h/2)^2 of the true one (bounded via the
    # sampled second difference, safety factor 1.5)
    curvature = np.max(np.abs(np.roll(pos, 1) - 2 * pos + np.roll(pos, -1))) / h**2
    resolution = 1.5 * 0.5 * curvature * (h / 2) ** 2
    assert pos.max() - pos.min() <= s.stroke + 1e-12
    assert pos.max() - pos.min() >= s.stroke - 2 * resolution
    assert s.upstroke_crank_travel + s.downstroke_crank_travel == pytest.approx(2 * np.pi, rel=1e-15)
    assert 0 < s.upstroke_crank_travel < 2 * np.pi
    # upstroke travel from the grid: from the argmin to the argmax of the position in
    # the direction of rotation; within two grid steps of the summary's value
    up = ((np.argmax(pos) - np.argmin(pos)) % n) * h
    assert s.upstroke_crank_travel == pytest.approx(up, abs=2 * h)
    assert s.period == pytest.approx(2 * np.pi / OMEGA, rel=1e-15)
    assert s.crank_speed == OMEGA


@pytest.mark.parametrize("name", UNITS)
def test_summary_extremes_agree_with_dense_maxima(name):
    """Each extreme (value and crank angle) against a Brent refinement of the maximum of
    a 9973-point grid. Values: 1e-7 relative to the peak (the package refines a 7200-
    point grid by a parabola, error O(h^3) ~ 1e-9). Angles: at an extreme the curve is
    flat, so its location is less accurate than its value: the vertex of a three-point
    parabola is off by O(h^2 f'''/f'') ~ 1e-6 rad for the package's step h = 8.7e-4 rad;
    1e-5 rad leaves a factor 10 (and is 1/87 of a grid step, so an unrefined argmax
    would fail)."""
    lk = UNITS[name]
    omega = OMEGA
    s = uniform_kinematics(lk, omega).summary
    n = 9973
    h = 2 * np.pi / n
    theta = np.arange(n) * h

    def velocity(x):
        return float(_exact(lk, np.array([x]), omega).velocity[0])

    def acceleration(x):
        return float(_exact(lk, np.array([x]), omega).acceleration[0])

    def torque_factor(x):
        return float(lk.front_arm * motion(lk, np.array([x])).beam_rate[0])

    for f, hi, lo in (
        (velocity, s.max_velocity, s.min_velocity),
        (acceleration, s.max_acceleration, s.min_acceleration),
        (torque_factor, s.max_torque_factor, s.min_torque_factor),
    ):
        samples = np.array([f(x) for x in theta[::7]])  # coarse locate (every 7th point)
        peak = np.max(np.abs(samples))
        for extreme, sign in ((hi, 1.0), (lo, -1.0)):
            guess = theta[::7][int(np.argmax(sign * samples))]
            value, where = _true_extreme(lambda x: sign * f(x), guess, 7 * h)
            assert sign * extreme.value == pytest.approx(value, abs=1e-7 * peak)
            assert abs(_wrap(extreme.crank_angle - where)) < 1e-5
            assert 0 <= extreme.crank_angle < 2 * np.pi


def _wrap(x):
    return (x + np.pi) % (2 * np.pi) - np.pi


@pytest.mark.parametrize("name", UNITS)
def test_summary_does_not_depend_on_steps(name):
    lk = UNITS[name]
    a = uniform_kinematics(lk, OMEGA, steps=360).summary
    b = uniform_kinematics(lk, OMEGA, steps=37).summary
    c = uniform_kinematics(lk, OMEGA, steps=4001).summary
    for other in (b, c):
        for field in ("stroke", "period", "crank_angle_bottom", "crank_angle_top", "upstroke_crank_travel",
                      "downstroke_crank_travel"):
            assert getattr(other, field) == pytest.approx(getattr(a, field), rel=1e-12, abs=1e-15)
        for field in ("max_velocity", "min_velocity", "max_acceleration", "min_acceleration",
                      "max_torque_factor", "min_torque_factor"):
            assert getattr(other, field).value == pytest.approx(getattr(a, field).value, rel=1e-12)
            assert getattr(other, field).crank_angle == pytest.approx(getattr(a, field).crank_angle, abs=1e-12)
        for key, err in a.approximation_errors.items():
            assert other.approximation_errors[key].acceleration == pytest.approx(err.acceleration, rel=1e-12)
            assert other.approximation_errors[key].position == pytest.approx(err.position, rel=1e-12)


def test_result_arrays_follow_steps():
    kin = uniform_kinematics(SK8_LINKAGE, OMEGA, steps=50)
    np.testing.assert_allclose(kin.crank_angle, np.arange(50) * 2 * np.pi / 50, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(crank_grid(50), kin.crank_angle)
    for arr in (kin.rod.position, kin.rod.velocity, kin.rod.acceleration, kin.torque_factor, kin.beam_angle,
                kin.pitman_angular_acceleration, kin.approximations["harmonic"].position):
        assert arr.shape == (50,)


@pytest.mark.parametrize("omega", [0.0, -1.0, -1e-12, float("nan")])
def test_uniform_kinematics_rejects_nonpositive_omega(omega):
    with pytest.raises(ValueError, match="positive"):
        uniform_kinematics(SK8_LINKAGE, omega)


def test_velocity_scales_with_omega():
    """v = A psi' omega is linear in omega and a = A psi'' omega^2 quadratic."""
    k1 = uniform_kinematics(SK8_LINKAGE, 1.0, steps=90)
    k3 = uniform_kinematics(SK8_LINKAGE, 3.0, steps=90)
    np.testing.assert_allclose(k3.rod.velocity, 3 * k1.rod.velocity, rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(k3.rod.acceleration, 9 * k1.rod.acceleration, rtol=1e-14, atol=1e-13)
    np.testing.assert_allclose(k3.rod.position, k1.rod.position, rtol=0, atol=0)
    assert math.isclose(k3.summary.max_velocity.value, 3 * k1.summary.max_velocity.value, rel_tol=1e-12)
