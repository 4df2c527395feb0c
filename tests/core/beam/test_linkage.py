"""Tests of pumpjack_cli.core.beam.linkage against an independent vector-loop formulation.

The reference solution here does NOT use the cosine rule of the package. It solves the
planar vector loop of the four-bar numerically (Newton's method on two unknowns) and
obtains the derivatives from the differentiated loop (Bour's method: a 2x2 linear
system per crank angle). Conventions are those of the linkage.py module docstring:

* origin at the centre bearing, x towards the well, y up;
* crank shaft O = (-I, -(H - G));
* crank pin A = O + R (rotation * sin theta, cos theta);
* equalizer bearing B = -C (cos psi, sin psi)  (= C e(psi + pi));
* pitman angle chi = direction of A -> B, so A + P e(chi) = B.

Loop:  F(chi, psi) = O + R a(theta) + P e(chi) + C e(psi) = 0,
with e(x) = (cos x, sin x), a(theta) = (s sin theta, cos theta), s = rotation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.core.beam.geometry import (CLOCKWISE, COUNTERCLOCKWISE, MIN_TRANSMISSION_ANGLE, Linkage,
                                             assembly_angle, check_assembly, dead_positions)
from pumpjack_cli.core.beam.linkage import _beam_angle, crank_pin, motion, rod_motion
from pumpjack_cli.errors import GeometryError

from helpers import INCH

# SK8-3,5-4000 geometry as given in the brief and in configs/sk8-3.5-4000.toml
# ([SK8Rotation2013] data): A = 3.5, C = 2.5, R = 1.01, P = 3.0, I = 2.195, H - G = 3.0 m.
SK8 = dict(front_arm=3.5, rear_arm=2.5, crank_radius=1.01, pitman=3.0, horizontal_offset=2.195, vertical_offset=3.0)

# API unit C-114D-133-54, Guo, Lyons & Ghalambor [Guo2007], "Petroleum Production Engineering",
# Elsevier 2007, Table 12.1 (p. 12/167): A=72, C=64, I=64, P=74.5, H=116, G=41, R1=24 in.
C114 = dict(
    front_arm=72 * INCH,
    rear_arm=64 * INCH,
    crank_radius=24 * INCH,
    pitman=74.5 * INCH,
    horizontal_offset=64 * INCH,
    vertical_offset=(116 - 41) * INCH,
)

GEOMETRIES = {"SK8-3,5-4000": SK8, "C-114D-133-54": C114}
ROTATIONS = {"cw": CLOCKWISE, "ccw": COUNTERCLOCKWISE}

# Crank angles for the comparisons: a full turn at 0.5 deg, plus angles outside
# [0, 2 pi) to exercise the periodic handling of theta.
ANGLES = np.concatenate([np.radians(np.arange(0.0, 360.0, 0.5)), np.array([-2.0, -0.3, 7.0, 12.5])])


def _e(x: float) -> np.ndarray:
    return np.array([math.cos(x), math.sin(x)])


def _e_perp(x: float) -> np.ndarray:
    """d e(x) / dx."""
    return np.array([-math.sin(x), math.cos(x)])


def _wrap(x):
    """Angle difference mapped into (-pi, pi]."""
    return (np.asarray(x) + np.pi) % (2.0 * np.pi) - np.pi


def independent_loop(lk: Linkage, thetas: np.ndarray) -> dict[str, np.ndarray]:
    """Solve the vector loop by Newton's method with continuation and differentiate it.

    Returns chi, psi and their first and second derivatives w.r.t. theta, plus the
    positions of A and B, all computed without the package's formulas.
    """
    r, p, c, s = lk.crank_radius, lk.pitman, lk.rear_arm, lk.rotation
    o = np.array([-lk.horizontal_offset, -lk.vertical_offset])
    # Initial guess for the first angle: pitman vertical (pointing up from the crank
    # pin), beam horizontal -- the mid-stroke posture of every conventional unit.
    chi, psi = math.pi / 2, 0.0
    out = {k: [] for k in ("chi", "psi", "chi1", "psi1", "chi2", "psi2", "A", "B")}
    for theta in thetas:
        a_vec = np.array([s * math.sin(theta), math.cos(theta)])
        a1 = np.array([s * math.cos(theta), -math.sin(theta)])  # d a / d theta
        a2 = np.array([-s * math.sin(theta), -math.cos(theta)])  # d2 a / d theta2
        for _ in range(60):
            f = o + r * a_vec + p * _e(chi) + c * _e(psi)
            jac = np.column_stack([p * _e_perp(chi), c * _e_perp(psi)])
            step = np.linalg.solve(jac, -f)
            chi += step[0]
            psi += step[1]
            if abs(step[0]) + abs(step[1]) < 1e-15:
                break
        f = o + r * a_vec + p * _e(chi) + c * _e(psi)
        assert np.max(np.abs(f)) < 1e-13 * (r + p + c), "reference Newton iteration did not converge"
        jac = np.column_stack([p * _e_perp(chi), c * _e_perp(psi)])
        # first derivative: R a' + P e_perp(chi) chi' + C e_perp(psi) psi' = 0
        chi1, psi1 = np.linalg.solve(jac, -r * a1)
        # second derivative: R a'' + P (e_perp chi'' - e chi'^2) + C (e_perp psi'' - e psi'^2) = 0
        rhs = -r * a2 + p * _e(chi) * chi1**2 + c * _e(psi) * psi1**2
        chi2, psi2 = np.linalg.solve(jac, rhs)
        pin = o + r * a_vec
        out["chi"].append(chi)
        out["psi"].append(psi)
        out["chi1"].append(chi1)
        out["psi1"].append(psi1)
        out["chi2"].append(chi2)
        out["psi2"].append(psi2)
        out["A"].append(pin)
        out["B"].append(pin + p * _e(chi))
    return {k: np.array(v) for k, v in out.items()}


@pytest.fixture(scope="module", params=[(g, rot) for g in GEOMETRIES for rot in ROTATIONS], ids=lambda x: f"{x[0]}-{x[1]}")
def case(request):
    name, rot = request.param
    lk = Linkage(**GEOMETRIES[name], rotation=ROTATIONS[rot])
    return lk, independent_loop(lk, ANGLES), motion(lk, ANGLES)


def test_reference_is_on_the_conventional_branch(case):
    """Sanity of the reference itself: the pitman points up from the crank pin to the
    equalizer bearing, and the equalizer bearing is behind the centre bearing (x < 0),
    as in every conventional (class I) unit ([API11E] fig. 1)."""
    lk, ref, _ = case
    assert np.all(np.sin(ref["chi"]) > 0.5)
    assert np.all(ref["B"][:, 0] < 0.0)


def test_positions_match_independent_loop(case):
    """Closed form vs. Newton solution of the vector loop, 1e-9 m.

    Tolerance: both are double-precision solutions of the same well-conditioned
    equations on metre-size links (errors ~1e-15 m); 1e-9 m leaves room for the
    conditioning of arccos away from toggle, yet catches any formula slip.
    """
    lk, ref, m = case
    a = lk.front_arm
    b_code = -lk.rear_arm * np.stack([np.cos(m.beam_angle), np.sin(m.beam_angle)], axis=1)
    np.testing.assert_allclose(b_code, ref["B"], rtol=0, atol=1e-9)
    # polished-rod arc A psi (angles compared modulo 2 pi)
    np.testing.assert_allclose(a * _wrap(m.beam_angle - ref["psi"]), 0.0, rtol=0, atol=1e-9)
    # pitman direction, as the displacement of its far end: P * d(chi)
    np.testing.assert_allclose(lk.pitman * _wrap(m.pitman_angle - ref["chi"]), 0.0, rtol=0, atol=1e-9)
    # crank pin convention A = O + R (s sin theta, cos theta)
    np.testing.assert_allclose(crank_pin(lk, ANGLES).T, ref["A"], rtol=0, atol=1e-12)


def test_first_derivatives_match_bour(case):
    """beam_rate, pitman_rate vs. the differentiated loop (2x2 linear system), 1e-9
    relative to the largest rate (rates cross zero, so a pointwise relative bound would
    be meaningless there). Both are exact formulas evaluated in double precision."""
    lk, ref, m = case
    for code, key in ((m.beam_rate, "psi1"), (m.pitman_rate, "chi1")):
        scale = np.max(np.abs(ref[key]))
        np.testing.assert_allclose(code, ref[key], rtol=0, atol=1e-9 * scale)


def test_second_derivatives_match_bour(case):
    """beam_rate2, pitman_rate2 vs. the twice differentiated loop, 1e-9 relative to
    the largest value (same reasoning as for the first derivatives)."""
    lk, ref, m = case
    for code, key in ((m.beam_rate2, "psi2"), (m.pitman_rate2, "chi2")):
        scale = np.max(np.abs(ref[key]))
        np.testing.assert_allclose(code, ref[key], rtol=0, atol=1e-9 * scale)


@pytest.mark.parametrize("name", GEOMETRIES)
@pytest.mark.parametrize("rot", ROTATIONS.values())
def test_loop_closure(name, rot):
    """|B - A| = P at every crank angle (1e-12 relative: pure rounding of a few
    trigonometric evaluations on O(1) lengths)."""
    lk = Linkage(**GEOMETRIES[name], rotation=rot)
    theta = np.linspace(-np.pi, 3 * np.pi, 2001)
    m = motion(lk, theta)
    a = crank_pin(lk, theta)
    b = -lk.rear_arm * np.stack([np.cos(m.beam_angle), np.sin(m.beam_angle)])
    np.testing.assert_allclose(np.hypot(*(b - a)), lk.pitman, rtol=1e-12, atol=0)
    # the pitman angle is the direction of A -> B
    np.testing.assert_allclose(b - a, lk.pitman * np.stack([np.cos(m.pitman_angle), np.sin(m.pitman_angle)]),
                               rtol=0, atol=1e-12 * lk.pitman)


def test_crank_pin_convention_clockwise_points_to_well():
    """[API11E]: theta from 12 o'clock in the direction of rotation. Clockwise seen
    with the well to the right means the pin is at 3 o'clock (towards the well, +x) at
    theta = 90 deg; counterclockwise puts it at 9 o'clock (-x)."""
    cw = Linkage(**SK8, rotation=CLOCKWISE)
    ccw = Linkage(**SK8, rotation=COUNTERCLOCKWISE)
    o = np.array([-2.195, -3.0])
    np.testing.assert_allclose(crank_pin(cw, np.pi / 2), o + [1.01, 0.0], atol=1e-15)
    np.testing.assert_allclose(crank_pin(ccw, np.pi / 2), o + [-1.01, 0.0], atol=1e-15)
    np.testing.assert_allclose(crank_pin(cw, 0.0), o + [0.0, 1.01], atol=1e-15)


