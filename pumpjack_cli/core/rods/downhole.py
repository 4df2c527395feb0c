"""The pump (downhole) card from a surface dynamometer card, and back.

Datum. Position is displacement UP; load is axial tension. The static tension
T_s(x) = buoyant weight of the rods below x (:meth:`RodString.static_tension`) is taken
out first: the wave equation carries the dynamic load F = T - T_s, so

* the dynamic load at the polished rod is surface load - W_rf (buoyant weight of the
  string in the well fluid, couplings included, section by section);
* the pump load is T(L) = F(L), the net plunger load: about zero on the downstroke
  (travelling valve open) and the fluid load on the upstroke;
* positions carry the surface datum: a string hanging at rest in the fluid with zero
  pump load has the pump at the polished rod's position, so the pump position is
  the surface position minus the stretch caused by the dynamic load.

Both methods solve m (w_tt + c w_t) = (E A w_x)_x with Gibbs' damping
c = pi a nu / (2 L) [Gibbs1963]; ``gibbs`` exactly per harmonic, ``everitt-jennings``
by finite differences [EverittJennings1992]. The forward transfer (pump to surface)
marches the reversed string with the tension's sign flipped, the same equations.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import DownholeError
from ..constants import STANDARD_GRAVITY
from . import everitt_jennings, gibbs
from .analysis import as_cards, card_work, series_work, summarise_pump_card
from .string import RodString

#: Default Gibbs damping factor nu (dimensionless): nu / 2 = 2.5 % of critical damping of
#: the string's first mode. No published default was found; see docs/downhole.md.
DEFAULT_DAMPING_FACTOR = 0.05

#: A card whose load-transfer slope exceeds this multiple of the rods' spring constant
#: is refused (:mod:`.plausibility`).
LOAD_TRANSFER_MARGIN = 2.0

_METHODS = {"gibbs": gibbs.march, "everitt-jennings": everitt_jennings.march}


def downhole_methods() -> tuple[str, ...]:
    """Names accepted by ``method=`` of :func:`pump_card` and :func:`surface_card`.

    >>> downhole_methods()
    ('gibbs', 'everitt-jennings')
    """
    return tuple(_METHODS)


@dataclass(frozen=True)
class DownholeCard:
    """Surface and pump cards of one string on one time grid; arrays (N,) or (B, N).

    Parameters
    ----------
    method : str
        The method that produced the card.
    period : float or numpy.ndarray
        T [s]; samples at t_k = k T / N (per card, shape (B,), when the cards have their own).
    damping_factor : float or numpy.ndarray
        nu [-] (per card, shape (B,), when the cards have their own).
    damping_coefficient : float or numpy.ndarray
        c [1/s], as ``damping_factor``.
    buoyant_weight : float
        W_rf [N], the load datum between the two cards.
    surface_position, surface_load : numpy.ndarray
        Polished rod [m] (up positive) and [N].
    pump_position, pump_load : numpy.ndarray
        Plunger [m] (surface datum) and net plunger load [N].
    joint_position, joint_load : numpy.ndarray
        Shape (..., S + 1, N): displacement [m] and tension T = F + T_s [N] at the
        section ends, index 0 the polished rod, index S the pump.
    """

    method: str
    period: float | np.ndarray
    damping_factor: float | np.ndarray
    damping_coefficient: float | np.ndarray
    buoyant_weight: float
    surface_position: np.ndarray
    surface_load: np.ndarray
    pump_position: np.ndarray
    pump_load: np.ndarray
    joint_position: np.ndarray
    joint_load: np.ndarray

    @property
    def time(self) -> np.ndarray:
        """t_k = k T / N [s]."""
        samples = self.surface_position.shape[-1]
        return np.arange(samples) * np.asarray(self.period)[..., None] / samples

    def card(self, index: int) -> DownholeCard:
        """Card ``index`` of cards (B, N), with its own period and damping."""
        def own(value):
            return float(value[index]) if np.ndim(value) else value

        return DownholeCard(method=self.method, period=own(self.period), damping_factor=own(self.damping_factor),
                            damping_coefficient=own(self.damping_coefficient), buoyant_weight=self.buoyant_weight,
                            surface_position=self.surface_position[index], surface_load=self.surface_load[index],
                            pump_position=self.pump_position[index], pump_load=self.pump_load[index],
                            joint_position=self.joint_position[index], joint_load=self.joint_load[index])


def _march_function(method: str):
    if method not in _METHODS:
        raise DownholeError(f"unknown downhole method {method!r}; valid methods: {', '.join(_METHODS)}")
    return _METHODS[method]


def _card_arrays(period, position, load, what: str) -> tuple[np.ndarray, np.ndarray]:
    position, load = as_cards(position, load, what)
    if np.ndim(period) and (position.ndim != 2 or np.shape(period) != position.shape[:1]):
        raise DownholeError(f"{np.size(period)} periods for cards of shape {position.shape}")
    if not (np.all(np.isfinite(period)) and np.all(np.asarray(period) > 0)):
        raise DownholeError(f"card period must be finite and positive, got {period} s")
    return position, load


def _each_card(march):
    """A march of one period and damping made to take cards (B, N) with their own: card by card."""
    def each(string, period, position, load, damping, **options):
        if not np.ndim(period) and not np.ndim(damping):
            return march(string, period, position, load, damping, **options)
        periods, dampings = (np.broadcast_to(np.asarray(v, dtype=float), position.shape[:1]) for v in (period, damping))
        found = [march(string, float(t), p, f, float(c), **options)
                 for t, p, f, c in zip(periods, position, load, dampings)]
        return np.array([w for w, _ in found]), np.array([f for _, f in found])

    return each


def _solve(string: RodString, period: float | np.ndarray, position: np.ndarray, load: np.ndarray, *,
           fluid_density: float, damping_factor: float | np.ndarray, method: str, harmonics: int | None, gravity: float,
           upward: bool) -> DownholeCard:
    march = _march_function(method)
    options = {}
    if harmonics is not None:
        if method != "gibbs":
            raise DownholeError(f"harmonics applies to the gibbs method only, not {method!r}")
        if harmonics < 1:
            raise DownholeError(f"harmonics must be at least 1, got {harmonics}")
        options["harmonics"] = harmonics
    damping = string.damping_coefficient(damping_factor)
    if method == "gibbs":
        given = np.asarray(damping)[..., None] if np.ndim(damping) else damping   # per card: against the harmonics
    else:
        march, given = _each_card(march), damping
    static = string.static_tension(fluid_density, gravity)
    if upward:
        w, f = march(string.reversed(), period, position, -load, given, **options)   # T_s(L) = 0
        w, f = w[..., ::-1, :], -f[..., ::-1, :]
    else:
        w, f = march(string, period, position, load - static[0], given, **options)
    tension = f + static[:, None]
    scalar = not np.ndim(period) and not np.ndim(damping_factor)
    return DownholeCard(method=method, period=float(period) if scalar else np.broadcast_to(period, w.shape[:1]).copy(),
                        damping_factor=float(damping_factor) if scalar else np.broadcast_to(damping_factor,
                                                                                            w.shape[:1]).copy(),
                        damping_coefficient=damping, buoyant_weight=float(static[0]),
                        surface_position=w[..., 0, :], surface_load=tension[..., 0, :],
                        pump_position=w[..., -1, :], pump_load=tension[..., -1, :],
                        joint_position=w, joint_load=tension)


def pump_card(string: RodString, period: float | np.ndarray, position, load, *, fluid_density: float,
              damping_factor: float | np.ndarray = DEFAULT_DAMPING_FACTOR, method: str = "gibbs",
              harmonics: int | None = None, gravity: float = STANDARD_GRAVITY) -> DownholeCard:
    """Pump card (plunger position and net plunger load) from a surface card.

    Parameters
    ----------
    string : RodString
        The rods, top section first.
    period : float or array_like
        T [s] of one stroke; the card is sampled at t_k = k T / N, k = 0 .. N-1; for B
        cards, one for all or one per card, shape (B,).
    position : array_like
        Polished-rod position [m], up positive, shape (N,) or (B, N) for B cards of the
        same string.
    load : array_like
        Polished-rod load [N], same shape.
    fluid_density : float
        rho_f [kg/m^3] of the fluid around the rods (buoyancy).
    damping_factor : float or array_like
        Gibbs' nu [-]; c = pi a nu / (2 L) [Gibbs1963]; for B cards one for all or one
        per card, shape (B,).
    method : str
        One of :func:`downhole_methods`.
    harmonics : int, optional
        ``gibbs`` only: highest harmonic kept (default all the grid resolves).
    gravity : float
        g [m/s^2].

    Returns
    -------
    DownholeCard
        Pump position [m] and load [N] on the same grid, and the section-end loads
        (:meth:`DownholeCard.card` gives each of B cards). Gibbs' solution transfers B
        cards in one array computation, each card exactly as alone.

    Raises
    ------
    DownholeError
        Unknown method (the message lists the valid ones; it is a ValueError), or a card
        that is not finite. Whether these rods can have made the card is the run layer's
        question, asked once for every command (:mod:`.plausibility`).

    References
    ----------
    [Gibbs1963], [GibbsNeely1966], [EverittJennings1992].
    """
    position, load = _card_arrays(period, position, load, "surface card")
    _march_function(method)
    return _solve(string, period, position, load, fluid_density=fluid_density, damping_factor=damping_factor,
                  method=method, harmonics=harmonics, gravity=gravity, upward=False)


def surface_card(string: RodString, period: float, pump_position, pump_load, *, fluid_density: float,
                 damping_factor: float = DEFAULT_DAMPING_FACTOR, method: str = "gibbs",
                 harmonics: int | None = None, gravity: float = STANDARD_GRAVITY) -> DownholeCard:
    """Surface card from a pump card: the forward transfer, the same equations upward.

    Parameters are those of :func:`pump_card`, with the plunger position [m] and net
    plunger load [N] as input; no plausibility check is made.

    References
    ----------
    [Gibbs1963], [EverittJennings1992].
    """
    position, load = _card_arrays(period, pump_position, pump_load, "pump card")
    return _solve(string, period, position, load, fluid_density=fluid_density, damping_factor=damping_factor,
                  method=method, harmonics=harmonics, gravity=gravity, upward=True)


#: Largest damping factor the energy balance searches [-].
LARGEST_DAMPING = 2.0
#: The energy balance's root is found to this damping factor [-] (the bracket's width).
DAMPING_TOLERANCE = 1e-10
#: Steps of regula falsi a card may take before its bracket is halved instead (bisection from
#: then on: the search ends whatever the function's shape).
_FALSI_STEPS = 30


def decreasing_roots(excess, largest: float, count: int,
                     tolerance: float = DAMPING_TOLERANCE) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Roots of ``count`` decreasing functions of nu on [0, ``largest``], found together.

    ``excess(nu, rows)`` gives the functions ``rows`` (indices) at their own ``nu`` (arrays of
    one length) in one evaluation. Regula falsi with the Anderson-Bjoerck weight
    ([AndersonBjorck1973]; superlinear for a smooth function, each card keeping a bracket),
    then bisection after :data:`_FALSI_STEPS` steps; a card stops when its bracket is narrower
    than ``tolerance`` or the function is zero. Each card's iterates depend on its own
    function only, so K cards solved together give each card the root it has alone.
    Returns the roots, NaN where the ends do not bracket one (``excess(0) < 0`` or
    ``excess(largest) > 0``, the caller saying why), and the functions at 0 and ``largest``.
    """
    rows = np.arange(count)
    a, b = np.zeros(count), np.full(count, float(largest))
    fa, fb = excess(a, rows), excess(b, rows)
    ends = fa.copy(), fb.copy()
    root = np.where(fa == 0.0, a, np.where(fb == 0.0, b, np.nan))
    active = (fa > 0.0) & (fb < 0.0)
    steps = np.zeros(count, dtype=int)
    while active.any():
        k = np.flatnonzero(active)
        falsi = (b[k] * fa[k] - a[k] * fb[k]) / (fa[k] - fb[k])
        middle = 0.5 * (a[k] + b[k])
        inside = (falsi - a[k]) * (falsi - b[k]) < 0.0
        c = np.where((steps[k] < _FALSI_STEPS) & inside, falsi, middle)
        fc = excess(c, k)
        steps[k] += 1
        crossed = fc * fb[k] < 0.0        # the root is between b and c: b becomes the other end
        weight = 1.0 - fc / np.where(fb[k] == 0.0, 1.0, fb[k])
        fa[k] = np.where(crossed, fb[k], fa[k] * np.where(weight > 0.0, weight, 0.5))
        a[k] = np.where(crossed, b[k], a[k])
        b[k], fb[k] = c, fc
        done = (fc == 0.0) | (np.abs(b[k] - a[k]) <= tolerance)
        root[k[done]] = c[done]
        active[k[done]] = False
    return root, ends[0], ends[1]


