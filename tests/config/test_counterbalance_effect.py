"""`[counterbalance] counterbalance_effect`: the CBE a crew measures, instead of the moment.

A unit file that gives the measured counterbalance effect must give the same net torque as
one that gives the equivalent moment (or, for the air-balanced unit, pressure): the
equivalent is computed here by the forward definition CBE = B + M sin(theta_t - tau)/TF(theta_t)
([Rowlan2004]; the package's :func:`counterbalance_effect`), never read from the command's
output. One check is against a published number: [Guo2007] Table 12.1 prints the torque
factor of C-80D-133-48 at 90 degrees, 23.51 in, so a moment of 130 000 lbf·in is a CBE of
440 + 130 000 / 23.51 = 5969.6 lbf.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from pumpjack_cli.config import load_unit
from pumpjack_cli.core.beam.counterbalance import counterbalance_effect, upstroke_test_angle

from helpers import POUND_FORCE, REPO_ROOT, INCH, sample_card

C80 = REPO_ROOT / "configs" / "c-80d-133-48.toml"
MOMENT_LINE = re.compile(r'^moment = "130000 lbf\*in".*$', re.M)


def _with_counterbalance(tmp_path, source, name, replacement) -> str:
    text = source.read_text(encoding="utf-8")
    changed = MOMENT_LINE.sub(replacement, text) if MOMENT_LINE.search(text) else text.replace(
        "[counterbalance]\n", "[counterbalance]\n" + replacement + "\n")
    assert changed != text
    path = tmp_path / name
    path.write_text(changed, encoding="utf-8")
    return str(path)


def test_guo2007_torque_factor_turns_the_moment_into_the_measured_effect(tmp_path, run_card_json):
    """CBE 5969.6 lbf at 90 deg ([Guo2007]: TF(90 deg) = 23.51 in, B = 440 lbf) stands for M = 130 000
    lbf·in; the table's torque factor is printed to 4 digits, hence 2e-4."""
    cbe = 440 + 130000 / 23.51
    unit = _with_counterbalance(tmp_path, C80, "c80-cbe.toml", f'counterbalance_effect = "{cbe:.1f} lbf"')
    summary = run_card_json("torque", unit, "--units", "field", card_file=sample_card("c-80d-133-48"))["summary"]
    assert summary["counterbalance_moment_lbf_in"] == pytest.approx(130000, rel=2e-4)
    assert summary["counterbalance_effect_lbf"] == pytest.approx(round(cbe, 1), rel=1e-12)


@pytest.mark.parametrize("angle_deg", [90.0, 60.0, 250.0])
def test_a_measured_effect_gives_the_torque_of_the_equivalent_moment(tmp_path, run_card_json, angle_deg):
    """The C-80D-133-48 (M = 130 000 lbf·in) against the same unit described by its CBE at 90, 60 and
    250 deg (a downstroke angle: the effect is still the load the counterbalance holds there)."""
    unit = load_unit(C80)
    mechanism = unit.geometry.mechanism()
    balance, _ = unit.counterbalance_model()
    test = mechanism.motion(np.array([math.radians(angle_deg)]))
    # forward: B + M sin(theta + tau) / TF
    tf = float(test.torque_factor[0])
    cbe = balance.structural_unbalance + balance.moment * math.sin(math.radians(angle_deg) + balance.offset) / tf
    assert cbe == pytest.approx(counterbalance_effect(test, balance), rel=1e-12)
    written = _with_counterbalance(tmp_path, C80, "c80-cbe.toml",
                                   f'counterbalance_effect = "{cbe / POUND_FORCE!r} lbf"\n'
                                   f'counterbalance_effect_angle = "{angle_deg} deg"')
    card = sample_card("c-80d-133-48")
    given = run_card_json("torque", str(C80), card_file=card)
    measured = run_card_json("torque", written, card_file=card)
    assert measured["summary"]["counterbalance_moment_n_m"] == pytest.approx(130000 * POUND_FORCE * INCH, rel=1e-12)
    np.testing.assert_allclose(measured["series"]["net_torque_n_m"], given["series"]["net_torque_n_m"],
                               rtol=0, atol=1e-9 * max(map(abs, given["series"]["net_torque_n_m"])))


def test_the_mark_ii_effect_follows_its_tail_counterweights(tmp_path, run_card_json):
    """Class III: the counterweights ride on the crank's tail with the crank offset, so the same CBE
    needs another moment than on a class I unit; the file with the CBE and the one with that
    moment give one torque."""
    source = REPO_ROOT / "configs" / "m-912d-365-168.toml"
    unit = load_unit(source)
    balance, _ = unit.counterbalance_model()
    moment = 2.0e6 * INCH * POUND_FORCE
    angle = math.radians(75.0)
    test = unit.geometry.mechanism().motion(np.array([angle]))
    tf = float(test.torque_factor[0])
    # tail: T_c = +M sin(theta + tau), so CBE = B - M sin(theta + tau) / TF
    cbe = balance.structural_unbalance - moment * math.sin(angle + balance.offset) / tf
    with_moment = _with_counterbalance(tmp_path, source, "m-moment.toml", f'moment = "{moment!r} N*m"')
    with_effect = _with_counterbalance(tmp_path, source, "m-cbe.toml",
                                       f'counterbalance_effect = "{cbe!r} N"\ncounterbalance_effect_angle = "75 deg"')
    card = sample_card("m-912d-365-168")
    a = run_card_json("torque", with_moment, card_file=card)
    b = run_card_json("torque", with_effect, card_file=card)
    assert b["summary"]["counterbalance_moment_n_m"] == pytest.approx(moment, rel=1e-12)
    np.testing.assert_allclose(b["series"]["net_torque_n_m"], a["series"]["net_torque_n_m"], rtol=0,
                               atol=1e-9 * max(map(abs, a["series"]["net_torque_n_m"])))


