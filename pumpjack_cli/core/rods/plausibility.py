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
* its load range is at most :data:`RANGE_FACTOR` (F_max + W_r): the fluid load and a
  dynamic swing as large as the string's whole weight, each way, doubled;
* its minimum load is at most W_r: the polished rod never carries more than the whole
  string at the bottom of a downstroke;
* its load-transfer slope (range over stroke) is at most
  :data:`~pumpjack_cli.core.rods.downhole.LOAD_TRANSFER_MARGIN` times the rods' spring
  constant (:func:`~pumpjack_cli.core.rods.downhole.load_transfer_slope`).

A parted string is the one real card below the rods' weight: the polished rod then hangs
only the rods above the break, so the median sits at their buoyant weight, smoothly, and
the card is thin (no fluid is lifted: its loop holds only the damping of the rods left,
:data:`PARTED_FULLNESS` of the box stroke x load range at most, against 0.3 to 0.9 for a
pumping card). Such a card passes with a warning that gives the break's approximate depth
(where the buoyant weight of the rods from the top equals the median load). A card whose
loads a common unit slip would bring into the window (kN written as lbf, lbf as N, kgf as
N, a factor 1000) is refused with the factor named.

Without a ``[well]`` only the gross slips are refused: a load range below
:data:`RATING_LOW` or above :data:`RATING_HIGH` times the unit's structure rating.

The thresholds and their reasons: ``docs/cards.md``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import CardError
from ..beam.card import loop_work
from ..constants import STANDARD_GRAVITY
from .downhole import LOAD_TRANSFER_MARGIN, load_transfer_slope
from .string import RodString

#: A connected string's median load is at least this share of W_rf.
MEDIAN_SHARE = 0.75
#: A connected string's peak load is at most this multiple of (W_r + F_max)(1 + 2 alpha).
PEAK_FACTOR = 1.5
#: A connected string's load range is at most this multiple of F_max + W_r.
RANGE_FACTOR = 2.0
#: A parted string's card encloses at most this share of the box stroke x load range.
PARTED_FULLNESS = 0.3
#: The shortest string that can hang from a break: one API rod, 25 ft ([API11B]) [m].
SHORTEST_HANGING = 7.62
#: Without well data: a load range outside [RATING_LOW, RATING_HIGH] x the structure rating.
RATING_LOW = 0.01
RATING_HIGH = 100.0
#: Unit slips of a load column: the factor that turns the read loads into the true ones,
#: and what it means.
LOAD_SLIPS = (
    (1000.0, "kN written as N"), (1e-3, "N written as kN"),
    (4.4482216152605, "lbf written as N"), (1 / 4.4482216152605, "N written as lbf"),
    (1000.0 / 4.4482216152605, "kN written as lbf"), (4.4482216152605 / 1000.0, "lbf written as kN"),
    (9.80665, "kgf written as N"), (1 / 9.80665, "N written as kgf"),
    (1000.0 / 9.80665, "kN written as kgf"), (9.80665 / 1000.0, "kgf written as kN"),
)


@dataclass(frozen=True)
class WellLimits:
    """What the rods and the fluid column can produce: the rods, the fluid density [kg/m^3],
    the largest fluid load on the plunger F_max = p_d A_p [N]."""

    rods: RodString
    fluid_density: float
    max_fluid_load: float


@dataclass(frozen=True)
class Verdict:
    """A card the rule lets through: ``warning`` is empty, or says the string is parted at
    about ``break_depth`` [m] along the rods."""

    warning: str = ""
    break_depth: float | None = None


