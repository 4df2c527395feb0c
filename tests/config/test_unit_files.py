"""Unit files (of pumping units): every shipped file validates, bundled names, GOST names and
API letters, one invalid field at a time, file-level errors.

That the bundled SK8-3,5-4000 holds the data of [SK8Rotation2013] is checked in
tests/validation/test_sk8rotation2013.py.
"""

from __future__ import annotations

import copy
import dataclasses
import json
import math
import tomllib
from pathlib import Path

import pytest

from pumpjack_cli.config import bundled_units, load_unit, parse_unit, read_unit_file
from pumpjack_cli.errors import ConfigError, PumpjackError

from helpers import REPO_ROOT, SK8_API_YAML, SK8_TOML

CONFIG_SUFFIXES = (".toml", ".yaml", ".yml", ".json")
#: Unit files shipped (the dynamometer cards in samples/, <unit>-card.*, are no unit files).
SHIPPED_FILES = sorted(
    p for folder in ("configs", "samples") for p in (REPO_ROOT / folder).iterdir()
    if p.suffix in CONFIG_SUFFIXES and not p.stem.endswith("-card")
)
BUNDLED_FILES = sorted(p for p in (REPO_ROOT / "configs").iterdir() if p.suffix in CONFIG_SUFFIXES)


def _sk8_data() -> dict:
    with SK8_TOML.open("rb") as f:
        return tomllib.load(f)


# --- every shipped file validates --------------------------------------------------


def test_shipped_files_are_discovered():
    # Guard for the parametrized test below: an empty glob would silently test nothing.
    names = {p.relative_to(REPO_ROOT).as_posix() for p in SHIPPED_FILES}
    assert {"configs/sk8-3.5-4000.toml", "samples/sk8-3.5-4000-api.yaml"} <= names


@pytest.mark.parametrize("path", SHIPPED_FILES, ids=lambda p: p.relative_to(REPO_ROOT).as_posix())
def test_shipped_file_validates(path):
    config = read_unit_file(path)
    assert config.name
    if config.kind == "beam-pump":
        # A beam pump's geometry must give a usable linkage (validation checks assembly).
        assert config.geometry.mechanism().crank_radius > 0


# --- bundled units and load_unit ---------------------------------------------------


def test_bundled_units_lists_every_config_file():
    units = bundled_units()
    assert set(units) == {p.stem for p in BUNDLED_FILES}
    assert list(units) == sorted(units)
    for name, path in units.items():
        assert Path(path).is_file()
        assert Path(path).stem == name
        assert Path(path).read_bytes() == (REPO_ROOT / "configs" / Path(path).name).read_bytes()


@pytest.mark.parametrize("spec", ["sk8-3.5-4000", "SK8-3.5-4000", "Sk8-3.5-4000", "SK8-3,5-4000", "sk8-3,5-4000"])
def test_load_unit_by_bundled_name(spec):
    assert load_unit(spec) == read_unit_file(SK8_TOML)


def test_load_unit_by_path(monkeypatch):
    expected = read_unit_file(SK8_TOML)
    assert load_unit(str(SK8_TOML)) == expected
    monkeypatch.chdir(REPO_ROOT)
    assert load_unit("configs/sk8-3.5-4000.toml") == expected
    assert load_unit("samples/sk8-3.5-4000-api.yaml").name == "SK8-3,5-4000 (API letters)"


def test_load_unit_unknown_name_lists_available():
    with pytest.raises(ConfigError) as info:
        load_unit("sk99-no-such-unit")
    message = str(info.value)
    assert "sk99-no-such-unit" in message
    for path in BUNDLED_FILES:
        assert path.stem in message


def test_load_unit_missing_file(tmp_path):
    missing = tmp_path / "nothing-here.toml"
    with pytest.raises(ConfigError, match="no such file") as info:
        load_unit(str(missing))
    assert str(missing) in str(info.value)


def test_config_error_is_a_user_error():
    # The CLI turns PumpjackError into one line and exit 2; ConfigError must be one.
    assert issubclass(ConfigError, PumpjackError)


# --- GOST names vs API letters -----------------------------------------------------


