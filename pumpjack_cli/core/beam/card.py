"""Dynamometer cards on the crank-angle axis.

A card is the polished-rod load over one pumping cycle. Measured cards come as load
against polished-rod position (or position and time); the calculator needs load
against crank angle. Two ways onto the crank-angle axis, both through the exact
kinematics of :mod:`.linkage` (no approximation):

* **position only.** Each position occurs once on the upstroke and once on the
  downstroke, so each point is mapped on the branch of its own stroke direction:
  upstroke points on the exact position curve between the bottom and top dead
  positions, downstroke points on the curve from top back to bottom
  (:func:`crank_angle_from_position`).
* **time and position.** The time stamps say how fast the crank turned: for uniform
  rotation theta_i = theta_0 + omega t_i, and theta_0 and omega are fitted by least
  squares to the measured positions (:func:`fit_rotation`), optionally with a
  periodic variation of the crank speed over the cycle. The fitted mean omega is the
  card's pumping speed, the fitted series' derivatives the crank speed and
  acceleration at every sample, and the residual says how well the card fits this unit;
  the cards of one unit are fitted together, each as alone, by :func:`fit_rotations`.
  [Takacs2016] derive the crank angle against time from dynamometer data
  iteratively; here it is a least-squares fit of a few parameters.

Orientation: over a steady pumping cycle the unit does positive work on the rods,
W = closed integral of F ds > 0: the rods, the fluid and the well return to their
state after a cycle, so W equals the hydraulic work done on the fluid plus the
friction and damping losses, each >= 0 (energy balance, docs/cards.md). The rods go
up on the high load and down on the low load, and the sign of :func:`loop_work` in
the order listed tells a card stored in reverse.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from ...errors import CardError
from ..mechanism import Mechanism
from ..sampling import ahead, behind, wrapped
from .geometry import Linkage  # noqa: F401 (the docstrings' examples build one)

#: Crank positions per stroke branch used to invert position -> crank angle.
_BRANCH_STEPS = 8192
#: Gauss-Newton iterations of the time fit at most (exact data converge in under ten).
_FIT_ITERATIONS = 50
#: Step-halvings tried before the fit stops at a point no step improves.
_LINE_SEARCH = 20
#: A Gauss-Newton step below this many radians (start angle, and speed times the half
#: time span) ends the fit: 1e-10 rad moves a 3 m-stroke polished rod by under 1 nm.
_FIT_TOLERANCE = 1e-10
#: Harmonics fitted before the others: a pumping unit's crank speed varies mostly at once
#: and twice per revolution (the upstroke's and the downstroke's torque peaks).
_FIRST_HARMONICS = 2
#: Machine epsilon of float64: R's diagonal below n times this, relative to its largest entry,
#: counts as rank-deficient (the cut-off of ``numpy.linalg.lstsq``'s default ``rcond``).
_EPSILON = float(np.finfo(float).eps)
#: Cards evaluated and factorised together: a block's augmented matrices (17 x 32 x 180 doubles,
#: 0.8 MB, for 180-sample cards and six harmonics) stay in a core's cache from the crank angles to
#: the QR, while numpy's fixed cost per call is shared by 32 cards (measured on 2000 field cards
#: of 180 samples in groups of 64: 0.24 ms of CPU a card's fit in blocks of 32, 0.26 in blocks of
#: 16, 0.28 in blocks of 64).
_BLOCK = 32


@dataclass(frozen=True)
class Card:
    """A dynamometer card on the crank-angle axis.

    Attributes
    ----------
    crank_angle : numpy.ndarray
        Crank angles, increasing, within [0, 2 pi) [rad].
    load : numpy.ndarray
        Polished-rod load at those angles [N].
    """

    crank_angle: np.ndarray
    load: np.ndarray

    @cached_property
    def _table(self) -> tuple[np.ndarray, np.ndarray]:
        return periodic_table(self.crank_angle, self.load)


def periodic_table(crank_angle: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The (angles, values) table of a curve over one revolution for :func:`periodic_interp`: the
    angles taken modulo 2 pi and sorted, one sample carried over each end (what
    ``numpy.interp(..., period=2 pi)`` builds at every call, made once); :func:`periodic_tables`
    of one curve."""
    angle, values = periodic_tables(np.asarray(crank_angle, dtype=float)[None], np.asarray(values, dtype=float)[None])
    return angle[0], values[0]


