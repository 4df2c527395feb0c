"""The class III beam unit (Mark II, air-balanced): the equalizer between the centre bearing
and the horsehead, the crank shaft ahead of the centre bearing.

Frame and letters as :mod:`.geometry` (origin at the centre bearing, x towards the well, y
up; crank angle theta from 12 o'clock in the direction of rotation, [API11E]): the crank
shaft is at O = (+I, -(H - G)), the equalizer bearing at B = +C (cos psi, sin psi) on the
horsehead side, the pitman |B - A| = P from the crank pin A = O + R (s sin theta, cos theta),
s = +1 clockwise, -1 counterclockwise with the well to the right. The horsehead is an arc
of radius A, so the polished rod rises A dpsi as the beam turns ([API11E]: the class III
lever carries the pitman's force between the fulcrum and the load).

The mirror x -> -x maps this four-bar onto the class I four-bar of :class:`.geometry.Linkage`
with the same letters turning the other way (the reflection reverses the sense of rotation
and keeps the crank angle from 12 o'clock): A_III = mirror(A_I), and B_III = C e(psi) goes to
-C e(-psi), so psi_III(theta) = -psi_I(theta). Hence, exactly,

* s_III(theta) = S - s_I(theta) (the top of one is the bottom of the other), TF_III = -TF_I;
* the class III bottom of the stroke is the mirror's top, and its upstroke crank travel the
  mirror's downstroke travel, which is the upstroke travel of the class I unit of the same
  letters turning the *same* way: with the same letters and rotation a class III unit has
  the stroke and upstroke travel of the class I unit, which is why strokes cannot tell the
  classes apart (the phase of PR(theta) and TF(theta) against the crank angle can);
* the pitman direction chi_III = pi - chi_I, the joints' x-components change sign.

The class I kinematics is therefore computed once (:mod:`.linkage`) and mirrored here;
``tests/core/beam/test_class_three.py`` checks the mirror against a direct solution of the
class III loop and TF = dPR/dtheta by finite differences.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from ..mechanism import ChordSliderCrank, EquivalentCrank, JointRates, Motion
from .geometry import CLOCKWISE, DeadPositions, Linkage


@dataclass(frozen=True)
class ClassThreeLinkage:
    """Geometry of a class III beam unit's four-bar, SI; implements
    :class:`~pumpjack_cli.core.mechanism.Mechanism`.

    Parameters
    ----------
    front_arm : float
        A [m]: centre bearing to horsehead arc.
    rear_arm : float
        C [m]: centre bearing to equalizer bearing, on the horsehead side (the API letter
        keeps its name on a class III unit).
    crank_radius : float
        R [m].
    pitman : float
        P [m].
    horizontal_offset : float
        I [m]: the crank shaft's horizontal distance ahead of the centre bearing.
    vertical_offset : float
        H - G [m]: the centre bearing above the crank shaft.
    rotation : int
        +1 clockwise, -1 counterclockwise, seen with the well to the right.

    References
    ----------
    [API11E] (letters and classes).

    Examples
    --------
    The mirror identity with the class I unit of the same letters turning the other way:

    >>> unit = ClassThreeLinkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0, CLOCKWISE)
    >>> mirror = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0, -CLOCKWISE)
    >>> round(unit.stroke, 9) == round(mirror.stroke, 9)
    True
    >>> dead = unit.dead_positions()
    >>> round(dead.upstroke_crank_travel, 9) == round(mirror.dead_positions().downstroke_crank_travel, 9)
    True
    """

    front_arm: float
    rear_arm: float
    crank_radius: float
    pitman: float
    horizontal_offset: float
    vertical_offset: float
    rotation: int = CLOCKWISE

    @cached_property
    def _mirror(self) -> Linkage:
        """The class I four-bar of the same letters turning the other way."""
        return Linkage(self.front_arm, self.rear_arm, self.crank_radius, self.pitman, self.horizontal_offset,
                       self.vertical_offset, -self.rotation)

    @property
    def frame_length(self) -> float:
        """K = sqrt(I^2 + (H - G)^2) [m]."""
        return math.hypot(self.horizontal_offset, self.vertical_offset)

    def check(self) -> None:
        """Raise :class:`~pumpjack_cli.errors.GeometryError` unless the crank turns through a
        revolution (Grashof, the same lengths as the mirror's)."""
        self._mirror.check()

    @cached_property
    def _dead(self) -> DeadPositions:
        top = self._mirror.dead_positions()
        return DeadPositions(top.crank_angle_top, top.crank_angle_bottom, -top.beam_angle_top, -top.beam_angle_bottom,
                             self.front_arm)

    def dead_positions(self) -> DeadPositions:
        """Bottom and top of the stroke: the mirror's top and bottom, beam angles negated."""
        return self._dead

    @property
    def stroke(self) -> float:
        """Exact polished-rod stroke [m], the mirror's."""
        return self._dead.stroke

    def motion(self, crank_angle: Any) -> Motion:
        """The mirror's motion reflected: psi and its rates, TF and its rate negated, s = S - s_I,
        chi = pi - chi_I (wrapped to (-pi, pi]) with its rates negated."""
        import numpy as np

        m = self._mirror.motion(crank_angle)
        chi = np.pi - m.pitman_angle
        return Motion(crank_angle=m.crank_angle, rod_position=self.stroke - m.rod_position,
                      torque_factor=-m.torque_factor, torque_factor_rate=-m.torque_factor_rate,
                      beam_angle=-m.beam_angle, beam_rate=-m.beam_rate, beam_rate2=-m.beam_rate2,
                      pitman_angle=np.where(chi > np.pi, chi - 2.0 * np.pi, chi),
                      pitman_rate=-m.pitman_rate, pitman_rate2=-m.pitman_rate2)

    def rod_position(self, crank_angle: Any) -> Any:
        """Polished-rod position above the bottom of the stroke [m]."""
        return self.rod_motion(crank_angle)[0]

    def rod_motion(self, crank_angle: Any) -> tuple[Any, Any]:
        """The mirror's polished-rod position and torque factor reflected: s = S - s_I, TF negated."""
        position, torque_factor = self._mirror.rod_motion(crank_angle)
        return self.stroke - position, -torque_factor

    def torque_factor(self, crank_angle: Any) -> Any:
        """TF = ds/dtheta [m] ([API11E])."""
        return self.motion(crank_angle).torque_factor

    def turned(self) -> ClassThreeLinkage:
        """The same four-bar turning the other way."""
        return dataclasses.replace(self, rotation=-self.rotation)

    def joint_rates(self, motion: Motion) -> JointRates:
        """The mirror's crank pin and equalizer rates with their x-components negated."""
        import numpy as np

        mirrored = dataclasses.replace(motion, beam_angle=-motion.beam_angle, beam_rate=-motion.beam_rate,
                                       beam_rate2=-motion.beam_rate2)
        rates = self._mirror.joint_rates(mirrored)
        flip = np.array([-1.0, 1.0])[:, None]
        return JointRates(flip * rates.crank_pin_rate, flip * rates.crank_pin_rate2, flip * rates.equalizer_rate,
                          flip * rates.equalizer_rate2)

    @property
    def lever_class(self) -> str:
        """``"III"``: the equalizer bearing between the centre bearing and the horsehead ([API11E])."""
        return "III"

    @property
    def horsehead_arm(self) -> float:
        """A [m]."""
        return self.front_arm

    @property
    def equalizer_arm(self) -> float:
        """+C [m]: the equalizer bearing on the horsehead side."""
        return self.rear_arm

    @property
    def pitman_length(self) -> float:
        """P [m]."""
        return self.pitman

    def equivalent_crank(self) -> EquivalentCrank:
        """Amplitude R A / C [m] and crank ratio R / P of the textbook laws ([Aliverdizade1951])."""
        return EquivalentCrank(self.crank_radius * self.front_arm / self.rear_arm, self.crank_radius / self.pitman)

    def chord_slider_crank(self) -> ChordSliderCrank:
        """The mirror's chord slider-crank (distances are the same) with the scale negated: the
        polished rod rises as the mirror's falls."""
        chord = self._mirror.chord_slider_crank()
        return dataclasses.replace(chord, scale=-chord.scale)
