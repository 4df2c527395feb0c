"""Card files as they come from the field: every accepted format of the SK8 sample card reads to the same card.

The reference is the sample card read as shipped (time_s, position_m, load_kN); the
same numbers written in other units, delimiters, decimal marks, encodings, line ends,
with index columns, mapped headers or in reverse order must give the same SI samples
and the same crank-angle card to round-off. Values are written with ``repr`` (17
significant digits), so a unit conversion and back costs at most a few ulp: the
tolerances below (1e-12 relative, 1e-9 rad) are round-off, not modelling, bounds.
"""

from __future__ import annotations

import io
import math

import numpy as np
import pytest

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.core.cards import PlacedCard
from pumpjack_cli.quantities import FOOT, INCH, KILOGRAM_FORCE, POUND_FORCE
from pumpjack_cli.readers.cards import parse_card_columns, read_card

from helpers import SK8_CARD

SK8 = load_unit("sk8-3.5-4000").geometry.mechanism()

#: The sample's columns in SI, read with numpy (independently of the reader).
TIME, POSITION, LOAD = np.loadtxt(SK8_CARD, delimiter=",", comments="#", skiprows=4, unpack=True) * [[1.0], [1.0], [1e3]]
REFERENCE = place(read_card(SK8_CARD), SK8)

#: Unit spelling -> factor to SI, from the definitions of units.py ([NIST811]); lb is lbf for a force column.
FORCE = {"N": 1.0, "kN": 1e3, "lbf": POUND_FORCE, "lb": POUND_FORCE, "lbs": POUND_FORCE, "klb": 1e3 * POUND_FORCE,
         "kip": 1e3 * POUND_FORCE, "klbf": 1e3 * POUND_FORCE, "kgf": KILOGRAM_FORCE, "tf": 1e3 * KILOGRAM_FORCE}
LENGTH = {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "in": INCH, "ft": FOOT}
TIME_UNITS = {"s": 1.0, "ms": 1e-3, "min": 60.0}


def table(header: list[str], columns: list[np.ndarray], delimiter: str = ",", decimal: str = ".") -> str:
    """A card text: header and rows of repr-formatted values."""
    rows = [delimiter.join(repr(float(v)).replace(".", decimal) for v in row) for row in zip(*columns)]
    return "\n".join([delimiter.join(header), *rows]) + "\n"


def sample_text(force="kN", length="m", time="s", **kwargs) -> str:
    return table([f"time_{time}", f"position_{length}", f"load_{force}"],
                 [TIME / TIME_UNITS[time], POSITION / LENGTH[length], LOAD / FORCE[force]], **kwargs)


def read_text(text: str | bytes, linkage=SK8, **kwargs) -> PlacedCard:
    stream = io.BytesIO(text) if isinstance(text, bytes) else io.StringIO(text)
    return place(read_card("-", stream=stream, **kwargs), linkage)


def assert_same_card(reading: PlacedCard, reference: PlacedCard = REFERENCE) -> None:
    assert np.allclose(reading.load, LOAD, rtol=1e-12, atol=0)
    assert np.allclose(reading.position, POSITION, rtol=1e-12, atol=1e-15)
    if reading.time is not None:
        assert np.allclose(reading.time, TIME, rtol=1e-12, atol=1e-15)
    assert reading.card.crank_angle.shape == reference.card.crank_angle.shape
    assert np.allclose(reading.card.crank_angle, reference.card.crank_angle, rtol=0, atol=1e-9)
    assert np.allclose(reading.card.load, reference.card.load, rtol=1e-12, atol=0)


def test_reference_reads_cleanly():
    assert REFERENCE.warnings == () and not REFERENCE.reversed and REFERENCE.card.crank_angle.size == TIME.size


@pytest.mark.parametrize("force", FORCE)
def test_force_units(force):
    assert_same_card(read_text(sample_text(force=force)))


@pytest.mark.parametrize("length", LENGTH)
def test_length_units(length):
    assert_same_card(read_text(sample_text(length=length)))


@pytest.mark.parametrize("time", TIME_UNITS)
def test_time_units(time):
    assert_same_card(read_text(sample_text(time=time)))


@pytest.mark.parametrize("header", [
    ["Time (ms)", "Position [in]", "Load (lbf)"],
    ["TIME [MS]", "POSITION [IN]", "LOAD [LBF]"],
    ["t_ms", "pos_in", "prl_lbf"],
    ['"Time, ms"', '"Displacement, in"', '"Polished Rod Load, lbf"'],
    ["time (ms)", "position (in.)", "force (lbs.)"],
], ids=["brackets", "upper-case", "short-names", "quoted-comma-units", "dotted-units"])
def test_header_spellings(header):
    text = table(header, [TIME / 1e-3, POSITION / INCH, LOAD / POUND_FORCE], delimiter=";" if "," in "".join(header) else ",")
    assert_same_card(read_text(text))


