"""Dormand and Prince's Runge-Kutta pair of orders 8(5,3) with its dense output of order 7,
for the few states of the machine's equation of motion.

The method of Hairer's code DOP853 ([HairerNorsettWanner1993] sec. II.5 and II.6: twelve
stages, a fifth- and a third-order error estimate combined into one error norm, three
more stages for the continuous extension), with the step-size control and initial step of
the same book (sec. II.4: safety 0.9, step factor between 0.2 and 10, the error exponent
-1/8), as scipy's ``solve_ivp(method="DOP853")`` runs it; the tableau is the one scipy
publishes as the attributes of its ``scipy.integrate.DOP853`` class. The difference is
the arithmetic: a state of three numbers is stepped in plain floats, not in numpy arrays
of three elements, whose every operation costs a microsecond of dispatch (with scipy's
stepper one periodic solve took about twice as long: docs/performance.md). The continuous
extension is made only when it is asked for, so that the shots of a shooting that are not
kept never pay its three extra stages. The twelve stages of a step are one function made
for the number of states (:func:`_stepper`), its stage combinations written out.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

from ...errors import DynamicsError

#: Right-hand side f(t, y) of y' = f(t, y): the derivatives of the state, as many as y has.
RightHandSide = Callable[[float, Sequence[float]], Sequence[float]]

#: Step-size control ([HairerNorsettWanner1993] sec. II.4).
SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0
#: The error estimate is of order 7: the step scales as error^(-1/8).
EXPONENT = -1.0 / 8.0


@dataclass(frozen=True)
class _Tableau:
    """The coefficients as plain lists: the stages' rows of A (each as long as the stages before
    it), C, the weights B, the two error estimators, and the continuous extension's rows."""

    a: tuple[tuple[float, ...], ...]
    c: tuple[float, ...]
    b: tuple[float, ...]
    e3: tuple[float, ...]
    e5: tuple[float, ...]
    extra_a: tuple[tuple[float, ...], ...]
    extra_c: tuple[float, ...]
    d: tuple[tuple[float, ...], ...]


@cache
def _tableau() -> _Tableau:
    """scipy's DOP853 coefficients (imported when the first integration runs)."""
    from scipy.integrate import DOP853

    stages = int(DOP853.n_stages)
    return _Tableau(
        a=tuple(tuple(DOP853.A[s, :s].tolist()) for s in range(stages)),
        c=tuple(DOP853.C.tolist()),
        b=tuple(DOP853.B.tolist()),
        e3=tuple(DOP853.E3.tolist()),
        e5=tuple(DOP853.E5.tolist()),
        extra_a=tuple(tuple(DOP853.A_EXTRA[r, :stages + 1 + r].tolist()) for r in range(len(DOP853.C_EXTRA))),
        extra_c=tuple(DOP853.C_EXTRA.tolist()),
        d=tuple(tuple(row) for row in DOP853.D.tolist()),
    )


