"""Unit catalogues (docs/catalogue.md): a CSV row is a unit file, validated by the unit-file schema.

A row and the TOML file that says the same are the same unit (the same model, stroke and
kinematics); every spelling of the header's units gives that unit; the published stroke is
checked to 0.5 in; the names resolve as documented; and every file or row that cannot be a
catalogue is refused with one line naming the file, the line and the column.
"""

from __future__ import annotations

import importlib.util
import math
import typing
from pathlib import Path

import numpy as np
import pytest

from pumpjack_cli.analysis.kinematics import kinematics
from pumpjack_cli.config import load_unit, read_unit_file
from pumpjack_cli.config.catalogue import OFFSET_KEY, STROKE_TOLERANCE, catalogue_listing, catalogue_unit
from pumpjack_cli.config import unit_classes
from pumpjack_cli.config.unit_classes import UNIT_CLASSES
from pumpjack_cli.errors import ConfigError, collected_warnings
from pumpjack_cli.readers import catalogue as reader
from pumpjack_cli.readers.catalogue import read_catalogue
from pumpjack_cli.readers.unit_files import bundled_units, unit_source

from helpers import INCH, REPO_ROOT

SAMPLE = REPO_ROOT / "samples" / "catalogue.csv"
#: C-80D-133-48 in its longest hole ([Guo2007] Table 12.1, as configs/c-80d-133-48.toml).
HEADER = "designation,crank_hole,rotation,A_in,C_in,I_in,P_in,H_in,G_in,R_in,stroke_in,B_lbf,tau_deg"
ROW = "C-80D-133-48,{hole},cw,64,64,64,74.5,116,41,{radius},{stroke},440,0"
#: Its exact stroke [in] in the 24 in hole (the listing of samples/catalogue.csv).
STROKE_24 = 49.363864381


def write(folder: Path, text: str, name: str = "field.csv") -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def field(folder: Path, *rows: str, header: str = HEADER) -> Path:
    return write(folder, "\n".join([header, *rows]) + "\n")


def rotation_of(kind: str) -> str:
    """A rotation the kind's schema accepts (Mark II units turn counterclockwise only)."""
    return typing.get_args(UNIT_CLASSES[kind].model().model_fields["rotation"].annotation)[0]


def equivalent_toml(folder: Path, kind: str | None = None) -> Path:
    """The unit file that says what ``ROW`` (hole 1, 24 in) says, or the same letters, rotation and
    counterbalance as a unit of ``kind``, its crank offset where its schema keeps it."""
    designation = "C-80D-133-48" if kind is None else f"{UNIT_CLASSES[kind].letters[0]}-80D-133-48"
    kind_line = "" if kind is None else f'class = "{kind}"\n'
    rotation = "cw" if kind is None else rotation_of(kind)
    in_geometry = kind is not None and OFFSET_KEY in UNIT_CLASSES[kind].model().model_fields
    return write(folder, f'name = "{designation}/1"\ndesignation = "{designation}"\n\n[geometry]\n{kind_line}'
                         'A = "64 in"\nC = "64 in"\nI = "64 in"\nP = "74.5 in"\nH = "116 in"\nG = "41 in"\n'
                         f'R = "24 in"\nrotation = "{rotation}"\n'
                         + (f'{OFFSET_KEY} = "0 deg"\n' if in_geometry else "")
                         + '\n[counterbalance]\nstructural_unbalance = "440 lbf"\n'
                         + ("" if in_geometry else 'phase = "0 deg"\n'), "unit.toml")


# --- the sample -------------------------------------------------------------------------


def test_the_sample_is_what_its_script_makes():
    spec = importlib.util.spec_from_file_location("make_catalogue", REPO_ROOT / "samples" / "make_catalogue.py")
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    assert SAMPLE.read_text(encoding="utf-8") == script.catalogue()


SAMPLE_UNITS = ("c-114d-133-54", "c-80d-133-48", "m-912d-365-168")


