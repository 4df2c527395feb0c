"""The card layouts of issue 21, each written by an independent writer here and read back.

Every file holds the numbers of the SK8 sample card (read with numpy, independently of the
reader): a delimited card after a metadata preamble (written with plain string
formatting, values by ``repr`` so that they read back bit for bit), the fixed float32
block of XSPOC-type storage as binary (``struct``) and as hex text (``bytes.hex``), the
JSON of card services and the tool's own ``-f json`` and ``-f csv`` outputs (``json``,
``csv``), and a continuous recording of 20 strokes (numpy noise, seeded). A binary block
comes back to float32 rounding, exactly: the test rounds with numpy and converts with
the package's own factors (``tests/validation/test_nist811.py`` checks them).
"""

from __future__ import annotations

import csv
import importlib.util
import io
import json
import math
import sqlite3
import struct

import numpy as np
import pytest

from pumpjack_cli.analysis.card_runs import CardSource, chosen, place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.card import card_load
from pumpjack_cli.errors import CardError
from pumpjack_cli.readers import cards
from pumpjack_cli.readers.cards import read_card

from helpers import INCH, POUND_FORCE, REPO_ROOT, SK8, SK8_CARD, command_result, written

MECHANISM = load_unit(SK8).geometry.mechanism()
#: The sample's columns in SI, read with numpy: time [s], position [m], load [N].
TIME, POSITION, LOAD = np.loadtxt(SK8_CARD, delimiter=",", comments="#", skiprows=4, unpack=True) * [[1.0], [1.0],
                                                                                                     [1e3]]
#: Its cycle time [s]: 180 samples equally spaced over one cycle (from the last time stamp, rounded to 0.1 ms).
PERIOD = TIME[-1] * TIME.size / (TIME.size - 1)
REFERENCE = place(read_card(SK8_CARD), MECHANISM)


def from_text(content: str | bytes, **options):
    stream = io.BytesIO(content) if isinstance(content, bytes) else io.StringIO(content)
    return read_card("-", stream=stream, **options)


def refused(content: str | bytes, fragment: str, **options) -> None:
    """Reading (and placing) ``content`` is refused in one line holding ``fragment``."""
    with pytest.raises(CardError) as error:
        place(from_text(content, **options), MECHANISM)
    message = str(error.value)
    assert "\n" not in message and message.startswith("<stdin>: ") and fragment in message, message


