"""What the pump card says: the pump's condition, by explainable rules on measured features.

A pump card (plunger position and net plunger load, :mod:`.downhole`) is read for the
features an analyst looks at ([Rowlan2008], [McCoyRowlanPodio], [EchometerLeakValve],
[EchometerPumpCards]), each a number per card, computed for K cards of one well at once
(arrays (K, N) in, (K,) out; no loop over cards):

* the **reference loads** of [Rowlan2008]: on the pump card the buoyant rod weight W_rf is
  the zero line and W_rf + F_o the fluid-load line, F_o from the fluid level (or, without
  one, F_o max, the fluid level at the pump). The card's own **fluid load** (upstroke
  minus downstroke load level) and **mean load** are read against F_o;
* the **valve points**, where the load crosses 10 %, 50 % and 90 % of the card's fluid
  load: on the upstroke the travelling valve closes (10 %) and the standing valve opens
  (90 %); on the downstroke the standing valve closes (90 %) and the travelling valve
  opens (10 %); the 50 % point of the downstroke is the fillage;
* the **load-transfer travels** (slopes): the plunger travel over which the load is picked
  up (10 % to 90 %) and released (90 % to 10 %); the released share of the travel left
  to the bottom, the **unloading sharpness**;
* the load on the plunger while it moves **slowly**: rising towards the top (upstroke, top
  quarter of the stroke, at 15 % to 50 % of its mean speed) and falling towards the bottom
  (downstroke, bottom quarter): a sound valve lets the load go or takes it up only when the
  plunger turns, a leaking one as soon as the plunger moves slower than the leak;
* **spikes** at the ends of the stroke: how far the load goes below the downstroke level
  in the lowest 10 % of the stroke, or above the upstroke level in the highest 10 %;
* the **card area** against the ideal rectangle F_o x gross stroke.

The rules (each with its source in ``docs/diagnosis.md``) turn the features into a score
in 0..1 per condition of :data:`CONDITIONS`; the label is the best score, the confidence
the best score less half the second, and the second-best label is given when its score
is at least :data:`SECOND_SCORE`. No shape is matched against templates; no concavity of
the card is tested (the patented tests of US 10,990,846 and US 9,810,212 are not used).

Across strokes, :func:`sequence_conditions` tells a pump going off from gas interference
by how the fillage moves from card to card.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ...errors import DownholeError
from ..sampling import ahead, behind
from .analysis import as_cards, rolled, series_work
from .string import RodString

#: The labels, in the order of :attr:`Diagnosis.scores`.
CONDITIONS = ("full", "fluid_pound", "gas_interference", "travelling_valve_leak", "standing_valve_leak",
              "tagging_down", "tagging_up", "unanchored_tubing", "rod_part")
#: A second label is given when its score reaches this.
SECOND_SCORE = 0.25
#: Share of the stroke at its ends where the load of the slowly moving plunger is read.
END_TRAVEL = 0.25
#: A slowly moving plunger: its speed between these shares of its mean speed 2 S / T.
SLOW = (0.15, 0.5)
#: Share of the stroke at its ends where spikes are looked for.
SPIKE_TRAVEL = 0.1
#: Load levels (shares of the card's fluid load) of the valve points.
TRANSFER_LEVELS = (0.1, 0.5, 0.9)
#: The upstroke and downstroke load levels: medians over these shares of the stroke (as
#: :func:`.analysis.summarise_pump_card`).
UPSTROKE_BAND = (0.6, 0.9)
DOWNSTROKE_BAND = (0.1, 0.4)

#: Thresholds of the rules: (no evidence, full evidence), dimensionless; reasons in docs/diagnosis.md.
RULES = {
    "below_zero": (0.10, 0.25),        # mean load below the zero line / F_o: missing rod weight
    "no_fluid_load": (0.70, 0.50),     # card fluid load / F_o
    "flat": (0.30, 0.15),              # card fluid load / F_o of a flat card
    "on_zero": (0.15, 0.05),           # |mean load| / F_o of a flat card on the zero line
    "spike": (0.13, 0.21),             # end-of-stroke spike / card fluid load
    "incomplete": (0.07, 0.11),        # 1 - fillage
    "sharp": (0.25, 0.15),             # unloading sharpness: released share of the travel to the bottom
    "lost_slowly": (0.12, 0.22),       # 1 - load of the plunger rising slowly to the top (share of F_o)
    "gained_slowly": (0.14, 0.22),     # load of the plunger falling slowly to the bottom (share of F_o)
    "slanted": (0.008, 0.014),         # shorter of the two transfer travels / stroke
    "alike": (0.40, 0.60),             # shorter / longer transfer travel
}


def ramp(value, rule: str) -> np.ndarray:
    """Evidence 0..1 of a rule: 0 at its first threshold, 1 at its second, linear between
    (either order); NaN (no such point on the card) is no evidence.

    >>> ramp(np.array([0.05, 0.16, 0.3]), "below_zero").round(6).tolist()
    [0.0, 0.4, 1.0]
    """
    none, full = RULES[rule]
    with np.errstate(invalid="ignore"):
        share = np.clip((np.asarray(value, dtype=float) - none) / (full - none), 0.0, 1.0)
    return np.nan_to_num(share, nan=0.0)


def _first_crossing(x: np.ndarray, y: np.ndarray, mask: np.ndarray, level: float, rising: bool) -> np.ndarray:
    """x where y first reaches ``level`` among the samples of ``mask`` (in time order), interpolated
    from the sample before when it is in the mask too; NaN where it never does."""
    hit = mask & ((y >= level) if rising else (y <= level))
    found = hit.any(axis=1)
    i = np.argmax(hit, axis=1)
    rows = np.arange(len(x))
    j = np.maximum(i - 1, 0)
    y0, y1 = y[rows, j], y[rows, i]
    usable = (i > 0) & mask[rows, j] & (y1 != y0)
    with np.errstate(invalid="ignore", divide="ignore"):
        weight = np.clip(np.where(usable, (level - y0) / np.where(usable, y1 - y0, 1.0), 1.0), 0.0, 1.0)
    return np.where(found, x[rows, j] + weight * (x[rows, i] - x[rows, j]), np.nan)


def _running_median(values: np.ndarray, top: np.ndarray, window: int) -> np.ndarray:
    """The running median over ``window`` (odd) samples within the upstroke (samples 0 to ``top`` of
    each row) and within the downstroke (the rest), never across the turn: each part's end values
    stand for the samples beyond its ends. Both parts in one selection: each row laid out as its
    upstroke and its downstroke, each padded with its end values, the median of every window of
    that layout taken, and each sample's read off its own part."""
    samples = values.shape[1]
    half = window // 2
    top = top[:, None]
    laid = np.arange(samples + 4 * half)[None, :]          # the upstroke padded, then the downstroke padded
    source = np.where(laid <= top + 2 * half, np.clip(laid - half, 0, top),
                      np.clip(laid - 3 * half, top + 1, samples - 1))
    rows = np.arange(len(values))[:, None]
    windows = np.lib.stride_tricks.sliding_window_view(values[rows, source], window, axis=1)
    medians = np.partition(windows, half, axis=-1)[..., half]
    index = np.arange(samples)[None, :]
    return medians[rows, np.where(index <= top, index, index + 2 * half)]


