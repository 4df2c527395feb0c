"""The card reader's quick paths read every file as its careful reading does, bit for bit.

Four shortcuts make reading a fleet's cards cheap: the rows of a plain delimited card are read
in one call of numpy's text reader (``delimited._table``), what a header or a preamble line
means is kept for the next file (``delimited._kept``), a card of one stroke is known without
the sample-by-sample walk of ``recording.tops`` (``recording.turns_twice``), and a file named
``.csv`` is not searched for its header to tell its format (``_format_of``). Without them the
reader is the one they were added to: every row looked at in turn, every column converted by
``float`` with its refusals, every line understood anew, every time card walked, every format
asked.

Each file here is read both ways and must give the same raw card (every array as its bytes,
the line of every sample, metadata, warnings, strokes) or the same one-line refusal: every
sample of ``samples/`` (all formats, made by ``samples/make_formats.py``) with the options that
read or refuse it, the hostile files of ``test_card_hostile.py``, and the sample card with what
sends its rows to the careful reading (blank, comment and space lines among the rows, quotes,
decimal commas, tabs, an index column, rows of another width, too few rows).
"""

from __future__ import annotations

import importlib.util
import itertools
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pumpjack_cli.errors import CardError
from pumpjack_cli.readers import cards
from pumpjack_cli.readers.cards import delimited, raw, read_card, recording

from helpers import REPO_ROOT, SK8_CARD

SAMPLES = sorted(path for path in (REPO_ROOT / "samples").iterdir() if path.suffix in {".json", ".hex", ".bin"}
                 or path.name.endswith(("card.csv", "recording.csv", "preamble.csv")))
OPTIONS = ({}, {"units": "si"}, {"units": "field"}, {"format": "delimited"}, {"format": "json"},
           {"format": "hex", "units": "field"}, {"format": "binary", "units": "si"}, {"points": 180, "units": "field"})


