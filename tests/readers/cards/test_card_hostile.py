"""Hostile card files, generated: every one is refused with one line naming the file, the line and the culprit.

The cases are built by mutating the SK8 sample card (kept with its three comment lines,
so its header is line 4 and sample r is on line r + 5) one cell, row, header name,
encoding or property at a time, plus files that are not card files at all. Each
asserts a CardError whose message is a single line starting with the file's name (or
``<stdin>``) and holding the expected fragment, which names the line and the column
(by kind or number) wherever there is one.
"""

from __future__ import annotations

import io
import math
import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import load_unit
from pumpjack_cli.errors import CardError
from pumpjack_cli.readers import cards
from pumpjack_cli.readers.cards import delimited, parse_card_columns

from helpers import INCH, SK8_CARD

SK8 = load_unit("sk8-3.5-4000").geometry.mechanism()
LINES = SK8_CARD.read_text(encoding="utf-8").splitlines()
COMMENTS, HEADER, ROWS = LINES[:3], LINES[3], LINES[4:]
KINDS = ("time", "position", "load")
PICKS = (0, 89, len(ROWS) - 1)


def line_of(row: int) -> int:
    return row + 5


def card(rows=ROWS, header=HEADER) -> str:
    return "\n".join([*COMMENTS, header, *rows]) + "\n"


def with_cell(row: int, column: int, value: str) -> str:
    rows = list(ROWS)
    cells = rows[row].split(",")
    cells[column] = value
    rows[row] = ",".join(cells)
    return card(rows)


def with_time(row: int, value: str) -> str:
    return with_cell(row, 0, value)


def cells(row: int) -> list[str]:
    return ROWS[row].split(",")


def numeric_card(header: str, columns, delimiter=",") -> str:
    return header + "\n" + "\n".join(delimiter.join(repr(float(v)) for v in row) for row in zip(*columns)) + "\n"


def rod(theta):
    m = SK8.motion(theta)
    return SK8.front_arm * (m.beam_angle - SK8.dead_positions().beam_angle_bottom), m.beam_rate


def time_card(theta, time) -> str:
    s, rate = rod(theta)
    return numeric_card("time_s,position_m,load_n", [time, s, np.where(rate > 0, 52e3, 40e3)])


BAD_CELLS = {"abc": "'abc' is not a number", "": "is empty", "nan": "is nan, not a finite number",
             "-inf": "is -inf, not a finite number", "1e999": "is 1e999, not a finite number",
             "12..5": "'12..5' is not a number", "0x1F": "'0x1F' is not a number", "1 000": "'1 000' is not a number",
             # Python's float reads these two (underscores, Arabic-Indic digits); no logger writes them
             "4_5.5": "'4_5.5' is not a number", "\u0664\u0665.\u0665": "'\u0664\u0665.\u0665' is not a number"}

CASES: list[tuple[str, str | bytes, str]] = []
CASES += [(f"cell-{kind}-line{line_of(r)}-{value or 'empty'}", with_cell(r, j, value), f"line {line_of(r)}: {kind} {what}")
          for r in PICKS for j, kind in enumerate(KINDS) for value, what in BAD_CELLS.items()]
CASES += [(f"absurd-{kind}-{value}-line{line_of(r)}", with_cell(r, j, value), f"line {line_of(r)}: {kind} {value} {unit} is beyond {shown}")
          for r in PICKS for j, kind, value, unit, shown in ((1, "position", "1001", "m", "1 km"),
                                                             (1, "position", "-2e5", "m", "1 km"),
                                                             (2, "load", "1.0001e4", "kN", "10 MN"),
                                                             (2, "load", "-1e300", "kN", "10 MN"))]
CASES += [(f"row-short-line{line_of(r)}", card([*ROWS[:r], ",".join(cells(r)[:2]), *ROWS[r + 1:]]),
           f"line {line_of(r)}: 2 values, the header has 3") for r in PICKS]
CASES += [(f"row-long-line{line_of(r)}", card([*ROWS[:r], ROWS[r] + ",7", *ROWS[r + 1:]]),
           f"line {line_of(r)}: 4 values, the header has 3") for r in PICKS]
CASES += [(f"thousands-separator-line{line_of(r)}", with_cell(r, 2, "52,023.9"),
           f"line {line_of(r)}: 4 values, the header has 3; a decimal comma or thousands separator") for r in PICKS]
