"""Counterbalance of a crank-balanced beam pumping unit: B, M and tau from the masses,
the counterbalance effect, and the counterweight placement that realises a moment (the
moment that best balances a card is :mod:`.balance`).

Conventions (those of the whole package, :mod:`.geometry`): crank angle theta from 12
o'clock in the direction of rotation, well to the right; net gearbox torque T positive
when the gearbox drives the crank in its direction of rotation (the sign of
:attr:`.kinetostatics.Reactions.net_torque`); torque factor TF = A psi' = ds/dtheta,
positive on the upstroke of a conventional unit; polished-rod load W positive pulling
the horsehead down. The API net torque is then ([API11E]; [Rowlan2004] method 1)

    T(theta) = TF(theta) (W(theta) - B) - M sin(theta + tau)

* B, structural unbalance [N]: the force that must act *downwards* at the polished rod
  to hold the walking beam level with the pitmans disconnected from the crank pins
  (they then hang from the equalizer pins: a distance C behind the centre bearing on a
  class I unit, in front of it on a class III unit). Positive for a rear-heavy beam,
  whose weight helps lift the rods.
* M, maximum counterbalance moment [N·m]: the gravity moment of both crank arms and all
  counterweights about the crank shaft when their resultant is horizontal.
* tau, crank offset [rad]: the angle by which the resultant of crank arms and
  counterweights *leads* the crank pin, in the direction of rotation (negative when it
  lags); 0 when the counterweights sit on the crank arm in line with the pin (every
  conventional unit). With the package's ``counterweight_phase`` phi (angle from the
  pin to the blocks, in the direction of rotation) and no crank-arm mass, tau = phi.
  Sources write the sign before tau differently (sin(theta - tau) or sin(theta + tau));
  this one makes the offsets catalogues print well-balanced: a reverse-mark's -9 to -14
  deg is a lag, and the lag is what lowers its peak torque (``docs/conventions.md``,
  ``tests/validation/test_unitdatabase2018.py``); it is tested against the spatial
  kinetostatics.

The counterbalance term: the potential energy of crank arms and counterweights is
V = g sum m_i r_i cos(theta + phi_i) (heights above the shaft), so the gearbox torque
that holds them is dV/dtheta = -g sum m_i r_i sin(theta + phi_i) = -M sin(theta + tau)
with M exp(i tau) = g sum m_i r_i exp(i phi_i).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple, Protocol

import numpy as np

from ...errors import TorqueError
from ..constants import STANDARD_GRAVITY
from ..mechanism import Mechanism, Motion
from .masses import MassModel


class CounterbalanceModel(Protocol):
    """How a unit's structure and counterbalance load the gearbox: the seam of balancing kinds.

    The gearbox torque of the structure and of the counterbalance at the mechanism's motion,
    the latter affine in the unit's balancing variable ``value`` (the crank counterweights'
    moment M, a beam counterweight, an air cylinder's pressure): counterbalance torque =
    c0(theta) + value g(theta), g = :meth:`torque_per_value`. Crank counterweights are
    :class:`Counterbalance`; a unit kind that balances otherwise adds its model in its own
    module (``docs/architecture.md``). Torques are + when they drive the crank forward.
    """

    @property
    def value(self) -> float:
        """The balancing variable's present value (its unit: the kind's)."""
        ...

    def structural_torque(self, motion: Motion) -> np.ndarray:
        """Gearbox torque of the structure's unbalance [N·m] at the motion's crank angles."""
        ...

    def counterbalance_torque(self, motion: Motion) -> np.ndarray:
        """Gearbox torque of the counterbalance [N·m] at the motion's crank angles."""
        ...

    def torque_per_value(self, motion: Motion) -> np.ndarray:
        """d(counterbalance torque)/d(value) at the motion's crank angles."""
        ...

    def with_value(self, value: float) -> CounterbalanceModel:
        """The same counterbalance with the balancing variable at ``value``."""
        ...

    @property
    def variable(self) -> str:
        """The balancing variable's output name (``names.py``): ``counterbalance_moment``,
        ``beam_counterweight``, ``air_pressure``; the recommendation is ``recommended_`` + it."""
        ...

    @property
    def symbol(self) -> str:
        """The SI unit of the balancing variable, for messages (``N·m``, ``N``, ``Pa``)."""
        ...

    def summary(self) -> tuple[tuple[str, float], ...]:
        """The fixed figures of the structure and counterbalance to report, by output name."""
        ...


