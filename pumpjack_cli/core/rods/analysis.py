"""What a pump card says: strokes, fillage, fluid load, rates, work; rod loads and Goodman loading.

Every function takes arrays of shape (N,) for one card or (B, N) for a batch and
returns one value per card (a float array of shape () or (B,)).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import DownholeError
from .string import RodString

#: Bands of the gross stroke (fractions from the bottom) whose median loads are the
#: upstroke and downstroke load levels: clear of the corners of a full card, of a late
#: pickup (gas) and of the fluid-pound drop in the upper part of the downstroke.
UPSTROKE_BAND = (0.6, 0.9)
DOWNSTROKE_BAND = (0.1, 0.4)

#: Slope of the modified Goodman line of API RP 11BR [API11BR].
GOODMAN_SLOPE = 0.5625


def as_cards(position, load, what: str = "card") -> tuple[np.ndarray, np.ndarray]:
    """Position and load as float arrays of one shape, (N,) or (B, N), N >= 8, all finite.

    Raises
    ------
    DownholeError
        Naming the card of a batch and the sample that is not finite.
    """
    position = np.asarray(position, dtype=float)
    load = np.asarray(load, dtype=float)
    if position.shape != load.shape or position.ndim not in (1, 2):
        raise DownholeError(f"{what} position and load must both have shape (N,) or (B, N), "
                            f"got {position.shape} and {load.shape}")
    if position.shape[-1] < 8:
        raise DownholeError(f"{what} has {position.shape[-1]} samples per cycle; at least 8 are needed")
    for name, array in (("position", position), ("load", load)):
        if not np.isfinite(array).all():
            index = np.argwhere(~np.isfinite(array))[0]
            card = f"{what} {index[0] + 1}" if array.ndim == 2 else what
            raise DownholeError(f"{card}: {name} is not finite at sample {int(index[-1])}")
    return position, load


def _finite(name: str, value, unit: str) -> np.ndarray:
    array = np.asarray(value, dtype=float)
    if not np.isfinite(array).all():
        raise DownholeError(f"{name} must be finite, got {array} {unit}")
    return array


def card_work(position, load) -> np.ndarray:
    """Work of one cycle, the loop integral of load d(position) [J], per card.

    Computed for the trigonometric interpolant of the samples,

        W = -(4 pi / N^2) sum_{n >= 1} n Im(conj(F_n) P_n)

    with P_n, F_n the discrete Fourier coefficients: exact for a band-limited card, and
    within O(1/N^2) of the polygon (trapezoid) area for a smooth one. Positive when the
    load is higher on the way up than on the way down (work done on the rods at the
    surface, by the rods on the pump at the plunger).

    Examples
    --------
    An elliptic card p = 1 - cos(theta), F = 1 + sin(theta) has area pi:

    >>> theta = 2 * np.pi * np.arange(16) / 16
    >>> round(float(card_work(1 - np.cos(theta), 1 + np.sin(theta))), 12) == round(np.pi, 12)
    True
    """
    position, load = as_cards(position, load)
    return series_work(np.fft.rfft(position, axis=-1), np.fft.rfft(load, axis=-1), position.shape[-1])


def series_work(position: np.ndarray, load: np.ndarray, samples: int) -> np.ndarray:
    """:func:`card_work` of cards of ``samples`` samples given by their Fourier coefficients
    (``numpy.fft.rfft``, n = 0, 1, ..., as many as kept: the harmonics left out add no work),
    W = -(4 pi / N^2) sum_{n >= 1} n Im(conj(F_n) P_n) [J] per card; for a pump card that Gibbs'
    transfer gives as a series (:func:`.gibbs.transfer`) without its samples.
    """
    n = np.arange(1, position.shape[-1])
    return -4.0 * np.pi / samples**2 * np.sum(n * np.imag(np.conj(load[..., 1:]) * position[..., 1:]), axis=-1)


def rolled(values: np.ndarray, start: np.ndarray) -> np.ndarray:
    """Each row of ``values`` (K, N) rolled to begin at its sample ``start`` (K,): a window of the row
    written twice, without the modulo of every index."""
    samples = values.shape[-1]
    twice = np.concatenate([values, values], axis=-1)
    return np.lib.stride_tricks.sliding_window_view(twice, samples, axis=-1)[np.arange(len(values)), start]


def _band_median(p, f, stroke_mask, low, stroke, band, what):
    """The median load of each card over the samples of ``stroke_mask`` between the ``band``'s shares
    of the stroke (a load level of :class:`PumpCardSummary`); an empty band is an error."""
    lower, upper = low + band[0] * stroke, low + band[1] * stroke
    inside = stroke_mask & (p >= lower[:, None]) & (p <= upper[:, None])
    count = inside.sum(axis=-1)
    if not count.all():
        index = int(np.flatnonzero(count == 0)[0])
        raise DownholeError(f"pump card {index + 1}: no sample on the {what} between {band[0]:.0%} and "
                            f"{band[1]:.0%} of the stroke; sample the card more finely")
    values = np.sort(np.where(inside, f, np.nan), axis=-1)  # NaN last: the band's values first
    rows = np.arange(len(values))
    return 0.5 * (values[rows, (count - 1) // 2] + values[rows, count // 2])


@dataclass(frozen=True)
class PumpCardSummary:
    """Figures read off a pump card, one value per card.

    Parameters
    ----------
    gross_stroke : numpy.ndarray
        S_g = max - min plunger position [m].
    net_stroke : numpy.ndarray
        S_n [m]: plunger travel from the point of the downstroke where the load first
        falls below the mid level (upstroke + downstroke level) / 2 down to the bottom of
        the stroke; the travel over which the plunger moves through liquid.
    fillage : numpy.ndarray
        S_n / S_g [-] (Echometer-style, from the downstroke unloading point).
    upstroke_load, downstroke_load : numpy.ndarray
        Load levels [N]: median pump load over the upstroke samples between 60 % and
        90 % of the gross stroke, and over the downstroke samples between 10 % and 40 %.
    fluid_load : numpy.ndarray
        upstroke_load - downstroke_load [N].
    peak_load, minimum_load : numpy.ndarray
        Largest and smallest pump load [N]; a negative minimum is compression at the
        pump (buckling tendency of the bottom rods).
    """

    gross_stroke: np.ndarray
    net_stroke: np.ndarray
    fillage: np.ndarray
    upstroke_load: np.ndarray
    downstroke_load: np.ndarray
    fluid_load: np.ndarray
    peak_load: np.ndarray
    minimum_load: np.ndarray

    def card(self, index: int) -> PumpCardSummary:
        """The figures of card ``index`` of cards (K, N)."""
        return PumpCardSummary(*(value[index] for value in vars(self).values()))


def summarise_pump_card(pump_position, pump_load) -> PumpCardSummary:
    """Strokes, fillage and load levels of pump cards; definitions in :class:`PumpCardSummary`.

    Parameters
    ----------
    pump_position : array_like
        Plunger position [m], up positive, shape (N,) or (B, N), in time order.
    pump_load : array_like
        Net plunger load [N], same shape.

    Raises
    ------
    DownholeError
        A card with no stroke, or too few samples to find a load level.
    """
    position, load = as_cards(pump_position, pump_load, "pump card")
    single = position.ndim == 1
    p, f = np.atleast_2d(position), np.atleast_2d(load)
    rows = np.arange(len(p))
    bottom, top = np.argmin(p, axis=-1), np.argmax(p, axis=-1)
    low = p[rows, bottom]
    stroke = p[rows, top] - low
    if not (stroke > 0).all():
        index = int(np.flatnonzero(~(stroke > 0))[0])
        raise DownholeError(f"pump card {index + 1} has no plunger stroke")
    # the stroke from the bottom, in time order around the cycle, without rolling the cards: the
    # upstroke from the bottom to the top sample (across the record's end where the top comes first)
    sample = np.arange(p.shape[-1])[None, :]
    later, until_top = sample >= bottom[:, None], sample <= top[:, None]
    upstroke = np.where((bottom <= top)[:, None], later & until_top, later | until_top)
    up = _band_median(p, f, upstroke, low, stroke, UPSTROKE_BAND, "upstroke")
    down = _band_median(p, f, ~upstroke, low, stroke, DOWNSTROKE_BAND, "downstroke")
    middle = 0.5 * (up + down)
    below = (f < middle[:, None]) & ~upstroke
    unloaded = below.any(axis=-1)
    after_bottom = below & later
    first = np.where(after_bottom.any(axis=-1), np.argmax(after_bottom, axis=-1), np.argmax(below, axis=-1))
    before = (first - 1) % p.shape[-1]        # never the bottom itself: it is on the upstroke
    f0, f1 = f[rows, before], f[rows, first]
    with np.errstate(invalid="ignore", divide="ignore"):
        weight = np.where(f0 > f1, (f0 - middle) / (f0 - f1), 0.0)
    crossing = p[rows, before] + weight * (p[rows, first] - p[rows, before])
    net = np.where(unloaded, np.clip(crossing - low, 0.0, stroke), 0.0)
    result = PumpCardSummary(stroke, net, net / stroke, up, down, up - down, f.max(axis=-1), f.min(axis=-1))
    return result.card(0) if single else result


def plunger_area(plunger_diameter: float) -> float:
    """A_p = pi D^2 / 4 [m^2] of a plunger of diameter D [m]."""
    if not (np.isfinite(plunger_diameter) and plunger_diameter > 0):
        raise DownholeError(f"plunger diameter must be finite and positive, got {plunger_diameter:g} m")
    return float(np.pi * plunger_diameter**2 / 4.0)


def displacement_rate(stroke, period, plunger_diameter: float) -> np.ndarray:
    """Pump displacement at the card's speed, Q = A_p S / T [m^3/s] (strokes and periods of
    one card or of K).

    With the gross stroke this is the theoretical displacement, with the net stroke the
    liquid the plunger displaces (before slippage and shrinkage).

    Examples
    --------
    38 mm plunger, 2.5 m stroke, 10.9 strokes/min: 1.134e-3 m^2 * 2.5 m / 5.505 s.

    >>> round(float(displacement_rate(2.5, 60 / 10.9, 0.038)) * 86400, 1)   # m^3/day
    44.5
    """
    periods = np.asarray(period, dtype=float)
    wrong = ~(np.isfinite(periods) & (periods > 0))
    if wrong.any():
        raise DownholeError(f"period must be finite and positive, got {periods[wrong].flat[0]:g} s")
    return plunger_area(plunger_diameter) * _finite("stroke", stroke, "m") / period


def intake_pressure(fluid_load, plunger_diameter: float, discharge_pressure: float) -> np.ndarray:
    """Pump intake pressure from the fluid load, p_i = p_d - F_o / A_p [Pa].

    The fluid load is the pressure difference across the closed travelling valve on the
    plunger area, F_o = (p_d - p_i) A_p, with p_d the discharge pressure at the pump
    (tubing head pressure plus the fluid column above the pump).

    Examples
    --------
    A 13.96 kN fluid load on a 38 mm plunger is 12.31 MPa; with 12.5 MPa at discharge:

    >>> round(float(intake_pressure(13958.3, 0.038, 12.5e6)) / 1e6, 3)
    0.192
    """
    area = plunger_area(plunger_diameter)
    return _finite("discharge pressure", discharge_pressure, "Pa") - _finite("fluid load", fluid_load, "N") / area


@dataclass(frozen=True)
class TaperLoads:
    """Extreme loads and stresses at the top and bottom of every taper, shape (..., S).

    Parameters
    ----------
    top_max_load, top_min_load, bottom_max_load, bottom_min_load : numpy.ndarray
        Tension [N] over the cycle (static plus dynamic, the pump-load datum).
    top_max_stress, top_min_stress, bottom_max_stress, bottom_min_stress : numpy.ndarray
        The same divided by the taper's metal area [Pa].
    """

    top_max_load: np.ndarray
    top_min_load: np.ndarray
    bottom_max_load: np.ndarray
    bottom_min_load: np.ndarray
    top_max_stress: np.ndarray
    top_min_stress: np.ndarray
    bottom_max_stress: np.ndarray
    bottom_min_stress: np.ndarray

    def card(self, index: int) -> TaperLoads:
        """The loads of card ``index`` of K cards' (K, S)."""
        return TaperLoads(*(getattr(self, name)[index] for name in self.__dataclass_fields__))


