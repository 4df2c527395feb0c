"""Spatial kinematics and kinetostatics of the rational mechanism (issue 3).

The checks are independent of the solver: an energy balance built from positions by
finite differences (virtual work), the [API11E] torque-factor method for massless
links, the planar closed form for the spatial kinematics, and the gravity torque of
counterweights. The mirror symmetry of identical sides ([Spatial7SK12], fig. 10) is checked
in tests/validation/test_spatial7sk12.py.
"""

from __future__ import annotations

import dataclasses
import tomllib

import numpy as np
import pytest

from pumpjack_cli.config import load_unit, parse_unit
from pumpjack_cli.core.beam.kinetostatics import applied_loads, rational_mechanism, rational_reactions
from pumpjack_cli.core.beam.masses import MassModel
from pumpjack_cli.core.constants import STANDARD_GRAVITY
from pumpjack_cli.core.beam.linkage import motion
from pumpjack_cli.core.beam.spatial import SpatialLinkage, spatial_motion
from pumpjack_cli.errors import ConfigError

from helpers import BEAM_UNITS, REPO_ROOT


def unit(name: str):
    config = load_unit(name)
    return config.geometry.spatial(name), config.masses.model()


def rod_load(theta: np.ndarray) -> np.ndarray:
    """A smooth card-like load [N]: mean 50 kN with a first and second harmonic."""
    return 50e3 + 15e3 * np.sin(theta) + 5e3 * np.cos(2 * theta)


# --- independent energy bookkeeping --------------------------------------------------


def mass_points(spatial: SpatialLinkage, m: MassModel, theta: np.ndarray):
    """Positions (N, 3) of every centre of mass and its mass, built here from the geometry."""
    lk = spatial.planar
    b, e = spatial.crank_half_spacing, spatial.equalizer_half_length
    o = np.array([-lk.horizontal_offset, -lk.vertical_offset])
    pin_dir = np.stack([lk.rotation * np.sin(theta), np.cos(theta)], axis=-1)
    cw_dir = np.stack([lk.rotation * np.sin(theta + m.counterweight_phase), np.cos(theta + m.counterweight_phase)], axis=-1)
    psi = motion(lk, theta).beam_angle
    line = np.stack([np.cos(psi), np.sin(psi)], axis=-1)

    def xyz(xy, z):
        return np.concatenate([xy, np.full((theta.size, 1), z)], axis=-1)

    a_xy = o + lk.crank_radius * pin_dir
    d_xy = -lk.rear_arm * line
    points = []
    for z in (b, -b):
        points.append((m.crank_arm_mass, xyz(o + m.crank_arm_cg * pin_dir, z)))
        points.append((0.5 * m.counterweight_mass, xyz(o + m.counterweight_radius * cw_dir, z)))
    for zb, ze in ((b, e), (-b, -e)):
        a, top = xyz(a_xy, zb), xyz(d_xy, ze)
        points.append((m.pitman_mass, a + m.pitman_cg / spatial.pitman * (top - a)))
    points.append((m.equalizer_mass, xyz(d_xy, 0.0)))
    points.append((m.beam_mass, xyz(m.beam_cg * line, 0.0)))
    points.append((m.horsehead_mass, xyz(m.horsehead_cg * line, 0.0)))
    pitman_dirs = [xyz(d_xy, ze) - xyz(a_xy, zb) for zb, ze in ((b, e), (-b, -e))]
    return points, psi, pitman_dirs