def periodic_tables(crank_angle: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The tables of :func:`periodic_table` of K curves of as many samples, rows of (K, n) arrays:
    each row's as alone (angles (K, n + 2), values (K, n + 2))."""
    angle = wrapped(crank_angle)
    order = np.argsort(angle, axis=-1)
    angle, values = np.take_along_axis(angle, order, axis=-1), np.take_along_axis(values, order, axis=-1)
    return (np.concatenate((angle[:, -1:] - 2.0 * np.pi, angle, angle[:, :1] + 2.0 * np.pi), axis=-1),
            np.concatenate((values[:, -1:], values, values[:, :1]), axis=-1))


def periodic_interp(crank_angle: np.ndarray, table: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """A curve of :func:`periodic_table` at any crank angles (taken modulo 2 pi), by linear
    interpolation: ``numpy.interp(crank_angle, ..., period=2 pi)`` of the curve, to the bit."""
    return np.interp(wrapped(crank_angle), *table)


@dataclass(frozen=True)
class RotationFit:
    """Crank rotation fitted to time-stamped polished-rod positions (:func:`fit_rotation`).

    ``crank_angle`` [rad] of every sample (not wrapped), ``crank_speed`` omega =
    dtheta/dt [rad/s] and ``crank_acceleration`` alpha = d2theta/dt2 [rad/s²] of every
    sample (the fitted series differentiated), ``start_angle`` [rad] the crank angle at
    the first sample, ``speed`` the mean crank speed [rad/s], ``offset`` c [m] and
    ``scale`` k [-] of the positions (p = c + k s), ``rms`` the root-mean-square position
    residual [m] of this fit and ``uniform_rms`` [m] that of the uniform-rotation fit.
    """

    crank_angle: np.ndarray
    crank_speed: np.ndarray
    crank_acceleration: np.ndarray
    start_angle: float
    speed: float
    offset: float
    scale: float
    rms: float
    uniform_rms: float


def card_load(card: Card, crank_angle: np.ndarray) -> np.ndarray:
    """Polished-rod load at any crank angles: periodic linear interpolation of the card.

    Parameters
    ----------
    card : Card
        The card [rad, N].
    crank_angle : numpy.ndarray
        Crank angles, any values (taken modulo 2 pi) [rad].

    Returns
    -------
    numpy.ndarray
        Load [N].

    Examples
    --------
    A two-point card, 1 N at 0 and 3 N at pi, is 2 N half way on either side:

    >>> card = Card(np.array([0.0, np.pi]), np.array([1.0, 3.0]))
    >>> card_load(card, np.array([np.pi / 2, 3 * np.pi / 2, 2 * np.pi])).tolist()
    [2.0, 2.0, 1.0]
    """
    return periodic_interp(crank_angle, card._table)


def upstroke_points(position: np.ndarray) -> np.ndarray:
    """True where the card's polished rod is moving up, from the neighbours of each point.

    The card is periodic, so the first and last points are neighbours; the sign of
    s[i+1] - s[i-1] decides (at the dead positions either branch gives the same angle).

    Parameters
    ----------
    position : numpy.ndarray
        Polished-rod positions of the card in the order measured [m] (any length unit);
        several cards of as many samples as the rows of a 2-D array.

    Returns
    -------
    numpy.ndarray
        Boolean mask, True on the upstroke.

    Examples
    --------
    >>> upstroke_points(np.array([0.0, 1.0, 2.0, 1.0])).tolist()
    [False, True, False, False]
    >>> upstroke_points(np.array([[0.0, 1.0, 2.0, 1.0], [2.0, 1.0, 0.0, 1.0]])).tolist()
    [[False, True, False, False], [False, False, False, True]]
    """
    position = np.asarray(position)
    return (ahead(position) - behind(position)) > 0


def _rod(linkage: Mechanism, crank_angle: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Polished-rod position s [m] and the torque factor ds/dtheta [m/rad]."""
    return linkage.rod_motion(crank_angle)


@lru_cache(maxsize=16)
def _branches(linkage: Mechanism) -> tuple[tuple[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]:
    """(position, crank angle) tables of the upstroke and the downstroke, position increasing."""
    dead = linkage.dead_positions()
    up = dead.crank_angle_bottom + np.linspace(0.0, dead.upstroke_crank_travel, _BRANCH_STEPS)
    down = (dead.crank_angle_top + np.linspace(0.0, dead.downstroke_crank_travel, _BRANCH_STEPS))[::-1]
    return (_rod(linkage, up)[0], up), (_rod(linkage, down)[0], down)


def crank_angle_from_position(linkage: Mechanism, position: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
    """Crank angle of each polished-rod position on the branch of its stroke.

    Positions must lie within [0, stroke]; the exact position s = A (psi - psi_bottom) is
    monotonic between the dead positions, so each branch (bottom -> top on the upstroke,
    top -> bottom on the downstroke) is inverted by linear interpolation on 8192 points.

    Parameters
    ----------
    linkage : Linkage
        The four-bar [m].
    position : numpy.ndarray
        Polished-rod positions from the bottom of the stroke [m], any shape.
    upstroke : numpy.ndarray
        Boolean mask of the points on the upstroke (:func:`upstroke_points`), shaped as ``position``.

    Returns
    -------
    numpy.ndarray
        Crank angles in [0, 2 pi) [rad].

    Examples
    --------
    The bottom and the top of the stroke map to the dead positions:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> dead = sk8.dead_positions()
    >>> theta = crank_angle_from_position(sk8, np.array([0.0, dead.stroke]), np.array([True, True]))
    >>> bool(np.allclose(theta, [dead.crank_angle_bottom, dead.crank_angle_top], atol=1e-9))
    True
    """
    position = np.asarray(position, dtype=float)
    theta = np.empty_like(position)
    for (s, branch), mask in zip(_branches(linkage), (upstroke, ~upstroke)):
        theta[mask] = np.interp(position[mask], s, branch)
    return theta % (2.0 * np.pi)


def card_from_angles(crank_angle: np.ndarray, load: np.ndarray) -> Card:
    """A card from points in any order: angles wrapped to [0, 2 pi), sorted, repeats averaged.

    Parameters
    ----------
    crank_angle : numpy.ndarray
        Crank angles of the points [rad].
    load : numpy.ndarray
        Polished-rod loads [N].

    Returns
    -------
    Card
        Sorted, unique crank angles [rad] and their mean loads [N].

    Examples
    --------
    >>> card = card_from_angles(np.array([0.5, 0.1, 0.5]), np.array([10.0, 5.0, 20.0]))
    >>> card.crank_angle.tolist(), card.load.tolist()
    ([0.1, 0.5], [5.0, 15.0])
    """
    theta = wrapped(crank_angle)
    unique, inverse = np.unique(theta, return_inverse=True)
    sums = np.bincount(inverse, weights=np.asarray(load, dtype=float))
    return Card(crank_angle=unique, load=sums / np.bincount(inverse))


def cards_from_angles(crank_angle: np.ndarray, load: np.ndarray) -> tuple[list[Card], np.ndarray]:
    """:func:`card_from_angles` of each row of (K, n) crank angles [rad] and loads [N], and the
    :func:`largest_gap` of each row [rad], from one sort of all the rows.

    A row of distinct angles within [0, 2 pi) is its angles sorted, each with its load (the mean
    of one: ``+ 0.0`` turns a load of -0.0 into the +0.0 that card_from_angles' sum makes of it),
    and its gaps are the steps between them; any other row is left to the two functions.

    >>> theta = np.array([[0.5, 0.1, 3.0], [0.5, 0.1, 0.5]])
    >>> cards, gaps = cards_from_angles(theta, np.array([[1.0, 2.0, 3.0], [10.0, 5.0, 20.0]]))
    >>> [(card.crank_angle.tolist(), card.load.tolist()) for card in cards]
    [([0.1, 0.5, 3.0], [2.0, 1.0, 3.0]), ([0.1, 0.5], [5.0, 15.0])]
    >>> gaps.tolist() == [largest_gap(row) for row in theta]
    True
    """
    order = np.argsort(crank_angle, axis=1)
    ordered = np.take_along_axis(crank_angle, order, axis=1)
    loads = np.take_along_axis(np.asarray(load, dtype=float), order, axis=1) + 0.0
    steps = np.diff(ordered, axis=1, append=ordered[:, :1] + 2.0 * np.pi)
    plain = np.all(steps[:, :-1] > 0.0, axis=1) & (ordered[:, 0] >= 0.0) & (ordered[:, -1] < 2.0 * np.pi)
    gaps = np.max(steps, axis=1)
    cards = []
    for k in range(len(ordered)):
        if plain[k]:
            cards.append(Card(crank_angle=ordered[k], load=loads[k]))
        else:
            cards.append(card_from_angles(crank_angle[k], load[k]))
            gaps[k] = largest_gap(crank_angle[k])
    return cards, gaps


def loop_work(position: np.ndarray, load: np.ndarray) -> float:
    """Work done on the rods around the closed card in the order listed [J].

    W = closed integral of F ds, by the trapezoidal rule over the polygon of the points
    closed from the last back to the first: the signed area of the card in the
    position-load plane. Positive when the rods rise on the high load and fall on the
    low load, as a pumping unit drives them (energy balance over a steady cycle).

    Parameters
    ----------
    position : numpy.ndarray
        Polished-rod position [m], in cycle order.
    load : numpy.ndarray
        Polished-rod load [N] at those positions.

    Returns
    -------
    float
        Work per cycle [J]; negative for a card listed in reverse.

    References
    ----------
    [Takacs2016] (torque analysis from the polished-rod card); the trapezoidal rule is
    a hand derivation.

    A rectangle 1 m by 1 N, up at 2 N and down at 1 N (hand calculation: 2 - 1 = 1 J):

    >>> loop_work(np.array([0.0, 1.0, 1.0, 0.0]), np.array([2.0, 2.0, 1.0, 1.0]))
    1.0
    >>> loop_work(np.array([0.0, 1.0, 1.0, 0.0])[::-1], np.array([2.0, 2.0, 1.0, 1.0])[::-1])
    -1.0
    """
    s = np.asarray(position, dtype=float)
    f = np.asarray(load, dtype=float)
    return float(np.sum(0.5 * (f + ahead(f)) * (ahead(s) - s)))


def largest_gap(crank_angle: np.ndarray) -> float:
    """Largest crank rotation [rad] between neighbouring angles of a card, around the circle.

    >>> round(float(np.degrees(largest_gap(np.radians([0.0, 90.0, 180.0])))), 6)
    180.0
    >>> round(float(np.degrees(largest_gap(np.radians([350.0, 10.0])))), 6)
    340.0
    """
    theta = np.sort(np.asarray(crank_angle, dtype=float) % (2.0 * np.pi))
    return float(np.max(np.diff(theta, append=theta[0] + 2.0 * np.pi)))


@lru_cache(maxsize=8)
def _series(count: int) -> tuple[np.ndarray, np.ndarray]:
    """Indices into (a_1, b_1, ..., a_H, b_H) and factors making the (3, 2H) coefficients of the
    waves (cos phi, sin phi, ..., cos H phi, sin H phi) in the three sums of :func:`_angles`:
    a_j and b_j; j b_j and -j a_j; -j^2 a_j and -j^2 b_j."""
    j = np.repeat(np.arange(1.0, count + 1.0), 2)
    pairs = np.arange(2 * count)
    index = np.stack([pairs, pairs ^ 1, pairs])
    factor = np.stack([np.ones(2 * count), np.where(pairs % 2, -j, j), -(j * j)])
    index.flags.writeable = factor.flags.writeable = False
    return index, factor


def _angles(params: np.ndarray, tc: np.ndarray, waves: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Crank angles (K, n) of K cards and the first and second derivatives of the angle by phi
    (speed over mean speed, acceleration over its square), for params (K, 2 + 2H) and centred
    times tc (K, n); ``waves`` (2H, K, n) receives cos j phi and sin j phi (rows 2j - 2 and
    2j - 1, j = 1..H), the angle's derivatives by a_j and b_j.

    theta = theta_c + phi + sum_j (a_j cos j phi + b_j sin j phi), phi = omega t_c, for
    params = (theta_c, omega, a_1, b_1, ..., a_H, b_H); so
    dtheta/dphi = 1 + sum_j j (b_j cos j phi - a_j sin j phi) and
    d2theta/dphi2 = -sum_j j^2 (a_j cos j phi + b_j sin j phi): the three sums are one product
    of matrices a card, their (3, 2H) coefficients by the card's (2H, n) waves. The multiples of
    phi come from cos phi and sin phi alone: by the angle-sum formulas,
    cos (j + 1) phi + cos (j - 1) phi = 2 cos phi cos j phi and
    sin (j + 1) phi + sin (j - 1) phi = 2 cos phi sin j phi, so each wave follows from the two
    before it (cos 0 phi = 1, sin 0 phi = 0).
    """
    phi = params[:, 1:2] * tc
    theta = params[:, 0:1] + phi
    count = (params.shape[1] - 2) // 2
    if not count:
        return theta, np.ones(tc.shape), np.zeros(tc.shape)
    twice = 2.0 * np.cos(phi, out=waves[0])
    np.sin(phi, out=waves[1])
    for row in range(2, 2 * count, 2):
        np.multiply(twice, waves[row - 2:row], out=waves[row:row + 2])
        if row > 2:
            waves[row:row + 2] -= waves[row - 4:row - 2]
        else:
            waves[row] -= 1.0
    index, factor = _series(count)
    weights = params[:, 2:][:, index] * factor
    sums = weights @ waves.transpose(1, 0, 2)
    return theta + sums[:, 0], 1.0 + sums[:, 1], sums[:, 2]


def _evaluate(linkage: Mechanism, tc: np.ndarray, p: np.ndarray, params: np.ndarray,
              known: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The residual r = k s(theta(t_i)) + c - p_i of K cards with its Jacobian J, as the augmented
    matrices [J r] stored column by column (P + 1, K, n: a column of all K cards one contiguous
    block, the layout in which the arrays pass fastest, and each card's column contiguous, as
    LAPACK lays a matrix out), and the sums of squares (K,); the linkage's motion on all K n angles
    in one call, unless ``known`` (3, K, n) holds k ds/dtheta, s and r at these params already
    (the previous stage's last evaluation: its crank angles are these, the new harmonics at zero).
    """
    size = params.shape[1]
    augmented = np.empty((size + 1,) + tc.shape)
    theta, ratio, _ = _angles(params[:, :-2], tc, augmented[2:-3])
    if known is None:
        s, ds = (value.reshape(theta.shape) for value in _rod(linkage, theta.ravel()))
        slope = np.multiply(params[:, -1:], ds, out=augmented[0])
        augmented[-2] = s
        residual = np.subtract(params[:, -1:] * s + params[:, -2:-1], p, out=augmented[-1])
    else:
        augmented[[0, -2, -1]] = known
        slope, residual = augmented[0], augmented[-1]
    np.multiply(slope, tc * ratio, out=augmented[1])
    augmented[2:-3] *= slope
    augmented[-3] = 1.0
    return augmented, (residual * residual).sum(axis=-1)


def _steps(augmented: np.ndarray) -> np.ndarray:
    """Gauss-Newton steps x (K, P) minimising |J x + r| for a stack of augmented matrices [J r] (K, n, P + 1).

    Householder QR of the augmented matrix ([Bjorck1996], ch. 2): its triangle holds R of J
    and, in its last column, Q^T r, so R x = -Q^T r is solved by back substitution
    (``numpy.linalg.solve`` on a triangle exchanges no rows: the entries below the
    diagonal are exact zeros). A J of fewer rows than columns, or whose R has a diagonal
    entry below n eps times its largest (rank-deficient to working precision), is solved
    by ``numpy.linalg.lstsq`` instead (the minimum-norm solution by the SVD), one card at a time.
    The triangle comes from ``numpy.linalg.qr(..., mode="raw")`` (the factorised matrix, R on and
    above its diagonal) with zeros put below the diagonal by a mask made once per size: the R of
    ``mode="r"`` bit for bit, without ``numpy.triu`` building its mask at every Gauss-Newton step.
    """
    rows, size = augmented.shape[1], augmented.shape[2] - 1
    full_rank = np.zeros(len(augmented), dtype=bool)
    if rows >= size:
        factored = np.linalg.qr(augmented, mode="raw")[0].swapaxes(1, 2)  # R on and above the diagonal
        triangle = np.where(_upper(size), factored[:, :size], 0.0)
        diagonal = np.abs(np.diagonal(triangle, axis1=1, axis2=2))
        full_rank = diagonal.min(axis=1) > _EPSILON * rows * diagonal.max(axis=1)
        if full_rank.all():
            return -np.linalg.solve(triangle[:, :, :size], triangle[:, :, size:])[:, :, 0]
    steps = np.empty((augmented.shape[0], size))
    if full_rank.any():
        steps[full_rank] = -np.linalg.solve(triangle[full_rank, :, :size], triangle[full_rank, :, size:])[:, :, 0]
    for card in np.flatnonzero(~full_rank):
        steps[card] = np.linalg.lstsq(augmented[card, :, :size], -augmented[card, :, size], rcond=None)[0]
    return steps


@lru_cache(maxsize=8)
def _upper(size: int) -> np.ndarray:
    """The mask (size, size + 1) of the entries on and above the diagonal (``numpy.triu``'s)."""
    mask = ~np.tri(size, size + 1, -1, dtype=bool)
    mask.flags.writeable = False
    return mask


def _solved(linkage: Mechanism, tc: np.ndarray, p: np.ndarray, params: np.ndarray, bound: np.ndarray | None,
            known: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The sums of squares (K,) of K cards at ``params`` (K, P), the Gauss-Newton steps (K, P) from
    there of the cards whose sum is at most ``bound`` (K,), of every card when it is None (the
    other rows are left unset), and k ds/dtheta, s and r there (3, K, n; ``known`` of
    :func:`_evaluate`, which it takes).

    The cards go :data:`_BLOCK` at a time through :func:`_evaluate` and :func:`_steps`: a block's
    augmented matrices are factorised while they are still in a core's cache. Each card's
    figures are its own, whatever the block.
    """
    if len(params) > _BLOCK:
        blocks = [_solved(linkage, tc[block], p[block], params[block], None if bound is None else bound[block],
                          None if known is None else known[:, block])
                  for block in (slice(start, start + _BLOCK) for start in range(0, len(params), _BLOCK))]
        return (np.concatenate([cost for cost, _, _ in blocks]), np.concatenate([steps for _, steps, _ in blocks]),
                np.concatenate([evaluated for _, _, evaluated in blocks], axis=1))
    augmented, cost = _evaluate(linkage, tc, p, params, known)
    matrices = augmented.transpose(1, 2, 0)
    wanted = None if bound is None else cost <= bound
    if wanted is None or wanted.all():
        steps = _steps(matrices)
    else:
        steps = np.empty(params.shape)
        if wanted.any():
            steps[wanted] = _steps(matrices[wanted])
    return cost, steps, augmented[[0, -2, -1]]


def _least_squares(linkage: Mechanism, tc: np.ndarray, p: np.ndarray, params: np.ndarray,
                   known: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Gauss-Newton on sum_i (k s(theta(t_i)) + c - p_i)^2 with step halving ([Bjorck1996], ch. 9), for K
    cards at once; their parameters (K, P), sums of squares (K,) and k ds/dtheta, s and r there
    (3, K, n: ``known`` of the next stage, as this one takes it of the last).

    ``params`` holds the angle parameters of :func:`_angles`, then c [m] and k [-], one row
    per card. Each card takes its own sequence of iterates: a new step after each accepted
    one (at most :data:`_FIT_ITERATIONS`), the step halved when it does not lower the sum of
    squares (at most :data:`_LINE_SEARCH` times), done when the step is below
    :data:`_FIT_TOLERANCE`; the cards still iterating are evaluated together, and a card
    leaves that set when it is done.
    """
    params = params.copy()
    scale = np.ones_like(params)
    scale[:, 1] = 0.5 * (tc[:, -1] - tc[:, 0])
    cost, step, known = _solved(linkage, tc, p, params, None, known)
    solves, halvings = np.ones(len(params), dtype=int), np.zeros(len(params), dtype=int)
    active = np.ones(len(params), dtype=bool)
    while True:
        active &= ~(np.abs(step) * scale <= _FIT_TOLERANCE).all(axis=1)
        if not active.any():
            return params, cost, known
        rows = slice(None) if active.all() else active
        trial = params[rows] + step[rows]
        # a trial that lowers the sum of squares gets its step, unless its card has had all its solves
        bound = np.where(solves[rows] < _FIT_ITERATIONS, cost[rows], -np.inf)
        trial_cost, trial_step, evaluated = _solved(linkage, tc[rows], p[rows], trial, bound)
        better = np.zeros_like(active)
        better[rows] = trial_cost <= cost[rows]
        params[better], cost[better] = trial[better[rows]], trial_cost[better[rows]]
        if better.all():
            known = evaluated
        else:
            known[:, better] = evaluated[:, better[rows]]
        renewed = better & (solves < _FIT_ITERATIONS)
        step[renewed] = trial_step[renewed[rows]]
        solves[renewed] += 1
        halvings[renewed] = 0
        rejected = active & ~better
        step[rejected] *= 0.5
        halvings[rejected] += 1
        active = renewed | (rejected & (halvings < _LINE_SEARCH))


def fit_rotation(linkage: Mechanism, time: np.ndarray, position: np.ndarray, harmonics: int = 0) -> RotationFit:
    """Crank rotation that best explains a time-stamped card, uniform or with a periodic speed variation.

    The measured position is p_i = c + k s(theta_i), s the exact position curve of
    ``linkage`` (A (psi - psi_bottom)), c the dynamometer's zero and k its scale (near 1
    for positions already scaled to the unit's stroke); the parameters minimise
    sum (c + k s(theta_i) - p_i)^2, with the crank angles of

    * uniform rotation: theta_i = theta_0 + omega t_i (``harmonics=0``);
    * steady running with a crank speed that varies periodically over the cycle (as the
      machine's equation of motion of [SK8Rotation2013] makes it):
      theta_i = theta_0 + omega t_i + sum_{j<=K} (a_j cos j phi_i + b_j sin j phi_i),
      phi_i = omega t_i, so omega is the mean crank speed over a cycle.

    The start comes from the stroke-branch map of :func:`crank_angle_from_position`,
    unwrapped along time and fitted by a straight line (no assumption on how many
    cycles the card holds); then Gauss-Newton with the exact Jacobian through
    ds/dtheta = A psi', halving a step that does not lower the sum of squares, each
    step a linear least-squares problem solved by QR ([Bjorck1996]); the
    uniform fit first, then the first two harmonics, then the rest, each fit started
    from the previous one with the new terms at zero (a large speed variation, which a
    uniform start can miss, is found through the two harmonics that carry most of it).
    The speed and acceleration at every sample are the derivatives of the fitted series:
    omega = omega_m (1 + sum_j j (b_j cos j phi - a_j sin j phi)),
    alpha = -omega_m^2 sum_j j^2 (a_j cos j phi + b_j sin j phi), omega_m the mean speed.
    This is :func:`fit_rotations` for one card.

    Parameters
    ----------
    linkage : Linkage
        The unit, with its rotation direction.
    time : numpy.ndarray
        Sample times [s], strictly increasing.
    position : numpy.ndarray
        Polished-rod positions [m], close to the unit's stroke from its bottom (the
        start uses them as such).
    harmonics : int
        Number K of harmonics of the speed variation (0: uniform rotation).

    Returns
    -------
    RotationFit
        Crank angle [rad], speed [rad/s] and acceleration [rad/s²] of every sample,
        start angle [rad], mean speed omega [rad/s], position offset [m] and scale, RMS
        position residual [m] of this fit and of the uniform fit.

    References
    ----------
    [Takacs2016] (the crank angle against time from dynamometer data);
    [SK8Rotation2013] (exact kinematics, eq. 6; non-uniform crank rotation);
    [Bjorck1996] (Gauss-Newton with step halving, ch. 9; least squares by QR, ch. 2).

    Positions of SK8-3,5-4000 at omega = 0.6283 rad/s (6 strokes/min) from a crank
    angle of 1 rad, sampled at uneven times, give those numbers back:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> t = np.sort(np.random.default_rng(1).uniform(0.0, 10.0, 150))
    >>> theta = 1.0 + 0.2 * np.pi * t
    >>> fit = fit_rotation(sk8, t, _rod(sk8, theta)[0])
    >>> abs(fit.speed / (0.2 * np.pi) - 1.0) < 1e-9, fit.rms < 1e-9
    (True, True)
    >>> bool(np.max(np.abs(np.sin(0.5 * (fit.crank_angle - theta)))) < 1e-9)   # same angles, modulo 2 pi
    True

    With the crank speed varying by +-10 % (theta = omega t + 0.1 sin omega t) the
    uniform fit misses the mean speed and the positions; one harmonic recovers both:

    >>> theta = 1.0 + 0.2 * np.pi * t + 0.1 * np.sin(0.2 * np.pi * t)
    >>> uniform, periodic = (fit_rotation(sk8, t, _rod(sk8, theta)[0], k) for k in (0, 1))
    >>> abs(uniform.speed / (0.2 * np.pi) - 1.0) > 0.01, uniform.rms > 0.01
    (True, True)
    >>> abs(periodic.speed / (0.2 * np.pi) - 1.0) < 1e-9, periodic.rms < 1e-9, periodic.uniform_rms == uniform.rms
    (True, True, True)

    and with them the speed omega (1 + 0.1 cos omega t) and acceleration -0.1 omega^2 sin omega t:

    >>> w = 0.2 * np.pi
    >>> bool(np.allclose(periodic.crank_speed, w * (1 + 0.1 * np.cos(w * t)), rtol=1e-9, atol=0))
    True
    >>> bool(np.allclose(periodic.crank_acceleration, -0.1 * w**2 * np.sin(w * t), rtol=0, atol=1e-9 * w**2))
    True
    """
    t, p = time_samples(time, position)
    return fit_rotations(linkage, t[None, :], p[None, :], harmonics)[0]


def time_samples(time: np.ndarray, position: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """One card's sample times [s] and positions [m] as float arrays, refused (:class:`CardError`)
    unless they are matching 1-D arrays of at least 3 samples.

    >>> time_samples(np.arange(3.0), np.zeros(4))
    Traceback (most recent call last):
    ...
    pumpjack_cli.errors.CardError: time fit: needs matching 1-D arrays of at least 3 samples, got (3,) and (4,)
    """
    t = np.asarray(time, dtype=float)
    p = np.asarray(position, dtype=float)
    if t.ndim != 1 or t.shape != p.shape or t.size < 3:
        raise CardError(f"time fit: needs matching 1-D arrays of at least 3 samples, got {t.shape} and {p.shape}")
    return t, p


def fit_input_errors(time: np.ndarray, position: np.ndarray, harmonics: int) -> list[str]:
    """Why :func:`fit_rotations` refuses each card of (K, n) arrays of times [s] and positions [m]:
    the message, or '' for a card it fits.

    >>> fit_input_errors(np.array([[0.0, 1.0, 2.0], [0.0, 1.0, 1.0]]), np.zeros((2, 3)), 0)
    ['', 'time fit: time must increase strictly']
    """
    samples = time.shape[1]
    finite = np.all(np.isfinite(time), axis=1) & np.all(np.isfinite(position), axis=1)
    increasing = np.all(np.diff(time, axis=1) > 0, axis=1)
    enough = harmonics >= 0 and samples >= 2 * harmonics + 3
    return np.where(~finite, "time fit: time and position must be finite numbers",
                    np.where(~increasing, "time fit: time must increase strictly",
                             "" if enough else f"time fit: {harmonics} harmonics need at least {2 * harmonics + 3} "
                                               f"samples, got {samples}")).tolist()


def fit_rotations(linkage: Mechanism, time: np.ndarray, position: np.ndarray, harmonics: int = 0) -> list[RotationFit]:
    """The crank rotations of K time-stamped cards of one unit, each as :func:`fit_rotation` fits it, in one
    array computation.

    The same model, start, stages (uniform, :data:`_FIRST_HARMONICS` harmonics, then
    ``harmonics``), step halving, tolerances and convergence rule as :func:`fit_rotation`,
    per card: every card takes the sequence of iterates its single fit takes, while each
    evaluation (the linkage's motion at the crank angles of all the cards still
    iterating, their Jacobians, a stacked QR of them) is one array operation for each
    block of :data:`_BLOCK` cards; a card that has converged or stopped leaves the set
    iterated. A stage starts where the one before ended, its new harmonics at zero: the
    crank angles are those of the last evaluation, whose polished-rod positions, torque
    factors and residuals it takes over rather than compute them again.

    Parameters
    ----------
    linkage : Linkage
        The unit, with its rotation direction.
    time : numpy.ndarray
        Sample times [s] of the K cards, (K, n), strictly increasing along each row.
    position : numpy.ndarray
        Polished-rod positions [m], (K, n), close to the unit's stroke from its bottom.
    harmonics : int
        Number of harmonics of the speed variation, the same for every card (0: uniform).

    Returns
    -------
    list of RotationFit
        One per card, in order (:func:`fit_rotation`).

    Raises
    ------
    CardError
        Unless ``time`` and ``position`` are matching 2-D arrays of at least 3 samples a
        row; for the first card whose samples :func:`fit_rotation` refuses, with its
        message and the card's index (counted from 0) when there are several.

    References
    ----------
    [Takacs2016], [SK8Rotation2013], [Bjorck1996] (as :func:`fit_rotation`).

    Two cards of SK8-3,5-4000, at 6 and at 7 strokes/min, the second with a +-10 % speed
    variation, come out as each alone:

    >>> sk8 = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> t = np.linspace(0.0, 10.0, 180, endpoint=False)
    >>> theta = np.stack([1.0 + 0.2 * np.pi * t, 2.0 + 0.7 * t + 0.1 * np.sin(0.7 * t)])
    >>> both = fit_rotations(sk8, np.stack([t, t]), _rod(sk8, theta.ravel())[0].reshape(2, -1), 1)
    >>> alone = [fit_rotation(sk8, t, _rod(sk8, angles)[0], 1) for angles in theta]
    >>> [round(fit.speed, 9) for fit in both]
    [0.628318531, 0.7]
    >>> all(np.array_equal(a.crank_speed, b.crank_speed) and a.rms == b.rms for a, b in zip(both, alone))
    True
    >>> fit_rotations(sk8, np.stack([t, t[::-1]]), np.zeros((2, 180)))
    Traceback (most recent call last):
    ...
    pumpjack_cli.errors.CardError: time fit: time must increase strictly (card 1)
    """
    t = np.asarray(time, dtype=float)
    p = np.asarray(position, dtype=float)
    if t.ndim != 2 or t.shape != p.shape or t.shape[1] < 3:
        raise CardError(f"time fit: needs matching 2-D arrays (cards, samples) of at least 3 samples, "
                        f"got {t.shape} and {p.shape}")
    for card, error in enumerate(fit_input_errors(t, p, harmonics)):
        if error:
            raise CardError(error if len(t) == 1 else f"{error} (card {card})")
    tc = t - 0.5 * (t[:, :1] + t[:, -1:])
    unwrapped = np.unwrap(crank_angle_from_position(linkage, p, upstroke_points(p)))
    mean = np.mean(unwrapped, axis=1)
    omega = np.sum(tc * (unwrapped - mean[:, None]), axis=1) / np.sum(tc * tc, axis=1)
    start = np.column_stack([mean - omega * np.mean(tc, axis=1), omega, np.zeros(len(t)), np.ones(len(t))])
    params, cost, known = _least_squares(linkage, tc, p, start)
    uniform_rms = np.sqrt(cost / t.shape[1])
    fitted = 0
    for count in sorted({min(_FIRST_HARMONICS, harmonics), harmonics} - {0}):
        params, cost, known = _least_squares(linkage, tc, p, np.concatenate(
            [params[:, :-2], np.zeros((len(t), 2 * (count - fitted))), params[:, -2:]], axis=1), known)
        fitted = count
    theta, ratio, curvature = _angles(params[:, :-2], tc, np.empty((params.shape[1] - 4,) + t.shape))
    speed = params[:, 1:2]
    crank_speed, crank_acceleration = speed * ratio, speed**2 * curvature
    rms = np.sqrt(cost / t.shape[1])
    return [RotationFit(crank_angle=theta[k], crank_speed=crank_speed[k], crank_acceleration=crank_acceleration[k],
                        start_angle=float(theta[k, 0]),
                        speed=float(speed[k, 0]), offset=float(params[k, -2]), scale=float(params[k, -1]),
                        rms=float(rms[k]), uniform_rms=float(uniform_rms[k])) for k in range(len(t))]
