"""Dynamometer-card reading: layouts, units, the position -> crank angle map, bad files."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import card_load, crank_angle_from_position
from pumpjack_cli.core.beam.kinematics import uniform_kinematics
from pumpjack_cli.core.cards import place_card
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.errors import CardError
from pumpjack_cli.readers.cards import read_card

from helpers import INCH, POUND_FORCE, REPO_ROOT, sample_card

SK8 = load_unit("sk8-3.5-4000").geometry.mechanism()


def exact_run(steps: int = 360):
    return uniform_kinematics(SK8, 1.0, steps)


def angle_misfit(found: np.ndarray, expected: np.ndarray) -> float:
    """Largest circular distance [rad] from a found crank angle to the nearest expected one."""
    d = (found[:, None] - expected[None, :] + np.pi) % (2 * np.pi) - np.pi
    return float(np.max(np.min(np.abs(d), axis=1)))


def read(path: Path, unit=SK8, units: str | None = None):
    """A card file read without a unit, then placed on ``unit``'s crank-angle axis."""
    return place(read_card(path, units=units), unit)


def write(tmp_path: Path, text: str, name: str = "card.csv") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def load_of(theta: np.ndarray) -> np.ndarray:
    return 40e3 + 10e3 * np.sin(theta)


def test_position_card_maps_back_to_its_crank_angles(tmp_path):
    """Positions taken from the exact kinematics at known crank angles, listed in time
    order from crank angle 0, come back as those angles (inversion on each branch)."""
    run = exact_run()
    rows = "\n".join(f"{s},{w}" for s, w in zip(run.rod.position, load_of(run.crank_angle)))
    reading = read(write(tmp_path, "position_m,load_n\n" + rows))
    card = reading.card
    assert reading.warnings == ()
    # The card's lowest and highest samples are not exactly the dead positions (1 deg
    # grid), so shifting and scaling it to the exact stroke moves points near the dead
    # positions, where ds/dtheta -> 0, by up to ~0.4 deg and the interpolated load by
    # up to ~0.2 %; elsewhere the map is exact to the branch interpolation (next test).
    assert card.crank_angle.size == run.crank_angle.size
    assert angle_misfit(card.crank_angle, run.crank_angle) < np.radians(0.5)
    assert np.allclose(card_load(card, run.crank_angle), load_of(run.crank_angle), rtol=3e-3)


def test_crank_angle_from_position_inverts_the_exact_motion():
    """Exact positions at known crank angles, at least 5 deg from the dead positions,
    come back to 1e-5 rad (linear interpolation on 8192 points per branch)."""
    run = uniform_kinematics(SK8, 1.0, 720)
    dead = (run.summary.crank_angle_bottom, run.summary.crank_angle_top)
    away = np.all([np.abs((run.crank_angle - d + np.pi) % (2 * np.pi) - np.pi) > np.radians(5) for d in dead], axis=0)
    theta = run.crank_angle[away]
    found = crank_angle_from_position(SK8, run.rod.position[away], run.rod.velocity[away] > 0)
    assert np.max(np.abs((found - theta + np.pi) % (2 * np.pi) - np.pi)) < 1e-5


def test_layouts_and_units_give_the_same_card(tmp_path):
    """Crank-angle, position and time-position cards in SI, field and bracketed units agree."""
    run = exact_run()
    theta, s, w = run.crank_angle, run.rod.position, load_of(run.crank_angle)
    time = run.time
    files = {
        "angle": "crank_angle_deg,load_kN\n" + "\n".join(f"{math.degrees(t)},{x / 1e3}" for t, x in zip(theta, w)),
        "field": "position_in,load_lbf\n" + "\n".join(f"{p / INCH},{x / POUND_FORCE}" for p, x in zip(s, w)),
        "brackets": "Time (s),Position [mm],Load [kN]\n" + "\n".join(
            f"{t},{1e3 * p},{x / 1e3}" for t, p, x in zip(time, s, w)),
    }
    probe = crank_grid(360)
    reference = load_of(probe)
    for name, text in files.items():
        card = read(write(tmp_path, text, f"{name}.csv")).card
        assert np.allclose(card_load(card, probe), reference, rtol=3e-3), name


def test_default_units_for_bare_headers(tmp_path):
    run = exact_run()
    text = "position,load\n" + "\n".join(f"{p / INCH},{x / POUND_FORCE}" for p, x in zip(run.rod.position, load_of(run.crank_angle)))
    path = write(tmp_path, text)
    field = read(path, units="field").card
    assert np.allclose(card_load(field, run.crank_angle), load_of(run.crank_angle), rtol=3e-3)
    with pytest.raises(CardError, match="stroke"):  # read as metres, the stroke is 39 times too long
        read(path, units="si")


def test_comments_and_a_closed_card(tmp_path):
    run = exact_run()
    pairs = list(zip(run.rod.position, load_of(run.crank_angle)))
    pairs.append(pairs[0])  # closed: the first point again
    text = "# measured 2026-11-01\nposition_m,load_n\n" + "\n".join(f"{p},{x}" for p, x in pairs)
    card = read(write(tmp_path, text)).card
    assert card.crank_angle.size == run.crank_angle.size


