"""What every beam pumping unit's mechanism provides, whatever its linkage: the seam of unit kinds.

A unit kind (conventional class I, Mark II and air-balanced class III, ...) is one
module in :mod:`pumpjack_cli.core.beam` with one class that satisfies
:class:`Mechanism` (``docs/architecture.md``: adding a unit kind). Everything above the
mechanism (kinematics, cards, torque, counterbalance, balance, inertia laws, the
equation of motion, the rod-string drive) uses only this protocol: the crank angle goes
in, the polished-rod motion, the torque factor and the motion of the articulating links
come out, and the stroke and the crank travel of each stroke are properties of the dead
positions. No module outside the mechanisms computes a torque factor or reads a
linkage's dimensions (``tests/architecture``).

Every beam unit has a crank (with counterweights), a pitman pair, and a walking beam
turning about its centre bearing with the horsehead at one end and the equalizer
bearing somewhere along it; the protocol names these generically, so a consumer's
formula (the gravity of the beam group, the inertia of the pitmans) holds for every
kind. Only the spatial kinetostatics of the six-link mechanism (``reactions``,
``compare-redundancy``) is specific to the conventional unit, and says so.

This module imports nothing heavy, so configs can use it at start-up.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    import numpy as np


class DeadPositions(Protocol):
    """The two positions where the polished rod stops (bottom and top of the stroke).

    Attributes
    ----------
    crank_angle_bottom, crank_angle_top : float
        Crank angles of the bottom and the top of the stroke [rad], in the unit's
        crank-angle convention (from 12 o'clock in the direction of rotation, [API11E]).
    beam_angle_bottom, beam_angle_top : float
        Beam angles there [rad] (front arm above the horizontal).
    stroke : float
        Polished-rod travel from bottom to top [m].
    upstroke_crank_travel : float
        Crank rotation from bottom to top in the direction of rotation [rad].
    downstroke_crank_travel : float
        2 pi - upstroke_crank_travel [rad].

    References
    ----------
    [API11E] (crank-angle convention).
    """

    @property
    def crank_angle_bottom(self) -> float: ...

    @property
    def crank_angle_top(self) -> float: ...

    @property
    def beam_angle_bottom(self) -> float: ...

    @property
    def beam_angle_top(self) -> float: ...

    @property
    def stroke(self) -> float: ...

    @property
    def upstroke_crank_travel(self) -> float: ...

    @property
    def downstroke_crank_travel(self) -> float: ...


@dataclass(frozen=True)
class Motion:
    """The motion of a beam unit's links at an array of crank angles: angles and their first
    two derivatives with respect to the crank angle, and the polished rod's.

    All arrays share the shape of the crank angles they were computed for.

    Attributes
    ----------
    crank_angle : numpy.ndarray
        theta [rad].
    rod_position : numpy.ndarray
        s, polished-rod position above the bottom of the stroke [m].
    torque_factor : numpy.ndarray
        TF = ds/dtheta [m] ([API11E]): the gearbox torque per unit polished-rod load.
    torque_factor_rate : numpy.ndarray
        d2s/dtheta2 [m/rad].
    beam_angle : numpy.ndarray
        psi, front arm above horizontal [rad].
    beam_rate : numpy.ndarray
        dpsi/dtheta (dimensionless, rad/rad).
    beam_rate2 : numpy.ndarray
        d2psi/dtheta2 [1/rad].
    pitman_angle : numpy.ndarray
        chi, direction crank pin -> equalizer bearing above horizontal [rad].
    pitman_rate, pitman_rate2 : numpy.ndarray
        dchi/dtheta (dimensionless) and d2chi/dtheta2 [1/rad].

    References
    ----------
    [SK8Rotation2013] eqs. 6-7; [API11E] (torque factor).
    """

    crank_angle: np.ndarray
    rod_position: np.ndarray
    torque_factor: np.ndarray
    torque_factor_rate: np.ndarray
    beam_angle: np.ndarray
    beam_rate: np.ndarray
    beam_rate2: np.ndarray
    pitman_angle: np.ndarray
    pitman_rate: np.ndarray
    pitman_rate2: np.ndarray


@dataclass(frozen=True)
class JointRates:
    """Crank-angle derivatives of the crank pin and the equalizer bearing, each shape (2, N)
    in the unit's frame (centre bearing at the origin, x towards the well, y up):
    dA/dtheta, d2A/dtheta2, dB/dtheta, d2B/dtheta2 [m/rad, m/rad²]."""

    crank_pin_rate: np.ndarray
    crank_pin_rate2: np.ndarray
    equalizer_rate: np.ndarray
    equalizer_rate2: np.ndarray


@dataclass(frozen=True)
class EquivalentCrank:
    """The textbook laws' view of a unit: the polished rod as a crank of radius
    ``amplitude`` = R A / C [m] with a connecting rod of ratio ``crank_ratio`` = R / P
    ([Aliverdizade1951], [NUNG] eqs. 5.12-5.18)."""

    amplitude: float
    crank_ratio: float


@dataclass(frozen=True)
class ChordSliderCrank:
    """The chord law's offset slider-crank ([InertiaUNB600A] eq. 7): the equalizer bearing
    moved on the chord between its two dead positions. ``slider`` is the
    :class:`~pumpjack_cli.core.slider_crank.geometry.SliderCrank` (r = R, l = P, offset e
    [m]); its crank angle is phi = ``phase`` + theta [rad]; the polished rod moves
    ``scale`` (= +-A/C, the sign saying whether it rises as the slider moves along its
    axis) times the slider [-]."""

    slider: Any
    phase: float
    scale: float


class Mechanism(Protocol):
    """A beam pumping unit's linkage from the crank to the polished rod.

    Attributes
    ----------
    rotation : int
        +1 (clockwise) or -1 (counterclockwise), seen with the well to the right.
    lever_class : str
        ``"I"`` (equalizer behind the centre bearing: conventional, reverse-mark,
        beam-balanced) or ``"III"`` (equalizer between the centre bearing and the
        horsehead: Mark II, air-balanced) ([API11E]).
    horsehead_arm : float
        Radius of the horsehead arc about the centre bearing [m] (API letter A).
    equalizer_arm : float
        Position of the equalizer bearing along the beam from the centre bearing,
        towards the well positive [m] (-C for class I, +C for class III).
    pitman_length : float
        Crank pin to equalizer bearing in the plane of motion [m].

    References
    ----------
    [API11E] (torque factor, crank-angle convention, unit classes).
    """

    @property
    def rotation(self) -> int: ...

    @property
    def lever_class(self) -> str: ...

    @property
    def horsehead_arm(self) -> float: ...

    @property
    def equalizer_arm(self) -> float: ...

    @property
    def pitman_length(self) -> float: ...

    def __hash__(self) -> int:
        """Mechanisms are immutable values: analyses cache their tables per mechanism."""
        ...

    def check(self) -> None:
        """Raise :class:`~pumpjack_cli.errors.GeometryError` unless the crank turns through a revolution."""
        ...

    def dead_positions(self) -> DeadPositions:
        """The bottom and top of the stroke (crank angles [rad], stroke [m])."""
        ...

    def turned(self) -> Mechanism:
        """The same unit turning the other way (its rotation reversed)."""
        ...

    @property
    def stroke(self) -> float:
        """The exact polished-rod stroke [m]."""
        ...

    def motion(self, crank_angle: Any) -> Motion:
        """Link angles [rad], rod position [m], torque factor [m] and their crank-angle derivatives, arrays."""
        ...

    def rod_position(self, crank_angle: Any) -> Any:
        """Polished-rod position above the bottom of the stroke [m] at crank angles [rad], arrays."""
        ...

    def rod_motion(self, crank_angle: Any) -> tuple[Any, Any]:
        """The polished-rod position [m] and torque factor [m] alone, as :meth:`motion` gives them,
        at crank angles [rad] (for a caller that needs no more: the time fit's iterates)."""
        ...

    def torque_factor(self, crank_angle: Any) -> Any:
        """TF = ds/dtheta [m] at crank angles [rad], arrays ([API11E])."""
        ...

    def joint_rates(self, motion: Motion) -> JointRates:
        """Crank-angle derivatives of the crank pin and the equalizer bearing [m/rad, m/rad²]."""
        ...

    def equivalent_crank(self) -> EquivalentCrank:
        """The amplitude and crank ratio of the textbook approximations."""
        ...

    def chord_slider_crank(self) -> ChordSliderCrank:
        """The offset slider-crank of the chord law of [InertiaUNB600A]."""
        ...
