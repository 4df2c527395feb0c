"""Units of measure (pumpjack_cli.quantities): parse_quantity and the output units.

Expected values are built here from the conversion factors of the units they combine (the
package's in, ft, lb, lbf, kgf and hp, whose values are checked against their published
definitions in tests/validation/test_nist811.py; the SI prefixes; rpm = 2 pi / 60 rad/s), so
each case checks that its text maps to the right unit and the right combination of factors.
Tolerance: each expected value is a product of a few factors, computed in a possibly
different order than the package does, so the two may differ by a few units in the last
place; rel = 1e-14 (about 45 ulp) allows that and nothing more.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.core.constants import STANDARD_GRAVITY
from pumpjack_cli.quantities import OUTPUT_QUANTITIES, output_unit, parse_quantity, significant

from helpers import FOOT, HORSEPOWER, INCH, KILOGRAM_FORCE, POUND_FORCE, POUND_MASS, RPM

REL = 1e-14  # see the module docstring


CASES = [
    # length
    ("3500 mm", "length", 3.5),
    ("350 cm", "length", 3.5),
    ("2 m", "length", 2.0),
    ("1.53 km", "length", 1530.0),
    ("137.5 in", "length", 137.5 * INCH),
    ("1 in", "length", INCH),
    ("1 ft", "length", FOOT),
    ("10 ft", "length", 10 * FOOT),
    # mass
    ("1 lb", "mass", POUND_MASS),
    ("3 lbm", "mass", 3 * POUND_MASS),
    ("1373 kg", "mass", 1373.0),
    ("2 t", "mass", 2000.0),
    ("500 g", "mass", 0.5),
    # force
    ("1 lbf", "force", POUND_FORCE),
    ("1 lbf", "force", POUND_MASS * STANDARD_GRAVITY),
    ("13.3 klbf", "force", 13300 * POUND_FORCE),
    ("1 kgf", "force", STANDARD_GRAVITY),
    ("2 tf", "force", 2000 * KILOGRAM_FORCE),
    ("80 kN", "force", 80000.0),
    ("5 N", "force", 5.0),
    # torque
    ("1 N·m", "torque", 1.0),
    ("7 N*m", "torque", 7.0),
    ("56 kN·m", "torque", 56000.0),
    ("5600 kgf·m", "torque", 5600 * KILOGRAM_FORCE),
    ("114000 lbf·in", "torque", 114000 * POUND_FORCE * INCH),
    ("12 in·lbf", "torque", POUND_FORCE * FOOT),  # 12 in = 1 ft
    ("1 ft·lbf", "torque", POUND_FORCE * FOOT),
    ("1 lbf*ft", "torque", POUND_FORCE * FOOT),
    # moment of inertia
    ("0.232 kg*m2", "moment_of_inertia", 0.232),
    ("0.232 kg·m²", "moment_of_inertia", 0.232),
    ("1 lb·ft²", "moment_of_inertia", POUND_MASS * FOOT**2),
    ("1 lb*in2", "moment_of_inertia", POUND_MASS * INCH**2),
    # rotational speed
    ("1460 rpm", "rotational_speed", 1460 * RPM),
    ("1460 RPM", "rotational_speed", 1460 * RPM),
    ("60 1/min", "rotational_speed", 2 * math.pi),
    ("10 spm", "rotational_speed", 10 * RPM),
    ("1.5 rad/s", "rotational_speed", 1.5),
    ("1.5 1/s", "rotational_speed", 1.5),
    # angle
    ("180 deg", "angle", math.pi),
    ("90°", "angle", math.pi / 2),
    ("0.5 rad", "angle", 0.5),
    # power
    ("1 hp", "power", HORSEPOWER),
    ("30 kW", "power", 30000.0),
    ("750 W", "power", 750.0),
    # density
    ("820 kg/m3", "density", 820.0),
    ("820 kg/m³", "density", 820.0),
    ("1 g/cm3", "density", 1000.0),
    ("62.4 lb/ft3", "density", 62.4 * POUND_MASS / FOOT**3),
    # kinematic viscosity
    ("1 cSt", "kinematic_viscosity", 1e-6),
    ("3 cSt", "kinematic_viscosity", 3e-6),
    ("3 mm2/s", "kinematic_viscosity", 3e-6),
    ("3e-6 m2/s", "kinematic_viscosity", 3e-6),
    # fraction
    ("51 %", "fraction", 0.51),
    ("51%", "fraction", 0.51),
    ("100 %", "fraction", 1.0),
]


@pytest.mark.parametrize(("text", "dimension", "expected"), CASES, ids=[f"{d}:{t}" for t, d, _ in CASES])
def test_parse_quantity_field_units(text, dimension, expected):
    value = parse_quantity(text, dimension)
    assert isinstance(value, float)
    assert value == pytest.approx(expected, rel=REL)


@pytest.mark.parametrize(
    ("text", "dimension"),
    [("0.232 kg*m2", "moment_of_inertia"), ("0.232 kg·m²", "moment_of_inertia"), ("0.232 kg⋅m²", "moment_of_inertia"),
     ("4 N·m", "torque"), ("4 N*m", "torque"), ("4 N⋅m", "torque")],
)
def test_multiplication_spellings_are_equivalent(text, dimension):
    # Every spelling of the product means the same unit: kg*m2 = kg·m² = 1 kg·m²,
    # N*m = N·m = 1 N·m (SI units, factor exactly 1).
    expected = 0.232 if dimension == "moment_of_inertia" else 4.0
    assert parse_quantity(text, dimension) == expected


@pytest.mark.parametrize(
    ("value", "expected"),
    [(3, 3.0), (3.25, 3.25), (-2, -2.0), (0, 0.0), ("3.5", 3.5), (" 1e-3 ", 1e-3), ("42", 42.0)],
)
def test_plain_numbers_are_si(value, expected):
    # A number without a unit is taken as SI, whatever the dimension.
    for dimension in ("length", "mass", "rotational_speed", "fraction"):
        result = parse_quantity(value, dimension)
        assert isinstance(result, float)
        assert result == expected


@pytest.mark.parametrize(
    ("value", "dimension", "fragment"),
    [
        ("3,5 m", "length", "decimal comma"),
        ("3,5", "length", "decimal comma"),
        ("1460,5 rpm", "rotational_speed", "decimal comma"),
        ("3 kg", "length", "is a mass"),
        ("3 m", "mass", "is a length"),
        ("10 spm", "length", "is a rotational speed"),
        ("30 kW", "torque", "is a power"),
        ("3 furlong", "length", "unknown unit"),
        ("3 parsec", "length", "unknown unit 'parsec'"),
        ("abc", "length", "not a number"),
        ("\u0663 m", "length", "not a number"),  # an Arabic-Indic 3: digits are 0-9 only
        ("3 \u043c\u0435\u0442\u0440", "length", "unknown unit"),  # not one of the abbreviations
        ("m 3", "length", "not a number"),
        ("", "length", "not a number"),
        (True, "length", "boolean"),
        (False, "mass", "boolean"),
        (None, "length", "expected a number"),
        ([3, "m"], "length", "expected a number"),
    ],
)
def test_parse_quantity_rejects(value, dimension, fragment):
    with pytest.raises(ValueError) as info:
        parse_quantity(value, dimension)
    assert fragment in str(info.value)


def test_wrong_dimension_message_names_both_dimensions():
    with pytest.raises(ValueError, match=r"'3 kg' is a mass, not a length"):
        parse_quantity("3 kg", "length")


def test_unknown_unit_message_lists_the_accepted_units():
    with pytest.raises(ValueError) as info:
        parse_quantity("3 furlong", "length")
    for unit in ("m", "mm", "in", "ft"):
        assert unit in str(info.value).split("use one of", 1)[1]


# Output side: the display scale of each quantity in the oilfield system is the
# reciprocal of the exact definition. rel 1e-12: one division, a few ulp at most.
@pytest.mark.parametrize(
    ("quantity", "si_value", "field_value", "suffix"),
    [
        ("length", INCH, 1.0, "in"),
        ("velocity", FOOT, 1.0, "ft_s"),
        ("acceleration", FOOT, 1.0, "ft_s2"),
        ("force", POUND_FORCE, 1.0, "lbf"),
        ("torque", POUND_FORCE * INCH, 1.0, "lbf_in"),
        ("angle", math.pi, 180.0, "deg"),
        ("stroke_rate", 2 * math.pi / 60, 1.0, "spm"),
    ],
)
def test_output_units_field_system(quantity, si_value, field_value, suffix):
    unit = output_unit(quantity, "field")
    assert unit.suffix == suffix
    assert si_value * unit.scale == pytest.approx(field_value, rel=1e-12)


@pytest.mark.parametrize(
    ("quantity", "suffix"),
    [("length", "m"), ("velocity", "m_s"), ("acceleration", "m_s2"), ("force", "n"), ("torque", "n_m"), ("time", "s")],
)
def test_output_units_si_system_is_identity(quantity, suffix):
    unit = output_unit(quantity, "si")
    assert unit.suffix == suffix
    assert unit.scale == 1.0


@pytest.mark.parametrize(("text", "dimension", "same_as"), [
    ("3.5 metres", "length", "3.5 m"), ("3.5 meter", "length", "3.5 m"), ("137.5 inches", "length", "137.5 in"),
    ("137.5 in.", "length", "137.5 in"), ("11.5 feet", "length", "11.5 ft"), ("11.5 ft.", "length", "11.5 ft"),
    ("45 degrees", "angle", "45 deg"), ("1460 r/min", "rotational_speed", "1460 rpm"),
    ("1460 rev/min", "rotational_speed", "1460 rpm"),
    # the Cyrillic abbreviations of GOST documents
    ("3500 \u043c\u043c", "length", "3500 mm"), ("1460 \u043e\u0431/\u043c\u0438\u043d", "rotational_speed", "1460 rpm"),
    ("8 \u0442\u0441", "force", "8 tf"), ("4000 \u043a\u0433\u0441\u00b7\u043c", "torque", "4000 kgf*m"),
    ("30 \u043a\u0412\u0442", "power", "30 kW"), ("850 \u043a\u0433/\u043c\u00b3", "density", "850 kg/m3"),
    ("5 \u041c\u041f\u0430", "pressure", "5 MPa"),
    ("\u22125 m", "length", "-5 m"),  # the minus sign of typeset text
])
def test_other_spellings_are_the_same_unit(text, dimension, same_as):
    assert parse_quantity(text, dimension) == parse_quantity(same_as, dimension)


def test_a_float_keeps_15_significant_digits_as_formatting_rounds_it():
    """significant of a float is float(f"{x:.15g}"), and the array path gives the same, over the
    whole range of doubles (random bit patterns), with zeros and the non-finite values kept."""
    values = np.random.default_rng(11).integers(0, 2**64, size=20000, dtype=np.uint64).view(np.float64)
    values = np.concatenate([values[np.isfinite(values)], [0.0, -0.0, 5e-324, 1.7976931348623157e308, 7e5 - 1e-10]])
    found = [significant(float(x)) for x in values]
    assert found == [float(f"{x:.15g}") for x in values.tolist()]
    assert found == significant(values).tolist()
    assert math.copysign(1.0, significant(-0.0)) == -1.0 and math.isnan(significant(math.nan))


@pytest.mark.parametrize("system", ["si", "field"])
def test_a_summary_is_converted_as_each_value_alone(system):
    """converted_summary (results.py) gives each value what OutputUnit.convert gives it, a value shown in
    the unit it is computed in as the value + 0.0: every quantity, a negative zero, the ends of the
    range, a numpy float and an int; text as it is."""
    from pumpjack_cli.names import catalogue
    from pumpjack_cli.results import Result, Scalar, converted_summary

    names = {}
    for name, (quantity, _) in catalogue().items():
        if "{" not in name:
            names.setdefault(quantity, name)
    values = (0.0, -0.0, 1.0, -2.5, 5e-324, 1e200, 123.45678901234567, np.float64(0.1 + 0.2), 3)
    for quantity, name in names.items():
        if quantity == "text":
            assert converted_summary(Result("", (Scalar(name, "full"),), ()), system) == {name: "full"}
            continue
        unit = OUTPUT_QUANTITIES[quantity][system]
        for value in values:
            ((key, shown),) = converted_summary(Result("", (Scalar(name, value),), ()), system).items()
            expected = float(unit.convert(float(value)))
            assert type(shown) is float and key.startswith(name)
            assert (shown, math.copysign(1.0, shown)) == (expected, math.copysign(1.0, expected)), (name, value)
