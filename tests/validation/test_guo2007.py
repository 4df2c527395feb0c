"""Validation of the exact kinematics against a published table of API units.

Source [Guo2007]: Guo B., Lyons W.C., Ghalambor A., "Petroleum Production Engineering: A
Computer-Assisted Approach", Elsevier 2007, Table 12.1 (p. 12/167), "Conventional
pumping units API geometry dimensions". It lists A, C, I, P, H, G and the crank holes
R1 > R2 > R3 in inches, and a "Torque factor" column: the [API11E] torque factor
TF = ds/dtheta at crank angle 90 deg for the longest hole R1, rotation clockwise with
the well to the right (the API convention), in inches.

Our torque factor is TF = A psi'(90 deg) (module kinematics docstring). Lengths are
given to the package in inches directly: the kinematics is homogeneous of degree one in
length, so TF comes out in inches.
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.core.beam.geometry import CLOCKWISE, COUNTERCLOCKWISE, Linkage, dead_positions
from pumpjack_cli.core.beam.linkage import motion

from helpers import INCH

# (designation, A, C, I, P, H, G, R1, TF) -- Guo, Lyons & Ghalambor 2007, Table 12.1, p. 12/167
TABLE_12_1 = [
    ("C-114D-133-54", 72, 64, 64, 74.5, 116, 41, 24, 26.45),
    ("C-80D-133-48", 64, 64, 64, 74.5, 116, 41, 24, 23.51),
    ("C-P57D-76-54", 64, 51, 51, 64, 103, 39, 21, 25.8),
    ("C-80D-109-48", 64, 56.05, 56, 65.63, 105, 37, 21, 23.3),
    ("C-P57D-109-48", 57, 51, 51, 64, 103, 39, 21, 22.98),
    ("C-40D-76-48", 64, 48.17, 48, 57.5, 98.5, 37, 18, 23.1),
    ("C-P40D-76-48", 61, 47, 47, 56, 95, 39, 18, 22.92),
    ("C-P57D-89-42", 51, 51, 51, 64, 103, 39, 21, 20.56),
    ("C-P40D-89-42", 53, 47, 47, 56, 95, 39, 18, 19.92),
    ("C-P40D-89-36", 47, 47, 47, 56, 95, 39, 18, 17.66),
    ("C-25D-67-30", 45, 36.22, 36, 49.5, 84.5, 31, 12, 14.53),
]

# Two further rows of the same table share C, I, P, H, G, R1 with C-40D-76-48 and differ
# only in A:  C-57D-89-42 (A = 56, printed TF 20.27) and C-40D-89-36 (A = 48, printed
# TF 17.37). The beam angle psi(theta) does not involve A, so TF = A psi' must be
# proportional to A: from C-40D-76-48 (A = 64, TF 23.1) they should read
# 23.1 * 56/64 = 20.21 and 23.1 * 48/64 = 17.33. The printed 20.27 and 17.37 are off by
# 0.06 and 0.04 in, far beyond rounding: a table inconsistency (most likely those rows
# were computed with slightly different dimensions than printed). We therefore do NOT
# assert their printed values; test_tf_proportional_to_front_arm checks the
# proportionality instead.
SAME_LINKAGE_AS_C40D_76_48 = [("C-40D-76-48", 64), ("C-57D-89-42", 56), ("C-40D-89-36", 48)]


def _linkage(a, c, i, p, h, g, r, rotation=CLOCKWISE) -> Linkage:
    return Linkage(front_arm=a, rear_arm=c, crank_radius=r, pitman=p, horizontal_offset=i,
                   vertical_offset=h - g, rotation=rotation)


def _tf90(lk: Linkage) -> float:
    return float(lk.front_arm * motion(lk, np.array([np.pi / 2])).beam_rate[0])


@pytest.mark.parametrize("row", TABLE_12_1, ids=[r[0] for r in TABLE_12_1])
def test_torque_factor_at_90_degrees(row):
    """Tolerance 0.01 in: one unit of the table's last printed digit (the printed TF is
    rounded to 0.005 in, and the printed dimensions such as C = 36.22 in are themselves
    rounded, which moves TF by a few thousandths of an inch)."""
    _, a, c, i, p, h, g, r, tf = row
    assert _tf90(_linkage(a, c, i, p, h, g, r)) == pytest.approx(tf, abs=0.01)


@pytest.mark.parametrize("row", TABLE_12_1, ids=[r[0] for r in TABLE_12_1])
def test_torque_factor_from_uniform_kinematics(row):
    """The same through the public per-angle result: steps = 4 puts a grid point exactly
    at 90 deg (crank_grid starts at 0 with step 360/steps)."""
    _, a, c, i, p, h, g, r, tf = row
    kin = uniform_kinematics(_linkage(a, c, i, p, h, g, r), 1.0, steps=4)
    assert kin.crank_angle[1] == pytest.approx(np.pi / 2, abs=1e-15)
    assert kin.torque_factor[1] == pytest.approx(tf, abs=0.01)


def test_tf_proportional_to_front_arm():
    """TF / A is the same for linkages differing only in A (1e-12 relative: psi' does
    not involve A at all)."""
    base = TABLE_12_1[[r[0] for r in TABLE_12_1].index("C-40D-76-48")]
    _, _, c, i, p, h, g, r, _ = base
    ratios = [_tf90(_linkage(a, c, i, p, h, g, r)) / a for _, a in SAME_LINKAGE_AS_C40D_76_48]
    assert ratios[1] == pytest.approx(ratios[0], rel=1e-12)
    assert ratios[2] == pytest.approx(ratios[0], rel=1e-12)
    # and the proportional values, not the printed 20.27 / 17.37, are what we compute:
    # 23.1 * 56/64 = 20.2125 and 23.1 * 48/64 = 17.325 (tolerance 0.01 in, as above)
    assert _tf90(_linkage(56, c, i, p, h, g, r)) == pytest.approx(23.1 * 56 / 64, abs=0.01)
    assert _tf90(_linkage(48, c, i, p, h, g, r)) == pytest.approx(23.1 * 48 / 64, abs=0.01)


def test_counterclockwise_does_not_reproduce_table():
    """The table is for clockwise rotation (API convention, well to the right). With the
    crank turning the other way, crank angle 90 deg is the 9 o'clock position and TF
    differs by more than 1 in (far outside the 0.01 in match of the clockwise case)."""
    _, a, c, i, p, h, g, r, tf = TABLE_12_1[0]
    ccw = _tf90(_linkage(a, c, i, p, h, g, r, rotation=COUNTERCLOCKWISE))
    assert abs(ccw - tf) > 1.0
    assert _tf90(_linkage(a, c, i, p, h, g, r, rotation=CLOCKWISE)) == pytest.approx(tf, abs=0.01)


def test_stroke_close_to_nominal():
    """C-114D-133-54: the designation's last field is the nominal stroke, 54 in (API
    Spec 11E designation: type - reducer rating kin-lbf - structure rating 100 lbf -
    stroke in). Nominal strokes are rounded, so allow 3 %."""
    _, a, c, i, p, h, g, r, _ = TABLE_12_1[0]
    lk = _linkage(a, c, i, p, h, g, r)
    dead = dead_positions(lk)
    stroke = a * (dead.beam_angle_top - dead.beam_angle_bottom)
    assert stroke == pytest.approx(54.0, rel=0.03)
    # the kinematics summary reports the same stroke (inch input, inch output)
    assert uniform_kinematics(lk, 1.0).summary.stroke == pytest.approx(stroke, rel=1e-12)


def test_bundled_config_matches_table():
    """configs/c-114d-133-54.toml holds the table's inches, converted to metres
    (1e-12 relative covers the float conversion)."""
    unit = load_unit("c-114d-133-54")
    geo = unit.geometry
    _, a, c, i, p, h, g, r, tf = TABLE_12_1[0]
    assert unit.name == "C-114D-133-54"
    assert geo.front_arm == pytest.approx(a * INCH, rel=1e-12)
    assert geo.rear_arm == pytest.approx(c * INCH, rel=1e-12)
    assert geo.horizontal_offset == pytest.approx(i * INCH, rel=1e-12)
    assert geo.pitman == pytest.approx(p * INCH, rel=1e-12)
    assert geo.vertical_offset == pytest.approx((h - g) * INCH, rel=1e-12)
    assert geo.crank_radius == pytest.approx(r * INCH, rel=1e-12)
    assert geo.rotation == "clockwise"
    lk = geo.mechanism()
    assert lk.rotation == CLOCKWISE
    # and the SI linkage reproduces the table's torque factor, converted back to inches
    assert _tf90(lk) / INCH == pytest.approx(tf, abs=0.01)