ENCODINGS = {
    "crlf": lambda text: text.replace("\n", "\r\n").encode(),
    "cr": lambda text: text.replace("\n", "\r").encode(),
    "bom": lambda text: b"\xef\xbb\xbf" + text.encode(),
    "bom-crlf": lambda text: b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode(),
    "bom-in-text-stream": lambda text: "\ufeff" + text,
    "comments-and-blank-lines": lambda text: "# exported 2026-11-01\n\n" + text.replace("\n", "\n\n# note\n", 3),
    "trailing-spaces": lambda text: text.replace(",", " , ").replace("\n", "  \n"),
}


@pytest.mark.parametrize("name", ENCODINGS)
def test_encodings_and_line_ends(name):
    assert_same_card(read_text(ENCODINGS[name](sample_text())))


@pytest.mark.parametrize(("delimiter", "decimal"), [(";", ","), ("\t", ","), ("\t", "."), (";", ".")],
                         ids=["semicolon-comma", "tab-comma", "tab-point", "semicolon-point"])
def test_delimiters_and_decimal_commas(delimiter, decimal):
    assert_same_card(read_text(sample_text(force="lbf", length="in", delimiter=delimiter, decimal=decimal)))


@pytest.mark.parametrize("name", ["index", "sample", "n", "#", "point", "Sample #", "No.", ""])
@pytest.mark.parametrize("where", ["first", "last"])
def test_index_and_unnamed_columns_are_ignored(name, where):
    """The index column holds anything (here text labels): it is never parsed."""
    labels = np.array([f"s{i}" for i in range(TIME.size)])
    header = ["time_s", "position_m", "load_kN"]
    columns = [f"{float(t)!r},{float(p)!r},{float(w) / 1e3!r}" for t, p, w in zip(TIME, POSITION, LOAD)]
    rows = [f"{label},{row}" if where == "first" else f"{row},{label}" for label, row in zip(labels, columns)]
    head = [name, *header] if where == "first" else [*header, name]
    assert_same_card(read_text("\n".join([",".join(head), *rows]) + "\n"))


def test_mapped_columns():
    """Headers the reader does not know, named by --card-columns; units from the mapped headers' brackets."""
    text = table(["Zeit (ms)", "Weg (in)", "Kraft (klb)", "Status"],
                 [TIME / 1e-3, POSITION / INCH, LOAD / (1e3 * POUND_FORCE), np.zeros_like(TIME)])
    mapping = parse_card_columns("time=zeit (ms), position=Weg (in),load=KRAFT (KLB)")
    assert_same_card(read_text(text, columns=mapping))


def test_mapped_cyrillic_headers_with_units_and_decimal_commas():
    """A Russian-language export (semicolons, decimal commas, units in brackets written in
    Cyrillic: с, мм, кН), named by --card-columns: the same card."""
    text = table(["Время (с)", "Ход (мм)", "Нагрузка (кН)"], [TIME, POSITION / 1e-3, LOAD / 1e3], delimiter=";",
                 decimal=",")
    mapping = parse_card_columns("time=Время (с),position=Ход (мм),load=Нагрузка (кН)")
    assert_same_card(read_text(text, columns=mapping))


def test_mapped_columns_without_units_take_the_default_units():
    text = table(["Weg", "Kraft"], [POSITION / INCH, LOAD / POUND_FORCE])
    reading = read_text(text, columns={"position": "Weg", "load": "Kraft"}, units="field")
    assert np.allclose(reading.position, POSITION, rtol=1e-12) and np.allclose(reading.load, LOAD, rtol=1e-12)


def test_crank_angle_card_in_radians_with_index():
    theta = np.linspace(0.0, 2 * np.pi, 90, endpoint=False)
    load = 40e3 + 10e3 * np.sin(theta)
    reading = read_text(table(["#", "theta [rad]", "load [kN]"], [np.arange(theta.size), theta, load / 1e3]))
    assert np.allclose(reading.card.crank_angle, theta, atol=1e-15) and np.allclose(reading.card.load, load, rtol=1e-12)
    assert reading.speed is None and reading.position is None


def test_file_and_stdin_agree(tmp_path):
    path = tmp_path / "card.csv"
    path.write_bytes(ENCODINGS["bom-crlf"](sample_text(delimiter=";", decimal=",")))
    from_file = place(read_card(path), SK8)
    from_stdin = read_text(path.read_bytes())
    assert from_stdin.source == "<stdin>" and from_file.source == str(path)
    assert np.array_equal(from_file.card.load, from_stdin.card.load)
    assert np.array_equal(from_file.card.crank_angle, from_stdin.card.crank_angle)