@pytest.mark.parametrize("name", SAMPLE_UNITS)
def test_the_sample_longest_hole_is_the_bundled_unit(name):
    """Hole 1 of each sample unit has the bundled file's geometry ([Guo2007] Table 12.1, [LufkinM912]),
    field for field and to the bit (the same inches converted once), but for the spatial model's
    estimated pin spacings, which a catalogue does not hold; and its structural unbalance."""
    bundled = load_unit(name)
    unit = load_unit(f"{bundled.name}/1", read_catalogue(SAMPLE))
    given = {key: value for key, value in unit.geometry.model_dump().items() if value is not None}
    assert given == {key: bundled.geometry.model_dump()[key] for key in given}
    assert unit.ratings() == bundled.ratings()
    if bundled.counterbalance is not None:  # B and tau as the file gives them (not from its estimated masses)
        mine, theirs = unit.counterbalance_model()[0], bundled.counterbalance_model()[0]
        assert (mine.structural_unbalance, mine.offset, mine.tail) == (theirs.structural_unbalance, theirs.offset,
                                                                       theirs.tail)


def test_the_sample_holes_shorten_the_stroke():
    """Hole 1 is the longest stroke: the exact strokes fall with the hole number; the published
    strokes of M-912D-365-168 ([LufkinM912]: 168, 149, 130 in) agree within 0.5 in but the third's,
    0.83 in short of the exact 130.83 in (configs/m-912d-365-168.toml says so)."""
    rows = catalogue_listing(read_catalogue(SAMPLE))
    for name in SAMPLE_UNITS:
        strokes = [row["stroke"] for row in rows if row["designation"].lower() == name]
        assert len(strokes) == 3 and strokes == sorted(strokes, reverse=True)
    checks = {row["name"]: row["stroke_check"] for row in rows}
    assert [checks[f"M-912D-365-168/{hole}"] for hole in (1, 2, 3)] == ["ok", "ok", "differs"]
    assert {checks[name] for name in checks if not name.startswith("M-")} == {"not published"}


# --- a row is a unit file ---------------------------------------------------------------


def test_a_row_is_the_unit_of_its_toml_file(tmp_path):
    """The same model (every field), the same stroke and the same kinematics, to the bit."""
    row = catalogue_unit(read_catalogue(field(tmp_path, ROW.format(hole=1, radius=24, stroke=""))).rows[0])
    toml = read_unit_file(equivalent_toml(tmp_path))
    assert row.model_dump() == toml.model_dump()
    assert row.geometry.mechanism().stroke == toml.geometry.mechanism().stroke
    assert row.geometry.mechanism().stroke / INCH == pytest.approx(STROKE_24, abs=1e-5)
    a, b = kinematics(row, 8.0, 36), kinematics(toml, 8.0, 36)
    assert [s.value for s in a.summary] == [s.value for s in b.summary]
    for x, y in zip(a.columns, b.columns):
        np.testing.assert_array_equal(x.values, y.values)


@pytest.mark.parametrize("kind", list(UNIT_CLASSES))
def test_a_row_of_each_kind_validates_as_its_toml_file(tmp_path, kind):
    """For every kind the registry has: the row with its ``class`` is the TOML file's unit (the crank
    offset where the kind keeps it), or is refused with the very message the file gets (one
    validation path; a kind whose schema needs more than a catalogue's columns is refused)."""
    designation = f"{UNIT_CLASSES[kind].letters[0]}-80D-133-48"
    text = ROW.format(hole=1, radius=24, stroke="").replace("C-80D-133-48,1,cw,",
                                                            f"{designation},1,{kind},{rotation_of(kind)},", 1)
    path = field(tmp_path, text, header=HEADER.replace("crank_hole,", "crank_hole,class,"))
    try:
        toml = read_unit_file(equivalent_toml(tmp_path, kind))
    except ConfigError as exc:
        with pytest.raises(ConfigError) as refused:
            catalogue_unit(read_catalogue(path).rows[0])
        assert str(exc).split(": ", 2)[-1] in str(refused.value)
        return
    assert catalogue_unit(read_catalogue(path).rows[0]).model_dump() == toml.model_dump()