def energies(spatial, m, theta, h):
    """Kinetic energy at unit crank speed (T/omega^2 = I_red/2) and potential energy, by
    central differences of positions in crank angle (step h)."""
    (pts_p, psi_p, dirs_p), (pts_m, psi_m, dirs_m), (pts_0, _, _) = (
        mass_points(spatial, m, theta + h), mass_points(spatial, m, theta - h), mass_points(spatial, m, theta))
    t_unit = 0.5 * 2 * m.crank_arm_inertia * np.ones_like(theta)
    for (mass, p_plus), (_, p_minus) in zip(pts_p, pts_m):
        t_unit += 0.5 * mass * np.sum(((p_plus - p_minus) / (2 * h)) ** 2, axis=-1)
    beam_rate = (psi_p - psi_m) / (2 * h)
    t_unit += 0.5 * (m.beam_inertia + m.horsehead_inertia + m.equalizer_inertia) * beam_rate**2
    for d_plus, d_minus in zip(dirs_p, dirs_m):
        n_plus = d_plus / np.linalg.norm(d_plus, axis=-1, keepdims=True)
        n_minus = d_minus / np.linalg.norm(d_minus, axis=-1, keepdims=True)
        # spin-free pitman: |w|^2 = |dn/dt|^2
        t_unit += 0.5 * m.pitman_inertia * np.sum(((n_plus - n_minus) / (2 * h)) ** 2, axis=-1)
    potential = sum(mass * STANDARD_GRAVITY * p[:, 1] for mass, p in pts_0)
    return t_unit, potential


@pytest.mark.parametrize("name", BEAM_UNITS)
@pytest.mark.parametrize("epsilon", [0.0, 0.3])
def test_virtual_work(name, epsilon):
    """M_z omega = dT/dt + dV/dt + F v_E at every crank angle (power balance, d'Alembert).

    With T = I_red(theta) omega^2 / 2: dT/dt = I_red omega eps + I_red' omega^3 / 2,
    dV/dt = V' omega, F v_E = F A psi' omega. I_red, V and psi are differentiated here
    by central differences (h = 1e-4, outer step 1e-3): truncation ~1e-8 relative."""
    spatial, m = unit(name)
    theta = np.linspace(0, 2 * np.pi, 73, endpoint=False)
    omega = 1.1
    load = rod_load(theta)
    _, r = rational_mechanism(spatial, m, theta, omega, epsilon, load)
    h, h2 = 1e-3, 1e-4
    t_p, v_p = energies(spatial, m, theta + h, h2)
    t_m, v_m = energies(spatial, m, theta - h, h2)
    t_0, _ = energies(spatial, m, theta, h2)
    i_red, di_red = 2 * t_0, (t_p - t_m) / h
    dv = (v_p - v_m) / (2 * h)
    lk = spatial.planar
    psi_rate = motion(lk, theta).beam_rate
    power = i_red * omega * epsilon + 0.5 * di_red * omega**3 + dv * omega + load * lk.front_arm * psi_rate * omega
    scale = np.max(np.abs(power))
    assert np.max(np.abs(r.net_torque * omega - power)) < 1e-6 * scale


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_massless_links_give_the_api_torque_factor_method(name):
    """With massless links M_z = TF x load ([API11E]), to 1e-9 relative."""
    spatial, m = unit(name)
    massless = MassModel(**{f.name: 0.0 for f in dataclasses.fields(MassModel)})
    theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    load = rod_load(theta)
    _, r = rational_mechanism(spatial, massless, theta, 1.0, 0.0, load)
    tf = spatial.planar.front_arm * motion(spatial.planar, theta).beam_rate
    expected = tf * load
    assert np.max(np.abs(r.net_torque - expected)) < 1e-9 * np.max(np.abs(expected))


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_every_link_is_in_equilibrium(name):
    """Force and moment residual of each link (reactions + applied loads) below 1e-9 of the largest load."""
    spatial, m = unit(name)
    theta = np.linspace(0, 2 * np.pi, 90, endpoint=False)
    sm = spatial_motion(spatial, theta, 1.1, 0.2)
    loads = applied_loads(spatial, m, sm, rod_load(theta))
    r = rational_reactions(spatial, sm, loads)
    origin = np.zeros_like(sm.pin_a)
    links = {
        "pitman 2": (loads.pitman2, [(r.r12, sm.pin_a), (-r.r24, sm.pin_b)], 0.0),
        "pitman 3": (loads.pitman3, [(r.r13, sm.pin_a1), (-r.r34, sm.pin_b1)], 0.0),
        "equalizer": (loads.equalizer, [(r.r24, sm.pin_b), (r.r34, sm.pin_b1), (-r.r45, sm.pin_d)], 0.0),
        "beam": (loads.beam, [(r.r45, sm.pin_d), (r.r05, origin)], r.m05),
        "crank": (loads.crank, [(-r.r12, sm.pin_a), (-r.r13, sm.pin_a1), (r.r01, sm.crank_shaft)],
                  r.m01 + r.net_torque[:, None] * spatial.crank_spin),
    }
    scale = np.max(rod_load(theta))
    for link, (applied, reactions, couple) in links.items():
        force = applied.resultant() + sum(f for f, _ in reactions)
        moment = applied.moment_about_origin() + sum(np.cross(p, f) for f, p in reactions) + couple
        assert np.max(np.abs(force)) < 1e-9 * scale, link
        assert np.max(np.abs(moment)) < 1e-9 * scale * 10.0, link  # moments: lever arms up to ~10 m