# --- dead positions ----------------------------------------------------------------


@pytest.mark.parametrize("name", GEOMETRIES)
@pytest.mark.parametrize("rot", ROTATIONS.values())
def test_dead_positions(name, rot):
    lk = Linkage(**GEOMETRIES[name], rotation=rot)
    dead = dead_positions(lk)
    m = motion(lk, np.array([dead.crank_angle_bottom, dead.crank_angle_top]))
    # the beam stops at the dead positions: psi' = 0 (1e-9: psi' ~ 0.3 elsewhere, the
    # residual is rounding of the dead-angle computation)
    np.testing.assert_allclose(m.beam_rate, 0.0, atol=1e-9)
    # the beam angle returned agrees with the motion at that crank angle
    np.testing.assert_allclose(m.beam_angle, [dead.beam_angle_bottom, dead.beam_angle_top], atol=1e-12)
    # and with the independent loop solution
    ref = independent_loop(lk, np.array([dead.crank_angle_bottom, dead.crank_angle_top]))
    np.testing.assert_allclose(ref["psi"], [dead.beam_angle_bottom, dead.beam_angle_top], atol=1e-12)
    np.testing.assert_allclose(ref["psi1"], 0.0, atol=1e-9)

    # extremes over a dense grid: no sample may exceed them, and the sampled extremes
    # lie within the grid resolution of them: |psi - psi_ext| <= 1/2 max|psi''| (h/2)^2.
    n = 3600
    h = 2 * np.pi / n
    psi = motion(lk, np.arange(n) * h).beam_angle
    curvature = np.max(np.abs(np.roll(psi, 1) - 2 * psi + np.roll(psi, -1))) / h**2  # from samples only
    resolution = 1.5 * 0.5 * curvature * (h / 2) ** 2  # 1.5: safety on the curvature estimate
    assert psi.max() <= dead.beam_angle_top + 1e-12
    assert psi.min() >= dead.beam_angle_bottom - 1e-12
    assert psi.max() >= dead.beam_angle_top - resolution
    assert psi.min() <= dead.beam_angle_bottom + resolution
    assert dead.beam_angle_top > dead.beam_angle_bottom

    # stretched position (|OB| = P + R, crank and pitman in line) is the bottom for a
    # conventional unit ([SK8Rotation2013]); folded (|OB| = P - R) is the top.
    o = lk.crank_shaft
    for theta_dead, reach in ((dead.crank_angle_bottom, lk.pitman + lk.crank_radius),
                              (dead.crank_angle_top, lk.pitman - lk.crank_radius)):
        b = independent_loop(lk, np.array([theta_dead]))["B"][0]
        assert np.hypot(*(b - o)) == pytest.approx(reach, rel=1e-12)