class Trajectory:
    """The dense solution of one integration: the state at any t of its interval, vectorised.

    Each step keeps its start, length, start state, end state and stage derivatives; the
    interpolation coefficients of the continuous extension are made, for all steps at once,
    at the first call (three right-hand sides a step, of ``rhs``, which counts them)."""

    def __init__(self, rhs: RightHandSide):
        self._rhs = rhs
        self._steps: list[tuple[float, float, list[float], list[float], list[list[float]]]] = []
        self._table: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = None

    def add(self, t: float, h: float, y: list[float], y_new: list[float], columns: list[list[float]]) -> None:
        self._steps.append((t, h, y, y_new, columns))

    def _coefficients(self, t: float, h: float, y: list[float], y_new: list[float],
                      columns: list[list[float]]) -> list[list[float]]:
        """F_0 .. F_6 of one step, by component (the extension's three stages evaluated)."""
        return _extension(len(y))(self._rhs, t, h, y, y_new, columns)

    def _tabled(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        if self._table is None:
            starts = np.array([s[0] for s in self._steps])
            lengths = np.array([s[1] for s in self._steps])
            states = np.array([s[2] for s in self._steps])
            coefficients = np.array([self._coefficients(*s) for s in self._steps])   # (steps, states, 7)
            self._table = starts, lengths, states, coefficients
        return self._table

    def in_last_step(self) -> Callable[[float], list[float]]:
        """The state at any t of the last step (its coefficients made once; for an event's root)."""
        start, h, y, y_new, columns = self._steps[-1]
        coefficients = self._coefficients(start, h, y, y_new, columns)
        table = (np.array([start]), np.array([h]), np.array([y]), np.array([coefficients]))
        return lambda t: _dense(*table, np.array([t]))[:, 0].tolist()

    def __call__(self, t: np.ndarray) -> np.ndarray:
        """The states at ``t`` (any shape (N,)), shape (states, N)."""
        return _dense(*self._tabled(), np.asarray(t, dtype=float))


def _dense(starts: np.ndarray, lengths: np.ndarray, states: np.ndarray, coefficients: np.ndarray,
           t: np.ndarray) -> np.ndarray:
    """The continuous extension at ``t`` (N,) from the steps' starts, lengths, start states and
    coefficients F_0 .. F_6 (steps, states, 7): y0 + x(F0 + (1-x)(F1 + x(F2 + (1-x)(...)))),
    x the fraction of the step ([HairerNorsettWanner1993] sec. II.6); shape (states, N)."""
    i = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, starts.size - 1)
    x = ((t - starts[i]) / lengths[i])[:, None]
    f = coefficients[i]
    acc = np.zeros((t.size, states.shape[1]))
    for n in range(f.shape[2] - 1, -1, -1):
        acc += f[:, :, n]
        acc *= x if n % 2 == 0 else 1.0 - x
    return (states[i] + acc).T


@dataclass(frozen=True)
class Integration:
    """The end state, the dense solution, the right-hand sides evaluated, and where the event
    stopped the integration (None: it reached the end)."""

    end: list[float]
    trajectory: Trajectory
    evaluations: int
    stopped_at: float | None


def _divides_by_zero(t: float) -> DynamicsError:
    """The error for a right-hand side that divided by zero at t (plain floats raise where
    numpy's arrays would give inf)."""
    return DynamicsError(f"the equation of motion divides by zero at {t:.10g}")


#: One step's stages (see :func:`_stepper`).
Stepper = Callable[[RightHandSide, float, float, float, list[float], Sequence[float], Sequence[float], float],
                   tuple[list[float], Sequence[float], list[list[float]], float, float]]
#: One step's continuous extension (see :func:`_extension`).
Extension = Callable[[RightHandSide, float, float, list[float], list[float], list[list[float]]], list[list[float]]]


def _combination(weights: Sequence[float], i: int) -> str:
    """The sum of weights[j] x k{j}_{i} (stage j's derivative of state i) over the nonzero
    weights, as Python source, left to right: the same additions in the same order as
    ``sum(map(mul, weights, ...))`` (the terms with a zero weight add an exact zero there)."""
    return " + ".join(f"{w!r} * k{j}_{i}" for j, w in enumerate(weights) if w != 0.0)


def _names(prefix: str, states: int) -> str:
    """``prefix0, prefix1, ...`` as an assignment's targets (a one-element tuple with its comma)."""
    return ", ".join(f"{prefix}{i}" for i in range(states)) + ("," if states == 1 else "")


def _stage(j: int, c: float, weights: Sequence[float], states: int, indent: str) -> list[str]:
    """Source of stage j: its derivatives k{j}_0 .. from rhs at t + c h and y + h sum(weights k)."""
    state = ", ".join(f"y{i} + h * ({_combination(weights, i)})" for i in range(states))
    return [f"{indent}ts = t + {c!r} * h", f"{indent}{_names(f'k{j}_', states)} = rhs(ts, [{state}])"]


def _compiled(lines: list[str], name: str, states: int) -> Callable[..., Any]:
    """The function ``name`` defined by the source ``lines`` (its file name in tracebacks
    tells the number of states)."""
    namespace: dict[str, Any] = {"divides_by_zero": _divides_by_zero}
    exec(compile("\n".join(lines), f"<DOP853 {name} of {states} states>", "exec"), namespace)
    return namespace[name]