def test_the_air_balanced_effect_sets_the_air_pressure(tmp_path, run_card_json):
    """The kind's own balancing variable: a measured CBE of the bundled air-balanced unit gives the pressure
    whose effect it is (forward through the air cylinder's own torque)."""
    source = REPO_ROOT / "configs" / "a-228d-246-86.toml"
    unit = load_unit(source)
    balance, known = unit.counterbalance_model()
    assert known
    # measured where the file's default puts it: the cranks horizontal on the upstroke (270 deg on this class III unit)
    mechanism = unit.geometry.mechanism()
    test = mechanism.motion(np.array([upstroke_test_angle(mechanism)]))
    cbe = counterbalance_effect(test, balance)
    text = source.read_text(encoding="utf-8")
    without = re.sub(r"^pressure = .*$", "", text, flags=re.M)
    assert without != text
    path = tmp_path / "air.toml"
    path.write_text(without.replace("[counterbalance]\n", f'[counterbalance]\ncounterbalance_effect = "{cbe!r} N"\n'),
                    encoding="utf-8")
    assert load_unit(path).counterbalance_model()[0].value == pytest.approx(balance.value, rel=1e-9)


@pytest.mark.parametrize(("lines", "message"), [
    ('moment = "130000 lbf*in"\ncounterbalance_effect = "6000 lbf"', "give moment or counterbalance_effect, not both"),
    ('counterbalance_effect = "-5 lbf"', "greater than or equal to 0"),
    ('counterbalance_effect = "6000 lbf"\ncounterbalance_effect_angle = "0 deg"', "greater than 0"),
    ('counterbalance_effect = "6000 kg"', "is a mass, not a force"),
    ('counterbalance_effect = "100 lbf"', "below 0"),
    # 2 deg past the bottom dead position TF is a few % of its largest: the moment it would imply is noise
    ('counterbalance_effect = "6000 lbf"\ncounterbalance_effect_angle = "2 deg"', "too near a dead position"),
])
def test_a_bad_effect_is_refused_in_one_line(tmp_path, run_cli, lines, message):
    text = MOMENT_LINE.sub(lines.replace("\\", "\\\\"), C80.read_text(encoding="utf-8"))
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = run_cli("torque", path, "--card", sample_card("c-80d-133-48"), "-f", "json")
    assert (code, out) == (2, "")
    assert err.count("\n") == 1 and message in err, err


def test_an_effect_at_a_dead_position_is_refused(tmp_path, run_cli):
    """At a dead position TF = 0: the load there does not reach the crank, so no CBE is measured there."""
    bottom = load_unit(C80).geometry.mechanism().dead_positions().crank_angle_bottom
    text = MOMENT_LINE.sub(f'counterbalance_effect = "6000 lbf"\ncounterbalance_effect_angle = "{bottom!r} rad"',
                           C80.read_text(encoding="utf-8"))
    path = tmp_path / "dead.toml"
    path.write_text(text, encoding="utf-8")
    code, _, err = run_cli("torque", path, "--card", sample_card("c-80d-133-48"))
    assert code == 2 and "counterbalance_effect" in err and err.count("\n") == 1, err


def test_an_effect_implying_a_moment_no_file_may_give_is_refused(tmp_path, run_cli):
    """C-228D-213-86's TF(90 deg) is about 43 in, so a CBE of 10 MN (the largest a file may give) implies
    M of about 1.1e7 N·m, above the 1e7 N·m of [counterbalance] moment: refused, not used."""
    source = REPO_ROOT / "configs" / "c-228d-213-86.toml"
    text = re.sub(r'^moment = .*$', 'counterbalance_effect = "1e7 N"', source.read_text(encoding="utf-8"), flags=re.M)
    path = tmp_path / "huge.toml"
    path.write_text(text, encoding="utf-8")
    code, _, err = run_cli("torque", path, "--card", sample_card("c-228d-213-86"))
    assert code == 2 and "above the 1e+07 N·m of [counterbalance] moment" in err and err.count("\n") == 1, err


def test_an_effect_where_the_counterweights_hang_vertical_is_refused(tmp_path, run_cli):
    """M-912D-365-168 at 340 deg: the torque factor is still over 5 % of its largest, but the
    counterweights' arm (its tail, +19 deg) stands 1 deg from the vertical, so their torque is 1.7 %
    of M: a measured effect there would stand for an unbounded moment; refused."""
    source = REPO_ROOT / "configs" / "m-912d-365-168.toml"
    path = _with_counterbalance(tmp_path, source, "m912.toml",
                                'counterbalance_effect = "17000 lbf"\ncounterbalance_effect_angle = "340 deg"')
    code, _, err = run_cli("torque", path, "--card", sample_card("m-912d-365-168"))
    assert code == 2 and "where their torque is 1.7 % of M" in err and err.count("\n") == 1, err