class Counterbalance(NamedTuple):
    """Crank counterweights: structural unbalance B [N], maximum counterbalance moment M [N·m]
    (the balancing variable), crank offset tau [rad]; a :class:`CounterbalanceModel`.

    ``tail`` False (class I): the counterweights ride on the crank pin's arm and
    T_c = -M sin(theta + tau), tau their lead ahead of the pin in the direction of rotation
    ([API11E]). ``tail`` True (class III, Mark II): they ride on the crank's tail, the arm
    opposite the pin, and T_c = +M sin(theta + tau), tau their lead ahead of the tail
    (``docs/conventions.md``: the sign that makes the offsets catalogues print, a Mark II's
    positive and a reverse-mark's negative one, the well-balanced ones).

    >>> import numpy as np
    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> m = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0).motion(np.array([np.pi / 2]))
    >>> balance = Counterbalance(1000.0, 50e3, 0.0)
    >>> float(balance.counterbalance_torque(m)[0]), float(balance.torque_per_value(m)[0])
    (-50000.0, -1.0)
    >>> float(balance._replace(tail=True).counterbalance_torque(m)[0])
    50000.0
    """

    structural_unbalance: float
    moment: float
    offset: float = 0.0
    tail: bool = False

    @property
    def value(self) -> float:
        """M [N·m]."""
        return self.moment

    @property
    def variable(self) -> str:
        """``counterbalance_moment``."""
        return "counterbalance_moment"

    @property
    def symbol(self) -> str:
        """``N·m``."""
        return "N·m"

    def summary(self) -> tuple[tuple[str, float], ...]:
        """B [N] and tau [rad]."""
        return (("structural_unbalance", self.structural_unbalance), ("crank_offset", self.offset))

    def structural_torque(self, motion: Motion) -> np.ndarray:
        """-TF B [N·m] ([API11E])."""
        return -motion.torque_factor * self.structural_unbalance

    def counterbalance_torque(self, motion: Motion) -> np.ndarray:
        """-M sin(theta + tau), on the tail +M sin(theta + tau) [N·m] ([API11E]; [Rowlan2004])."""
        return self.moment * self.torque_per_value(motion)

    def torque_per_value(self, motion: Motion) -> np.ndarray:
        """:meth:`per_moment` at the motion's crank angles [N·m per N·m]."""
        return self.per_moment(motion.crank_angle)

    def per_moment(self, crank_angle: np.ndarray) -> np.ndarray:
        """-sin(theta + tau), on the tail +sin(theta + tau) [-]."""
        wave = np.sin(crank_angle + self.offset)
        return wave if self.tail else -wave

    def with_value(self, value: float) -> Counterbalance:
        """The counterweights with the moment M = ``value`` [N·m]."""
        return self._replace(moment=value)