def break_depth(rods: RodString, hanging_weight: float, fluid_density: float,
                gravity: float = STANDARD_GRAVITY) -> float:
    """Length of rods from the top whose buoyant weight is ``hanging_weight`` [N], in [m].

    >>> rods = RodString(np.array([500.0, 500.0]), np.array([4e-4, 3e-4]), np.array([2e11, 2e11]),
    ...                  np.array([4.0, 3.0]))
    >>> w = rods.buoyant_weight_per_length(1000.0)            # N/m per taper
    >>> round(break_depth(rods, 500.0 * w[0] + 100.0 * w[1], 1000.0), 6)
    600.0
    """
    per_length = rods.buoyant_weight_per_length(fluid_density, gravity)
    ends = np.concatenate([[0.0], np.cumsum(rods.length)])
    weights = np.concatenate([[0.0], np.cumsum(per_length * rods.length)])
    return float(np.interp(hanging_weight, weights, ends))


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
    parted string); the rule of the module docstring.

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
    load = np.asarray(load, dtype=float)
    peak, low, median, spread = float(load.max()), float(load.min()), float(np.median(load)), float(np.ptp(load))
    kn = 1e-3
    if well is None:
        if structure_rating is None:
            return Verdict()
        if not RATING_LOW * structure_rating <= spread <= RATING_HIGH * structure_rating:
            raise CardError(f"{source}: the card's load range {spread * kn:.4g} kN is "
                            f"{spread / structure_rating:.3g} x the unit's structure rating "
                            f"{structure_rating * kn:.4g} kN (plausible: {RATING_LOW:g} to {RATING_HIGH:g} x); "
                            f"check the load column's unit")
        return Verdict()
    rods = well.rods
    air = rods.weight_in_air(gravity)
    buoyant = rods.buoyant_weight(well.fluid_density, gravity)
    alpha = stroke * crank_speed**2 / (2.0 * gravity)
    upper = PEAK_FACTOR * (air + well.max_fluid_load) * (1.0 + 2.0 * alpha)
    widest = RANGE_FACTOR * (well.max_fluid_load + air)

    def connected(loads: np.ndarray) -> bool:
        return bool(np.median(loads) >= MEDIAN_SHARE * buoyant and loads.max() <= upper
                    and np.ptp(loads) <= widest and loads.min() <= air)

    figures = (f"W_r {air * kn:.4g} kN, W_rf {buoyant * kn:.4g} kN, F_max {well.max_fluid_load * kn:.4g} kN")
    if peak > upper:
        problem = (f"peak load {peak * kn:.4g} kN is above {PEAK_FACTOR:g} (W_r + F_max)(1 + 2 alpha) = "
                   f"{upper * kn:.4g} kN")
    elif spread > widest:
        problem = f"load range {spread * kn:.4g} kN is above {RANGE_FACTOR:g} (F_max + W_r) = {widest * kn:.4g} kN"
    elif low > air:
        problem = f"minimum load {low * kn:.4g} kN is above the rods' weight in air W_r: wrong load datum?"
    elif median < MEDIAN_SHARE * buoyant:
        box = spread * float(np.ptp(position))
        fullness = abs(loop_work(position, load)) / box if box > 0 else 0.0
        shortest = float(rods.buoyant_weight_per_length(well.fluid_density, gravity)[0]) * SHORTEST_HANGING
        if fullness <= PARTED_FULLNESS and median >= shortest and peak <= upper:
            depth = break_depth(rods, median, well.fluid_density, gravity)
            return Verdict(f"{source}: the loads are those of a parted rod string: the median load "
                           f"{median * kn:.4g} kN is {median / buoyant:.0%} of the rods' buoyant weight "
                           f"{buoyant * kn:.4g} kN and the card lifts no fluid (its loop is {fullness:.0%} of its "
                           f"box); the break is about {depth:.0f} m down the {rods.total_length:.0f} m string", depth)
        problem = (f"median load {median * kn:.4g} kN is below {MEDIAN_SHARE:g} W_rf = {MEDIAN_SHARE * buoyant * kn:.4g} "
                   f"kN, and the card is not that of a parted string (its loop is {fullness:.0%} of its box)")
    else:
        slope = float(load_transfer_slope(position, load)[0])
        limit = LOAD_TRANSFER_MARGIN * rods.spring_constant
        if slope > limit:
            raise CardError(f"{source}: the card's load-transfer slope {slope * kn:.4g} kN/m is stiffer than "
                            f"{LOAD_TRANSFER_MARGIN:g} x the rods' spring constant {rods.spring_constant * kn:.4g} kN/m: "
                            f"position in the wrong unit or wrong rod string")
        return Verdict()
    raise CardError(f"{source}: these rods cannot have made this card: its {problem} ({figures}){_slip(load, connected)}")
