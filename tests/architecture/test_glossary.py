"""Every output name of every command is in the catalogue and the glossary, with one meaning.

The catalogue (``pumpjack_cli/names.py``) declares each name once; the glossary's output
sections are generated from it and must be what it generates. Each command runs with
``-f json``; every summary key and column key, stripped of the unit suffix of its system,
must be a name of the catalogue and of the glossary (a code span there may hold brace
alternatives, ``r{12,13}_{x,y}``, expanded here).
"""

from __future__ import annotations

import itertools
import json
import re
from pathlib import Path

import pytest

from pumpjack_cli.names import SECTIONS, catalogue, glossary_sections, lookup
from pumpjack_cli.quantities import OUTPUT_QUANTITIES

from helpers import REPO_ROOT, SK8_CARD, command_result, sample_card, written

GLOSSARY = REPO_ROOT / "docs" / "glossary.md"
#: A deviated well's sample card and survey (samples/make_deviated.py).
DEVIATED_CARD = REPO_ROOT / "samples" / "sk8-3.5-4000-deviated-card.csv"
J_SURVEY = REPO_ROOT / "samples" / "j-well-survey.csv"

RUNS = [
    ("units",),
    ("units", "--catalogue", REPO_ROOT / "samples" / "catalogue.csv"),
    ("kinematics", "sk8-3.5-4000", "--steps", "8"),
    ("reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--steps", "8"),
    ("compare-redundancy", "7sk12-2.5-5600", "--card", sample_card("7sk12-2.5-5600"), "--spm", "8", "--steps", "8"),
    ("dynamics", "sk8-3.5-4000", "--steps", "8"),
    ("dynamics", "sk8-3.5-4000", "--steps", "8", "--card", "DRIVABLE"),
    ("inertia-error", "unb-600a", "--steps", "8"),
    ("inertia-error", "unb-600a", "--steps", "8", "--support-friction"),
    ("inertia-error", "sk8-3.5-4000", "--steps", "8", "--mass", "100 kg"),
    ("torque", "sk8-3.5-4000", "--card", SK8_CARD, "--steps", "8"),
    ("torque", "c-80d-133-48", "--card", sample_card("c-80d-133-48"), "--steps", "8"),
    ("downhole", "sk8-3.5-4000", "--card", SK8_CARD, "--samples", "64"),
    ("predict", "sk8-3.5-4000", "--samples", "64", "--damping", "0.1"),
    ("predict", "sk8-3.5-4000", "--samples", "64", "--damping", "0.1", "--crank-motion", "dynamic"),
    ("predict", "c-80d-133-48", "--samples", "64", "--damping", "0.1", "--spm", "8"),
    ("dynamics", "sk8-3.5-4000", "--samples", "64", "--well-model", "wave", "--damping", "0.1"),
    ("downhole", "sk8-3.5-4000", "--card", DEVIATED_CARD, "--survey", J_SURVEY, "--samples", "64", "--damping", "0.05",
     "--guide-limit", "100 lbf"),
    ("downhole", "sk8-3.5-4000", "--card", DEVIATED_CARD, "--survey", J_SURVEY, "--samples", "64", "--damping", "0.05",
     "--profile", "--guide-limit", "100 lbf"),
]


def _expand(span: str) -> list[str]:
    parts = re.split(r"\{([^}]*)\}", span)
    choices = [[part] if i % 2 == 0 else part.split(",") for i, part in enumerate(parts)]
    return ["".join(combo) for combo in itertools.product(*choices)]


def glossary_names() -> set[str]:
    text = GLOSSARY.read_text(encoding="utf-8")
    return {name for span in re.findall(r"`([^`]+)`", text) for name in _expand(span)}


def _base(key: str, system: str, names: set[str]) -> str:
    if key in names:
        return key
    suffixes = sorted({units[system].suffix for units in OUTPUT_QUANTITIES.values() if units[system].suffix},
                      key=len, reverse=True)
    for suffix in suffixes:
        if key.endswith("_" + suffix):
            return key[: -len(suffix) - 1]
    return key


def test_brace_expansion():
    assert _expand("r{12,13}_{x,y}") == ["r12_x", "r12_y", "r13_x", "r13_y"]


@pytest.mark.parametrize("argv", RUNS, ids=lambda argv: " ".join(argv[:2]))
def test_every_output_name_is_in_the_glossary(sk8_drivable_card, argv):
    """The command's result as ``-f json`` writes it in each unit system (the command run once:
    the systems differ in the writing only). DRIVABLE: the SK8 sample card light enough for the
    seed's motor (conftest)."""
    result, out = command_result(*(sk8_drivable_card if arg == "DRIVABLE" else arg for arg in argv))
    assert json.loads(out) == json.loads(written(result, "si"))  # the result written is the one emitted
    names = glossary_names()
    for system in ("si", "field"):
        document = json.loads(written(result, system))
        keys = list(document["summary"]) + list(document["columns"])
        missing = sorted({key for key in keys if _base(key, system, names) not in names})
        assert not missing, f"not in docs/glossary.md ({system}): {missing}"
        for key, column in document["columns"].items():  # the quantity the catalogue declares is the one shown
            quantity = lookup(_base(key, system, names))[0]
            assert column["unit"] == ("" if quantity == "text" else OUTPUT_QUANTITIES[quantity][system].label), key


def test_batch_store_names_are_in_the_glossary(run_cli, tmp_path):
    manifest = tmp_path / "m.csv"
    manifest.write_text(f"well,unit,card,timestamp\nw,sk8-3.5-4000,{Path(SK8_CARD).resolve()},2026-11-24\n")
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", manifest, "--store", store, "--workers", "1")[0] == 0
    names = glossary_names()
    for argv in (("export", "--store", store), ("trend", "--store", store, "--well", "w")):
        code, out, err = run_cli("batch", *argv, "-f", "json")
        assert code == 0, err
        keys = json.loads(out)["columns"]
        missing = sorted({key for key in keys if _base(key, "si", names) not in names})
        assert not missing, f"not in docs/glossary.md: {missing}"


def test_the_glossary_shows_the_catalogue():
    """docs/glossary.md's output sections are exactly what the catalogue generates."""
    text = GLOSSARY.read_text(encoding="utf-8")
    start, end = "<!-- output names: generated from pumpjack_cli/names.py; do not edit by hand -->\n\n", \
        "\n<!-- end of generated output names -->"
    assert text[text.index(start) + len(start):text.index(end)] == glossary_sections()


def test_one_meaning_per_name_and_every_quantity_known():
    names = catalogue()  # raises if a name is declared twice
    assert all(quantity == "text" or quantity in OUTPUT_QUANTITIES for quantity, _ in names.values())
    families = [entry.pattern for section in SECTIONS for entry in section.entries]
    assert len(families) == len(set(families))
    with pytest.raises(KeyError, match="not in the catalogue"):
        lookup("balancing_torque")  # a name of the past, unified into net_torque
