"""Validation of the kinematics against an operator's unit database ([UnitDatabase2018]): the
conventional unit C-228D-213-86 (the unit of `pumpjack report`'s example), the Mark II
M-912D-365-168 of [LufkinM912], whose letters the database repeats independently, seven
Lufkin reverse-mark rows, with the sign of their crank offset, ten Lufkin air-balanced rows and
the one Lufkin beam-balanced row.

The database gives A = 111, C = 96.05, I = 96, K = 151.34 (the centre bearing to the crank
shaft, so H - G = sqrt(K^2 - I^2)) and P = 114 in, four crank holes 37, 32, 27 and 22 in, and
the stroke of the first hole, 88.35 in, to two decimals. Its row prints C = 96.5 in, a typing
slip: that value gives 87.86 in, and the test says so.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.class_three import ClassThreeLinkage
from pumpjack_cli.core.beam.counterbalance import Counterbalance
from pumpjack_cli.core.beam.geometry import CLOCKWISE, COUNTERCLOCKWISE, Linkage
from pumpjack_cli.core.rods.predict import predict_cards

from helpers import INCH, POUND_FORCE

LETTERS = dict(front_arm=111.0, rear_arm=96.05, pitman=114.0, horizontal_offset=96.0,
               vertical_offset=math.sqrt(151.34**2 - 96.0**2))


def stroke(radius: float, **changed) -> float:
    """The exact stroke [in] of a crank hole (lengths in inches: the kinematics is homogeneous in length)."""
    return Linkage(**{**LETTERS, **changed}, crank_radius=radius, rotation=CLOCKWISE).stroke


def class_three(a: float, c: float, i: float, k: float, p: float, r: float, rotation: int) -> ClassThreeLinkage:
    """The class III four-bar of a database row's letters A, C, I, K, P and crank radius R [in]
    (K the centre bearing to the crank shaft, so H - G = sqrt(K^2 - I^2))."""
    return ClassThreeLinkage(front_arm=a, rear_arm=c, pitman=p, horizontal_offset=i,
                             vertical_offset=math.sqrt(k**2 - i**2), crank_radius=r, rotation=rotation)


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


#: Lufkin reverse-mark rows of the database: row, designation, A, C, I, K, P, the first hole's R [in],
#: its stored stroke [in], B [lb] and the phase angle [deg] as stored. Rows 2058, 2060, 2061 and 2063
#: (the C = 92 in structure) store K = 200.73 in, the next structure's: with it the unit cannot
#: assemble (K + R > P + C), a slip, so they are left out.
REVERSE_MARK = (
    (2056, "RM-114D-119-74", 96.0, 73.0, 104.0, 147.08, 110.0, 25.75, 74.0, 140.0, -14.0),
    (2057, "RM-228D-173-74", 89.0, 92.0, 127.0, 179.6, 134.0, 35.0, 74.0, 680.0, -14.0),
    (2062, "RM-228D-213-120", 144.5, 103.0, 142.0, 200.73, 149.0, 39.0, 120.0, 40.0, -14.0),
    (2076, "RM-456D-305-168", 202.0, 103.0, 142.0, 200.73, 149.0, 39.0, 168.0, -1580.0, -14.0),
    (2078, "RM-456D-365-144", 178.0, 118.0, 153.0, 223.56, 171.0, 45.0, 144.3, -170.0, -9.0),
    (2084, "RM-640D-305-192", 228.5, 118.0, 163.0, 230.51, 171.0, 45.0, 192.0, -1600.0, -12.0),
    (2086, "RM-640D-365-168", 200.0, 118.0, 163.0, 230.51, 171.0, 45.0, 168.0, -695.0, -12.0),
)


def reverse_mark_file(row: tuple, well: str = "") -> str:
    """The unit file of a reverse-mark row (lengths in inches), with an optional [well]."""
    _, name, a, c, i, k, p, r, _, b, tau = row
    return (f'name = "{name}"\ndesignation = "{name}"\n[geometry]\nclass = "reverse-mark"\nA = "{a} in"\n'
            f'C = "{c} in"\nI = "{i} in"\nK = "{k} in"\nP = "{p} in"\nR = "{r} in"\nrotation = "clockwise"\n'
            f'crank_offset = "{tau} deg"\n[counterbalance]\nstructural_unbalance = "{b} lbf"\n{well}')


@pytest.mark.parametrize("row", REVERSE_MARK, ids=[row[1] for row in REVERSE_MARK])
def test_a_reverse_mark_row_gives_its_stroke_and_a_long_clockwise_upstroke(tmp_path, row):
    """The rear working centre shifted forward (C < I) and clockwise rotation, as [LufkinRM] runs
    them: the exact stroke of the first hole within 0.25 in of the stored one (a nominal stroke,
    rounded), and an upstroke of more than half a turn (about 186-194 deg is the usual
    statement), as a Mark II's counterclockwise."""
    path = tmp_path / "unit.toml"
    path.write_text(reverse_mark_file(row), encoding="utf-8")
    unit = load_unit(str(path))
    assert unit.geometry.unit_class == "reverse-mark" and row[3] < row[4]
    mechanism = unit.geometry.mechanism()
    assert mechanism.stroke / INCH == pytest.approx(row[8], abs=0.25)
    assert 185.0 < math.degrees(mechanism.dead_positions().upstroke_crank_travel) < 195.0