@pytest.mark.parametrize("kind", [kind for kind in UNIT_CLASSES if OFFSET_KEY in UNIT_CLASSES[kind].model().model_fields])
def test_a_kind_that_keeps_its_crank_offset_in_its_geometry_gets_tau_there(tmp_path, kind):
    """Mark II and reverse-mark units: tau is ``[geometry] crank_offset`` and needs no B."""
    designation = f"{UNIT_CLASSES[kind].letters[0]}-80D-133-48"
    path = field(tmp_path, f"{designation},1,{kind},{rotation_of(kind)},64,64,64,74.5,116,41,24,,,19",
                 header=HEADER.replace("crank_hole,", "crank_hole,class,"))
    try:
        unit = catalogue_unit(read_catalogue(path).rows[0])
    except ConfigError as exc:  # letters that do not assemble as this kind: the schema's message, placed
        assert str(exc).startswith(f"{path}: line 2: columns A_in, C_in, I_in, P_in, H_in, G_in, R_in: ")
        return
    assert getattr(unit.geometry, OFFSET_KEY) == pytest.approx(math.radians(19), rel=1e-15)
    assert unit.counterbalance is None


@pytest.mark.parametrize("spelling", [
    ("A_in,C_in,I_in,P_in,H_in,G_in,R_in,B_lbf,tau_deg", "64,64,64,74.5,116,41,24,440,0"),
    ("A_mm,C_mm,I_mm,P_mm,H_mm,G_mm,R_mm,B_N,tau_rad", "1625.6,1625.6,1625.6,1892.3,2946.4,1041.4,609.6,"
                                                       "1957.2175107146,0"),
    ("A_m,C_cm,I_ft,P_in,K_in,R_in,B_kN,tau_deg", "1.6256,162.56,5.3333333333333333,74.5,"
                                                   "98.595131725,24,1.9572175107146,0"),
    ("a_IN,c_In,i_in,p_in,h_in,g_in,r_in,b_LBF,TAU_DEG", "64,64,64,74.5,116,41,24,440,0"),
])
def test_every_spelling_of_the_units_is_the_same_unit(tmp_path, spelling):
    """SI and oilfield units in the header, K for H and G (sqrt(75^2 + 64^2) = 98.595131725 in), any
    case: the same geometry and stroke (1e-7 relative: K is given to 1e-6 in)."""
    columns, values = spelling
    path = field(tmp_path, f"C-80D-133-48,1,cw,{values}", header=f"designation,crank_hole,rotation,{columns}")
    unit = catalogue_unit(read_catalogue(path).rows[0])
    reference = read_unit_file(equivalent_toml(tmp_path))
    assert unit.geometry.mechanism().stroke == pytest.approx(reference.geometry.mechanism().stroke, rel=1e-7)
    assert unit.counterbalance.structural_unbalance == pytest.approx(440 * 4.4482216152605, rel=1e-12)
    assert unit.geometry.vertical_offset == pytest.approx(75 * INCH, rel=1e-7)


def test_ratings_come_from_the_designation_unless_given(tmp_path):
    path = field(tmp_path, "C-80D-133-48,1,cw,64,64,64,74.5,116,41,24,,,,,",
                 "C-80D-133-48,2,cw,64,64,64,74.5,116,41,20,,,,100000,60",
                 header="designation,crank_hole,rotation,A_in,C_in,I_in,P_in,H_in,G_in,R_in,stroke_in,B_lbf,"
                        "tau_deg,gearbox_torque_lbf_in,max_stroke_in")
    first, second = (catalogue_unit(row).ratings() for row in read_catalogue(path).rows)
    assert first.gearbox_torque == pytest.approx(80e3 * 4.4482216152605 * INCH, rel=1e-12)
    assert second.gearbox_torque == pytest.approx(100e3 * 4.4482216152605 * INCH, rel=1e-12)
    assert (first.max_stroke, second.max_stroke) == pytest.approx((48 * INCH, 60 * INCH), rel=1e-12)
    assert second.structure_load == first.structure_load


def test_a_row_without_b_has_no_counterbalance_and_a_source_is_kept(tmp_path):
    path = field(tmp_path, "C-80D-133-48,1,cw,64,64,64,74.5,116,41,24,,[Guo2007] Table 12.1",
                 header="designation,crank_hole,rotation,A_in,C_in,I_in,P_in,H_in,G_in,R_in,B_lbf,source")
    unit = catalogue_unit(read_catalogue(path).rows[0])
    assert unit.counterbalance is None and unit.sources == ("[Guo2007] Table 12.1",)