CASES += [(f"duplicated-time-line{line_of(r)}", with_time(r, cells(r - 1)[0]),
           f"line {line_of(r)}: time {float(cells(r - 1)[0]):.6g} s repeats line {line_of(r - 1)}") for r in PICKS[1:]]
CASES += [(f"time-goes-back-line{line_of(r)}", with_time(r, cells(r - 2)[0]), f"line {line_of(r)}: time does not increase")
          for r in PICKS[1:]]
CASES += [(f"unknown-{j}-{name}", card(header=",".join(name if i == j else h for i, h in enumerate(HEADER.split(",")))),
           f"line 4: unknown column '{name}' (column {j + 1})")
          for j in range(3) for name in ("speed", "Pressure (psi)", "Zeit", "load2", "?")]
WRONG_UNITS = {0: ("m", "kN", "deg"), 1: ("s", "kN", "kg"), 2: ("m", "s", "psi")}
CASES += [(f"unit-{KINDS[j]}-{unit}", card(header=",".join(f"{KINDS[j]}_{unit}" if i == j else h
                                                          for i, h in enumerate(HEADER.split(",")))),
           f"line 4: column {j + 1} '{KINDS[j]}_{unit}' has unit '{unit}', not a unit of "
           f"{('time', 'length', 'force')[j]}") for j, units in WRONG_UNITS.items() for unit in units]
CASES += [(f"layout-{header}", card(header=header + ",index" * (3 - header.count(",") - 1)),
           "line 4: columns") for header in ("time_s,load_kN", "position_m,time_s", "crank_angle_deg,position_m",
                                            "load_kN,load_kN", "time_s,position_m,load_kN,crank_angle_deg")]
CASES += [(f"decimal-mark-{KINDS[j]}-line{line_of(r)}",
           card([";".join(c.replace(".", "." if (i, k) == (r, j) else ",") for k, c in enumerate(row.split(",")))
                 for i, row in enumerate(ROWS)], header=HEADER.replace(",", ";")),
           f"line {line_of(r)}: {KINDS[j]} '{cells(r)[j]}' a point; cannot tell the decimal mark")
          for r in PICKS for j in range(3) if (r, j) != (0, 0)]
