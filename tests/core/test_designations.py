"""Unit designations: API Spec 11E and GOST 5866-76 parsed into SI ratings.

Expected values are hand arithmetic with the conversion factors lbf, in and kgf (checked
against NIST SP 811 in tests/validation/test_nist811.py); the printed SI values (25 760.54 N·m,
78 453.2 N, 39 226.6 N·m) are the products worked out by hand.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from pumpjack_cli.core.designations import API, API_TYPES, GOST, Designation, parse_designation
from pumpjack_cli.errors import DesignationError, PumpjackError

from helpers import INCH, KILOGRAM_FORCE, POUND_FORCE

LBF_IN = POUND_FORCE * INCH  # N·m per lbf·in


def test_guo2007_example_c_228d_213_86():
    """Guo, Lyons & Ghalambor 2007, p. 12/163 and PetroWiki: reducer 228 000 lbf·in,
    double reduction, structure 21 300 lbf, stroke 86 in. 1e-12 relative: float
    rounding of the products only."""
    d = parse_designation("C-228D-213-86")
    assert isinstance(d, Designation)
    assert d.family == API and d.unit_class == "conventional" and d.reduction == "double"
    assert d.gearbox_torque == pytest.approx(228_000 * LBF_IN, rel=1e-12)
    assert d.gearbox_torque == pytest.approx(25_760.54, abs=0.01)
    assert d.structure_load == pytest.approx(21_300 * POUND_FORCE, rel=1e-12)
    assert d.max_stroke == pytest.approx(86 * INCH, rel=1e-12)
    assert d.series is None and d.reducer_code == "228D"


@pytest.mark.parametrize("text, cls, torque_kin, structure_100, stroke_in", [
    ("C-456D-305-144", "conventional", 456, 305, 144),
    ("M-912D-427-192", "mark-ii", 912, 427, 192),
    ("A-1280D-470-240", "air-balanced", 1280, 470, 240),
    ("B-40D-89-42", "beam-balanced", 40, 89, 42),
    ("C-6.4-32-16", "conventional", 6.4, 32, 16),
])
def test_api_classes_and_ratings(text, cls, torque_kin, structure_100, stroke_in):
    d = parse_designation(text)
    assert d.unit_class == cls
    assert d.gearbox_torque == pytest.approx(torque_kin * 1000 * LBF_IN, rel=1e-12)
    assert d.structure_load == pytest.approx(structure_100 * 100 * POUND_FORCE, rel=1e-12)
    assert d.max_stroke == pytest.approx(stroke_in * INCH, rel=1e-12)


def test_a_makers_letters_parse_only_where_a_kind_declares_them():
    """API 11E defines C, M, A and B; Lufkin's RM (reverse-mark, [LufkinRM]) is declared once,
    by its unit kind in config/unit_classes.py, and the parser reads the letters it is given."""
    from pumpjack_cli.config.unit_classes import designation_types, unit_class

    with pytest.raises(DesignationError, match="unknown API unit type 'RM'"):
        parse_designation("RM-640D-365-168")
    d = parse_designation("rm-640D-365-168", designation_types())
    assert d.unit_class == "reverse-mark" == unit_class({}, "RM-640D-365-168")
    assert d.gearbox_torque == pytest.approx(640_000 * LBF_IN, rel=1e-12)
    assert parse_designation("Q-1-2-3", {"Q": "a kind of one's own"}).unit_class == "a kind of one's own"
    assert {letter: designation_types()[letter] for letter in "CMAB"} == API_TYPES


def test_guo2007_table_12_1_prefixed_reducer_and_printed_dashes():
    """Guo Table 12.1 prints C-P57D-76-54 (the P is kept, not interpreted); p. 12/163
    prints C---228D---200---74 with long dashes."""
    p = parse_designation("C-P57D-76-54")
    assert p.reducer_code == "P57D" and p.gearbox_torque == pytest.approx(57_000 * LBF_IN, rel=1e-12)
    q = parse_designation("C---228D---200---74")
    assert q.structure_load == pytest.approx(20_000 * POUND_FORCE, rel=1e-12) and q.max_stroke == pytest.approx(74 * INCH)
    assert parse_designation(" c-228d-213-86 ").reduction == "double"
    assert parse_designation("C-228-213-86").reduction is None


@pytest.mark.parametrize("text", ["SK8-3,5-4000", "SK8-3.5-4000", "СК8-3,5-4000", "ск8-3,5-4000",
                                  "SК8-3,5-4000", "SK8 \u2013 3,5 \u2013 4000"])
def test_gost_sk8_3_5_4000(text):
    """8 tf = 8000 kgf = 78 453.2 N (nominally 80 kN), 3.5 m, 4000 kgf·m = 39 226.6 N·m;
    Latin, Cyrillic or mixed letters, decimal comma or point, any dash."""
    d = parse_designation(text)
    assert d.family == GOST and d.unit_class == "conventional" and d.series is None
    assert d.structure_load == pytest.approx(8000 * KILOGRAM_FORCE, rel=1e-12)
    assert d.structure_load == pytest.approx(78_453.2, abs=0.01)
    assert d.max_stroke == pytest.approx(3.5, rel=1e-12)
    assert d.gearbox_torque == pytest.approx(39_226.6, abs=1e-6)


@pytest.mark.parametrize("text", ["7SK12-2,5-5600", "7СК12-2,5-5600"])
def test_gost_7sk12_2_5_5600(text):
    """The unit of seed 000: 12 tf, 2.5 m, 5600 kgf·m; the leading 7 is kept as series."""
    d = parse_designation(text)
    assert d.series == 7
    assert d.structure_load == pytest.approx(12_000 * KILOGRAM_FORCE, rel=1e-12)
    assert d.max_stroke == pytest.approx(2.5, rel=1e-12)
    assert d.gearbox_torque == pytest.approx(5600 * KILOGRAM_FORCE, rel=1e-12)


@pytest.mark.parametrize("text, fragment", [
    ("X-228D-213-86", "unknown API unit type 'X'"),
    ("C-228Q-213-86", "unknown reducer letter 'Q'"),
    ("C-0D-213-86", "reducer rating is 0"),
    ("C-228D-0-86", "structure rating is 0"),
    ("C-228,5D-213-86", "decimal point"),
    ("SK8-3,5-4,000", "whole number"),
    ("SK0-3,5-4000", "polished-rod load is 0"),
    ("SK8-3,5", "unknown unit designation 'SK8-3,5'"),
    ("C-228D-213", "unknown unit designation"),
    ("", "unknown unit designation ''"),
    ("pumpjack", "unknown unit designation 'pumpjack'"),
    ("SK8-3,5-4000-1", "unknown unit designation"),
])
def test_bad_designations_name_the_text_and_the_forms(text, fragment):
    with pytest.raises(DesignationError) as err:
        parse_designation(text)
    message = str(err.value)
    assert fragment in message
    assert "\n" not in message
    assert isinstance(err.value, PumpjackError)


def test_unknown_designation_lists_both_expected_forms():
    with pytest.raises(DesignationError, match="C-228D-213-86.*SK8-3,5-4000"):
        parse_designation("QQ-1-2-3")


def test_not_text_is_a_designation_error():
    with pytest.raises(DesignationError, match="not text"):
        parse_designation(228)  # type: ignore[arg-type]


def test_module_imports_nothing_heavy():
    """pumpjack units may call it: importing it must not load numpy, scipy or pydantic."""
    code = ("import sys; import pumpjack_cli.core.designations; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('numpy', 'scipy', 'pydantic')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"