# --- the stroke check -----------------------------------------------------------------


@pytest.mark.parametrize(("off", "flagged"), [(1.0, True), (-1.0, True), (0.3, False), (-0.3, False)])
def test_a_published_stroke_off_by_more_than_half_an_inch_is_flagged(tmp_path, off, flagged):
    """1 in off is flagged (a warning naming the file, line and hole; `differs` in the listing),
    0.3 in is not (`ok`); the tolerance is 0.5 in = 12.7 mm."""
    assert STROKE_TOLERANCE == pytest.approx(0.0127, rel=1e-15)
    path = field(tmp_path, ROW.format(hole=1, radius=24, stroke=f"{STROKE_24 + off:.9f}"))
    catalogue = read_catalogue(path)
    with collected_warnings() as noted:
        catalogue_unit(catalogue.rows[0])
    [listed] = catalogue_listing(catalogue)
    assert listed["stroke_difference"] == pytest.approx(-off * INCH, abs=1e-10)  # STROKE_24 is to 1e-9 in
    if flagged:
        assert len(noted) == 1 and f"{path}: line 2: C-80D-133-48/1: the exact stroke 49.36 in" in noted[0]
        assert "R_in" in noted[0] and listed["stroke_check"] == "differs"
    else:
        assert noted == [] and listed["stroke_check"] == "ok"


def test_without_a_published_stroke_nothing_is_checked(tmp_path):
    catalogue = read_catalogue(field(tmp_path, ROW.format(hole=1, radius=24, stroke="")))
    with collected_warnings() as noted:
        catalogue_unit(catalogue.rows[0])
    [listed] = catalogue_listing(catalogue)
    assert noted == [] and listed["published_stroke"] is None and listed["stroke_check"] == "not published"


def test_the_listing_stroke_is_the_models_stroke():
    """Pure Python (the registry's raw stroke) and the validated model agree (1e-12 relative)."""
    catalogue = read_catalogue(SAMPLE)
    for row, listed in zip(catalogue.rows, catalogue_listing(catalogue)):
        assert listed["stroke"] == pytest.approx(catalogue_unit(row).geometry.mechanism().stroke, rel=1e-12)


# --- names ------------------------------------------------------------------------------


@pytest.fixture
def holes(tmp_path):
    """Three holes of C-320D-256-120 and one of SK6-2,1-2500, both with C-80D-133-48's letters (names
    are what is tested here, not those units' geometry; neither is a bundled unit's name)."""
    rows = [ROW.format(hole=h, radius=r, stroke="").replace("C-80D-133-48", "C-320D-256-120")
            for h, r in ((1, 24), (2, 20), (3, 16))]
    return read_catalogue(field(tmp_path, *rows, '"SK6-2,1-2500",1,cw,64,64,64,74.5,116,41,16,,,'))


@pytest.mark.parametrize(("spec", "name"), [
    ("C-320D-256-120/2", "C-320D-256-120/2"), ("c-320d-256-120/3", "C-320D-256-120/3"),
    (" C-320D-256-120/01 ", "C-320D-256-120/1"),
    ("sk6-2.1-2500/1", "SK6-2,1-2500/1"), ("SK6-2,1-2500", "SK6-2,1-2500/1"), ("sk8-3,5-4000", None),
])
def test_a_catalogue_unit_is_named_by_designation_and_hole(holes, spec, name):
    """Case and the decimal comma do not matter; a designation of one hole names it; a bundled
    unit's name (sk8-3,5-4000) is the bundled file."""
    found = unit_source(spec, holes)
    assert found.name == name if name is not None else found == bundled_units()["sk8-3.5-4000"]


def test_a_bundled_name_and_a_file_come_before_the_catalogue(holes, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "C-320D-256-120").mkdir()
    (tmp_path / "C-320D-256-120" / "2").write_text("", encoding="utf-8")
    assert unit_source("C-320D-256-120/2", holes) == Path("C-320D-256-120/2")
    assert unit_source("C-320D-256-120/3", holes).name == "C-320D-256-120/3"


