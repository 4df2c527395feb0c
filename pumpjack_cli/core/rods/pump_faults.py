"""Pump faults at the bottom boundary of the rod string: leaking valves and tagging.

The chamber of :mod:`.pump` (valves, fillage, gas, tubing stretch) with two more physical
fault models, so that the predictive model (:mod:`.predict`) can make the cards of a
failing pump and the diagnosis (:mod:`.diagnosis`) can be tested on cards it did not draw:

* **a leaking valve**: a worn or cut seat passes liquid from the high to the low pressure
  side whenever the valve is shut, as an orifice does, q = C_d a sqrt(2 dp / rho)
  ([White2011]), written with the leak Q at the full pressure difference
  dp_o = F_o / A_p (the rate a valve test measures):

      q(dp) = Q sqrt(dp / dp_o).

  The travelling valve (with the plunger) leaks from the tubing into the chamber while
  p_c < p_d, i.e. on the upstroke and during both load transfers; the standing valve
  leaks from the chamber back to the intake while p_c > p_i. With both valves shut the
  liquid-filled chamber is no longer held still: its volume follows the leaks,
  A dz/dt = q_tv - q_sv, and the plunger load F = (p_d - p_c) A_p is the one that makes
  the leaks match the plunger's speed. Hence on the upstroke of a leaking travelling valve
  the load is F_o (v / v_L)^2 while the plunger rises slower than v_L = Q / A_p (near
  the ends of the stroke): the load picks up late and falls off before the top; a
  leaking standing valve holds F = F_o (1 - (v / v_L)^2) on the downstroke while the
  plunger falls slower than v_L: the load is lost late at the top and picked up early
  near the bottom. That is how [EchometerLeakValve] and [McCoyRowlanPodio] describe the
  pump cards of leaking valves.
* **tagging**: the plunger meets a rigid stop, the bottom of the pump near the bottom
  of the downstroke (tagging down) or the top of the barrel near the top of the
  upstroke (tagging up). The stop holds the plunger at its position; the contact force
  N >= 0 (up at the bottom, down at the top) adds to the valves' load. The rod string's
  own elasticity and inertia make the spike (a rod end stopped at speed v carries a load
  step of its impedance E A / a times v, [Gibbs1963]).

Positions are the plunger's relative to the barrel (the chamber's ``position``, up
positive, the datum of :class:`~.predict.Prediction`'s ``plunger_position`` plus the
tubing stretch (F_o - F) / k_t of an unanchored tubing). Leaks are modelled with a pump
full of liquid (fillage 1, no gas): the leak of a partly filled barrel is not.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ...errors import PredictionError
from .pump import Pump, PumpChamber
from .string import RodString

#: Bisection steps of the closed-chamber balance when both valves leak.
_BISECTIONS = 60


def check_faults(pump: Pump) -> None:
    """Raise :class:`PredictionError` for fault data that make no pump."""
    for name, value in (("travelling valve leak", pump.travelling_valve_leak),
                        ("standing valve leak", pump.standing_valve_leak)):
        if not (math.isfinite(value) and value >= 0.0):
            raise PredictionError(f"{name} must be >= 0 and finite, got {value} m³/s")
    leaks = pump.travelling_valve_leak > 0.0 or pump.standing_valve_leak > 0.0
    if leaks and (pump.fillage < 1.0 or pump.gas_exponent is not None):
        raise PredictionError("valve leaks are modelled with a pump full of liquid (fillage 1, no gas)")
    if leaks and not pump.fluid_load > 0.0:
        raise PredictionError("a valve leaks under a pressure difference: the pump needs a fluid load")
    for name, stop in (("bottom stop", pump.bottom_stop), ("top stop", pump.top_stop)):
        if stop is not None and not math.isfinite(stop):
            raise PredictionError(f"{name} must be finite, got {stop} m")
    if pump.bottom_stop is not None and pump.top_stop is not None and not pump.bottom_stop < pump.top_stop:
        raise PredictionError(f"the bottom stop {pump.bottom_stop:.6g} m must lie below the top stop "
                              f"{pump.top_stop:.6g} m")


def pump_chamber(pump: Pump, compliance: float, position: float, step: float) -> PumpChamber:
    """The chamber to march: :class:`~.pump.PumpChamber` for a sound pump (the very same
    object as before the faults existed), :class:`FaultyChamber` for a faulty one.
    ``step`` [s] is the time step of the march (the leaks' volume per step)."""
    if not pump.faulty:
        return PumpChamber(pump, compliance, position)
    return FaultyChamber(pump, compliance, position, step)


class FaultyChamber(PumpChamber):
    """The valves and chamber of :class:`~.pump.PumpChamber` with leaking valves and stops
    (module docstring). ``step`` [s] is the time between samples."""

    def __init__(self, pump: Pump, compliance: float, position: float, step: float):
        super().__init__(pump, compliance, position)
        if not (math.isfinite(step) and step > 0.0):
            raise PredictionError(f"time step must be positive and finite, got {step} s")
        self.interval = step
        self.travelling_leak = pump.travelling_valve_leak
        self.standing_leak = pump.standing_valve_leak
        self.bottom_stop, self.top_stop = pump.bottom_stop, pump.top_stop

    # --- leaks -------------------------------------------------------------------------

    def _leaks(self, load: float) -> tuple[float, float]:
        """Leak rates [m^3/s] of the travelling valve (into the chamber) and of the standing
        valve (out of it) with both valves shut and the plunger load ``load`` [N]."""
        share = min(max(load / self.fluid_load, 0.0), 1.0)
        return self.travelling_leak * math.sqrt(share), self.standing_leak * math.sqrt(1.0 - share)

    def _closed_load(self, gap: float) -> float:
        """The load F in [0, F_o] at which the shut chamber's leaks move the plunger by
        ``gap - compliance F`` in one step: ``gap - c F = h (q_tv(F) - q_sv(F)) / A``, the
        left side falling and the right rising with F, so one root (closed forms for one
        leak, bisection for two)."""
        c, fo = self.compliance, self.fluid_load
        rate = self.interval / self.area
        if self.standing_leak == 0.0:      # c Fo s^2 + h Q_tv / A s - gap = 0, s = sqrt(F / Fo)
            a, b = c * fo, rate * self.travelling_leak
            s = 2.0 * gap / (b + math.sqrt(b * b + 4.0 * a * gap))
            return fo * s * s
        if self.travelling_leak == 0.0:    # c Fo t^2 + h Q_sv / A t + gap - c Fo = 0, t = sqrt(1 - F / Fo)
            a, b, e = c * fo, rate * self.standing_leak, gap - c * fo
            t = -2.0 * e / (b + math.sqrt(b * b - 4.0 * a * e))
            return fo * (1.0 - t * t)
        low, high = 0.0, fo
        for _ in range(_BISECTIONS):
            middle = 0.5 * (low + high)
            tv, sv = self._leaks(middle)
            if gap - c * middle - rate * (tv - sv) > 0.0:
                low = middle
            else:
                high = middle
        return 0.5 * (low + high)

    def _locked(self, known: float) -> tuple[float, float]:
        """Liquid-filled chamber between shut valves, with the leaks (module docstring); tight valves
        are the sound chamber's, to the last bit."""
        if self.travelling_leak == 0.0 and self.standing_leak == 0.0:
            return super()._locked(known)
        h, c, fo, area = self.interval, self.compliance, self.fluid_load, self.area
        gap = known - self.position
        if gap - c * fo - h * self.travelling_leak / area >= 0.0:      # the standing valve opens
            position = known - c * fo
            swept = area * (position - self.position)
            leak = self.travelling_leak * h
            self.volume += swept
            self.liquid = self.volume
            self.intake += swept - leak
            self.discharge -= leak
            return fo, position
        if gap + h * self.standing_leak / area <= 0.0:                 # the travelling valve opens
            leak = self.standing_leak * h
            self.volume += area * gap
            self.liquid = self.volume
            self.discharge += -area * gap - leak
            self.intake -= leak
            return 0.0, known
        load = min(max(self._closed_load(gap), 0.0), fo)
        tv, sv = self._leaks(load)
        position = self.position + h * (tv - sv) / area
        self.volume += area * (position - self.position)
        self.liquid = self.volume
        self.discharge -= h * tv
        self.intake -= h * sv
        return load, position

    # --- stops -------------------------------------------------------------------------

    def step(self, known: float) -> tuple[float, float]:
        """Pump load F [N] and plunger position [m] of the new sample, the stops holding the
        plunger: the valves act on the motion to the stop and the contact takes the rest."""
        if self.bottom_stop is None and self.top_stop is None:
            return super().step(known)
        saved = dict(vars(self))
        load, position = super().step(known)
        for stop, beyond in ((self.bottom_stop, position < (self.bottom_stop or 0.0)),
                             (self.top_stop, position > (self.top_stop or 0.0))):
            if stop is None or not beyond:
                continue
            valve = load
            for _ in range(2):          # the valves' load on the way to the stop (exact for open valves)
                vars(self).update(saved)
                valve, reached = super().step(stop + self.compliance * valve)
            self.position = stop
            return (known - stop) / self.compliance, stop
        return load, position


# --- a parted string and the stops of a tagging pump, for the predictive model -----------


#: The shortest piece of rod a break can leave hanging or below it [m]: 2 ft, the shortest pony
#: rod of [API11B] (a string parts at a rod, a pin or a coupling).
SHORTEST_ROD = 0.6096


def parted_string(rods: RodString, depth: float) -> RodString:
    """The rods left hanging from the polished rod when the string parts ``depth`` [m] down
    (measured along the rods): the sections above the break, the last one cut short.

    >>> rods = RodString(np.array([400.0, 600.0]), np.full(2, 3e-4), np.full(2, 2.1e11), np.full(2, 2.5))
    >>> parted_string(rods, 550.0).length.tolist()
    [400.0, 150.0]
    """
    if not (math.isfinite(depth) and SHORTEST_ROD <= depth <= rods.total_length - SHORTEST_ROD):
        raise PredictionError(f"the break must lie a rod's length ({SHORTEST_ROD:g} m, the shortest pony rod) or more "
                              f"below the polished rod and above the pump ({SHORTEST_ROD:g} .. "
                              f"{rods.total_length - SHORTEST_ROD:.6g} m along the rods), got {depth:.6g} m")
    ends = np.cumsum(rods.length)
    keep = int(np.searchsorted(ends, depth)) + 1
    length = rods.length[:keep].copy()
    length[-1] -= ends[keep - 1] - depth
    return RodString(length, rods.area[:keep], rods.youngs_modulus[:keep], rods.mass_per_length[:keep],
                     rods.material_density[:keep], rods.tensile_strength[:keep], rods.names[:keep])


def parted_damping(rods: RodString, hanging: RodString, damping: float) -> float:
    """Gibbs' nu of the rods left hanging that keeps the damping force per length of the whole
    string: c = pi a nu / (2 L) unchanged ([Gibbs1963]), so nu_h = nu (L_h / L) (a / a_h)."""
    return damping * hanging.total_length / rods.total_length * rods.mean_wave_speed / hanging.mean_wave_speed


def hanging_pump(pump: Pump) -> Pump:
    """Nothing on the free end of a parted string: no pressure difference, no valves' load."""
    return replace(pump, discharge_pressure=0.0, intake_pressure=0.0, fillage=1.0, gas_exponent=None,
                   travelling_valve_leak=0.0, standing_valve_leak=0.0, bottom_stop=None, top_stop=None)


def tag_stops(plunger_position: np.ndarray, pump_load: np.ndarray, pump: Pump, bottom: float | None,
              top: float | None) -> tuple[float | None, float | None]:
    """The stops of a pump that tags: ``bottom`` [m] above the lowest and ``top`` [m] below the
    highest position the plunger reaches relative to the barrel in the same well without them
    (``plunger_position`` [m] and ``pump_load`` [N] of that prediction; relative to the barrel
    the plunger is higher by the tubing's stretch (F_o - F) / k_t). None: no stop."""
    relative = np.asarray(plunger_position) + (pump.fluid_load - np.asarray(pump_load)) / pump.tubing_stiffness
    for name, value in (("bottom", bottom), ("top", top)):
        if value is not None and not (math.isfinite(value) and 0.0 < value < float(np.ptp(relative))):
            raise PredictionError(f"the {name} tag must be within the plunger's stroke {float(np.ptp(relative)):.4g} m, "
                                  f"got {value:.4g} m")
    return (None if bottom is None else float(relative.min()) + bottom,
            None if top is None else float(relative.max()) - top)
