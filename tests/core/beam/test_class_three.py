"""The class III four-bar (Mark II, air-balanced) against an independent solution of its own loop.

The reference here does not use the mirror of ``core/beam/class_three.py``: it solves the
class III vector loop directly (Newton's method on the beam angle from the constraint
|B - A| = P, started at the level beam), with the crank shaft O = (+I, -(H - G)) ahead of the
centre bearing and the equalizer B = +C (cos psi, sin psi) on the horsehead side, and takes
every derivative by central finite differences of that solution (step h, error O(h²)).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pumpjack_cli.core.beam.class_three import ClassThreeLinkage
from pumpjack_cli.core.beam.geometry import CLOCKWISE, COUNTERCLOCKWISE, Linkage
from pumpjack_cli.core.beam.inertia_laws import chord_motion
from pumpjack_cli.errors import GeometryError

#: A class III four-bar of Mark II proportions [m]: the crank shaft a little behind the equalizer
#: bearing (I < C), as the Mark II's cross yoke sits ahead of the crank shaft.
UNIT = dict(front_arm=5.33, rear_arm=3.05, crank_radius=1.19, pitman=3.77, horizontal_offset=2.9, vertical_offset=3.6)
#: Finite-difference step [rad]: truncation ~h² |f'''| / 6, rounding ~1e-16 |f| / h.
H = 1e-4


def _pin(unit: dict, rotation: int, theta: np.ndarray) -> np.ndarray:
    o = np.array([unit["horizontal_offset"], -unit["vertical_offset"]])[:, None]
    return o + unit["crank_radius"] * np.stack([rotation * np.sin(theta), np.cos(theta)])


def _beam_angle(unit: dict, rotation: int, theta: np.ndarray) -> np.ndarray:
    """psi with |C e(psi) - A(theta)| = P, Newton from the level beam (the equalizer above the pin)."""
    a = _pin(unit, rotation, theta)
    c, p = unit["rear_arm"], unit["pitman"]
    psi = np.zeros_like(theta)
    for _ in range(60):
        b = c * np.stack([np.cos(psi), np.sin(psi)])
        f = np.sum((b - a) ** 2, axis=0) - p * p
        df = 2.0 * np.sum((b - a) * c * np.stack([-np.sin(psi), np.cos(psi)]), axis=0)
        psi = psi - f / df
    b = c * np.stack([np.cos(psi), np.sin(psi)])
    assert np.all(np.abs(np.hypot(*(b - a)) - p) < 1e-12) and np.all(b[1] > a[1])
    return psi


def _fd(f, theta: np.ndarray, order: int = 1) -> np.ndarray:
    if order == 1:
        return (f(theta + H) - f(theta - H)) / (2 * H)
    return (f(theta + H) - 2 * f(theta) + f(theta - H)) / H**2


@pytest.mark.parametrize("rotation", [CLOCKWISE, COUNTERCLOCKWISE])
def test_the_mirror_matches_the_direct_solution_of_the_class_three_loop(rotation):
    unit = ClassThreeLinkage(**UNIT, rotation=rotation)
    theta = np.linspace(0.0, 2 * np.pi, 721)
    m = unit.motion(theta)
    psi = _beam_angle(UNIT, rotation, theta)
    assert m.beam_angle == pytest.approx(psi, abs=1e-12)
    # the polished rod on the horsehead arc, from the bottom of the stroke
    assert m.rod_position == pytest.approx(UNIT["front_arm"] * (psi - psi.min()), abs=1e-5)
    assert m.beam_rate == pytest.approx(_fd(lambda t: _beam_angle(UNIT, rotation, t), theta), abs=1e-7)
    assert m.beam_rate2 == pytest.approx(_fd(lambda t: _beam_angle(UNIT, rotation, t), theta, 2), abs=2e-5)
    # the pitman's direction A -> B
    a = _pin(UNIT, rotation, theta)
    b = UNIT["rear_arm"] * np.stack([np.cos(psi), np.sin(psi)])
    assert np.cos(m.pitman_angle) == pytest.approx((b - a)[0] / UNIT["pitman"], abs=1e-12)
    assert np.sin(m.pitman_angle) == pytest.approx((b - a)[1] / UNIT["pitman"], abs=1e-12)


@pytest.mark.parametrize("rotation", [CLOCKWISE, COUNTERCLOCKWISE])
def test_torque_factor_is_the_derivative_of_the_polished_rod_position(rotation):
    unit = ClassThreeLinkage(**UNIT, rotation=rotation)
    theta = np.linspace(0.0, 2 * np.pi, 1441)
    tf = unit.motion(theta).torque_factor
    peak = np.abs(tf).max()
    assert np.abs(tf - _fd(unit.rod_position, theta)).max() < 1e-6 * peak
    rate = unit.motion(theta).torque_factor_rate
    assert np.abs(rate - _fd(unit.torque_factor, theta)).max() < 1e-6 * np.abs(rate).max()


@pytest.mark.parametrize("rotation", [CLOCKWISE, COUNTERCLOCKWISE])
def test_joint_rates_are_the_derivatives_of_the_joints(rotation):
    unit = ClassThreeLinkage(**UNIT, rotation=rotation)
    theta = np.linspace(0.0, 2 * np.pi, 361)
    rates = unit.joint_rates(unit.motion(theta))

    def equalizer(t):
        psi = unit.motion(t).beam_angle
        return UNIT["rear_arm"] * np.stack([np.cos(psi), np.sin(psi)])

    assert rates.crank_pin_rate == pytest.approx(_fd(lambda t: _pin(UNIT, rotation, t), theta), abs=1e-8)
    assert rates.crank_pin_rate2 == pytest.approx(_fd(lambda t: _pin(UNIT, rotation, t), theta, 2), abs=1e-6)
    assert rates.equalizer_rate == pytest.approx(_fd(equalizer, theta), abs=1e-7)
    assert rates.equalizer_rate2 == pytest.approx(_fd(equalizer, theta, 2), abs=5e-5)


@pytest.mark.parametrize("rotation", [CLOCKWISE, COUNTERCLOCKWISE])
def test_dead_positions_are_the_ends_of_the_stroke(rotation):
    unit = ClassThreeLinkage(**UNIT, rotation=rotation)
    dead = unit.dead_positions()
    ends = unit.motion(np.array([dead.crank_angle_bottom, dead.crank_angle_top]))
    assert ends.rod_position == pytest.approx([0.0, unit.stroke], abs=1e-12)
    assert ends.torque_factor == pytest.approx([0.0, 0.0], abs=1e-9)
    s = unit.rod_position(np.linspace(0.0, 2 * np.pi, 100_001))
    assert s.min() == pytest.approx(0.0, abs=1e-8) and s.max() == pytest.approx(unit.stroke, abs=1e-8)
    # the rod rises from the bottom through the upstroke travel
    up = dead.crank_angle_bottom + rotation * 0 + np.linspace(0.0, dead.upstroke_crank_travel, 50)[1:-1]
    assert np.all(unit.torque_factor(up) > 0)


@pytest.mark.parametrize("rotation", [CLOCKWISE, COUNTERCLOCKWISE])
def test_rod_motion_is_the_motion_to_the_bit(rotation):
    """The time fit's position and torque factor (rod_motion) are the motion's, to the bit."""
    unit = ClassThreeLinkage(**UNIT, rotation=rotation)
    theta = np.random.default_rng(4).uniform(-20.0, 20.0, 20_000)
    position, torque_factor = unit.rod_motion(theta)
    m = unit.motion(theta)
    assert np.array_equal(position, m.rod_position) and np.array_equal(torque_factor, m.torque_factor)


def test_the_mirror_identity_with_the_class_one_unit():
    # same letters: the class III unit has the class I stroke; turning one way, its upstroke
    # takes the crank travel of the class I upstroke turning the same way, and its dead
    # positions lie elsewhere on the crank circle (the phase tells the classes apart)
    for rotation in (CLOCKWISE, COUNTERCLOCKWISE):
        three = ClassThreeLinkage(**UNIT, rotation=rotation)
        one = Linkage(**UNIT, rotation=rotation)
        assert three.stroke == pytest.approx(one.stroke, rel=1e-12)
        assert three.dead_positions().upstroke_crank_travel == pytest.approx(
            one.dead_positions().upstroke_crank_travel, rel=1e-12)
        apart = (three.dead_positions().crank_angle_bottom - one.dead_positions().crank_angle_bottom) % (2 * np.pi)
        assert math.radians(60) < apart < math.radians(300)


def test_counterclockwise_gives_the_longer_upstroke_when_the_crank_shaft_is_behind_the_equalizer():
    # I < C (the cross yoke ahead of the crank shaft): counterclockwise, the Mark II's rotation,
    # lifts the rods over more than half a turn; clockwise over less
    ccw = ClassThreeLinkage(**UNIT, rotation=COUNTERCLOCKWISE).dead_positions().upstroke_crank_travel
    cw = ClassThreeLinkage(**UNIT, rotation=CLOCKWISE).dead_positions().upstroke_crank_travel
    assert ccw > math.pi > cw
    assert ccw + cw == pytest.approx(2 * math.pi, rel=1e-12)


def test_chord_law_ends_at_the_dead_positions():
    unit = ClassThreeLinkage(**UNIT, rotation=COUNTERCLOCKWISE)
    dead = unit.dead_positions()
    s = chord_motion(unit, np.array([dead.crank_angle_bottom, dead.crank_angle_top]), 1.0).position
    # the chord is shorter than the arc it spans: 2 A sin(swing / 2) against A swing
    swing = dead.beam_angle_top - dead.beam_angle_bottom
    assert s[0] == pytest.approx(0.0, abs=1e-12)
    assert s[1] == pytest.approx(2 * UNIT["front_arm"] * math.sin(swing / 2), rel=1e-9)


def test_a_unit_that_cannot_turn_is_refused():
    with pytest.raises(GeometryError, match="cannot assemble"):
        ClassThreeLinkage(**{**UNIT, "crank_radius": 3.0}).check()


@settings(max_examples=30, deadline=None)
@given(a=st.floats(3.0, 7.0), c=st.floats(2.0, 4.0), r=st.floats(0.5, 1.4), p=st.floats(3.0, 4.5),
       i=st.floats(1.0, 4.0), h=st.floats(2.5, 4.5), rotation=st.sampled_from([CLOCKWISE, COUNTERCLOCKWISE]))
def test_any_class_three_unit_conserves_energy(a, c, r, p, i, h, rotation):
    # the rod position returns after a turn and TF integrates to zero over it (virtual work of
    # a constant load over a cycle), for any unit that turns
    unit = ClassThreeLinkage(a, c, r, p, i, h, rotation)
    try:
        unit.check()
    except GeometryError:
        assume(False)
    theta = np.linspace(0.0, 2 * np.pi, 4097)
    tf = unit.torque_factor(theta)
    assert abs(np.trapezoid(tf, theta)) < 1e-9 * unit.stroke