def taper_loads(string: RodString, joint_load) -> TaperLoads:
    """Per taper, the extreme tensions at its top and bottom and the stresses.

    Parameters
    ----------
    string : RodString
        The S tapers.
    joint_load : array_like
        Tension at the section ends [N], shape (..., S + 1, N), as
        :attr:`DownholeCard.joint_load`.

    Returns
    -------
    TaperLoads
        Loads [N] and stresses [Pa], shape (..., S).
    """
    load = _finite("joint load", joint_load, "N")
    if load.ndim < 2 or load.shape[-2] != len(string.length) + 1:
        raise DownholeError(f"joint loads have {load.shape[-2]} section ends for {len(string.length)} tapers")
    high, low = load.max(axis=-1), load.min(axis=-1)
    top_max, top_min, bottom_max, bottom_min = high[..., :-1], low[..., :-1], high[..., 1:], low[..., 1:]
    area = string.area
    return TaperLoads(top_max, top_min, bottom_max, bottom_min,
                      top_max / area, top_min / area, bottom_max / area, bottom_min / area)


def goodman_allowable_stress(tensile_strength, minimum_stress, service_factor: float = 1.0) -> np.ndarray:
    """Modified Goodman allowable maximum stress S_A = (T/4 + 0.5625 S_min) SF [Pa] [API11BR].

    Parameters
    ----------
    tensile_strength : array_like
        Minimum tensile strength T of the grade [Pa].
    minimum_stress : array_like
        S_min [Pa] over the cycle.
    service_factor : float
        SF [-].

    Examples
    --------
    Grade D (115 000 psi = 792.9 MPa) with S_min = 40 MPa: 198.2 + 22.5 = 220.7 MPa.

    >>> round(float(goodman_allowable_stress(792.9e6, 40e6)) / 1e6, 1)
    220.7

    References
    ----------
    [API11BR].
    """
    return (np.asarray(tensile_strength) / 4.0 + GOODMAN_SLOPE * np.asarray(minimum_stress)) * service_factor


