"""Predicted cards of a deviated well (core/rods/deviated_predict.py): the time march against the modal
solution of a vertical hole, the closed forms of a slow straight slant, the quasi-static drag equation of
a J-shaped hole (capstan included), the energy balance and the drag's regularisation."""

from __future__ import annotations

import importlib.util

import numpy as np
import pytest

from pumpjack_cli.core.beam.geometry import Linkage
from pumpjack_cli.core.rods.deviated import side_load_per_length
from pumpjack_cli.core.rods.deviated_predict import Alpha, predict_deviated
from pumpjack_cli.core.rods.path import VerticalPath
from pumpjack_cli.core.rods.predict import predict
from pumpjack_cli.core.rods.pump import Pump, pump_pressures
from pumpjack_cli.core.rods.string import RodString
from pumpjack_cli.core.rods.survey_path import SurveyPath

from helpers import REPO_ROOT, SK8_LINKAGE

RHO = 820.0


def _j_hole() -> SurveyPath:
    """The J-shaped hole of samples/make_deviated.py (vertical to 500 m, 3 deg/30 m to 45 deg, hold)."""
    spec = importlib.util.spec_from_file_location("make_deviated", REPO_ROOT / "samples" / "make_deviated.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.path()


def _slow(linkage: Linkage, samples: int, spm: float = 0.1) -> tuple[np.ndarray, float]:
    """The polished rod's position over one cycle at ``spm`` strokes per minute, and the period."""
    theta = np.arange(samples) * 2 * np.pi / samples
    return linkage.rod_position(theta), 60.0 / spm


def test_generalized_alpha_parameters():
    """[ChungHulbert1993]: rho_inf = 1 is the trapezoidal rule (alpha_m = alpha_f = 1/2, beta = 1/4, gamma = 1/2);
    rho_inf = 0 annihilates the highest modes in one step (alpha_m = -1, alpha_f = 0, beta = 1, gamma = 3/2)."""
    assert Alpha.of(1.0) == Alpha(0.5, 0.5, 0.5, 0.25)
    assert Alpha.of(0.0) == Alpha(-1.0, 0.0, 1.5, 1.0)


def test_a_vertical_hole_marched_in_time_is_the_modal_solution(sk8_rods, sk8_pump):
    """Two independent solvers of the same rods and pump (exact modal steps; finite differences in
    space and generalized-alpha in time): at 1024 steps per cycle the loads agree to the time march's
    resolution of the valve events (first order in the step: 7.6, 3.6, 1.9, 1.1 % of F_o rms at 256 ..
    2048 steps, docs/deviated.md), the works to 0.1 %."""
    position = SK8_LINKAGE.rod_position(np.arange(1024) * 2 * np.pi / 1024)
    period = 2 * np.pi / 1.1422
    modal = predict(sk8_rods, sk8_pump, position, period, damping=0.1, fluid_density=RHO)
    marched = predict_deviated(sk8_rods, VerticalPath(), sk8_pump, position, period, damping=0.1, fluid_density=RHO,
                               friction_coefficient=0.3)
    a, b = modal.summary, marched.cards.summary
    f_o = sk8_pump.fluid_load
    assert b.peak_polished_rod_load.value == pytest.approx(a.peak_polished_rod_load.value, rel=0.005)
    assert b.minimum_polished_rod_load.value == pytest.approx(a.minimum_polished_rod_load.value, rel=0.01)
    assert np.sqrt(np.mean((marched.cards.polished_rod_load - modal.polished_rod_load) ** 2)) < 0.025 * f_o
    assert b.pump_card_work == pytest.approx(a.pump_card_work, rel=1e-3)
    assert b.surface_card_work == pytest.approx(a.surface_card_work, rel=1e-3)
    assert marched.friction_work == 0.0 and abs(b.energy_residual) < 1e-5
    assert b.buoyant_rod_weight == pytest.approx(sk8_rods.buoyant_weight(RHO), rel=1e-12)


@pytest.mark.parametrize("mu", [0.0, 0.25])
def test_a_slow_straight_slant_carries_weight_along_it_and_drag_across(mu):
    """3/4 in rods on a 40 deg slant from the surface, 0.1 strokes/min: the rods slide up with the
    fluid load on the plunger, PPRL = q L cos(phi) + F_o + mu q L sin(phi), and down without it,
    MPRL = q L cos(phi) - mu q L sin(phi), F_o from the pressures at the pump's true vertical depth."""
    phi, length = np.radians(40.0), 1200.0
    area = np.pi * 0.01905**2 / 4
    rods = RodString([length], [area], [2.04e11], [2.4317])
    path = SurveyPath(np.array([0.0, 2000.0]), np.array([phi, phi]), np.zeros(2))
    discharge, intake = pump_pressures(length * np.cos(phi), RHO, submergence=50.0)
    pump = Pump(np.pi * 0.0381**2 / 4, discharge, intake)
    q = float(rods.buoyant_weight_per_length(RHO)[0])
    position, period = _slow(SK8_LINKAGE, 256)
    found = predict_deviated(rods, path, pump, position, period, damping=0.1, fluid_density=RHO,
                             friction_coefficient=mu, regularisation=0.001)
    s = found.cards.summary
    assert s.fluid_load == pytest.approx(RHO * 9.80665 * (length * np.cos(phi) - 50.0) * pump.plunger_area, rel=1e-12)
    assert s.peak_polished_rod_load.value == pytest.approx(
        q * length * np.cos(phi) + s.fluid_load + mu * q * length * np.sin(phi), rel=0.01)
    assert s.minimum_polished_rod_load.value == pytest.approx(
        q * length * np.cos(phi) - mu * q * length * np.sin(phi), rel=0.01)
    assert (found.friction_work == 0.0) == (mu == 0.0)


@pytest.fixture(scope="module")
def j_hole():
    return _j_hole()


def _drag_equation(rods: RodString, path, at_pump: float, mu: float, sign: float, step: float = 1.0) -> float:
    """The quasi-static drag equation dT/ds = -q cos(phi) - sign mu N(T) integrated up the hole from the
    pump's load (sign +1 for rods sliding up, -1 down) by the classical Runge-Kutta rule, N the
    soft-string side load ([JohancsikSPE11380]): the polished-rod load of a string sliding as a whole,
    with the capstan effect of every bend."""
    q = rods.buoyant_weight_per_length(RHO)
    length = rods.total_length
    s = np.linspace(length, 0.0, int(round(length / (0.5 * step))) + 1)  # the steps' ends and midpoints
    phi, rate_phi, rate_psi = path.inclination(s), path.inclination_rate(s), path.azimuth_rate(s)
    w = q[np.minimum(np.searchsorted(np.cumsum(rods.length), s), q.size - 1)]
    h = s[2] - s[0]

    def slope(k: int, tension: float) -> float:
        n = side_load_per_length(tension, w[k], phi[k], rate_phi[k], rate_psi[k])
        return -w[k] * np.cos(phi[k]) - sign * mu * float(n)

    tension = at_pump
    for k in range(0, s.size - 2, 2):
        k1 = slope(k, tension)
        k2 = slope(k + 1, tension + 0.5 * h * k1)
        k3 = slope(k + 1, tension + 0.5 * h * k2)
        k4 = slope(k + 2, tension + h * k3)
        tension += h * (k1 + 2 * k2 + 2 * k3 + k4) / 6
    return tension


def test_a_slow_j_shaped_well_follows_the_drag_equation_with_its_capstan(sk8_rods, j_hole):
    """The SK8 rods in the J-shaped hole at 0.1 strokes/min, mu = 0.3: PPRL and MPRL within 1 % of the
    drag equation integrated along the hole (the drag adds 8.4 kN to the frictionless 48.0 kN and
    takes 4.0 kN off the 36.9 kN, the build's capstan included)."""
    discharge, intake = pump_pressures(float(j_hole.vertical_depth(1530.0)), RHO, submergence=100.0)
    pump = Pump(np.pi * 0.038**2 / 4, discharge, intake)
    position, period = _slow(SK8_LINKAGE, 256)
    found = predict_deviated(sk8_rods, j_hole, pump, position, period, damping=0.1, fluid_density=RHO,
                             friction_coefficient=0.3, regularisation=0.001)
    s = found.cards.summary
    up = _drag_equation(sk8_rods, j_hole, pump.fluid_load, 0.3, +1.0)
    down = _drag_equation(sk8_rods, j_hole, 0.0, 0.3, -1.0)
    assert up - _drag_equation(sk8_rods, j_hole, pump.fluid_load, 0.0, +1.0) > 8e3
    assert s.peak_polished_rod_load.value == pytest.approx(up, rel=0.01)
    assert s.minimum_polished_rod_load.value == pytest.approx(down, rel=0.01)
    assert abs(s.energy_residual) < 1e-4


def test_the_drag_converges_as_its_regularisation_vanishes(sk8_rods, j_hole):
    """The sign function's band (eta times the polished rod's peak speed) shrinking by 3 at a time: the
    loads' changes shrink with it (held rods creep by at most the band)."""
    discharge, intake = pump_pressures(float(j_hole.vertical_depth(1530.0)), RHO, submergence=100.0)
    pump = Pump(np.pi * 0.038**2 / 4, discharge, intake)
    position, period = _slow(SK8_LINKAGE, 128, spm=2.0)
    loads = [predict_deviated(sk8_rods, j_hole, pump, position, period, damping=0.1, fluid_density=RHO,
                              friction_coefficient=0.2, regularisation=eta).cards.polished_rod_load
             for eta in (0.09, 0.03, 0.01, 0.0033)]
    changes = [float(np.sqrt(np.mean((b - a) ** 2))) for a, b in zip(loads, loads[1:])]
    assert changes[2] < changes[1] < changes[0] and changes[2] < 0.01 * pump.fluid_load
