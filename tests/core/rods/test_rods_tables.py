"""Rod tables and the rod string: names, building, sinker and fibreglass sections, errors, static
tension, travel time and damping.

The tables' published data ([API11L] Table 4.1 and its wave speeds and buoyancy, [API11B] sizes
and grades) are checked in tests/validation/test_api_rp11l.py and test_api11b.py.
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.constants import STEEL_DENSITY
from pumpjack_cli.core.rods.string import RodString
from pumpjack_cli.core.rods.tables import RodSection, rod_string, steel_rod, tensile_strength
from pumpjack_cli.errors import DownholeError, PumpjackError

from helpers import FOOT, INCH, POUND_FORCE, POUND_MASS


def test_metric_designations_match_the_inch_sizes():
    for millimetres, name in ((16, "5/8 in"), (19, "3/4 in"), (22, "7/8 in"), (25, "1 in"), (29, "1-1/8 in")):
        assert steel_rod(millimetres * 1e-3).name == name


@pytest.mark.parametrize("diameter", [0.020, 0.035, np.nan])
def test_unknown_diameter_lists_the_table(diameter):
    with pytest.raises(DownholeError) as error:
        steel_rod(diameter)
    message = str(error.value)
    assert "no API steel sucker rod of diameter" in message
    assert ("5/8 in (15.875 mm), 3/4 in (19.050 mm), 7/8 in (22.225 mm), 1 in (25.400 mm), "
            "1-1/8 in (28.575 mm)") in message
    assert "\n" not in message


def test_rod_string_from_sections_sk8_well():
    # seed 004: 1530 m, 19 mm (51 %), 22 mm (26 %), 25 mm (23 %), largest at the top
    depth = 1530.0
    string = rod_string([RodSection(0.025, 0.23 * depth, grade="D"), RodSection(0.022, 0.26 * depth, grade="D"),
                         RodSection(0.019, 0.51 * depth, grade="D")])
    assert string.names == ("1 in D", "7/8 in D", "3/4 in D")
    assert string.total_length == pytest.approx(depth)
    # weight in air, hand sum of 2.904/2.224/1.634 lb/ft over the lengths in ft
    pounds = (2.904 * 0.23 + 2.224 * 0.26 + 1.634 * 0.51) * depth / FOOT
    assert string.weight_in_air(1.0) == pytest.approx(pounds * POUND_MASS)
    assert np.all(string.tensile_strength == tensile_strength("D"))
    # spring constant from RP 11L: 1/k_r = sum E_r,i L_i (E_r in in/(lb ft), L in ft)
    stretch = (0.497 * 0.23 + 0.649 * 0.26 + 0.883 * 0.51) * 1e-6 * depth / FOOT   # in/lb
    assert string.spring_constant == pytest.approx(1.0 / (stretch * INCH / POUND_FORCE), rel=1e-12)


def test_rod_string_with_sinker_and_fibreglass_sections():
    string = rod_string([RodSection(0.0254, 800.0, kind="fibreglass", youngs_modulus=48e9, mass_per_length=1.1,
                                    tensile_strength=600e6),
                         RodSection(0.022, 500.0), RodSection(0.0381, 100.0, kind="sinker")])
    assert string.youngs_modulus[0] == 48e9 and string.mass_per_length[0] == 1.1
    # fibreglass displaces its body volume: density m / A
    assert string.material_density[0] == pytest.approx(1.1 / (np.pi * 0.0254**2 / 4))
    assert string.material_density[1:] == pytest.approx([STEEL_DENSITY, STEEL_DENSITY])
    assert string.tensile_strength[0] == 600e6 and np.isnan(string.tensile_strength[1:]).all()
    assert string.names[2] == "1-1/2 in sinker bar"


@pytest.mark.parametrize("section, message", [
    (RodSection(0.0254, 100.0, kind="fibreglass"), "needs its Young's modulus and mass per length"),
    (RodSection(0.022, 100.0, kind="wood"), "unknown kind 'wood'; kinds: steel, sinker, fibreglass"),
    (RodSection(0.022, 100.0, grade="D", tensile_strength=8e8), "a grade or a tensile strength, not both"),
    (RodSection(0.022, -5.0), "length of section 1 must be finite and positive"),
    (RodSection(0.022, 100.0, mass_per_length=np.nan), "mass_per_length of section 1 must be finite"),
])
def test_bad_sections_raise_one_line(section, message):
    with pytest.raises(DownholeError, match=message) as error:
        rod_string([section])
    assert isinstance(error.value, PumpjackError) and "\n" not in str(error.value)


def test_rod_string_validation():
    with pytest.raises(DownholeError, match="area has 1 values for 2 sections"):
        RodString([1.0, 2.0], [1.0], [1.0, 1.0], [1.0, 1.0])
    with pytest.raises(DownholeError, match="a rod string needs at least one section"):
        rod_string([])
    with pytest.raises(DownholeError, match="fluid density"):
        RodString([1.0], [1.0], [1.0], [1.0]).buoyant_weight(-1.0)
    fibreglass = RodString([1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], material_density=[7800.0, 1900.0])
    with pytest.raises(DownholeError, match="not below the density of rod section 2, 1900 kg/m.3: the rods would float"):
        fibreglass.buoyant_weight(2000.0)


def test_static_tension_and_reversal():
    string = RodString([100.0, 200.0], [1e-4, 2e-4], [2e11, 2e11], [3.0, 2.0], material_density=[6000.0, 8000.0])
    q = 9.81 * np.array([3.0 * (1 - 1000 / 6000), 2.0 * (1 - 1000 / 8000)])   # N/m, hand values
    assert string.static_tension(1000.0, 9.81) == pytest.approx([100 * q[0] + 200 * q[1], 200 * q[1], 0.0])
    assert string.depth == pytest.approx([0.0, 100.0, 300.0])
    back = string.reversed()
    assert back.length == pytest.approx([200.0, 100.0]) and back.material_density == pytest.approx([8000, 6000])


def test_travel_time_average_speed_and_damping():
    string = RodString([1000.0, 500.0], [1.0, 1.0], [4000.0**2, 5000.0**2], [1.0, 1.0])
    assert string.travel_time == pytest.approx(0.25 + 0.1)
    assert string.mean_wave_speed == pytest.approx(1500.0 / 0.35)
    # c = pi a nu / (2 L): the first fixed-free natural frequency pi a / (2 L) times nu
    assert string.damping_coefficient(0.2) == pytest.approx(0.2 * np.pi / (2 * 0.35))