CASES += [
    ("utf16-bom", card().encode("utf-16"), "UTF-16 or UTF-32 text"),
    ("utf16-be-bom", b"\xfe\xff" + card().encode("utf-16-be"), "UTF-16 or UTF-32 text"),
    ("utf16-no-bom", card().encode("utf-16-le"), "line 1: a NUL character"),
    ("cp1251-header", card(header="Время,Ход,Нагрузка").encode("cp1251"), "line 4: byte 0xc2 is not UTF-8"),
    ("latin1-comment", card().replace("# (rod string", "# Winkel in °, (rod string").encode("latin-1"),
     "line 2: byte 0xb0 is not UTF-8"),
    ("nul-in-data", card().replace(ROWS[89], ROWS[89] + "\0"), f"line {line_of(89)}: a NUL character"),
    ("gzip", b"\x1f\x8b\x08\x00" + bytes(range(256)), "line 1: a NUL character"),
    ("empty", "", "empty card"),
    ("only-comments", "\n".join(COMMENTS) + "\n\n", "empty card"),
    ("header-only", card(rows=[]), "0 points; a card needs at least 8"),
    ("seven-points", card(rows=ROWS[:7]), "7 points; a card needs at least 8"),
    ("no-header", "\n".join(ROWS) + "\n", "line 1: numbers where the header should be"),
    ("no-header-decimal-commas", "0,0;0,1;52,3\n0,1;0,2;52,4\n", "line 1: numbers where the header should be"),
    ("no-delimiter", "time position load\n1 2 3\n", "line 1: no comma, semicolon or tab in the header"),
    ("too-many-columns", ",".join(["index"] * 65) + "\n", "line 1: 65 columns; a card file has at most 64"),
    ("angles-all-equal", numeric_card("crank_angle_deg,load_n", [np.full(20, 90.0), np.linspace(4e4, 5e4, 20)]),
     "every crank angle is 90 deg"),
    ("angles-half-turn", numeric_card("crank_angle_deg,load_n", [np.arange(0.0, 181.0, 2.0), np.full(91, 4e4)]),
     "crank angles leave 180 deg of the crank's revolution without a sample"),
    ("rod-does-not-move", numeric_card("position_m,load_n", [np.full(20, 1.2), np.linspace(4e4, 5e4, 20)]),
     "the polished rod does not move (every position is 1.2 m)"),
    ("stroke-10-percent-short", numeric_card("position_in,load_lbf", [0.9 * rod(np.linspace(0, 6.28, 90))[0] / INCH,
                                                                      np.full(90, 9e3)]),
     "differs from the unit's exact stroke 114.7 in by -10.0 %"),
    ("reversed-against-time", numeric_card("time_s,position_m,load_kN", [np.arange(len(ROWS)) * 0.03,
                                                                          *np.array([c.split(",")[1:] for c in ROWS[::-1]],
                                                                                    dtype=float).T]),
     "in time order the rods do"),
    ("shuffled-positions", numeric_card("time_s,position_m,load_n", [np.arange(180) * 0.03,
                                                                      np.random.default_rng(3).permutation(rod(np.linspace(0, 6.28, 180))[0]),
                                                                      np.linspace(4e4, 5e4, 180)]),
     "samples; a stroke needs at least 8 (positions that turn every few samples are not a recording)"),
    ("positions-reversed-in-blocks", numeric_card("time_s,position_m,load_n", [
        np.arange(180) * 0.03, np.concatenate([block[::-1] for block in np.split(rod(np.linspace(0, 6.28, 180))[0], 18)]),
        np.where(rod(np.linspace(0, 6.28, 180))[1] > 0, 52e3, 40e3)]), "the time stamps do not fit this unit's motion"),
    ("crank-turning-back", time_card(0.6 * np.arange(180) * 0.05 + 1.2 * np.sin(0.6 * np.arange(180) * 0.05),
                                     np.arange(180) * 0.05), "turn backwards at times"),
    ("three-quarter-turn", time_card(np.linspace(0.0, 1.5 * math.pi, 150), np.linspace(0.0, 7.5, 150)),
     "leave 9"),
]


def read(path, unit=SK8, units: str | None = None, **kwargs):
    """A card file read without a unit (:func:`pumpjack_cli.readers.cards.read_card`), then placed on ``unit``."""
    return place(cards.read_card(path, units=units, **kwargs), unit)


def check(error: pytest.ExceptionInfo, source: str, fragment: str) -> None:
    message = str(error.value)
    assert "\n" not in message and "\r" not in message
    assert message.startswith(f"{source}: "), message
    assert fragment in message, message


@pytest.mark.parametrize(("content", "fragment"), [case[1:] for case in CASES], ids=[case[0] for case in CASES])
def test_hostile_file(tmp_path, content, fragment):
    path = tmp_path / "card.csv"
    (path.write_bytes if isinstance(content, bytes) else lambda text: path.write_text(text, encoding="utf-8"))(content)
    with pytest.raises(CardError) as error:
        read(path, SK8)
    check(error, str(path), fragment)


@pytest.mark.parametrize(("content", "fragment"), [case[1:] for case in CASES[::7]], ids=[case[0] for case in CASES[::7]])
def test_hostile_stdin(content, fragment):
    stream = io.BytesIO(content) if isinstance(content, bytes) else io.StringIO(content)
    with pytest.raises(CardError) as error:
        read("-", SK8, stream=stream)
    check(error, "<stdin>", fragment)


def test_the_generator_makes_enough_cases():
    assert len(CASES) > 120 and len({case[0] for case in CASES}) == len(CASES)


def fifo(tmp_path):
    path = tmp_path / "fifo"
    os.mkfifo(path)
    return path


def sparse(tmp_path):
    path = tmp_path / "huge.csv"
    with open(path, "wb") as file:
        file.truncate(cards.MAX_BYTES + 1)  # sparse: the limit is checked before a byte is read
    return path