def _api_geometry() -> dict:
    """Geometry of SK8-3,5-4000 in API letters, as in samples/sk8-3.5-4000-api.yaml."""
    return {"A": "3500 mm", "C": "2500 mm", "R": "1010 mm", "P": "3000 mm", "I": "2195 mm",
            "H": "4500 mm", "G": "1500 mm", "rotation": "cw"}


def _with_geometry(geometry: dict) -> dict:
    return {"name": "test", "geometry": geometry}


def _assert_same_linkage(a, b, rel=1e-15):
    for field in dataclasses.fields(a):
        x, y = getattr(a, field.name), getattr(b, field.name)
        assert math.isclose(x, y, rel_tol=rel, abs_tol=0.0), (field.name, x, y)


def test_gost_and_api_files_give_the_same_linkage():
    # Same numbers in the same units, so the conversion is identical: 1e-15 relative
    # (H - G = 4.5 - 1.5 is exact in binary).
    _assert_same_linkage(read_unit_file(SK8_TOML).geometry.mechanism(), read_unit_file(SK8_API_YAML).geometry.mechanism())


def test_api_letters_inline_match_gost():
    gost = parse_unit(_with_geometry(_sk8_data()["geometry"]), "gost.toml").geometry.mechanism()
    api = parse_unit(_with_geometry(_api_geometry()), "api.toml").geometry.mechanism()
    _assert_same_linkage(gost, api)


def test_k_instead_of_h_and_g():
    # K is the straight distance crank shaft - centre bearing: K² = I² + (H - G)².
    geometry = _api_geometry()
    del geometry["H"], geometry["G"]
    geometry["K"] = math.hypot(2.195, 3.0)
    linkage = parse_unit(_with_geometry(geometry), "k.toml").geometry.mechanism()
    # sqrt(K² - I²) after hypot: a few roundings, rel 1e-12.
    assert linkage.vertical_offset == pytest.approx(3.0, rel=1e-12)
    reference = parse_unit(_with_geometry(_api_geometry()), "api.toml").geometry.mechanism()
    _assert_same_linkage(linkage, reference, rel=1e-12)


@pytest.mark.parametrize(
    ("change", "fragments"),
    [
        ({"k1": "3500 mm"}, ("given twice", "k1", "A")),
        ({"r": "1010 mm"}, ("given twice",)),
        ({"l2": "3000 mm"}, ("given twice",)),
        ({"G": None}, ("H and G",)),
        ({"H": None}, ("H and G",)),
        ({"K": "3717 mm"}, ("either K or both H and G",)),
        ({"H": None, "G": None, "K": "2000 mm"}, ("must exceed I",)),
        ({"H": None, "G": None, "K": "2195 mm"}, ("must exceed I",)),
    ],
    ids=["k1-and-A", "r-and-R", "l2-and-H-G", "H-without-G", "G-without-H", "K-with-H-G", "K-below-I", "K-equal-I"],
)
def test_api_letter_conflicts(change, fragments):
    geometry = _api_geometry()
    for key, value in change.items():
        if value is None:
            geometry.pop(key)
        else:
            geometry[key] = value
    with pytest.raises(ConfigError) as info:
        parse_unit(_with_geometry(geometry), "api.toml")
    message = str(info.value)
    assert message.startswith("api.toml: geometry")
    for fragment in fragments:
        assert fragment in message


# --- one field at a time -----------------------------------------------------------


def _set(path: str, value):
    """Change of the SK8 data: set the value at a dotted path (None deletes it)."""

    def apply(data: dict) -> None:
        *parents, last = path.split(".")
        node = data
        for part in parents:
            node = node[int(part)] if isinstance(node, list) else node[part]
        if value is None:
            del node[last]
        elif isinstance(node, list):
            node[int(last)] = value
        else:
            node[last] = value

    return apply


