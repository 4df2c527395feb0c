"""Every kind of beam unit through its unit file: kinematics, virtual work of the counterbalance,
the balance of each kind's own variable, and the upstroke each kind's rotation gives.

Unit files are written here as TOML text with API letters (C-114D-133-54's letters of
[Guo2007] for the class I kinds, with the crank shaft moved back for the reverse-mark; the bundled
M-912D-365-168 and A-228D-246-86 for class III), so each kind is read through the
same schema and registry a user's file is.
"""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.balance import balance_criteria, recommend_counterbalance
from pumpjack_cli.core.beam.counterbalance import Counterbalance, counterbalance_from_masses, upstroke_mask
from pumpjack_cli.core.beam.masses import MassModel
from pumpjack_cli.core.dynamics.coefficients import gravity_torque
from pumpjack_cli.core.sampling import crank_grid
from pumpjack_cli.errors import ConfigError

from helpers import INCH, POUND_FORCE, REPO_ROOT, zoom_scan

LETTERS = 'A = "72 in"\nC = "64 in"\nP = "74.5 in"\nH = "116 in"\nG = "41 in"\nR = "24 in"\n'
FILES = {
    "conventional": f'[geometry]\nclass = "conventional"\n{LETTERS}I = "64 in"\nrotation = "clockwise"\n'
                    '[counterbalance]\nstructural_unbalance = "330 lbf"\nmoment = "300000 lbf*in"\n',
    "reverse-mark": f'[geometry]\nclass = "reverse-mark"\n{LETTERS}I = "72 in"\ncrank_offset = "-10 deg"\n'
                    '[counterbalance]\nstructural_unbalance = "330 lbf"\nmoment = "300000 lbf*in"\n',
    "beam-balanced": f'[geometry]\nclass = "beam-balanced"\n{LETTERS}I = "64 in"\nrotation = "counterclockwise"\n'
                     'beam_counterweight = "6000 lbf"\nbeam_counterweight_arm = "60 in"\n'
                     '[counterbalance]\nstructural_unbalance = "330 lbf"\n',
}
BUNDLED = {"mark-ii": "m-912d-365-168", "air-balanced": "a-228d-246-86"}
KINDS = (*FILES, *BUNDLED)
H = 1e-5


@pytest.fixture(scope="module")
def units(tmp_path_factory):
    folder = tmp_path_factory.mktemp("kinds")
    found = {}
    for kind, text in FILES.items():
        path = folder / f"{kind}.toml"
        path.write_text(f'name = "{kind}"\n{text}', encoding="utf-8")
        found[kind] = load_unit(str(path))
    found.update({kind: load_unit(name) for kind, name in BUNDLED.items()})
    return found


@pytest.mark.parametrize("kind", KINDS)
def test_each_kind_is_read_as_itself(units, kind):
    unit = units[kind]
    assert unit.geometry.unit_class == kind
    assert unit.geometry.mechanism().lever_class == ("III" if kind in ("mark-ii", "air-balanced") else "I")


@pytest.mark.parametrize("kind", KINDS)
def test_torque_factor_is_the_derivative_of_the_rod_position(units, kind):
    mechanism = units[kind].geometry.mechanism()
    theta = np.linspace(0.0, 2 * np.pi, 1441)
    tf = mechanism.torque_factor(theta)
    fd = (mechanism.rod_position(theta + H) - mechanism.rod_position(theta - H)) / (2 * H)
    assert np.abs(tf - fd).max() < 1e-6 * np.abs(tf).max()


def test_upstroke_travel_with_each_kinds_standard_rotation(units):
    # [LufkinMarkII]: the Mark II lifts over more than half a turn counterclockwise; the
    # reverse-mark, its rear working centre shifted forward of the crank shaft (C < I, as in every
    # reverse-mark row of [UnitDatabase2018]), also over more than half a turn, clockwise ([LufkinRM])
    assert units["mark-ii"].geometry.mechanism().dead_positions().upstroke_crank_travel > math.pi
    assert units["reverse-mark"].geometry.mechanism().dead_positions().upstroke_crank_travel > math.pi