PATHS = {
    "directory": (lambda tmp_path: tmp_path, "is a directory, not a card file"),
    "fifo": (fifo, "is a FIFO (named pipe), not a card file"),
    "dev-zero": (lambda tmp_path: Path("/dev/zero"), "is a device, not a card file"),
    "dev-null": (lambda tmp_path: Path("/dev/null"), "is a device, not a card file"),
    "missing": (lambda tmp_path: tmp_path / "nope.csv", "cannot read: no such file"),
    "name-too-long": (lambda tmp_path: tmp_path / ("x" * 5000), "cannot read: file name too long"),
    "oversize": (sparse, f"{cards.MAX_BYTES + 1:,} bytes; a card file is at most {cards.MAX_BYTES:,} bytes"),
}


@pytest.mark.parametrize("name", PATHS)
def test_paths_that_are_not_card_files(tmp_path, name):
    """No hang on a FIFO or /dev/zero, no reading of a 10 MB file: refused from its metadata."""
    make, fragment = PATHS[name]
    path = make(tmp_path)
    with pytest.raises(CardError) as error:
        read(path, SK8)
    check(error, str(path), fragment)


def test_name_with_control_characters_stays_on_one_line(tmp_path):
    path = tmp_path / "two\nlines.csv"
    with pytest.raises(CardError) as error:
        read(path, SK8)
    check(error, str(path).replace("\n", "\\n"), "cannot read")
    with pytest.raises(CardError, match="the name holds a NUL character"):
        read("a\0b.csv", SK8)


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="root reads any file")
def test_permission_denied(tmp_path):
    path = tmp_path / "card.csv"
    path.write_text(card(), encoding="utf-8")
    path.chmod(0)
    with pytest.raises(CardError) as error:
        read(path, SK8)
    check(error, str(path), "cannot read: permission denied")


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_stdin_terminal_is_refused():
    with pytest.raises(CardError) as error:
        read("-", SK8, stream=Terminal(card()))
    check(error, "<stdin>", "is a terminal")


def test_stdin_is_read_with_a_bounded_size(monkeypatch):
    """An endless pipe (here a stream longer than the limit) is cut at MAX_BYTES + 1 and refused."""
    monkeypatch.setattr(cards, "MAX_BYTES", 1000)
    stream = io.BytesIO(card().encode())
    with pytest.raises(CardError) as error:
        read("-", SK8, stream=stream)
    check(error, "<stdin>", "more than 1,000 bytes")
    assert stream.tell() == 1001


@pytest.mark.skipif(not os.path.isfile("/proc/version"), reason="no /proc/version")
def test_a_file_that_states_no_size_is_read_whole_and_bounded():
    """A file is read by the size it states (reading by the limit would allocate the limit, 10 MB
    for each card); one that states none (size 0, as the files of /proc) or grew meanwhile is
    read on, still cut at the limit."""
    from pumpjack_cli.text_input import read_bytes

    content = Path("/proc/version").read_bytes()
    assert os.stat("/proc/version").st_size == 0 and len(content) > 20
    assert read_bytes("/proc/version", 10_000, "card file", CardError) == content
    with pytest.raises(CardError) as error:
        read_bytes("/proc/version", 20, "card file", CardError)
    check(error, "/proc/version", "more than 20 bytes")


@given(st.lists(st.sampled_from(["", " ", "\t", "#", "# note", "#,position,load", " #;1", "#x\t", "1,2", "a#b,3",
                                 "\t1\t2"]), max_size=12))
def test_the_lines_read_are_those_neither_blank_nor_comments(lines):
    """The delimited reader looks at each line only up to the last '#': the lines it keeps are
    those the rule of raw.is_content keeps, wherever the comments and blanks are."""
    from pumpjack_cli.readers.cards.raw import is_content

    text = "\n".join(lines)
    assert delimited._content(text.split("\n"), text) == [i for i, line in enumerate(text.split("\n"))
                                                           if is_content(line)]


@given(st.floats(-1e7, 1e7), st.one_of(st.floats(-1e7, 1e7), st.just(0.0)), st.floats(-1e-4, 1e-4))
def test_a_closed_card_is_told_as_numpy_allclose_tells_it(a, b, step):
    """A card whose last sample repeats its first within numpy.allclose's tolerances loses the
    repeat: the reader's scalar test agrees with numpy's on finite numbers, near and far."""
    from pumpjack_cli.readers.cards.raw import _close

    for x, y in ((a, b), (a, a + step), (a, a * (1 + step))):
        assert _close(x, y) == bool(np.allclose(x, y)), (x, y)


