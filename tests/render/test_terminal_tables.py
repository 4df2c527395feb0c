"""Terminal tables never cut a number or a header: at 80 columns every command's table
keeps each cell whole (no ellipsis) and within the width (issue: every input, every output)."""

from __future__ import annotations

import pytest

from helpers import SK8_CARD, sample_card

RUNS = [
    ("units",),
    ("kinematics", "sk8-3.5-4000"),
    ("reactions", "sk8-3.5-4000", "--card", SK8_CARD),
    ("compare-redundancy", "7sk12-2.5-5600", "--card", sample_card("7sk12-2.5-5600"), "--crank-phase", "0.1 deg"),
    ("dynamics", "sk8-3.5-4000"),
    ("inertia-error", "unb-600a"),
    ("inertia-error", "unb-600a", "--support-friction"),
    ("torque", "sk8-3.5-4000", "--card", SK8_CARD),
    ("downhole", "sk8-3.5-4000", "--card", SK8_CARD),
    ("predict", "c-80d-133-48", "--spm", "8", "--damping", "0.1", "--samples", "64"),
]


@pytest.mark.parametrize("argv", RUNS, ids=lambda argv: " ".join(argv[:2]))
@pytest.mark.parametrize("width", [80, 60])
def test_tables_keep_every_cell_whole(run_cli, monkeypatch, argv, width):
    monkeypatch.setenv("COLUMNS", str(width))
    code, out, err = run_cli(*argv, "--steps", "24", "-f", "table") if argv[0] in (
        "kinematics", "reactions", "compare-redundancy", "dynamics", "inertia-error", "torque") else run_cli(
        *argv, "-f", "table")
    assert code == 0, err
    assert "…" not in out
    assert max(len(line) for line in out.splitlines()) <= width


def test_wrapped_text_keeps_digit_groups_together(run_cli, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    code, out, err = run_cli("units", "-f", "table")
    assert code == 0, err
    assert "13 300 lbf" in out and "114 000 lbf" in out