def test_the_reverse_mark_offset_is_a_lag_where_the_balance_is_best(tmp_path):
    """RM-640D-365-168 stores a phase angle of -12 deg. On a card predicted by the wave equation
    (an illustrative 8000 ft well at 5 strokes/min), the moment with the least peak torque is found
    for every offset from -40 to +40 deg: read as tau of T = TF (W - B) - M sin(theta + tau), a lead
    of -12 deg (the counterweights lag the pin) is within 5 % of the least peak and the best offset
    is a lag too; read the other way (+12 deg) the peak is more than 1.5 times larger. So the
    class I tau is a lead and a catalogue's negative offset a lag (docs/conventions.md)."""
    well = ('[well]\npump_depth = "8000 ft"\nplunger_diameter = "1.5 in"\n'
            'rod_string = [{ diameter = "1 in", fraction = "45 %", grade = "D" }, '
            '{ diameter = "0.875 in", fraction = "55 %", grade = "D" }]\n'
            'fluid_density = "950 kg/m3"\npump_submergence = "300 ft"\ntubing_inner_diameter = "2.441 in"\n')
    path = tmp_path / "rm.toml"
    path.write_text(reverse_mark_file(REVERSE_MARK[-1], well), encoding="utf-8")
    unit = load_unit(str(path))
    balance, _ = unit.counterbalance_model()
    assert balance.offset == pytest.approx(math.radians(-12.0)) and not balance.tail
    mechanism = unit.geometry.mechanism()
    cards = predict_cards(mechanism, 5.0 * math.pi / 30.0, unit.rods(), unit.pump(), damping=0.05,
                          fluid_density=unit.well.fluid_density, samples=720)
    motion = mechanism.motion(cards.crank_angle)
    base = motion.torque_factor * cards.polished_rod_load + balance.structural_torque(motion)
    moments = np.linspace(0.0, 3.0 * np.abs(base).max(), 1201)

    def least_peak(offset_deg: float) -> float:
        per_moment = Counterbalance(0.0, 1.0, math.radians(offset_deg)).counterbalance_torque(motion)
        return float(np.abs(base[None, :] + moments[:, None] * per_moment[None, :]).max(axis=1).min())

    offsets = np.arange(-40.0, 41.0, 2.0)
    peaks = np.array([least_peak(t) for t in offsets])
    assert offsets[np.argmin(peaks)] < 0.0
    assert least_peak(-12.0) < 1.05 * peaks.min()
    assert least_peak(12.0) > 1.5 * least_peak(-12.0)


