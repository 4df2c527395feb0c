"""What the pump card says about the well: inferred production, intake pressure, fluid level, energy.

Pure functions of SI numbers (one card's, or arrays of cards'):

* **inferred production** Q = A_p S_n N f_run eta_p - q_s: the plunger's net stroke through
  liquid S_n (read off the pump card), the plunger area A_p, the strokes per unit time N,
  the share of the day the unit runs f_run, and either a stated pump (volumetric)
  efficiency eta_p or the slippage q_s past the plunger from its clearance (field form
  BFPD = 0.1166 d^2 SPM S_n eta %runtime with d and S_n in inches);
* **slippage** past a plunger of diameter D and length L_p with diametral clearance c
  (radial gap c / 2) under the pressure difference dp of the fluid load, laminar flow
  through the narrow concentric annulus (Poiseuille): q = pi D (c/2)^3 dp / (12 mu L_p)
  ([Wang2019]; the drag of the moving plunger, the Couette part, reverses with the stroke
  and is left out), while the plunger carries the load;
* **pump intake pressure** p_i = p_d - F_o / A_p from the card's fluid load and the
  discharge pressure p_d = p_th + rho g H over the pump's true vertical depth H
  ([Rowlan2009PIP]);
* **producing fluid level**: the liquid above the pump h = (p_i - p_c) / (rho g), the
  casing-head pressure p_c at the top of the annulus and the gas-free liquid gradient
  (the gas column's weight neglected), and its depth from the surface H - h
  ([Rowlan2009PIP], [McCoyRowlanPodio]);
* **energy per day** E = P_PR / eta_d x 24 h x f_run from the polished-rod power P_PR and
  the efficiency eta_d of the drive between the supply and the polished rod; its cost
  with a price per unit energy.
"""

from __future__ import annotations

import math

import numpy as np

from ...errors import DownholeError
from ..constants import STANDARD_GRAVITY

#: Seconds in a day.
DAY = 86400.0


def _positive(name: str, value, unit: str, allow_zero: bool = False) -> np.ndarray:
    array = np.asarray(value, dtype=float)
    ok = np.isfinite(array) & ((array >= 0) if allow_zero else (array > 0))
    if not ok.all():
        raise DownholeError(f"{name} must be {'non-negative' if allow_zero else 'positive'} and finite, "
                            f"got {value} {unit}".rstrip())
    return array


def _share(name: str, value) -> float:
    share = float(value)
    if not (math.isfinite(share) and 0.0 < share <= 1.0):
        raise DownholeError(f"{name} must lie in (0, 1], got {share:g}")
    return share


def slippage_rate(plunger_diameter: float, clearance: float, plunger_length: float, viscosity: float,
                  pressure_difference) -> np.ndarray:
    """Liquid slipping past the plunger while it carries the fluid load [m^3/s].

    q = pi D (c/2)^3 dp / (12 mu L_p): laminar flow through the narrow concentric annulus
    between plunger and barrel ([Wang2019]).

    Parameters
    ----------
    plunger_diameter : float
        D [m].
    clearance : float
        Diametral clearance c between barrel and plunger [m] (the radial gap is c / 2).
    plunger_length : float
        L_p [m].
    viscosity : float
        Dynamic viscosity mu of the liquid [Pa s].
    pressure_difference : float or array
        dp across the plunger [Pa], F_o / A_p.

    Examples
    --------
    1.5 in plunger, 0.003 in fit, 4 ft long, 1 cP water, 1000 psi: pi 0.0381 (3.81e-5)^3 6.895e6 /
    (12 1e-3 1.219) = 3.12e-6 m^3/s, 0.270 m^3/d (1.70 bbl/d).

    >>> q = slippage_rate(1.5 * 0.0254, 0.003 * 0.0254, 4 * 0.3048, 1e-3, 1000 * 6894.757)
    >>> round(float(q) * 86400, 3)
    0.27
    """
    for name, value, unit in (("plunger diameter", plunger_diameter, "m"), ("plunger clearance", clearance, "m"),
                              ("plunger length", plunger_length, "m"), ("viscosity", viscosity, "Pa s")):
        _positive(name, value, unit)
    dp = _positive("pressure difference", pressure_difference, "Pa", allow_zero=True)
    return math.pi * plunger_diameter * (clearance / 2.0)**3 * dp / (12.0 * viscosity * plunger_length)


