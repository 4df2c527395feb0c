"""Physical quantities at the edges: parsing field units on input, labelling output.

This module imports no numpy (start-up cost matters in pipelines); display conversion
works on floats and on numpy arrays alike.

Inside the package every number is SI (m, kg, s, N, rad). Config values may be plain
numbers (taken as SI) or strings with a unit (``"3500 mm"``, ``"137.5 in"``,
``"1460 rpm"``); :func:`parse_quantity` converts them once. The renderer converts
results back for display through :data:`OUTPUT_QUANTITIES`.

Conversion factors are exact definitions or the values of [NIST811], Appendix B (in = 0.0254 m, ft = 0.3048 m, lb = 0.45359237 kg,
lbf = 4.4482216152605 N, kgf = 9.80665 N, hp = 745.699872 W).
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass


INCH = 0.0254
FOOT = 0.3048
POUND_MASS = 0.45359237
POUND_FORCE = 4.4482216152605
KILOGRAM_FORCE = 9.80665
HORSEPOWER = 745.69987158227022
#: Oil barrel, 42 US gallons of 231 in^3 [NIST811].
BARREL = 42 * 231 * INCH**3
#: Kilowatt hour [J] and day [s] ([NIST811]).
KWH = 3.6e6
DAY = 86400.0
#: Pumping speeds the tool takes [1/min]: of ``--spm``, of a file's stated SPM, and of a card's
#: time stamps (a card that implies another speed is no beam unit's card).
SPM_RANGE = (0.1, 60.0)

#: Accepted input units for each dimension: normalised unit text -> factor to SI.
INPUT_UNITS: dict[str, dict[str, float]] = {
    "length": {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "km": 1e3, "in": INCH, "ft": FOOT},
    "mass": {"kg": 1.0, "t": 1e3, "g": 1e-3, "lb": POUND_MASS, "lbm": POUND_MASS},
    "force": {
        "n": 1.0,
        "kn": 1e3,
        "lbf": POUND_FORCE,
        "klbf": 1e3 * POUND_FORCE,
        "kgf": KILOGRAM_FORCE,
        "tf": 1e3 * KILOGRAM_FORCE,
    },
    "torque": {
        "n*m": 1.0,
        "kn*m": 1e3,
        "kgf*m": KILOGRAM_FORCE,
        "lbf*in": POUND_FORCE * INCH,
        "in*lbf": POUND_FORCE * INCH,
        "lbf*ft": POUND_FORCE * FOOT,
        "ft*lbf": POUND_FORCE * FOOT,
    },
    "moment_of_inertia": {
        "kg*m2": 1.0,
        "lb*ft2": POUND_MASS * FOOT**2,
        "lb*in2": POUND_MASS * INCH**2,
    },
    "rotational_speed": {
        "rad/s": 1.0,
        "1/s": 1.0,
        "rpm": 2 * math.pi / 60,
        "1/min": 2 * math.pi / 60,
        "spm": 2 * math.pi / 60,
    },
    "angle": {"rad": 1.0, "mrad": 1e-3, "deg": math.pi / 180},
    # rotational stiffness of a joint: moment per radian
    "rotational_stiffness": {"n*m/rad": 1.0, "kn*m/rad": 1e3, "lbf*in/rad": POUND_FORCE * INCH,
                             "lbf*ft/rad": POUND_FORCE * FOOT},
    "power": {"w": 1.0, "kw": 1e3, "hp": HORSEPOWER},
    "density": {"kg/m3": 1.0, "g/cm3": 1e3, "lb/ft3": POUND_MASS / FOOT**3},
    "kinematic_viscosity": {"m2/s": 1.0, "mm2/s": 1e-6, "cst": 1e-6},
    "fraction": {"%": 1e-2},
    "area": {"m2": 1.0, "cm2": 1e-4, "mm2": 1e-6, "in2": INCH**2},
    "volume": {"m3": 1.0, "l": 1e-3, "in3": INCH**3, "ft3": FOOT**3, "gal": 231 * INCH**3},
    "area_moment": {"m4": 1.0, "cm4": 1e-8, "mm4": 1e-12, "in4": INCH**4},
    "pressure": {"pa": 1.0, "kpa": 1e3, "mpa": 1e6, "gpa": 1e9, "bar": 1e5, "psi": POUND_FORCE / INCH**2},
    # weight per unit length of a rod (couplings included); "lb/ft" and "kg/m" are the
    # weights of a pound and a kilogram per unit length, as rod tables print them
    "weight_per_length": {"n/m": 1.0, "kn/m": 1e3, "lbf/ft": POUND_FORCE / FOOT, "lb/ft": POUND_FORCE / FOOT,
                          "kgf/m": KILOGRAM_FORCE, "kg/m": KILOGRAM_FORCE},
    "flow_rate": {"m3/s": 1.0, "m3/d": 1 / 86400, "bbl/d": BARREL / 86400, "l/s": 1e-3, "l/min": 1e-3 / 60},
    # the share of the day a unit runs: a percentage or hours per day
    "runtime": {"%": 1e-2, "h/d": 1 / 24, "h": 1 / 24},
    # a price per unit of energy, in any currency: SI per joule
}

#: Other spellings of the units above, normalised text -> key: English names, and the
#: Cyrillic abbreviations of GOST drawings and passports (мм, кгс, об/мин, ...).
UNIT_SPELLINGS = {
    "meter": "m", "meters": "m", "metre": "m", "metres": "m", "millimeter": "mm", "millimeters": "mm",
    "millimetre": "mm", "millimetres": "mm", "inch": "in", "inches": "in", "foot": "ft", "feet": "ft",
    "degree": "deg", "degrees": "deg", "radian": "rad", "radians": "rad", "r/min": "rpm", "rev/min": "rpm",
    "м": "m", "мм": "mm", "см": "cm", "км": "km", "кг": "kg", "т": "t", "н": "n", "кн": "kn", "кгс": "kgf",
    "тс": "tf", "н*м": "n*m", "кн*м": "kn*m", "кгс*м": "kgf*m", "кг*м2": "kg*m2", "об/мин": "rpm", "град": "deg",
    "вт": "w", "квт": "kw", "кг/м3": "kg/m3", "па": "pa", "кпа": "kpa", "мпа": "mpa", "гпа": "gpa", "бар": "bar",
}

#: A unit to suggest when one is missing, per dimension.
_EXAMPLE_UNITS = {"length": "m", "mass": "kg", "force": "N", "torque": "N*m", "moment_of_inertia": "kg*m2",
                  "rotational_speed": "rpm", "angle": "deg", "rotational_stiffness": "N*m/rad", "power": "kW", "density": "kg/m3",
                  "kinematic_viscosity": "mm2/s", "fraction": "%", "area": "cm2", "area_moment": "cm4",
                  "pressure": "MPa", "weight_per_length": "lbf/ft",
                  "runtime": "h/d", "flow_rate": "m3/d"}

#: The SI unit every value of a dimension is converted to, as messages print it.
SI_LABELS = {"length": "m", "mass": "kg", "force": "N", "torque": "N·m", "moment_of_inertia": "kg·m²",
             "rotational_speed": "rad/s", "angle": "rad", "rotational_stiffness": "N·m/rad", "power": "W",
             "density": "kg/m³", "kinematic_viscosity": "m²/s", "fraction": "", "area": "m²", "area_moment": "m⁴",
             "pressure": "Pa", "weight_per_length": "N/m", "volume": "m³",
             "runtime": "", "flow_rate": "m³/s"}

_NUMBER = re.compile(r"^\s*([+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)\s*(.*?)\s*$")


@functools.lru_cache(maxsize=1024)
def _normalise_unit(text: str) -> str:
    """Fold the spellings of a unit: case, multiplication dots or spaces, superscripts, an
    abbreviation's final dot (``"in."``) and the names of :data:`UNIT_SPELLINGS`.

    A space between two symbols multiplies them (``"N m"`` is N*m), so ``"m m"`` is m*m,
    an area, never mm.
    """
    text = re.sub(r"\s*([·⋅×.*/^])\s*", r"\1", text.strip().lower().removesuffix("."))
    text = re.sub(r"\s+", "*", text)
    for dot in ("·", "⋅", "×", "."):
        text = text.replace(dot, "*")
    text = text.replace("²", "2").replace("³", "3").replace("^", "").replace("°", "deg")
    return UNIT_SPELLINGS.get(text, text)


def _a(dimension: str) -> str:
    """The dimension's name with its indefinite article ("a length", "an angle")."""
    name = dimension.replace("_", " ")
    return f"{'an' if name[0] in 'aeiou' else 'a'} {name}"