def counterbalance_from_masses(linkage: Mechanism, masses: MassModel, gravity: float = STANDARD_GRAVITY) -> Counterbalance:
    """B, M and tau of a unit from the masses of its links.

    B = -g [(m_eq + 2 m_p) x_eq + m_b x_b + m_h x_h] / A: the beam group level (psi = 0),
    both pitmans hanging whole from the equalizer pins at the equalizer bearing x_eq (-C
    on a class I unit), the beam body and horsehead centres of mass at x_b, x_h, all
    measured from the centre bearing towards the well. M exp(i alpha) = g (2 m_a r_a + m_cw r_cw
    exp(i phi)): both crank arms in line with the pin, all counterweights at phase phi ahead of
    it; tau = alpha on a class I unit, and on a class III unit, whose counterweights ride on
    the crank's tail, tau = alpha - pi, their lead ahead of the tail (:class:`Counterbalance`).

    Parameters
    ----------
    linkage : Mechanism
        Its horsehead arm A [m] and equalizer arm x_eq [m] are used.
    masses : MassModel
        Link masses [kg] and centres of mass [m].
    gravity : float
        g [m/s²].

    Returns
    -------
    Counterbalance
        B [N], M [N·m], tau [rad].

    References
    ----------
    [API11E] (definitions of B and M); [Rowlan2004].

    Examples
    --------
    Only counterweights, 1000 kg at 1 m in line with the pin: M = 9806.65 N·m, tau = 0;
    a beam body of 100 kg at 2 m towards the well, A = 4 m: B = -9.80665·200/4 = -490.3 N.

    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> lk = Linkage(4.0, 2.5, 1.0, 3.0, 2.2, 3.0)
    >>> m = MassModel(0, 0, 0, 1000.0, 1.0, 0.0, 0, 0, 0, 0, 0, 0, 100.0, 2.0, 0, 0, 0, 0)
    >>> [round(v, 2) for v in counterbalance_from_masses(lk, m)[:3]]
    [-490.33, 9806.65, 0.0]
    """
    moment = ((masses.equalizer_mass + 2.0 * masses.pitman_mass) * linkage.equalizer_arm
              + masses.beam_mass * masses.beam_cg + masses.horsehead_mass * masses.horsehead_cg)
    arms = 2.0 * masses.crank_arm_mass * masses.crank_arm_cg
    weights = masses.counterweight_mass * masses.counterweight_radius
    x = arms + weights * math.cos(masses.counterweight_phase)
    y = weights * math.sin(masses.counterweight_phase)
    lead = math.atan2(y, x)     # the resultant's angle ahead of the pin, in the direction of rotation
    tail = linkage.lever_class == "III"
    offset = (lead % (2.0 * math.pi)) - math.pi if tail else lead
    return Counterbalance(-gravity * moment / linkage.horsehead_arm, gravity * math.hypot(x, y), offset, tail)


#: API RP 11L's allowance over the mean of the up- and downstroke static loads in its
#: design counterbalance effect ([API11L]).
RP11L_COUNTERBALANCE_FACTOR = 1.06


def rp11l_counterbalance_effect(buoyant_rod_weight: float, fluid_load: float) -> float:
    """The counterbalance effect API RP 11L recommends for a design [N]:
    CBE = 1.06 (W_rf + F_o/2), the mean of the static upstroke (W_rf + F_o) and downstroke
    (W_rf) loads with 6 % added ([API11L]).

    Parameters
    ----------
    buoyant_rod_weight : float
        W_rf, the rods with couplings in the well fluid [N].
    fluid_load : float
        F_o, the fluid load on the plunger [N].

    Returns
    -------
    float
        CBE [N].

    References
    ----------
    [API11L].

    Examples
    --------
    The example of [RP11LXLS] (7000 ft of rod 76, 30.6 % 7/8 in at 2.224 lb/ft over 3/4 in
    at 1.634 lb/ft, G = 1, 1.25 in plunger): W_r = 7000 (0.306 x 2.224 + 0.694 x 1.634)
    = 12 701.8 lb, W_rf = W_r (1 - 0.128) = 11 076.0 lb, F_o = 0.340 x 1.25² x 7000
    = 3718.75 lb; CBE = 1.06 (11 076.0 + 1859.4) = 13 711.4 lb.

    >>> lbf = 4.4482216152605
    >>> wrf = 7000 * (0.306 * 2.224 + 0.694 * 1.634) * (1 - 0.128) * lbf
    >>> round(rp11l_counterbalance_effect(wrf, 0.340 * 1.25**2 * 7000 * lbf) / lbf, 1)
    13711.4
    """
    return RP11L_COUNTERBALANCE_FACTOR * (buoyant_rod_weight + 0.5 * fluid_load)


