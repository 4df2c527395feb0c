"""The real mechanism with redundant constraints against the rational one (issue 6).

Independent checks: the equilibrium matrix of all 28 unknowns and its self-stress
states are assembled here; the pitmans' complementary energy is integrated here on a
fine grid (not Simpson's rule) and differentiated numerically; compatibility
(Menabrea) must then hold for every self-stress state.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import scipy.linalg

from pumpjack_cli.analysis.card_runs import place
from pumpjack_cli.config import Deviations, load_unit
from pumpjack_cli.core.beam import redundancy
from pumpjack_cli.core.beam.card import card_load
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.core.beam.kinetostatics import applied_loads, rational_mechanism
from pumpjack_cli.core.beam.redundancy import PinTilts, real_mechanism
from pumpjack_cli.core.beam.spatial import spatial_motion
from pumpjack_cli.readers.cards import read_card

from helpers import REPO_ROOT, sample_card

from pumpjack_cli.core.constants import STANDARD_GRAVITY

UNIT = "7sk12-2.5-5600"
OMEGA = 8 * np.pi / 30


@pytest.fixture(scope="module")
def setup():
    config = load_unit(UNIT)
    ideal = config.geometry.spatial()
    theta = crank_grid(72)
    card = place(read_card(sample_card(UNIT)), ideal.planar).card
    return config, ideal, config.masses.model(), config.pitman_section.model(), theta, card_load(card, theta)


#: One deviation at a time, each of a size found on worn units (mm, tenths of a degree, mrad).
CASES = {
    "crank_phase": (dict(crank_phase_offset=np.radians(0.2)), PinTilts()),
    "crank_radius": (dict(crank_radius_offset=0.002), PinTilts()),
    "pitman_length": (dict(pitman_length_offset=0.002), PinTilts()),
    "crank_pin_radial": ({}, PinTilts(crank_pin_radial=1e-3)),
    "crank_pin_tangential": ({}, PinTilts(crank_pin_tangential=1e-3)),
    "equalizer_pin_roll": ({}, PinTilts(equalizer_pin_roll=1e-3)),
    "equalizer_pin_yaw": ({}, PinTilts(equalizer_pin_yaw=1e-3)),
}


def run(setup, scale=1.0, case=None):
    config, ideal, masses, section, theta, load = setup
    offsets, tilts = CASES[case] if case else ({}, PinTilts())
    actual = dataclasses.replace(ideal, **{k: scale * v for k, v in offsets.items()})
    tilts = PinTilts(**{f.name: scale * getattr(tilts, f.name) for f in dataclasses.fields(PinTilts)})
    return real_mechanism(ideal, actual, tilts, section, masses, theta, OMEGA, 0.0, load)


def test_no_errors_real_equals_rational(setup):
    """Zero deviations: no misfit, no self-stress; every reaction and M_z as in the
    rational mechanism to 1e-9 of the largest load, and R12 = R13."""
    config, ideal, masses, section, theta, load = setup
    _, rational = rational_mechanism(ideal, masses, theta, OMEGA, 0.0, load)
    _, joints, real = run(setup)
    scale = np.max(load)
    for name in ("r12", "r13", "r24", "r34", "r45", "r05", "r01", "m05", "m01"):
        assert np.max(np.abs(getattr(real, name) - getattr(rational, name))) < 1e-9 * scale, name
    assert np.max(np.abs(real.net_torque - rational.net_torque)) < 1e-9 * scale
    assert np.max(np.abs(real.r12 - real.r13)) < 1e-9 * scale
    for name in ("m12", "m13", "m24", "m34"):
        assert np.max(np.abs(getattr(joints, name))) < 1e-9 * scale


@pytest.mark.parametrize("case", CASES)
def test_small_errors_act_linearly_and_keep_equilibrium(setup, case):
    """Linear elasticity about the rational motion: halving a small deviation halves
    every difference from the rational mechanism (to 1 %: the deviation also moves the
    geometry, a second-order effect); the 28-unknown equilibrium holds to 1e-9."""
    config, ideal, masses, section, theta, load = setup
    _, rational = rational_mechanism(ideal, masses, theta, OMEGA, 0.0, load)
    _, _, full = run(setup, 1.0, case)
    _, _, half = run(setup, 0.5, case)
    d_full = full.r12 - rational.r12
    d_half = half.r12 - rational.r12
    assert np.max(np.abs(d_full)) > 10.0  # the deviation does load the joints
    assert np.max(np.abs(d_full - 2 * d_half)) < 0.01 * np.max(np.abs(d_full))
    assert full.residual.max() < 1e-9 and half.residual.max() < 1e-9


def skew(v):
    x, y, z = v
    return np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])


@pytest.mark.parametrize("stiffness", [None, (3e6, 2.5e7)], ids=["rigid pins", "elastic pins"])
def test_compatibility_every_self_stress_state(setup, stiffness):
    """Menabrea with misfit: for every self-stress state s (null space of the 24 x 28
    equilibrium matrix, assembled here), dU*/dX . s = (misfit work) . s, with U* the
    pitmans' complementary energy integrated here on 4000 intervals per pitman, plus, with
    elastic pins (rotational springs in series), sum M^2 / 2k over the joint moments."""
    config, ideal, masses, section, theta, load = setup
    k = 7  # one crank angle is enough for this independent check
    actual = dataclasses.replace(ideal, pitman_length_offset=0.002, crank_phase_offset=np.radians(0.1))
    tilts = PinTilts(crank_pin_radial=5e-4, equalizer_pin_roll=-5e-4)
    pins = redundancy.JointCompliance() if stiffness is None else redundancy.JointCompliance(*stiffness)
    sm_all, joints, real = real_mechanism(ideal, actual, tilts, section, masses, theta, OMEGA, 0.0, load,
                                          joints=pins)
    loads = applied_loads(actual, masses, sm_all, load)
    a2, u2, a3, u3 = redundancy.pin_axes(actual, sm_all, tilts)
    p = {name: getattr(sm_all, name)[k] for name in ("pin_a", "pin_a1", "pin_b", "pin_b1", "pin_d")}

    def basis(axis):
        q1 = np.cross(axis, [0.0, 1.0, 0.0])
        q1 /= np.linalg.norm(q1)
        return np.stack([q1, np.cross(axis, q1)], axis=1)

    bases = {"m12": basis(a2[k]), "m24": basis(u2[k]), "m13": basis(a3[k]), "m34": basis(u3[k])}
    cols = {"r12": 0, "r13": 3, "r24": 6, "r34": 9, "r45": 12, "r05": 15, "m05": 18,
            "m12": 20, "m13": 22, "m24": 24, "m34": 26}
    e = np.zeros((24, 28))

    def force(link, name, sign, point):
        e[6 * link:6 * link + 3, cols[name]:cols[name] + 3] += sign * np.eye(3)
        e[6 * link + 3:6 * link + 6, cols[name]:cols[name] + 3] += sign * skew(point)

    def couple(link, name, sign):
        e[6 * link + 3:6 * link + 6, cols[name]:cols[name] + 2] += sign * bases[name]

    force(0, "r12", 1, p["pin_a"]); force(0, "r24", -1, p["pin_b"]); couple(0, "m12", 1); couple(0, "m24", -1)
    force(1, "r13", 1, p["pin_a1"]); force(1, "r34", -1, p["pin_b1"]); couple(1, "m13", 1); couple(1, "m34", -1)
    force(2, "r24", 1, p["pin_b"]); force(2, "r34", 1, p["pin_b1"]); force(2, "r45", -1, p["pin_d"])
    couple(2, "m24", 1); couple(2, "m34", 1)
    force(3, "r45", 1, p["pin_d"]); force(3, "r05", 1, np.zeros(3))
    e[21, 18] = e[22, 19] = 1.0
    selfstress = scipy.linalg.null_space(e, rcond=1e-10)
    assert selfstress.shape[1] in (4, 5)  # the redundancy of the real mechanism

    x = np.concatenate([real.r12[k], real.r13[k], real.r24[k], real.r34[k], real.r45[k], real.r05[k],
                        real.m05[k, :2]] + [bases[n].T @ getattr(joints, n)[k] for n in ("m12", "m13", "m24", "m34")])

    def energy(xv):
        total = 0.0
        for pin, top, fc, mc, link in (("pin_a", "pin_b", "r12", "m12", loads.pitman2),
                                       ("pin_a1", "pin_b1", "r13", "m13", loads.pitman3)):
            a, b = p[pin], p[top]
            n = (b - a) / np.linalg.norm(b - a)
            c = np.array([0.0, 0.0, 1.0]) - n[2] * n
            c /= np.linalg.norm(c)
            t = np.cross(n, c)
            f_a, m_a = xv[cols[fc]:cols[fc] + 3], bases[mc] @ xv[cols[mc]:cols[mc] + 2]
            f_s, s_pt, m_s = link.forces[k, 0], link.points[k, 0], link.moment[k]
            x_s = (s_pt - a) @ n
            xs = np.linspace(0.0, np.linalg.norm(b - a), 4001)
            cut = a + xs[:, None] * n  # the cuts along the pitman, one row each
            loaded = (xs > x_s)[:, None] * 1.0
            f = -f_a - loaded * f_s
            m = -m_a - np.cross(a - cut, f_a) - loaded * (m_s + np.cross(s_pt - cut, f_s))
            vals = ((f @ n) ** 2 / (section.youngs_modulus * section.area)
                    + (m @ n) ** 2 / (section.shear_modulus * section.torsion_constant)
                    + (m @ c) ** 2 / (section.youngs_modulus * section.inplane_inertia)
                    + (m @ t) ** 2 / (section.youngs_modulus * section.outofplane_inertia))
            total += 0.5 * np.trapezoid(vals, xs)
        for name, spring in (("m12", pins.crank_pin_stiffness), ("m13", pins.crank_pin_stiffness),
                             ("m24", pins.equalizer_pin_stiffness), ("m34", pins.equalizer_pin_stiffness)):
            total += 0.5 * np.sum(xv[cols[name]:cols[name] + 2] ** 2) / spring
        return total

    gradient = np.array([(energy(x + h * s) - energy(x - h * s)) / (2 * h)
                         for s, h in ((col, 1e-3 * np.max(np.abs(x))) for col in selfstress.T)])
    ideal_motion = spatial_motion(ideal, theta[k:k + 1], OMEGA)
    one = spatial_motion(actual, theta[k:k + 1], OMEGA)
    work = np.zeros(28)
    for pin, top, mp, mt, axes in (("pin_a", "pin_b", "m12", "m24", (a2, u2)), ("pin_a1", "pin_b1", "m13", "m34", (a3, u3))):
        mu_a, mu_b = redundancy._misfit(ideal_motion, one, pin, top, axes[0][k:k + 1], axes[1][k:k + 1])
        work[cols[mp]:cols[mp] + 2] = bases[mp].T @ mu_a[0]
        work[cols[mt]:cols[mt] + 2] = -bases[mt].T @ mu_b[0]
    expected = selfstress.T @ work
    # Trapezoid on 4000 intervals with a kink at the centre of mass: relative error ~1e-4.
    assert np.allclose(gradient, expected, rtol=0, atol=2e-3 * np.max(np.abs(expected)))


def test_misfit_of_a_tilted_equalizer_pin_is_the_tilt():
    """Pin B1 bore turned by 1 mrad about the beam axis, nothing else: pitman 3's end B
    must turn by 1 mrad relative to its chord, its end A not at all."""
    ideal = load_unit(UNIT).geometry.spatial()
    theta = crank_grid(12)
    sm = spatial_motion(ideal, theta, OMEGA)
    _, _, a3, u3 = redundancy.pin_axes(ideal, sm, PinTilts(equalizer_pin_roll=1e-3))
    mu_a, mu_b = redundancy._misfit(sm, sm, "pin_a1", "pin_b1", a3, u3)
    assert np.allclose(np.linalg.norm(mu_b, axis=-1), np.sin(1e-3), rtol=1e-9)
    assert np.max(np.abs(mu_a)) < 1e-15


def test_config_deviations_and_bounds():
    config = load_unit(UNIT)
    assert config.deviations == Deviations()
    with pytest.raises(ValueError):
        Deviations(pitman_length="80 cm")


@pytest.mark.parametrize("field", ["youngs_modulus", "shear_modulus", "area", "inplane_inertia",
                                   "outofplane_inertia", "torsion_constant"])
def test_negative_stiffness_is_rejected(field):
    import tomllib

    from pumpjack_cli.config import parse_unit
    from pumpjack_cli.errors import ConfigError

    data = tomllib.loads((REPO_ROOT / "configs" / f"{UNIT}.toml").read_text())
    data["pitman_section"][field] = -1.0
    with pytest.raises(ConfigError, match=rf"x.toml: pitman_section.{field}: Input should be greater than 0"):
        parse_unit(data, "x.toml")


# --- like with like ([Spatial7SK12] compares the mechanisms with the same errors) -----------

def _same_errors(setup, case: str, scale: float):
    """Real minus rational M_z and R12y - R13y, both on the erroneous geometry."""
    config, ideal, masses, section, theta, load = setup
    offsets, tilts = CASES[case]
    actual = dataclasses.replace(ideal, **{k: scale * v for k, v in offsets.items()})
    tilts = PinTilts(**{f.name: scale * getattr(tilts, f.name) for f in dataclasses.fields(PinTilts)})
    _, _, real = real_mechanism(ideal, actual, tilts, section, masses, theta, OMEGA, 0.0, load)
    _, rational = rational_mechanism(actual, masses, theta, OMEGA, 0.0, load)
    return real.net_torque - rational.net_torque, real.r12[:, 1] - real.r13[:, 1]


@pytest.mark.parametrize("case", ["crank_phase", "crank_radius", "pitman_length", "equalizer_pin_roll"])
def test_self_stress_changes_the_torque_at_second_order_and_the_split_at_first(setup, case):
    """By virtual work the self-stress of the redundant constraints can change M_z only at
    second order in the error (its power is the rate of the pitmans' elastic energy, which
    is quadratic), while the force split is first order: doubling the error quadruples
    real - rational M_z (within 5 %) and doubles R12y - R13y."""
    torque_1, split_1 = _same_errors(setup, case, 1.0)
    torque_2, split_2 = _same_errors(setup, case, 2.0)
    if case != "equalizer_pin_roll":  # a roll of pin B1 leaves M_z unchanged to round-off (1e-9 N·m)
        assert np.max(np.abs(torque_2)) == pytest.approx(4.0 * np.max(np.abs(torque_1)), rel=0.05)
    assert np.max(np.abs(split_2)) == pytest.approx(2.0 * np.max(np.abs(split_1)), rel=0.01)


def test_whole_arm_phase_adds_the_turned_arms_gravity_torque(setup):
    """A crank-phase error of the whole arm turns side 3's arm and its counterweights with
    the pin: at uniform speed the gearbox torque gains their gravity torque change
    -g sum m r [sin(theta + phi + phi_i) - sin(theta + phi_i)] (centripetal forces pass
    through the shaft), from the potential energy g m r cos of each point mass."""
    config, ideal, masses, section, theta, load = setup
    phi = np.radians(0.5)
    pin = dataclasses.replace(ideal, crank_phase_offset=phi)
    arm = dataclasses.replace(pin, arm_phase_offset=phi)
    _, by_pin = rational_mechanism(pin, masses, theta, OMEGA, 0.0, load)
    _, by_arm = rational_mechanism(arm, masses, theta, OMEGA, 0.0, load)
    expected = -STANDARD_GRAVITY * (masses.crank_arm_mass * masses.crank_arm_cg * (np.sin(theta + phi) - np.sin(theta))
                     + 0.5 * masses.counterweight_mass * masses.counterweight_radius
                     * (np.sin(theta + phi + masses.counterweight_phase) - np.sin(theta + masses.counterweight_phase)))
    assert np.max(np.abs(by_arm.net_torque - by_pin.net_torque - expected)) < 1e-9 * np.max(
        np.abs(by_pin.net_torque))
    assert np.max(np.abs(expected)) > 50.0  # N·m: the 0.5 deg of 4 x 840 kg at 1 m matters


# --- joint compliance and clearance ------------------------------------------------------

def _split(setup, offsets, tilts=PinTilts(), joints=redundancy.JointCompliance()):
    config, ideal, masses, section, theta, load = setup
    actual = dataclasses.replace(ideal, **offsets)
    _, moments, real = real_mechanism(ideal, actual, tilts, section, masses, theta, OMEGA, 0.0, load, joints=joints)
    return np.max(np.abs(real.r12[:, 1] - real.r13[:, 1])), moments, real


def test_stiff_joints_tend_to_the_rigid_ones_and_soft_joints_relieve_the_split(setup):
    offsets = {"crank_phase_offset": np.radians(0.1)}
    rigid, _, _ = _split(setup, offsets)
    stiff, _, _ = _split(setup, offsets, joints=redundancy.JointCompliance(1e16, 1e16))
    assert stiff == pytest.approx(rigid, rel=1e-6)
    previous = rigid
    for k in (2.5e7, 5e6, 2e6):  # softer and softer springs in series: less self-stress
        found, _, _ = _split(setup, offsets, joints=redundancy.JointCompliance(k, k))
        assert found < previous
        previous = found


@pytest.mark.parametrize("offsets", [{"crank_phase_offset": np.radians(0.1)}, {"pitman_length_offset": 0.002}],
                         ids=["crank phase", "pitman length"])
def test_clearance_is_a_dead_band(setup, offsets):
    """Below the error that closes the play there is no self-stress (the real mechanism is the
    rational one with the same error); above it the split grows continuously from zero and
    tends to the rigid split less a constant; every crank angle satisfies equilibrium,
    compatibility and the contact conditions."""
    config, ideal, masses, section, theta, load = setup
    rigid, _, _ = _split(setup, offsets)
    splits = []
    for scale in (0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 4.0):
        scaled = {key: scale * value for key, value in offsets.items()}
        found, moments, real = _split(setup, scaled, joints=redundancy.JointCompliance(
            crank_pin_clearance=1e-3, equalizer_pin_clearance=1e-3))
        assert real.residual.max() < 1e-9
        assert moments.contact.compatibility_residual.max() < 1e-9
        assert moments.contact.contact_residual.max() < 1e-5
        splits.append(found)
        if scale == 0.02:
            inside = real
    _, rational = rational_mechanism(dataclasses.replace(ideal, **{k: 0.02 * v for k, v in offsets.items()}), masses,
                                     theta, OMEGA, 0.0, load)
    assert np.max(np.abs(inside.r12 - rational.r12)) < 1e-3 * rigid  # inside the play: the rational mechanism
    assert splits[0] < 1e-3 * rigid  # inside the play: no self-stress
    assert np.all(np.diff(splits) >= -1e-6 * rigid)  # continuous, monotonic growth
    assert splits[-1] > 2.0 * rigid  # far beyond the play: the constraint works again
    assert 4.0 * rigid - splits[-1] < 4.0 * rigid * 0.5  # less a constant: the play taken up


def test_zero_clearance_and_rigid_pins_give_unchanged_results(setup):
    offsets = {"crank_phase_offset": np.radians(0.1), "crank_radius_offset": 1e-3}
    _, base_moments, base = _split(setup, offsets)
    _, moments, same = _split(setup, offsets, joints=redundancy.JointCompliance(np.inf, np.inf, 0.0, 0.0))
    assert np.array_equal(same.r12, base.r12) and np.array_equal(same.net_torque, base.net_torque)
    assert np.all(moments.contact.iterations == 1)
