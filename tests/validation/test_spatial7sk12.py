"""[Spatial7SK12]: the spatial six-link mechanism of 7SK12-2,5-5600 and what the paper publishes.

Source: [Spatial7SK12], kinematic and kinetostatic research of the spatial six-link lever
mechanism of a pumping-unit drive with and without redundant constraints, unit
7SK12-2,5-5600. Checked here: its fig. 10 (without redundant constraints the two identical
sides share the load: R12 = R13, no z-components) on every bundled beam unit, and the pitman
section it gives (E = 2.1·10¹¹ Pa, J_z = 17.61·10⁻⁶ m⁴) as the bundled unit file holds it.
Its differences between the real and the rational mechanism are discussed, not reproduced,
in docs/redundancy.md (the unit's geometry and card are estimated).
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.kinetostatics import rational_mechanism

from helpers import BEAM_UNITS


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_identical_sides_share_the_load(name):
    """Fig. 10: without redundant constraints R12 = R13 and z-components vanish (1e-9 of the
    load: round-off of the 3-D block elimination), under a smooth card-like load."""
    config = load_unit(name)
    spatial, m = config.geometry.spatial(name), config.masses.model()
    theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    load = 50e3 + 15e3 * np.sin(theta) + 5e3 * np.cos(2 * theta)
    _, r = rational_mechanism(spatial, m, theta, 1.2, 0.1, load)
    scale = np.max(load)
    assert np.max(np.abs(r.r12 - r.r13)) < 1e-9 * scale
    for vector in (r.r12, r.r13, r.r24, r.r34, r.r45, r.r05, r.r01):
        assert np.max(np.abs(vector[:, 2])) < 1e-9 * scale
    # R24 and R34 mirror each other: same x, y; the equalizer pulls its pins apart or together.
    assert np.max(np.abs(r.r24[:, :2] - r.r34[:, :2])) < 1e-9 * scale
    assert np.max(np.abs(r.m05)) < 1e-9 * scale
    assert np.max(r.residual) < 1e-9


def test_pitman_section_is_the_papers():
    """E = 2.1e11 Pa and J_z = 17.61e-6 m^4 as the paper gives them; the file writes them as
    "210 GPa" and "1761 cm4", so 1e-12 relative covers the unit conversion's round-off."""
    section = load_unit("7sk12-2.5-5600").pitman_section
    assert section.youngs_modulus == pytest.approx(2.1e11, rel=1e-12)
    assert section.inplane_inertia == pytest.approx(17.61e-6, rel=1e-12)