# --- assembly check ----------------------------------------------------------------


def _sk8(**changes) -> Linkage:
    return Linkage(**{**SK8, **changes})


def test_check_assembly_accepts_real_units():
    check_assembly(Linkage(**SK8))
    check_assembly(Linkage(**C114, rotation=COUNTERCLOCKWISE))


def test_check_assembly_crank_too_large():
    # K = hypot(2.195, 3) = 3.717 m; K + R = 6.72 m > P + C = 5.5 m
    with pytest.raises(GeometryError) as info:
        check_assembly(_sk8(crank_radius=3.0))
    msg = str(info.value)
    assert "cannot assemble" in msg
    for word in ("crank_radius", "pitman", "rear_arm"):
        assert word in msg


def test_check_assembly_pitman_too_short():
    # K + R = 4.73 m > P + C = 0.5 + 2.5 = 3.0 m
    with pytest.raises(GeometryError, match="cannot assemble") as info:
        check_assembly(_sk8(pitman=0.5))
    assert "pitman" in str(info.value)


def test_check_assembly_pitman_too_long_folds():
    # K - R = 2.707 m <= |P - C| = |6 - 2.5| = 3.5 m: pitman and rear arm fold past each other
    with pytest.raises(GeometryError, match="cannot assemble") as info:
        check_assembly(_sk8(pitman=6.0))
    msg = str(info.value)
    assert "crank_radius" in msg and "fold" in msg