@pytest.mark.parametrize("kind", ["conventional", "reverse-mark", "mark-ii"])
@pytest.mark.parametrize("phase_deg", [0.0, 23.0, 180.0, 199.0, -65.0])
def test_crank_counterweights_torque_is_the_virtual_work_of_their_weight(units, kind, phase_deg):
    # point masses on the crank: blocks at phase phi ahead of the pin, arms in line with it;
    # their weight's torque at the crank, computed by coefficients.gravity_torque from the
    # positions, equals the API form of the counterbalance built from the same masses
    mechanism = units[kind].geometry.mechanism()
    masses = dataclasses.replace(MassModel(*[0.0] * 18), crank_arm_mass=400.0, crank_arm_cg=0.5,
                                 counterweight_mass=3000.0, counterweight_radius=1.1,
                                 counterweight_phase=math.radians(phase_deg))
    theta = np.linspace(0.0, 2 * np.pi, 721)
    motion = mechanism.motion(theta)
    exact = gravity_torque(mechanism, masses, motion)
    balance = counterbalance_from_masses(mechanism, masses)
    api = balance.structural_torque(motion) + balance.counterbalance_torque(motion)
    assert np.abs(api - exact).max() < 1e-9 * np.abs(exact).max()


def test_the_mark_ii_crank_offset_puts_the_counterweights_ahead_of_the_tail(units):
    # tau = +19 deg on a Mark II: the resultant sits 180 + 19 deg ahead of the pin
    unit = units["mark-ii"]
    mechanism = unit.geometry.mechanism()
    balance, known = unit.counterbalance_model()
    assert isinstance(balance, Counterbalance) and balance.tail and not known
    balance = balance.with_value(2e5)
    masses = dataclasses.replace(MassModel(*[0.0] * 18), counterweight_mass=2e5 / 9.80665, counterweight_radius=1.0,
                                 counterweight_phase=math.radians(180.0 + 19.0))
    theta = np.linspace(0.0, 2 * np.pi, 361)
    motion = mechanism.motion(theta)
    assert np.abs(balance.counterbalance_torque(motion) - gravity_torque(mechanism, masses, motion)).max() < 1e-6


def test_the_beam_counterweight_torque_is_the_virtual_work_of_its_weight(units):
    unit = units["beam-balanced"]
    mechanism = unit.geometry.mechanism()
    balance, known = unit.counterbalance_model()
    assert known and balance.weight == pytest.approx(6000 * POUND_FORCE)
    masses = dataclasses.replace(MassModel(*[0.0] * 18), beam_mass=6000 * POUND_FORCE / 9.80665,
                                 beam_cg=-60 * INCH)
    theta = np.linspace(0.0, 2 * np.pi, 721)
    motion = mechanism.motion(theta)
    exact = gravity_torque(mechanism, masses, motion)
    assert np.abs(balance.counterbalance_torque(motion) - exact).max() < 1e-9 * np.abs(exact).max()
    # conservative: no work over a turn (the rectangle rule is spectral for a periodic integrand)
    grid = crank_grid(4096)
    assert abs(np.sum(balance.counterbalance_torque(mechanism.motion(grid)))) < 1e-9 * np.abs(exact).max() * 4096


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("criterion", balance_criteria())
def test_each_kinds_balance_agrees_with_a_brute_force_scan(units, kind, criterion):
    unit = units[kind]
    mechanism = unit.geometry.mechanism()
    balance, _ = unit.counterbalance_model()
    theta = crank_grid(2048)
    m = mechanism.motion(theta)
    up = upstroke_mask(mechanism, theta)
    scale = unit.ratings().structure_load or 1e5
    load = np.where(up, 0.45, 0.25) * scale + 0.03 * scale * np.sin(3 * theta)

    def net(values):
        return np.array([m.torque_factor * load + balance.structural_torque(m)
                         + balance.with_value(v).counterbalance_torque(m) for v in values])

    objectives = {
        "min-peak": lambda v: np.abs(net(v)).max(axis=1),
        "min-rms": lambda v: np.mean(net(v) ** 2, axis=1),
        "equal-peaks": lambda v: np.abs(np.where(up, net(v), -np.inf).max(axis=1)
                                        - np.where(up, -np.inf, net(v)).max(axis=1)),
    }
    found = recommend_counterbalance(criterion, mechanism, theta, load, balance)
    # the scan's range: ten times the value that holds the mean load at the test position
    per_value = float(np.abs(balance.torque_per_value(m)).max())
    top = 10.0 * float(np.abs(m.torque_factor * load).max()) / per_value
    scanned = zoom_scan(objectives[criterion], 0.0, top, rounds=9, points=201)
    assert found.value == pytest.approx(scanned, rel=1e-6, abs=1e-9 * top)


