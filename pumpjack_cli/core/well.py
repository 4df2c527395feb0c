"""Polished-rod load of a rod-pumped well: the resistance model of [SK8Rotation2013] (eqs. 19-23).

The rod string and the tubing are rigid ([SK8Rotation2013] makes the same assumption: the
plunger moves exactly as the polished rod), so the load depends only on the direction
of motion. With W' the weight of the rods in the fluid, P_f the fluid load on the
plunger and the friction forces F:

* upstroke (travelling valve closed, standing valve open), [SK8Rotation2013] eq. 19:
  P_up = W' + P_f + F_plunger + F_tubing, with F_tubing the hydraulic loss of the
  produced fluid flowing up the tubing;
* downstroke (travelling valve open, standing valve closed), [SK8Rotation2013] eqs. 22-23:
  P_down = W' - F_plunger - F_rods: the rod weight in the fluid drives, friction
  opposes the motion, F_rods the viscous drag of the rods moving down the tubing.

[SK8Rotation2013] cites the force formulas from textbooks without printing them (its refs.
5-7: [Boyko2012], [Virnovsky1971], [Molchanov1984]). We use: Archimedes for W'; the
hydrostatic pressure difference across the plunger for P_f; Serdyuk's empirical
plunger friction (quoted in [Mishchenko2003]); Darcy-Weisbach with the Hagen-Poiseuille
and Blasius friction factors for the fluid ([Idelchik2006]); and the laminar drag of a
rod displacing its own volume up a closed annulus, derived in ``docs/dynamics.md``.
Friction forces that depend on speed are evaluated at the mean polished-rod speed of
their stroke ([SK8Rotation2013]: "v_cp, mean velocity"), so each load is
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
    """Mass of a tapered rod string, rho_r sum(pi d_i^2 / 4 L_i), couplings neglected.

    Parameters
    ----------
    diameters, lengths : numpy.ndarray
        Diameter d_i and length L_i of each section [m].
    density : float
        rho_r of the rod material [kg/m³].

    Returns
    -------
    float
        Mass [kg].

    Examples
    --------
    >>> round(rod_string_mass([0.019], [1000.0], 7850.0), 1)   # 19 mm steel rod: 2.23 kg/m
    2225.7
    """
    return float(density * np.sum(_area(diameters) * np.asarray(lengths, dtype=float)))


def buoyant_weight(mass: float, material_density: float, fluid_density: float,
                   gravity: float = STANDARD_GRAVITY) -> float:
    """Weight of a body immersed in a fluid, W' = m g (1 - rho_f / rho_m) (Archimedes).

    Parameters
    ----------
    mass : float
        m [kg].
    material_density, fluid_density : float
        rho_m and rho_f [kg/m³].
    gravity : float
        g [m/s²] ([BIPM2019]).

    Returns
    -------
    float
        W' [N].

    References
    ----------
    [SK8Rotation2013] eq. 19 (rods in fluid); [Molchanov1984].

    Examples
    --------
    1000 kg of steel in the 820 kg/m³ oil of [SK8Rotation2013]: 9810 x (1 - 820/7850):

    >>> round(buoyant_weight(1000.0, 7850.0, 820.0, 9.81), 2)
    8785.26
    """
    return mass * gravity * (1.0 - fluid_density / material_density)


def fluid_load(plunger_diameter: float, lift: float, fluid_density: float,
               gravity: float = STANDARD_GRAVITY) -> float:
    """Fluid load on the plunger on the upstroke, P_f = rho g L pi D^2 / 4.

    The pressure above the plunger is that of the fluid column up to the surface, below
    it that of the submergence h under the dynamic level; their difference acts on the
    whole plunger area when the rods are counted with their weight in the fluid (the
    rods' buoyancy is that of a body with its lower end at the pressure above the
    plunger). Wellhead and casing pressures are neglected.

    Parameters
    ----------
    plunger_diameter : float
        D [m].
    lift : float
        L = H - h, depth of the dynamic level [m].
    fluid_density : float
        rho [kg/m³].
    gravity : float
        g [m/s²] ([BIPM2019]).

    Returns
    -------
    float
        P_f [N].

    References
    ----------
    Standard static-load formula of the Soviet textbooks ([Molchanov1984];
    [Mishchenko2003]); [SK8Rotation2013] eq. 20 (G_r, with d_n and h).

    Examples
    --------
    The 38 mm plunger and 1530 m well of [SK8Rotation2013] with the level at the pump:
    820 x 9.81 x 1530 x pi 0.038² / 4 = 13 958 N.

    >>> round(fluid_load(0.038, 1530.0, 820.0, 9.81), 1)
    13958.3
    """
    return fluid_density * gravity * lift * float(_area(plunger_diameter))


def plunger_friction(plunger_diameter: float, clearance: float) -> float:
    """Friction of a metal plunger in its barrel, F = 1.84 D / delta - 137.

    Serdyuk's empirical formula, quoted in [Mishchenko2003]; D and delta in the same
    unit, F in N. The formula is only meaningful where it is positive,
    delta < 1.84 D / 137.

    Parameters
    ----------
    plunger_diameter : float
        D [m].
    clearance : float
        delta, between plunger and barrel [m].

    Returns
    -------
    float
        F [N].

    Raises
    ------
    DynamicsError
        The formula gives no positive force (clearance too large).

    References
    ----------
    [Mishchenko2003] (Serdyuk's formula).

    Examples
    --------
    1.84 x 38 / 0.1 - 137 = 562.2 N:

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
    """Darcy friction factor of a smooth pipe.

        lambda = 64 / Re (laminar, Hagen-Poiseuille) for Re < 2300,
        lambda = 0.3164 Re^(-1/4) (Blasius) above.

    Blasius is fitted for 4e3 < Re < 1e5.

    Parameters
    ----------
    reynolds : float or numpy.ndarray
        Re (dimensionless).

    Returns
    -------
    numpy.ndarray
        lambda (dimensionless).

    References
    ----------
    [Idelchik2006], p. 77, as quoted in [ModelicaFluid] (``dp_turbulent``).

    Examples
    --------
    >>> [round(float(x), 5) for x in darcy_friction_factor([1000.0, 1e4])]
    [0.064, 0.03164]
    """
    re = np.asarray(reynolds, dtype=float)
    with np.errstate(divide="ignore"):
        return np.where(re < LAMINAR_LIMIT, 64.0 / re, 0.3164 * re**-0.25)


def tubing_friction(plunger_diameter: float, rod_diameters: np.ndarray, lengths: np.ndarray,
                    tubing_diameter: float, fluid_density: float, kinematic_viscosity: float,
                    rod_speed: float) -> float:
    """Hydraulic loss of the produced fluid in the tubing on the upstroke, as a polished-rod force.

    Continuity with rigid rods: while the plunger rises at v, the fluid crossing a
    tubing section above it is the plunger's displacement less the rod volume leaving
    the section, so in rod section i the fluid moves at
    v_i = v (A_p - A_ri) / (A_t - A_ri). Darcy-Weisbach in each annular section with
    the hydraulic diameter d_t - d_ri (rod wall taken as still):

        dp_i = lambda_i (L_i / (d_t - d_ri)) rho v_i^2 / 2,

    and the force on the polished rod whose power equals the dissipated power is
    F = sum dp_i (A_p - A_ri).

    Parameters
    ----------
    plunger_diameter : float
        D [m].
    rod_diameters, lengths : numpy.ndarray
        d_ri and L_i of the rod sections [m].
    tubing_diameter : float
        d_t, inner [m].
    fluid_density : float
        rho [kg/m³].
    kinematic_viscosity : float
        nu [m²/s].
    rod_speed : float
        v, mean polished-rod speed of the upstroke [m/s].

    Returns
    -------
    float
        F [N].

    References
    ----------
    [SK8Rotation2013] eq. 20 (lambda, l, v_cp, d_t); friction factor
    :func:`darcy_friction_factor` ([Idelchik2006]).

    Examples
    --------
    Without rods and with the plunger filling the tubing the flow is Hagen-Poiseuille
    pipe flow, F = 8 pi mu L v: 1000 m of 62 mm tubing, oil of 820 kg/m³ and
    1e-4 m²/s (Re = 62) at 0.1 m/s give 8 pi x 0.082 x 1000 x 0.1 = 206.09 N.

    >>> round(tubing_friction(0.062, [0.0], [1000.0], 0.062, 820.0, 1e-4, 0.1), 2)
    206.09
    """
    d_r = np.asarray(rod_diameters, dtype=float)
    a_p, a_r, a_t = float(_area(plunger_diameter)), _area(d_r), float(_area(tubing_diameter))
    velocity = rod_speed * (a_p - a_r) / (a_t - a_r)
    gap = tubing_diameter - d_r
    reynolds = np.abs(velocity) * gap / kinematic_viscosity
    loss = darcy_friction_factor(np.maximum(reynolds, 1e-300)) * np.asarray(lengths) / gap * fluid_density * velocity**2 / 2
    return float(np.sum(loss * (a_p - a_r)))


def annulus_drag_factor(diameter_ratio: np.ndarray | float) -> np.ndarray:
    """Drag factor of a rod in a closed tube, K(m) = (m^2 - 1) / ((m^2 + 1) ln m - (m^2 - 1)).

    Laminar drag per unit length of a rod moving at v along the axis of a tube, when
    the rod displaces its own volume through the annulus (closed lower end), is
    2 pi mu v K(m); derived in ``docs/dynamics.md`` (Couette-Poiseuille flow; checked
    numerically by ``tests/core/test_well.py``).

    Parameters
    ----------
    diameter_ratio : float or numpy.ndarray
        m = d_t / d_r > 1 (dimensionless).

    Returns
    -------
    numpy.ndarray
        K (dimensionless).

    Examples
    --------
    The 62 mm tubing and 19 mm rods of [SK8Rotation2013]:

    >>> round(float(annulus_drag_factor(62 / 19)), 4)
    2.3372
    """
    m2 = np.asarray(diameter_ratio, dtype=float) ** 2
    return (m2 - 1.0) / ((m2 + 1.0) * 0.5 * np.log(m2) - (m2 - 1.0))


def rod_friction(rod_diameters: np.ndarray, lengths: np.ndarray, tubing_diameter: float,
                 dynamic_viscosity: float, rod_speed: float) -> float:
    """Viscous drag of the rod string moving down the tubing, F = 2 pi mu v sum L_i K(d_t / d_ri).

    On the downstroke the standing valve is closed, so the rods entering the tubing
    push their own volume up the annulus: the laminar drag of :func:`annulus_drag_factor`.

    Parameters
    ----------
    rod_diameters, lengths : numpy.ndarray
        d_ri and L_i of the rod sections [m].
    tubing_diameter : float
        d_t, inner [m].
    dynamic_viscosity : float
        mu [Pa·s].
    rod_speed : float
        v, mean polished-rod speed of the downstroke [m/s].

    Returns
    -------
    float
        F [N].

    References
    ----------
    [SK8Rotation2013] eqs. 22-23 (rod friction on the downstroke; formula derived here).

    Examples
    --------
    2 pi x 0.001 x 1 x 1000 x K(62/19) = 2 pi x 2.3372 = 14.69 N:

    >>> round(rod_friction([0.019], [1000.0], 0.062, 0.001, 1.0), 2)
    14.69
    """
    ratio = tubing_diameter / np.asarray(rod_diameters, dtype=float)
    return float(2.0 * np.pi * dynamic_viscosity * rod_speed * np.sum(np.asarray(lengths) * annulus_drag_factor(ratio)))


def fluid_kinetic_mass(plunger_diameter: float, rod_diameters: np.ndarray, lengths: np.ndarray,
                       tubing_diameter: float, fluid_density: float) -> float:
    """Mass which, moving with the polished rod, has the kinetic energy of the tubing fluid on the upstroke.

    With v_i = v (A_p - A_ri)/(A_t - A_ri) (see :func:`tubing_friction`),
    sum rho L_i (A_t - A_ri) v_i^2 / 2 = m v^2 / 2 gives

        m = rho sum L_i (A_p - A_ri)^2 / (A_t - A_ri).

    ([SK8Rotation2013] eq. 9 takes "the mass of the fluid the plunger lifts"; this is
    that fluid's kinetic-energy equivalent.)

    Parameters
    ----------
    plunger_diameter : float
        D [m].
    rod_diameters, lengths : numpy.ndarray
        d_ri and L_i of the rod sections [m].
    tubing_diameter : float
        d_t, inner [m].
    fluid_density : float
        rho [kg/m³].

    Returns
    -------
    float
        m [kg].

    References
    ----------
    [SK8Rotation2013] eq. 9.

    Examples
    --------
    Without rods and with the plunger filling the tubing the whole column moves at v:
    m = rho L pi d_t^2 / 4 = 820 x 1000 x pi 0.062² / 4 = 2475.6 kg.

    >>> round(fluid_kinetic_mass(0.062, [0.0], [1000.0], 0.062, 820.0), 1)
    2475.6
    """
    a_p, a_r, a_t = float(_area(plunger_diameter)), _area(rod_diameters), float(_area(tubing_diameter))
    return float(fluid_density * np.sum(np.asarray(lengths) * (a_p - a_r) ** 2 / (a_t - a_r)))


@dataclass(frozen=True)
class WellLoad:
    """Polished-rod forces of the well model and the masses moving with the polished rod.

    Friction forces are magnitudes; see the module docstring for the stroke loads.

    Attributes
    ----------
    rod_weight : float
        W', rods in the fluid [N].
    fluid_load : float
        P_f [N].
    plunger_friction, tubing_friction, rod_friction : float
        Friction forces [N].
    rod_mass, fluid_mass : float
        Rods, and the tubing fluid's kinetic-energy equivalent [kg].

    References
    ----------
    [SK8Rotation2013] eqs. 9, 19-23.

    Examples
    --------
    >>> w = WellLoad(10.0, 5.0, 1.0, 0.5, 0.25, 100.0, 20.0)
    >>> w.upstroke, w.downstroke, w.mass_upstroke, w.mass_downstroke   # 10+5+1+0.5, 10-1-0.25
    (16.5, 8.75, 120.0, 100.0)
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
        """Upstroke load P_up = W' + P_f + F_plunger + F_tubing [N] ([SK8Rotation2013] eq. 19)."""
        return self.rod_weight + self.fluid_load + self.plunger_friction + self.tubing_friction

    @property
    def downstroke(self) -> float:
        """Downstroke load P_down = W' - F_plunger - F_rods [N] ([SK8Rotation2013] eqs. 22-23)."""
        return self.rod_weight - self.plunger_friction - self.rod_friction

    @property
    def mass_upstroke(self) -> float:
        """Mass moving with the polished rod on the upstroke, rods and fluid [kg] ([SK8Rotation2013] eq. 9)."""
        return self.rod_mass + self.fluid_mass

    @property
    def mass_downstroke(self) -> float:
        """Mass moving with the polished rod on the downstroke, the rods only [kg] ([SK8Rotation2013] eq. 9)."""
        return self.rod_mass

    def force(self, crank_angle: np.ndarray, upstroke: np.ndarray) -> np.ndarray:
        """Polished-rod load at the given crank angles, by stroke direction.

        Parameters
        ----------
        crank_angle : numpy.ndarray
            theta [rad] (the load depends only on the stroke).
        upstroke : numpy.ndarray
            Boolean mask of the upstroke.

        Returns
        -------
        numpy.ndarray
            P_up or P_down [N].
        """
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
    """The well model of [SK8Rotation2013] for one well.

    Parameters
    ----------
    pump_depth : float
        H [m] (= rod string length).
    submergence : float
        h, of the pump under the dynamic level [m], 0 <= h < H.
    plunger_diameter, plunger_clearance : float
        D and delta [m].
    rod_diameters : numpy.ndarray
        Rod sections, top down [m].
    rod_fractions : numpy.ndarray
        Their shares of the string length (dimensionless).
    rod_density, fluid_density : float
        [kg/m³].
    kinematic_viscosity : float
        nu [m²/s].
    tubing_diameter : float
        d_t, inner [m].
    upstroke_speed, downstroke_speed : float
        Mean polished-rod speeds of the two strokes [m/s].
    gravity : float
        g [m/s²] ([BIPM2019]).

    Returns
    -------
    WellLoad
        Forces [N] and masses [kg].

    Raises
    ------
    DynamicsError
        Tubing that does not clear the rods, a plunger not larger than the rods, a
        submergence outside [0, H), or a plunger clearance too large for the friction
        formula.

    References
    ----------
    [SK8Rotation2013] eqs. 9, 19-23; [Mishchenko2003]; [Idelchik2006].
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