def test_lines_limit_is_checked_before_splitting():
    """2.5 million lines of 4 bytes (under 10 MB) are refused from a count, not split into lists."""
    with pytest.raises(CardError) as error:
        read("-", SK8, stream=io.BytesIO(b"position,load\n" + b"1,2\n" * 2_499_000))
    check(error, "<stdin>", f"more than {delimited.MAX_LINES} lines")


def test_points_limit(monkeypatch):
    monkeypatch.setattr(delimited, "MAX_POINTS", 100)
    with pytest.raises(CardError) as error:
        read("-", SK8, stream=io.StringIO(card()))
    check(error, "<stdin>", "180 points; a card has at most 100")


MAPPED = numeric_card("Zeit,Weg,Kraft,Kraft", [np.arange(4.0)] * 4)
MAPPINGS = [
    ({"position": "Strecke", "load": "Zeit"}, "line 1: --card-columns position='Strecke': no column of that name"),
    ({"position": "Weg", "load": "Kraft"}, "line 1: --card-columns load='Kraft': 2 columns (3, 4) of that name"),
    ({"position": "Weg", "load": "Zeit (kg)"}, "--card-columns load='Zeit (kg)': no column"),
]


@pytest.mark.parametrize(("mapping", "fragment"), MAPPINGS)
def test_bad_mappings(mapping, fragment):
    with pytest.raises(CardError) as error:
        read("-", SK8, "si", stream=io.StringIO(MAPPED), columns=mapping)
    check(error, "<stdin>", fragment)


def test_mapped_header_with_a_wrong_unit():
    with pytest.raises(CardError) as error:
        read("-", SK8, stream=io.StringIO("Weg (kg),Kraft\n1,2\n"), columns={"position": "Weg (kg)", "load": "Kraft"})
    check(error, "<stdin>", "line 1: column 1 'Weg (kg)' has unit 'kg', not a unit of length")


@pytest.mark.parametrize(("text", "fragment"), [
    ("position=a", "--card-columns: position given; a card has"),
    ("position=a,load", "--card-columns: 'load' is not kind=header"),
    ("speed=a,load=b", "--card-columns: unknown column kind 'speed'"),
    ("position=a,POSITION=b,load=c", "--card-columns: position given twice"),
    ("position=a,load=b,time= ", "--card-columns: time needs a header name"),
    ("", "--card-columns: '' is not kind=header"),
])
def test_bad_card_columns_option(text, fragment):
    with pytest.raises(CardError) as error:
        parse_card_columns(text)
    assert "\n" not in str(error.value) and fragment in str(error.value)


@pytest.mark.parametrize(("scale", "spm"), [(1e-2, 1090.8), (1e3, 0.010908)])
def test_time_stamps_that_give_no_beam_units_speed_are_refused(tmp_path, scale, spm):
    """The sample card (10.908 strokes/min) with its time stamps scaled: the speed they give, 10.908 /
    scale, lies outside the 0.1 .. 60 strokes/min of --spm and of a stated SPM, so the card is refused
    by name (a time column in ms or minutes read as seconds) instead of giving numbers."""
    lines = Path(SK8_CARD).read_text(encoding="utf-8").splitlines()
    header = next(i for i, line in enumerate(lines) if line.startswith("time_s"))
    rows = [line.split(",") for line in lines[header + 1:]]
    path = tmp_path / "scaled.csv"
    path.write_text("\n".join([lines[header], *(",".join([repr(float(t) * scale), s, w]) for t, s, w in rows)]) + "\n",
                    encoding="utf-8")
    with pytest.raises(CardError, match=rf"^{path}: its time stamps give {spm:.4g} strokes/min, outside 0.1 \.\. 60"):
        place(cards.read_card(path), load_unit("sk8-3.5-4000").geometry.mechanism())


def test_a_json_card_with_an_integer_beyond_pythons_digit_limit_is_one_line(tmp_path):
    path = tmp_path / "card.json"
    path.write_text('{"position_m": [0, 1, 2], "load_n": [1, 2, ' + "1" * 5001 + "]}", encoding="utf-8")
    with pytest.raises(CardError, match=rf"^{path}: not valid JSON: an integer of more than 4300 digits$"):
        cards.read_card(path)