#: Lufkin Mark II rows: row, designation, A, C, I, K, P, the first hole's R [in] and its stroke as
#: the database stores it, to two decimals (an exact stroke, not a nominal one).
MARK_II = (
    (2108, "M-114D-143-64", 189.0, 162.0, 111.0, 146.42, 107.93, 24.18, 64.1),
    (2112, "M-114D-143-86", 189.0, 162.0, 111.0, 146.42, 112.18, 32.25, 86.03),
    (2119, "M-114D-200-74", 222.0, 186.0, 124.0, 169.37, 130.5, 27.25, 73.96),
    (2122, "M-160D-173-86", 222.0, 186.0, 124.0, 169.37, 135.75, 31.5, 86.05),
    (2133, "M-228D-173-100", 312.0, 258.0, 186.0, 244.69, 173.75, 37.62, 100.0),
    (2140, "M-228D-213-120", 312.0, 258.0, 186.0, 244.69, 173.75, 45.12, 120.02),
    (2151, "M-320D-253-144", 312.0, 258.0, 186.0, 244.69, 182.37, 53.75, 144.08),
    (2177, "M-456D-305-168", 334.0, 270.0, 202.56, 272.98, 193.5, 63.56, 168.05),
)


@pytest.mark.parametrize("row", MARK_II, ids=[row[1] for row in MARK_II])
def test_a_mark_ii_row_gives_its_stored_stroke_and_a_long_counterclockwise_upstroke(row):
    """Five Mark II structures, eight units: the exact class III stroke within 0.02 in of the
    stored one (rounding of the letters and of the stroke), and counterclockwise an upstroke of
    more than half a turn, 188-199 deg ([LufkinMarkII]: about 195 deg)."""
    _, _, a, c, i, k, p, r, stored = row
    mark_ii = class_three(a, c, i, k, p, r, COUNTERCLOCKWISE)
    assert mark_ii.stroke == pytest.approx(stored, abs=0.02)
    assert 188.0 < math.degrees(mark_ii.dead_positions().upstroke_crank_travel) < 199.0


@pytest.mark.parametrize("size", ["228D-213-120", "456D-305-168"])
def test_a_reverse_marks_upstroke_is_shorter_than_the_mark_iis_of_its_size(tmp_path, size):
    """The two sizes the database holds in both kinds, each turning its standard way: the reverse-mark's
    upstroke is shorter than the Mark II's (191.6 against 193.6 and 193.7 deg), both longer than half
    a turn. (Read as "less than 180 deg", #22's "a reverse-mark's less" would contradict every
    reverse-mark row.)"""
    reverse = next(row for row in REVERSE_MARK if row[1] == f"RM-{size}")
    _, _, a, c, i, k, p, r, _ = next(row for row in MARK_II if row[1] == f"M-{size}")
    path = tmp_path / "unit.toml"
    path.write_text(reverse_mark_file(reverse), encoding="utf-8")
    reverse_mark = load_unit(str(path)).geometry.mechanism().dead_positions().upstroke_crank_travel
    mark_ii = class_three(a, c, i, k, p, r, COUNTERCLOCKWISE).dead_positions().upstroke_crank_travel
    assert math.pi < reverse_mark < mark_ii
    assert math.degrees(mark_ii - reverse_mark) > 1.5


