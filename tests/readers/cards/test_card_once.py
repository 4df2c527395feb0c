"""A card is read without a unit, then parsed once and placed once per run.

The parser is the registry's delimited reader and the placement's one time fit is
``core.beam.card.fit_rotations`` as the placement calls it (one call fits a group of
cards, here the one card); both are counted through
monkeypatched wrappers while `pumpjack torque` and `pumpjack batch` (one worker, in this
process) run on a time-stamped card.
"""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from pumpjack_cli.core import cards as placement
from pumpjack_cli.errors import CardError
from pumpjack_cli.readers import cards
from pumpjack_cli.readers.cards import RawCard, read_card

from helpers import SK8_CARD

#: The sample's columns, read with numpy (independently of the reader): time [s], position [m], load [kN].
TIME, POSITION, LOAD_KN = np.loadtxt(SK8_CARD, delimiter=",", comments="#", skiprows=4, unpack=True)


def test_a_card_is_read_without_a_unit():
    """No unit file, no linkage: the SI columns, the line of every sample (three comment
    lines and a header, so sample r is on line r + 5), no warnings, no metadata yet."""
    raw = read_card(SK8_CARD)
    assert isinstance(raw, RawCard) and raw.source == str(SK8_CARD)
    assert np.array_equal(raw.time, TIME) and np.array_equal(raw.position, POSITION)
    assert np.allclose(raw.load, 1e3 * LOAD_KN, rtol=1e-15, atol=0)
    assert raw.crank_angle is None and not raw.reversed and raw.warnings == () and raw.metadata == {}
    assert raw.lines.tolist() == list(range(5, 5 + TIME.size))
    assert raw.column_units == {"time": ("s", 1.0), "position": ("m", 1.0), "load": ("kN", 1e3)}


def test_the_format_is_told_from_content_or_name_else_the_default(tmp_path):
    """A delimited card whose name says nothing is read by content; a name the registry does
    not know and content it does not recognise fall back to the default; an unknown format
    name is refused in one line."""
    path = tmp_path / "card.dynamometer"
    path.write_text(SK8_CARD.read_text(encoding="utf-8"), encoding="utf-8")
    assert np.array_equal(read_card(path).position, POSITION)
    text = cards.CardFile(b"no delimiter here\n", "card")
    assert cards._format_of(text, "card.xyz") == cards.DEFAULT_FORMAT
    assert cards._format_of(text, "card.csv") == "delimited"
    assert cards._format_of(text, "card.bin") == "binary"
    with pytest.raises(CardError, match="^--card-format 'xml': use json, hex, binary, delimited$"):
        read_card(path, format="xml")


@pytest.fixture
def counted(monkeypatch) -> Counter:
    """Calls of the card parser and of the time fit, counted."""
    calls = Counter()
    parse, fit = cards.READERS["delimited"], placement.fit_rotations

    def counting_parse(*args, **kwargs):
        calls["parse"] += 1
        return parse.read(*args, **kwargs)

    def counting_fit(*args, **kwargs):
        calls["fit"] += 1
        return fit(*args, **kwargs)

    monkeypatch.setitem(cards.READERS, "delimited", cards.Reader(counting_parse, parse.recognises, parse.extensions))
    monkeypatch.setattr(placement, "fit_rotations", counting_fit)
    return calls


def test_torque_with_the_cards_rotation_parses_and_fits_once(run_cli, counted):
    """--crank-motion card takes the crank speed and acceleration from the placement's fit: no
    second fit of the time stamps."""
    code, out, err = run_cli("torque", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-motion", "card", "-f", "csv")
    assert code == 0, err
    assert counted == {"parse": 1, "fit": 1}


def test_a_batch_card_is_parsed_and_fitted_once_for_both_analyses(run_cli, tmp_path, counted):
    """`pumpjack batch` on one worker (in this process): torque and downhole of one card."""
    (tmp_path / "card.csv").write_text(SK8_CARD.read_text(encoding="utf-8"), encoding="utf-8")
    manifest = tmp_path / "manifest.csv"
    manifest.write_text("well,unit,card\nwell-1,sk8-3.5-4000,card.csv\n", encoding="utf-8")
    code, out, err = run_cli("batch", manifest, "--store", tmp_path / "results.sqlite", "--workers", "1",
                             "--analyses", "torque,downhole")
    assert code == 0, err
    assert "2 results ok, 0 errors" in out
    assert counted == {"parse": 1, "fit": 1}
