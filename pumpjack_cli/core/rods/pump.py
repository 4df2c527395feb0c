"""The downhole pump as the bottom boundary of the rod string: valves, chamber and tubing.

Load datum ([Gibbs1963]; derivation in ``docs/predict.md``): with the effective tension
T_e = T + p A (true axial force plus the hydrostatic pressure on the rod section), the
weight and buoyancy of the rods enter only through the static profile
T_e,s(x) = g int_x^L m (1 - rho_f / rho_r) dx, and the rods pull the plunger with
T_e(L) = (p_d - p_c) A_p: p_d the discharge pressure above the plunger, p_c the chamber
pressure below it, A_p the gross plunger area. This net plunger load F lies in
[0, F_o], F_o = (p_d - p_i) A_p the fluid load, p_i the intake pressure:

* travelling valve open (p_c = p_d): F = 0, the plunger moves down through the liquid;
* standing valve open (p_c = p_i): F = F_o, the plunger moves up and the chamber fills;
* both closed: the chamber content sets p_c. Liquid is incompressible: a liquid-filled
  chamber holds the plunger still while the load transfers. The part 1 - f of the
  swept volume the liquid does not fill (fillage f) is either vapour at the intake
  pressure that collapses without resistance (fluid pound: the load stays F_o until
  the plunger hits the liquid; at zero fillage it never does, so the column stays on
  the plunger and the load never transfers) or, as an option, a polytropic gas
  p V^n = const (gas interference), expelled first when the travelling valve opens.

Unanchored tubing is a spring k_t = E_t A_t / L_t at the pump: it carries F_o - F (the
part of the fluid load not on the plunger) and moves the barrel by -(F_o - F)/k_t, so
the valves see the plunger position relative to the barrel
zeta = z_p + (F_o - F)/k_t ([API11L]: the plunger stroke loses F_o / k_t).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import PredictionError
from ..constants import STANDARD_GRAVITY

#: Young's modulus of steel tubing, 30e6 psi [Pa] ([API11L]), with 1 psi = 6894.757 Pa ([NIST811]).
TUBING_MODULUS = 30e6 * 6894.757293168
_INCH = 0.0254

#: API tubing by nominal size: outer and inner diameter [m] of the standard-weight
#: joints (2-3/8 in 4.70 lb/ft, 2-7/8 in 6.50 lb/ft, 3-1/2 in 9.30 lb/ft) ([API5CT]).
TUBING = {
    "2-3/8": (2.375 * _INCH, 1.995 * _INCH),
    "2-7/8": (2.875 * _INCH, 2.441 * _INCH),
    "3-1/2": (3.500 * _INCH, 2.992 * _INCH),
}

#: Newton/bisection steps of the closed-chamber gas solve.
_GAS_ITERATIONS = 60


def tubing_stiffness(size: str, length: float, modulus: float = TUBING_MODULUS) -> float:
    """Axial stiffness k_t = E A_t / L_t [N/m] of unanchored tubing of an API size.

    size: "2-3/8", "2-7/8" or "3-1/2"; length L_t [m] from the anchor (the surface if
    unanchored) to the pump; modulus E [Pa]. RP 11L tabulates the stretch constant
    E_t = 12 / (E A_t) [in/(lb·ft)]: 0.307e-6, 0.221e-6, 0.154e-6 ([API11L]).

    >>> k = tubing_stiffness("2-3/8", 1000 * 0.3048)
    >>> round(1 / (k * 0.0254 / 4.4482216152605) / 1000 * 1e6, 3)   # in/lb per 1000 ft, x 1e6
    0.307
    """
    if size not in TUBING:
        raise PredictionError(f"unknown tubing size {size!r}; use one of {', '.join(TUBING)}")
    if not length > 0:
        raise PredictionError(f"tubing length must be positive, got {length} m")
    outer, inner = TUBING[size]
    return modulus * math.pi * (outer**2 - inner**2) / 4.0 / length


def discharge_pressure(pump_depth: float, fluid_density: float, tubing_head_pressure: float = 0.0,
                       gravity: float = STANDARD_GRAVITY) -> float:
    """Pressure at the pump's discharge, p_d = p_th + rho g L [Pa], gauge: the tubing full of the
    produced fluid over the pump's true vertical depth L [m] ([API11L]).

    >>> round(discharge_pressure(1530.0, 820.0, 0.0, 9.81))
    12307626
    """
    return tubing_head_pressure + fluid_density * gravity * pump_depth


def pump_pressures(pump_depth: float, fluid_density: float, *, submergence: float | None = None,
                   intake_pressure: float | None = None, tubing_head_pressure: float = 0.0,
                   casing_head_pressure: float = 0.0, gravity: float = STANDARD_GRAVITY) -> tuple[float, float]:
    """Discharge and intake pressure at the pump (p_d, p_i) [Pa], hydrostatic.

    p_d = p_th + rho g L (the tubing full of the produced fluid); p_i given, or from the
    fluid level h above the pump (submergence): p_i = p_c + rho g h (the annulus gas
    column neglected). pump_depth L [m]; fluid_density rho [kg/m^3]; pressures [Pa], gauge.
    With no surface pressures F_o = (p_d - p_i) A_p = rho g (L - h) A_p, the textbook
    fluid load ([API11L]: F_o = 0.340 G D^2 H).

    >>> pd, pi = pump_pressures(1530.0, 820.0, submergence=100.0, gravity=9.81)
    >>> round((pd - pi) * 3.14159265 * 0.038**2 / 4, 1)   # core.well.fluid_load for 1430 m lift
    13046.0
    """
    if (submergence is None) == (intake_pressure is None):
        raise PredictionError("give either the pump submergence or the pump intake pressure, not both")
    for name, value in (("pump depth", pump_depth), ("fluid density", fluid_density)):
        if not (math.isfinite(value) and value > 0):
            raise PredictionError(f"{name} must be positive and finite, got {value}")
    discharge = discharge_pressure(pump_depth, fluid_density, tubing_head_pressure, gravity)
    if submergence is not None:
        if not 0.0 <= submergence <= pump_depth:
            raise PredictionError(f"submergence {submergence:.6g} m must lie between 0 and the pump depth {pump_depth:.6g} m")
        intake = casing_head_pressure + fluid_density * gravity * submergence
    elif intake_pressure is not None:
        intake = float(intake_pressure)
    if not (math.isfinite(intake) and math.isfinite(discharge)):
        raise PredictionError("pump pressures must be finite")
    return discharge, intake


@dataclass(frozen=True)
class Pump:
    """The pump and its tubing, SI (module docstring).

    Parameters
    ----------
    plunger_area : float
        Gross plunger area A_p [m^2].
    discharge_pressure, intake_pressure : float
        p_d above the plunger and p_i below the standing valve [Pa]; p_d >= p_i.
    fillage : float
        f in [0, 1]: liquid share of the volume swept while the standing valve is open.
    gas_exponent : float or None
        None: the unfilled share is vapour (fluid pound); n >= 1: polytropic gas at p_i.
    dead_volume : float
        Chamber volume left at the bottom of the stroke [m^3] (used by the gas option).
    tubing_stiffness : float
        k_t [N/m]; math.inf for anchored tubing.
    travelling_valve_leak, standing_valve_leak : float
        Leak of the travelling (with the plunger) and standing valve [m^3/s] at the full
        fluid-load pressure difference F_o / A_p; 0: tight (:mod:`.pump_faults`).
    bottom_stop, top_stop : float or None
        Plunger position relative to the barrel [m] where it meets the pump's bottom or top
        (tagging, :mod:`.pump_faults`); None: no contact.
    """

    plunger_area: float
    discharge_pressure: float
    intake_pressure: float
    fillage: float = 1.0
    gas_exponent: float | None = None
    dead_volume: float = 0.0
    tubing_stiffness: float = math.inf
    travelling_valve_leak: float = 0.0
    standing_valve_leak: float = 0.0
    bottom_stop: float | None = None
    top_stop: float | None = None

    @property
    def faulty(self) -> bool:
        """True when a valve leaks or a stop is set (the chamber of :mod:`.pump_faults`)."""
        return (self.travelling_valve_leak > 0.0 or self.standing_valve_leak > 0.0
                or self.bottom_stop is not None or self.top_stop is not None)

    @property
    def fluid_load(self) -> float:
        """F_o = (p_d - p_i) A_p [N]."""
        return (self.discharge_pressure - self.intake_pressure) * self.plunger_area

    def check(self) -> None:
        """Raise :class:`PredictionError` for data that make no pump."""
        if not (math.isfinite(self.plunger_area) and self.plunger_area > 0):
            raise PredictionError(f"plunger area must be positive and finite, got {self.plunger_area} m²")
        if not (math.isfinite(self.intake_pressure) and math.isfinite(self.discharge_pressure)):
            raise PredictionError("pump pressures must be finite")
        if not self.intake_pressure >= 0:
            raise PredictionError(f"pump intake pressure {self.intake_pressure:.6g} Pa must not be negative")
        if not self.discharge_pressure >= self.intake_pressure:
            raise PredictionError(
                f"pump intake pressure {self.intake_pressure:.6g} Pa exceeds the discharge pressure "
                f"{self.discharge_pressure:.6g} Pa: the well would flow, there is no fluid load to lift"
            )
        if not 0.0 <= self.fillage <= 1.0:
            raise PredictionError(f"pump fillage must lie between 0 and 1, got {self.fillage}")
        if self.gas_exponent is not None:
            if not (math.isfinite(self.gas_exponent) and self.gas_exponent >= 1.0):
                raise PredictionError(f"polytropic gas exponent must be >= 1, got {self.gas_exponent}")
            if not self.intake_pressure > 0:
                raise PredictionError("the gas option needs a positive pump intake pressure")
        if not (math.isfinite(self.dead_volume) and self.dead_volume >= 0):
            raise PredictionError(f"dead volume must be >= 0, got {self.dead_volume} m³")
        if not self.tubing_stiffness > 0:
            raise PredictionError(f"tubing stiffness must be positive (math.inf: anchored), got {self.tubing_stiffness}")
        from .pump_faults import check_faults

        check_faults(self)


class PumpChamber:
    """The valves and chamber, stepped in time against the rod string (module docstring).

    Each :meth:`step` gets the rods' relation ``zeta = known - compliance * F`` for the
    new sample (the plunger position relative to the barrel [m], up positive, as an
    affine function of the pump load F [N]) and returns (F, zeta) obeying the valve
    laws. State: the plunger position of the last sample, the chamber volume and its
    liquid volume [m^3], the gas constant p V_g^n, and the liquid volumes that passed
    the standing valve (``intake``) and the travelling valve (``discharge``).
    """

    def __init__(self, pump: Pump, compliance: float, position: float):
        self.area = pump.plunger_area
        self.discharge_pressure = pump.discharge_pressure
        self.intake_pressure = pump.intake_pressure
        self.fluid_load = pump.fluid_load
        self.fillage = pump.fillage
        self.exponent = 0.0 if pump.gas_exponent is None else pump.gas_exponent
        self.dead_volume = pump.dead_volume
        # plain floats: the chamber is stepped one sample at a time, where a numpy scalar's every
        # operation would cost a dispatch (a start position read from an array is one)
        self.compliance = float(compliance)
        self.position = float(position)
        self.volume = pump.dead_volume
        self.liquid = pump.dead_volume
        self.gas = 0.0
        self.intake = 0.0
        self.discharge = 0.0

    def rebase(self, lowest: float) -> None:
        """Move the chamber-volume datum so that the plunger's lowest position ``lowest`` [m]
        (of the last cycle) leaves the dead volume; keeps the gas and liquid contents."""
        target = self.dead_volume + self.area * (self.position - lowest)
        gas_volume = self.volume - self.liquid
        self.volume = target
        self.liquid = max(target - max(gas_volume, 0.0), 0.0)

    def step(self, known: float) -> tuple[float, float]:
        """Pump load F [N] and plunger position zeta [m] of the new sample."""
        gas_volume = self.volume - self.liquid
        if gas_volume > 0.0 or self.fillage == 0.0 == self.exponent:
            if self.exponent == 0.0:
                load, position = self._vapour(known, gas_volume)
            else:
                load, position = self._gas(known, gas_volume)
        else:
            load, position = self._locked(known)
        self.position = position
        return load, position

    def _admit(self, swept: float) -> None:
        """Standing valve open: the chamber grows by ``swept``, a share f of it liquid."""
        self.volume += swept
        self.liquid += self.fillage * swept
        self.intake += self.fillage * swept
        if self.exponent > 0.0:
            self.gas = self.intake_pressure * max(self.volume - self.liquid, 0.0) ** self.exponent

    def _expel(self, position: float, start: float) -> None:
        """Travelling valve open from ``start`` to ``position``: gas leaves first, then liquid."""
        self.volume += self.area * (position - start)
        left = self.volume - self.liquid
        if left <= 0.0:
            self.discharge -= left
            self.liquid = self.volume
            self.gas = 0.0
        elif self.exponent > 0.0:
            self.gas = self.discharge_pressure * left**self.exponent

    def _locked(self, known: float) -> tuple[float, float]:
        """Liquid-filled chamber: the plunger stays put unless a valve opens."""
        trial = (known - self.position) / self.compliance
        if trial > self.fluid_load:
            position = known - self.compliance * self.fluid_load
            self._admit(self.area * (position - self.position))
            return self.fluid_load, position
        if trial < 0.0:
            self._expel(known, self.position)
            return 0.0, known
        return trial, self.position

    def _vapour(self, known: float, vapour: float) -> tuple[float, float]:
        """Vapour at the intake pressure: full load until the plunger meets the liquid (never,
        at zero fillage: no liquid enters, the travelling valve never opens)."""
        position = known - self.compliance * self.fluid_load
        swept = self.area * (position - self.position)
        if swept >= 0.0:
            self._admit(swept)
            return self.fluid_load, position
        if vapour + swept >= 0.0 or self.fillage == 0.0:
            self.volume += swept
            return self.fluid_load, position
        self.position -= vapour / self.area
        self.volume = self.liquid
        return self._locked(known)

    def _gas(self, known: float, gas_volume: float) -> tuple[float, float]:
        """Polytropic gas p V^n = C between the valves, with the valves' limits."""
        area, n, c0 = self.area, self.exponent, self.compliance
        at_intake = (self.gas / self.intake_pressure) ** (1.0 / n)
        at_discharge = (self.gas / self.discharge_pressure) ** (1.0 / n)
        z_intake = self.position + (at_intake - gas_volume) / area
        z_discharge = self.position + (at_discharge - gas_volume) / area
        if z_intake - known + c0 * self.fluid_load <= 0.0:
            self.volume += area * (z_intake - self.position)
            position = known - c0 * self.fluid_load
            self._admit(area * (position - z_intake))
            return self.fluid_load, position
        if z_discharge - known >= 0.0:
            self.volume += area * (z_discharge - self.position)
            self._expel(known, z_discharge)
            return 0.0, known
        lo, hi = z_discharge, z_intake
        z = min(max(self.position, lo), hi)
        for _ in range(_GAS_ITERATIONS):
            volume = gas_volume + area * (z - self.position)
            pressure = self.gas / volume**n
            residual = z - known + c0 * area * (self.discharge_pressure - pressure)
            if residual > 0.0:
                hi = z
            else:
                lo = z
            newton = z - residual / (1.0 + c0 * area * area * n * pressure / volume)
            z_next = newton if lo < newton < hi else 0.5 * (lo + hi)
            if abs(z_next - z) <= 1e-15 * (1.0 + abs(z)):
                z = z_next
                break
            z = z_next
        volume = gas_volume + area * (z - self.position)
        self.volume += area * (z - self.position)
        return area * (self.discharge_pressure - self.gas / volume**n), z
