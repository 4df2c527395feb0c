"""The air-balanced unit's counterbalance: an air cylinder under the walking beam.

A class III four-bar (:class:`.class_three.ClassThreeLinkage`) counterbalanced by
compressed air: the cylinder stands under the beam and its piston rod is pinned to the beam
at the signed distance d along it from the centre bearing (towards the well positive). The
cylinder is taken as vertical (guided), so the pin rises d (sin psi - sin psi_b) from the
bottom of the stroke, the gas volume grows to

    V(psi) = V_b + A_c d (sin psi - sin psi_b),

and the gas follows a polytropic p V^n = const (absolute pressure; n = 1.4 isentropic air,
n = 1 isothermal). The piston pushes up with F = (p - p_a) A_c (the rod side at the
atmosphere p_a), and the gearbox torque that holds the beam against it is, by virtual work,

    T_c = -F d cos(psi) dpsi/dtheta = -F (d cos(psi) / A) TF

([Artobolevsky1951]; TF = A dpsi/dtheta, [API11E]). Its counterbalance at the polished rod,
F d cos(psi) / A, falls as the beam rises and the gas expands: it follows the beam's lever
and the gas, not sin(theta). The force depends on the position only, so the gas does no net
work over a cycle, and the mean net torque is the polished-rod work per radian whatever
the pressure (``tests/core/beam/test_air_balanced.py``).

The balancing variable is the gauge pressure p_r at a stated beam angle psi_r (the bottom of
the stroke, or a polished-rod position the gauge is read at): p(psi) = (p_r + p_a)
(V(psi_r) / V(psi))^n, so T_c is affine in p_r, as the balance needs.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..mechanism import Motion

#: Standard atmosphere [Pa] ([BIPM2019]: 101 325 Pa by definition).
ATMOSPHERE = 101_325.0


@dataclass(frozen=True)
class AirCylinder:
    """An air-balance cylinder; a :class:`~pumpjack_cli.core.beam.counterbalance.CounterbalanceModel`.

    Parameters
    ----------
    structural_unbalance : float
        B [N], the beam with the cylinder's rod disconnected (or at zero gauge pressure).
    pressure : float
        Gauge pressure p_r [Pa] at the beam angle ``reference_beam_angle`` (the balancing
        variable).
    reference_beam_angle : float
        psi_r [rad].
    piston_area : float
        A_c [m²].
    bottom_volume : float
        V_b [m³]: the gas volume (cylinder clearance and any tank) at the bottom of the stroke.
    bottom_beam_angle : float
        psi_b [rad].
    lever : float
        d [m]: the piston rod's pin along the beam from the centre bearing, towards the well
        positive.
    horsehead_arm : float
        A [m].
    exponent : float
        n, polytropic.
    atmosphere : float
        p_a [Pa].

    Examples
    --------
    At the bottom of the stroke the gas is at p_r; with psi_b = 0 the pin's lever is d:

    >>> import numpy as np
    >>> from pumpjack_cli.core.mechanism import Motion
    >>> z = np.zeros(1)
    >>> m = Motion(z, z, np.ones(1), z, z, z, z, z, z, z)
    >>> air = AirCylinder(0.0, 1e6, 0.0, 0.05, 0.1, 0.0, 2.0, 4.0, 1.4)
    >>> float(air.counterbalance_torque(m)[0])     # -p A_c d / A per metre of TF
    -25000.0
    """

    structural_unbalance: float
    pressure: float
    reference_beam_angle: float
    piston_area: float
    bottom_volume: float
    bottom_beam_angle: float
    lever: float
    horsehead_arm: float
    exponent: float = 1.4
    atmosphere: float = ATMOSPHERE

    @property
    def value(self) -> float:
        """p_r [Pa], gauge."""
        return self.pressure

    @property
    def variable(self) -> str:
        """``air_pressure``."""
        return "air_pressure"

    @property
    def symbol(self) -> str:
        """``Pa``."""
        return "Pa"

    def summary(self) -> tuple[tuple[str, float], ...]:
        """B [N], A_c [m²], V_b [m³], d [m], n."""
        return (("structural_unbalance", self.structural_unbalance), ("air_piston_area", self.piston_area),
                ("air_bottom_volume", self.bottom_volume), ("air_cylinder_lever", self.lever),
                ("air_exponent", self.exponent))

    def volume(self, beam_angle: np.ndarray) -> np.ndarray:
        """V(psi) [m³]."""
        return self.bottom_volume + self.piston_area * self.lever * (np.sin(beam_angle) - np.sin(self.bottom_beam_angle))

    def force(self, beam_angle: np.ndarray) -> np.ndarray:
        """F = (p - p_a) A_c [N], upward on the beam."""
        ratio = (self.volume(np.asarray(self.reference_beam_angle)) / self.volume(beam_angle)) ** self.exponent
        return ((self.pressure + self.atmosphere) * ratio - self.atmosphere) * self.piston_area

    def structural_torque(self, motion: Motion) -> np.ndarray:
        """-TF B [N·m] ([API11E])."""
        return -motion.torque_factor * self.structural_unbalance

    def _lever(self, motion: Motion) -> np.ndarray:
        """d cos(psi) TF / A [m]: the pin's rise per radian of crank."""
        return self.lever * np.cos(motion.beam_angle) * motion.torque_factor / self.horsehead_arm

    def counterbalance_torque(self, motion: Motion) -> np.ndarray:
        """-F d cos(psi) TF / A [N·m]."""
        return -self.force(motion.beam_angle) * self._lever(motion)

    def torque_per_value(self, motion: Motion) -> np.ndarray:
        """dT_c/dp_r = -A_c (V_r / V)^n d cos(psi) TF / A [N·m per Pa]."""
        ratio = (self.volume(np.asarray(self.reference_beam_angle)) / self.volume(motion.beam_angle)) ** self.exponent
        return -self.piston_area * ratio * self._lever(motion)

    def with_value(self, value: float) -> AirCylinder:
        """The same cylinder at the gauge pressure p_r = ``value`` [Pa]."""
        return replace(self, pressure=value)