def _hostile_cases() -> list[tuple[str, str | bytes, str]]:
    """The hostile files of test_card_hostile.py: (name, content, fragment of the refusal)."""
    spec = importlib.util.spec_from_file_location("card_hostile", Path(__file__).with_name("test_card_hostile.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.CASES


LINES = SK8_CARD.read_text(encoding="utf-8").split("\n")
HEADER = next(i for i, line in enumerate(LINES) if line and not line.startswith("#"))


def variant(change) -> str:
    """The SK8 sample card with its rows changed by ``change(rows) -> rows``."""
    return "\n".join(LINES[:HEADER + 1] + change([line for line in LINES[HEADER + 1:] if line])) + "\n"


VARIANTS = {
    "plain": variant(lambda rows: rows),
    "blank-line": variant(lambda rows: rows[:50] + [""] + rows[50:]),
    "space-line": variant(lambda rows: rows[:50] + ["   "] + rows[50:]),
    "blank-after-header": variant(lambda rows: [""] + rows),
    "comment-line": variant(lambda rows: rows[:50] + ["# a note, with, commas"] + rows[50:]),
    "comment-at-end": variant(lambda rows: rows + ["# end"]),
    "index-hash-row": variant(lambda rows: rows[:50] + ["#,1,2"] + rows[50:]),
    "trailing-blanks": variant(lambda rows: rows + ["", "", "  "]),
    "spaces-in-cells": variant(lambda rows: [row.replace(",", " , ") for row in rows]),
    "quoted-cells": variant(lambda rows: ['"' + row.replace(",", '","') + '"' for row in rows]),
    "quoted-header": variant(lambda rows: rows).replace("time_s,position_m,load_kN",
                                                        '"time_s","position_m","load_kN"'),
    "semicolons": variant(lambda rows: rows).replace(",", ";"),
    "decimal-commas": variant(lambda rows: rows).replace(",", ";").replace(".", ","),
    "tabs": variant(lambda rows: rows).replace(",", "\t"),
    "tab-space-line": variant(lambda rows: rows[:9] + [" , , "] + rows[9:]).replace(",", "\t"),
    "index-column": variant(lambda rows: [f"{k},{row}" for k, row in enumerate(rows)]).replace("time_s", "n,time_s", 1),
    "unnamed-column": variant(lambda rows: [row + "," for row in rows]).replace("load_kN", "load_kN,", 1),
    "short-row": variant(lambda rows: rows[:9] + [rows[9].rsplit(",", 1)[0]] + rows[10:]),
    "long-row": variant(lambda rows: rows[:9] + [rows[9] + ",1"] + rows[10:]),
    "underscore-number": variant(lambda rows: rows[:9] + ["1_0" + rows[9][rows[9].index(","):]] + rows[10:]),
    "unicode-digit": variant(lambda rows: rows[:9] + [rows[9].replace("0", "\uff10", 1)] + rows[10:]),
    "no-break-space": variant(lambda rows: [row + "\u00a0" for row in rows]),
    "crlf-bom": "\ufeff" + variant(lambda rows: rows).replace("\n", "\r\n"),
    "reversed": variant(lambda rows: rows[::-1]),
    "seven-rows": variant(lambda rows: rows[:7]),
    "one-row": variant(lambda rows: rows[:1]),
    "no-rows": variant(lambda rows: []),
    "beyond-limit": variant(lambda rows: rows[:9] + [rows[9].rsplit(",", 1)[0] + ",2e4"] + rows[10:]),
    "two-strokes": variant(lambda rows: rows + [f"{6 + float(row.split(',')[0]):.4f},{row.split(',', 1)[1]}"
                                                for row in rows]),
}


def described(card: cards.RawCard) -> dict[str, object]:
    """Every field of a raw card, arrays as their type, shape and bytes."""
    return {name: (value.dtype.str, value.shape, value.tobytes()) if isinstance(value, np.ndarray)
            else [described(stroke) for stroke in value] if name == "strokes" else value
            for name, value in vars(card).items()}


def exhaustive_format(file: cards.CardFile, path) -> str:
    """The format rule asked of every reader: the first that recognises the content, else the
    one that claims the name's ending, else the default."""
    suffix = Path(str(path)).suffix.lower()
    return next((name for name, reader in cards.READERS.items() if reader.recognises(file)),
                next((name for name, reader in cards.READERS.items() if suffix in reader.extensions),
                     cards.DEFAULT_FORMAT))


def outcome(path: Path, quick: bool, **options) -> object:
    """The raw card read from ``path`` (:func:`described`), or the refusal's message."""
    with pytest.MonkeyPatch.context() as patch:
        if not quick:
            patch.setattr(delimited, "_table", lambda block, delimiter, width: ([], None))
            patch.setattr(delimited, "_KEPT_LINE", -1)
            patch.setattr(recording, "turns_twice", lambda position, hysteresis: True)
            patch.setattr(cards, "_format_of", exhaustive_format)
        try:
            return described(read_card(path, **options))
        except CardError as error:
            return str(error)


def differing(cases) -> list[str]:
    """The labels of the (label, path, options) cases read differently quickly (twice, the second
    with what the first kept) and carefully."""
    found = []
    for label, path, options in cases:
        careful = outcome(path, False, **options)
        if not outcome(path, True, **options) == careful == outcome(path, True, **options):
            found.append(label)
    return found


def test_every_sample_reads_the_same_both_ways():
    found = differing((f"{sample.name} {options}", sample, options) for sample in SAMPLES for options in OPTIONS)
    assert not found, f"read differently quickly and carefully: {found}"


def test_every_hostile_file_is_refused_or_read_the_same_both_ways(tmp_path):
    def cases():
        for k, (label, content, _) in enumerate(_hostile_cases()):
            for name in ("card.csv", "card.dat"):
                path = tmp_path / str(k) / name
                path.parent.mkdir(exist_ok=True)
                path.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
                yield f"{label} as {name}", path, {}

    found = differing(cases())
    assert not found, f"read differently quickly and carefully: {found}"


def test_rows_the_careful_reading_takes_read_the_same_both_ways(tmp_path):
    def cases():
        for name, text in VARIANTS.items():
            path = tmp_path / name / "card.txt"
            path.parent.mkdir()
            path.write_bytes(text.encode("utf-8"))
            for options in ({}, {"units": "field"}, {"columns": {"position": "position_m", "load": "load_kN"}}):
                yield f"{name} {options}", path, options

    found = differing(cases())
    assert not found, f"read differently quickly and carefully: {found}"


def test_a_plain_card_takes_the_quick_path():
    """The sample card's rows are read in one call, and its positions walked by no one."""
    rows, table = delimited._table("\n".join(LINES[HEADER + 1:]), ",", 3)
    assert table is not None and table.shape == (len(rows), 3) == (180, 3)
    card = read_card(SK8_CARD)
    assert not recording.turns_twice(card.position, recording.HYSTERESIS * np.ptp(card.position))


@pytest.mark.parametrize("count", [0, 1, 2, raw.HEAD_LINES - 1, raw.HEAD_LINES, raw.HEAD_LINES + 1,
                                   3 * raw.HEAD_LINES])
@pytest.mark.parametrize("end", ["", "\n", "\n\n"])
def test_the_content_lines_found_one_by_one_are_those_of_the_split_text(count, end):
    """Blank, comment and content lines, fewer and more than the head looked at line by line: the
    content lines, their indices and where the next line starts are those of the split text."""
    kinds = ["", "  ", "# comment", "#,1,2", "time_s,position_m", " x ", "\t"]
    text = "\n".join(kinds[(7 * k) % len(kinds)] for k in range(count)) + end
    starts = np.cumsum([len(line) + 1 for line in text.split("\n")])
    assert list(raw.content_lines_of(text)) == [(i, line, starts[i]) for i, line in enumerate(text.split("\n"))
                                                if raw.is_content(line)]


def test_every_short_walk_with_two_tops_turns_twice():
    """turns_twice is true wherever tops finds two tops, so split's shortcut drops no recording:
    every sequence of up to 7 positions among 0, 1 and 2, whose turns are the hysteresis or
    more, exactly."""
    for size in range(2, 8):
        for values in itertools.product((0.0, 1.0, 2.0), repeat=size):
            position = np.array(values)
            for hysteresis in (1.0, 2.0):
                assert len(recording.tops(position, hysteresis)) < 2 or recording.turns_twice(position, hysteresis)


@given(st.lists(st.integers(-4, 4).map(float) | st.floats(-10.0, 10.0), min_size=2, max_size=40),
       st.sampled_from([0.5, 1.0, 2.0, 3.0]) | st.floats(1e-9, 20.0))
def test_positions_with_two_tops_turn_twice(values, hysteresis):
    """The same for longer walks of any numbers."""
    position = np.array(values)
    assert len(recording.tops(position, hysteresis)) < 2 or recording.turns_twice(position, hysteresis)