def test_check_assembly_offsets_too_large():
    # moving the crank shaft far away: K = hypot(5, 3) = 5.83 m, K + R > P + C
    with pytest.raises(GeometryError, match="cannot assemble"):
        check_assembly(_sk8(horizontal_offset=5.0))


@pytest.mark.parametrize(
    "geometry",
    [
        # K + R == P + C exactly (K = 3, R = 1, P = C = 2): a toggle, must be rejected
        dict(front_arm=1.0, rear_arm=2.0, crank_radius=1.0, pitman=2.0, horizontal_offset=0.0, vertical_offset=3.0),
        # K - R == |P - C| exactly (K = 3, R = 1, P = 4, C = 2)
        dict(front_arm=1.0, rear_arm=2.0, crank_radius=1.0, pitman=4.0, horizontal_offset=0.0, vertical_offset=3.0),
    ],
    ids=["stretched-toggle", "folded-toggle"],
)
def test_check_assembly_strict_at_toggle(geometry):
    """The docstring says the Grashof conditions are strict (no toggle allowed)."""
    with pytest.raises(GeometryError, match="cannot assemble"):
        check_assembly(Linkage(**geometry))


@pytest.mark.parametrize("field", ["front_arm", "rear_arm", "crank_radius", "pitman"])
@pytest.mark.parametrize("value", [0.0, -1.0, float("nan")])
def test_check_assembly_nonpositive_length(field, value):
    with pytest.raises(GeometryError, match=field):
        check_assembly(_sk8(**{field: value}))


