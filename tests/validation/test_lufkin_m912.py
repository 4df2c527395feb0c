"""Validation of the class III kinematics and the Mark II crank offset against the catalogue
data of the Mark II M-912D-365-168 ([LufkinM912]).

The catalogue prints A, C, I, P, H, G, three crank radii with their strokes, the structural
unbalance B = -5385 lb and the crank offset tau = 19 deg; [LufkinMarkII] states the upstroke
as about 195 deg of crank, counterclockwise. A catalogue stroke is a nominal stroke rounded
to the inch, so the exact stroke is expected within 0.5 in of it; the third hole's printed
130 in is 0.83 in off the 130.83 in of its letters, which is reported here, not hidden.

The sign of tau is checked physically: with the torque form of class III units
(T = TF (W - B) + M sin(theta + tau), the counterweights on the crank's tail,
docs/conventions.md) the catalogue's +19 deg lies near the offset that gives the least
peak torque for cards of this unit predicted by the wave equation, and the opposite sign
gives a far larger one.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.class_three import ClassThreeLinkage
from pumpjack_cli.core.beam.counterbalance import Counterbalance
from pumpjack_cli.core.beam.geometry import COUNTERCLOCKWISE
from pumpjack_cli.core.rods.predict import predict_cards

from helpers import INCH, POUND_FORCE

#: [LufkinM912]: crank radius [in] -> printed stroke [in].
HOLES = {63.56: 168.0, 56.56: 149.0, 49.56: 130.0}
LETTERS = dict(front_arm=334.0, rear_arm=270.0, pitman=193.5, horizontal_offset=202.56,
               vertical_offset=295.13 - 112.13)


@pytest.mark.parametrize("radius, printed", HOLES.items())
def test_strokes_per_crank_hole(radius, printed):
    # lengths in inches: the kinematics is homogeneous of degree one in length
    stroke = ClassThreeLinkage(**LETTERS, crank_radius=radius, rotation=COUNTERCLOCKWISE).stroke
    if radius == 49.56:
        assert 0.5 < stroke - printed < 1.0      # reported: the third hole's printed stroke is rounded down
    else:
        assert stroke == pytest.approx(printed, abs=0.5)


@pytest.mark.parametrize("radius", HOLES)
def test_the_upstroke_takes_about_195_degrees_counterclockwise(radius):
    dead = ClassThreeLinkage(**LETTERS, crank_radius=radius, rotation=COUNTERCLOCKWISE).dead_positions()
    assert 188.0 < math.degrees(dead.upstroke_crank_travel) < 198.0


def test_the_bundled_unit_is_the_catalogue_unit():
    unit = load_unit("m-912d-365-168")
    mechanism = unit.geometry.mechanism()
    assert mechanism.stroke == pytest.approx(168.0 * INCH, abs=0.5 * INCH)
    balance, _ = unit.counterbalance_model()
    assert balance.structural_unbalance == pytest.approx(-5385 * POUND_FORCE)
    assert balance.offset == pytest.approx(math.radians(19.0))


def test_the_catalogue_crank_offset_is_where_the_balance_is_best():
    unit = load_unit("m-912d-365-168")
    mechanism = unit.geometry.mechanism()
    cards = predict_cards(mechanism, 6.0 * math.pi / 30.0, unit.rods(), unit.pump(), damping=0.05,
                          fluid_density=unit.well.fluid_density, samples=720)
    theta, load = cards.crank_angle, cards.polished_rod_load
    motion = mechanism.motion(theta)
    structure = -motion.torque_factor * unit.counterbalance_model()[0].structural_unbalance
    moments = np.linspace(0.0, 6e5, 3001)

    def least_peak(offset_deg: float) -> float:
        per_moment = Counterbalance(0.0, 1.0, math.radians(offset_deg), tail=True).counterbalance_torque(motion)
        net = (motion.torque_factor * load + structure)[None, :] + moments[:, None] * per_moment[None, :]
        return float(np.abs(net).max(axis=1).min())

    offsets = np.arange(-40.0, 41.0, 1.0)
    peaks = np.array([least_peak(t) for t in offsets])
    best = float(offsets[np.argmin(peaks)])
    assert abs(best - 19.0) <= 8.0
    assert least_peak(19.0) < 1.05 * peaks.min()
    assert least_peak(-19.0) > 1.2 * least_peak(19.0)
