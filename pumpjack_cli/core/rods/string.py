"""A tapered sucker-rod string as arrays of sections, SI.

The string hangs from the polished rod (x = 0) down to the pump (x = L); section i
has length L_i, metal area A_i, Young's modulus E_i and a mass per unit length m_i
that includes the couplings (so the stress wave speed is a_i = sqrt(E_i A_i / m_i),
not sqrt(E/rho) of bare steel).

Gravity and buoyancy enter only through the static tension. Each section is a solid
of density rho_s,i (steel unless told otherwise) whose volume is m_i / rho_s,i, so its
weight in a fluid of density rho_f is the buoyant weight per length

    q_i = g m_i (1 - rho_f / rho_s,i)                                   [API11L]

(RP 11L writes the same as Wrf = Wr (1 - 0.128 G) for steel). The static tension
T_s(x) is the buoyant weight of the rods below x; the wave equation carries the rest.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...errors import DownholeError
from ..constants import STANDARD_GRAVITY, STEEL_DENSITY

#: Young's modulus of carbon steel [Pa], 207 GPa (30.0 Mpsi) [Shigley2011] (Table A-5).
#: With STEEL_DENSITY it gives sqrt(E/rho) = 5 135 m/s = 16 850 ft/s, the "about
#: 17 000 ft/s" theoretical value of [API11L] (A10).
STEEL_YOUNGS_MODULUS = 207e9


def _sections(name: str, values, count: int | None = None) -> np.ndarray:
    array = np.atleast_1d(np.asarray(values, dtype=float))
    if array.ndim != 1 or array.size == 0:
        raise DownholeError(f"rod string {name} must be one value per section, got shape {array.shape}")
    if count is not None and array.size != count:
        raise DownholeError(f"rod string {name} has {array.size} values for {count} sections")
    return array


@dataclass(frozen=True)
class RodString:
    """A tapered rod string: sections from the top down, one array value per section.

    Parameters
    ----------
    length : numpy.ndarray
        L_i [m].
    area : numpy.ndarray
        A_i [m²], metal cross-section of the rod body.
    youngs_modulus : numpy.ndarray
        E_i [Pa].
    mass_per_length : numpy.ndarray
        m_i [kg/m], rod with its couplings.
    material_density : numpy.ndarray, optional
        rho_s,i [kg/m^3] of the solid that displaces the fluid; default steel,
        :data:`STEEL_DENSITY`.
    tensile_strength : numpy.ndarray, optional
        Minimum tensile strength T_i [Pa] of the rod grade (for the Goodman loading);
        NaN where unknown, the default.
    names : tuple of str, optional
        A label per section (e.g. ``"7/8 in D"``), for reports.

    Raises
    ------
    DownholeError
        If an array is not one finite value per section, or a length, area, modulus,
        mass or density is not positive.

    Examples
    --------
    1000 m of bare 19 mm steel rod (E = 206 GPa, 7850 kg/m³): the wave speed is
    sqrt(E/rho) = 5122.7 m/s, the mass 7850 pi 0.019² / 4 x 1000 = 2225.7 kg.

    >>> area = np.pi * 0.019**2 / 4
    >>> rods = RodString(np.array([1000.0]), np.array([area]), np.array([2.06e11]), np.array([7850 * area]))
    >>> round(float(rods.wave_speed[0]), 1), round(rods.mass, 1), rods.total_length
    (5122.7, 2225.7, 1000.0)
    """

    length: np.ndarray
    area: np.ndarray
    youngs_modulus: np.ndarray
    mass_per_length: np.ndarray
    material_density: np.ndarray = field(default_factory=lambda: np.array(STEEL_DENSITY))
    tensile_strength: np.ndarray = field(default_factory=lambda: np.array(np.nan))
    names: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        length = _sections("length", self.length)
        count = length.size
        fields = {"length": length}
        for name in ("area", "youngs_modulus", "mass_per_length"):
            fields[name] = _sections(name, getattr(self, name), count)
        for name in ("material_density", "tensile_strength"):
            fields[name] = _sections(name, np.broadcast_to(getattr(self, name), count), count)
        for name, array in fields.items():
            if name == "tensile_strength":
                bad = ~(np.isnan(array) | (np.isfinite(array) & (array > 0)))
            else:
                bad = ~(np.isfinite(array) & (array > 0))
            if bad.any():
                index = int(np.flatnonzero(bad)[0])
                raise DownholeError(f"rod string {name} of section {index + 1} must be finite and positive, "
                                    f"got {array[index]:g}")
            object.__setattr__(self, name, array)
        if self.names and len(self.names) != count:
            raise DownholeError(f"rod string has {len(self.names)} names for {count} sections")
        object.__setattr__(self, "names", tuple(str(name) for name in self.names))

    @property
    def total_length(self) -> float:
        """Length of the string, L = sum L_i [m], polished rod to pump."""
        return float(np.sum(self.length))

    @property
    def wave_speed(self) -> np.ndarray:
        """Speed of the stress wave in each section, a_i = sqrt(E_i A_i / m_i) [m/s]."""
        return np.sqrt(self.youngs_modulus * self.area / self.mass_per_length)

    @property
    def mass(self) -> float:
        """Mass of the string with couplings, sum m_i L_i [kg]."""
        return float(np.sum(self.mass_per_length * self.length))

    def weight_in_air(self, gravity: float = STANDARD_GRAVITY) -> float:
        """Weight of the string in air, W_r = g sum m_i L_i.

        Parameters
        ----------
        gravity : float
            g [m/s²], standard gravity by default ([BIPM2019]).

        Returns
        -------
        float
            W_r [N].

        Examples
        --------
        >>> area = np.pi * 0.019**2 / 4
        >>> rods = RodString(np.array([1000.0]), np.array([area]), np.array([2.06e11]), np.array([7850 * area]))
        >>> round(rods.weight_in_air(), 1)   # 2225.70 kg x 9.80665 m/s^2
        21826.7
        """
        return gravity * self.mass

    @property
    def depth(self) -> np.ndarray:
        """x of the section ends [m], S + 1 values from 0 (polished rod) to L (pump)."""
        return np.concatenate(([0.0], np.cumsum(self.length)))

    @property
    def travel_time(self) -> float:
        """One-way travel time of a stress wave, polished rod to pump, sum L_i / a_i [s]."""
        return float(np.sum(self.length / self.wave_speed))

    @property
    def mean_wave_speed(self) -> float:
        """Travel-time average wave speed a = L / sum(L_i / a_i) [m/s].

        The uniform rod of this speed and the same length has the same travel time, so
        the same quarter-wave natural frequency pi a / (2 L) as the tapered string.
        """
        return self.total_length / self.travel_time

    @property
    def spring_constant(self) -> float:
        """k_r = 1 / sum(L_i / (E_i A_i)) [N/m], the string as one spring [API11L].

        RP 11L writes 1/k_r = sum(E_r,i L_i) with its elastic constants E_r = 1/(E A).

        References
        ----------
        [API11L] (A11).
        """
        return float(1.0 / np.sum(self.length / (self.youngs_modulus * self.area)))

    def buoyant_weight_per_length(self, fluid_density: float, gravity: float = STANDARD_GRAVITY) -> np.ndarray:
        """q_i = g m_i (1 - rho_f / rho_s,i) [N/m] per section [API11L].

        Parameters
        ----------
        fluid_density : float
            rho_f [kg/m^3] of the well fluid around the rods.
        gravity : float
            g [m/s^2].

        Examples
        --------
        RP 11L's buoyancy factor for water (G = 1) is 1 - 0.128 = 0.872, i.e. 1 - 62.4/490
        = 0.873 for its 490 lb/ft^3 steel; steel rods in water of 999 kg/m^3 (60 degF):

        >>> s = RodString([1000.0], [2.85e-4], [2.1e11], [2.43])
        >>> round(float(s.buoyant_weight_per_length(999.0, 1.0)[0] / 2.43), 3)
        0.873

        References
        ----------
        [API11L].
        """
        if not (np.isfinite(fluid_density) and fluid_density >= 0):
            raise DownholeError(f"fluid density must be finite and not negative, got {fluid_density:g} kg/m^3")
        floating = np.asarray(fluid_density >= self.material_density)
        if floating.any():
            index = int(np.flatnonzero(floating)[0])
            raise DownholeError(f"fluid density {fluid_density:g} kg/m^3 is not below the density of rod section "
                                f"{index + 1}, {self.material_density[index]:g} kg/m^3: the rods would float")
        return gravity * self.mass_per_length * (1.0 - fluid_density / self.material_density)

    def buoyant_weight(self, fluid_density: float, gravity: float = STANDARD_GRAVITY) -> float:
        """W_rf = sum q_i L_i [N], weight of the whole string in the well fluid."""
        return float(np.sum(self.buoyant_weight_per_length(fluid_density, gravity) * self.length))

    def static_tension(self, fluid_density: float, gravity: float = STANDARD_GRAVITY) -> np.ndarray:
        """T_s at the section ends [N], S + 1 values: buoyant weight of the rods below.

        T_s(0) is the buoyant weight of the string, T_s(L) = 0 (the datum of the pump load).
        """
        below = (self.buoyant_weight_per_length(fluid_density, gravity) * self.length)[::-1].cumsum()[::-1]
        return np.concatenate((below, [0.0]))

    def damping_coefficient(self, damping_factor):
        """Gibbs' viscous damping coefficient c = pi a nu / (2 L) [1/s] [Gibbs1963].

        nu is dimensionless (a float, or an array of one per card: c likewise); a is
        :attr:`mean_wave_speed` and L :attr:`total_length`,
        so pi a / (2 L) is the first natural frequency of the string fixed at the
        polished rod and free at the pump, and nu / 2 the fraction of critical damping
        of that mode. The damping force per unit length is c m_i du/dt in every section.

        Examples
        --------
        Uniform rod, a = 5000 m/s, L = 1000 m, nu = 0.1: c = pi 5000 0.1 / 2000.

        >>> s = RodString([1000.0], [1.0], [5000.0**2], [1.0])
        >>> round(s.damping_coefficient(0.1), 6)
        0.785398

        References
        ----------
        [Gibbs1963].
        """
        if not (np.all(np.isfinite(damping_factor)) and np.all(np.asarray(damping_factor) >= 0)):
            raise DownholeError(f"damping factor must be finite and not negative, got {damping_factor}")
        found = np.pi * self.mean_wave_speed * np.asarray(damping_factor, dtype=float) / (2.0 * self.total_length)
        return float(found) if found.ndim == 0 else found

    def subdivided(self, pieces: int) -> RodString:
        """The same string cut into at least ``pieces`` sections, none longer than L / pieces (to
        read the wave solution along the rods, not only at the tapers' ends).

        >>> s = RodString([600.0, 400.0], [4e-4, 3e-4], [2e11, 2e11], [3.2, 2.4]).subdivided(10)
        >>> s.length.tolist(), s.total_length
        ([100.0, 100.0, 100.0, 100.0, 100.0, 100.0, 100.0, 100.0, 100.0, 100.0], 1000.0)
        """
        counts = np.maximum(1, np.ceil(self.length * pieces / self.total_length - 1e-9)).astype(int)
        return RodString(np.repeat(self.length / counts, counts), np.repeat(self.area, counts),
                         np.repeat(self.youngs_modulus, counts), np.repeat(self.mass_per_length, counts),
                         np.repeat(self.material_density, counts), np.repeat(self.tensile_strength, counts),
                         tuple(name for name, count in zip(self.names, counts) for _ in range(count)))

    def reversed(self) -> RodString:
        """The same string listed from the pump up (for marching from the pump)."""
        return RodString(self.length[::-1], self.area[::-1], self.youngs_modulus[::-1],
                         self.mass_per_length[::-1], self.material_density[::-1],
                         self.tensile_strength[::-1], self.names[::-1])