#: Lufkin air-balanced rows of the database (class "A") whose stored stroke is not a whole number of
#: inches, i.e. an exact stroke rather than a nominal one: row, designation, A, C, I, K, P, the first
#: hole's R [in] and its stored stroke as printed. Row 1672 (A320D-256-120) stores 121.71 in with the
#: letters of row 1673, which give 119.77 in and store 119.8 in: its letters are not its structure's,
#: and it is left out.
AIR_BALANCED = (
    (1663, "A-114D-173-64", 115.0, 48.0, 46.5, 123.11, 114.0, 13.31, "64.63"),
    (1664, "A-114D-190-64", 115.0, 48.0, 46.5, 123.12, 114.0, 13.31, "64.6"),
    (1665, "A-160D-200-74", 120.0, 50.0, 48.0, 123.69, 114.0, 15.25, "74.39"),
    (1667, "A-160D-250-74", 120.0, 50.0, 48.0, 123.69, 114.0, 15.25, "74.4"),
    (1669, "A-228D-246-86", 131.0, 56.0, 54.0, 133.42, 122.0, 18.25, "86.98"),
    (1673, "A-320D-302-120", 184.0, 70.0, 68.0, 148.49, 132.0, 22.38, "119.8"),
    (1674, "A-320D-305-100", 155.0, 70.0, 68.0, 148.49, 132.0, 22.38, "100.88"),
    (1678, "A-456D-305-144", 208.0, 77.0, 74.58, 200.39, 186.0, 26.19, "144.39"),
    (1688, "A-640D-427-144", 200.0, 88.0, 85.0, 204.5, 186.0, 31.25, "145.2"),
    (1695, "A-912D-470-240", 336.0, 134.5, 130.0, 297.41, 267.5, 47.0, "239.92"),
)


@pytest.mark.parametrize("row", AIR_BALANCED, ids=[row[1] for row in AIR_BALANCED])
@pytest.mark.parametrize("rotation", [CLOCKWISE, COUNTERCLOCKWISE], ids=["cw", "ccw"])
def test_an_air_balanced_row_gives_its_stored_stroke_and_an_upstroke_of_half_a_turn(row, rotation):
    """Ten units of eight air-balanced structures, A-114D to A-912D: the exact class III stroke of the first hole
    equals the stored one within half a unit of its last printed decimal and 0.01 in for the letters'
    rounding (the stroke does not depend on the rotation), and either way round the upstroke takes
    half a turn within 1 deg (the crank shaft nearly under the equalizer, I ~ C: field.md, "upstroke
    close to 180 deg")."""
    _, _, a, c, i, k, p, r, stored = row
    decimals = len(stored.partition(".")[2])
    unit = class_three(a, c, i, k, p, r, rotation)
    assert unit.stroke == pytest.approx(float(stored), abs=0.5 * 10.0**-decimals + 0.01)
    assert abs(math.degrees(unit.dead_positions().upstroke_crank_travel) - 180.0) < 1.0


def test_the_lufkin_beam_balanced_row_gives_its_stroke(tmp_path):
    """Row 1705, LUFKIN BB-114-133-74 (class "BB"): A 81, C 50.3, I 58, K 123.7, P 109.5 in, crank
    holes 22 and 16 in, stored stroke 74 in (a nominal one) and B +405 lb. Read as a beam-balanced
    unit file (the database has no beam counterweight: an arm is given, the weight left to `torque`
    to recommend), its longest hole's exact stroke is within 0.25 in of the stored 74 in, and the
    upstroke is near half a turn either way round (the equalizer 7.7 in ahead of the crank shaft)."""
    text = ('name = "BB-114-133-74"\n[geometry]\nclass = "beam-balanced"\n'
            'A = "81 in"\nC = "50.3 in"\nI = "58 in"\nK = "123.7 in"\nP = "109.5 in"\nR = "22 in"\n'
            'rotation = "{}"\nbeam_counterweight_arm = "60 in"\n[counterbalance]\nstructural_unbalance = "405 lbf"\n')
    for rotation, (low, high) in (("clockwise", (180.0, 186.0)), ("counterclockwise", (174.0, 180.0))):
        path = tmp_path / f"{rotation}.toml"
        path.write_text(text.format(rotation), encoding="utf-8")
        unit = load_unit(str(path))
        assert unit.geometry.unit_class == "beam-balanced"
        mechanism = unit.geometry.mechanism()
        assert mechanism.stroke / INCH == pytest.approx(74.0, abs=0.25)
        assert low < math.degrees(mechanism.dead_positions().upstroke_crank_travel) < high
