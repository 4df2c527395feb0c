"""Deviation survey files (readers/survey.py): the format of docs/deviated.md and every refusal, one line
naming the file, the line and the column."""

from __future__ import annotations

import math

import pytest

from pumpjack_cli.errors import ConfigError
from pumpjack_cli.readers.survey import parse_survey, read_survey

from helpers import FOOT

HEADER = "measured_depth_m,inclination_deg,azimuth_deg\n"


def test_stations_in_si_with_the_wellhead_first():
    survey = parse_survey(HEADER + "0,0,0\n500,0,0\n800,30,45\n", "s.csv")
    assert survey.measured_depth == (0.0, 500.0, 800.0)
    assert survey.inclination[2] == pytest.approx(math.pi / 6, abs=1e-15)
    assert survey.azimuth[2] == pytest.approx(math.pi / 4, abs=1e-15)
    assert survey.lines == (2, 3, 4) and survey.depth == 800.0


def test_feet_brackets_semicolons_comments_and_the_columns_an_export_adds():
    text = ("# exported survey\nMD (ft);Inc (deg);Azi (deg);TVD (ft);DLS (deg/100ft)\n"
            "0;0;10;0;0\n\n1000;2;10;999.8;0.2\n")
    survey = parse_survey(text, "export.txt")
    assert survey.measured_depth == (0.0, pytest.approx(1000 * FOOT, rel=1e-15))
    assert survey.lines == (3, 5)


def test_a_vertical_station_at_the_wellhead_is_added_and_azimuths_wrap():
    survey = parse_survey(HEADER + "30,1,-90\n60,2,360\n", "s.csv")
    assert survey.measured_depth == (0.0, 30.0, 60.0) and survey.inclination[0] == 0.0 and survey.lines[0] == 0
    assert survey.azimuth[1:] == (pytest.approx(1.5 * math.pi), pytest.approx(0.0, abs=1e-15))


@pytest.mark.parametrize("text, words", [
    (HEADER + "0,0,0\n500,0,0\n400,10,0\n", "s.csv: line 4: column 1 (measured_depth): 400 m does not go below the "
                                            "station before it (500 m, line 3)"),
    (HEADER + "0,0,0\n500,0,0\n500,10,0\n", "line 4: column 1 (measured_depth): 500 m does not go below"),
    (HEADER + "0,0,0\n500,181,0\n", "s.csv: line 3: column 2 (inclination): 181 deg is outside 0 .. 180 deg"),
    (HEADER + "0,0,0\n500,nan,0\n", "s.csv: line 3: column 2 (inclination): 'nan' is not a finite number"),
    (HEADER + "0,0,0\n500,10,abc\n", "s.csv: line 3: column 3 (azimuth): 'abc' is not a number"),
    (HEADER + "0,0,0\n500,10,400\n", "line 3: column 3 (azimuth): 400 deg is outside -360 .. 360 deg"),
    (HEADER + "0,0,0\n-5,10,0\n", "line 3: column 1 (measured_depth): -5 m is outside"),
    (HEADER + "0,0,0\n500,10\n", "s.csv: line 3: 2 cells for 3 columns"),
    ("measured_depth,inclination_deg,azimuth_deg\n0,0,0\n", "s.csv: line 1: column 1: column 'measured_depth' names "
                                                            "no unit"),
    ("measured_depth_km,inclination_deg,azimuth_deg\n0,0,0\n", "column 1: column 'measured_depth_km' has unit 'km'"),
    ("md_m,inclination_deg,azimuth_m\n0,0,0\n", "column 3: column 'azimuth_m' has unit 'm', not a unit of angle"),
    ("md_m,inclination_deg,load_n\n0,0,0\n", "s.csv: line 1: column 3: unknown column 'load_n'"),
    ("md_m,inclination_deg\n0,0\n", "s.csv: line 1: no azimuth column"),
    (HEADER, "s.csv: the survey has a header but no station"),
    ("# nothing\n", "s.csv: no header line"),
    ("md_m inclination_deg azimuth_deg\n", "s.csv: line 1: the header holds no comma, semicolon or tab"),
    ("md_m;inclination_deg;azimuth_deg\n0;0;0\n500;1,5;0\n", "line 3: column 2 (inclination): '1,5' has a decimal "
                                                            "comma"),
])
def test_bad_surveys_are_one_line_naming_file_line_and_column(text, words):
    with pytest.raises(ConfigError) as caught:
        parse_survey(text, "s.csv")
    message = str(caught.value)
    assert words in message and "\n" not in message


def test_files_are_read_as_every_input_is(tmp_path):
    good = tmp_path / "good.csv"
    good.write_text(HEADER + "0,0,0\n100,5,0\n", encoding="utf-8")
    assert read_survey(good).depth == 100.0
    binary = tmp_path / "bad.csv"
    binary.write_bytes(b"\xff\xfe" + HEADER.encode("utf-16-le"))
    with pytest.raises(ConfigError, match="bad.csv: is UTF-16"):
        read_survey(binary)
    with pytest.raises(ConfigError, match="missing.csv: cannot read: no such file"):
        read_survey(tmp_path / "missing.csv")


def test_a_survey_that_lifts_the_pump_above_the_wellhead_is_refused(tmp_path, run_cli):
    """Down 300 m, then a build to 150 deg: the hole climbs back, and at 1530 m measured the SK8's pump
    would sit above the wellhead, with no fluid column over it; refused naming the survey. Short of
    that, a fluid level above the pump's true vertical depth is refused naming the key and the survey."""
    survey = tmp_path / "updip.csv"
    survey.write_text("measured_depth_m,inclination_deg,azimuth_deg\n0,0,0\n300,0,0\n600,90,0\n900,120,0\n"
                      "1700,150,0\n", encoding="utf-8")
    code, out, err = run_cli("predict", "sk8-3.5-4000", "--survey", survey, "--samples", "64")
    assert (code, out) == (2, "")
    assert f"{survey}: the survey puts the pump (1530 m measured) at a true vertical depth of -" in err
    assert err.count("\n") == 1
    survey.write_text("measured_depth_m,inclination_deg,azimuth_deg\n0,0,0\n300,0,0\n600,90,0\n900,120,0\n"
                      "1600,120,0\n", encoding="utf-8")
    code, out, err = run_cli("predict", "sk8-3.5-4000", "--survey", survey, "--samples", "64", "--submergence", "100 m")
    assert (code, out) == (2, "")
    assert "well.pump_submergence 100 m is more than the pump's true vertical depth" in err and str(survey) in err
