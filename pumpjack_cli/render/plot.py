"""The plot of a result: its panels drawn with matplotlib, imported only when a plot is drawn.

The plot goes to a file: a figure drawn by the file backend of its format (Agg for PNG),
never through pyplot, so no interactive backend is needed, and the one named by the
environment (``MPLBACKEND``, which matplotlib checks when imported) is ignored.

What a figure shows, read at a glance: one unit system (every axis, level and legend
value in the units of ``--units``); legends and axis labels in words with their units
(:func:`~pumpjack_cli.names.words`), legends beside the axes, never over the curves; the
dead positions as vertical lines (:class:`~pumpjack_cli.results.Mark`); ratings and motor
torques as labelled horizontal lines with their values; a curve hidden under an equal
one is said so in the legend; titles and labels wrapped so that no text leaves the
figure (:func:`text_outside` measures it; ``tests/render/test_plot_layout.py`` runs every
plot of every command through it).
"""

from __future__ import annotations

import os
import textwrap

from ..names import words
from ..quantities import output_unit
from ..results import Curve, Result

#: Figure width [in], and height per panel [in].
WIDTH, PANEL_HEIGHT = 10.0, 3.0
#: Characters per line of the figure's title, and of a y-axis label (one panel high).
TITLE_CHARACTERS, Y_LABEL_CHARACTERS = 100, 34
#: Colours of the dead-position marks and of the levels.
MARK_COLOUR, LEVEL_COLOURS = "0.45", ("tab:red", "darkred", "tab:purple", "tab:brown")


def draw_plot(result: Result, system: str, stream, file_format: str) -> None:
    """The result's figure (:func:`figure`) to a binary stream in ``file_format`` (png, svg or pdf)."""
    figure(result, system).savefig(stream, format=file_format)


def _value_text(value: float, unit) -> str:
    """A value as a legend writes it: 4 significant digits and the unit ("39 230 N·m")."""
    shown = float(unit.convert(float(value)))
    if 1e4 <= abs(shown) < 1e15:
        text = f"{round(shown, 4 - len(str(int(abs(shown))))):,.0f}".replace(",", " ")
    else:
        text = f"{shown:.4g}"
    return f"{text} {unit.label}".strip()