@cache
def _stepper(states: int) -> Stepper:
    """The stages of one step for ``states`` states, made once per number of states:
    ``step(rhs, t, h, t_new, y, f, atol, rtol)`` (f = rhs(t, y), t_new = t + h as the caller
    rounds it) gives the end state, rhs at it, each state's thirteen stage derivatives (for
    the dense output), and the sums of the squared fifth- and third-order error estimates
    over the scales atol + max(|y|, |y_new|) rtol.

    Why made: a step combines its stages in some 70 products a state, which in a loop over
    the coefficient rows cost a dispatch of sum(map(...)) each, more than the right-hand
    sides of the step. Written out with the coefficients as literals (their repr reads back
    to the same floats) and the stage derivatives as local variables, the same products and
    additions in the same order give the same numbers: a step of the machine's three states
    took 24 µs instead of 41 µs, 13 µs of them its twelve right-hand sides. A
    ZeroDivisionError of the right-hand side becomes a DynamicsError at the stage's t."""
    tab = _tableau()
    stages = len(tab.b)
    n = range(states)

    def error(weights: Sequence[float]) -> str:
        return " + ".join(f"(({_combination(weights, i)}) / s{i}) ** 2" for i in n)

    lines = ["def step(rhs, t, h, t_new, y, f, atol, rtol):",
             f"    {_names('y', states)} = y",
             f"    {_names('k0_', states)} = f",
             "    try:"]
    for j in range(1, stages):
        lines += _stage(j, tab.c[j], tab.a[j], states, "        ")
    lines += [f"        y_new = [{', '.join(f'y{i} + h * ({_combination(tab.b, i)})' for i in n)}]",
              "        ts = t_new",
              "        f_new = rhs(ts, y_new)",
              f"        {_names(f'k{stages}_', states)} = f_new",
              "    except ZeroDivisionError:",
              "        raise divides_by_zero(ts) from None",
              f"    {_names('u', states)} = y_new",
              f"    {_names('a', states)} = atol"]
    lines += [f"    s{i} = a{i} + (abs(u{i}) if abs(u{i}) > abs(y{i}) else abs(y{i})) * rtol" for i in n]
    columns = ", ".join("[" + ", ".join(f"k{j}_{i}" for j in range(stages + 1)) + "]" for i in n)
    lines += [f"    return y_new, f_new, [{columns}], {error(tab.e5)}, {error(tab.e3)}"]
    return _compiled(lines, "step", states)


@cache
def _extension(states: int) -> Extension:
    """The continuous extension of one step for ``states`` states, made once per number of
    states as :func:`_stepper` is and for the same reason: ``extension(rhs, t, h, y, y_new,
    columns)`` (``columns``: each state's thirteen stage derivatives) evaluates the three
    extra stages and gives each state's F_0 .. F_6 ([HairerNorsettWanner1993] sec. II.6)."""
    tab = _tableau()
    stages = len(tab.b)
    n = range(states)
    lines = ["def extension(rhs, t, h, y, y_new, columns):",
             f"    {_names('y', states)} = y",
             f"    {_names('u', states)} = y_new"]
    lines += [f"    {', '.join(f'k{j}_{i}' for j in range(stages + 1))} = columns[{i}]" for i in n]
    for r, (a, c) in enumerate(zip(tab.extra_a, tab.extra_c)):
        lines += _stage(stages + 1 + r, c, a, states, "    ")
    lines += [f"    d{i} = u{i} - y{i}" for i in n]
    rows = [f"[d{i}, h * k0_{i} - d{i}, 2.0 * d{i} - h * (k{stages}_{i} + k0_{i}), "
            + ", ".join(f"h * ({_combination(row, i)})" for row in tab.d) + "]" for i in n]
    lines += [f"    return [{', '.join(rows)}]"]
    return _compiled(lines, "extension", states)


def _norm(values: Sequence[float], scale: Sequence[float]) -> float:
    return math.sqrt(sum((v / s) ** 2 for v, s in zip(values, scale)) / len(scale))