def goodman_loading(string: RodString, loads: TaperLoads, service_factor: float = 1.0) -> np.ndarray:
    """Goodman loading of every taper [-], the larger of its top and bottom, shape (..., S).

    Loading = (S_max - S_min) / (S_A - S_min): the stress range over the allowable range
    of API RP 11BR, Delta S_A = S_A - S_min [API11BR]; 1.0 is the Goodman line. Infinite
    where the allowable range is not positive.

    Parameters
    ----------
    string : RodString
        The tapers, with their minimum tensile strengths T_i [Pa].
    loads : TaperLoads
        From :func:`taper_loads`; stresses [Pa].
    service_factor : float
        SF [-], 1 for non-corrosive fluid, below 1 for corrosive service.

    Returns
    -------
    numpy.ndarray
        Loading [-] per taper, shape (..., S).

    Raises
    ------
    DownholeError
        A taper without a tensile strength (no grade given).

    References
    ----------
    [API11BR].
    """
    strength = string.tensile_strength
    if np.isnan(strength).any():
        index = int(np.flatnonzero(np.isnan(strength))[0])
        raise DownholeError(f"taper {index + 1} has no rod grade or tensile strength for the Goodman loading")
    if not (np.isfinite(service_factor) and service_factor > 0):
        raise DownholeError(f"service factor must be finite and positive, got {service_factor:g}")

    def loading(high, low):
        allowed = goodman_allowable_stress(strength, low, service_factor) - low
        with np.errstate(divide="ignore"):
            return np.where(allowed > 0, (high - low) / np.where(allowed > 0, allowed, 1.0), np.inf)

    return np.maximum(loading(loads.top_max_stress, loads.top_min_stress),
                      loading(loads.bottom_max_stress, loads.bottom_min_stress))
