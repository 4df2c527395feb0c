"""Polished-rod load of a rod-pumped well: the resistance model of seed 004 (eqs. 19-23).

The rod string and the tubing are rigid (seed 004 makes the same assumption: the
plunger moves exactly as the polished rod), so the load depends only on the direction
of motion. With W' the weight of the rods in the fluid, P_f the fluid load on the
plunger and the friction forces F:

* upstroke (travelling valve closed, standing valve open), seed 004 eq. 19:
  P_up = W' + P_f + F_plunger + F_tubing, with F_tubing the hydraulic loss of the
  produced fluid flowing up the tubing;
* downstroke (travelling valve open, standing valve closed), seed 004 eqs. 22-23:
  P_down = W' - F_plunger - F_rods: the rod weight in the fluid drives, friction
  opposes the motion, F_rods the viscous drag of the rods moving down the tubing.

Seed 004 cites the force formulas from textbooks without printing them (its refs.
[5-7]: Boyko 2012, Virnovsky 1971, Molchanov 1984). We use: Archimedes for W'; the
hydrostatic pressure difference across the plunger for P_f; Serdyuk's empirical
plunger friction (quoted in Mishchenko, Skvazhinnaya dobycha nefti, 2003); Darcy-Weisbach
with the Hagen-Poiseuille and Blasius friction factors for the fluid; and the laminar
drag of a rod displacing its own volume up a closed annulus, derived in
``docs/dynamics.md``. Friction forces that depend on speed are evaluated at the mean
polished-rod speed of their stroke (seed 004: "v_cp, mean velocity"), so each load is
constant over its stroke and the work per cycle is exact: stroke x (P_up - P_down).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import DynamicsError
from .constants import STANDARD_GRAVITY

#: Critical Reynolds number of pipe flow: laminar below, turbulent (Blasius) above.
LAMINAR_LIMIT = 2300.0


def _area(diameter):
    return np.pi * np.asarray(diameter, dtype=float) ** 2 / 4.0


def rod_string_mass(diameters: np.ndarray, lengths: np.ndarray, density: float) -> float:
    """Mass of a tapered rod string [kg]: rho_r sum(pi d_i^2 / 4 L_i), couplings neglected.

    diameters [m], lengths [m] of the sections; density [kg/m^3] of the rod material.

    >>> round(rod_string_mass([0.019], [1000.0], 7850.0), 1)   # 19 mm steel rod: 2.23 kg/m
    2225.7
    """
    return float(density * np.sum(_area(diameters) * np.asarray(lengths, dtype=float)))


def buoyant_weight(mass: float, material_density: float, fluid_density: float,
                   gravity: float = STANDARD_GRAVITY) -> float:
    """Weight of a body immersed in a fluid [N], W' = m g (1 - rho_f / rho_m) (Archimedes).

    mass [kg]; densities [kg/m^3].

    >>> round(buoyant_weight(1000.0, 7850.0, 820.0, 9.81), 2)
    8785.26
    """
    return mass * gravity * (1.0 - fluid_density / material_density)


def fluid_load(plunger_diameter: float, lift: float, fluid_density: float,
               gravity: float = STANDARD_GRAVITY) -> float:
    """Fluid load on the plunger on the upstroke [N], P_f = rho g L pi D^2 / 4.

    The pressure above the plunger is that of the fluid column up to the surface, below
    it that of the submergence h under the dynamic level; their difference acts on the
    whole plunger area when the rods are counted with their weight in the fluid (the
    rods' buoyancy is that of a body with its lower end at the pressure above the
    plunger). lift L = H - h [m] is the depth of the dynamic level (wellhead and casing
    pressures neglected); plunger_diameter D [m]. Standard static-load formula of the
    Soviet textbooks (Molchanov 1984; Mishchenko 2003), seed 004 eq. 20 (G_r, with d_n
    and h).

    >>> round(fluid_load(0.038, 1530.0, 820.0, 9.81), 1)
    13958.3
    """
    return fluid_density * gravity * lift * float(_area(plunger_diameter))


def plunger_friction(plunger_diameter: float, clearance: float) -> float:
    """Friction of a metal plunger in its barrel [N], F = 1.84 D / delta - 137.

    Serdyuk's empirical formula, quoted in Mishchenko, Skvazhinnaya dobycha nefti (2003);
    D plunger diameter and delta the clearance between plunger and barrel in the same
    unit (here both in m). The formula is only meaningful where it is positive,
    delta < 1.84 D / 137.

    >>> round(plunger_friction(0.038, 0.0001), 1)
    562.2
    """
    force = 1.84 * plunger_diameter / clearance - 137.0
    if not force > 0:
        raise DynamicsError(
            f"plunger clearance {clearance * 1e3:.4g} mm is too large for the plunger friction formula "
            f"1.84 D/delta - 137 N with D = {plunger_diameter * 1e3:.4g} mm (needs delta < "
            f"{1.84 * plunger_diameter / 137 * 1e3:.3g} mm)"
        )
    return force


def darcy_friction_factor(reynolds: np.ndarray | float) -> np.ndarray:
    """Darcy friction factor of a smooth pipe: 64/Re (laminar, Hagen-Poiseuille) below
    Re = 2300, Blasius 0.3164 Re^-1/4 above (Idelchik, Handbook of Hydraulic Resistance,
    2006, p. 77, as quoted in the Modelica Standard Library, Fluid.Dissipation
    dp_turbulent; Blasius is fitted for 4e3 < Re < 1e5).

    >>> [round(float(x), 5) for x in darcy_friction_factor([1000.0, 1e4])]
    [0.064, 0.03164]
    """
    re = np.asarray(reynolds, dtype=float)
    with np.errstate(divide="ignore"):
        return np.where(re < LAMINAR_LIMIT, 64.0 / re, 0.3164 * re**-0.25)


def tubing_friction(plunger_diameter: float, rod_diameters: np.ndarray, lengths: np.ndarray,
                    tubing_diameter: float, fluid_density: float, kinematic_viscosity: float,
                    rod_speed: float) -> float:
    """Hydraulic loss of the produced fluid in the tubing on the upstroke, as a polished-rod force [N].

    Continuity with rigid rods: while the plunger rises at v, the fluid crossing a
    tubing section above it is the plunger's displacement less the rod volume leaving
    the section, so in rod section i the fluid moves at
    v_i = v (A_p - A_ri) / (A_t - A_ri). Darcy-Weisbach in each annular section with
    the hydraulic diameter d_t - d_ri (rod wall taken as still):
    dp_i = lambda_i (L_i / (d_t - d_ri)) rho v_i^2 / 2; the force on the polished rod
    whose power equals the dissipated power is F = sum dp_i (A_p - A_ri). v [m/s] is
    the mean polished-rod speed of the upstroke (seed 004 eq. 20: lambda, l, v_cp, d_t).
    """
    d_r = np.asarray(rod_diameters, dtype=float)
    a_p, a_r, a_t = float(_area(plunger_diameter)), _area(d_r), float(_area(tubing_diameter))
    velocity = rod_speed * (a_p - a_r) / (a_t - a_r)
    gap = tubing_diameter - d_r
    reynolds = np.abs(velocity) * gap / kinematic_viscosity
    loss = darcy_friction_factor(np.maximum(reynolds, 1e-300)) * np.asarray(lengths) / gap * fluid_density * velocity**2 / 2
    return float(np.sum(loss * (a_p - a_r)))


def annulus_drag_factor(diameter_ratio: np.ndarray | float) -> np.ndarray:
    """K(m) = (m^2 - 1) / ((m^2 + 1) ln m - (m^2 - 1)), m = d_t / d_r.

    Laminar drag per unit length of a rod moving at v along the axis of a tube, when
    the rod displaces its own volume through the annulus (closed lower end), is
    2 pi mu v K(m); derived in ``docs/dynamics.md`` (Couette-Poiseuille flow).

    >>> round(float(annulus_drag_factor(62 / 19)), 4)
    2.3372
    """
    m2 = np.asarray(diameter_ratio, dtype=float) ** 2
    return (m2 - 1.0) / ((m2 + 1.0) * 0.5 * np.log(m2) - (m2 - 1.0))


def rod_friction(rod_diameters: np.ndarray, lengths: np.ndarray, tubing_diameter: float,
                 dynamic_viscosity: float, rod_speed: float) -> float:
    """Viscous drag of the rod string moving down the tubing [N], F = 2 pi mu v sum L_i K(d_t / d_ri).

    On the downstroke the standing valve is closed, so the rods entering the tubing
    push their own volume up the annulus: the laminar drag of :func:`annulus_drag_factor`.
    mu [Pa s]; v [m/s] the mean polished-rod speed of the downstroke.

    >>> round(rod_friction([0.019], [1000.0], 0.062, 0.001, 1.0), 2)
    14.69
    """
    ratio = tubing_diameter / np.asarray(rod_diameters, dtype=float)
    return float(2.0 * np.pi * dynamic_viscosity * rod_speed * np.sum(np.asarray(lengths) * annulus_drag_factor(ratio)))


def fluid_kinetic_mass(plunger_diameter: float, rod_diameters: np.ndarray, lengths: np.ndarray,
                       tubing_diameter: float, fluid_density: float) -> float:
    """Mass [kg] which, moving with the polished rod, has the kinetic energy of the tubing fluid on the upstroke.

    With v_i = v (A_p - A_ri)/(A_t - A_ri) (see :func:`tubing_friction`),
    sum rho L_i (A_t - A_ri) v_i^2 / 2 = m v^2 / 2 gives
    m = rho sum L_i (A_p - A_ri)^2 / (A_t - A_ri). (Seed 004 eq. 9 takes "the mass of the
    fluid the plunger lifts"; this is that fluid's kinetic-energy equivalent.)
    """
    a_p, a_r, a_t = float(_area(plunger_diameter)), _area(rod_diameters), float(_area(tubing_diameter))
    return float(fluid_density * np.sum(np.asarray(lengths) * (a_p - a_r) ** 2 / (a_t - a_r)))


@dataclass(frozen=True)
class WellLoad:
    """Polished-rod forces [N] of the well model and the masses [kg] moving with the polished rod.

    Friction forces are magnitudes; see the module docstring for the stroke loads.
    """

    rod_weight: float
    fluid_load: float
    plunger_friction: float
    tubing_friction: float
    rod_friction: float
    rod_mass: float
    fluid_mass: float

    @property
    def upstroke(self) -> float:
        """P_up = W' + P_f + F_plunger + F_tubing [N] (seed 004 eq. 19)."""
        return self.rod_weight + self.fluid_load + self.plunger_friction + self.tubing_friction

    @property
    def downstroke(self) -> float:
        """P_down = W' - F_plunger - F_rods [N] (seed 004 eqs. 22-23)."""
        return self.rod_weight - self.plunger_friction - self.rod_friction

    @property
    def mass_upstroke(self) -> float:
        """Rods and fluid [kg]: the fluid moves only on the upstroke (seed 004 eq. 9)."""
        return self.rod_mass + self.fluid_mass

    @property
    def mass_downstroke(self) -> float:
        return self.rod_mass

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
        """Polished-rod load [N] at the given crank angles, by stroke direction."""
        return np.where(np.asarray(upstroke), self.upstroke, self.downstroke)


def well_load(
    *,
    pump_depth: float,
    submergence: float,
    plunger_diameter: float,
    plunger_clearance: float,
    rod_diameters: np.ndarray,
    rod_fractions: np.ndarray,
    rod_density: float,
    fluid_density: float,
    kinematic_viscosity: float,
    tubing_diameter: float,
    upstroke_speed: float,
    downstroke_speed: float,
    gravity: float = STANDARD_GRAVITY,
) -> WellLoad:
    """The well model of seed 004 for one well, SI.

    pump_depth H [m] (= rod string length); submergence h [m] of the pump under the
    dynamic level; plunger_diameter D and plunger_clearance delta [m]; rod sections by
    diameter [m] and share of the length; densities [kg/m^3]; kinematic_viscosity
    [m^2/s]; tubing_diameter d_t [m] (inner); upstroke/downstroke_speed [m/s], the mean
    polished-rod speeds of the two strokes.
    """
    d_r = np.asarray(rod_diameters, dtype=float)
    lengths = pump_depth * np.asarray(rod_fractions, dtype=float)
    if not tubing_diameter > d_r.max():
        raise DynamicsError(f"tubing inner diameter {tubing_diameter * 1e3:.4g} mm does not clear the "
                            f"{d_r.max() * 1e3:.4g} mm rods")
    if not plunger_diameter > d_r.max():
        raise DynamicsError(f"plunger diameter {plunger_diameter * 1e3:.4g} mm must exceed the rod diameters "
                            f"(largest {d_r.max() * 1e3:.4g} mm)")
    if not 0 <= submergence < pump_depth:
        raise DynamicsError(f"submergence {submergence:.4g} m must lie between 0 and the pump depth {pump_depth:.4g} m")
    mass = rod_string_mass(d_r, lengths, rod_density)
    return WellLoad(
        rod_weight=buoyant_weight(mass, rod_density, fluid_density, gravity),
        fluid_load=fluid_load(plunger_diameter, pump_depth - submergence, fluid_density, gravity),
        plunger_friction=plunger_friction(plunger_diameter, plunger_clearance),
        tubing_friction=tubing_friction(plunger_diameter, d_r, lengths, tubing_diameter, fluid_density,
                                        kinematic_viscosity, upstroke_speed),
        rod_friction=rod_friction(d_r, lengths, tubing_diameter, fluid_density * kinematic_viscosity, downstroke_speed),
        rod_mass=mass,
        fluid_mass=fluid_kinetic_mass(plunger_diameter, d_r, lengths, tubing_diameter, fluid_density),
    )
