"""[API11B]: the sizes of the API sinker bars and the minimum tensile strength of the rod grades.

Source: API Spec 11B [API11B] (sinker bars of 1-1/4 to 2 in) and its grades K, C and D as
PetroWiki states them [PetroWikiRods]: 90 000, 90 000 and 115 000 psi.
"""

from __future__ import annotations

import pytest

from pumpjack_cli.core.rods.string import STEEL_YOUNGS_MODULUS
from pumpjack_cli.core.rods.tables import SINKER_BARS, mass_per_length, sinker_bar, tensile_strength
from pumpjack_cli.errors import DownholeError

from helpers import INCH, PSI


def test_sinker_bars_are_solid_steel_of_the_api_sizes():
    sizes = [1.25, 1.375, 1.5, 1.625, 1.75, 2.0]
    assert [bar.diameter for bar in SINKER_BARS] == pytest.approx([d * INCH for d in sizes])
    bar = sinker_bar(1.5 * INCH)
    # hand calculation: 7850 kg/m^3 * pi * 0.0381^2 / 4 = 8.950 kg/m, i.e. 6.01 lb/ft
    assert bar.mass_per_length == pytest.approx(8.950, abs=1e-3)
    assert bar.youngs_modulus == STEEL_YOUNGS_MODULUS
    assert mass_per_length(1.5 * INCH, kind="sinker") == bar.mass_per_length


def test_grade_strengths():
    # PetroWiki "Sucker rods", after API Spec 11B: K and C 90 000 psi, D 115 000 psi minimum.
    assert tensile_strength("K") == pytest.approx(90_000 * PSI)
    assert tensile_strength("c") == pytest.approx(90_000 * PSI)
    assert tensile_strength(" D ") == pytest.approx(115_000 * PSI)
    with pytest.raises(DownholeError, match="unknown rod grade 'X'; known grades: K, C, D"):
        tensile_strength("X")