def counterbalance_effect(test: Motion, balance: CounterbalanceModel) -> float:
    """Counterbalance effect CBE [N]: the polished-rod load the structure and counterbalance hold
    at the test position.

    From T = TF W + T_s + T_c = 0 there: CBE = -(T_s + T_c) / TF, T_s and T_c the structure's
    and counterbalance's gearbox torques; for crank counterweights CBE = B + M sin(theta_t +
    tau) / TF(theta_t). The usual test position is the crank horizontal on the upstroke,
    theta_t = 90 deg ([Rowlan2004]).

    Parameters
    ----------
    test : Motion
        The mechanism's motion at the one test crank angle theta_t; TF(theta_t) must not vanish.
    balance : CounterbalanceModel
        The structure and counterbalance.

    Returns
    -------
    float
        CBE [N].

    References
    ----------
    [Rowlan2004]; [API11E].

    Examples
    --------
    B = 1000 N, M = 50 kN·m, tau = 0 on SK8-3,5-4000 at 90 deg, where TF = 1.3471 m:
    CBE = 1000 + 50 000 / TF = 38 115.7 N.

    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> test = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0).motion(np.array([math.pi / 2]))
    >>> round(float(test.torque_factor[0]), 4), round(counterbalance_effect(test, Counterbalance(1000.0, 50e3)), 1)
    (1.3471, 38115.7)
    """
    tf = float(test.torque_factor[0])
    if not abs(tf) > 0 or not math.isfinite(tf):
        raise TorqueError(f"counterbalance effect: the torque factor at the test angle "
                          f"{math.degrees(float(test.crank_angle[0])):.4g} deg is {tf:.4g} m; "
                          f"choose a test angle away from the dead positions")
    return -float(balance.structural_torque(test)[0] + balance.counterbalance_torque(test)[0]) / tf


def value_for_effect(test: Motion, balance: CounterbalanceModel, effect: float) -> float:
    """The balancing variable that makes the counterbalance effect at the test position ``effect``
    [N]: the inverse of :func:`counterbalance_effect` for the unit's own counterbalance model.

    The counterbalance torque is affine in the variable v, T_c(v) = T_c(v0) + (v - v0) g, so
    from CBE TF = -(T_s + T_c(v)) at theta_t: v = v0 - (CBE TF + T_s + T_c(v0)) / g. For crank
    counterweights (g = -sin(theta_t + tau)) this is M = (CBE - B) TF(theta_t) / sin(theta_t + tau),
    the moment a crew's measured CBE stands for ([Rowlan2004]; [API11E]).

    Parameters
    ----------
    test : Motion
        The mechanism's motion at the one test crank angle theta_t (where the CBE was measured).
    balance : CounterbalanceModel
        The structure and counterbalance; its present value is replaced.
    effect : float
        CBE [N], the polished-rod load the counterbalance holds at theta_t.

    Returns
    -------
    float
        The balancing variable (M [N·m] for crank counterweights).

    References
    ----------
    [Rowlan2004]; [API11E].

    Examples
    --------
    The example of :func:`counterbalance_effect` backwards: CBE = 38 115.7 N at 90 deg with
    B = 1000 N gives M = (38 115.7 - 1000) x 1.3471 = 50 000 N·m.

    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> test = Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0).motion(np.array([math.pi / 2]))
    >>> round(value_for_effect(test, Counterbalance(1000.0, 0.0), 38115.7), -1)
    50000.0
    """
    tf = float(test.torque_factor[0])
    per_value = float(balance.torque_per_value(test)[0])
    angle = math.degrees(float(test.crank_angle[0]))
    if not abs(tf) > 0 or not math.isfinite(tf):
        raise TorqueError(f"counterbalance effect: the torque factor at the test angle {angle:.4g} deg is {tf:.4g} m; "
                          f"give the effect measured away from the dead positions")
    if not abs(per_value) > 0 or not math.isfinite(per_value):
        raise TorqueError(f"counterbalance effect: at the test angle {angle:.4g} deg the counterbalance exerts no "
                          f"torque, so the effect measured there does not tell it")
    own = float(balance.structural_torque(test)[0] + balance.counterbalance_torque(test)[0])
    return balance.value - (effect * tf + own) / per_value


# --- realising a moment with counterweight blocks ----------------------------------


@dataclass(frozen=True)
class CounterweightPlacement:
    """Where the counterweights must sit for a moment M (point masses, as :class:`MassModel`).

    ``radius`` [m]: crank shaft to the blocks' centre of mass with the present blocks,
    None when no radius gives M (the crank arms alone exceed it); ``mass`` [kg]: total
    counterweight mass needed at the present radius, None when none does;
    ``within_range``: the radius lies in [r_min, r_max]; ``note``: why not, or empty.
    """

    radius: float | None
    mass: float | None
    within_range: bool
    note: str