@pytest.mark.parametrize(("spec", "message"), [
    ("C-320D-256-120", "unit 'C-320D-256-120': {file} has crank holes 1, 2, 3 of C-320D-256-120; name one as "
                      "C-320D-256-120/HOLE"),
    ("C-320D-256-120/4", "unit 'C-320D-256-120/4': {file} has crank holes 1, 2, 3 of C-320D-256-120, not 4"),
    ("C-320D-256-102/1", "unknown unit 'C-320D-256-102/1': not a file, a bundled unit or a unit of {file}; close: "
                        "C-320D-256-120/1, "),
    ("nothing-like-it", "unknown unit 'nothing-like-it': not a file, a bundled unit or a unit of {file}; "
                        "`pumpjack units --catalogue {file}` lists its units"),
])
def test_a_name_the_catalogue_does_not_have_is_one_line(holes, spec, message):
    with pytest.raises(ConfigError) as refused:
        unit_source(spec, holes)
    assert str(refused.value).startswith(message.format(file=holes.source))
    assert "\n" not in str(refused.value)


def test_without_a_catalogue_a_designation_and_hole_says_what_names_it():
    with pytest.raises(ConfigError, match=r"unknown unit 'C-80D-133-48/1': give a file path or one of .*; "
                                          r"DESIGNATION/HOLE names a unit of --catalogue FILE$"):
        unit_source("C-80D-133-48/1")


# --- refusals -------------------------------------------------------------------------

GOOD = ROW.format(hole=1, radius=24, stroke="")

HOSTILE = [
    ("", "{file}: empty: a unit catalogue is a header line"),
    ("# only a comment\n\n", "{file}: empty: a unit catalogue is a header line"),
    (HEADER + "\n", "{file}: no unit rows under the header (line 1)"),
    ("designation,crank_hole,rotation,A_in,C_in,I_in,P_in,H_in,R_in\n" + GOOD,
     "{file}: line 1: missing column K (or H and G)"),
    (HEADER.replace("R_in", "Radius_in") + "\n" + GOOD, "{file}: line 1: unknown column 'Radius_in' (column 10)"),
    (HEADER.replace("B_lbf", "weight") + "\n" + GOOD, "{file}: line 1: unknown column 'weight' (column 12)"),
    (HEADER.replace("A_in", "A") + "\n" + GOOD, "{file}: line 1: column 'A' names no unit: write it after the name, "
                                                "e.g. A_in"),
    (HEADER.replace("B_lbf", "B_psi") + "\n" + GOOD, "{file}: line 1: column 'B_psi': '1 psi' is a pressure, "
                                                      "not a force"),
    (HEADER.replace("A_in", "A_furlong") + "\n" + GOOD, "{file}: line 1: column 'A_furlong': unknown unit 'furlong'"),
    (HEADER + ",A_mm\n" + GOOD + ",1", "{file}: line 1: column A is given twice (A_in and A_mm)"),
    (HEADER + ",\n" + GOOD + ",", "{file}: line 1: column 14 has no name"),
    (HEADER + "\n" + GOOD.replace(",74.5,", ",seventy,"), "{file}: line 2: column P_in: 'seventy' is not a number"),
    (HEADER + "\n" + GOOD.replace(",74.5,", ',"74,5",'), "{file}: line 2: column P_in: '74,5' is not a number"),
    (HEADER + "\n" + GOOD.replace(",74.5,", ",nan,"), "{file}: line 2: column P_in: 'nan' is not a number"),
    (HEADER + "\n" + GOOD.replace(",74.5,", ",inf,"), "{file}: line 2: column P_in: 'inf' is not a number"),
    (HEADER + "\n" + GOOD.replace(",74.5,", ",,"), "{file}: line 2: column P_in is empty"),
    (HEADER + "\n" + GOOD.replace(",1,cw", ",1.5,cw"), "{file}: line 2: column crank_hole: '1.5' is not a whole "
                                                      "number from 1"),
    (HEADER + "\n" + GOOD.replace(",1,cw", ",0,cw"), "{file}: line 2: column crank_hole: '0' is not a whole number"),
    (HEADER + "\n" + GOOD + ",", "{file}: line 2: 14 cells for the header's 13 columns (a cell holding a comma is "
                                 "quoted"),
    (HEADER + "\nSK8-3,5-4000,1,cw,64,64,64,74.5,116,41,24,,440,0", "{file}: line 2: 14 cells for the header's 13 "
                                                                   "columns (a cell holding a comma is quoted"),
    (HEADER + "\n" + GOOD[:-6], "{file}: line 2: 11 cells for the header's 13 columns"),
    (HEADER + "\n" + GOOD + "\n# a comment\n" + GOOD.replace("C-80D", "c-80d"),
     "{file}: line 4: c-80d-133-48/1 is given twice (lines 2 and 4)"),
    (HEADER + '\n"C-80D-133-48,1,cw', "{file}: line 2: not valid CSV"),
    (HEADER + '\n"C-80D\n-133-48"' + GOOD[12:], "{file}: line 2: not valid CSV: a quoted cell is not closed on its "
                                                "line"),
]