def test_counterweight_gravity_torque():
    """Uniform rotation: point counterweights on a circle exert no inertia torque, and
    their weight helps the gearbox by m g r sin(theta + phase) (phase 0: in line with
    the pin), so removing them raises M_z by exactly that."""
    spatial, m = unit("sk8-3.5-4000")
    theta = np.linspace(0, 2 * np.pi, 120, endpoint=False)
    load = rod_load(theta)
    _, with_cw = rational_mechanism(spatial, m, theta, 1.1, 0.0, load)
    _, without = rational_mechanism(spatial, dataclasses.replace(m, counterweight_mass=0.0), theta, 1.1, 0.0, load)
    expected = m.counterweight_mass * STANDARD_GRAVITY * m.counterweight_radius * np.sin(theta + m.counterweight_phase)
    assert np.max(np.abs((without.net_torque - with_cw.net_torque) - expected)) < 1e-9 * np.max(expected)


def test_switches_separate_contributions():
    """Weights and inertia are additive: M_z(all) = M_z(no inertia) + M_z(no weights) - M_z(neither)."""
    spatial, m = unit("sk8-3.5-4000")
    theta = np.linspace(0, 2 * np.pi, 90, endpoint=False)
    load = rod_load(theta)

    def torque(**kw):
        return rational_mechanism(spatial, m, theta, 1.1, 0.05, load, **kw)[1].net_torque

    combined = torque(inertia=False) + torque(weights=False) - torque(weights=False, inertia=False)
    assert np.allclose(torque(), combined, rtol=0, atol=1e-9 * np.max(load))
    # Without weights and inertia only the rod load remains: the torque-factor method.
    tf = spatial.planar.front_arm * motion(spatial.planar, theta).beam_rate
    assert np.allclose(torque(weights=False, inertia=False), tf * load, rtol=0, atol=1e-9 * np.max(load))


# --- spatial kinematics ------------------------------------------------------------


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_spatial_kinematics_reproduce_the_planar_motion(name):
    """Both sides equal: beam and pitman rotate about z exactly as the planar four-bar says."""
    spatial, _ = unit(name)
    theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    omega, eps = 1.3, 0.4
    sm = spatial_motion(spatial, theta, omega, eps)
    planar = motion(spatial.planar, theta)
    assert np.allclose(sm.w5[:, 2], planar.beam_rate * omega, rtol=0, atol=1e-12)
    assert np.allclose(sm.e5[:, 2], planar.beam_rate2 * omega**2 + planar.beam_rate * eps, rtol=0, atol=1e-12)
    assert np.allclose(sm.w2[:, 2], planar.pitman_rate * omega, rtol=0, atol=1e-12)
    assert np.allclose(sm.e2[:, 2], planar.pitman_rate2 * omega**2 + planar.pitman_rate * eps, rtol=0, atol=1e-12)
    assert np.allclose(sm.w2, sm.w3, rtol=0, atol=1e-12)
    assert np.allclose(sm.w4, sm.w5, rtol=0, atol=1e-12)
    assert np.allclose(sm.e4, sm.e5, rtol=0, atol=1e-12)
    # The polished rod: v_E = A w5z, the planar suspension-point velocity.
    assert np.allclose(spatial.planar.front_arm * sm.w5[:, 2],
                       spatial.planar.front_arm * planar.beam_rate * omega, rtol=0, atol=1e-12)


