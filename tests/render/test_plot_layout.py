"""Every plot of every command reads at a glance: no text beyond the figure's canvas.

Each command that draws runs in-process with ``--plot``; the renderer's figure is measured
by :func:`pumpjack_cli.render.plot.text_outside` (every title, label, tick label and
legend against the canvas) instead of being saved, and what its legends say is checked:
words, not snake_case names; the dead positions marked on panels against the crank angle;
the rated and pull-out torques on the motor torque panels; the permissible-load branches
named by stroke; the Goodman strength in the unit system of the axes; a curve hidden
under an equal one said so.
"""

from __future__ import annotations

import re

import pytest

import pumpjack_cli.render as render
from pumpjack_cli.render import plot

from helpers import SK8_CARD, sample_card

RUNS = {
    "kinematics": ("kinematics", "sk8-3.5-4000", "--steps", "72"),
    "kinematics class III": ("kinematics", "m-912d-365-168", "--steps", "72", "--spm", "6"),
    "reactions": ("reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--steps", "72"),
    "compare-redundancy": ("compare-redundancy", "7sk12-2.5-5600", "--card", sample_card("7sk12-2.5-5600"), "--spm",
                           "8", "--steps", "24", "--crank-phase", "0.1 deg"),
    "inertia-error slider-crank": ("inertia-error", "unb-600a", "--steps", "72"),
    "inertia-error support friction": ("inertia-error", "unb-600a", "--steps", "72", "--support-friction"),
    "inertia-error beam": ("inertia-error", "sk8-3.5-4000", "--steps", "72", "--mass", "100 kg"),
    "dynamics": ("dynamics", "sk8-3.5-4000", "--steps", "72"),
    "dynamics wave": ("dynamics", "sk8-3.5-4000", "--samples", "64", "--well-model", "wave", "--damping", "0.1"),
    "torque": ("torque", "sk8-3.5-4000", "--card", SK8_CARD, "--steps", "72", "--units", "field"),
    "torque unknown counterbalance": ("torque", "m-912d-365-168", "--card", sample_card("m-912d-365-168"),
                                      "--steps", "72"),
    "downhole": ("downhole", "c-114d-133-54", "--card", sample_card("c-114d-133-54"), "--samples", "128",
                 "--units", "field"),
    "predict": ("predict", "c-80d-133-48", "--samples", "64", "--damping", "0.1", "--spm", "8"),
    "predict dynamic": ("predict", "sk8-3.5-4000", "--samples", "64", "--damping", "0.1", "--crank-motion", "dynamic"),
}


@pytest.fixture(scope="module")
def figures():
    """The figure of each run, drawn once (module scope: several tests read them)."""
    from pumpjack_cli.cli import main
    import contextlib
    import io
    import tempfile
    from pathlib import Path

    drawn = {}

    def keep(result, system, stream, file_format):
        drawn["figure"] = plot.figure(result, system)

    found = {}
    original = render.draw_plot
    render.draw_plot = keep
    try:
        with tempfile.TemporaryDirectory() as folder:
            for name, argv in RUNS.items():
                drawn.clear()
                with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()) as err:
                    code = main([*map(str, argv), "--plot", str(Path(folder) / "plot.png"), "-f", "csv"])
                assert code == 0, (name, err.getvalue())
                found[name] = drawn["figure"]
    finally:
        render.draw_plot = original
    return found


@pytest.mark.parametrize("name", RUNS)
def test_no_text_leaves_the_figure(figures, name):
    assert plot.text_outside(figures[name]) == []


def _legend(figure) -> list[str]:
    return [text.get_text() for ax in figure.axes if ax.get_legend() for text in ax.get_legend().get_texts()]


@pytest.mark.parametrize("name", RUNS)
def test_legends_and_labels_are_words(figures, name):
    fig = figures[name]
    texts = _legend(fig) + [ax.get_xlabel() for ax in fig.axes] + [ax.get_ylabel() for ax in fig.axes]
    snake = [t for t in texts if re.search(r"[a-z]_[a-z]", t) and "S_A" not in t and "S_max" not in t
             and "M_R" not in t and "M_z" not in t]
    assert not snake, snake
    assert all(re.search(r"\[[^\]]+\]", ax.get_ylabel().replace("\n", " ")) for ax in fig.axes)


def test_dead_positions_are_marked_against_the_crank_angle(figures):
    for name in ("kinematics", "reactions", "dynamics", "torque", "predict dynamic", "inertia-error beam"):
        legend = _legend(figures[name])
        assert "bottom dead position" in legend and "top dead position" in legend, name
    assert "outer dead centre" in _legend(figures["inertia-error slider-crank"])


def test_motor_torque_panels_show_rated_and_pull_out_torque(figures):
    for name in ("dynamics", "dynamics wave", "predict dynamic"):
        legend = " ".join(_legend(figures[name]))
        assert "rated motor torque" in legend and "pull-out torque" in legend, name


def test_permissible_load_branches_are_named_and_shown(figures):
    fig = figures["torque"]
    legend = _legend(fig)
    assert {"upstroke: largest permissible load", "downstroke: smallest permissible load"} <= \
        {" ".join(t.split()) for t in legend}
    card_axes = fig.axes[0]
    low, high = card_axes.get_ylim()
    card = card_axes.get_lines()[0].get_ydata()
    assert low < card.min() and high > card.max()


def test_the_goodman_strength_is_in_the_axes_units(figures):
    legend = " ".join(_legend(figures["downhole"]))
    assert "psi" in legend and "MPa" not in legend
    assert "psi" in figures["downhole"].axes[-1].get_ylabel()


def test_a_hidden_curve_is_said_so(figures):
    legend = " ".join(" ".join(_legend(figures["reactions"])).split())
    assert "R12 x (equal to R13 x, drawn under it)" in legend


def test_the_check_sees_a_title_beyond_the_canvas():
    """The measure itself: a figure whose unwrapped title is wider than the canvas fails it."""
    fig = plot._figure_class()(figsize=(4, 3), layout="constrained")
    fig.subplots(1, 1)
    fig.suptitle("a title far too long for a figure four inches wide " * 3)
    assert any("edge" in found for found in plot.text_outside(fig))
