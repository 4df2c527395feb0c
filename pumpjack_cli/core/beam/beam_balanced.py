"""The beam-balanced unit's counterbalance: a weight on the walking beam's rear arm.

A class I four-bar (:class:`.geometry.Linkage`) whose counterweight rides on the beam, not
on the cranks. A weight W at the signed distance d along the beam from the centre bearing
(towards the well positive, so d < 0 on the rear arm) sits at the height d sin psi; the
gearbox torque that holds it is, by virtual work,

    T_c = W d cos(psi) dpsi/dtheta = W (d cos(psi) / A) TF

([Artobolevsky1951]: the torque of a weight reduced to the crank; TF = A dpsi/dtheta,
[API11E]), so its counterbalance at the polished rod, -d W cos(psi) / A, follows the torque
factor like the rod load and varies only with cos psi over the stroke. The balancing
variable is W.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..mechanism import Motion


@dataclass(frozen=True)
class BeamCounterweight:
    """A beam counterweight: structural unbalance B [N] (without the counterweight), the
    weight W [N] (the balancing variable), its arm d [m] along the beam from the centre bearing
    (towards the well positive: negative on the rear arm), the horsehead arm A [m]; a
    :class:`~pumpjack_cli.core.beam.counterbalance.CounterbalanceModel`.

    >>> import numpy as np
    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> unit = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0)
    >>> m = unit.motion(np.array([np.pi / 2]))
    >>> w = BeamCounterweight(0.0, 10e3, -2.0, 3.5)
    >>> t = float(w.counterbalance_torque(m)[0])
    >>> round(t / float(m.torque_factor[0]) * 3.5 / float(np.cos(m.beam_angle[0])), 6)   # W d
    -20000.0
    """

    structural_unbalance: float
    weight: float
    arm: float
    horsehead_arm: float

    @property
    def value(self) -> float:
        """W [N]."""
        return self.weight

    @property
    def variable(self) -> str:
        """``beam_counterweight``."""
        return "beam_counterweight"

    @property
    def symbol(self) -> str:
        """``N``."""
        return "N"

    def summary(self) -> tuple[tuple[str, float], ...]:
        """B [N] and d [m]."""
        return (("structural_unbalance", self.structural_unbalance), ("beam_counterweight_arm", self.arm))

    def structural_torque(self, motion: Motion) -> np.ndarray:
        """-TF B [N·m] ([API11E])."""
        return -motion.torque_factor * self.structural_unbalance

    def counterbalance_torque(self, motion: Motion) -> np.ndarray:
        """W d cos(psi) TF / A [N·m]."""
        return self.weight * self.torque_per_value(motion)

    def torque_per_value(self, motion: Motion) -> np.ndarray:
        """d cos(psi) TF / A [N·m per N]."""
        return self.arm * np.cos(motion.beam_angle) * motion.torque_factor / self.horsehead_arm

    def with_value(self, value: float) -> BeamCounterweight:
        """The same counterweight with W = ``value`` [N]."""
        return replace(self, weight=value)