def parse_quantity(value: object, dimension: str, require_unit: bool = False) -> float:
    """Convert a config value of the given dimension to an SI float.

    Plain numbers are taken as SI, unless ``require_unit`` (command-line options whose
    name does not carry the unit). Strings carry a unit from :data:`INPUT_UNITS`; a
    string without a unit is taken as SI likewise. A decimal comma is rejected, never
    guessed (``"3,5 m"`` could be 3.5 m or 35 m); so are infinite and NaN values.

    >>> parse_quantity("3500 mm", "length")
    3.5
    >>> round(parse_quantity("137.5 in", "length"), 6)
    3.4925
    >>> round(parse_quantity("1460 rpm", "rotational_speed"), 4)   # 1460 x 2 pi / 60 = 152.89084...
    152.8908
    >>> parse_quantity("12 N m", "torque")
    12.0
    >>> parse_quantity("0.1", "angle", require_unit=True)
    Traceback (most recent call last):
    ...
    ValueError: '0.1' has no unit: write it with one, e.g. '0.1 deg'

    """
    if isinstance(value, bool):
        raise ValueError("expected a number or a string with a unit, got a boolean")
    if isinstance(value, (int, float)):
        if require_unit:
            raise ValueError(f"{value!r} has no unit: write it with one, e.g. '{value} {_EXAMPLE_UNITS[dimension]}'")
        if not math.isfinite(value):
            raise ValueError(f"{value!r} is not a finite number")
        return float(value)
    if not isinstance(value, str):
        raise ValueError(f"expected a number or a string with a unit, got {type(value).__name__}")
    value = value.replace("\u2212", "-")  # the minus sign of typeset documents
    if re.search(r"\d,\d", value):
        raise ValueError(f"{value!r} has a decimal comma, which is ambiguous: write it with a point")
    match = _NUMBER.match(value)
    if not match:
        raise ValueError(f"{value!r} is not a number with a unit")
    number, unit = float(match.group(1)), _normalise_unit(match.group(2))
    if not math.isfinite(number):
        raise ValueError(f"{value!r} is not a finite number")
    if not unit:
        if require_unit:
            raise ValueError(f"{value!r} has no unit: write it with one, e.g. '{value.strip()} {_EXAMPLE_UNITS[dimension]}'")
        return number
    units = INPUT_UNITS[dimension]
    if unit not in units:
        for other, table in INPUT_UNITS.items():
            if unit in table:
                raise ValueError(f"{value!r} is {_a(other)}, not {_a(dimension)}")
        raise ValueError(f"unknown unit {match.group(2)!r} for a {dimension.replace('_', ' ')}; use one of {', '.join(units)}")
    return number * units[unit]