def test_motion_and_dead_positions_refuse_unassemblable():
    bad = _sk8(crank_radius=3.0)
    with pytest.raises(GeometryError):
        motion(bad, np.array([0.0]))
    with pytest.raises(GeometryError):
        dead_positions(bad)


# --- the fast paths equal the reference formulas to the bit ---------------------------


@pytest.mark.parametrize("name", GEOMETRIES)
def test_beam_angle_is_assembly_angle_to_the_bit(name):
    """The wrap of _beam_angle by one subtraction gives numpy.mod's result exactly, on both of its
    branches: points X all around the centre bearing at every distance the cosine rule allows
    (|P - C| to P + C), so that psi + pi falls below and above 2 pi."""
    lk = Linkage(**GEOMETRIES[name])
    rng = np.random.default_rng(5)
    distance = rng.uniform(abs(lk.pitman - lk.rear_arm), lk.pitman + lk.rear_arm, 200_000)
    direction = rng.uniform(-np.pi, np.pi, distance.size)
    x, y = distance * np.cos(direction), distance * np.sin(direction)
    expected = assembly_angle(x, y, lk.pitman, lk.rear_arm, np)
    assert np.array_equal(_beam_angle(lk, x, y), expected, equal_nan=True)
    shifted = np.arctan2(y, x) + np.arccos((lk.pitman**2 - lk.rear_arm**2 - distance**2) / (2 * lk.rear_arm * distance))
    assert np.any(shifted + np.pi >= 2 * np.pi) and np.any(shifted + np.pi < 2 * np.pi)


@pytest.mark.parametrize("rot", ROTATIONS)
@pytest.mark.parametrize("name", GEOMETRIES)
def test_rod_motion_is_motion_to_the_bit(name, rot):
    """rod_motion's rearranged quotient rounds as motion's: position and torque factor equal to the
    bit at 100 000 crank angles, within and beyond one turn."""
    lk = Linkage(**GEOMETRIES[name], rotation=ROTATIONS[rot])
    theta = np.concatenate([np.random.default_rng(6).uniform(-20.0, 20.0, 50_000), np.linspace(0.0, 2 * np.pi, 50_000)])
    position, torque_factor = rod_motion(lk, theta)
    m = motion(lk, theta)
    assert np.array_equal(position, m.rod_position) and np.array_equal(torque_factor, m.torque_factor)


# --- mirror symmetry ---------------------------------------------------------------


@pytest.mark.parametrize("name", GEOMETRIES)
def test_mirror_symmetry(name):
    """Reversing rotation and the sign of theta puts the crank pin at the same place:
    psi_ccw(-theta) = psi_cw(theta); differentiating, psi_ccw'(-theta) = -psi_cw'(theta)
    and psi_ccw''(-theta) = psi_cw''(theta). Tolerance 1e-12: sin(-x) = -sin(x) exactly
    in IEEE arithmetic, so only rounding in the formulas differs."""
    theta = np.linspace(0.0, 2 * np.pi, 721)
    cw = motion(Linkage(**GEOMETRIES[name], rotation=CLOCKWISE), theta)
    ccw = motion(Linkage(**GEOMETRIES[name], rotation=COUNTERCLOCKWISE), -theta)
    np.testing.assert_allclose(ccw.beam_angle, cw.beam_angle, rtol=0, atol=1e-12)
    np.testing.assert_allclose(ccw.beam_rate, -cw.beam_rate, rtol=0, atol=1e-12)
    np.testing.assert_allclose(ccw.beam_rate2, cw.beam_rate2, rtol=0, atol=1e-12)
    np.testing.assert_allclose(ccw.pitman_angle, cw.pitman_angle, rtol=0, atol=1e-12)
    np.testing.assert_allclose(ccw.pitman_rate, -cw.pitman_rate, rtol=0, atol=1e-12)
    np.testing.assert_allclose(ccw.pitman_rate2, cw.pitman_rate2, rtol=0, atol=1e-12)
    # dead positions mirror as well: theta_ccw = 2 pi - theta_cw, same beam angles
    d_cw = dead_positions(Linkage(**GEOMETRIES[name], rotation=CLOCKWISE))
    d_ccw = dead_positions(Linkage(**GEOMETRIES[name], rotation=COUNTERCLOCKWISE))
    assert d_ccw.beam_angle_bottom == pytest.approx(d_cw.beam_angle_bottom, abs=1e-12)
    assert d_ccw.beam_angle_top == pytest.approx(d_cw.beam_angle_top, abs=1e-12)
    assert _wrap(d_ccw.crank_angle_bottom + d_cw.crank_angle_bottom) == pytest.approx(0.0, abs=1e-12)
    assert _wrap(d_ccw.crank_angle_top + d_cw.crank_angle_top) == pytest.approx(0.0, abs=1e-12)


