"""[NIST811]: the package's conversion factors against their published values.

Source: A. Thompson, B.N. Taylor, NIST SP 811 (2008), Appendix B [NIST811]. Exact by
definition: in = 0.0254 m and ft = 0.3048 m (international yard and pound, 1959),
lb = 0.45359237 kg, the standard acceleration of gravity g_n = 9.80665 m/s² (3rd CGPM,
[BIPM2019]), so kgf = 9.80665 N, lbf = lb g_n = 4.4482216152605 N, hp = 550 ft·lbf/s and the
oil barrel = 42 US gallons of 231 in³. Printed (7 significant digits, Appendix B.8):
lbf 4.448 222 N, lbf·in 1.129 848 E-01 N·m, psi 6.894 757 E+03 Pa, hp 7.456 999 E+02 W,
bbl 1.589 873 E-01 m³, ft·lbf 1.355 818 N·m.

These literal values are written here only: every other test takes the package's factors
(tests/helpers.py), which this file pins to the definitions.
Tolerances: a factor stored as a decimal literal must equal the definition's nearest double
(equality); a product of definitions may differ from the package's by a few ulp (rel 1e-15
for one product, 1e-14 for a chain); a printed 7-digit value is met to half a unit of its
last digit.
"""

from __future__ import annotations

import pytest

from pumpjack_cli.core.constants import STANDARD_GRAVITY
from pumpjack_cli.quantities import output_unit, parse_quantity

from helpers import BARREL, FOOT, HORSEPOWER, INCH, KILOGRAM_FORCE, POUND_FORCE, POUND_MASS, PSI

#: The exact definitions, as published.
IN, FT, LB, G_N = 0.0254, 0.3048, 0.45359237, 9.80665
LBF = 4.4482216152605
HP = 550 * FT * LBF
BBL = 42 * 231 * IN**3

#: Factors the package writes as decimal literals: (its factor, the definition).
LITERALS = {
    "inch": (INCH, IN), "foot": (FOOT, FT), "pound": (POUND_MASS, LB), "kilogram-force": (KILOGRAM_FORCE, G_N),
    "standard gravity": (STANDARD_GRAVITY, G_N), "pound-force": (POUND_FORCE, LBF),
}
#: Factors built from the definitions: (the package's, the definition, NIST's 7 printed digits, half a unit
#: of the last of them).
PRODUCTS = {
    "pound-force": (POUND_FORCE, LB * G_N, 4.448222, 5e-7),
    "pound-force inch": (POUND_FORCE * INCH, LBF * IN, 1.129848e-1, 5e-8),
    "foot pound-force": (POUND_FORCE * FOOT, LBF * FT, 1.355818, 5e-7),
    "psi": (PSI, LBF / IN**2, 6.894757e3, 5e-4),
    "horsepower": (HORSEPOWER, HP, 7.456999e2, 5e-5),
    "barrel": (BARREL, BBL, 1.589873e-1, 5e-8),
}


def test_definitions_used_here_are_consistent():
    """lbf and hp are themselves defined from lb, g_n and ft: the literals above agree."""
    assert LB * G_N == pytest.approx(LBF, rel=1e-15)
    assert HP == pytest.approx(745.69987158227022, rel=1e-15)
    assert BBL == pytest.approx(0.158987294928, rel=1e-15)


@pytest.mark.parametrize("name", LITERALS)
def test_a_literal_factor_is_the_definition(name):
    package, definition = LITERALS[name]
    assert package == definition


@pytest.mark.parametrize("name", PRODUCTS)
def test_a_derived_factor_is_the_definition_and_the_printed_value(name):
    package, definition, printed, half_unit = PRODUCTS[name]
    assert package == pytest.approx(definition, rel=1e-15)
    assert abs(package - printed) <= half_unit


@pytest.mark.parametrize(("text", "dimension", "definition"), [
    ("1 in", "length", IN), ("1 ft", "length", FT), ("1 lb", "mass", LB), ("1 kgf", "force", G_N),
    ("1 lbf", "force", LBF), ("1 lbf·in", "torque", LBF * IN), ("1 ft·lbf", "torque", LBF * FT),
    ("1 hp", "power", 745.69987158227022), ("1 psi", "pressure", LBF / IN**2),
])
def test_input_units_parse_to_the_definition(text, dimension, definition):
    assert parse_quantity(text, dimension) == pytest.approx(definition, rel=1e-14)


@pytest.mark.parametrize(("quantity", "suffix", "definition"), [
    ("length", "in", IN), ("velocity", "ft_s", FT), ("mass", "lb", LB), ("force", "lbf", LBF),
    ("torque", "lbf_in", LBF * IN), ("energy", "ft_lbf", LBF * FT), ("pressure", "psi", LBF / IN**2),
    ("power", "hp", HP), ("volume", "bbl", BBL),
])
def test_field_output_units_show_one_unit_for_its_definition(quantity, suffix, definition):
    """The oilfield display of the SI value of one unit is 1 (one division: rel 1e-14)."""
    unit = output_unit(quantity, "field")
    assert unit.suffix == suffix
    assert definition * unit.scale == pytest.approx(1.0, rel=1e-14)
