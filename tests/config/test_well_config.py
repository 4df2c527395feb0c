"""The well's config builds its core objects once, and a changed copy its own."""

from __future__ import annotations

import pytest

from pumpjack_cli.config import load_unit


def test_the_rod_string_is_built_once_and_a_changed_copy_builds_its_own():
    """A well's rods are made once (the batch asks for them for every card), and a copy with another
    pump depth (``model_copy(update=...)``) does not inherit them: its string is its own length."""
    well = load_unit("sk8-3.5-4000").well
    rods = well.rods()
    assert well.rods() is rods
    deeper = well.model_copy(update={"pump_depth": 2000.0})
    assert deeper.rods().total_length == pytest.approx(2000.0) and rods.total_length == pytest.approx(1530.0)