#: Significant digits of a converted output value: the most a float64 keeps through a decimal
#: round trip (DBL_DIG of C's float.h; IEEE 754 binary64 has a 53-bit significand, 15.95 digits).
SIGNIFICANT_DIGITS = 15


def significant(values, digits: int = SIGNIFICANT_DIGITS):
    """A float or a numpy array rounded to ``digits`` significant digits, as ``f"{x:.15g}"``
    rounds (zeros and non-finite values are left as they are).

    An array is rounded without leaving numpy where 10^k is exact (k <= 22): n = round(x 10^k)
    of the exact product, and n / 10^k, the float nearest to the decimal.

    >>> significant(699999.9999999999), significant(0.30000000000000004), significant(1.0000000000000002e-05)
    (700000.0, 0.3, 1e-05)
    """
    if isinstance(values, (float, int)):
        value = float(values)
        if value == 0.0 or not math.isfinite(value):
            return value
        return float("%.*g" % (digits, value))
    import numpy as np   # an array: numpy is already loaded

    x = np.asarray(values, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        magnitude = np.abs(x)
        usable = np.isfinite(x) & (magnitude > 0)
        power = np.zeros(x.shape, dtype=int)
        power[usable] = (digits - 1) - np.floor(np.log10(magnitude[usable])).astype(int)
        exact = usable & (power >= 0) & (power <= 22)   # 10^k exact: the vectorised rounding
        out = x.copy()
        scale = 10.0 ** power[exact]
        out[exact] = _round_product(x[exact], scale) / scale
    for i in np.flatnonzero(usable & ~exact):   # below 1e-8 or above 1e15: rare, one at a time
        out.flat[i] = float(f"{float(x.flat[i]):.{digits}g}")
    return out


def _round_product(x, scale):
    """round(x scale) of the exact product (not of its float): the product split into the float
    p and its error e (Dekker's two-product, by Veltkamp's splitting), so that a product within
    an ulp of a half is rounded as the exact value is, half to even. Arrays."""
    import numpy as np

    def split(a):
        c = 134217729.0 * a   # 2^27 + 1
        high = c - (c - a)
        return high, a - high

    p = x * scale
    xh, xl = split(x)
    sh, sl = split(scale)
    e = ((xh * sh - p) + xh * sl + xl * sh) + xl * sl
    n = np.round(p)
    rest = (p - n) + e   # exact: p - n is exact for |p| < 2^52
    n = np.where(rest > 0.5, n + 1.0, np.where(rest < -0.5, n - 1.0, n))
    tie = rest == 0.5
    n = np.where(tie & (np.mod(n, 2.0) == 1.0), n + 1.0, n)
    tie = rest == -0.5
    return np.where(tie & (np.mod(n, 2.0) == 1.0), n - 1.0, n)


@dataclass(frozen=True)
class OutputUnit:
    """How one quantity is shown: a label, a column-name suffix, a scale from SI and,
    for angles, the decimals kept (so that 60 degrees prints as 60.0, not
    59.99999999999999 after the round trip through radians)."""

    label: str
    suffix: str
    scale: float
    decimals: int | None = None

    def convert(self, si_values):
        """SI value(s) -> display value(s): a float for a float, an array for a numpy array.

        Rounding (angles) is round-half-even at ``decimals``, computed as numpy's
        ``around`` does (scale, round to integer, unscale) for floats and arrays alike.
        A value that is scaled (any other unit than the SI one it is computed in) is kept
        to :data:`SIGNIFICANT_DIGITS` significant digits, so that the last-bit noise of
        the conversion is not shown (700000 lbf·in read from a unit file comes back as
        700000.0, not 699999.9999999999); a value shown in its SI unit is unchanged. A
        negative zero comes back as 0.0.

        >>> torque = OUTPUT_QUANTITIES["torque"]["field"]
        >>> torque.convert(700000 * POUND_FORCE * INCH), OUTPUT_QUANTITIES["force"]["si"].convert(-0.0)
        (700000.0, 0.0)
        """
        shown = si_values * self.scale
        if self.decimals is not None:
            factor = 10.0**self.decimals
            if isinstance(shown, float):
                shown = round(shown * factor) / factor
            else:
                shown = shown.round(self.decimals)
        elif self.scale != 1.0:
            shown = significant(shown)
        return shown + 0.0   # -0.0 + 0.0 is +0.0 (IEEE 754, round to nearest)


_DEGREES = OutputUnit("deg", "deg", 180 / math.pi, decimals=9)

#: Output quantities: kind -> (SI display, oilfield display). Angles are shown in
#: degrees in both systems, to 1e-9 degree; the internal value is radians.
OUTPUT_QUANTITIES: dict[str, dict[str, OutputUnit]] = {
    "angle": {"si": _DEGREES, "field": _DEGREES},
    "time": {"si": OutputUnit("s", "s", 1.0), "field": OutputUnit("s", "s", 1.0)},
    "length": {"si": OutputUnit("m", "m", 1.0), "field": OutputUnit("in", "in", 1 / INCH)},
    "velocity": {"si": OutputUnit("m/s", "m_s", 1.0), "field": OutputUnit("ft/s", "ft_s", 1 / FOOT)},
    "acceleration": {"si": OutputUnit("m/s²", "m_s2", 1.0), "field": OutputUnit("ft/s²", "ft_s2", 1 / FOOT)},
    "angular_velocity": {"si": OutputUnit("rad/s", "rad_s", 1.0), "field": OutputUnit("rad/s", "rad_s", 1.0)},
    "angular_acceleration": {
        "si": OutputUnit("rad/s²", "rad_s2", 1.0),
        "field": OutputUnit("rad/s²", "rad_s2", 1.0),
    },
    "stroke_rate": {"si": OutputUnit("1/min", "spm", 60 / (2 * math.pi)), "field": OutputUnit("1/min", "spm", 60 / (2 * math.pi))},
    "force": {"si": OutputUnit("N", "n", 1.0), "field": OutputUnit("lbf", "lbf", 1 / POUND_FORCE)},
    "mass": {"si": OutputUnit("kg", "kg", 1.0), "field": OutputUnit("lb", "lb", 1 / POUND_MASS)},
    "pressure": {"si": OutputUnit("Pa", "pa", 1.0), "field": OutputUnit("psi", "psi", INCH**2 / POUND_FORCE)},
    "stress": {"si": OutputUnit("MPa", "mpa", 1e-6), "field": OutputUnit("psi", "psi", INCH**2 / POUND_FORCE)},
    "volume": {"si": OutputUnit("m³", "m3", 1.0), "field": OutputUnit("bbl", "bbl", 1 / BARREL)},
    "gas_volume": {"si": OutputUnit("m³", "m3", 1.0), "field": OutputUnit("ft³", "ft3", 1 / FOOT**3)},
    "area": {"si": OutputUnit("m²", "m2", 1.0), "field": OutputUnit("in²", "in2", 1 / INCH**2)},
    "flow_rate": {"si": OutputUnit("m³/d", "m3_d", 86400.0), "field": OutputUnit("bbl/d", "bbl_d", 86400.0 / BARREL)},
    "torque": {"si": OutputUnit("N·m", "n_m", 1.0), "field": OutputUnit("lbf·in", "lbf_in", 1 / (POUND_FORCE * INCH))},
    "percent": {"si": OutputUnit("%", "percent", 100.0), "field": OutputUnit("%", "percent", 100.0)},
    "ratio": {"si": OutputUnit("1", "", 1.0), "field": OutputUnit("1", "", 1.0)},
    "count": {"si": OutputUnit("1", "", 1.0), "field": OutputUnit("1", "", 1.0)},
    "power": {"si": OutputUnit("W", "w", 1.0), "field": OutputUnit("hp", "hp", 1 / HORSEPOWER)},
    "energy": {"si": OutputUnit("J", "j", 1.0), "field": OutputUnit("ft·lbf", "ft_lbf", 1 / (POUND_FORCE * FOOT))},
    "force_per_length": {"si": OutputUnit("N/m", "n_m", 1.0), "field": OutputUnit("lbf/ft", "lbf_ft", FOOT / POUND_FORCE)},
    # a hole's curvature [rad/m] as drillers give it: degrees per 30 m, degrees per 100 ft
    "dogleg_severity": {"si": OutputUnit("°/30 m", "deg_30m", 180 / math.pi * 30.0),
                        "field": OutputUnit("°/100 ft", "deg_100ft", 180 / math.pi * 100 * FOOT)},
    # a depth in a well: m, or feet as oilfield documents write it (a length on a unit is in inches)
    "depth": {"si": OutputUnit("m", "m", 1.0), "field": OutputUnit("ft", "ft", 1 / FOOT)},
    "density": {"si": OutputUnit("kg/m³", "kg_m3", 1.0), "field": OutputUnit("lb/ft³", "lb_ft3", FOOT**3 / POUND_MASS)},
    # energy per day (SI: J a day) in kWh a day in both systems, as electricity is billed
    "daily_energy": {"si": OutputUnit("kWh/d", "kwh_d", 1 / KWH), "field": OutputUnit("kWh/d", "kwh_d", 1 / KWH)},
    # money per day in the currency of the price given (--electricity-price)
    "daily_cost": {"si": OutputUnit("money/d", "per_day", 1.0), "field": OutputUnit("money/d", "per_day", 1.0)},
    "rotational_stiffness": {
        "si": OutputUnit("N·m/rad", "n_m_rad", 1.0),
        "field": OutputUnit("lbf·in/rad", "lbf_in_rad", 1 / (POUND_FORCE * INCH)),
    },
    "moment_of_inertia": {
        "si": OutputUnit("kg·m²", "kg_m2", 1.0),
        "field": OutputUnit("lb·ft²", "lb_ft2", 1 / (POUND_MASS * FOOT**2)),
    },
}

UNIT_SYSTEMS = ("si", "field")


def output_unit(quantity: str, system: str) -> OutputUnit:
    """The display unit of a quantity kind in a unit system (``"si"`` or ``"field"``)."""
    return OUTPUT_QUANTITIES[quantity][system]