def test_reversed_sample_gives_exactly_the_same_card():
    """Rows reversed (as some exports store cards): time decreases, the reader turns the rows back
    and says so once; the crank-angle card (and so every torque computed from it) is identical."""
    lines = SK8_CARD.read_text(encoding="utf-8").splitlines()
    reversed_text = "\n".join(lines[:4] + lines[4:][::-1]) + "\n"
    reading = read_text(reversed_text)
    assert len(reading.warnings) == 1 and "reverse time order" in reading.warnings[0] and reading.reversed
    assert np.array_equal(reading.card.crank_angle, REFERENCE.card.crank_angle)
    assert np.array_equal(reading.card.load, REFERENCE.card.load)
    assert reading.speed == REFERENCE.speed


def test_reversed_position_card_gives_exactly_the_same_card():
    """Without time stamps the order comes from the work: listed in reverse, the loop would
    have the rods do work on the unit; the reader reverses it, with one warning."""
    forward = read_text(table(["position_m", "load_kN"], [POSITION, LOAD / 1e3]))
    backward = read_text(table(["position_m", "load_kN"], [POSITION[::-1], LOAD[::-1] / 1e3]))
    assert forward.warnings == () and not forward.reversed
    assert len(backward.warnings) == 1 and "listed in reverse" in backward.warnings[0] and backward.reversed
    assert np.array_equal(forward.card.crank_angle, backward.card.crank_angle)
    assert np.array_equal(forward.card.load, backward.card.load)


def test_crank_angle_card_has_no_orientation():
    theta = np.linspace(0.0, 2 * np.pi, 90, endpoint=False)
    load = 40e3 + 10e3 * np.sin(theta)
    forward = read_text(table(["crank_angle_rad", "load_n"], [theta, load]))
    backward = read_text(table(["crank_angle_rad", "load_n"], [theta[::-1], load[::-1]]))
    assert forward.warnings == backward.warnings == ()
    assert np.array_equal(forward.card.load, backward.card.load)


def test_stroke_warning_in_the_cards_units():
    """A card 3 % short, in inches: the warning quotes the card's and the unit's stroke in
    inches (the unit's exact stroke 2.9128 m of the geometry doctest = 114.7 in)."""
    reading = read_text(table(["position_in", "load_lbf"], [0.97 * POSITION / INCH, LOAD / POUND_FORCE]))
    assert len(reading.warnings) == 1
    warning = reading.warnings[0]
    assert f"{0.97 * np.ptp(POSITION) / INCH:.4g} in" in warning and "114.7 in" in warning and "-3.0 %" in warning


def test_parse_card_columns():
    assert parse_card_columns(" position = Pos (in) ,load=PRL,TIME=Time ") == {
        "position": "Pos (in)", "load": "PRL", "time": "Time"}
    assert parse_card_columns("crank_angle=Winkel,load=Kraft") == {"crank_angle": "Winkel", "load": "Kraft"}


def test_closed_card_is_read_once():
    """A card closed by repeating its first sample (with the time of one cycle later)."""
    period = 2 * math.pi / REFERENCE.speed
    closed = table(["time_s", "position_m", "load_kN"], [np.append(TIME, TIME[0] + period),
                                                          np.append(POSITION, POSITION[0]), np.append(LOAD, LOAD[0]) / 1e3])
    assert_same_card(read_text(closed))


@pytest.mark.parametrize(("header", "culprit", "example"), [
    (["time", "position_m", "load_kN"], "column 1 'time'", "time_s, Time (s)"),
    (["time_s", "position", "load_kN"], "column 2 'position'", "position_m, Position (in)"),
    (["time_s", "position_m", "load"], "column 3 'load'", "load_N, Load (lbf)"),
])
def test_a_column_without_a_unit_needs_the_card_units(header, culprit, example):
    """No guess: a header that names no unit is refused unless the card's units are given,
    and then read in them (the field units here)."""
    text = table(header, [TIME, POSITION / INCH, LOAD / POUND_FORCE])
    with pytest.raises(Exception) as error:
        read_text(text)
    assert f"line 1: {culprit} names no unit: write it in the header ({example})" in str(error.value)
    assert "--card-units si or field" in str(error.value)
    given = read_text(table(["time", "position", "load"], [TIME, POSITION / INCH, LOAD / POUND_FORCE]),
                      units="field")
    assert_same_card(given)