# --- property tests on random assemblable geometries --------------------------------


@st.composite
def geometries(draw):
    """Realistic conventional-unit proportions, metres (SK8 and API units fall inside)."""
    r = draw(st.floats(0.2, 1.5))
    p = draw(st.floats(1.5, 5.0))
    c = draw(st.floats(1.0, 4.0))
    i = draw(st.floats(0.0, 4.0))
    v = draw(st.floats(1.0, 5.0))
    a = draw(st.floats(1.0, 6.0))
    rot = draw(st.sampled_from([CLOCKWISE, COUNTERCLOCKWISE]))
    k = math.hypot(i, v)
    # Grashof crank-rocker conditions with a 10 % of K margin from toggle: real units stay
    # far from it, and within a few % of a toggle psi'' peaks so sharply (hundreds of
    # 1/rad^2 over a few degrees) that no fixed finite-difference step checks it to 1e-6
    assume(k + r < p + c - 0.1 * k)
    assume(k - r > abs(p - c) + 0.1 * k)
    linkage = Linkage(a, c, r, p, i, v, rot)
    try:   # and a transmission angle the package accepts
        check_assembly(linkage)
    except GeometryError:
        assume(False)
    return linkage


PROPERTY_SETTINGS = settings(max_examples=60, deadline=None)


@PROPERTY_SETTINGS
@given(geometries())
def test_property_loop_closure_and_periodicity(lk):
    theta = np.linspace(0.0, 2 * np.pi, 361)
    m = motion(lk, theta)
    a = crank_pin(lk, theta)
    b = -lk.rear_arm * np.stack([np.cos(m.beam_angle), np.sin(m.beam_angle)])
    np.testing.assert_allclose(np.hypot(*(b - a)), lk.pitman, rtol=1e-12, atol=0)
    # 360 deg periodicity; 1e-10 absolute covers the rounding of theta + 2 pi (~1e-15)
    # amplified by psi' (< 10 at 10 % of K from toggle)
    shifted = motion(lk, theta + 2 * np.pi)
    np.testing.assert_allclose(_wrap(shifted.beam_angle - m.beam_angle), 0.0, atol=1e-10)
    np.testing.assert_allclose(shifted.beam_rate, m.beam_rate, rtol=0, atol=1e-10 * np.max(np.abs(m.beam_rate)))
    np.testing.assert_allclose(shifted.beam_rate2, m.beam_rate2, rtol=0, atol=1e-10 * np.max(np.abs(m.beam_rate2)))