INVALID = [
    # (id, change, field path in the message, what is wrong)
    ("negative-length", _set("geometry.r", "-1 m"), "geometry.crank_radius", "greater than 0"),
    ("negative-plain-number", _set("geometry.l", -3.0), "geometry.pitman", "greater than 0"),
    ("zero-length", _set("geometry.k", 0), "geometry.rear_arm", "greater than 0"),
    ("zero-mass", _set("masses.pitman.mass", "0 kg"), "masses.pitman.mass", "greater than 0"),
    ("zero-rod-diameter", _set("well.rod_string.0.diameter", 0), "well.rod_string.0.diameter", "greater than 0"),
    ("unknown-top-level-key", _set("colour", "red"), "colour", "unknown key"),
    ("unknown-key-in-geometry", _set("geometry.stroke", "3 m"), "geometry.stroke", "unknown key"),
    ("unknown-key-in-motor", _set("drive.motor.voltage", 380), "drive.motor.voltage", "unknown key"),
    ("unknown-key-in-rod", _set("well.rod_string.1.colour", "D"), "well.rod_string.1.colour", "unknown key"),
    ("mass-for-length", _set("geometry.k1", "3500 kg"), "geometry.front_arm", "is a mass, not a length"),
    ("length-for-mass", _set("masses.pitman.mass", "130 m"), "masses.pitman.mass", "is a length, not a mass"),
    ("mass-for-speed", _set("drive.motor.rated_speed", "1460 kg"), "drive.motor.rated_speed",
     "is a mass, not a rotational speed"),
    ("mass-for-rod-diameter", _set("well.rod_string.0.diameter", "19 kg"), "well.rod_string.0.diameter",
     "is a mass, not a length"),
    ("unknown-unit", _set("well.fluid_density", "820 furlongs"), "well.fluid_density", "unknown unit"),
    ("decimal-comma", _set("geometry.l", "3,0 m"), "geometry.pitman", "decimal comma"),
    ("decimal-comma-in-mass", _set("masses.counterweights.radius", "0,83 m"), "masses.counterweights.radius",
     "decimal comma"),
    ("boolean-length", _set("geometry.l1", True), "geometry.horizontal_offset", "boolean"),
    ("rated-equals-synchronous", _set("drive.motor.rated_speed", "1500 rpm"), "drive.motor",
     "rated_speed must be below synchronous_speed"),
    ("rated-above-synchronous", _set("drive.motor.rated_speed", "1550 rpm"), "drive.motor",
     "rated_speed must be below synchronous_speed"),
    ("fractions-sum-0.99", _set("well.rod_string.2.fraction", "50 %"), "well", "fractions add up to 0.990"),
    ("fractions-sum-1.1", _set("well.rod_string.0.fraction", 0.33), "well", "fractions add up to 1.100"),
    ("fraction-above-1", _set("well.rod_string.0.fraction", "151 %"), "well.rod_string.0.fraction",
     "less than or equal to 1"),
    ("cannot-assemble", _set("geometry.r", "2 m"), "geometry", "cannot assemble"),
    ("bad-rotation", _set("geometry.rotation", "sideways"), "geometry.rotation", "'clockwise' or 'counterclockwise'"),
    ("rotation-not-text", _set("geometry.rotation", 1), "geometry.rotation", "'clockwise' or 'counterclockwise'"),
    ("front-arm-above-20m", _set("geometry.k1", "21 m"), "geometry.front_arm", "less than or equal to 20 m; got 21 m"),
    ("front-arm-bare-inches", _set("geometry.k1", 137.8), "geometry.front_arm",
     "less than or equal to 20 m; got 137.8 m"),
    ("crank-radius-above-5m", _set("geometry.r", "6 m"), "geometry.crank_radius", "less than or equal to 5"),
    ("crank-radius-in-feet", _set("geometry.r", "20 ft"), "geometry.crank_radius",
     "less than or equal to 5 m; got 6.096 m"),
    ("optional-half-spacing", _set("geometry.crank_half_spacing", "8 m"), "geometry.crank_half_spacing",
     "less than or equal to 5 m; got 8 m"),
    ("phase-beyond-half-turn", _set("masses.counterweights.phase", "200 deg"), "masses.counterweights.phase",
     "less than or equal to 3.141592653589793 rad (180 deg); got 3.49066 rad (200 deg)"),
    # 1460 rpm / (2 x 900 mm / 250 mm) = 202.8 strokes/min
    ("submergence-above-the-wellhead", _set("well.pump_submergence", "2000 m"), "well",
     "pump_submergence 2000 m is more than the pump depth 1530 m"),
    ("drive-beyond-pumping-speeds", _set("drive.gearbox_ratio", 2), "drive",
     "motor, sheaves and gearbox turn the crank at 202.8 strokes/min at the motor's rated speed, outside 0.1 .. 60"),
    ("designation-rating-beyond-any-unit", _set("designation", "C-99999999999999999999D-133-54"), "designation",
     "its gearbox torque rating 1.13e+22 N·m is above 1e+07 N·m, the limit of [rating] gearbox_torque"),
    ("submergence-negative", _set("well.pump_submergence", "-10 ft"), "well.pump_submergence",
     "greater than or equal to 0 m; got -3.048 m"),
    ("counterweights-above-16", _set("masses.counterweights.count", 17), "masses.counterweights.count",
     "less than or equal to 16"),
    ("counterweight-count-fractional", _set("masses.counterweights.count", 8.5), "masses.counterweights.count",
     "valid integer"),
    ("rod-diameter-above-60mm", _set("well.rod_string.0.diameter", "61 mm"), "well.rod_string.0.diameter",
     "less than or equal to 0.06"),
    ("density-at-100", _set("well.fluid_density", 100), "well.fluid_density", "greater than 100"),
    ("gearbox-ratio-1", _set("drive.gearbox_ratio", 1), "drive.gearbox_ratio", "greater than 1"),
    ("breakdown-ratio-above-10", _set("drive.motor.breakdown_torque_ratio", 11), "drive.motor.breakdown_torque_ratio",
     "less than or equal to 10"),
    ("missing-pitman", _set("geometry.l", None), "geometry.pitman", "Field required"),
    ("missing-name", _set("name", None), "name", "Field required"),
    ("missing-motor-model", _set("drive.motor.model", None), "drive.motor.model", "Field required"),
    ("missing-rotation", _set("geometry.rotation", None), "geometry.rotation", "Field required"),
    ("empty-rod-string", _set("well.rod_string", []), "well.rod_string", "at least 1 item"),
    ("section-not-a-table", _set("masses", 5), "masses", "valid dictionary"),
]


