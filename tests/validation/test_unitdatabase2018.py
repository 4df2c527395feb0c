"""Validation of the kinematics against an operator's unit database ([UnitDatabase2018]): the
conventional unit C-228D-213-86 (the unit of `pumpjack report`'s example) and the Mark II
M-912D-365-168 of [LufkinM912], whose letters the database repeats independently.

The database gives A = 111, C = 96.05, I = 96, K = 151.34 (the centre bearing to the crank
shaft, so H - G = sqrt(K^2 - I^2)) and P = 114 in, four crank holes 37, 32, 27 and 22 in, and
the stroke of the first hole, 88.35 in, to two decimals. Its row prints C = 96.5 in, a typing
slip: that value gives 87.86 in, and the test says so.
"""

from __future__ import annotations

import math

import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.class_three import ClassThreeLinkage
from pumpjack_cli.core.beam.geometry import CLOCKWISE, COUNTERCLOCKWISE, Linkage

from helpers import INCH, POUND_FORCE

LETTERS = dict(front_arm=111.0, rear_arm=96.05, pitman=114.0, horizontal_offset=96.0,
               vertical_offset=math.sqrt(151.34**2 - 96.0**2))


def stroke(radius: float, **changed) -> float:
    """The exact stroke [in] of a crank hole (lengths in inches: the kinematics is homogeneous in length)."""
    return Linkage(**{**LETTERS, **changed}, crank_radius=radius, rotation=CLOCKWISE).stroke


def test_the_longest_hole_gives_the_stored_stroke():
    assert stroke(37.0) == pytest.approx(88.35, abs=0.005)


def test_the_rows_c_is_a_slip_for_the_structures_96_05_in():
    assert abs(stroke(37.0, rear_arm=96.5) - 88.35) > 0.4


def test_the_holes_shorten_the_stroke_in_turn_and_the_upstroke_is_near_half_a_turn():
    strokes = [stroke(r) for r in (37.0, 32.0, 27.0, 22.0)]
    assert strokes == sorted(strokes, reverse=True)
    # the stroke is nearly proportional to the crank radius times A / C (the small-angle lever)
    for radius, found in zip((37.0, 32.0, 27.0, 22.0), strokes):
        assert found == pytest.approx(2.0 * radius * 111.0 / 96.05, rel=0.04)
    dead = Linkage(**LETTERS, crank_radius=37.0, rotation=CLOCKWISE).dead_positions()
    assert 180.0 < math.degrees(dead.upstroke_crank_travel) < 190.0


def test_the_bundled_unit_is_the_database_unit():
    unit = load_unit("c-228d-213-86")
    assert unit.geometry.mechanism().stroke == pytest.approx(88.35 * INCH, abs=0.005 * INCH)
    balance, _ = unit.counterbalance_model()
    assert balance.structural_unbalance == pytest.approx(450 * POUND_FORCE)
    rated = unit.ratings()
    assert rated.gearbox_torque == pytest.approx(228_000 * POUND_FORCE * INCH)
    assert rated.max_stroke == pytest.approx(86 * INCH)


def test_the_mark_ii_first_hole_gives_the_stored_stroke():
    """M-912D-365-168 (rows 2223-2224): A 334, C 270, I 202.56, K 272.98, P 193.5 in, R1 = 63.56 in,
    stored stroke 168.04 in; K agrees with the H - G = 183.00 in of [LufkinM912] to 0.01 in."""
    vertical = math.sqrt(272.98**2 - 202.56**2)
    assert vertical == pytest.approx(295.13 - 112.13, abs=0.01)
    mark_ii = ClassThreeLinkage(front_arm=334.0, rear_arm=270.0, pitman=193.5, horizontal_offset=202.56,
                                vertical_offset=vertical, crank_radius=63.56, rotation=COUNTERCLOCKWISE)
    assert mark_ii.stroke == pytest.approx(168.04, abs=0.01)