@PROPERTY_SETTINGS
@given(geometries())
def test_property_rates_are_derivatives(lk):
    """psi' = numerical derivative of psi, psi'' = numerical derivative of psi'.

    Fourth-order central differences, h = 1e-3 rad: truncation h^4/30 |f^(5)| and
    rounding ~1e-16 |f| / h stay below the 1e-6 bound (relative to the largest |psi'|
    resp. |psi''| over the turn, since the rates cross zero) for geometries at least
    10 % of K away from a toggle (see :func:`geometries`).
    """
    h = 1e-3
    theta = np.linspace(0.0, 2 * np.pi, 181, endpoint=False) + 0.01
    m = motion(lk, theta)
    p1, m1, p2, m2 = (motion(lk, theta + d) for d in (h, -h, 2 * h, -2 * h))

    def derivative(name, wrap=False):
        step = (lambda x: _wrap(x)) if wrap else (lambda x: x)
        return (8 * step(getattr(p1, name) - getattr(m1, name)) - step(getattr(p2, name) - getattr(m2, name))) / (12 * h)

    fd1 = derivative("beam_angle", wrap=True)
    np.testing.assert_allclose(m.beam_rate, fd1, rtol=0, atol=1e-6 * np.max(np.abs(m.beam_rate)))
    fd2 = derivative("beam_rate")
    np.testing.assert_allclose(m.beam_rate2, fd2, rtol=0, atol=1e-6 * np.max(np.abs(m.beam_rate2)))
    fdc = derivative("pitman_rate")
    np.testing.assert_allclose(m.pitman_rate2, fdc, rtol=0, atol=1e-6 * np.max(np.abs(m.pitman_rate2)))
    fdc1 = derivative("pitman_angle", wrap=True)
    np.testing.assert_allclose(m.pitman_rate, fdc1, rtol=0, atol=1e-6 * np.max(np.abs(m.pitman_rate)))


@PROPERTY_SETTINGS
@given(geometries())
def test_property_stroke(lk):
    """Stroke = A (psi_top - psi_bottom) = range of the polished-rod position, and every
    position lies in [0, stroke]."""
    dead = dead_positions(lk)
    kin = uniform_kinematics(lk, 1.0, steps=720)
    stroke = kin.summary.stroke
    assert stroke == pytest.approx(lk.front_arm * (dead.beam_angle_top - dead.beam_angle_bottom), rel=1e-12)
    # dense grid; sampled extremes within 1/2 max|s''| (h/2)^2 of the true ones
    n = 7919  # prime, so the grid does not contain the package's own 7200-point grid
    h = 2 * np.pi / n
    theta = np.arange(n) * h + 0.123
    psi = motion(lk, theta).beam_angle
    s = lk.front_arm * (psi - dead.beam_angle_bottom)
    curvature = np.max(np.abs(np.roll(s, 1) - 2 * s + np.roll(s, -1))) / h**2
    resolution = 1.5 * 0.5 * curvature * (h / 2) ** 2 + 1e-12 * lk.front_arm
    assert s.min() >= -1e-12 * lk.front_arm
    assert s.max() <= stroke + 1e-12 * lk.front_arm
    assert s.max() - s.min() == pytest.approx(stroke, abs=2 * resolution)
    pos = kin.rod.position
    assert pos.min() >= -1e-12 * lk.front_arm
    assert pos.max() <= stroke + 1e-12 * lk.front_arm


def test_a_four_bar_near_its_toggle_is_refused():
    """SK8-3,5-4000's four-bar with the crank 1 mm short of the toggle (K + R = P + C - 1 mm): pitman and
    rear arm stand within a degree of a line, where the beam's acceleration grows without bound (the
    helper found it change threefold with the grid); refused. A crank that keeps them 12 deg from a
    line passes."""
    k = math.hypot(2.195, 3.0)
    with pytest.raises(GeometryError, match="near a toggle: with the crank pin farthest from the centre bearing"):
        check_assembly(Linkage(3.5, 2.5, 5.5 - k - 1e-3, 3.0, 2.195, 3.0))
    # the crank at which the far transmission angle is 180 - 12 deg: (K + R)^2 = P^2 + C^2 - 2 P C cos(168 deg)
    reach = math.sqrt(3.0**2 + 2.5**2 - 2 * 3.0 * 2.5 * math.cos(math.radians(180.0 - 12.0)))
    assert MIN_TRANSMISSION_ANGLE < 12.0
    check_assembly(Linkage(3.5, 2.5, reach - k, 3.0, 2.195, 3.0))