@pytest.mark.parametrize(("change", "where", "what"), [case[1:] for case in INVALID], ids=[case[0] for case in INVALID])
def test_one_invalid_field(change, where, what):
    data = copy.deepcopy(_sk8_data())
    parse_unit(copy.deepcopy(data), "x.toml")  # the unchanged file is valid
    change(data)
    with pytest.raises(ConfigError) as info:
        parse_unit(data, "x.toml")
    message = str(info.value)
    # One line: "x.toml: <dotted path>: <problem>".
    assert "\n" not in message
    assert message.startswith(f"x.toml: {where}: "), message
    assert what in message


def test_unknown_machine_kind():
    data = _sk8_data()
    data["kind"] = "gas-lift"
    with pytest.raises(ConfigError) as info:
        parse_unit(data, "x.toml")
    assert str(info.value).startswith("x.toml: kind: ")
    assert "gas-lift" in str(info.value)


def test_default_kind_is_beam_pump():
    data = _sk8_data()
    assert "kind" not in data
    data["kind"] = "beam-pump"
    assert parse_unit(data, "x.toml") == read_unit_file(SK8_TOML)


def test_several_problems_are_counted():
    data = _sk8_data()
    data["geometry"]["k"] = -1
    data["masses"]["pitman"]["mass"] = -1
    with pytest.raises(ConfigError, match=r"\(and 1 more problem\)"):
        parse_unit(data, "x.toml")


@pytest.mark.parametrize("rotation", ["cw", "CW", "Clockwise", "clockwise"])
def test_rotation_spellings(rotation):
    data = _sk8_data()
    data["geometry"]["rotation"] = rotation
    assert parse_unit(data, "x.toml").geometry.rotation == "clockwise"


def test_optional_sections_may_be_absent():
    data = _sk8_data()
    for section in ("masses", "drive", "well"):
        del data[section]
    config = parse_unit(data, "x.toml")
    assert config.masses is None and config.drive is None and config.well is None


@pytest.mark.parametrize("path", ["masses.counterweights.count", "drive.motor.starting_torque_ratio"])
def test_boolean_rejected_for_plain_number_fields(path):
    data = _sk8_data()
    _set(path, True)(data)
    with pytest.raises(ConfigError, match=path.replace(".", r"\.")):
        parse_unit(data, "x.toml")


