"""Loading of a beam pumping unit against its ratings: gearbox, structure, stroke, power.

* gearbox loading = 100 max |T| / T_rated, T the net gearbox torque over the cycle
  (the gearbox rating is a peak-torque rating, [API11E]);
* structure loading = 100 max W / W_rated, W the polished-rod load;
* stroke = 100 S / S_max;
* polished-rod power P_pr = (work per cycle) x (cycles per second), the work being the
  area of the card, the closed integral of W ds [J] (the work of the polished-rod force);
* cyclic load factor CLF = T_rms / T_mean, the ratio of the RMS to the average net
  gearbox torque over the cycle ([DurhamLockard1988]). At uniform crank speed
  T_mean = (card work) / 2 pi (the counterbalance and the structure do no net work),
  so T_mean omega = P_pr;
* equivalent (RMS) torque T_rms, and the motor power this needs by the RMS-equivalent
  rule: a motor loaded by a cyclic torque heats as if loaded steadily by its RMS
  value, so its rating must be at least P_motor = T_rms omega / eta = CLF P_pr / eta,
  omega the mean crank speed and eta the efficiency of the drive between motor and
  crank ([DurhamLockard1988]; the tabulated CLF values used when no torque curve is
  known are replaced here by the CLF of the curve itself). The rule assumes the motor
  torque follows the gearbox torque (a stiff drive at near-uniform speed); a high-slip
  motor and the flywheel effect of the drive lower the real RMS.

Averages are over a uniform crank-angle grid, i.e. over time at uniform crank speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import TorqueError
from ..sampling import ahead, crank_grid
from .card import Card, loop_work
from ..mechanism import Mechanism


def card_work(linkage: Mechanism, card: Card) -> float:
    """Work done on the rods per cycle, the closed integral of W ds [J] (the card area).

    The polished-rod position s of each card point comes from the exact kinematics; the card is taken in the order of its crank angles (the order of
    time) and closed, and integrated by the trapezoidal rule along s.

    Parameters
    ----------
    linkage : Mechanism
        The unit.
    card : Card
        Load W [N] at crank angles [rad].

    Returns
    -------
    float
        Work per cycle [J]; positive when the rods are lifted heavier than they fall.

    References
    ----------
    [API11E] (polished-rod load and position); work of a force along its path.
    """
    return float(card_works(linkage, [card])[0])


def card_works(linkage: Mechanism, cards: list[Card]) -> np.ndarray:
    """:func:`card_work` of K cards of one unit, any lengths, their positions from one
    evaluation of the kinematics [J]."""
    angles = np.concatenate([np.asarray(card.crank_angle, dtype=float) for card in cards])
    loads = np.concatenate([np.asarray(card.load, dtype=float) for card in cards])
    positions = linkage.rod_position(angles)
    if not (np.all(np.isfinite(positions)) and np.all(np.isfinite(loads))):
        raise TorqueError("card work: the card is not finite at every point")
    lengths = {len(card.crank_angle) for card in cards}
    if len(lengths) == 1:      # cards of as many points: each row's work as loop_work sums it
        s, w = positions.reshape(len(cards), -1), loads.reshape(len(cards), -1)
        return np.sum(0.5 * (w + ahead(w)) * (ahead(s) - s), axis=-1)
    bounds = np.cumsum([len(card.crank_angle) for card in cards])[:-1]
    return np.array([loop_work(s, w) for s, w in zip(np.split(positions, bounds), np.split(loads, bounds))])


def cyclic_load_factor(net_torque: np.ndarray, weights: np.ndarray | None = None):
    """CLF = T_rms / T_mean over a cycle ([DurhamLockard1988]): a float, or one per cycle of
    ``net_torque`` (K, N), along the last axis.

    ``weights`` are the time shares of the samples (dt = dtheta / omega for a crank that
    does not turn uniformly); without them the samples are a uniform crank-angle grid
    at uniform speed. Raises :class:`TorqueError` when a mean torque is not positive
    (the unit does no net work on the rods: CLF undefined).

    >>> round(cyclic_load_factor(1.0 + np.sin(np.linspace(0, 2 * np.pi, 360, endpoint=False))), 6)   # sqrt(1.5)
    1.224745
    """
    t = np.asarray(net_torque, dtype=float)
    w = np.ones_like(t) if weights is None else np.asarray(weights, dtype=float)
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(w))):
        raise TorqueError("cyclic load factor: the net torque is not finite at every crank angle")
    total = np.sum(w, axis=-1)
    mean = np.sum(w * t, axis=-1) / total
    if not np.all(mean > 0):
        bad = float(np.ravel(mean)[np.flatnonzero(~(np.ravel(mean) > 0))[0]])
        raise TorqueError(f"cyclic load factor: the mean net torque is {bad:.6g} N·m; it must be positive "
                          f"(a card that does no work on the rods has no cyclic load factor)")
    found = np.sqrt(np.sum(w * t * t, axis=-1) / total) / mean
    return float(found) if found.ndim == 0 else found


@dataclass(frozen=True)
class Loading:
    """Loading against the ratings (SI; percentages in %).

    ``peak_net_torque`` max |T| [N·m] at ``peak_net_torque_angle`` [rad];
    ``gearbox_loading_percent``; ``peak_polished_rod_load`` max W [N];
    ``structure_loading_percent``; ``stroke``, ``max_stroke`` [m], ``stroke_percent``;
    ``card_work`` [J per cycle]; ``polished_rod_power`` [W]; ``mean_torque``,
    ``rms_torque`` [N·m]; ``cyclic_load_factor``; ``motor_power`` [W] by the RMS rule.
    """

    peak_net_torque: float
    peak_net_torque_angle: float
    gearbox_rating: float
    gearbox_loading_percent: float
    peak_polished_rod_load: float
    structure_rating: float
    structure_loading_percent: float
    stroke: float
    max_stroke: float
    stroke_percent: float
    card_work: float
    polished_rod_power: float
    mean_torque: float
    rms_torque: float
    cyclic_load_factor: float
    motor_power: float


def loading(net_torque: np.ndarray, card: Card, linkage: Mechanism, cycles_per_second: float, *,
            gearbox_rating: float, structure_rating: float, max_stroke: float,
            drive_efficiency: float = 1.0) -> Loading:
    """Loading of the gearbox, the structure and the motor for one card.

    Parameters
    ----------
    net_torque : ndarray
        T [N·m] on the uniform grid ``crank_grid(len(net_torque))`` (from theta = 0).
    card : Card
        The polished-rod load W [N] at crank angles [rad].
    linkage : Linkage
        The unit (stroke, card positions).
    cycles_per_second : float
        Pumping speed [1/s] (strokes per minute / 60).
    gearbox_rating, structure_rating, max_stroke : float
        T_rated [N·m], W_rated [N], S_max [m] (e.g. from :mod:`pumpjack_cli.core.designations`).
    drive_efficiency : float
        eta in (0, 1] between motor shaft and crank; 1 gives the power at the gearbox output.

    Returns
    -------
    Loading

    References
    ----------
    [API11E]; [DurhamLockard1988].

    Examples
    --------
    T = 10 kN·m + 5 kN·m sin(theta): peak 15 kN·m of a 30 kN·m rating = 50 %; CLF =
    sqrt(100 + 12.5)/10 = 1.0607; P_motor = T_rms 2 pi f = 10 606.6 N·m x 1.047 198 1/s = 11 107.2 W.

    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> lk = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> theta = crank_grid(3600)
    >>> card = Card(theta, np.where(np.sin(theta) > 0, 60e3, 40e3))
    >>> r = loading(10e3 + 5e3 * np.sin(theta), card, lk, 1 / 6, gearbox_rating=30e3, structure_rating=80e3,
    ...             max_stroke=3.5)
    >>> round(r.gearbox_loading_percent, 3), r.structure_loading_percent, round(r.cyclic_load_factor, 4)
    (50.0, 75.0, 1.0607)
    >>> round(r.motor_power, 1)
    11107.2
    """
    t = np.asarray(net_torque, dtype=float)
    for name, value in (("gearbox rating", gearbox_rating), ("structure rating", structure_rating),
                        ("maximum stroke", max_stroke), ("pumping speed", cycles_per_second)):
        if not (math.isfinite(value) and value > 0):
            raise TorqueError(f"loading: the {name} is {value!r}; it must be positive")
    if not (math.isfinite(drive_efficiency) and 0 < drive_efficiency <= 1):
        raise TorqueError(f"loading: the drive efficiency is {drive_efficiency!r}; it must lie in (0, 1]")
    clf = cyclic_load_factor(t)
    theta = crank_grid(t.size)
    i = int(np.argmax(np.abs(t)))
    peak = float(abs(t[i]))
    w_max = float(np.max(card.load))
    stroke = linkage.stroke
    work = card_work(linkage, card)
    mean = float(np.mean(t))
    rms = clf * mean
    return Loading(
        peak_net_torque=peak,
        peak_net_torque_angle=float(theta[i]),
        gearbox_rating=gearbox_rating,
        gearbox_loading_percent=100.0 * peak / gearbox_rating,
        peak_polished_rod_load=w_max,
        structure_rating=structure_rating,
        structure_loading_percent=100.0 * w_max / structure_rating,
        stroke=stroke,
        max_stroke=max_stroke,
        stroke_percent=100.0 * stroke / max_stroke,
        card_work=work,
        polished_rod_power=work * cycles_per_second,
        mean_torque=mean,
        rms_torque=rms,
        cyclic_load_factor=clf,
        motor_power=rms * 2.0 * math.pi * cycles_per_second / drive_efficiency,
    )


def stroke_peaks(linkage: Mechanism, crank_angle: np.ndarray, net_torque: np.ndarray):
    """The largest net torque T [N·m] of the upstroke and of the downstroke (the two peaks that a
    balanced unit makes equal, [Rowlan2004]); the upstroke runs from the bottom dead position
    through the upstroke travel. Floats, or one per cycle of ``net_torque`` (K, N).

    A torque of 5 N·m on every upstroke sample and 3 N·m on every downstroke sample:

    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> from pumpjack_cli.core.beam.counterbalance import upstroke_mask
    >>> lk = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    >>> stroke_peaks(lk, theta, np.where(upstroke_mask(lk, theta), 5.0, 3.0))
    (5.0, 3.0)
    """
    from .counterbalance import upstroke_mask

    t = np.asarray(net_torque, dtype=float)
    up = upstroke_mask(linkage, crank_angle)
    if not (up.any() and (~up).any()):
        raise TorqueError("stroke peaks: the crank-angle grid does not cover both strokes")
    if t.ndim == 1:
        return float(np.max(t[up])), float(np.max(t[~up]))
    return np.max(t[:, up], axis=-1), np.max(t[:, ~up], axis=-1)


def driving_work(net_torque: np.ndarray):
    """Work the gearbox does on the unit per revolution when it drives [J]: the integral of
    max(T, 0) over the crank angle, T [N·m] on a uniform grid of one revolution (a float, or
    one per cycle of ``net_torque`` (K, N)).

    The power T omega is that of the gearbox on the crank; over a cycle its integral is
    the integral of T dtheta whatever the crank speed, and with the negative part (the
    unit driving the motor) left out it is the energy a motor gives that is credited
    nothing for the energy it takes back. With T = T0 sin theta it is 2 T0.

    >>> round(driving_work(100.0 * np.sin(np.linspace(0, 2 * np.pi, 3600, endpoint=False))), 3)
    200.0
    """
    t = np.asarray(net_torque, dtype=float)
    if not np.all(np.isfinite(t)):
        raise TorqueError("driving work: the net torque is not finite at every crank angle")
    found = np.sum(np.maximum(t, 0.0), axis=-1) * (2.0 * np.pi / t.shape[-1])
    return float(found) if found.ndim == 0 else found