def inferred_production(net_stroke, plunger_area: float, period: float, runtime: float, *,
                        pump_efficiency: float = 1.0, slippage=0.0, loaded_share=0.5) -> np.ndarray:
    """Liquid produced per unit time averaged over the day [m^3/s].

    Q = (A_p S_n / T eta_p - q_s t_load / T) f_run: the net stroke S_n [m] through liquid per
    period T [s], a stated pump efficiency eta_p (0..1, shrinkage and slippage together) or
    the slippage rate q_s [m^3/s] for the share ``loaded_share`` t_load / T of the cycle in
    which the plunger carries the load, times the runtime share f_run (0..1]. Never below 0.

    Examples
    --------
    The field form BFPD = 0.1166 d^2 SPM S_n eta %runtime: 1.5 in, 10 SPM, 100 in, 0.85, 75 %
    is 167.2 bbl/d:

    >>> d, spm, s = 1.5 * 0.0254, 10.0, 100 * 0.0254
    >>> q = inferred_production(s, math.pi * d**2 / 4, 60 / spm, 0.75, pump_efficiency=0.85)
    >>> round(float(q) * 86400 / 0.158987294928, 1), round(0.1166 * 1.5**2 * spm * 100 * 0.85 * 0.75, 1)
    (167.2, 167.2)
    """
    stroke = _positive("net stroke", net_stroke, "m", allow_zero=True)
    _positive("plunger area", plunger_area, "m²")
    _positive("period", period, "s")
    run, efficiency = _share("runtime", runtime), _share("pump efficiency", pump_efficiency)
    slip = _positive("slippage", slippage, "m³/s", allow_zero=True)
    loaded = np.clip(np.asarray(loaded_share, dtype=float), 0.0, 1.0)
    return np.maximum(plunger_area * stroke / period * efficiency - slip * loaded, 0.0) * run


def intake_pressure_from_load(fluid_load, plunger_area: float, discharge_pressure: float) -> np.ndarray:
    """Pump intake pressure p_i = p_d - F_o / A_p [Pa] ([Rowlan2009PIP]).

    >>> round(float(intake_pressure_from_load(13000.0, 1e-3, 12.3e6)) / 1e6, 3)
    -0.7
    """
    _positive("plunger area", plunger_area, "m²")
    return float(discharge_pressure) - np.asarray(fluid_load, dtype=float) / plunger_area


def fluid_above_pump(intake_pressure, casing_head_pressure: float, liquid_density: float,
                     gravity: float = STANDARD_GRAVITY) -> np.ndarray:
    """Height of liquid above the pump h = (p_i - p_c) / (rho g) [m], the gas-free gradient
    (the annular gas column's weight neglected) ([Rowlan2009PIP]). Negative when the intake
    pressure is below the casing-head pressure: the card says more than the well can.

    >>> round(float(fluid_above_pump(804e3, 0.0, 820.0, 9.81)), 2)
    99.95
    """
    _positive("liquid density", liquid_density, "kg/m³")
    return (np.asarray(intake_pressure, dtype=float) - casing_head_pressure) / (liquid_density * gravity)


def energy_per_day(polished_rod_power, system_efficiency: float, runtime: float) -> np.ndarray:
    """Energy the well takes from the supply per day [J]: E = P_PR / eta_s x f_run x 86 400 s, eta_s
    the system efficiency from the supply to the polished rod.

    >>> round(float(energy_per_day(5000.0, 0.8, 0.5)) / 3.6e6, 1)   # kWh per day
    75.0
    """
    power = _positive("polished-rod power", polished_rod_power, "W", allow_zero=True)
    return power / _share("system efficiency", system_efficiency) * _share("runtime", runtime) * DAY