@pytest.mark.parametrize(("text", "message"), HOSTILE, ids=[m.split(": ", 1)[1][:50] for _, m in HOSTILE])
def test_a_malformed_catalogue_is_refused_with_its_line_and_column(tmp_path, text, message):
    path = write(tmp_path, text)
    with pytest.raises(ConfigError) as refused:
        read_catalogue(path)
    assert str(refused.value).startswith(message.format(file=path)), str(refused.value)


@pytest.mark.parametrize(("data", "message"), [
    (HEADER.encode() + b"\n\0\0\0", "line 2: a NUL character: binary data, not text"),
    ("\ufeff".encode("utf-16") + HEADER.encode("utf-16-le"), "is UTF-16 or UTF-32 text"),
    (HEADER.encode() + "\nC-80D-133-48,1,cw,6\xe4".encode("latin-1"), "line 2: byte 0xe4 is not UTF-8"),
])
def test_a_file_that_is_not_text_is_refused(tmp_path, data, message):
    path = tmp_path / "field.csv"
    path.write_bytes(data)
    with pytest.raises(ConfigError, match=f"^{path}: .*{message}"):
        read_catalogue(path)


def test_a_huge_file_is_refused_before_it_is_read(tmp_path, monkeypatch):
    """Bounded like a unit file (16 MiB here; a limit of 1000 bytes stands for it)."""
    monkeypatch.setattr(reader, "MAX_BYTES", 1000)
    path = write(tmp_path, HEADER + "\n" + "\n".join(GOOD.replace(",1,", f",{k},") for k in range(1, 40)))
    with pytest.raises(ConfigError, match=f"^{path}: is [0-9,]+ bytes; a unit catalogue is at most 1,000 bytes$"):
        read_catalogue(path)


def test_a_directory_is_refused(tmp_path):
    with pytest.raises(ConfigError, match=f"^{tmp_path}: is a directory, not a unit catalogue$"):
        read_catalogue(tmp_path)


@pytest.mark.parametrize(("change", "message"), [
    ((",74.5,", ",30,", ",24,", ",40,"),
     "line 2: columns A_in, C_in, I_in, P_in, H_in, G_in, R_in: the unit cannot assemble"),
    ((",64,64,64,", ",1000,64,64,"), "line 2: column A_in: Input should be less than or equal to 20 m; got 25.4 m"),
    ((",440,0", ",440,400"), "line 2: column tau_deg: Input should be less than or equal to 3.14159"),
    ((",cw,", ",up,"), "line 2: column rotation: Input should be 'clockwise' or 'counterclockwise'"),
    ((",440,0",  ",,5"), "line 2: column tau_deg: a crank offset needs the structural unbalance B"),
    (("C-80D-133-48,", "X-80D-133-48,"), "line 2: column designation: unit designation 'X-80D-133-48': unknown API "
                                         "unit type 'X'"),
])
def test_a_row_the_schema_refuses_names_its_line_and_column(tmp_path, change, message):
    """The schema's own message, placed by the row's line and the column (the letters' columns
    when the linkage cannot assemble: P = 30 in, R = 40 in cannot reach)."""
    text = GOOD
    for old, new in zip(change[::2], change[1::2]):
        text = text.replace(old, new, 1)
    path = field(tmp_path, text)
    with pytest.raises(ConfigError) as refused:
        catalogue_unit(read_catalogue(path).rows[0])
    assert str(refused.value).startswith(f"{path}: {message}"), str(refused.value)
    assert "\n" not in str(refused.value)