def test_leaning_pitmans_bour_formula():
    """Crank pins and equalizer pins spaced differently: every loop vector's derivative
    is w x l (Bour's formula), checked against finite differences of the positions, and
    the pitmans do not spin about their own axes."""
    config = load_unit("sk8-3.5-4000")
    geometry = config.geometry.model_copy(update={"equalizer_half_length": 0.6})
    spatial = geometry.spatial()
    assert spatial.pitman == pytest.approx(3.0, rel=1e-15)
    theta = np.linspace(0, 2 * np.pi, 48, endpoint=False)
    omega, h = 0.9, 1e-6
    sm, sp, sn = (spatial_motion(spatial, theta + d, omega) for d in (0.0, h, -h))
    dt = 2 * h / omega
    for w, top, pin in ((sm.w2, "pin_b", "pin_a"), (sm.w3, "pin_b1", "pin_a1")):
        vec = getattr(sm, top) - getattr(sm, pin)
        rate = ((getattr(sp, top) - getattr(sp, pin)) - (getattr(sn, top) - getattr(sn, pin))) / dt
        assert np.allclose(np.cross(w, vec), rate, rtol=0, atol=1e-7)
        assert np.allclose(np.sum(w * vec, axis=-1), 0.0, atol=1e-12)
        assert np.allclose(np.linalg.norm(vec, axis=-1), 3.0, rtol=1e-12)
    d_rate = (sp.pin_d - sn.pin_d) / dt
    assert np.allclose(np.cross(sm.w5, sm.pin_d), d_rate, rtol=0, atol=1e-7)
    # Angular accelerations are the time derivatives of the angular velocities.
    for name in ("w2", "w5"):
        rate = (getattr(spatial_motion(spatial, theta + h, omega), name)
                - getattr(spatial_motion(spatial, theta - h, omega), name)) / dt
        assert np.allclose(getattr(sm, "e" + name[1]), rate, rtol=0, atol=1e-6)


def test_geometry_rejects_pitman_shorter_than_its_lean():
    data = tomllib.loads((REPO_ROOT / "configs" / "sk8-3.5-4000.toml").read_text())
    data["geometry"]["crank_half_spacing"] = "4 m"
    with pytest.raises(ConfigError, match=r"geometry: pitman .* shorter than the offset"):
        parse_unit(data, "x.toml")


def skew(v: np.ndarray) -> np.ndarray:
    x, y, z = v
    return np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])


@pytest.mark.parametrize("name", BEAM_UNITS)
def test_full_group_system_has_rank_20_and_the_solution_satisfies_it(name):
    """Assemble all 24 equilibrium equations of the group 2-3-4-5 (forces, and moments
    about C, for links 2, 3, 4, 5) in the 20 unknowns R12, R13, R24, R34, R45, R05,
    M_R05x, M_R05y, here in the test, independently of the solver's block elimination:
    the matrix has full column rank (the rational mechanism is statically determinate,
    4 rows dependent: its idle freedoms) and the solver's reactions satisfy it."""
    spatial, m = unit(name)
    theta = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    sm = spatial_motion(spatial, theta, 1.1, 0.2)
    loads = applied_loads(spatial, m, sm, rod_load(theta))
    r = rational_reactions(spatial, sm, loads)
    col = {name: 3 * i for i, name in enumerate(("r12", "r13", "r24", "r34", "r45", "r05"))}
    for k in range(theta.size):
        e = np.zeros((24, 20))

        def add(link, unknown, sign, point):
            rows, c = 6 * link, col[unknown]
            e[rows:rows + 3, c:c + 3] += sign * np.eye(3)
            e[rows + 3:rows + 6, c:c + 3] += sign * skew(point)

        add(0, "r12", 1, sm.pin_a[k]); add(0, "r24", -1, sm.pin_b[k])
        add(1, "r13", 1, sm.pin_a1[k]); add(1, "r34", -1, sm.pin_b1[k])
        add(2, "r24", 1, sm.pin_b[k]); add(2, "r34", 1, sm.pin_b1[k]); add(2, "r45", -1, sm.pin_d[k])
        add(3, "r45", 1, sm.pin_d[k]); add(3, "r05", 1, np.zeros(3))
        e[21, 18] = e[22, 19] = 1.0
        f = -np.concatenate([np.concatenate([link.resultant()[k], link.moment_about_origin()[k]])
                             for link in (loads.pitman2, loads.pitman3, loads.equalizer, loads.beam)])
        x = np.concatenate([r.r12[k], r.r13[k], r.r24[k], r.r34[k], r.r45[k], r.r05[k], r.m05[k, :2]])
        assert np.linalg.matrix_rank(e) == 20
        assert np.max(np.abs(e @ x - f)) < 1e-9 * np.max(np.abs(f))
        # and the least-squares solution of the full system is the same
        assert np.allclose(np.linalg.lstsq(e, f, rcond=None)[0], x, rtol=0, atol=1e-7 * np.max(np.abs(f)))


