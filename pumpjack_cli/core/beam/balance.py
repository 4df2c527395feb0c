"""The counterbalance moment that best balances a card: equal stroke peaks, least RMS
torque, least peak torque.

The API net torque (:mod:`.counterbalance`) is affine in the counterbalance moment M:
T_i(M) = a_i - M s_i with a_i = TF_i (W_i - B) (+ any torque that does not depend on M)
and s_i = sin(theta_i - tau), on a grid of crank angles theta_i. Every criterion is
therefore a one-dimensional problem in M that is solved exactly on the grid (no scan):
the RMS in closed form, the peak and the stroke peaks as maxima of affine functions
(convex, piecewise linear), by bisection to the float resolution and the exact
intersection of the active lines.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import TorqueError
from .counterbalance import CounterbalanceModel, counterbalance_effect, upstroke_mask
from ..mechanism import Mechanism

#: Balance criteria of :func:`recommend_counterbalance`.
BALANCE_CRITERIA = ("equal-peaks", "min-rms", "min-peak")

#: Bisection steps of the 1-D searches (each halves the bracket; 200 reach the float
#: resolution from any bracket a double can hold).
_BISECTIONS = 200


def balance_criteria() -> tuple[str, ...]:
    """Names of the balance criteria: ``equal-peaks``, ``min-rms``, ``min-peak``."""
    return BALANCE_CRITERIA


def _check(name: str, base: np.ndarray, sine: np.ndarray) -> None:
    """Raise TorqueError unless base and sine are finite 1-D arrays of one length >= 2."""
    if base.ndim != 1 or base.shape != sine.shape or base.size < 2:
        raise TorqueError(f"{name}: torque and sine must be 1-D arrays of one length, at least 2 crank angles")
    if not (np.all(np.isfinite(base)) and np.all(np.isfinite(sine))):
        raise TorqueError(f"{name}: the torque is not finite at every crank angle")


def _lines(base: np.ndarray, sine: np.ndarray, moment: float) -> np.ndarray:
    return base - moment * sine


def equal_peaks_moment(base: np.ndarray, sine: np.ndarray, upstroke: np.ndarray) -> float | None:
    """M >= 0 at which the largest net torques of the up- and the downstroke are equal.

    With T_i(M) = a_i - M s_i (a = net torque without counterbalance, s = sin(theta -
    tau)), U(M) = max over the upstroke of T and D(M) = max over the downstroke are
    convex piecewise-linear; g = U - D is piecewise-linear but need not be monotonic.
    Each maximum follows its upper envelope (:func:`_fronts`), whose lines take over one
    from the next at known M; between the union of those M (and beyond the last) one line
    of each stroke leads, g is linear, and its root there, if it lies in the piece, is the
    exact intersection of the two lines. Every root at M >= 0 is found so; of several the
    one with the smallest largest |T| is returned; None when g has no root at M >= 0 (the
    criterion cannot be met by any counterbalance). This is :func:`equal_peaks_moments`
    of one card.

    Parameters
    ----------
    base : ndarray
        a_i, net torque without the counterbalance term [N·m], per crank angle.
    sine : ndarray
        s_i = sin(theta_i - tau).
    upstroke : ndarray of bool
        True on the upstroke; both strokes must hold samples.

    Returns
    -------
    float or None
        M [N·m].

    References
    ----------
    Equal peak torques on both strokes: [Rowlan2004] (balanced gearbox loading).

    Examples
    --------
    T = 10 - M on the upstroke, -4 + M on the downstroke: equal at M = 7.

    >>> equal_peaks_moment(np.array([10.0, -4.0]), np.array([1.0, -1.0]), np.array([True, False]))
    7.0
    """
    base, sine = np.asarray(base, dtype=float), np.asarray(sine, dtype=float)
    _check("equal peak torques", base, sine)
    found = float(equal_peaks_moments(base[None], sine, upstroke)[0])
    return None if math.isnan(found) else found


def equal_peaks_moments(bases: np.ndarray, sine: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
    """:func:`equal_peaks_moment` of K cards on one crank grid, ``bases`` (K, N), their sine and
    strokes shared: M (K,) [N·m], NaN where no M >= 0 makes the stroke peaks equal. Each card's
    envelopes, pieces and roots are rows of arrays; every card gets the moment it has alone."""
    bases, sine = np.asarray(bases, dtype=float), np.asarray(sine, dtype=float)
    up = np.asarray(upstroke, dtype=bool)
    if up.shape != sine.shape or not np.any(up) or np.all(up):
        raise TorqueError("equal peak torques: the crank angles must cover both the upstroke and the downstroke")
    (a_up, s_up, at_up), (a_down, s_down, at_down) = (_leading(bases, sine, np.flatnonzero(mask))
                                                      for mask in (up, ~up))
    rows = np.arange(len(bases))[:, None]
    cuts = np.sort(np.concatenate((np.zeros((len(bases), 1)), np.where(at_up > 0.0, at_up, np.inf),
                                   np.where(at_down > 0.0, at_down, np.inf)), axis=1), axis=1)
    cuts[:, 1:][cuts[:, 1:] == cuts[:, :-1]] = np.inf           # each cut once
    cuts = np.sort(cuts, axis=1)
    following = np.append(cuts[:, 1:], np.full((len(bases), 1), np.inf), axis=1)
    i = np.sum(at_up[:, None, :] <= cuts[:, :, None], axis=2)  # the line leading from each cut on
    j = np.sum(at_down[:, None, :] <= cuts[:, :, None], axis=2)
    gap, turn = a_up[rows, i] - a_down[rows, j], s_up[rows, i] - s_down[rows, j]    # g = gap - M turn
    with np.errstate(divide="ignore", invalid="ignore"):
        root = np.where(turn != 0.0, gap / np.where(turn != 0.0, turn, 1.0), np.nan)
    cut = np.isfinite(cuts)
    inside = cut & (turn != 0.0) & (root >= cuts) & (root <= following)
    same = cut & (turn == 0.0) & (gap == 0.0)                 # the same line leads both strokes: g = 0
    roots = np.sort(np.where(inside, root, np.where(same, cuts, np.nan)), axis=1)
    roots[:, 1:][roots[:, 1:] == roots[:, :-1]] = np.nan        # each root once
    roots = np.sort(roots, axis=1)
    count = np.sum(~np.isnan(roots), axis=1)
    found = np.where(count > 0, roots[:, 0], np.nan)
    several = np.flatnonzero(count > 1)
    if several.size:       # of several roots the one of the smallest largest |T|, the first of equals
        peak = np.full((several.size, roots.shape[1]), np.inf)
        for r in range(int(count.max())):
            live = count[several] > r
            peak[live, r] = np.max(np.abs(bases[several[live]] - roots[several[live], r:r + 1] * sine), axis=1)
        found[several] = roots[several, np.argmin(peak, axis=1)]
    return found


def _leading(bases: np.ndarray, sine: np.ndarray, columns: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The lines of each card's upper envelope over ``columns`` (:func:`_fronts`) in the order they
    lead as M grows from 0, and the M at which each after the first takes over from the one
    before (increasing; +inf past a card's last line): arrays (K, E), (K, E), (K, E - 1)."""
    a, s, size = _fronts(bases[:, columns], sine[columns])
    a, s = _reverse_rows(a, size), _reverse_rows(s, size)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = np.maximum.accumulate((a[:, :-1] - a[:, 1:]) / (s[:, :-1] - s[:, 1:]), axis=1)
    return a, s, np.where(np.arange(a.shape[1] - 1) < size[:, None] - 1, at, np.inf)