def test_small_stroke_mismatch_is_scaled_with_a_warning(tmp_path):
    run = exact_run()
    text = "position_m,load_n\n" + "\n".join(f"{0.97 * p},{x}" for p, x in zip(run.rod.position, load_of(run.crank_angle)))
    reading = read(write(tmp_path, text))
    assert len(reading.warnings) == 1 and "-3.0 %" in reading.warnings[0]
    assert angle_misfit(reading.card.crank_angle, run.crank_angle) < np.radians(0.5)


GOOD_ROWS = "\n".join(f"{0.1 * i},{1000 + i}" for i in range(10))

#: Broken card files and a fragment of their one-line message.
BROKEN_CARDS = [
        ("speed,load\n" + GOOD_ROWS, "unknown column 'speed'"),
        ("position_m,time_s\n" + GOOD_ROWS, "a card has crank_angle and load"),
        ("position_m,load_n,load_n\n0,1,2\n", "a card has crank_angle and load"),
        ("position_kg,load_n\n" + GOOD_ROWS, "unit 'kg', not a unit of length"),
        ("position_m,load_m\n" + GOOD_ROWS, "unit 'm', not a unit of force"),
        ("position_m,load_n\n0.1,abc\n" + GOOD_ROWS, "line 2: load 'abc' is not a number"),
        ("position_m,load_n\n0.1,nan\n" + GOOD_ROWS, "line 2: load is nan, not a finite number"),
        ("position_m,load_n\n0.1,1000,5\n" + GOOD_ROWS, "line 2: 3 values, the header has 2"),
        ("position_m,load_n\n0.1,1000\n", "1 points; a card needs at least 8"),
        ("", "empty card"),
        ("time_s,position_m,load_n\n" + "\n".join(f"{t},{0.1 * i},{1000}" for i, t in enumerate([0, 1, 2, 3, 2.5, 5, 6, 7, 8])),
         "line 6: time does not increase"),
        ("position_m,load_n\n" + "\n".join(f"{0.3 * i},{1000}" for i in range(10)), "moves only up"),
        ("position_m,load_n\n" + "\n".join(f"{0.1 * (i if i < 5 else 10 - i)},{1000}" for i in range(10)),
         "differs from the unit's exact stroke"),
]


@pytest.mark.parametrize(("text", "fragment"), BROKEN_CARDS)
def test_broken_cards(tmp_path, text, fragment):
    path = write(tmp_path, text)
    with pytest.raises(CardError) as info:
        read(path)
    message = str(info.value)
    assert message.startswith(str(path)) and "\n" not in message
    assert fragment in message


@pytest.mark.parametrize(("text", "fragment"), BROKEN_CARDS)
def test_every_broken_card_exits_2_with_one_line(run_cli, tmp_path, text, fragment):
    bad = write(tmp_path, text, "bad.csv")
    code, out, err = run_cli("reactions", "sk8-3.5-4000", "--card", bad)
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and err.startswith(f"pumpjack: error: {bad}") and fragment in err


def test_missing_card_file(tmp_path):
    with pytest.raises(CardError, match="cannot read"):
        read(tmp_path / "nope.csv")


def test_sample_cards_are_what_the_script_makes():
    """samples/make_cards.py documents how the sample cards were made: rerun it in memory."""
    spec = importlib.util.spec_from_file_location("make_cards", REPO_ROOT / "samples" / "make_cards.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for name in module.CARDS:
        assert sample_card(name).read_text(encoding="utf-8") == module.write(name), name


@pytest.mark.parametrize("name", ["sk8-3.5-4000", "7sk12-2.5-5600", "c-114d-133-54"])
def test_sample_cards_fit_their_units(name):
    """Each sample card reads without warnings; its stroke matches its unit, and its
    peak stays below the unit's rated polished-rod load (80, 120 kN; 13 300 lbf)."""
    rated = {"sk8-3.5-4000": 80e3, "7sk12-2.5-5600": 120e3, "c-114d-133-54": 13300 * POUND_FORCE}
    linkage = load_unit(name).geometry.mechanism()
    reading = read(sample_card(name), linkage)
    assert reading.warnings == ()
    assert 0 < reading.card.load.min() < reading.card.load.max() < rated[name]


def test_an_angle_card_measured_against_the_rotation_is_refused():
    """The sample card's loads at its fitted crank angles place as an angle card; the same loads at
    the angles mirrored (2 pi - theta, measured against the rotation) run the loop backwards, the rods
    doing work on the unit, and are refused by name instead of giving a pump card of negative work."""
    placed = place(read_card(sample_card("sk8-3.5-4000")), SK8)
    good = place_card(SK8, placed.load, crank_angle=placed.crank_angle, source="angles.csv")
    assert good.card.load.size == placed.card.load.size
    with pytest.raises(CardError, match=r"^angles\.csv: on these crank angles the rods do .* J of work on the unit"):
        place_card(SK8, placed.load, crank_angle=2.0 * math.pi - placed.crank_angle, source="angles.csv")
