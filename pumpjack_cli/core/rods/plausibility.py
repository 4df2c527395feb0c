"""One plausibility rule for every card a command reads: could this unit and its rods have made it?

A number an engineer acts on must not depend on which command read the card, so the
rule is one function, run once when a card is placed (``analysis.card_runs``), and a card
it refuses is refused with the same one line by ``torque``, ``reactions``, ``dynamics``,
``compare-redundancy``, ``downhole`` and as an error row by ``batch``.

With the unit's rods and fluid known (a ``[well]``), a card of a connected string
(W_r the rods' weight in air, W_rf in the well fluid, F_max = p_d A_p the largest fluid
load the plunger can carry, with no pressure below it; alpha = S omega^2 / (2 g) the
polished rod's acceleration at the ends of a harmonic stroke in units of g, S the stroke,
[Aliverdizade1951]):

* its median load is at least :data:`MEDIAN_SHARE` W_rf: over a steady cycle the
  inertia and damping forces of the rods average out (their velocity is periodic) and the
  pump's load is not negative on average, so the load sits about W_rf + the mean pump
  load; waves and asymmetric strokes move the median by far less than a quarter of W_rf;
* its peak load is at most :data:`PEAK_FACTOR` (W_r + F_max)(1 + 2 alpha): the whole string
  and the largest fluid load, accelerated, with half again for the rod waves;
* its load range is at most that same bound: the polished rod's load is never below zero
  (the carrier bar cannot push the rods down);
* (with or without a ``[well]``) its minimum load is not below zero by more than
  :data:`NEGATIVE_SHARE` of its peak, for the same reason;
* its minimum load is at most W_r: the polished rod never carries more than the whole
  string at the bottom of a downstroke;
* its load-transfer slope (range over stroke) is at most
  :data:`~pumpjack_cli.core.rods.downhole.LOAD_TRANSFER_MARGIN` times the rods' spring
  constant (:func:`~pumpjack_cli.core.rods.downhole.load_transfer_slope`).

A parted string is the one real card below the rods' weight: the polished rod then hangs
only the rods above the break, whose lower end is free. The wave equation run down from
the card with the whole string ([Gibbs1963], :func:`~pumpjack_cli.core.rods.downhole.pump_card`)
then finds the effective tension zero at the break at every instant: the constant
difference between the whole string's buoyant weight and the hanging part's passes down
unchanged and cancels the static tension of the rods below the break. A card whose
diagnosed load stays within :data:`PARTED_FLATNESS` of its load range of zero at some depth,
for some damping factor (the damping of the rods left is not known), passes with a warning
that gives that depth. A card from a connected string, at any scale, has no such depth: its
fluid load and inertia swing the load at every depth. A card whose loads a common unit
slip would bring into the window (kN written as lbf, lbf as N, kgf as N, a factor 1000)
is refused with the factor named.

Without a ``[well]`` only the gross slips are refused: a load range below
:data:`RATING_LOW` or above :data:`RATING_HIGH` times the unit's structure rating, or a peak
load above :data:`PEAK_RATING` times it (a beam loaded so far beyond its rating has yielded:
no running unit records such a card; 1.5 to 2 times is the overload met in the field).

The thresholds and their reasons: ``docs/cards.md``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import CardError
from ..constants import STANDARD_GRAVITY
from .downhole import LOAD_TRANSFER_MARGIN, load_transfer_slope
from .gibbs import march
from .string import RodString

#: A card's minimum load may lie below zero by at most this share of its peak load (a load cell's
#: zero and noise): the polished rod's load is never below zero, the carrier bar cannot push it down.
NEGATIVE_SHARE = 0.05
#: A connected string's median load is at least this share of W_rf.
MEDIAN_SHARE = 0.75
#: A connected string's peak load is at most this multiple of (W_r + F_max)(1 + 2 alpha).
PEAK_FACTOR = 1.5
#: A parted string's diagnosed load at the break stays within this share of the card's load
#: range of zero.
PARTED_FLATNESS = 0.1
#: A free end found below this share of the string's length is the pump carrying no load (a
#: string parted at the pump makes the same card): no parted-string warning.
PUMP_END = 0.95
#: Sections the string is cut into to find the break; the depth is found to L / BREAK_SECTIONS.
BREAK_SECTIONS = 100
#: Gibbs damping factors tried for the rods left hanging: zero and 0.005 to 2 in equal ratios
#: (the whole range a unit file may give).
BREAK_DAMPING = (0.0, *np.geomspace(0.005, 2.0, 24).tolist())
#: Harmonics of the card kept in finding the break: the rods' first modes, not the noise.
BREAK_HARMONICS = 30
#: The shortest string that can hang from a break: one API rod, 25 ft ([API11B]) [m].
SHORTEST_HANGING = 7.62
#: Without well data: a load range below RATING_LOW x the structure rating, or above RATING_HIGH
#: x that rating, or a peak load above PEAK_RATING x that rating.
RATING_LOW = 0.01
RATING_HIGH = 100.0
PEAK_RATING = 3.0
#: Unit slips of a load column: the factor that turns the read loads into the true ones,
#: and what it means.
LOAD_SLIPS = (
    (1000.0, "kN written as N, or klbf as lbf"), (1e-3, "N written as kN, or lbf as klbf"),
    (4.4482216152605, "lbf written as N"), (1 / 4.4482216152605, "N written as lbf"),
    (1000.0 / 4.4482216152605, "kN written as lbf"), (4.4482216152605 / 1000.0, "lbf written as kN"),
    (9.80665, "kgf written as N"), (1 / 9.80665, "N written as kgf"),
    (1000.0 / 9.80665, "kN written as kgf"), (9.80665 / 1000.0, "kgf written as kN"),
)


@dataclass(frozen=True)
class WellLimits:
    """What the rods and the fluid column can produce: the rods, the fluid density [kg/m^3],
    the largest fluid load on the plunger F_max = p_d A_p [N], and in a deviated hole the rods'
    weight along it."""

    rods: RodString
    fluid_density: float
    max_fluid_load: float
    #: The rods' buoyant weight along a deviated hole [N] (:func:`.deviated.axial_weight`), what a
    #: connected string's loads center on instead of W_rf; None in a vertical hole.
    hanging_weight: float | None = None


@dataclass(frozen=True)
class Verdict:
    """A card the rule lets through: ``warning`` is empty, or says the string is parted at
    about ``break_depth`` [m] along the rods."""

    warning: str = ""
    break_depth: float | None = None


def free_end(load: np.ndarray, position: np.ndarray, period: float, rods: RodString, fluid_density: float,
             gravity: float = STANDARD_GRAVITY) -> tuple[float, float]:
    """Where the wave equation run down the whole string from a card finds a free end.

    Returns the depth x [m] along the rods where max_t |T_e(x, t)| is least, and that least
    value over the card's load range: zero at the break of a parted string (module
    docstring). The damping factor is the one of :data:`BREAK_DAMPING` that makes it least;
    the first :data:`BREAK_HARMONICS` harmonics are kept.

    ``load`` [N] and ``position`` [m] (up positive) are one cycle on a uniform time grid of
    ``period`` [s].
    """
    fine = rods.subdivided(BREAK_SECTIONS)
    static = fine.static_tension(fluid_density, gravity)
    damping = np.array([fine.damping_coefficient(nu) for nu in BREAK_DAMPING])[:, None]
    _, dynamic = march(fine, period, position, load - static[0], damping, harmonics=BREAK_HARMONICS)
    # relative to the load's range (a card of constant load has none: then to its size)
    scale = max(float(np.ptp(load)), 1e-12 * float(np.max(np.abs(load))), np.finfo(float).tiny)
    off = np.abs(dynamic + static[:, None]).max(axis=-1) / scale
    nu, where = np.unravel_index(int(np.argmin(off)), off.shape)
    return float(np.concatenate([[0.0], np.cumsum(fine.length)])[where]), float(off[nu, where])


def _slip(loads: np.ndarray, fits) -> str:
    """The unit slip that would bring the loads into the window, said in words, or ''."""
    found = [(abs(np.log(factor)), words, factor) for factor, words in LOAD_SLIPS if fits(factor * loads)]
    if not found:
        return ""
    _, words, factor = min(found)
    return f"; loads {factor:.4g} times {'larger' if factor > 1 else 'smaller'} would fit: {words}?"


def check_card_loads(load: np.ndarray, position: np.ndarray, *, stroke: float, crank_speed: float,
                     well: WellLimits | None, structure_rating: float | None, source: str,
                     gravity: float = STANDARD_GRAVITY) -> Verdict:
    """Refuse a card this unit and its rods cannot have made, or pass it (with a warning for a
    parted string); the rule of the module docstring (:func:`check_cards_loads` of one card).

    Parameters
    ----------
    load : numpy.ndarray
        Polished-rod load over one cycle on a uniform crank-angle grid [N].
    position : numpy.ndarray
        Polished-rod position at the same crank angles [m].
    stroke : float
        The unit's stroke S [m].
    crank_speed : float
        Mean crank speed omega [1/s].
    well : WellLimits or None
        The rods and the fluid column, or None for a unit without a ``[well]``.
    structure_rating : float or None
        The unit's structure (polished-rod load) rating [N], if known.
    source : str
        The card's name, first in the message.
    gravity : float
        g [m/s^2].

    Returns
    -------
    Verdict

    Raises
    ------
    CardError
        One line naming the card, the figure, the limit and, where one fits, the unit slip.
    """
    (found,) = check_cards_loads(np.asarray(load, dtype=float)[None], position, stroke=stroke,
                                 crank_speeds=np.array([crank_speed]), well=well, structure_rating=structure_rating,
                                 sources=[source], gravity=gravity)
    if isinstance(found, CardError):
        raise found
    return found


def check_cards_loads(loads: np.ndarray, position: np.ndarray, *, stroke: float, crank_speeds: np.ndarray,
                      well: WellLimits | None, structure_rating: float | None, sources: list[str],
                      gravity: float = STANDARD_GRAVITY) -> list[Verdict | CardError]:
    """:func:`check_card_loads` of K cards of one unit on one crank grid (``loads`` (K, N), their
    mean crank speeds (K,) and names): each card's verdict or its error, the figures of all
    the cards one array computation."""
    loads = np.asarray(loads, dtype=float)
    peaks, lows, spreads = loads.max(axis=1), loads.min(axis=1), np.ptp(loads, axis=1)
    below = [_below_zero(float(low), float(peak), source) for low, peak, source in zip(lows, peaks, sources)]
    if well is None:
        return [found or _rated(float(peak), float(spread), structure_rating, source)
                for found, peak, spread, source in zip(below, peaks, spreads, sources)]
    medians = np.median(loads, axis=1)
    slopes = load_transfer_slope(position, loads)
    rods = well.rods
    air = rods.weight_in_air(gravity)
    buoyant = rods.buoyant_weight(well.fluid_density, gravity) if well.hanging_weight is None else well.hanging_weight
    shortest = float(rods.buoyant_weight_per_length(well.fluid_density, gravity)[0]) * SHORTEST_HANGING
    alphas = stroke * np.asarray(crank_speeds, dtype=float)**2 / (2.0 * gravity)
    uppers = PEAK_FACTOR * (air + well.max_fluid_load) * (1.0 + 2.0 * alphas)
    figures = (f"W_r {air * _KN:.4g} kN, W_rf {buoyant * _KN:.4g} kN, F_max {well.max_fluid_load * _KN:.4g} kN")
    out: list[Verdict | CardError] = []
    for k, source in enumerate(sources):
        refused = below[k]
        if refused is not None:
            out.append(refused)
            continue
        peak, low, median, spread, upper = (float(x[k]) for x in (peaks, lows, medians, spreads, uppers))
        problem = ""
        if peak > upper:
            problem = (f"peak load {peak * _KN:.4g} kN is above {PEAK_FACTOR:g} (W_r + F_max)(1 + 2 alpha) = "
                       f"{upper * _KN:.4g} kN")
        elif spread > upper:
            problem = (f"load range {spread * _KN:.4g} kN is above {PEAK_FACTOR:g} (W_r + F_max)(1 + 2 alpha) = "
                       f"{upper * _KN:.4g} kN")
        elif low > air:
            problem = f"minimum load {low * _KN:.4g} kN is above the rods' weight in air W_r: wrong load datum?"
        elif median < shortest:
            problem = f"median load {median * _KN:.4g} kN is less than the weight of one rod ({SHORTEST_HANGING:g} m)"
        elif median < buoyant:
            depth, off = free_end(loads[k], position, 2.0 * np.pi / float(crank_speeds[k]), rods, well.fluid_density,
                                  gravity)
            if off <= PARTED_FLATNESS and depth < PUMP_END * rods.total_length:
                out.append(Verdict(f"{source}: the loads are those of a parted rod string: the median load "
                                   f"{median * _KN:.4g} kN is {median / buoyant:.0%} of the rods' buoyant weight "
                                   f"{buoyant * _KN:.4g} kN and the wave equation finds a free end about {depth:.0f} m "
                                   f"down the {rods.total_length:.0f} m string", depth))
                continue
            if median < MEDIAN_SHARE * buoyant:
                problem = (f"median load {median * _KN:.4g} kN is below {MEDIAN_SHARE:g} W_rf = "
                           f"{MEDIAN_SHARE * buoyant * _KN:.4g} kN, and the card is not that of a parted string (at no "
                           f"depth does the rods' load stay nearer zero than {off:.0%} of the card's range; a break: "
                           f"{PARTED_FLATNESS:.0%})")
        if problem:
            def connected(trial: np.ndarray, upper: float = upper) -> bool:
                return bool(np.median(trial) >= MEDIAN_SHARE * buoyant and trial.max() <= upper
                            and np.ptp(trial) <= upper and trial.min() <= air)

            out.append(CardError(f"{source}: these rods cannot have made this card: its {problem} ({figures})"
                                 f"{_slip(loads[k], connected)}"))
        elif slopes[k] > LOAD_TRANSFER_MARGIN * rods.spring_constant:
            out.append(CardError(f"{source}: the card's load-transfer slope {slopes[k] * _KN:.4g} kN/m is stiffer than "
                                 f"{LOAD_TRANSFER_MARGIN:g} x the rods' spring constant "
                                 f"{rods.spring_constant * _KN:.4g} kN/m: position in the wrong unit or wrong rod string"))
        else:
            out.append(Verdict())
    return out


#: N to kN, for messages.
_KN = 1e-3


def _below_zero(low: float, peak: float, source: str) -> CardError | None:
    """The error of a card whose loads lie below zero by more than :data:`NEGATIVE_SHARE` of its peak."""
    if low < -NEGATIVE_SHARE * max(peak, 0.0):
        return CardError(f"{source}: its minimum load {low * _KN:.4g} kN is below zero by more than "
                         f"{NEGATIVE_SHARE:.0%} of its peak {peak * _KN:.4g} kN; the polished rod's load is never "
                         f"below zero (the carrier bar cannot push the rods down): the load cell's zero, or the "
                         f"rods floating off the carrier bar (too fast for them to fall)?")
    return None


def _rated(peak: float, spread: float, structure_rating: float | None, source: str) -> Verdict | CardError:
    """The verdict on a card's loads without well data: only the gross slips against the structure rating."""
    if structure_rating is None:
        return Verdict()
    if not RATING_LOW * structure_rating <= spread <= RATING_HIGH * structure_rating:
        return CardError(f"{source}: the card's load range {spread * _KN:.4g} kN is "
                         f"{spread / structure_rating:.3g} x the unit's structure rating "
                         f"{structure_rating * _KN:.4g} kN (plausible: {RATING_LOW:g} to {RATING_HIGH:g} x); "
                         f"check the load column's unit")
    if peak > PEAK_RATING * structure_rating:
        return CardError(f"{source}: the card's peak load {peak * _KN:.4g} kN is {peak / structure_rating:.3g} x "
                         f"the unit's structure rating {structure_rating * _KN:.4g} kN (plausible: up to "
                         f"{PEAK_RATING:g} x); check the load column's unit")
    return Verdict()
