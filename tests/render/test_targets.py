"""Text for a stream whose encoding cannot write it: the plain-ASCII spellings of the
characters the renderer writes, kept where the encoding has them, a backslash escape for
anything else (the console script under an ASCII locale: tests/test_hostile_inputs.py)."""

from __future__ import annotations

import io

from pumpjack_cli.names import VOCABULARY, catalogue
from pumpjack_cli.quantities import OUTPUT_QUANTITIES
from pumpjack_cli.render.targets import PLAIN, EncodedText, plain


def test_every_non_ascii_character_of_the_outputs_has_a_plain_spelling():
    """The catalogue's meanings, its vocabulary and the unit labels of both systems are
    everything of a result that is not the user's (a unit's name, a file's name)."""
    texts = [meaning for _, meaning in catalogue().values()]
    texts += [words for alternatives in VOCABULARY.values() for words in alternatives.values()]
    texts += [unit.label for systems in OUTPUT_QUANTITIES.values() for unit in systems.values()]
    assert {char for text in texts for char in text if not char.isascii()} <= set(PLAIN)
    assert all(spelled.isascii() for spelled in PLAIN.values())


def test_plain_spells_only_what_the_encoding_lacks():
    assert plain("28 N·m, 9.81 m/s², 60 ω1 / 2π", "ascii") == "28 N*m, 9.81 m/s^2, 60 omega1 / 2pi"
    # latin-1 has the degree sign and the middle dot, not the minus sign
    assert plain("90° − τ, N·m", "latin-1") == "90° - tau, N·m"
    # a unit's name in Cyrillic, a file name that is not UTF-8 (a surrogate): escaped
    assert plain("СК8, \udcff.csv", "ascii") == "\\u0421\\u041a8, \\udcff.csv"
    assert plain("\udcff.csv", "utf-8") == "\\udcff.csv"
    assert plain("N·m", "utf-8") == "N·m"


def test_a_stream_that_cannot_encode_gets_the_plain_text_whole():
    raw = io.BytesIO()
    stream = io.TextIOWrapper(raw, encoding="ascii", newline="")
    text = EncodedText(stream)
    text.write("torque [N·m]\n")
    text.write("plain\n")
    stream.flush()
    assert raw.getvalue() == b"torque [N*m]\nplain\n"