def figure(result: Result, system: str):
    """Each panel against its x column (default: the first column): solid curves, dashed curves
    (approximations and bounds), further curves, the levels, the marks of the x column."""
    import numpy as np

    Figure = _figure_class()

    def shown(name: str):
        column = result.column(name)
        unit = output_unit(column.quantity, system)
        return unit.convert(np.asarray(column.values, dtype=float)), unit

    def values(axis, quantity):
        if isinstance(axis, str):
            return shown(axis)
        unit = output_unit(quantity, system)
        return unit.convert(np.asarray(axis, dtype=float)), unit

    panels = result.panels
    shares_x = all(panel.x is None and not panel.curves for panel in panels)
    fig = Figure(figsize=(WIDTH, PANEL_HEIGHT * len(panels) + 0.5), layout="constrained")
    axes = np.atleast_1d(fig.subplots(len(panels), 1, sharex=shares_x, squeeze=False)[:, 0])
    for ax, panel in zip(axes, panels):
        x_name = panel.x or result.columns[0].name
        x, x_unit = shown(x_name)
        labels = dict(panel.labels)
        drawn: list[tuple[object, np.ndarray, np.ndarray, str]] = []
        for names, style in ((panel.solid, "-"), (panel.dashed, "--")):
            for name in names:
                y = shown(name)[0]
                label = labels.get(name, words(name))
                if panel.colour and style == "-":
                    colour, colour_unit = shown(panel.colour)
                    points = ax.scatter(x, y, c=colour, s=6, cmap="viridis", label=label)
                    fig.colorbar(points, ax=ax, label=f"{words(panel.colour)} [{colour_unit.label}]")
                    continue
                (line,) = ax.plot(x, y, style, label=label)
                drawn.append((line, x, y, label))
        y_unit = output_unit(result.column(panel.solid[0]).quantity, system) if panel.solid else None
        curve_x_names = set()
        for curve in panel.curves:
            (cx, cx_unit), (cy, cy_unit) = values(curve.x, curve.quantity), values(curve.y, curve.y_quantity or
                                                                                  curve.quantity)
            label = _curve_label(curve, system)
            (line,) = ax.plot(cx, cy, curve.style, label=label or None,
                              **({"color": curve.color} if curve.color else {}))
            if label:
                drawn.append((line, cx, cy, label))
            y_unit = y_unit or cy_unit
            if isinstance(curve.x, str):
                curve_x_names.add(curve.x)
            if not panel.solid:
                x_unit = cx_unit
        _say_hidden(drawn)
        if panel.clip and panel.solid:
            _clip(ax, np.concatenate([shown(name)[0] for name in panel.solid]),
                  [shown(name)[0] for name in panel.dashed] + [line.get_ydata() for line, *_ in drawn[len(panel.solid):]])
        colour = -1
        for label, value in panel.levels:   # a level without a label continues the one before (a rating's -T_r)
            colour = min(colour + 1, len(LEVEL_COLOURS) - 1) if label or colour < 0 else colour
            ax.axhline(float(y_unit.convert(float(value))), color=LEVEL_COLOURS[colour], linewidth=1.0,
                       linestyle=":", label=f"{label}, {_value_text(value, y_unit)}" if label else None)
        marked = {x_name} if panel.solid else curve_x_names
        for k, mark in enumerate(m for m in result.marks if m.column in marked):
            unit = output_unit(result.column(mark.column).quantity, system)
            ax.axvline(float(unit.convert(float(mark.value))), color=MARK_COLOUR, linewidth=0.9,
                       linestyle=(0, (4, 2, 1, 2)) if k % 2 else (0, (1, 1.5)), label=mark.label)
        ax.set_ylabel("\n".join(textwrap.wrap(f"{panel.title} [{y_unit.label}]", Y_LABEL_CHARACTERS)))
        if panel.y_down:
            ax.invert_yaxis()
        ax.grid(True, alpha=0.3)
        handles, names = ax.get_legend_handles_labels()
        if len(handles) > 1 or (handles and not panel.solid):
            ax.legend(handles, ["\n".join(textwrap.wrap(n, 30)) for n in names], fontsize="small",
                      loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
        if not shares_x or ax is axes[-1]:
            name = panel.x_label if not panel.solid and panel.x_label else words(x_name)
            ax.set_xlabel(f"{name} [{x_unit.label}]")
    fig.suptitle("\n".join(textwrap.wrap(result.title, TITLE_CHARACTERS)), fontsize="medium")
    return fig


def _curve_label(curve: Curve, system: str) -> str:
    """A curve's label with its values written in the plot's unit system."""
    if not curve.label_values:
        return curve.label
    return curve.label.format(*(_value_text(value, output_unit(quantity, system))
                                for quantity, value in curve.label_values))


def _say_hidden(drawn) -> None:
    """A curve that a later one covers exactly (same x and y) gets "(hidden under ...)" in its
    legend label, so that a legend of four names over two visible lines is not a puzzle."""
    import numpy as np

    for i, (line, x, y, label) in enumerate(drawn):
        for later_line, later_x, later_y, later_label in drawn[i + 1:]:
            if np.shape(x) != np.shape(later_x) or np.shape(y) != np.shape(later_y):
                continue
            scale = float(np.nanmax(np.abs(y))) if np.size(y) and np.any(np.isfinite(y)) else 0.0
            if np.allclose(x, later_x, equal_nan=True) and np.allclose(y, later_y, rtol=0, atol=1e-9 * scale + 1e-300,
                                                                       equal_nan=True):
                line.set_label(f"{label} (equal to {later_label}, drawn under it)")
                break


def _clip(ax, solid, others) -> None:
    """Vertical range: the solid curves, and of each other curve the value nearest to them above
    and below (within three times their range), with a margin; a bound that grows without limit
    near a dead position is cut, its nearest approach to the card is shown."""
    import numpy as np

    low, high = float(np.nanmin(solid)), float(np.nanmax(solid))
    span = high - low or max(abs(high), 1.0)
    top, bottom = high, low
    for y in others:
        y = np.asarray(y, dtype=float)
        y = y[np.isfinite(y)]
        above, below = y[(y > high) & (y < high + 3 * span)], y[(y < low) & (y > low - 3 * span)]
        if above.size:
            top = max(top, float(above.min()))
        if below.size:
            bottom = min(bottom, float(below.max()))
    margin = 0.12 * (top - bottom or span)
    ax.set_ylim(bottom - margin, top + margin)


def text_outside(fig) -> list[str]:
    """What of a figure reaches beyond its canvas: its tight bounding box (every drawn title,
    label, tick label and legend, as matplotlib measures for ``bbox_inches="tight"``) against
    the canvas, side by side ([] when everything fits; half a pixel of rounding allowed).
    The check of ``tests/render/test_plot_layout.py``."""
    renderer = fig.canvas.get_renderer()
    fig.get_layout_engine().execute(fig)   # the layout a save does, without rasterising the curves
    tight = fig.get_tightbbox(renderer)   # inches
    dpi = fig.dpi
    width, height = fig.get_size_inches()
    found = []
    for side, over in (("left", -tight.x0), ("right", tight.x1 - width), ("bottom", -tight.y0),
                       ("top", tight.y1 - height)):
        if over * dpi > 0.5:
            found.append(f"{over * dpi:.1f} px beyond the {side} edge")
    return found


def _figure_class():
    """matplotlib's Figure, imported with ``MPLBACKEND`` out of sight (an unknown name would
    stop the import; the figure never uses the backend it names)."""
    backend = os.environ.pop("MPLBACKEND", None)
    try:
        from matplotlib.figure import Figure
        from matplotlib.backends.backend_agg import FigureCanvasAgg
    finally:
        if backend is not None:
            os.environ["MPLBACKEND"] = backend

    class AggFigure(Figure):
        """A Figure with an Agg canvas, so that its text can be measured before it is saved."""

        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            FigureCanvasAgg(self)

    return AggFigure