def test_sides_with_deviations_close_both_loops_and_differentiate_consistently():
    """Crank phase, crank radius and pitman length differing between the sides: the
    Newton position solve closes both loops, and the angular velocities and
    accelerations of every link are the time derivatives of the positions and of each
    other (finite differences), so the kinematics of unequal sides are consistent."""
    base = load_unit("7sk12-2.5-5600").geometry.spatial()
    spatial = dataclasses.replace(base, crank_phase_offset=np.radians(0.5), crank_radius_offset=0.003,
                                  pitman_length_offset=0.004)
    theta = np.linspace(0, 2 * np.pi, 36, endpoint=False)
    omega, h = 0.9, 1e-6
    sm, sp, sn = (spatial_motion(spatial, theta + d, omega) for d in (0.0, h, -h))
    assert np.allclose(np.linalg.norm(sm.pin_b - sm.pin_a, axis=-1), spatial.pitman, rtol=1e-14)
    assert np.allclose(np.linalg.norm(sm.pin_b1 - sm.pin_a1, axis=-1), spatial.pitman3, rtol=1e-14)
    dt = 2 * h / omega
    pairs = (("w2", "pin_b", "pin_a"), ("w3", "pin_b1", "pin_a1"), ("w4", "pin_b", "pin_b1"), ("w5", "pin_d", None))
    for w, head, tail in pairs:
        def vec(m):
            return getattr(m, head) - (getattr(m, tail) if tail else 0.0)
        assert np.allclose(np.cross(getattr(sm, w), vec(sm)), (vec(sp) - vec(sn)) / dt, rtol=0, atol=1e-8), w
        rate = (getattr(sp, w) - getattr(sn, w)) / dt
        assert np.allclose(getattr(sm, "e" + w[1]), rate, rtol=0, atol=1e-8), w
    # the equalizer rolls: it no longer turns with the beam alone
    assert np.max(np.abs(sm.w4 - sm.w5)) > 1e-4


def test_a_long_grid_solved_in_blocks_is_the_whole_grid(monkeypatch):
    """Beyond BLOCK crank angles the kinetostatics is solved block by block (bounded
    memory); every array of the motion and of the reactions is that of one batch of the
    whole grid, to the bit, with the crank speed and acceleration varying along it."""
    from pumpjack_cli.core.beam import kinetostatics

    unit = load_unit("sk8-3.5-4000")
    spatial, masses = unit.geometry.spatial(), unit.mass_model()
    theta = np.linspace(0.0, 2 * np.pi, 1000, endpoint=False)
    omega, epsilon, load = 1.1 + 0.1 * np.sin(theta), 0.05 * np.cos(theta), 5e4 + 2e4 * np.sin(theta)
    speeds = (omega, 1.1)
    wholes = [rational_mechanism(spatial, masses, theta, speed, epsilon, load) for speed in speeds]
    monkeypatch.setattr(kinetostatics, "BLOCK", 64)
    for speed, whole in zip(speeds, wholes):
        blocks = rational_mechanism(spatial, masses, theta, speed, epsilon, load)
        for part, expected in zip(blocks, whole):
            for field in dataclasses.fields(expected):
                if field.name != "residual":
                    assert np.array_equal(getattr(part, field.name), getattr(expected, field.name)), field.name
        # The residual is relative to the largest load of its block, not of the whole grid:
        # the same round-off, never smaller.
        assert np.all(blocks[1].residual >= whole[1].residual) and blocks[1].residual.max() < 1e-12