@pytest.mark.parametrize("text, message", [
    (FILES["reverse-mark"].replace('crank_offset = "-10 deg"\n', 'crank_offset = "-10 deg"\nrotation = "counterclockwise"\n'),
     "geometry.rotation: Input should be 'clockwise'"),
    (FILES["beam-balanced"].replace('structural_unbalance = "330 lbf"\n', 'structural_unbalance = "330 lbf"\nmoment = "1 N*m"\n'),
     "a beam-balanced unit needs [counterbalance] structural_unbalance, without moment"),
])
def test_a_kind_refuses_what_it_cannot_be(tmp_path, text, message):
    path = tmp_path / "unit.toml"
    path.write_text(f'name = "x"\n{text}', encoding="utf-8")
    with pytest.raises(ConfigError, match=message.replace("[", r"\[").replace("(", r"\(")):
        load_unit(str(path)).counterbalance_model()


def test_blocks_that_contradict_the_crank_offset_are_refused(tmp_path):
    # a Mark II with [masses] whose blocks sit in line with the pin (phase 0, tau = -180 deg on the
    # tail) while crank_offset says 19 deg: refused with both angles; blocks at 180 + 19 = -161 deg pass
    mark = (REPO_ROOT / "configs" / "m-912d-365-168.toml").read_text(encoding="utf-8")
    start, end = mark.index("[counterbalance]"), mark.index("# ILLUSTRATIVE well")
    conventional = (REPO_ROOT / "configs" / "c-114d-133-54.toml").read_text(encoding="utf-8")
    blocks = conventional[conventional.index("[masses.crank_arm]"):conventional.index("# ILLUSTRATIVE well")]
    # crank arms of negligible mass, so that the blocks alone set the offset
    blocks = blocks.replace('phase = "0 deg"', 'phase = "{phase}"').replace('mass = "300 kg"', 'mass = "0.001 kg"', 1)
    path = tmp_path / "mark.toml"
    path.write_text(mark[:start] + blocks.format(phase="0 deg") + mark[end:], encoding="utf-8")
    with pytest.raises(ConfigError, match="put the crank offset at -180 deg, \\[geometry\\] crank_offset says 19 deg"):
        load_unit(str(path)).counterbalance_model()
    path.write_text(mark[:start] + blocks.format(phase="-161 deg") + mark[end:], encoding="utf-8")
    balance, known = load_unit(str(path)).counterbalance_model()
    assert known and balance.offset == pytest.approx(math.radians(19.0))


@pytest.mark.parametrize("line, message", [
    ('lever = "132 in"', "geometry.air_cylinder.lever 3.353 m is beyond the beam's front arm A 3.327 m"),
    ('pressure_position = "88 in"', "geometry.air_cylinder.pressure_position 2.235 m is beyond the stroke 2.209 m"),
])
def test_an_air_cylinder_off_its_beam_or_stroke_is_refused(tmp_path, line, message):
    """The piston rod's pin lies on the beam (at most A = 131 in from the centre bearing), and the
    stated pressure's position within the stroke (86.98 in): one inch beyond either is refused."""
    text = (REPO_ROOT / "configs" / "a-228d-246-86.toml").read_text(encoding="utf-8")
    key = line.partition(" =")[0]
    changed = re.sub(rf"^{key} = .*$", line, text, flags=re.M)
    assert changed != text
    path = tmp_path / "unit.toml"
    path.write_text(changed, encoding="utf-8")
    with pytest.raises(ConfigError, match=re.escape(message)):
        load_unit(str(path)).counterbalance_model()
