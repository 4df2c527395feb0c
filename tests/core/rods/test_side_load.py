"""The soft-string side load N = sqrt((T phi' - q sin phi)^2 + (T psi' sin phi)^2) ([JohancsikSPE11380]):
its sign proved by the force balance of a string hanging in a curved hole, and the grid's cell
integral of it (core/rods/deviated.py) against the formula.

The balance is independent of the formula: the hole is cut into short straight chords, each
carrying a tension along itself; at a node the two chords' pulls and the node's share of the
buoyed weight leave a resultant that the wall must take; its part across the hole, per length
of hole, is the side load. A formula written with + q sin(phi) (phi' measured going up) or
without the weight misses it by far more than the chords' error.
"""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.rods.deviated import side_load_per_length, string_grid
from pumpjack_cli.core.rods.string import RodString
from pumpjack_cli.core.rods.survey_path import SurveyPath

DOWN = np.array([0.0, 0.0, 1.0])  # (north, east, down)


def _wall_force(path: SurveyPath, s: np.ndarray, tension, weight: float) -> tuple[np.ndarray, np.ndarray]:
    """Across-the-hole wall force per length on the string at the inner nodes of ``s`` (equal steps),
    from the chords' tensions and the weight: what holds the string in the hole. Also the tangents."""
    points = path.position(s)
    chords = np.diff(points, axis=0)
    pull = tension(0.5 * (s[1:] + s[:-1]))[:, None] * chords / np.linalg.norm(chords, axis=1)[:, None]
    ds = s[1] - s[0]
    wall = -(pull[1:] - pull[:-1] + weight * ds * DOWN)
    t = path.tangent(s[1:-1])
    across = wall - np.sum(wall * t, axis=1)[:, None] * t
    return across / ds, t


@pytest.mark.parametrize("tension_at_top", [60e3, 2e3])  # tension's pull outweighs the weight, then the other way
def test_force_balance_on_a_build_proves_the_sign(tension_at_top):
    """A 3 deg/30 m build from vertical to 60 deg, q = 25 N/m, the tension falling along the hole."""
    kappa = np.radians(3.0) / 30.0
    path = SurveyPath(np.array([0.0, 600.0]), np.radians([0.0, 60.0]), np.zeros(2))
    q = 25.0

    def tension(s):
        return tension_at_top - 20.0 * s

    s = np.linspace(0.0, 600.0, 6001)
    across, t = _wall_force(path, s, tension, q)
    inner = s[1:-1]
    phi = path.inclination(inner)
    found = np.linalg.norm(across, axis=1)
    formula = side_load_per_length(tension(inner), q, phi, path.inclination_rate(inner), path.azimuth_rate(inner))
    assert np.allclose(formula[200:-200], found[200:-200], rtol=2e-4, atol=1e-6)
    wrong = np.abs(tension(inner) * kappa + q * np.sin(phi))  # phi' measured going up
    assert np.max(np.abs(wrong - found)[200:-200] / found[200:-200]) > 0.1
    # and which wall: the high side (e_phi, up across the hole) while T phi' < q sin(phi), else the low side
    high = np.cross(np.cross(t, DOWN * -1.0), t)  # up, less its part along the hole
    high /= np.linalg.norm(high, axis=1)[:, None]
    pushes_up = np.sum(across * high, axis=1) > 0
    assert np.array_equal(pushes_up[200:-200], (tension(inner) * kappa < q * np.sin(phi))[200:-200])


def test_force_balance_on_a_turn_gives_the_binormal_term():
    """At 60 deg of inclination turning 4 deg/30 m of azimuth (stations every 5 m, minimum
    curvature), phi' = 0 and N = sqrt((q sin phi)^2 + (T psi' sin phi)^2)."""
    depth = np.arange(0.0, 605.0, 5.0)
    path = SurveyPath(depth, np.radians(np.where(depth > 0, 60.0, 60.0)), np.radians(4.0 / 30.0 * depth))
    q = 25.0

    def tension(s):
        return 40e3 - 10.0 * s

    s = np.linspace(100.0, 500.0, 4001)
    across, _ = _wall_force(path, s, tension, q)
    inner = s[1:-1]
    formula = side_load_per_length(tension(inner), q, path.inclination(inner), path.inclination_rate(inner),
                                   path.azimuth_rate(inner))
    assert np.allclose(formula, np.linalg.norm(across, axis=1), rtol=1e-3)
    without = q * np.sin(path.inclination(inner))  # the weight alone
    assert np.min(formula / without) > 2.0


def test_the_grid_integrates_the_formula_over_its_cells():
    """N_i l_i of the grid's cells over l_i tends to the formula at the nodes as the cells shrink."""
    path = SurveyPath(np.array([0.0, 300.0, 750.0, 1200.0]), np.radians([0.0, 0.0, 45.0, 70.0]),
                      np.radians([0.0, 0.0, 20.0, 60.0]))
    rods = RodString([1200.0], [2.85e-4], [2.05e11], [2.4])
    q = float(rods.buoyant_weight_per_length(850.0)[0])
    errors = []
    for segments in (60, 240):
        grid = string_grid(rods, path, np.array([segments]), fluid_density=850.0, damping_factor=0.1)
        tension = 30e3 - 20.0 * grid.depth
        inner = slice(1, -1)
        d = grid.depth[inner]
        cell = grid.side_force(tension)[inner] / grid.cell_length[inner]
        formula = side_load_per_length(tension[inner], q, path.inclination(d), path.inclination_rate(d),
                                       path.azimuth_rate(d))
        away = (d > 330.0) & (np.abs(d - 750.0) > 30.0)  # below the vertical part; the curvature jumps at stations
        errors.append(np.max(np.abs(cell - formula)[away] / formula[away]))
        # the weight along the hole: the cells' sum is int q cos(phi) ds
        fine = np.linspace(0.0, 1200.0, 120001)
        exact = q * np.trapezoid(np.cos(path.inclination(fine)), fine)
        assert grid.hanging_weight == pytest.approx(exact, rel=1e-6)
    assert errors[1] < 1e-3 and errors[1] < errors[0] / 10
