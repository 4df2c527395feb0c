"""docs/unit-files.md lists every key of the unit files as the schema defines it.

The page's generated part must be what :func:`pumpjack_cli.config.reference.unit_file_reference`
generates from the schema now; and, read independently of the generator, every key of
every section of the schema (each kind of ``[geometry]`` in ``UNIT_CLASSES`` included) must
have its row, and the page's TOML example must load.
"""

from __future__ import annotations

import re

from pydantic import BaseModel

from pumpjack_cli.config.reference import BEGIN, END, PAGE, unit_file_reference
from pumpjack_cli.config.unit_classes import UNIT_CLASSES


def _generated() -> str:
    text = PAGE.read_text(encoding="utf-8")
    return text[text.index(BEGIN) + len(BEGIN):text.index(END)].strip("\n") + "\n"


def test_the_page_is_what_the_schema_generates():
    assert _generated() == unit_file_reference(), \
        "docs/unit-files.md is stale: run python -m pumpjack_cli.config.reference --write"


def _keys(model: type[BaseModel]) -> set[str]:
    return {field.alias or name for name, field in model.model_fields.items()}


def _rows(heading: str) -> set[str]:
    """The keys of the table under a heading of the page."""
    text = _generated()
    start = text.index(heading)
    following = re.search(r"\n#{2,4} ", text[start + len(heading):])
    block = text[start:start + len(heading) + (following.start() if following else len(text))]
    return set(re.findall(r"^\| `([^`]+)` \|", block, re.M))


def test_every_geometry_kind_and_key_has_its_row():
    for name, kind in UNIT_CLASSES.items():
        model = kind.model()
        scalar = {key for key in _keys(model) if key != "air_cylinder"}
        assert scalar <= _rows(f"#### `[geometry]` of a `{name}` unit"), name


def test_every_section_of_the_beam_unit_has_its_rows():
    from pumpjack_cli.config.beam_unit import CounterbalanceConfig, Deviations, JointsConfig, PitmanSectionConfig, Rating
    from pumpjack_cli.config.drive import Drive, Motor
    from pumpjack_cli.config.masses import BeamPart, Counterweights, CrankArm, Equalizer, Pitman
    from pumpjack_cli.config.well import RodSection, Well

    for heading, model in (("### `[rating]`", Rating), ("### `[counterbalance]`", CounterbalanceConfig),
                           ("### `[masses.crank_arm]`", CrankArm), ("### `[masses.counterweights]`", Counterweights),
                           ("### `[masses.pitman]`", Pitman), ("### `[masses.equalizer]`", Equalizer),
                           ("### `[masses.beam]`", BeamPart), ("### `[masses.horsehead]`", BeamPart),
                           ("### `[drive]`", Drive), ("### `[drive.motor]`", Motor),
                           ("### `[[well.rod_string]]`", RodSection), ("### `[pitman_section]`", PitmanSectionConfig),
                           ("### `[deviations]`", Deviations), ("### `[joints]`", JointsConfig)):
        keys = {k for k in _keys(model) if k not in ("motor",)}
        assert keys <= _rows(heading), heading
    assert _keys(Well) - {"rod_string"} <= _rows("### `[well]`")
    assert {"counterbalance_effect", "counterbalance_effect_angle", "moment"} <= _rows("### `[counterbalance]`")
    assert {"tubing_anchored", "tubing_size"} <= _rows("### `[well]`")


def test_the_pages_example_unit_loads(tmp_path):
    from pumpjack_cli.config import load_unit

    block = re.search(r"```toml\n(.*?)```", PAGE.read_text(encoding="utf-8"), re.S).group(1)
    path = tmp_path / "unit.toml"
    path.write_text(block, encoding="utf-8")
    balance, known = load_unit(str(path)).counterbalance_model()
    assert known and balance.moment > 0
