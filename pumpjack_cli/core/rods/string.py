"""A tapered sucker-rod string as arrays of sections, SI.

The string hangs from the polished rod (x = 0) down to the pump (x = L); section i
has length L_i, metal area A_i, Young's modulus E_i and a mass per unit length m_i
that includes the couplings (so the stress wave speed is a_i = sqrt(E_i A_i / m_i),
not sqrt(E/rho) of bare steel).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..constants import STANDARD_GRAVITY


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
