"""The own DOP853 integrator (pumpjack_cli.core.dynamics.dop853) against exact solutions,
against scipy's solve_ivp running the same method and step control, and on its event and
failure paths.

A tolerance-controlled method keeps each step's local error below rtol x the state's scale;
its global error over N steps is at most of order N x rtol (the errors add, and the
harmonic oscillator does not damp them). The bounds below are 100 x rtol for a few
dozen steps, which the method meets with a margin and a wrong coefficient (an order-5
method, a wrong error estimator, a dense output of lower order) misses by orders.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pumpjack_cli.core.dynamics.dop853 import integrate
from pumpjack_cli.errors import DynamicsError


def oscillator(t, y):
    """y = (cos t, -sin t): the undamped harmonic oscillator."""
    return y[1], -y[0]


@pytest.mark.parametrize("rtol", [1e-6, 1e-10])
def test_end_state_and_dense_output_match_the_exact_solution(rtol):
    run = integrate(oscillator, 0.0, 10.0, [1.0, 0.0], rtol, [rtol, rtol])
    assert run.stopped_at is None
    assert run.end[0] == pytest.approx(math.cos(10.0), abs=100 * rtol)
    assert run.end[1] == pytest.approx(-math.sin(10.0), abs=100 * rtol)
    t = np.linspace(0.0, 10.0, 1001)   # mostly inside steps: the order-7 extension is what is tested
    states = run.trajectory(t)
    assert states.shape == (2, t.size)
    assert np.max(np.abs(states[0] - np.cos(t))) < 100 * rtol
    assert np.max(np.abs(states[1] + np.sin(t))) < 100 * rtol


def test_tighter_tolerance_is_more_accurate_and_takes_more_steps():
    errors, evaluations = [], []
    for rtol in (1e-5, 1e-8, 1e-11):
        run = integrate(oscillator, 0.0, 10.0, [1.0, 0.0], rtol, [rtol, rtol])
        errors.append(abs(run.end[0] - math.cos(10.0)))
        evaluations.append(run.evaluations)
    assert errors[0] > errors[1] > errors[2]
    assert evaluations[0] < evaluations[1] < evaluations[2]


def test_relative_tolerance_on_growing_solution():
    """y' = y from 1 to e^20 ~ 5e8: the absolute tolerance alone could not reach it; rtol does."""
    rtol = 1e-9
    run = integrate(lambda t, y: (y[0],), 0.0, 20.0, [1.0], rtol, [1e-12])
    assert run.end[0] == pytest.approx(math.exp(20.0), rel=100 * rtol)
    assert run.trajectory(np.array([7.5]))[0, 0] == pytest.approx(math.exp(7.5), rel=100 * rtol)


def test_same_steps_and_values_as_scipy_dop853():
    """Same tableau, error norm, step control and initial step as scipy's DOP853: the two agree
    to rounding (a few machine epsilons a step over a few hundred steps), at the end, in the
    dense output and in the number of right-hand sides (scipy's count includes the continuous
    extension's three stages of every step; here they are evaluated only when the dense
    output is first asked for)."""
    from scipy.integrate import solve_ivp

    def pendulum(t, y):
        return y[1], -9.81 * math.sin(y[0]) - 0.3 * y[1] + math.cos(1.7 * t)

    rtol, atol = 1e-10, [1e-12, 1e-12]
    ours = integrate(pendulum, 0.0, 20.0, [2.5, 0.0], rtol, atol)
    ref = solve_ivp(pendulum, (0.0, 20.0), [2.5, 0.0], method="DOP853", rtol=rtol, atol=atol, dense_output=True)
    assert ref.success
    np.testing.assert_allclose(ours.end, ref.y[:, -1], rtol=1e-11, atol=1e-11)
    t = np.linspace(0.0, 20.0, 777)
    np.testing.assert_allclose(ours.trajectory(t), ref.sol(t), rtol=1e-11, atol=1e-11)
    steps = ref.t.size - 1
    assert ours.evaluations == ref.nfev - 3 * steps   # counted before the dense output was asked for


def test_event_stops_at_its_root():
    """cos t falls to 1/2 at t = pi/3: the root on the step's dense output, to the method's error."""
    rtol = 1e-10
    run = integrate(oscillator, 0.0, 10.0, [1.0, 0.0], rtol, [rtol, rtol], event=lambda t, y: y[0] - 0.5)
    assert run.stopped_at == pytest.approx(math.pi / 3.0, abs=100 * rtol)
    assert run.end[0] == pytest.approx(0.5, abs=100 * rtol)
    assert run.end[1] == pytest.approx(-math.sin(math.pi / 3.0), abs=100 * rtol)


def test_event_root_in_a_short_step_far_from_zero():
    """Steps shorter than 1e4 spacings of the floats at t (here h ~ 1e-3 at t ~ 1000, where
    the spacing is 1.1e-13): bisecting to 1e-12 of the step is below the float resolution, and
    the root must still be found, to the method's error, not looped on."""
    w, t0, rtol = 1000.0, 1000.0, 1e-10
    run = integrate(lambda t, y: (w * y[1], -w * y[0]), t0, t0 + 0.01, [1.0, 0.0], rtol, [rtol, rtol],
                    event=lambda t, y: y[0] - 0.5)
    assert run.stopped_at == pytest.approx(t0 + math.pi / 3.0 / w, abs=100 * rtol / w)
    assert run.end[0] == pytest.approx(0.5, abs=100 * rtol)


def test_event_that_never_changes_sign_does_not_stop():
    run = integrate(oscillator, 0.0, 10.0, [1.0, 0.0], 1e-8, [1e-8, 1e-8], event=lambda t, y: y[0] + 2.0)
    assert run.stopped_at is None
    assert run.end[0] == pytest.approx(math.cos(10.0), abs=1e-6)


def test_blow_up_is_an_error_not_a_number():
    """y' = y^2, y(0) = 1: y = 1/(1 - t) is infinite at t = 1; integrating past it must fail."""
    with pytest.raises(DynamicsError):
        integrate(lambda t, y: (y[0] * y[0],), 0.0, 2.0, [1.0], 1e-8, [1e-8])


def test_division_by_zero_in_the_right_hand_side_is_an_error():
    """Plain floats raise where numpy would give inf: y' = 1/y from y = 0 is refused by name."""
    with pytest.raises(DynamicsError, match="divides by zero at 0"):
        integrate(lambda t, y: (1.0 / y[0],), 0.0, 1.0, [0.0], 1e-8, [1e-8])