def _reverse_rows(values: np.ndarray, size: np.ndarray) -> np.ndarray:
    """Each row's first ``size`` entries in reverse order (the padding after them kept)."""
    columns = np.arange(values.shape[1])
    index = np.where(columns < size[:, None], size[:, None] - 1 - columns, columns)
    return np.take_along_axis(values, index, axis=1)


def _fronts(bases: np.ndarray, sine: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The lines a_i - M s_i of each of K cards (``bases`` (K, n), ``sine`` (n,)) that are the
    largest for some M >= 0: their upper envelope, in the order of s, as rows padded with NaN
    after each card's ``size`` lines: (a (K, E), s (K, E), size (K,)).

    Line j is at or above line i for every M >= 0 when a_j >= a_i and s_j <= s_i, so first
    only the lines above every line of smaller (or equal, earlier) s are kept (of equal s the
    largest a): in the order of s their a increases, and the last is the largest at M = 0.
    From it the envelope is followed as M grows: the next line is the one of smaller s that
    overtakes the present one first, at M = (a_j - a_i) / (s_j - s_i) (of equal such M the
    one of smallest s, the others leading at a single point), until the line of smallest s
    (the convex-hull trick), every card's next line found at once. The maximum over the
    envelope is the maximum over all lines; a line that would lead only by rounding may be
    left out, which moves the maximum by a rounding error."""
    order = np.argsort(sine, kind="stable")
    s_sorted = sine[order]
    starts = np.flatnonzero(np.append(True, s_sorted[1:] != s_sorted[:-1]))
    a = np.maximum.reduceat(bases[:, order], starts, axis=1)      # of equal s the largest a
    before = np.concatenate((np.full((len(a), 1), -np.inf), np.maximum.accumulate(a, axis=1)[:, :-1]), axis=1)
    a, s, size = _compact(a, np.broadcast_to(s_sorted[starts], a.shape), a > before)
    present = size - 1
    leads = np.zeros(a.shape, dtype=bool)
    leads[np.arange(len(a)), present] = True
    while True:
        k = np.flatnonzero(present > 0)
        if not k.size:
            return _compact(a, s, leads)
        at = present[k]
        width = int(at.max())
        with np.errstate(divide="ignore", invalid="ignore"):
            takeover = (a[k, at][:, None] - a[k, :width]) / (s[k, at][:, None] - s[k, :width])
        takeover[np.arange(width) >= at[:, None]] = np.inf
        present[k] = np.argmin(takeover, axis=1)
        leads[k, present[k]] = True


def _compact(a: np.ndarray, s: np.ndarray, chosen: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The chosen entries of each row of ``a`` and ``s`` (K, n), in order, as rows padded with NaN,
    and their number in each row."""
    rows, columns = np.nonzero(chosen)
    size = np.bincount(rows, minlength=len(a))
    place = np.arange(rows.size) - (np.cumsum(size) - size)[rows]
    shape = (len(a), max(int(size.max()), 1))
    kept_a, kept_s = np.full(shape, np.nan), np.full(shape, np.nan)
    kept_a[rows, place], kept_s[rows, place] = a[rows, columns], s[rows, columns]
    return kept_a, kept_s, size


def min_rms_moment(base: np.ndarray, sine: np.ndarray, weights: np.ndarray | None = None) -> float:
    """M minimising the RMS net torque (closed form; may be negative, the caller clamps).

    T = a - M s is affine in M, so mean(w T^2) is a parabola in M with its minimum at
    M = mean(w a s) / mean(w s^2); w are time weights (uniform crank speed: all equal).

    Parameters
    ----------
    base : ndarray
        a_i [N·m].
    sine : ndarray
        s_i = sin(theta_i - tau).
    weights : ndarray, optional
        Time share of each sample (dt_i); None for a uniform crank-angle grid at uniform speed.

    Returns
    -------
    float
        M [N·m].

    References
    ----------
    Minimum RMS torque balance (motor heating): [DurhamLockard1988].

    Examples
    --------
    >>> min_rms_moment(np.array([1.0, 3.0]), np.array([1.0, 1.0]))
    2.0
    """
    base, sine = np.asarray(base, dtype=float), np.asarray(sine, dtype=float)
    _check("minimum RMS torque", base, sine)
    w = np.ones_like(base) if weights is None else np.asarray(weights, dtype=float)
    if w.shape != base.shape or not np.all(np.isfinite(w)) or np.any(w < 0):
        raise TorqueError("minimum RMS torque: the weights must be finite, >= 0, one per crank angle")
    denominator = float(np.sum(w * sine * sine))
    if not denominator > 0:
        raise TorqueError("minimum RMS torque: sin(theta + tau) vanishes at every crank angle given")
    return float(np.sum(w * base * sine)) / denominator


def min_peak_moment(base: np.ndarray, sine: np.ndarray) -> float:
    """M >= 0 minimising max |a_i - M s_i| (exact 1-D minimisation of a convex piecewise-linear function).

    f(M) = max_i |a_i - M s_i| is convex; its minimiser lies in [0, 2 max|a| / max|s|]
    (f(M) >= |M| max|s| - max|a| and f(0) = max|a|). Bisection on the sign of the
    subgradient -sigma_i s_i of the active line i (sigma_i its sign) brackets the kink;
    the two active lines at the ends of the final bracket are intersected exactly.

    Parameters
    ----------
    base : ndarray
        a_i [N·m].
    sine : ndarray
        s_i = sin(theta_i - tau).

    Returns
    -------
    float
        M [N·m]; 0 when the unconstrained optimum would be negative.

    References
    ----------
    Minimum peak torque balance: [Rowlan2004]; convexity of a maximum of affine functions.

    Examples
    --------
    max(|10 - M|, |-4 + M|) is smallest (7) at M = 7:

    >>> min_peak_moment(np.array([10.0, -4.0]), np.array([1.0, -1.0]))
    7.0
    """
    base, sine = np.asarray(base, dtype=float), np.asarray(sine, dtype=float)
    _check("minimum peak torque", base, sine)

    def active(moment: float) -> tuple[int, float]:
        torque = _lines(base, sine, moment)
        i = int(np.argmax(np.abs(torque)))
        return i, (1.0 if torque[i] >= 0 else -1.0)

    def slope(moment: float) -> float:
        i, sign = active(moment)
        return -sign * float(sine[i])

    def f(moment: float) -> float:
        return float(np.max(np.abs(_lines(base, sine, moment))))

    scale = float(np.max(np.abs(sine)))
    if not scale > 0:
        raise TorqueError("minimum peak torque: sin(theta + tau) vanishes at every crank angle given")
    lo, hi = 0.0, 2.0 * float(np.max(np.abs(base))) / scale
    if slope(lo) >= 0.0 or hi == 0.0:
        return 0.0
    for _ in range(_BISECTIONS):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        s_mid = slope(mid)
        if s_mid == 0.0:
            return mid
        if s_mid < 0:
            lo = mid
        else:
            hi = mid
    (i, si), (j, sj) = active(lo), active(hi)
    candidates = [lo, hi]
    denominator = si * sine[i] - sj * sine[j]
    if i != j and denominator != 0.0:
        kink = float((si * base[i] - sj * base[j]) / denominator)
        if lo - (hi - lo) <= kink <= hi + (hi - lo):
            candidates.append(kink)
    return min(candidates, key=f)


@dataclass(frozen=True)
class BalanceRecommendation:
    """The value of the balancing variable a criterion asks for and the loading it gives (SI).

    ``value`` (crank counterweights: the moment M [N·m]; a beam weight [N]; an air pressure
    [Pa]; None when the criterion cannot be met, ``note`` says why);
    ``peak_net_torque`` max |T| [N·m]; ``upstroke_peak``, ``downstroke_peak``: the
    largest T of each stroke [N·m]; ``rms_torque`` [N·m]; ``counterbalance_effect``
    CBE [N] at the test angle; B and tau are those given.
    """

    criterion: str
    value: float | None
    peak_net_torque: float | None
    upstroke_peak: float | None
    downstroke_peak: float | None
    rms_torque: float | None
    counterbalance_effect: float | None
    note: str


def recommend_counterbalance(criterion: str, linkage: Mechanism, crank_angle: np.ndarray, rod_load: np.ndarray,
                             balance: CounterbalanceModel, *, extra_torque: np.ndarray | float = 0.0,
                             weights: np.ndarray | None = None, test_angle: float = math.pi / 2) -> BalanceRecommendation:
    """The value of the balancing variable (crank counterweights: the moment M; a beam weight;
    an air pressure) that meets ``criterion`` for a card, the structure and the rest of the
    counterbalance kept; the value is at least 0.

    The net torque T(theta; x) = TF W + T_s + T_c(x) + T_extra is affine in the variable x,
    T_c(x) = c0 + x g (:class:`.counterbalance.CounterbalanceModel`; crank counterweights: T = TF (W - B) + T_extra -
    M sin(theta + tau)); with base = TF W + T_s + c0 + T_extra and sine = -g, T = base - x sine:

    * ``equal-peaks``: the largest T of the upstroke equals that of the downstroke
      (:func:`equal_peaks_moment`);
    * ``min-rms``: the smallest RMS of T (:func:`min_rms_moment`), clamped at M >= 0;
    * ``min-peak``: the smallest max |T| (:func:`min_peak_moment`).

    Parameters
    ----------
    criterion : str
        One of :data:`BALANCE_CRITERIA`.
    linkage : Mechanism
        The unit (torque factors, dead positions).
    crank_angle : ndarray
        theta [rad]; a uniform grid over one revolution unless ``weights`` are given.
    rod_load : ndarray
        W [N] at those angles.
    balance : CounterbalanceModel
        The structure and counterbalance (crank counterweights: B [N] and tau [rad] are
        used; its M is ignored).
    extra_torque : ndarray or float
        Further torque terms that do not change with M [N·m] (e.g. the inertia terms of
        :func:`.torque.torque_components`); 0 for the API method.
    weights : ndarray, optional
        Time share of each sample for the RMS (non-uniform speed).
    test_angle : float
        theta_t of the counterbalance effect [rad].

    Returns
    -------
    BalanceRecommendation

    References
    ----------
    [Rowlan2004]; [API11E]; [DurhamLockard1988].
    """
    return recommend_counterbalances(criterion, linkage, crank_angle, np.asarray(rod_load, dtype=float)[None],
                                     balance, extra_torque=np.asarray(extra_torque, dtype=float)[None],
                                     weights=None if weights is None else np.asarray(weights, dtype=float)[None],
                                     test_angle=test_angle)[0]


def recommend_counterbalances(criterion: str, linkage: Mechanism, crank_angle: np.ndarray, rod_load: np.ndarray,
                              balance: CounterbalanceModel, *, extra_torque: np.ndarray | float = 0.0,
                              weights: np.ndarray | None = None,
                              test_angle: float = math.pi / 2) -> list[BalanceRecommendation]:
    """:func:`recommend_counterbalance` of K cards on one crank-angle grid: ``rod_load``,
    ``extra_torque`` and ``weights`` of shape (K, N); what depends on the grid alone (torque
    factors, the counterbalance's torque per unit of its variable, the strokes) made once, each
    card's criterion solved on its own."""
    if criterion not in BALANCE_CRITERIA:
        raise TorqueError(f"unknown balance criterion {criterion!r}; use one of {', '.join(BALANCE_CRITERIA)}")
    theta = np.asarray(crank_angle, dtype=float)
    m = linkage.motion(theta)
    sine = -balance.torque_per_value(m)
    fixed = balance.structural_torque(m) + balance.counterbalance_torque(m) + balance.value * sine
    bases = m.torque_factor * np.asarray(rod_load, dtype=float) + fixed + extra_torque
    if not np.all(np.isfinite(bases)):
        raise TorqueError("balance: the rod load or the extra torque is not finite at every crank angle")
    if weights is not None and (np.shape(weights) != bases.shape or not np.all(np.isfinite(weights))
                                or np.any(np.asarray(weights) < 0) or not np.all(np.sum(weights, axis=-1) > 0)):
        raise TorqueError("balance: the weights must be finite, >= 0, not all 0, one per crank angle")
    up = upstroke_mask(linkage, theta)
    at_test = linkage.motion(np.array([test_angle]))
    name = balance.variable.replace("_", " ")
    notes = [""] * len(bases)
    if criterion == "equal-peaks":
        moments = equal_peaks_moments(bases, sine, up)
    elif criterion == "min-rms":
        moments = np.array([min_rms_moment(base, sine, None if weights is None else weights[k])
                            for k, base in enumerate(bases)])
        for below in np.flatnonzero(moments < 0):
            notes[below] = (f"the RMS torque is least at a {name} of {moments[below]:.6g} {balance.symbol} < 0; 0 is "
                            f"the best counterbalance")
        moments = np.maximum(moments, 0.0)
    else:
        moments = np.array([min_peak_moment(base, sine) for base in bases])
    torque = bases - np.where(np.isnan(moments), 0.0, moments)[:, None] * sine
    upstroke_peak, downstroke_peak = np.max(torque[:, up], axis=1), np.max(torque[:, ~up], axis=1)
    w = np.ones_like(torque) if weights is None else np.asarray(weights, dtype=float)
    rms = np.sqrt(np.sum(w * torque * torque, axis=1) / np.sum(w, axis=1))
    peak = np.max(np.abs(torque), axis=1)
    found = []
    for k, moment in enumerate(moments.tolist()):
        if math.isnan(moment):
            found.append(BalanceRecommendation(criterion, None, None, None, None, None, None,
                                               f"no {name} >= 0 makes the stroke peaks equal (at 0 the upstroke "
                                               f"peak is {upstroke_peak[k]:.6g} N·m, the downstroke peak "
                                               f"{downstroke_peak[k]:.6g} N·m)"))
            continue
        cbe = counterbalance_effect(at_test, balance.with_value(moment))
        found.append(BalanceRecommendation(criterion, moment, float(peak[k]), float(upstroke_peak[k]),
                                           float(downstroke_peak[k]), float(rms[k]), cbe, notes[k]))
    return found
