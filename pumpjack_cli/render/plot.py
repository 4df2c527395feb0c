"""The plot of a result: its panels drawn with matplotlib, imported only when a plot is drawn.

The plot goes to a file: a figure drawn by the file backend of its format (Agg for PNG),
never through pyplot, so no interactive backend is needed, and the one named by the
environment (``MPLBACKEND``, which matplotlib checks when imported) is ignored.
"""

from __future__ import annotations

import os
import textwrap

from ..quantities import output_unit
from ..results import Result


def draw_plot(result: Result, system: str, stream, file_format: str) -> None:
    """Each panel against its x column (default: the first column), dashed curves for
    approximations and bounds, further curves, horizontal lines at the panel's levels,
    to a binary stream in ``file_format`` (png, svg or pdf)."""
    import numpy as np

    Figure = _figure_class()

    def shown(name: str):
        column = result.column(name)
        unit = output_unit(column.quantity, system)
        return unit.convert(np.asarray(column.values, dtype=float)), unit

    def values(curve_axis, quantity):
        if isinstance(curve_axis, str):
            return shown(curve_axis)
        unit = output_unit(quantity, system)
        return unit.convert(np.asarray(curve_axis, dtype=float)), unit

    shares_x = all(panel.x is None and not panel.curves for panel in result.panels)
    fig = Figure(figsize=(8, 2.8 * len(result.panels)))
    axes = fig.subplots(len(result.panels), 1, sharex=shares_x)
    for ax, panel in zip(np.atleast_1d(axes), result.panels):
        x_name = panel.x or result.columns[0].name
        x, x_unit = shown(x_name)
        for names, style in ((panel.solid, "-"), (panel.dashed, "--")):
            for name in names:
                if panel.colour and style == "-":
                    colour, colour_unit = shown(panel.colour)
                    points = ax.scatter(x, shown(name)[0], c=colour, s=6, cmap="viridis", label=name)
                    fig.colorbar(points, ax=ax, label=f"{panel.colour} [{colour_unit.label}]")
                else:
                    ax.plot(x, shown(name)[0], style, label=name)
        y_unit = output_unit(result.column(panel.solid[0]).quantity, system) if panel.solid else None
        for curve in panel.curves:
            (cx, cx_unit), (cy, cy_unit) = values(curve.x, curve.quantity), values(curve.y, curve.quantity)
            ax.plot(cx, cy, curve.style, label=curve.label)
            y_unit = y_unit or cy_unit
            if not panel.solid:
                x_unit = cx_unit
        if panel.clip:
            solid = np.concatenate([shown(name)[0] for name in panel.solid])
            low, high = float(solid.min()), float(solid.max())
            ax.set_ylim(low - 0.5 * (high - low), high + 0.5 * (high - low))
        for label, value in panel.levels:
            ax.axhline(float(y_unit.convert(float(value))), color="red", linewidth=0.8, linestyle=":",
                       label=label or None)
        ax.set_ylabel(f"{panel.title} [{y_unit.label}]")
        if panel.y_down:
            ax.invert_yaxis()
        ax.grid(True, alpha=0.3)
        if len(panel.solid) + len(panel.dashed) + len(panel.curves) + len([lv for lv in panel.levels if lv[0]]) > 1:
            ax.legend(fontsize="small")
        if not shares_x or ax is np.atleast_1d(axes)[-1]:
            name = panel.x_label if not panel.solid and panel.x_label else x_name
            ax.set_xlabel(f"{name} [{x_unit.label}]")
    fig.suptitle(textwrap.fill(result.title, 100), fontsize="medium")  # a long title on two lines, not cut off
    fig.tight_layout()
    fig.savefig(stream, format=file_format)


def _figure_class():
    """matplotlib's Figure, imported with ``MPLBACKEND`` out of sight (an unknown name would
    stop the import; the figure never uses the backend it names)."""
    backend = os.environ.pop("MPLBACKEND", None)
    try:
        from matplotlib.figure import Figure
    finally:
        if backend is not None:
            os.environ["MPLBACKEND"] = backend
    return Figure
