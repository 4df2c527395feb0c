"""The pump card of a deviated well: Everitt & Jennings' march with gravity along the hole and Coulomb
drag (core/rods/deviated_diagnostic.py), against the vertical march, closed forms and the energy balance."""

from __future__ import annotations

import numpy as np
import pytest

from pumpjack_cli.core.rods import everitt_jennings
from pumpjack_cli.core.rods.analysis import card_work
from pumpjack_cli.core.rods.deviated import grid_segments, string_grid
from pumpjack_cli.core.rods.deviated_diagnostic import deviated_pump_card, march
from pumpjack_cli.core.rods.downhole import pump_card, surface_card
from pumpjack_cli.core.rods.path import VerticalPath
from pumpjack_cli.core.rods.survey_path import SurveyPath

RHO = 820.0
N = 200


@pytest.fixture(scope="module")
def surface(sk8_rods):
    """A realistic surface card of the SK8 rods: a full-pump card pushed up the vertical string."""
    period = 5.5
    t = np.arange(N) / N
    plunger = 1.4 * (1 - np.cos(2 * np.pi * t))
    load = 13e3 * (1 + np.tanh(8 * np.sin(2 * np.pi * t))) / 2
    up = surface_card(sk8_rods, period, plunger, load, fluid_density=RHO, damping_factor=0.05, method="gibbs")
    return period, up.surface_position, up.surface_load


def test_a_vertical_hole_is_the_vertical_march_even_with_friction(sk8_rods, surface):
    """N = 0 in a vertical hole: no drag whatever mu, and term by term the march of everitt_jennings."""
    period, position, load = surface
    vertical = pump_card(sk8_rods, period, position, load, fluid_density=RHO, damping_factor=0.05,
                         method="everitt-jennings")
    found = deviated_pump_card(sk8_rods, VerticalPath(), period, position, load, fluid_density=RHO,
                               damping_factor=0.05, friction_coefficient=0.3,
                               segments=everitt_jennings.segments(sk8_rods, period / N))
    scale = np.ptp(vertical.pump_load)
    assert np.max(np.abs(found.card.pump_load - vertical.pump_load)) < 1e-9 * scale
    assert np.max(np.abs(found.card.pump_position - vertical.pump_position)) < 1e-12
    # at the tapers' joints: the node's tension (its cell's mean) against the lower face's, half a cell apart
    assert np.max(np.abs(found.card.joint_load[1:-1] - vertical.joint_load[1:-1])) < 0.05 * scale
    assert found.friction_work == 0.0 and found.card.buoyant_weight == pytest.approx(vertical.buoyant_weight, 1e-12)


def test_a_slant_without_friction_moves_only_the_datum(sk8_rods, surface):
    """Along a straight hole at phi the rods weigh W cos(phi) along it: with mu = 0 the dynamic loads,
    hence the pump card, are the vertical hole's for the card raised by W_rf (1 - cos phi)."""
    period, position, load = surface
    phi = np.radians(35.0)
    slant = SurveyPath(np.array([0.0, 2000.0]), np.array([phi, phi]), np.zeros(2))
    found = deviated_pump_card(sk8_rods, slant, period, position, load, fluid_density=RHO, damping_factor=0.05,
                               friction_coefficient=0.0)
    weight = sk8_rods.buoyant_weight(RHO)
    assert found.grid.hanging_weight == pytest.approx(weight * np.cos(phi), rel=1e-12)
    segments = found.grid.joints[1:] - found.grid.joints[:-1]
    vertical = deviated_pump_card(sk8_rods, VerticalPath(), period, position, load + weight * (1 - np.cos(phi)),
                                  fluid_density=RHO, damping_factor=0.05, friction_coefficient=0.0, segments=segments)
    assert np.max(np.abs(found.card.pump_load - vertical.card.pump_load)) < 1e-8 * np.ptp(load)
    assert found.friction_work == 0.0
    assert np.max(found.profile.max_side_load) == pytest.approx(
        float(sk8_rods.buoyant_weight_per_length(RHO).max()) * np.sin(phi), rel=0.05)  # q sin(phi) + T phi' = 0


def test_the_surface_work_goes_to_the_pump_the_damping_and_the_drag(sk8_rods, surface):
    """Every relation of the march is a force balance, so per cycle surface work = pump work + damping
    dissipation + drag work: exactly (to rounding) with the works the march's own central
    differences define, sum F v dt, and to O(dt^2) with the cards' areas (the trigonometric
    interpolant's work, card_work)."""
    period, position, load = surface
    path = SurveyPath(np.array([0.0, 400.0, 850.0, 2000.0]), np.radians([0.0, 0.0, 40.0, 40.0]), np.zeros(4))
    residuals = []
    for k in (1, 2):
        samples = N * k
        fine_t = np.arange(samples) / samples
        spectrum = np.fft.rfft(position), np.fft.rfft(load + 3e3)
        pos, ld = (np.fft.irfft(x, samples) * k for x in spectrum)  # the same band-limited card, finer sampled
        dt = period / samples
        grid = string_grid(sk8_rods, path, grid_segments(sk8_rods, dt), fluid_density=RHO, damping_factor=0.1)
        result = march(grid, period, pos, ld - grid.hanging_weight, 0.2, 0.01 * 1.0)
        v = result["velocity"]
        damping = grid.damping * float(np.sum(grid.node_mass[:, None] * v * v)) * dt
        drag = float(np.sum(result["drag"] * v)) * dt
        top_velocity = (np.roll(pos, -1) - np.roll(pos, 1)) / (2 * dt)
        surface_work = float(np.sum(ld * top_velocity)) * dt
        pump_work = float(np.sum(result["pump_load"] * v[-1])) * dt
        assert surface_work - pump_work - damping - drag == pytest.approx(0.0, abs=1e-12 * surface_work)
        assert drag > 0.2 * surface_work and damping > 0
        areas = float(card_work(pos, ld)) - float(card_work(result["position"][-1], result["pump_load"]))
        residuals.append((areas - damping - drag) / float(card_work(pos, ld)))
        del fine_t
    assert abs(residuals[0]) < 1e-3 and 3.0 < residuals[0] / residuals[1] < 5.0  # second order