def _magnitude_root(c: float, phase: float, target: float, per_unit: float) -> float | None:
    """x >= 0 with |c + per_unit x exp(i phase)| = target (the positive root of a quadratic), or None."""
    disc = target * target - (c * math.sin(phase)) ** 2
    if disc < 0 or not per_unit > 0:
        return None
    x = (-c * math.cos(phase) + math.sqrt(disc)) / per_unit
    return x if x >= 0 else None


def counterweight_placement(moment: float, masses: MassModel, radius_range: tuple[float, float],
                            gravity: float = STANDARD_GRAVITY) -> CounterweightPlacement:
    """Counterweight radius (with the present blocks) and total mass (at the present radius) giving M.

    Solves |2 m_a r_a + m_cw r_cw exp(i phi)| = M/g for r_cw (blocks fixed) and for m_cw
    (radius fixed), phi the counterweight phase; with phi != 0 the crank offset tau
    changes with them (see :func:`counterbalance_from_masses`).

    Parameters
    ----------
    moment : float
        M [N·m], >= 0.
    masses : MassModel
        Crank arms and counterweights [kg, m, rad].
    radius_range : (float, float)
        r_min, r_max [m]: the slot range of the blocks on the crank arm.
    gravity : float
        g [m/s²].

    Returns
    -------
    CounterweightPlacement

    References
    ----------
    [API11E] (M from crank arms and counterweights).

    Examples
    --------
    M = 9806.65 N·m, 1000 kg of blocks, massless arms: r = 1 m; 0.8 m at most fits:

    >>> m = MassModel(0, 0, 0, 1000.0, 0.9, 0.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)
    >>> p = counterweight_placement(9806.65, m, (0.3, 0.8))
    >>> round(p.radius, 6), round(p.mass, 3), p.within_range
    (1.0, 1111.111, False)
    """
    r_min, r_max = radius_range
    if not (math.isfinite(moment) and moment >= 0):
        raise TorqueError(f"counterweight placement: the counterbalance moment is {moment!r} N·m; it must be >= 0")
    if not (0 <= r_min <= r_max and math.isfinite(r_max)):
        raise TorqueError(f"counterweight placement: slot range [{r_min!r}, {r_max!r}] m is not 0 <= r_min <= r_max")
    arms = 2.0 * masses.crank_arm_mass * masses.crank_arm_cg
    target = moment / gravity
    radius = _magnitude_root(arms, masses.counterweight_phase, target, masses.counterweight_mass)
    mass = _magnitude_root(arms, masses.counterweight_phase, target, masses.counterweight_radius)
    radius = radius if radius is not None and math.isfinite(radius) else None
    mass = mass if mass is not None and math.isfinite(mass) else None
    if radius is None:
        note = (f"no counterweight radius gives {moment:.6g} N·m with {masses.counterweight_mass:.6g} kg of blocks: "
                f"the crank arms alone give {gravity * arms:.6g} N·m")
        return CounterweightPlacement(None, mass, False, note)
    within = r_min <= radius <= r_max
    note = "" if within else (f"the blocks would have to sit at {radius:.4g} m, outside the slots "
                              f"[{r_min:.4g}, {r_max:.4g}] m; change the number of blocks")
    return CounterweightPlacement(radius, mass, within, note)


def upstroke_mask(linkage: Mechanism, crank_angle: np.ndarray) -> np.ndarray:
    """True at crank angles [rad] on the upstroke: from the bottom dead position through the upstroke travel."""
    dead = linkage.dead_positions()
    return ((np.asarray(crank_angle, dtype=float) - dead.crank_angle_bottom) % (2.0 * np.pi)) < dead.upstroke_crank_travel


def upstroke_test_angle(linkage: Mechanism) -> float:
    """The crank angle of the counterbalance-effect test: the cranks horizontal on the upstroke,
    90 deg where that lies on the upstroke (a conventional unit), else 270 deg (a Mark II,
    whose upstroke runs through 270 deg) [rad] ([Rowlan2004]: the effect is measured with the
    cranks horizontal).

    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> round(math.degrees(upstroke_test_angle(Linkage(3.5, 2.5, 1.01, 3.0, 2.195, 3.0))))
    90
    """
    quarter = math.pi / 2
    return quarter if bool(upstroke_mask(linkage, np.array([quarter]))[0]) else 3.0 * quarter