# --- file-level errors -------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "text", "fragment"),
    [
        ("bad.toml", 'name = "x"\n[geometry\n', "not valid TOML"),
        ("bad.toml", "name = \n", "not valid TOML"),
        ("bad.json", '{"name": "x", }', "not valid JSON"),
        ("bad.json", "", "not valid JSON"),
        ("bad.yaml", "name: [x\ngeometry: {", "not valid YAML"),
        ("bad.yml", "name: x\n  - y: : z\n\t", "not valid YAML"),
        ("unit.ini", "[geometry]\n", "unknown file type '.ini'"),
        ("list.json", "[1, 2, 3]", "expected a table of sections at the top level"),
        ("scalar.yaml", "42\n", "expected a table of sections at the top level"),
        ("empty.yaml", "", "expected a table of sections at the top level"),
    ],
)
def test_file_level_errors(tmp_path, name, text, fragment):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError) as info:
        read_unit_file(path)
    message = str(info.value)
    assert message.startswith(f"{path}: "), message
    assert fragment in message


def test_missing_file(tmp_path):
    path = tmp_path / "missing.toml"
    with pytest.raises(ConfigError) as info:
        read_unit_file(path)
    assert str(path) in str(info.value)
    assert "cannot read" in str(info.value)


@pytest.mark.parametrize("suffix", [".json", ".yaml", ".yml"])
def test_same_data_in_every_format(tmp_path, suffix):
    # The TOML data written as JSON (YAML is a superset of JSON) gives the same config.
    path = tmp_path / f"sk8{suffix}"
    path.write_text(json.dumps(_sk8_data()), encoding="utf-8")
    assert read_unit_file(path) == read_unit_file(SK8_TOML)


def test_field_error_in_a_file_names_the_file(tmp_path):
    text = SK8_TOML.read_text(encoding="utf-8").replace('r = "1010 mm"', 'r = "2 m"')
    assert text != SK8_TOML.read_text(encoding="utf-8")
    path = tmp_path / "bad-geometry.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError, match="cannot assemble") as info:
        read_unit_file(path)
    assert str(info.value).startswith(f"{path}: geometry: ")


@pytest.mark.parametrize("suffix", [".toml", ".json", ".yaml"])
def test_an_integer_beyond_pythons_digit_limit_is_one_line(tmp_path, suffix):
    """An integer of 5001 digits: Python refuses to convert it (a ValueError, not the parser's own
    error); the reader names the file and the form in one line."""
    digits = "1" * 5001
    text = {".toml": f'name = "x"\n[geometry]\nr = {digits}\n', ".json": f'{{"name": "x", "geometry": {{"r": {digits}}}}}',
            ".yaml": f"name: x\ngeometry:\n  r: {digits}\n"}[suffix]
    path = tmp_path / f"x{suffix}"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError) as info:
        load_unit(str(path))
    assert str(info.value) == f"{path}: not valid {suffix[1:].upper()}: an integer of more than 4300 digits"


def test_a_yaml_error_names_the_file_once(tmp_path):
    path = tmp_path / "x.yaml"
    path.write_text("name: x\ngeometry:\n  r: 1 m\n  r: 2 m\n", encoding="utf-8")
    with pytest.raises(ConfigError) as info:
        load_unit(str(path))
    assert str(info.value).count(str(path)) == 1 and "given twice" in str(info.value)


@pytest.mark.parametrize("key, text", [("name", "SK8\x1b[31mRED"), ("description", "two\nlines"),
                                       ("designation", "C-228D\x07-213-86")])
def test_text_a_command_prints_has_no_control_characters(tmp_path, key, text):
    """A unit's name, description and designation reach the terminal in tables and messages: an
    escape sequence in them would recolour it or move the cursor, so the file is refused naming the
    key, and the message does not carry the character itself."""
    source = (REPO_ROOT / "configs" / "sk8-3.5-4000.toml").read_text(encoding="utf-8")
    data = tomllib.loads(source)
    data[key] = text
    with pytest.raises(ConfigError, match=f"{key}: must be printable text") as error:
        parse_unit(data, "unit.toml")
    assert str(error.value).isprintable()