def _initial_step(rhs: RightHandSide, t0: float, y0: list[float], f0: Sequence[float], span: float, rtol: float,
                  atol: Sequence[float]) -> float:
    """[HairerNorsettWanner1993] sec. II.4's starting step (one right-hand side)."""
    scale = [a + abs(y) * rtol for a, y in zip(atol, y0)]
    d0, d1 = _norm(y0, scale), _norm(f0, scale)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, span)
    f1 = rhs(t0 + h0, [y + h0 * f for y, f in zip(y0, f0)])
    d2 = _norm([b - a for a, b in zip(f0, f1)], scale) / h0
    h1 = max(1e-6, h0 * 1e-3) if d1 <= 1e-15 and d2 <= 1e-15 else (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1, span)


def integrate(rhs: RightHandSide, t0: float, t1: float, y0: Sequence[float], rtol: float, atol: Sequence[float],
              event: Callable[[float, Sequence[float]], float] | None = None) -> Integration:
    """Integrate y' = rhs(t, y) from t0 to t1 > t0 at the relative tolerance ``rtol`` and the
    absolute tolerances ``atol`` (one per state).

    ``event(t, y)``, when given, stops the integration where it changes sign: its root on the
    dense solution of the step in which it did (bisection to 1e-12 of the step or to adjacent
    floating-point numbers, whichever comes first).

    Raises
    ------
    DynamicsError
        When the step size falls below ten spacings of floating-point numbers at t (a
        singular right-hand side), a state is not finite or the right-hand side divides by zero.
    """
    counter = [0]

    def counted(t: float, y: Sequence[float]) -> Sequence[float]:
        """rhs, counted: the initial step's, and the continuous extension's (the steps count their own)."""
        counter[0] += 1
        try:
            return rhs(t, y)
        except ZeroDivisionError:  # plain floats raise where numpy's arrays would give inf
            raise _divides_by_zero(t) from None

    trajectory = Trajectory(counted)
    t, y = float(t0), [float(v) for v in y0]
    states, step = len(y), _stepper(len(y))
    evaluations = len(_tableau().b)   # right-hand sides a step: eleven stages and the end state's
    f = counted(t, y)
    h_abs = _initial_step(counted, t, y, f, t1 - t0, rtol, atol)
    g = event(t, y) if event is not None else 0.0
    while t < t1:
        min_step = 10.0 * (math.nextafter(t, math.inf) - t)
        h_abs = max(h_abs, min_step)
        rejected = False
        while True:
            if h_abs < min_step or not math.isfinite(h_abs):
                raise DynamicsError(f"the integration's step fell below the floating-point spacing at {t:.10g}: "
                                    f"the equation of motion is singular there")
            t_new = min(t + h_abs, t1)
            h = t_new - t
            counter[0] += evaluations
            y_new, f_new, columns, err5, err3 = step(rhs, t, h, t_new, y, f, atol, rtol)
            if not (math.isfinite(err5) and math.isfinite(err3)):
                raise DynamicsError(f"the equation of motion's state is not finite near {t:.10g}")
            error = 0.0 if err5 == 0.0 == err3 else h * err5 / math.sqrt((err5 + 0.01 * err3) * states)
            if error < 1.0:
                factor = MAX_FACTOR if error == 0.0 else min(MAX_FACTOR, SAFETY * error**EXPONENT)
                h_abs *= min(1.0, factor) if rejected else factor
                break
            h_abs *= max(MIN_FACTOR, SAFETY * error**EXPONENT)
            rejected = True
        trajectory.add(t, h, y, y_new, columns)
        if event is not None:
            g_new = event(t_new, y_new)
            if (g <= 0.0 <= g_new) or (g >= 0.0 >= g_new):
                return _stopped(trajectory, event, t, t_new, g <= 0.0, counter)
            g = g_new
        t, y, f = t_new, y_new, f_new
    return Integration(y, trajectory, counter[0], None)


def _stopped(trajectory: Trajectory, event: Callable[[float, Sequence[float]], float], t: float, t_new: float,
             below: bool, counter: list[int]) -> Integration:
    """The event's root in the last step, by bisection on its dense solution (``below``: the
    event is <= 0 at the step's start)."""
    at = trajectory.in_last_step()
    lo, hi = t, t_new
    while hi - lo > 1e-12 * (t_new - t):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:  # a short step far from t = 0: the floats between lo and hi ran out
            break
        if (event(mid, at(mid)) <= 0.0) == below:
            lo = mid
        else:
            hi = mid
    return Integration(at(hi), trajectory, counter[0], hi)