def test_the_listing_refuses_letters_that_cannot_assemble(tmp_path):
    path = field(tmp_path, GOOD.replace(",74.5,", ",30,").replace(",24,", ",40,"))
    with pytest.raises(ConfigError, match=f"^{path}: line 2: columns A_in, C_in, I_in, P_in, H_in, G_in, R_in: "
                                          "the unit cannot assemble"):
        catalogue_listing(read_catalogue(path))


def test_the_listing_refuses_a_rotation_that_is_none(tmp_path):
    path = field(tmp_path, GOOD.replace(",cw,", ",sideways,"))
    with pytest.raises(ConfigError, match=f"^{path}: line 2: column rotation: rotation 'sideways' is neither "
                                          "clockwise nor counterclockwise"):
        catalogue_listing(read_catalogue(path))


@pytest.mark.parametrize(("row", "column", "message"), [
    (GOOD.replace("C-80D", "M-80D"), "designation", "the designation 'M-80D-133-48' names a mark-ii unit"),
    (GOOD.replace(",1,cw,", ",1,shaped,cw,"), "class", "class 'shaped' is not a kind of unit"),
])
def test_a_kind_the_registry_lacks_is_refused_by_the_listing_and_the_schema(tmp_path, monkeypatch, row, column,
                                                                          message):
    """A Mark II designation while ``mark-ii`` is not registered (taken out of the registry here),
    or an unknown class: the one message of config/unit_classes.py, with the row's line and column.
    The registry is a copy without ``mark-ii`` for the test (taking the key out and putting it back
    would move it to the end, and the generated unit-file page lists the kinds in registry order)."""
    monkeypatch.setattr(unit_classes, "UNIT_CLASSES", {k: v for k, v in UNIT_CLASSES.items() if k != "mark-ii"})
    header = HEADER if column == "designation" else HEADER.replace("crank_hole,", "crank_hole,class,")
    catalogue = read_catalogue(field(tmp_path, row, header=header))
    for refuse in (lambda: catalogue_unit(catalogue.rows[0]), lambda: catalogue_listing(catalogue)):
        with pytest.raises(ConfigError, match=f"^{catalogue.source}: line 2: column {column}: {message}"):
            refuse()


def test_air_balanced_and_beam_balanced_rows_carry_their_counterbalance(tmp_path):
    """The kinds that balance otherwise than with crank counterweights take their keys from
    their own columns: the air cylinder's and the beam counterweight's."""
    from pumpjack_cli.core.beam.air_balanced import AirCylinder
    from pumpjack_cli.core.beam.beam_balanced import BeamCounterweight

    header = (HEADER + ",air_piston_diameter_in,air_bottom_volume_ft3,air_lever_in,air_pressure_psi,"
              "beam_counterweight_lbf,beam_counterweight_arm_in")
    path = field(tmp_path, "A-228D-213-86,1,ccw,120,70,70,100,140,45,24.5,,-500,,12,7,50,230,,",
                 "B-80D-133-48,1,cw,64,64,64,74.5,116,41,24,,440,,,,,,6000,60", header=header)
    air, beam = (catalogue_unit(row).counterbalance_model() for row in read_catalogue(path).rows)
    cylinder, known = air
    assert isinstance(cylinder, AirCylinder) and known
    assert cylinder.piston_area == pytest.approx(math.pi * (12 * INCH) ** 2 / 4, rel=1e-12)
    assert cylinder.bottom_volume == pytest.approx(7 * (12 * INCH) ** 3, rel=1e-12)
    assert cylinder.lever == pytest.approx(50 * INCH, rel=1e-12)
    weight, known = beam
    assert isinstance(weight, BeamCounterweight) and known
    assert weight.arm == pytest.approx(-60 * INCH, rel=1e-12)