def _brent_root(excess, largest: float, count: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`decreasing_roots` of one function by Brent's method (``scipy.optimize.brentq``,
    [Brent1973]): for one card's transfer of its own (a deviated well's march, a march per
    evaluation), where Brent's interpolation saves a few evaluations that the cards of a
    vertical well, solved together, do not need to share."""
    from scipy.optimize import brentq

    rows, known = np.zeros(1, dtype=int), {}

    def one(nu: float) -> float:
        if nu not in known:
            known[nu] = float(excess(np.array([nu]), rows)[0])
        return known[nu]

    undamped, damped = one(0.0), one(float(largest))
    root = np.nan
    if undamped == 0.0 or damped == 0.0:
        root = 0.0 if undamped == 0.0 else float(largest)
    elif undamped > 0.0 > damped:
        root = float(brentq(one, 0.0, float(largest), xtol=DAMPING_TOLERANCE))
    return np.array([root]), np.array([undamped]), np.array([damped])


def _pump_ends(string: RodString, period: np.ndarray, position: np.ndarray, load: np.ndarray, *,
               fluid_density: float, method: str, gravity: float):
    """A search's transfer of K surface cards (K, N) of periods (K,) (checked once by the caller,
    :func:`_many`): (nu, rows) -> the pump position and load, shape (K', N), and the pump card's work
    per cycle [J], shape (K',), of the cards ``rows`` (increasing indices, as :func:`decreasing_roots`
    gives them) at their damping factors nu (K',). Gibbs: the cards' Fourier series taken once for all
    the calls, the pump's end alone transformed back, its work from its series
    (:func:`.analysis.series_work`), the pump card as :func:`_solve` makes it. Another method: its
    pump card by :func:`_solve`, the work by :func:`.analysis.card_work`."""
    if method != "gibbs":
        def solved(nu: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            card = _solve(string, period[rows], position[rows], load[rows], fluid_density=fluid_density,
                          damping_factor=nu, method=method, harmonics=None, gravity=gravity, upward=False)
            return card.pump_position, card.pump_load, card_work(card.pump_position, card.pump_load)

        return solved
    static = string.static_tension(fluid_density, gravity)
    omega, w, f = gibbs.series(period, position, load - static[0])
    samples = position.shape[-1]

    def transferred(nu: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        damping = np.asarray(string.damping_coefficient(nu))[:, None]
        chosen = slice(None) if len(rows) == len(omega) else rows      # all the cards: no copies
        bottom_w, bottom_f = gibbs.transfer(string, omega[chosen], w[chosen], f[chosen], damping, bottom_only=True)
        return (np.fft.irfft(bottom_w, n=samples, axis=-1), np.fft.irfft(bottom_f, n=samples, axis=-1) + static[-1],
                series_work(bottom_w, bottom_f, samples))

    return transferred


def _many(period, position, load, what: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """K cards (K, N) and their periods (K,) from one card or many (checked by :func:`_card_arrays`)."""
    position, load = (np.atleast_2d(a) for a in _card_arrays(period, position, load, what))
    return np.broadcast_to(np.asarray(period, dtype=float), position.shape[:1]).copy(), position, load


def damping_for_pump_work(string: RodString, period: float, position, load, pump_work: float, *,
                          fluid_density: float, method: str = "gibbs", gravity: float = STANDARD_GRAVITY,
                          largest: float = LARGEST_DAMPING) -> float:
    """The damping factor nu at which the pump card does a given work per cycle [-].

    Energy balance of the rods over one cycle: surface card work = pump card work +
    damping dissipation. When the useful pump work is known (e.g. the hydraulic work per
    stroke from the production rate and the net lift), the dissipation, hence nu, follows
    [Gibbs1963] (Gibbs estimated c from polished-rod minus hydraulic power). The root on
    [0, largest] by :func:`decreasing_roots`.

    Parameters
    ----------
    string, period, position, load, fluid_density, method, gravity
        As :func:`pump_card`, for ONE card (shape (N,)).
    pump_work : float
        Target work of the pump card per cycle [J].
    largest : float
        Upper end of the search [-].

    Raises
    ------
    DownholeError
        If the target is not between the pump work at nu = largest and at nu = 0 (the
        surface card's work): no damping explains it.
    """
    periods, position, load = _many(period, position, load, "surface card")
    if len(position) != 1:
        raise DownholeError("damping_for_pump_work takes one card of shape (N,)")

    transferred = _pump_ends(string, periods, position, load, fluid_density=fluid_density, method=method,
                             gravity=gravity)

    def excess(nu: np.ndarray, rows: np.ndarray) -> np.ndarray:
        return transferred(nu, rows)[2] - pump_work

    roots, undamped, damped = decreasing_roots(excess, largest, 1)
    if np.isnan(roots[0]):
        raise DownholeError(f"pump work {pump_work / 1e3:.4g} kJ per cycle is not between "
                            f"{(damped[0] + pump_work) / 1e3:.4g} and {(undamped[0] + pump_work) / 1e3:.4g} kJ, the pump work at damping factors {largest:g} and 0: no "
                            f"damping factor explains it")
    return float(roots[0])


def dampings_from_fluid_load(string: RodString, period, position, load, fluid_load, *, fluid_density: float,
                             method: str = "gibbs", gravity: float = STANDARD_GRAVITY,
                             largest: float = LARGEST_DAMPING, solve=None) -> tuple[np.ndarray, tuple[str, ...]]:
    """The damping factors nu that close the energy balance of the rods with the pump's
    hydraulic work, for K cards of one rod string at once [-].

    The useful work of the pump per stroke is the fluid load times the net plunger
    stroke, F_o S_n; the rest of the surface card's work is dissipated along the rods
    ([Gibbs1963]: c from polished-rod minus hydraulic power; [EverittJennings1992]). The
    pump card, hence its work W_p and S_n (:func:`.analysis.summarise_pump_card`), depends
    on nu, so nu is the root of W_p(nu) - F_o S_n(nu) on [0, largest]
    (:func:`decreasing_roots`: every card's pump card at its own nu in one transfer).

    Parameters
    ----------
    string, method, gravity, fluid_density
        As :func:`pump_card`.
    period : float or array_like
        T [s] of each card (one for all, or shape (K,)).
    position, load : array_like
        Surface cards, shape (N,) or (K, N).
    fluid_load : float or array_like
        F_o = (p_d - p_i) A_p [N], one for all or per card.
    largest : float
        Upper end of the search [-].
    solve : callable, optional
        nu -> the pump card (a :class:`DownholeCard`) of another transfer of ONE card (a
        deviated well's march, :mod:`.deviated_diagnostic`, whose drag takes its share of the
        surface work); default the transfer of ``method``.

    Returns
    -------
    (numpy.ndarray, tuple of str)
        nu per card (NaN where none), and per card why there is none ('' where found): the
        undamped rods deliver less than F_o S_n (the fluid load is lower than assumed), more
        than ``largest`` would be needed, or a pump card without a stroke or load level.
    """
    periods, position, load = _many(period, position, load, "surface card")
    count = len(position)
    if solve is not None and count != 1:
        raise DownholeError("a transfer of its own (solve) takes one card")
    fluid = np.broadcast_to(np.asarray(fluid_load, dtype=float), (count,))
    problems = [""] * count

    if solve is None:
        pump_ends = _pump_ends(string, periods, position, load, fluid_density=fluid_density, method=method,
                               gravity=gravity)
    else:
        def pump_ends(nu: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            card = solve(float(nu[0]))
            p, f = np.atleast_2d(card.pump_position), np.atleast_2d(card.pump_load)
            return p, f, card_work(p, f)

    def excess(nu: np.ndarray, rows: np.ndarray) -> np.ndarray:
        p, f, work = pump_ends(nu, rows)
        out = np.full(len(rows), np.nan)
        live = np.array([not problems[r] for r in rows], dtype=bool)
        if not live.all():
            p, f, work = p[live], f[live], work[live]
        try:
            net = summarise_pump_card(p, f).net_stroke
        except DownholeError:       # a card without a stroke or a load level: each card alone, for its message
            net = np.full(len(p), np.nan)
            for i, r in enumerate(rows[live]):
                try:
                    net[i] = summarise_pump_card(p[i], f[i]).net_stroke
                except DownholeError as exc:
                    problems[r] = str(exc)
        out[live] = work - fluid[rows[live]] * net
        return np.where(np.isnan(out), 0.0, out)    # a card with a problem stops at once

    roots, undamped, damped = (decreasing_roots if solve is None else _brent_root)(excess, largest, count)
    for k in range(count):
        if not problems[k] and undamped[k] < 0.0:
            problems[k] = (f"the rods without damping deliver {-undamped[k] / 1e3:.4g} kJ per cycle less than the "
                           f"pump's hydraulic work F_o S_n with F_o = {fluid[k] / 1e3:.4g} kN: the fluid load is lower "
                           f"(fluid level higher, pump less full) than the well says; give the damping factor")
        elif not problems[k] and damped[k] > 0.0:
            problems[k] = (f"the card dissipates more than damping factor {largest:g} explains with F_o = "
                           f"{fluid[k] / 1e3:.4g} kN; check the fluid level and the rods, or give the damping factor")
        if problems[k]:
            roots[k] = np.nan
    return roots, tuple(problems)


def damping_from_fluid_load(string: RodString, period: float, position, load, fluid_load: float, *,
                            fluid_density: float, method: str = "gibbs", gravity: float = STANDARD_GRAVITY,
                            largest: float = LARGEST_DAMPING, solve=None) -> float:
    """The damping factor of ONE card (shape (N,)) that closes the rods' energy balance
    (:func:`dampings_from_fluid_load`, whose parameters it takes) [-].

    Raises
    ------
    DownholeError
        When there is none, saying why.
    """
    if np.ndim(position) != 1:
        raise DownholeError("damping_from_fluid_load takes one card of shape (N,)")
    roots, problems = dampings_from_fluid_load(string, period, position, load, fluid_load, fluid_density=fluid_density,
                                               method=method, gravity=gravity, largest=largest, solve=solve)
    if problems[0]:
        raise DownholeError(problems[0])
    return float(roots[0])


def load_transfer_slope(position, load) -> np.ndarray:
    """Diagonal slope of a card, R / S [N/m]: load range over position range, per card.

    Any card has two points (its minimum and maximum load) whose secant is at least
    R / S steep, so R / S is a lower bound of the card's steepest load transfer. A
    quasi-static string transfers load no faster than its spring constant k_r (a stuck
    plunger gives exactly R / S = k_r); dynamic loads add to R, hence the margin of
    :mod:`.plausibility`. A measured slope such as the 25 %-75 % secant of the pickup is
    not used: the rods' inertia near the bottom of the stroke makes it steep on sound
    cards.
    """
    position = np.atleast_2d(position)
    load = np.atleast_2d(load)
    stroke = np.ptp(position, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(stroke > 0, np.ptp(load, axis=-1) / np.where(stroke > 0, stroke, 1.0), np.inf)