def test_the_committed_samples_are_what_the_script_makes():
    """samples/make_formats.py documents how the layout samples were made: rerun it in memory."""
    spec = importlib.util.spec_from_file_location("make_formats", REPO_ROOT / "samples" / "make_formats.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for name, make in module.FILES.items():
        content = make()
        path = REPO_ROOT / "samples" / name
        assert (path.read_bytes() if isinstance(content, bytes) else path.read_text(encoding="utf-8")) == content, name


#: The sample's numbers as a position card (no time stamps), placed.
POSITION_REFERENCE = place(read_card("-", stream=io.StringIO("position_m,load_n\n" + "".join(
    f"{float(p)!r},{float(w)!r}\n" for p, w in zip(POSITION, LOAD)))), MECHANISM)


@pytest.mark.parametrize(("name", "options", "reference", "tolerance"), [
    ("sk8-3.5-4000-preamble.csv", {}, REFERENCE, 1e-3), ("sk8-3.5-4000-card.bin", {"units": "field"},
                                                          POSITION_REFERENCE, 1e-3),
    ("sk8-3.5-4000-card.hex", {"units": "field"}, POSITION_REFERENCE, 1e-3),
    ("sk8-3.5-4000-card.json", {}, POSITION_REFERENCE, 1e-3), ("sk8-3.5-4000-recording.csv", {}, REFERENCE, 1e-2),
])
def test_every_sample_reads_to_the_sample_card(name, options, reference, tolerance):
    """Each layout sample, told by its content, is the SK8 card placed as the same layout (a
    time card, or a position card for those without time stamps): its loads at the same
    crank angles within ``tolerance`` of the load range. The samples' rounding (0.01 lbf of
    a 12 700 lbf range, 1e-4 in of a 115 in stroke, float32's 6e-8) is about 1e-6 of the
    ranges, so 1e-3 leaves a wide margin; the recording's last stroke adds its noise, 0.2 %
    of the range, at most 5 of its sigma (1e-2) over 180 samples."""
    reading = place(read_card(REPO_ROOT / "samples" / name, **options), MECHANISM)
    error = card_load(reading.card, reference.card.crank_angle) - reference.card.load
    assert np.max(np.abs(error)) < tolerance * np.ptp(LOAD)


# --- delimited text after a metadata preamble -------------------------------------------------

def body(header: str = "time_s,position_m,load_kN", delimiter: str = ",") -> str:
    rows = [delimiter.join(map(repr, (float(t), float(p), float(w) / 1e3))) for t, p, w in zip(TIME, POSITION, LOAD)]
    return header.replace(",", delimiter) + "\n" + "\n".join(rows) + "\n"


STROKE_IN = f"{np.ptp(POSITION) / INCH:.1f}"
PREAMBLES = {
    "commas": "Well Name,EAST-12\nDate,2026-11-20 08:05\nSPM,10.91\nStroke,{stroke} in\n",
    "colons": "Well Name: EAST-12\nDate: 2026-11-20 08:05\nSPM: 10.91\nStroke: {stroke} in\n",
    "semicolons": "Well Name;EAST-12\nDate;2026-11-20 08:05\nSPM;10.91\nStroke;{stroke} in\n",
    "tabs": "Well Name\tEAST-12\nDate\t2026-11-20 08:05\nSPM\t10.91\nStroke\t{stroke} in\n",
    "excel-padding": "Well Name,EAST-12,,\nDate,2026-11-20 08:05,,\nSPM,10.91 spm,,\nStroke,{stroke} in,,\n",
    "date-and-time-lines": "WELL_NAME,EAST-12\nDate,2026-11-20\nTime,08:05\nStrokes per minute,10.91\n"
                           "Stroke (in),{stroke}\n",
    "comments-between": "# exported by a controller\nWell Name,EAST-12\n\nDate,2026-11-20T08:05:00\n# speed\n"
                        "SPM: 10.91\nStroke length,{stroke} in\n",
}


@pytest.mark.parametrize("name", PREAMBLES)
def test_a_preamble_is_the_cards_metadata(name):
    """The preamble's lines are metadata with canonical keys in SI, not columns (a
    'Well Name' line is no unknown column); the columns read as without it, bit for bit."""
    preamble = PREAMBLES[name].format(stroke=STROKE_IN)
    delimiter = ";" if name == "semicolons" else "\t" if name == "tabs" else ","
    raw = from_text(preamble + body(delimiter=delimiter))
    assert raw.metadata == {"well": "EAST-12", "timestamp": "2026-11-20T08:05:00", "spm": 10.91,
                            "stroke": float(STROKE_IN) * INCH}
    assert np.array_equal(raw.time, TIME) and np.array_equal(raw.position, POSITION)
    assert np.allclose(raw.load, LOAD, rtol=1e-15, atol=0)
    lines = preamble.splitlines()
    assert raw.metadata_lines["spm"] == 1 + next(i for i, line in enumerate(lines) if "10.91" in line)
    assert raw.lines[0] == len(lines) + 2  # the header follows the preamble
    placed = place(raw, MECHANISM)
    assert np.array_equal(placed.card.load, REFERENCE.card.load) and placed.speed == REFERENCE.speed


def test_a_preambles_units_are_those_of_a_bare_header():
    """Units,field names the units of the header's bare columns, as --card-units field would."""
    text = "Units,field\ntime,position,load\n" + "".join(
        f"{float(t)!r},{float(p) / INCH!r},{float(w) / POUND_FORCE!r}\n" for t, p, w in zip(TIME, POSITION, LOAD))
    raw = from_text(text)
    assert raw.metadata == {"units": "field"}
    assert np.allclose(raw.position, POSITION, rtol=1e-14) and np.allclose(raw.load, LOAD, rtol=1e-14)
    assert np.array_equal(raw.position, from_text(text.split("\n", 1)[1], units="field").position)


@pytest.mark.parametrize(("preamble", "fragment", "options"), [
    ("SPM,fast\n", "line 1: SPM 'fast' is not a number of strokes per minute", {}),
    ("SPM: 0\n", "line 1: SPM 0 is outside 0.1 .. 60 strokes per minute", {}),
    ("Well Name,W1\nDate,20.11.2026\n", "line 2: Date '20.11.2026' is not a date and time", {}),
    ("Stroke,114.7 furlongs\n", "line 1: Stroke '114.7 furlongs' has unit 'furlongs', not a unit of length", {}),
    ("Stroke,long\n", "line 1: Stroke 'long' is not a length", {}),
    ("Stroke,114.7\n", "line 1: Stroke '114.7' names no unit", {}),
    ("Stroke,100 in\n", f"line 1: stated stroke 2.54 m, but the positions span {np.ptp(POSITION):.4g} m "
                        f"(+{100 * (np.ptp(POSITION) / (100 * INCH) - 1):.1f} %)", {}),
    ("SPM,7\nSPM,8\n", "line 2: SPM given twice (line 1)", {}),
    ("Well Name,\n", "line 1: Well Name is empty", {}),
    ("Units,imperialish\n", "line 1: Units 'imperialish': use si or field", {}),
    ("Units,field\n", "line 1: Units field, but --card-units si", {"units": "si"}),
    ("Time,08:05\n", "line 1: a Time goes with a Date line", {}),
    ("Controller: SAM\n", "line 1: no comma, semicolon or tab in the header 'Controller: SAM' (a preamble line? "
                          "its keys are Well Name, Date, Time, SPM, Stroke, Units)", {}),
    ("SPM,8\n", "line 1: the stated SPM 8 disagrees with the card's time stamps (10.91 strokes/min) by -26.7 %", {}),
])
def test_preamble_values_that_do_not_parse_are_refused_by_line(preamble, fragment, options):
    """A stated stroke 5 % or more off the positions' range (here 100 in for about 114.7) and a
    stated SPM 2 % or more off the time stamps' (8 for 10.91) are refused, as --spm is."""
    refused(preamble + body(), fragment, **options)


def test_a_stroke_within_5_percent_and_an_spm_within_2_percent_pass():
    text = f"Stroke,{1.04 * np.ptp(POSITION) / INCH:.2f} in\nSPM,{1.015 * 60 / PERIOD:.3f}\n" + body()
    placed = place(from_text(text), MECHANISM)
    assert placed.speed == REFERENCE.speed and placed.stated_speed is None


# --- the fixed float32 block: binary and hex ---------------------------------------------------

def resampled(points: int) -> tuple[np.ndarray, np.ndarray]:
    """The sample card at ``points`` equal time steps (periodic linear interpolation): position [m], load [N]."""
    time = np.arange(points) * PERIOD / points
    return (np.interp(time, TIME, POSITION, period=PERIOD), np.interp(time, TIME, LOAD, period=PERIOD))


def packed(position: np.ndarray, load: np.ndarray, points: int = 200, length: float = INCH,
           force: float = POUND_FORCE) -> bytes:
    """An independent writer: ``points`` little-endian float32 loads, then positions, (0, 0) beyond the card's."""
    loads, positions = np.zeros(points), np.zeros(points)
    loads[:load.size], positions[:position.size] = load / force, position / length
    return struct.pack(f"<{2 * points}f", *loads, *positions)


def float32(values: np.ndarray, factor: float) -> np.ndarray:
    """What a float32 block gives back: each value rounded to float32, times the unit's factor."""
    return (values / factor).astype(np.float32).astype(float) * factor


def test_a_200_point_block_gives_back_its_200_points_exactly(tmp_path):
    position, load = resampled(200)
    path = tmp_path / "card.dat"
    path.write_bytes(packed(position, load))
    raw = read_card(path, units="field")
    assert np.array_equal(raw.position, float32(position, INCH)) and np.array_equal(raw.load, float32(load, POUND_FORCE))
    assert raw.time is None and raw.lines.tolist() == list(range(1, 201))
    assert raw.column_units == {"position": ("in", INCH), "load": ("lbf", POUND_FORCE)}


@pytest.mark.parametrize("name", ["card.bin", "card.dat", "card", "card.csv"])
def test_a_block_is_told_by_its_size_and_the_padding_is_dropped(tmp_path, name):
    """The 180 points of the sample in a 200-point block (si units here), padded with (0, 0):
    recognised by content (binary, 1600 bytes) whatever the name; 180 points come back."""
    path = tmp_path / name
    path.write_bytes(packed(POSITION, LOAD, length=1.0, force=1.0))
    raw = read_card(path, units="si")
    assert np.array_equal(raw.position, float32(POSITION, 1.0)) and np.array_equal(raw.load, float32(LOAD, 1.0))


def test_card_points_sets_the_block_size():
    position, load = resampled(120)
    raw = from_text(packed(position, load, points=120), units="field", points=120)
    assert np.array_equal(raw.load, float32(load, POUND_FORCE))


def test_a_block_places_as_its_numbers_in_a_delimited_position_card():
    """The block's float32 numbers written by repr as a position card place to the same card."""
    block = from_text(packed(POSITION, LOAD), units="field")
    text = "position_in,load_lbf\n" + "".join(f"{float(p)!r},{float(w)!r}\n" for p, w in
                                             zip(float32(POSITION, INCH) / INCH, float32(LOAD, POUND_FORCE) / POUND_FORCE))
    placed, delimited = place(block, MECHANISM), place(from_text(text), MECHANISM)
    assert np.array_equal(placed.card.crank_angle, delimited.card.crank_angle)
    assert np.array_equal(placed.card.load, delimited.card.load)


BLOCK = packed(POSITION, LOAD)


@pytest.mark.parametrize(("content", "options", "fragment"), [
    (BLOCK, {}, "a card block names no units: give --card-units si (positions in m, loads in N) or field"),
    (BLOCK[:-8], {"units": "si", "format": "binary"}, "1,592 bytes; a block of 200 points is 1,600 bytes"),
    (packed(POSITION[:5], LOAD[:5]), {"units": "field"}, "after the (0, 0) padding: 5 points; a card needs at least 8"),
    (BLOCK[:24] + struct.pack("<f", math.nan) + BLOCK[28:], {"units": "field"}, "point 7: load is nan, not a finite"),
    (BLOCK[:800 + 36] + struct.pack("<f", 1e30) + BLOCK[840:], {"units": "field"},
     "point 10: position 1e+30 in is beyond 1 km"),
    (BLOCK.hex() + "\nxyz\n", {"units": "field"}, "line 2: 'x' is not a hex digit"),
    (BLOCK.hex() + "\n" + BLOCK.hex()[:-2] + "\n", {"units": "field"},
     "line 2: 3198 hex digits; a block of 200 points is 3200"),
])
def test_bad_blocks_are_refused_in_one_line(content, options, fragment):
    refused(content, fragment, **options)


def test_a_hex_line_is_the_same_block():
    hexed = from_text(f"# a block\n{BLOCK.hex()}\n", units="field")
    binary = from_text(BLOCK, units="field")
    assert np.array_equal(hexed.position, binary.position) and np.array_equal(hexed.load, binary.load)
    assert set(hexed.lines.tolist()) == {2} and hexed.strokes == ()


def test_hex_lines_are_several_cards_the_last_read_unless_stroke_picks_another():
    """Three blocks (the card at 0.9, 1.0 and 1.1 of its loads): strokes in the file's order,
    the last by default, --stroke picks another, the median is the middle one."""
    lines = [packed(POSITION, scale * LOAD).hex().upper() for scale in (0.9, 1.0, 1.1)]
    raw = from_text("\n".join(lines) + "\n", units="field")
    assert len(raw.strokes) == 3 and [s.source for s in raw.strokes] == [f"<stdin> stroke {k}" for k in (1, 2, 3)]
    assert np.array_equal(raw.load, raw.strokes[2].load) and raw.source == "<stdin>"
    for stroke, scale in ((1, 0.9), (2, 1.0), ("last", 1.1)):
        assert np.array_equal(chosen(raw, stroke, MECHANISM).load, float32(scale * LOAD, POUND_FORCE))
    median, middle = chosen(raw, "median", MECHANISM), place(raw.strokes[1], MECHANISM)
    assert np.allclose(median.card.load, card_load(middle.card, median.crank_angle), rtol=1e-12)
    with pytest.raises(CardError, match=r"^<stdin>: --stroke 4: the file holds 3 strokes$"):
        chosen(raw, 4, MECHANISM)


# --- JSON: card services and the tool's own outputs --------------------------------------------

def test_a_card_services_json_is_a_position_card_with_its_speed():
    document = {"S": POSITION.tolist(), "F": (LOAD / 1e3).tolist(), "SPM": 7.5, "well": "W-1"}
    raw = from_text(json.dumps(document))
    assert np.array_equal(raw.position, POSITION) and np.array_equal(raw.load, np.array(document["F"]) * 1e3)
    assert raw.time is None and raw.metadata == {"spm": 7.5} and raw.lines.tolist() == [1] * POSITION.size
    assert place(raw, MECHANISM).stated_speed == 7.5 * math.pi / 30


def test_json_unit_keys_and_the_line_of_every_item():
    document = {"S_unit": "in", "F_unit": "lbf", "S": (POSITION / INCH).tolist(), "F": (LOAD / POUND_FORCE).tolist()}
    text = json.dumps(document, indent=1)
    raw = from_text(text)
    assert np.array_equal(raw.position, np.array(document["S"]) * INCH)
    assert np.array_equal(raw.load, np.array(document["F"]) * POUND_FORCE)
    first = text.splitlines().index(" \"S\": [") + 2
    assert raw.lines.tolist() == list(range(first, first + POSITION.size)) and raw.metadata == {}


@pytest.mark.parametrize(("text", "fragment"), [
    ('{"S": [1, 2, 3],\n "F": [1, "x", 3]}', 'line 2: F item 2: \'"x"\' is not a number'),
    ('{"S": [1, 2, 3], "F": [1, 2]}', "S has 3 items and F 2"),
    ('{"S": [1, 2], "F": [3, 4]}', "2 points; a card needs at least 8"),
    ('{"position": [1, 2]}', 'a JSON card has "S" and "F" arrays'),
    ('{"S": [1, 2,\n 3], ', "line 2: not valid JSON"),
    ('{"S": ' + "[" * 100_000 + "]" * 100_000 + "}", "not valid JSON: nested too deep"),
    ('{"S": [NaN, 1, 2, 3, 4, 5, 6, 7], "F": [1, 2, 3, 4, 5, 6, 7, 8]}', "line 1: S item 1: position is nan"),
    ('{"S_unit": "kg", "S": [1], "F": [2]}', "line 1: S_unit has unit 'kg', not a unit of length"),
    ('{"S": [1, 2, 3, 4, 5, 6, 7, 8], "F": [1, 2, 3, 4, 5, 6, 7, 8], "SPM": "fast"}', "line 1: SPM 'fast'"),
    ('{"series": {"time_s": [0, 1], "my_load": [1, 2]}}', "series 'my_load' is not a column pumpjack writes"),
])
def test_bad_json_cards_are_refused_in_one_line(text, fragment):
    refused(text, fragment)


@pytest.fixture(scope="module")
def predicted():
    """`pumpjack predict`'s result as -f json (parsed) and -f csv (text) write it in both unit systems."""
    result, _ = command_result("predict", SK8)
    return {system: (json.loads(written(result, system)), written(result, system, "csv")) for system in ("si", "field")}


@pytest.mark.parametrize("system", ["si", "field"])
def test_the_tools_own_json_and_csv_are_read_without_column_mapping(predicted, system):
    """The surface card (time, position, rod_load) of the tool's own outputs, every other column
    ignored; the numbers those of the output, parsed here with json and csv."""
    document, text = predicted[system]
    length, force = (1.0, 1.0) if system == "si" else (INCH, POUND_FORCE)
    suffix = {"si": ("m", "n"), "field": ("in", "lbf")}[system]
    series = document["series"]
    columns = {name: np.array([float(row[name]) for row in csv.DictReader(io.StringIO(text))])
               for name in ("time_s", f"position_{suffix[0]}", f"rod_load_{suffix[1]}")}
    for raw in (from_text(json.dumps(document, indent=1)), from_text(text)):
        assert np.array_equal(raw.time, np.array(series["time_s"])) and np.array_equal(raw.time, columns["time_s"])
        assert np.array_equal(raw.position, np.array(series[f"position_{suffix[0]}"]) * length)
        assert np.array_equal(raw.load, columns[f"rod_load_{suffix[1]}"] * force)
        assert len(series) > 3 and raw.crank_angle is None


def test_an_unknown_column_in_a_users_csv_stays_an_error():
    text = "time_s,position_m,rod_load_n,valve\n" + "".join(f"{t!r},{p!r},{w!r},0\n" for t, p, w in
                                                            zip(TIME, POSITION, LOAD))
    refused(text, "line 1: unknown column 'valve' (column 4)")


def test_a_tool_output_without_a_surface_card_is_refused():
    """Kinematics has no rod_load: as CSV its columns are a user's (velocity is unknown), as JSON
    its series hold no card."""
    columns = {"crank_angle_deg": [float(i) for i in range(20)], "position_m": [0.5] * 20, "velocity_m_s": [0.1] * 20}
    text = ",".join(columns) + "\n" + "".join(f"{a},{p},{v}\n" for a, p, v in zip(*columns.values()))
    refused(text, "line 1: unknown column 'velocity_m_s' (column 3)")
    refused(json.dumps({"series": columns}), "line 1: the series hold no surface card")


# --- continuous recordings ---------------------------------------------------------------------

STROKES = 20
#: Load noise of the recording: 0.2 % of the load range, Gaussian, independent at each sample.
SIGMA = 2e-3 * np.ptp(LOAD)


def recording(first: int, last: int, sigma: float = SIGMA, seed: int = 7) -> str:
    """Samples ``first`` to ``last`` (excluded) of the sample card repeated, time from sample 0,
    loads with noise ``sigma``, written by repr."""
    index = np.arange(first, last)
    n = TIME.size
    load = LOAD[index % n] + np.random.default_rng(seed).normal(0.0, sigma, index.size)
    rows = (f"{float(t)!r},{float(p)!r},{float(w)!r}" for t, p, w in zip(index * PERIOD / n, POSITION[index % n], load))
    return "time_s,position_m,load_n\n" + "\n".join(rows) + "\n"


#: 20 whole strokes between half a stroke before and half a stroke after (as a controller cuts them).
RECORDING = recording(90, 90 + 90 + STROKES * 180 + 90)


def test_a_recording_splits_into_its_whole_strokes():
    """Each stroke is the rows from one bottom to the next (the sample's lowest position, at
    its sample 0), with its start time; the half strokes at either end are dropped."""
    raw = from_text(RECORDING)
    assert len(raw.strokes) == STROKES
    for k, stroke in enumerate(raw.strokes, 1):
        assert np.array_equal(stroke.position, POSITION)
        assert stroke.metadata["start"] == pytest.approx(k * PERIOD, rel=1e-12)
        assert stroke.lines[0] == 2 + 90 + (k - 1) * 180 and stroke.source == f"<stdin> stroke {k}"
    assert np.array_equal(raw.load, raw.strokes[-1].load) and raw.source == "<stdin>"


def test_the_median_card_is_the_sample_card_within_the_noise():
    """The median of 20 independent noisy values has a standard deviation of sqrt(pi / 2)
    sigma / sqrt(20) = 0.28 sigma (interpolating between neighbouring samples only lowers
    it): its RMS over the 180 crank angles stays below 0.5 sigma and its largest error
    below 2 sigma (7 of its standard deviations), where one stroke is off by about sigma."""
    raw = from_text(RECORDING)
    median = chosen(raw, "median", MECHANISM)
    error = median.card.load - card_load(REFERENCE.card, median.card.crank_angle)
    assert np.sqrt(np.mean(error**2)) < 0.5 * SIGMA and np.max(np.abs(error)) < 2 * SIGMA
    single = place(raw.strokes[4], MECHANISM)
    assert np.sqrt(np.mean((single.card.load - card_load(REFERENCE.card, single.card.crank_angle))**2)) > 0.7 * SIGMA
    # the recording's period comes from the sample's last time stamp, rounded to 0.1 ms in 5.5 s
    assert median.speed == pytest.approx(REFERENCE.speed, rel=1e-4) and median.time is not None


def test_a_stroke_is_read_as_its_rows_alone():
    """--stroke 3 gives the card of stroke 3's rows written as a file of their own."""
    lines = RECORDING.splitlines()
    alone = "\n".join([lines[0], *lines[1 + 90 + 2 * 180:1 + 90 + 3 * 180]]) + "\n"
    third, own = chosen(from_text(RECORDING), 3, MECHANISM), place(from_text(alone), MECHANISM)
    assert np.array_equal(third.card.load, own.card.load) and third.speed == own.speed


def test_a_recording_cut_at_bottoms_keeps_its_first_and_last_stroke():
    """Three cycles from the bottom, closed by the next bottom: three strokes (a bottom at
    the first or last sample counts when it lies at the level of the others)."""
    raw = from_text(recording(0, 3 * 180 + 1, sigma=0.0))
    assert len(raw.strokes) == 3 and all(np.array_equal(s.position, POSITION) for s in raw.strokes[:2])


def test_a_single_cycle_is_not_a_recording():
    assert from_text(recording(0, 180, sigma=0.0)).strokes == () and read_card(SK8_CARD).strokes == ()


def test_a_recording_without_a_whole_stroke_is_refused():
    """One and a half cycles from mid-upstroke: two tops, one bottom between them."""
    refused(recording(45, 45 + 270), "the positions pass 2 tops (a recording of several strokes) but hold no whole "
                                     "stroke from a bottom to the next")


def test_a_recording_with_a_stated_spm_checks_every_stroke():
    text = "Well Name,W-1\nSPM,9\n" + RECORDING
    with pytest.raises(CardError, match=r"^<stdin> stroke 20: line 2: the stated SPM 9 disagrees"):
        chosen(from_text(text), "last", MECHANISM)


def test_batch_stores_every_stroke_of_a_recording(run_cli, tmp_path):
    """20 rows per analysis, each stroke's number after the card's path and digest, its time
    stamp the manifest's plus the stroke's start; a second run finds them all done."""
    (tmp_path / "rec.csv").write_text(RECORDING, encoding="utf-8")
    manifest = tmp_path / "manifest.csv"
    manifest.write_text(f"well,unit,card,timestamp\nW-1,{SK8},rec.csv,2026-11-20T08:00:00\n", encoding="utf-8")
    store = tmp_path / "results.sqlite"
    code, out, err = run_cli("batch", manifest, "--store", store, "--workers", "1")
    assert code == 0, err
    assert "1 cards: 1 analysed" in out and f"{2 * STROKES} results ok" in out
    rows = sqlite3.connect(store).execute("SELECT analysis, card, card_sha256, timestamp FROM results").fetchall()
    for analysis in ("torque", "downhole"):
        mine = sorted(row[1:] for row in rows if row[0] == analysis)
        assert [card for card, _, _ in mine] == [f"{tmp_path / 'rec.csv'}#{k:02d}" for k in range(1, STROKES + 1)]
        assert len({digest for _, digest, _ in mine}) == STROKES and all(d.endswith(c[-3:]) for c, d, _ in mine)
        seconds = [float(stamp[17:]) + 60 * int(stamp[14:16]) for _, _, stamp in mine]
        assert np.allclose(seconds, [k * PERIOD for k in range(1, STROKES + 1)], atol=1e-3)
    code, out, err = run_cli("batch", manifest, "--store", store, "--workers", "1")
    assert code == 0 and "0 analysed, 1 already" in out, out + err


# --- the options on the commands ---------------------------------------------------------------

def test_every_card_command_takes_the_format_options(run_cli, tmp_path):
    """--card-format, --card-points and --stroke on each command that reads a card; their help
    names every format of the registry."""
    path = tmp_path / "card.hex"
    path.write_text(packed(POSITION, LOAD, points=180).hex() + "\n", encoding="utf-8")
    for command in ("torque", "reactions", "compare-redundancy", "downhole"):
        code, out, err = run_cli(command, SK8, "--card", path, "--card-format", "hex", "--card-points", "180",
                                 "--card-units", "field", "--stroke", "last", "-f", "csv")
        assert code == 0, (command, err)
    for command in ("torque", "reactions", "compare-redundancy", "dynamics", "downhole", "batch run"):
        code, out, err = run_cli(*command.split(), "--help")
        assert all(name in " ".join(out.split()) for name in cards.READERS), command


@pytest.mark.parametrize(("argv", "fragment"), [
    (["torque", SK8, "--card", SK8_CARD, "--card-format", "xml"], "--card-format 'xml': use json, hex, binary, delimited"),
    (["torque", SK8, "--card", SK8_CARD, "--stroke", "2"], "--stroke 2: the file holds one card, not a recording"),
    (["torque", SK8, "--card", SK8_CARD, "--stroke", "first"], "--stroke 'first': a stroke's number (from 1), last or "
                                                                "median"),
    (["batch", "m.csv", "--card-format", "xml"], "--card-format 'xml': use json"),
])
def test_bad_format_options_are_refused_in_one_line(run_cli, argv, fragment):
    code, out, err = run_cli(*argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and fragment in err, err


def test_a_stated_spm_is_the_speed_of_a_card_without_time_stamps(run_cli, tmp_path):
    path = tmp_path / "card.json"
    path.write_text(json.dumps({"S": POSITION.tolist(), "F": (LOAD / 1e3).tolist(), "SPM": 7.5}), encoding="utf-8")
    code, out, err = run_cli("torque", SK8, "--card", path, "-f", "json")
    assert code == 0, err
    assert json.loads(out)["summary"]["strokes_per_minute_spm"] == pytest.approx(7.5, rel=1e-12)
    code, out, err = run_cli("torque", SK8, "--card", path, "--spm", "8")
    assert code == 2 and f"--spm 8 disagrees with the SPM {path} states on line 1 (7.5 strokes/min)" in err, err


def test_card_source_checks_its_options_before_reading():
    with pytest.raises(CardError, match="--card-points 3: a card block has 8 to 100000 points"):
        CardSource(SK8_CARD, points=3)
