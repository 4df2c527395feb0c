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
    """Sections from the top down; every field is an array of one value per section.

    Parameters
    ----------
    length : numpy.ndarray
        L_i [m].
    area : numpy.ndarray
        A_i [m^2], metal cross-section of the rod body.
    youngs_modulus : numpy.ndarray
        E_i [Pa].
    mass_per_length : numpy.ndarray
        m_i [kg/m], rod with its couplings.
    """

    length: np.ndarray
    area: np.ndarray
    youngs_modulus: np.ndarray
    mass_per_length: np.ndarray

    @property
    def total_length(self) -> float:
        """L = sum L_i [m], polished rod to pump."""
        return float(np.sum(self.length))

    @property
    def wave_speed(self) -> np.ndarray:
        """a_i = sqrt(E_i A_i / m_i) [m/s] per section."""
        return np.sqrt(self.youngs_modulus * self.area / self.mass_per_length)

    @property
    def mass(self) -> float:
        """Mass of the string with couplings [kg]."""
        return float(np.sum(self.mass_per_length * self.length))

    def weight_in_air(self, gravity: float = STANDARD_GRAVITY) -> float:
        """W_r = g sum m_i L_i [N]."""
        return gravity * self.mass