def _cyclic_mean(values: np.ndarray, window: int) -> np.ndarray:
    """The mean over ``window`` (odd) samples centred on each sample, around the cycle, by cumulative sums."""
    half = window // 2
    sums = np.cumsum(np.concatenate((values[:, values.shape[1] - half - 1:], values, values[:, :half]), axis=1),
                     axis=1)
    return (sums[:, window:] - sums[:, :-window]) / window


def _masked_median(values: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """The median of each row's values over its mask; NaN for an empty row."""
    count = mask.sum(axis=1)
    ordered = np.sort(np.where(mask, values, np.inf), axis=1)          # the mask's values first
    low = np.take_along_axis(ordered, np.maximum((count - 1) // 2, 0)[:, None], axis=1)[:, 0]
    high = np.take_along_axis(ordered, np.minimum(count // 2, values.shape[1] - 1)[:, None], axis=1)[:, 0]
    return np.where(count > 0, 0.5 * (low + high), np.nan)


def _masked(values: np.ndarray, mask: np.ndarray, reduce) -> np.ndarray:
    """``reduce`` (numpy.nanmedian, nanmin, nanmax, nanmean) of values over a mask per row; NaN for an empty row."""
    empty = np.asarray(~mask.any(axis=1))
    with np.errstate(invalid="ignore"):
        safe = np.where(mask | empty[:, None], np.where(mask, values, 0.0), np.nan)
        return np.where(empty, np.nan, reduce(safe, axis=1))


@dataclass(frozen=True)
class CardFeatures:
    """What the rules read off pump cards, one value per card (shape (K,)).

    Loads [N]: ``upstroke_load``, ``downstroke_load`` (levels), ``fluid_load`` (their
    difference), ``reference_load`` (F_o of [Rowlan2008]). Ratios to the reference load:
    ``fluid_load_ratio``, ``mean_load_ratio``. Shares of the gross stroke from its bottom
    (NaN where the load never crosses the level): ``travelling_valve_closing``,
    ``standing_valve_opening``, ``standing_valve_closing``, ``travelling_valve_opening``,
    ``fillage``. Travels [m]: ``gross_stroke``, ``pickup_travel``, ``unloading_travel``.
    Shares of the card's fluid load: ``slow_upstroke_load``, ``slow_downstroke_load``,
    ``bottom_spike``, ``top_spike``. ``unloading_sharpness`` [-]: unloading travel / travel
    from the standing valve's closing... (module docstring); ``area_ratio`` [-]: card work /
    (F_o x gross stroke).
    """

    upstroke_load: np.ndarray
    downstroke_load: np.ndarray
    fluid_load: np.ndarray
    reference_load: np.ndarray
    fluid_load_ratio: np.ndarray
    mean_load_ratio: np.ndarray
    travelling_valve_closing: np.ndarray
    standing_valve_opening: np.ndarray
    standing_valve_closing: np.ndarray
    travelling_valve_opening: np.ndarray
    fillage: np.ndarray
    gross_stroke: np.ndarray
    pickup_travel: np.ndarray
    unloading_travel: np.ndarray
    unloading_sharpness: np.ndarray
    slow_upstroke_load: np.ndarray
    slow_downstroke_load: np.ndarray
    bottom_spike: np.ndarray
    top_spike: np.ndarray
    area_ratio: np.ndarray


def card_features(pump_position, pump_load, reference_load) -> CardFeatures:
    """The features of pump cards (:func:`_features`); empty windows and masks are NaN, quietly."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)      # an all-NaN window: NaN is the answer
        return _features(pump_position, pump_load, reference_load)


def _features(pump_position, pump_load, reference_load) -> CardFeatures:
    """The features of pump cards (module docstring), K cards of one well at once.

    Parameters
    ----------
    pump_position : array_like
        Plunger position [m], up positive, shape (N,) or (K, N), in time order over one stroke.
    pump_load : array_like
        Net plunger load [N] (the zero line is W_rf), same shape.
    reference_load : float or array_like
        F_o [N] of [Rowlan2008]: from the fluid level, else with the fluid level at the pump;
        one value or one per card.

    Returns
    -------
    CardFeatures
        Arrays of shape (K,) (K = 1 for one card).
    """
    position, load = as_cards(pump_position, pump_load, "pump card")
    position, load = np.atleast_2d(position), np.atleast_2d(load)
    cards, samples = position.shape
    reference = np.broadcast_to(np.asarray(reference_load, dtype=float), (cards,))
    if not (np.isfinite(reference).all() and (reference > 0).all()):
        raise DownholeError(f"the reference fluid load must be positive and finite, got {reference_load}")
    start = np.argmin(position, axis=1)
    p, f = rolled(position, start), rolled(load, start)
    low, stroke = p[:, 0], np.ptp(p, axis=1)
    if not (stroke > 0).all():
        raise DownholeError(f"pump card {int(np.flatnonzero(~(stroke > 0))[0]) + 1} has no plunger stroke")
    x = (p - low[:, None]) / stroke[:, None]
    top = np.argmax(p, axis=1)
    upstroke = np.arange(samples)[None, :] <= top[:, None]
    downstroke = ~upstroke
    # a running median over 1/40 of the stroke's samples, within the upstroke and within the
    # downstroke (never across the turn), takes out noise and the ringing of a sharp load change
    # (no feature below needs a finer resolution); spikes use a 3-point mean
    window = max(3, (samples // 40) | 1)
    smooth = _running_median(f, top, window)
    light = (behind(f) + f + ahead(f)) / 3.0

    def band(mask, limits):
        return _masked_median(smooth, mask & (x >= limits[0]) & (x <= limits[1]))

    up, down = band(upstroke, UPSTROKE_BAND), band(downstroke, DOWNSTROKE_BAND)
    fluid = up - down
    scale = np.where(np.abs(fluid) > 1e-9 * reference, fluid, reference)[:, None]
    y, spiky, raw = ((values - down[:, None]) / scale for values in (smooth, light, f))
    closing, midway_up, opening = (_first_crossing(x, y, upstroke, level, True) for level in TRANSFER_LEVELS)
    released, fillage, drained = (_first_crossing(x, y, downstroke, level, False) for level in TRANSFER_LEVELS[::-1])
    pickup, unloading = opening - closing, released - drained
    # the plunger's velocity / its mean speed 2 S / T, from its position averaged over the window:
    # noise on a card's load makes the computed plunger jitter where it rests at a turn, and a
    # resting plunger is neither rising nor falling slowly
    steady = _cyclic_mean(x, window)
    velocity = (ahead(steady) - behind(steady)) * samples / 4.0
    slow = (np.abs(velocity) >= SLOW[0]) & (np.abs(velocity) <= SLOW[1])
    with np.errstate(invalid="ignore", divide="ignore"):
        sharpness = unloading / (1.0 - drained)
    work = series_work(np.fft.rfft(p, axis=1), np.fft.rfft(f, axis=1), samples)
    return CardFeatures(
        upstroke_load=up, downstroke_load=down, fluid_load=fluid, reference_load=np.array(reference),
        fluid_load_ratio=fluid / reference, mean_load_ratio=f.mean(axis=1) / reference,
        travelling_valve_closing=closing, standing_valve_opening=opening, standing_valve_closing=released,
        travelling_valve_opening=drained, fillage=fillage, gross_stroke=stroke,
        pickup_travel=pickup * stroke, unloading_travel=unloading * stroke, unloading_sharpness=sharpness,
        slow_upstroke_load=_masked(raw, upstroke & (x >= 1.0 - END_TRAVEL) & slow & (velocity > 0), np.nanmean),
        slow_downstroke_load=_masked(raw, downstroke & (x <= END_TRAVEL) & slow & (velocity < 0), np.nanmean),
        bottom_spike=-_masked(spiky, x <= SPIKE_TRAVEL, np.nanmin),
        top_spike=_masked(spiky, x >= 1.0 - SPIKE_TRAVEL, np.nanmax) - 1.0,
        area_ratio=work / (reference * stroke),
    )


@dataclass(frozen=True)
class Diagnosis:
    """The condition of K pump cards: ``label`` and ``second`` (text arrays, ``second`` empty
    where no other label comes close), ``confidence`` (0..1), ``scores`` (K, 9) in the
    order of :data:`CONDITIONS`, and the features the rules read."""

    label: np.ndarray
    confidence: np.ndarray
    second: np.ndarray
    scores: np.ndarray
    features: CardFeatures

    def card(self, index: int) -> Diagnosis:
        """The diagnosis of card ``index`` alone (arrays of one card)."""
        one = slice(index, index + 1)
        features = CardFeatures(*(np.asarray(value)[one] for value in vars(self.features).values()))
        return Diagnosis(self.label[one], self.confidence[one], self.second[one], self.scores[one], features)


def condition_scores(features: CardFeatures) -> np.ndarray:
    """The score 0..1 of every condition for every card, shape (K, 9), by the rules of
    ``docs/diagnosis.md`` (each line names its source there)."""
    ft = features
    ratio, level = ft.fluid_load_ratio, ft.mean_load_ratio
    flat = ramp(ratio, "flat")                                                # no fluid load on the plunger
    # rod part: the card below the zero line by the missing rods' weight, no fluid load; or
    # flat on the zero line (a part at the pump; a travelling valve stuck open looks alike)
    shallow = ramp(-level, "below_zero") * ramp(ratio, "no_fluid_load")
    loaded = (1.0 - flat) * (1.0 - shallow)                                   # a pump the rods work
    deep = flat * ramp(np.abs(level), "on_zero")
    # flat on the fluid-load line: no valve lets the load go (a standing valve stuck open or
    # leaking beyond the pump's rate, or a gas-locked pump)
    stuck = flat * ramp(np.abs(level - 1.0), "on_zero")
    spikes_down, spikes_up = ramp(ft.bottom_spike, "spike"), ramp(ft.top_spike, "spike")
    lost = ramp(1.0 - ft.slow_upstroke_load, "lost_slowly")
    gained = ramp(ft.slow_downstroke_load, "gained_slowly")
    incomplete = ramp(1.0 - ft.fillage, "incomplete")
    sharp = ramp(ft.unloading_sharpness, "sharp")
    shorter = np.fmin(ft.pickup_travel, ft.unloading_travel) / ft.gross_stroke
    longer = np.fmax(ft.pickup_travel, ft.unloading_travel) / ft.gross_stroke
    with np.errstate(invalid="ignore", divide="ignore"):
        alike = ramp(shorter / longer, "alike")
    slanted = ramp(shorter, "slanted") * alike
    valves = np.fmax(lost, gained)
    pound = incomplete * sharp                     # the load held until the plunger meets the liquid, then dropped
    scores = np.stack([
        np.zeros_like(ratio),                                                  # full: set below
        loaded * pound,                                                        # fluid pound
        np.fmax(loaded * incomplete * (1.0 - sharp) * (1.0 - gained), 0.6 * stuck),   # gas interference
        loaded * lost * (1.0 - gained),                                        # travelling valve leak
        np.fmax(loaded * gained * (1.0 - lost) * (1.0 - pound), stuck),        # standing valve leak
        loaded * spikes_down,                                                  # tagging down
        loaded * spikes_up,                                                    # tagging up
        loaded * slanted * (1.0 - valves) * (1.0 - incomplete),                # unanchored tubing
        np.fmax(shallow, deep),                                                # rod part
    ], axis=1)
    scores = np.nan_to_num(scores, nan=0.0)
    scores[:, 0] = loaded * (1.0 - scores[:, 1:].max(axis=1))                 # full: nothing else
    return scores


def classify(features: CardFeatures) -> Diagnosis:
    """Label, confidence and second-best label of every card from its features."""
    scores = condition_scores(features)
    ranked = np.argsort(-scores, axis=1, kind="stable")
    rows = np.arange(len(scores))
    best, runner = scores[rows, ranked[:, 0]], scores[rows, ranked[:, 1]]
    names = np.array(CONDITIONS, dtype=object)
    second = np.where(runner >= SECOND_SCORE, names[ranked[:, 1]], "")
    return Diagnosis(names[ranked[:, 0]], np.clip(best - 0.5 * runner, 0.0, 1.0), second, scores, features)


def diagnose(pump_position, pump_load, reference_load) -> Diagnosis:
    """:func:`classify` of :func:`card_features`: the condition of K pump cards of one well.

    Parameters are those of :func:`card_features`.

    Examples
    --------
    A rectangle from 0 to F_o over the whole stroke is a full pump; the same card whose load
    falls only when the plunger has come down 40 % of the stroke pounds fluid at 60 % fillage:

    >>> t = np.linspace(0.0, 1.0, 200, endpoint=False)
    >>> z = 0.5 - 0.5 * np.cos(2 * np.pi * t)
    >>> full = np.where(t < 0.5, 10e3, 0.0)
    >>> pound = np.where((t < 0.5) | (z > 0.6), 10e3, 0.0)
    >>> found = diagnose(np.vstack([z, z]), np.vstack([full, pound]), 10e3)
    >>> found.label.tolist(), np.round(found.features.fillage, 2).tolist()
    (['full', 'fluid_pound'], [1.0, 0.6])
    """
    return classify(card_features(pump_position, pump_load, reference_load))


def hanging_depth(rods: RodString, hanging_weight, fluid_density: float) -> np.ndarray:
    """Depth [m] along the rods at which the string above weighs ``hanging_weight`` [N] in the
    fluid: where a string carrying that weight at the polished rod, on average over the cycle,
    has parted. Over a steady cycle the rods' inertia and damping forces average out (their
    velocity is periodic), so a string hanging free from the polished rod loads it, on
    average, with its buoyant weight ([EchometerPumpCards]: a shallow part plots below the
    zero line by the weight of the rods lost).

    >>> rods = RodString(np.array([500.0, 500.0]), np.full(2, 3e-4), np.full(2, 2.1e11), np.array([4.0, 2.0]))
    >>> w = rods.buoyant_weight_per_length(0.0)
    >>> round(float(hanging_depth(rods, 500 * w[0] + 250 * w[1], 0.0)), 6)
    750.0
    """
    static = rods.static_tension(fluid_density)
    above = static[0] - static                          # weight of the rods above each joint
    ends = np.concatenate([[0.0], np.cumsum(rods.length)])
    return np.interp(np.asarray(hanging_weight, dtype=float), above, ends)


#: A move of the fillage from card to card larger than this [share of the stroke] counts as one.
SEQUENCE_STEP = 0.02
#: Cards of the window that :func:`sequence_conditions` reads, the card and those before it.
SEQUENCE_WINDOW = 8
#: A march: the net change over the window is at least this share of the way the fillage went.
MARCH = 0.6
#: Back and forth: the net change is at most this share of the way the fillage went.
JUMPS = 0.4


def sequence_conditions(fillage, window: int = SEQUENCE_WINDOW) -> np.ndarray:
    """What a well's consecutive cards say together, one text per card (``""`` until the window holds
    three cards), from the load-transfer point (the fillage) over the last ``window`` cards:

    * ``pump_off``: it marches down: it fell by more than 3 :data:`SEQUENCE_STEP` and the fall is
      at least :data:`MARCH` of all the way it went (an efficiency ratio, net over path);
    * ``gas_interference``: it jumps back and forth: the moves larger than :data:`SEQUENCE_STEP` add
      up to more than 4 of them while the net change is at most :data:`JUMPS` of the path;
    * ``steady`` otherwise (a fillage that holds, wanders within the noise, or climbs back).

    A pump going off loses fillage stroke after stroke as the fluid level falls to the intake;
    gas coming and going fills the barrel more on one stroke, less on the next
    ([McCoyRowlanPodio]; docs/diagnosis.md). A card without a fillage (NaN: its analysis failed)
    is left out of the windows and gets ``""``.

    >>> marching = np.linspace(1.0, 0.6, 10)
    >>> jumping = np.tile([0.9, 0.65], 5)
    >>> sequence_conditions(marching)[-1], sequence_conditions(jumping)[-1], sequence_conditions(np.full(10, 0.97))[-1]
    ('pump_off', 'gas_interference', 'steady')
    """
    given = np.asarray(fillage, dtype=float)
    if given.ndim != 1:
        raise DownholeError(f"a sequence of fillages is one value per card, got shape {given.shape}")
    known = np.isfinite(given)
    result = np.full(given.size, "", dtype=object)
    result[known] = _sequence(given[known], window)    # a card without a fillage is left out, and empty
    return result


def _sequence(fill: np.ndarray, window: int) -> np.ndarray:
    """:func:`sequence_conditions` of fillages that are all known, every window at once."""
    count = fill.size
    out = np.full(count, "", dtype=object)
    if count < 3:
        return out
    moves = np.abs(np.diff(fill))
    path = np.concatenate([[0.0], np.cumsum(moves)])
    big = np.concatenate([[0.0], np.cumsum(np.where(moves > SEQUENCE_STEP, moves, 0.0))])
    end = np.arange(2, count)
    start = np.maximum(end - window + 1, 0)
    net, travel, jumps = fill[end] - fill[start], path[end] - path[start], big[end] - big[start]
    off = (net < -3.0 * SEQUENCE_STEP) & (-net >= MARCH * travel)
    gas = (jumps > 4.0 * SEQUENCE_STEP) & (np.abs(net) <= JUMPS * travel)
    out[2:] = np.where(off, "pump_off", np.where(gas, "gas_interference", "steady"))
    return out


#: The damping factors the energy balance may give before its premise is doubted: below, the rods
#: would ring on for tens of strokes; above, a quarter of the first mode's critical damping. A
#: stated choice, not a published range (docs/diagnosis.md).
PLAUSIBLE_DAMPING = (0.01, 0.5)


def balanced_dampings(string: RodString, period, position, load, fluid_load, *, fluid_density: float,
                      fallback: float, method: str = "gibbs", solve=None) -> list[tuple[float, str]]:
    """Gibbs' nu of each of K cards of one rod string (shape (K, N), periods (K,)) from the energy
    balance of the rods with the pump's hydraulic work F_o S_n, solved together
    (:func:`.downhole.dampings_from_fluid_load`), or ``fallback`` with the reason: when the balance
    has no root (a parted string, a pump that lifts nothing, a card doing less work than F_o S_n
    even with undamped rods or more than the largest damping explains), or when its root lies
    outside :data:`PLAUSIBLE_DAMPING` (a pump whose work is not F_o S_n: a leaking valve, a
    fluid level far from the well file's). Returns (nu, reason) per card, the reason empty when
    the balance held.

    The balance is exact for a full or fluid-pounding pump with the well's fluid level; on other
    cards it drifts (0.02 to 1.9 times the true damping on the corpus of docs/diagnosis.md), and
    the labels are made to hold for such a damping and 15 % either side of it. ``solve`` is the
    diagnostic of a deviated well, for one card (:func:`.downhole.dampings_from_fluid_load`).
    """
    from .downhole import dampings_from_fluid_load

    try:
        roots, problems = dampings_from_fluid_load(string, period, position, load, fluid_load,
                                                   fluid_density=fluid_density, method=method, solve=solve)
    except DownholeError as exc:
        count = np.atleast_2d(position).shape[0]
        roots, problems = np.full(count, np.nan), (str(exc),) * count
    low, high = PLAUSIBLE_DAMPING
    out = []
    for nu, problem in zip(roots, problems):
        if problem:
            out.append((fallback, f"no damping balances this card's energy ({problem})"))
        elif not low <= nu <= high:
            out.append((fallback, f"the energy balance gives damping factor {nu:.3g}, outside {low:g}-{high:g}: the "
                                  f"pump's work is not F_o S_n (a leaking valve, gas, a fluid level far from the "
                                  f"well's)"))
        else:
            out.append((float(nu), ""))
    return out


def balanced_damping(string: RodString, period: float, position, load, fluid_load: float, *, fluid_density: float,
                     fallback: float, method: str = "gibbs", solve=None) -> tuple[float, str]:
    """:func:`balanced_dampings` of ONE card (shape (N,)): (nu, reason)."""
    return balanced_dampings(string, period, np.asarray(position)[None], np.asarray(load)[None], fluid_load,
                             fluid_density=fluid_density, fallback=fallback, method=method, solve=solve)[0]
