"""Net gearbox torque of a beam pumping unit from a dynamometer card: the API 11E
torque-factor method, its decomposition with non-uniform crank speed, the permissible
load diagram, and the exact (spatial kinetostatic) method beside it.

Sign conventions are those of :mod:`.counterbalance`: theta from 12 o'clock in the
direction of rotation; T positive when the gearbox drives the crank forward; TF = A psi'
(ds/dtheta); W positive pulling the horsehead down; B positive for a rear-heavy beam;
tau the lead of the counterweight resultant ahead of the crank pin (negative: a lag).

API net torque ([API11E]; [Rowlan2004] method 1): T = TF (W - B) - M sin(theta + tau).

Decomposition with non-uniform crank speed ([Takacs2016]): crank speed omega(t) and
acceleration alpha(t) from the card's time stamps (:func:`pumpjack_cli.core.cards.place_card`) or
from the machine's equation of motion (:mod:`pumpjack_cli.core.dynamics.periodic`); then

* rod-load torque TF W,
* structural-unbalance torque -TF B,
* counterbalance torque -M sin(theta + tau),
* articulating-inertia torque (TF / A) I_b psi_tt, with I_b the moment of inertia of the
  beam group (beam, horsehead, equalizer, and the pitmans lumped at the equalizer pins,
  as [Takacs2016] defines I_b) about the saddle bearing and psi_tt = psi'' omega^2 +
  psi' alpha the beam's angular acceleration: the torque that accelerates the beam,
  reduced to the crank by the virtual-work ratio psi' = TF / A,
* rotary-inertia torque I_r alpha, with I_r the moment of inertia of crank arms and
  counterweights about the crank shaft,

and the net torque is their sum. Each term is the gearbox torque that the part needs
(virtual work: T omega = the power delivered to it), so the decomposition reproduces
the spatial kinetostatics exactly when the beam group is balanced about the saddle
bearing and the pitmans are massless (tested). The readable parts of [Takacs2016] here
are its abstract and symbol list (I_b: "mass moment of inertia of the beam, horsehead,
equalizer, bearings, and pitmans, referred to the saddle bearing"); its equation
numbers could not be read, so the terms above are derived, not copied.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import TorqueError
from .counterbalance import Counterbalance, CounterbalanceModel, counterbalance_from_masses
from . import kinetostatics
from .kinetostatics import applied_loads, rational_mechanism, rational_reactions
from ..mechanism import Mechanism
from .masses import MassModel
from .spatial import SpatialLinkage, SpatialMotion, spatial_motion

#: Net-torque methods: the API 11E torque-factor method and the spatial kinetostatics.
TORQUE_METHODS = ("api", "exact")


def _finite(name: str, *arrays: np.ndarray) -> None:
    for array in arrays:
        if not np.all(np.isfinite(array)):
            raise TorqueError(f"{name}: input is not finite at every crank angle")


def api_net_torque(crank_angle: np.ndarray, torque_factor: np.ndarray, rod_load: np.ndarray,
                   balance: Counterbalance) -> np.ndarray:
    """Net gearbox torque T = TF (W - B) - M sin(theta + tau) [N·m] ([API11E]; [Rowlan2004]);
    on a class III crank (``balance.tail``) T = TF (W - B) + M sin(theta + tau).

    Parameters
    ----------
    crank_angle : ndarray
        theta [rad].
    torque_factor : ndarray
        TF [m] at those angles.
    rod_load : ndarray
        W [N], polished-rod load.
    balance : Counterbalance
        B [N], M [N·m], tau [rad].

    Returns
    -------
    ndarray
        T [N·m], + when the gearbox drives the crank forward.

    References
    ----------
    [API11E]; [Rowlan2004].

    Examples
    --------
    TF = 1 m, W = 50 kN, B = 2 kN, M = 40 kN·m at theta = 90 deg: 48 000 - 40 000 = 8000 N·m.

    >>> api_net_torque(np.array([np.pi / 2]), np.array([1.0]), np.array([50e3]), Counterbalance(2e3, 40e3, 0.0))
    array([8000.])
    """
    theta = np.asarray(crank_angle, dtype=float)
    _finite("API net torque", theta, torque_factor, rod_load)
    return torque_factor * (rod_load - balance.structural_unbalance) + balance.moment * balance.per_moment(theta)


@dataclass(frozen=True)
class TorqueComponents:
    """Gearbox torque terms [N·m] at ``crank_angle`` [rad] ([Takacs2016]); :attr:`net` is their sum."""

    crank_angle: np.ndarray
    rod_load: np.ndarray
    structural: np.ndarray
    counterbalance: np.ndarray
    articulating_inertia: np.ndarray
    rotary_inertia: np.ndarray

    @property
    def net(self) -> np.ndarray:
        """Net gearbox torque [N·m]."""
        return self.rod_load + self.structural + self.counterbalance + self.articulating_inertia + self.rotary_inertia


def beam_group_inertia(linkage: Mechanism, masses: MassModel) -> float:
    """I_b [kg·m²]: beam, horsehead, equalizer and both pitmans about the saddle bearing.

    I_b = J_b + m_b x_b² + J_h + m_h x_h² + J_eq + (m_eq + 2 m_p) x_eq²: bodies on the beam
    line at their centres of mass (parallel-axis theorem), the equalizer at D (turning
    with the beam about its pin line), the pitmans lumped at the equalizer pins, as
    [Takacs2016] defines I_b. (The pitmans' lower ends move with the crank pins, so the
    lumping is an approximation; the exact method treats them exactly.)

    >>> m = MassModel(0, 0, 0, 0, 0, 0, 100.0, 1.5, 0, 50.0, 2.0, 0, 1000.0, 0.5, 3000.0, 0, 0, 0)
    >>> from pumpjack_cli.core.beam.geometry import Linkage
    >>> beam_group_inertia(Linkage(3.5, 2.5, 1.0, 3.0, 2.2, 3.0), m)   # 3000 + 250 + 2 + 312.5 + 1250
    4814.5
    """
    c = linkage.equalizer_arm
    return (masses.beam_inertia + masses.beam_mass * masses.beam_cg**2
            + masses.horsehead_inertia + masses.horsehead_mass * masses.horsehead_cg**2
            + masses.equalizer_inertia + masses.equalizer_mass * c**2 + 2.0 * masses.pitman_mass * c**2)


def crank_group_inertia(masses: MassModel) -> float:
    """I_r [kg·m²]: both crank arms and all counterweights (point masses) about the crank shaft.

    I_r = 2 (J_a + m_a r_a²) + m_cw r_cw² (parallel-axis theorem).

    >>> crank_group_inertia(MassModel(100.0, 0.5, 10.0, 1000.0, 1.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0))
    1070.0
    """
    return 2.0 * (masses.crank_arm_inertia + masses.crank_arm_mass * masses.crank_arm_cg**2) + \
        masses.counterweight_mass * masses.counterweight_radius**2


def torque_components(linkage: Mechanism, crank_angle: np.ndarray, rod_load: np.ndarray, balance: CounterbalanceModel, *,
                      beam_inertia: float = 0.0, rotary_inertia: float = 0.0,
                      crank_speed: np.ndarray | float = 0.0, crank_acceleration: np.ndarray | float = 0.0) -> TorqueComponents:
    """The gearbox torque terms of [Takacs2016] at each crank angle, as arrays.

    Parameters
    ----------
    linkage : Mechanism
        The unit (TF, psi', psi'').
    crank_angle : ndarray
        theta [rad].
    rod_load : ndarray
        W [N] at those angles; K cards' loads (K, N) give the card terms per card.
    balance : CounterbalanceModel
        The structure and counterbalance (crank counterweights: B [N], M [N·m], tau [rad]).
    beam_inertia : float
        I_b [kg·m²] about the saddle bearing (:func:`beam_group_inertia`).
    rotary_inertia : float
        I_r [kg·m²] about the crank shaft (:func:`crank_group_inertia`).
    crank_speed, crank_acceleration : ndarray or float
        Crank speed [1/s] and acceleration [1/s²] in the direction of rotation.

    Returns
    -------
    TorqueComponents
        rod_load TF W, structural -TF B, counterbalance -M sin(theta + tau),
        articulating_inertia (TF/A) I_b (psi'' omega² + psi' alpha), rotary_inertia I_r alpha [N·m].

    References
    ----------
    [Takacs2016]; [API11E]; virtual work for the reduction of inertia ([Artobolevsky1951]).
    """
    theta = np.asarray(crank_angle, dtype=float)
    w = np.asarray(rod_load, dtype=float)
    shape = np.broadcast_shapes(theta.shape, w.shape, np.shape(crank_speed), np.shape(crank_acceleration))
    crank_speed = np.broadcast_to(np.asarray(crank_speed, dtype=float), shape)
    crank_acceleration = np.broadcast_to(np.asarray(crank_acceleration, dtype=float), shape)
    _finite("torque components", theta, w, crank_speed, crank_acceleration)
    m = linkage.motion(theta)
    tf = m.torque_factor
    beam_acceleration = m.beam_rate2 * crank_speed**2 + m.beam_rate * crank_acceleration
    return TorqueComponents(
        crank_angle=theta,
        rod_load=tf * w,
        structural=balance.structural_torque(m),
        counterbalance=balance.counterbalance_torque(m),
        articulating_inertia=m.beam_rate * beam_inertia * beam_acceleration,
        rotary_inertia=rotary_inertia * crank_acceleration,
    )


def permissible_load(torque_factor: np.ndarray, counter_torque: np.ndarray,
                     torque_rating: float) -> tuple[np.ndarray, np.ndarray]:
    """Permissible load diagram: the polished-rod loads W_min, W_max [N] that keep |T| <= T_r.

    With T = TF W + T_c, T_c the gearbox torque of the structure and the counterbalance
    (crank counterweights: T_c = -TF B - M sin(theta + tau)), |T| <= T_r gives for TF > 0
    (-T_r - T_c)/TF <= W <= (T_r - T_c)/TF, and the bounds swap where TF < 0
    ([GaultSWPSC], from the definition). Where TF = 0 the load does not reach the gearbox:
    every W is allowed (W_min = -inf, W_max = +inf) if the counterbalance alone keeps
    |T_c| <= T_r, and none (W_min = +inf, W_max = -inf) otherwise. Near TF = 0 the finite
    bounds grow without limit.

    Parameters
    ----------
    torque_factor : ndarray
        TF [m].
    counter_torque : ndarray
        T_c [N·m] at the same crank angles.
    torque_rating : float
        T_r [N·m], > 0: the gearbox rating.

    Returns
    -------
    (ndarray, ndarray)
        W_min and W_max [N].

    References
    ----------
    [GaultSWPSC]; [API11E].

    Examples
    --------
    TF = 2 m, B = 1 kN, M = 30 kN·m at 90 deg (T_c = -2000 - 30 000 N·m), T_r = 50 kN·m:
    1000 + (30 000 -+ 50 000)/2.

    >>> permissible_load(np.array([2.0]), np.array([-32e3]), 50e3)
    (array([-9000.]), array([41000.]))
    """
    tf = np.asarray(torque_factor, dtype=float)
    counter = np.asarray(counter_torque, dtype=float)
    _finite("permissible load", tf, counter)
    if not (np.isfinite(torque_rating) and torque_rating > 0):
        raise TorqueError(f"permissible load: the gearbox rating is {torque_rating!r} N·m; it must be positive")
    zero = tf == 0.0
    safe = np.where(zero, 1.0, tf)
    first = (-torque_rating - counter) / safe
    second = (torque_rating - counter) / safe
    low, high = np.where(tf > 0, first, second), np.where(tf > 0, second, first)
    free = np.abs(counter) <= torque_rating
    low = np.where(zero, np.where(free, -np.inf, np.inf), low)
    high = np.where(zero, np.where(free, np.inf, -np.inf), high)
    return low, high


# --- methods ------------------------------------------------------------------------


def torque_methods() -> tuple[str, ...]:
    """Names of the net-torque methods: ``api`` and ``exact``."""
    return TORQUE_METHODS


def exact_net_torque(spatial: SpatialLinkage, masses: MassModel, crank_angle: np.ndarray, rod_load: np.ndarray,
                     crank_speed: np.ndarray | float = 0.0, crank_acceleration: np.ndarray | float = 0.0) -> np.ndarray:
    """Net gearbox torque [N·m] of the rational spatial mechanism: the balancing torque M_z
    of :func:`.kinetostatics.rational_mechanism` with weights and inertia of every link
    ([Spatial7SK12], [PopovychSenchishak]); omega [1/s], alpha [1/s²] the crank speed and
    acceleration (0: static)."""
    theta = np.asarray(crank_angle, dtype=float)
    load = np.asarray(rod_load, dtype=float)
    _finite("exact net torque", theta, load, np.asarray(crank_speed, dtype=float), np.asarray(crank_acceleration, dtype=float))
    _, reactions = rational_mechanism(spatial, masses, theta, crank_speed, crank_acceleration, load)
    return reactions.net_torque


@dataclass(frozen=True)
class ExactTorqueBasis:
    """The exact net torque of a unit on a crank grid as an affine function of the card.

    The rational mechanism is linear in its loads, and every inertia force and moment of
    a one-degree-of-freedom linkage is a crank-angle function times epsilon plus one times
    omega² (angular velocities scale with omega, so the gyroscopic terms do too). Hence

        M_z(theta) = static + per_load W + per_speed_squared omega² + per_acceleration alpha

    at each crank angle [N·m, N·m/N, N·m s², N·m s²], exactly ([Spatial7SK12],
    [PopovychSenchishak]): four kinetostatic solutions serve every card of the unit.
    """

    crank_angle: np.ndarray
    static: np.ndarray
    per_load: np.ndarray
    per_speed_squared: np.ndarray
    per_acceleration: np.ndarray

    def torque(self, rod_load, crank_speed=0.0, crank_acceleration=0.0) -> np.ndarray:
        """M_z [N·m] for the polished-rod load [N] and crank speed [1/s] and acceleration [1/s²]
        at the basis' crank angles."""
        crank_speed = np.asarray(crank_speed, dtype=float)
        return (self.static + self.per_load * np.asarray(rod_load, dtype=float) + self.per_speed_squared * crank_speed**2
                + self.per_acceleration * np.asarray(crank_acceleration, dtype=float))


def _basis_block(spatial: SpatialLinkage, masses: MassModel, theta: np.ndarray) -> np.ndarray:
    """Balancing torque [N·m] for (W, omega, alpha) = (0, 0, 0), (1 N, 0, 0), (0, 1 1/s, 0),
    (0, 0, 1 1/s²) at ``theta`` [rad], as four rows (one batched kinetostatic solution).

    The motion is solved once, at omega = 1 and alpha = 0: the links' angular velocities are
    omega k_i(theta) and their accelerations alpha k_i + omega² k_i' (the loop equations'
    velocity and acceleration systems share their matrix, and alpha enters the latter as omega
    the former, [Spatial7SK12] eqs. 5-16), so at (0, 1) the accelerations are the velocities at
    (1, 0) and the velocities are zero, and at rest both are zero."""
    n = theta.size
    sm = spatial_motion(spatial, theta, 1.0, 0.0)
    rest = np.zeros((n, 3))
    cases = {}
    for name, value in vars(sm).items():
        if name in _RATES:
            cases[name] = np.concatenate([rest, rest, value, rest])
        elif name in _ACCELERATIONS:
            cases[name] = np.concatenate([rest, rest, value, getattr(sm, "w" + name[1:])])
        else:
            cases[name] = np.concatenate([value] * 4)
    cases["omega1"], cases["epsilon1"] = np.repeat([0.0, 0.0, 1.0, 0.0], n), np.repeat([0.0, 0.0, 0.0, 1.0], n)
    motion = SpatialMotion(**cases)
    loads = applied_loads(spatial, masses, motion, np.repeat([0.0, 1.0, 0.0, 0.0], n))
    return rational_reactions(spatial, motion, loads).net_torque.reshape(4, n)


_RATES = ("w1", "w2", "w3", "w4", "w5")
_ACCELERATIONS = ("e1", "e2", "e3", "e4", "e5")


def exact_torque_basis(spatial: SpatialLinkage, masses: MassModel, crank_angle: np.ndarray) -> ExactTorqueBasis:
    """The four responses of :class:`ExactTorqueBasis` at ``crank_angle`` [rad], a quarter of
    :data:`.kinetostatics.BLOCK` crank angles at a time, so that only the torques of a long
    grid are kept, not its motion and reactions."""
    theta = np.asarray(crank_angle, dtype=float)
    _finite("exact torque basis", theta)
    size = kinetostatics.BLOCK // 4
    static, load, speed, acceleration = np.concatenate(
        [_basis_block(spatial, masses, theta[start:start + size]) for start in range(0, max(theta.size, 1), size)],
        axis=1)
    return ExactTorqueBasis(theta, static, load - static, speed - static, acceleration - static)


def net_torque(method: str, spatial: SpatialLinkage, masses: MassModel, crank_angle: np.ndarray,
               rod_load: np.ndarray, crank_speed: np.ndarray | float = 0.0, crank_acceleration: np.ndarray | float = 0.0) -> np.ndarray:
    """Net gearbox torque [N·m] by ``method``: ``api`` (static, B, M, tau from the masses by
    :func:`.counterbalance.counterbalance_from_masses`; omega and alpha unused) or ``exact``
    (:func:`exact_net_torque`)."""
    if method not in TORQUE_METHODS:
        raise TorqueError(f"unknown torque method {method!r}; use one of {', '.join(TORQUE_METHODS)}")
    if method == "exact":
        return exact_net_torque(spatial, masses, crank_angle, rod_load, crank_speed, crank_acceleration)
    linkage = spatial.planar
    return api_net_torque(crank_angle, linkage.torque_factor(crank_angle), np.asarray(rod_load, dtype=float),
                          counterbalance_from_masses(linkage, masses))


@dataclass(frozen=True)
class MethodComparison:
    """Net gearbox torque [N·m] by both methods at ``crank_angle`` [rad], and the B, M, tau the API one used."""

    crank_angle: np.ndarray
    api: np.ndarray
    exact: np.ndarray
    balance: Counterbalance


def compare_methods(spatial: SpatialLinkage, masses: MassModel, crank_angle: np.ndarray, rod_load: np.ndarray,
                    crank_speed: np.ndarray | float = 0.0, crank_acceleration: np.ndarray | float = 0.0) -> MethodComparison:
    """Both methods side by side; their difference is the beam group's weight off level
    (cos psi), the pitmans' weight shared with the crank pins, and (omega, alpha != 0) inertia."""
    theta = np.asarray(crank_angle, dtype=float)
    return MethodComparison(theta, net_torque("api", spatial, masses, theta, rod_load),
                            net_torque("exact", spatial, masses, theta, rod_load, crank_speed, crank_acceleration),
                            counterbalance_from_masses(spatial.planar, masses))
