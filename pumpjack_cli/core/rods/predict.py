"""Predicted dynamometer cards: the damped wave equation of the rod string between the
polished rod and the pump (uniform crank rotation).

Model ([Gibbs1963]; derivations in ``docs/predict.md``):

* rods: per taper ``u_tt = a_i^2 u_xx - c u_t``, c = pi a nu / (2 L) (Gibbs' damping
  factor nu), displacement and force continuous at the joints; solved in modal form
  with exact steps (:mod:`.predict_modes`);
* top: the polished rod's position s(t) on a uniform time grid over one period;
* bottom: the pump's valves, chamber and tubing (:mod:`.pump`);
* gravity and buoyancy: only through the static effective-tension profile, so the
  polished-rod load is P = W_rf + F(0, t) with W_rf = g sum m_i L_i (1 - rho_f / rho_r),
  the buoyant weight of the rods with couplings, and F the dynamic force; the pump
  load is the net plunger load (p_d - p_c) A_p, 0 with the travelling valve open and
  F_o with the standing valve open. Fluid inertia and Coulomb friction are not modelled.

Periodic steady state: the pump is marched sample by sample, cycle after cycle, from
the periodic response to the rigid-rod load (F_o on the upstroke), until the pump load
and plunger position repeat to ``tolerance``; the rods' response to the polished rod
is periodic from the start (exact), and to the pump load it is carried between cycles
in the modal states. The cards are then evaluated from the periodic pump load. A pump
that pounds fluid may settle into strokes that alternate (the rods' vibration left by one
stroke's hit of the fluid moves where the next one hits) and repeat only after 2 to 4
strokes; the periodic state is then that of those strokes together, and the cards are the
stroke of the highest polished-rod load (:func:`assemble`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ...errors import PredictionError
from ..mechanism import Mechanism
from ..constants import STANDARD_GRAVITY, STEEL_DENSITY
from .predict_solver import (Convergence, PumpMarch, WellModel, converge, periodic_carry,
                             periodic_fields, spectral_derivatives, well_model, with_step)
from .pump import Pump
from .pump_faults import pump_chamber
from .string import RodString

#: Default largest relative change of pump load and plunger position between cycles.
DEFAULT_TOLERANCE = 1e-8
#: Cycles marched at most.
MAX_CYCLES = 400
#: Liquid discharged per stroke taken as none, as a share of the plunger's swept volume: what the
#: sums of the chamber's volumes leave of nothing (a leak beyond the pump's rate: some 1e-11).
ROUNDING = 1e-9


@dataclass(frozen=True)
class CardExtreme:
    """An extreme of a card: value, time [s] and crank angle [rad] (NaN without one)."""

    value: float
    time: float
    crank_angle: float


@dataclass(frozen=True)
class PredictionSummary:
    """Scalar results (SI).

    Loads [N]: peak and minimum polished-rod load, buoyant rod weight W_rf, fluid load
    F_o. Strokes [m]: polished rod; gross plunger (the rod end's travel); net plunger
    (liquid discharged / A_p); static_stretch F_o (sum L/EA + 1/k_t). Pump displacement
    per cycle [m^3] and rate [m^3/s]. Works per cycle [J]: surface card (polished-rod
    work), pump card (work on the fluid), damping dissipation; energy_residual = (surface
    - pump - damping) / surface; polished_rod_power [W] = surface work / period [s].
    When the pump's state repeats only after several strokes (``convergence.strokes``), the
    loads and strokes are the shown stroke's, the works and production the strokes' means,
    and stroke_peak_loads [N] and stroke_displacements [m^3] give each stroke's (in order).
    """

    peak_polished_rod_load: CardExtreme
    minimum_polished_rod_load: CardExtreme
    buoyant_rod_weight: float
    fluid_load: float
    polished_rod_stroke: float
    gross_plunger_stroke: float
    net_plunger_stroke: float
    static_stretch: float
    pump_displacement: float
    pump_rate: float
    surface_card_work: float
    pump_card_work: float
    damping_dissipation: float
    energy_residual: float
    polished_rod_power: float
    period: float
    convergence: Convergence
    stroke_peak_loads: tuple[float, ...] = ()
    stroke_displacements: tuple[float, ...] = ()


@dataclass(frozen=True)
class Prediction:
    """Surface and pump cards on the uniform time grid t_k = k T / N (SI).

    time [s]; crank_angle [rad] (NaN where unknown); polished_rod_position [m] (up,
    as given) and polished_rod_velocity [m/s]; polished_rod_load P [N]; plunger_position
    [m] (up: the rod end, from where it hangs with the polished rod at the bottom of its
    stroke and no fluid load); pump_load [N] (net plunger load); chamber_pressure [Pa];
    taper_top_load and taper_bottom_load [N], shape (tapers, N): effective axial force
    (buoyant weight below plus dynamic force; divided by the area it is the von Mises
    stress of the rod under axial load and fluid pressure).
    """

    time: np.ndarray
    crank_angle: np.ndarray
    polished_rod_position: np.ndarray
    polished_rod_velocity: np.ndarray
    polished_rod_load: np.ndarray
    plunger_position: np.ndarray
    pump_load: np.ndarray
    chamber_pressure: np.ndarray
    taper_top_load: np.ndarray
    taper_bottom_load: np.ndarray
    summary: PredictionSummary


def card_extreme(values: np.ndarray, time: np.ndarray, angle: np.ndarray, pick) -> CardExtreme:
    """The sample picked by ``pick`` (numpy.argmax or numpy.argmin) with its time [s] and crank angle [rad]."""
    i = int(pick(values))
    return CardExtreme(float(values[i]), float(time[i]), float(angle[i]))


def predict(rods: RodString, pump: Pump, position: np.ndarray, period: float, *, damping: float,
            fluid_density: float, rod_density: float = STEEL_DENSITY, crank_angle: np.ndarray | None = None,
            tolerance: float = DEFAULT_TOLERANCE, max_cycles: int = MAX_CYCLES,
            gravity: float = STANDARD_GRAVITY) -> Prediction:
    """Surface and pump cards of a well driven at uniform crank speed.

    Parameters
    ----------
    rods : RodString
        Tapers from the top down (mass per length with couplings).
    pump : Pump
        Plunger, pressures, fillage, gas, tubing (:class:`~.pump.Pump`).
    position : numpy.ndarray
        Polished-rod position s(t_k) [m], up positive, on t_k = k T / N, k = 0 .. N-1.
    period : float
        T [s], one pumping cycle.
    damping : float
        Gibbs' dimensionless damping factor nu [-], c = pi a nu / (2 L).
    fluid_density, rod_density : float
        [kg/m^3], for the buoyant rod weight.
    crank_angle : numpy.ndarray, optional
        Crank angle [rad] at the samples, carried into the result.

    Returns
    -------
    Prediction
        Cards on the same time grid and the summary.

    References
    ----------
    [Gibbs1963] (wave equation, damping, buoyancy datum); [API11L] (tubing stretch).
    """
    s = np.asarray(position, dtype=float)
    if s.ndim != 1 or s.size < 16:
        raise PredictionError(f"polished-rod position must be a 1-D array of at least 16 samples, got shape {s.shape}")
    if not np.all(np.isfinite(s)):
        raise PredictionError("polished-rod position holds non-finite values")
    if not (np.isfinite(period) and period > 0):
        raise PredictionError(f"period must be positive and finite, got {period} s")
    if not 0 < tolerance < 1e-2:
        raise PredictionError(f"tolerance must lie in (0, 0.01), got {tolerance}")
    samples = s.size
    angle = np.full(samples, np.nan) if crank_angle is None else np.asarray(crank_angle, dtype=float)
    if angle.shape != s.shape:
        raise PredictionError(f"crank angle must have one value per position sample ({samples}), got shape {angle.shape}")
    stroke = float(np.ptp(s))
    if not stroke > 0:
        raise PredictionError("the polished rod does not move")
    model = well_model(rods, pump, damping=damping, step=period / samples, samples=samples,
                       fluid_density=fluid_density, rod_density=rod_density, gravity=gravity)
    velocity, acceleration = spectral_derivatives(s, period)
    top_drive = -(acceleration + model.modes.damping * velocity)
    f_o = pump.fluid_load
    driven = periodic_fields(model, np.zeros(samples), -s, -velocity, top_drive)
    guess = np.where(velocity > 0.0, f_o, 0.0)
    carry = periodic_carry(model, guess)
    start = periodic_fields(model, guess, -s, -velocity, top_drive).plunger_down[-1]
    chamber = pump_chamber(pump, model.compliance, (f_o - guess[-1]) / pump.tubing_stiffness - start,
                           period / samples)
    march = PumpMarch(model, chamber, carry, float(guess[-1]), float(start))
    load, _, discharged, convergence = converge(march, driven, max(f_o, 1.0), stroke, tolerance, max_cycles)
    time = np.arange(samples) * (period / samples)
    return assemble(model, time, angle, s, velocity, top_drive, load, discharged, period, convergence)


def assemble(model: WellModel, time: np.ndarray, angle: np.ndarray, position: np.ndarray, velocity: np.ndarray,
             top_drive: np.ndarray, load: np.ndarray, discharged: float | tuple[float, ...], period: float,
             convergence: Convergence) -> Prediction:
    """Cards and summary from the periodic pump load and the polished-rod motion (up positive).

    ``load`` holds one stroke's pump load, or the pump loads of strokes that repeat together
    (strokes x samples, :func:`~.predict_solver.converge`) with the liquid each discharged:
    the rods' response is then periodic over those strokes, and the cards are those of the
    stroke with the highest polished-rod load (the one the rods and the gearbox must bear),
    the works, dissipation and production per stroke the means of the strokes, so that the
    energy balance holds as for one stroke (the rods store different energies at the
    strokes' starts). ``time``, ``angle``, ``position``, ``velocity`` and ``top_drive`` are one
    stroke's samples, the same for every stroke, or every stroke's in turn (a machine whose
    speed follows the strokes); ``period`` [s] is a stroke's.
    """
    pump = model.pump
    loads = np.atleast_2d(load)
    strokes, samples = loads.shape
    volumes = np.atleast_1d(np.asarray(discharged, dtype=float))

    def every(values: np.ndarray) -> np.ndarray:
        """Every stroke's samples in turn."""
        return values if values.size == loads.size else np.tile(values, strokes)

    step = period / samples
    if strokes > 1:
        model = with_step(model, step, strokes * samples)
    velocities = every(velocity)
    fields = periodic_fields(model, loads.ravel(), -every(position), -velocities, every(top_drive))
    joint = (fields.joint_force + model.weight_below[:, None]).reshape(-1, strokes, samples)
    peaks = joint[0].max(axis=1)
    shown = int(np.argmax(peaks))
    window = slice(shown * samples, (shown + 1) * samples)
    time, angle, position, velocity = (every(values)[window] for values in (time, angle, position, velocity))
    polished, load = joint[0, shown], loads[shown]
    plungers = -fields.plunger_down
    plunger = plungers[window]
    surface = float(np.sum(fields.joint_force[0] * velocities) * step) / strokes
    pump_work = float(np.sum(0.5 * (loads.ravel() + np.roll(loads.ravel(), -1))
                             * (np.roll(plungers, -1) - plungers))) / strokes
    dissipation = fields.dissipation / strokes
    per_stroke = float(np.sum(volumes)) / strokes
    if abs(per_stroke) <= ROUNDING * pump.plunger_area * float(np.ptp(plungers)):
        per_stroke = 0.0    # the chamber's bookkeeping of a pump that lifts nothing (a leak beyond its rate)
    f_o = pump.fluid_load
    summary = PredictionSummary(
        peak_polished_rod_load=card_extreme(polished, time, angle, np.argmax),
        minimum_polished_rod_load=card_extreme(polished, time, angle, np.argmin),
        buoyant_rod_weight=model.buoyant_weight,
        fluid_load=f_o,
        polished_rod_stroke=float(np.ptp(position)),
        gross_plunger_stroke=float(np.ptp(plunger)),
        net_plunger_stroke=per_stroke / pump.plunger_area,
        static_stretch=f_o * (model.modes.static_compliance + 1.0 / pump.tubing_stiffness),
        pump_displacement=per_stroke,
        pump_rate=per_stroke / period,
        surface_card_work=surface,
        pump_card_work=pump_work,
        damping_dissipation=dissipation,
        energy_residual=(surface - pump_work - dissipation) / surface if surface != 0 else 0.0,
        polished_rod_power=surface / period,
        period=period,
        convergence=convergence,
        stroke_peak_loads=tuple(float(peak) for peak in peaks),
        stroke_displacements=tuple(float(volume) for volume in volumes),
    )
    return Prediction(
        time=time,
        crank_angle=angle,
        polished_rod_position=position,
        polished_rod_velocity=velocity,
        polished_rod_load=polished,
        plunger_position=plunger,
        pump_load=load,
        chamber_pressure=pump.discharge_pressure - load / pump.plunger_area,
        taper_top_load=joint[:-1, shown],
        taper_bottom_load=joint[1:, shown],
        summary=summary,
    )


def predict_cards(linkage: Mechanism, crank_speed: float, rods: RodString, pump: Pump, *, damping: float,
                  fluid_density: float, samples: int = 360, rod_density: float = STEEL_DENSITY,
                  resolution: int = 1024) -> Prediction:
    """Cards of a beam unit turning uniformly, on ``samples`` points of one cycle from crank angle 0.

    The polished rod moves exactly as the linkage makes it (s = A (psi - psi_bottom),
    theta = omega t); the wave equation is solved on ``samples`` x k points, k the
    smallest factor reaching ``resolution``, and every k-th point is returned (the
    summary keeps the fine grid's values). crank_speed omega [1/s]; other arguments as
    :func:`predict`.

    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> rods = RodString(np.array([1000.0]), np.array([2.85e-4]), np.array([2.1e11]), np.array([2.43]))
    >>> cards = predict_cards(Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0), 1.1422, rods, Pump(1e-3, 8e6, 1e6),
    ...                       damping=0.1, fluid_density=820.0, samples=180)
    >>> cards.time.size, round(float(cards.crank_angle[1]), 6) == round(2 * np.pi / 180, 6)
    (180, True)
    """
    if not 16 <= samples <= 1 << 16:
        raise PredictionError(f"samples per cycle must lie in 16 .. 65536, got {samples}")
    if not (np.isfinite(crank_speed) and crank_speed > 0):
        raise PredictionError(f"crank speed must be positive and finite, got {crank_speed} 1/s")
    factor, theta = crank_samples(samples, resolution)
    position = linkage.rod_position(theta)
    fine = predict(rods, pump, position, 2.0 * np.pi / crank_speed, damping=damping, fluid_density=fluid_density,
                   rod_density=rod_density, crank_angle=theta)
    return thinned(fine, factor)


def crank_samples(samples: int, resolution: int) -> tuple[int, np.ndarray]:
    """The factor k and the samples x k crank angles [rad] of one revolution from 0 that a
    prediction of ``samples`` points is solved on (the smallest multiple reaching ``resolution``)."""
    factor = max(1, -(-resolution // samples))
    return factor, np.arange(samples * factor) * (2.0 * np.pi / (samples * factor))


def thinned(fine: Prediction, factor: int) -> Prediction:
    """Every ``factor``-th sample of a prediction's cards (the summary is the fine grid's)."""
    pick = slice(None, None, factor)
    columns = ("time", "crank_angle", "polished_rod_position", "polished_rod_velocity", "polished_rod_load",
               "plunger_position", "pump_load", "chamber_pressure")
    return replace(fine, **{name: getattr(fine, name)[pick] for name in columns},
                   taper_top_load=fine.taper_top_load[:, pick], taper_bottom_load=fine.taper_bottom_load[:, pick])
