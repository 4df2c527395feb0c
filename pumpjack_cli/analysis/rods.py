"""Result pieces of the rod string: per-taper stresses and Goodman loading, the Goodman diagram.

The rod string itself is built by the unit's config (:meth:`~pumpjack_cli.config.well.Well.rods`).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.rods.analysis import goodman_allowable_stress, goodman_loading
from ..errors import warn
from ..results import Curve, Panel, Scalar


def taper_summary(string, loads, service_factor: float) -> list[Scalar]:
    """Per taper (top first): extreme stresses at its ends and its Goodman loading ([API11BR])."""
    found = []
    graded = not np.isnan(string.tensile_strength).any()
    if not graded:
        warn("a rod section has no grade or tensile_strength: the Goodman loading is left out")
    goodman = goodman_loading(string, loads, service_factor) if graded else np.full(len(string.length), np.nan)
    for i in range(1, len(string.length) + 1):
        for end in ("top", "bottom"):
            for label in ("max", "min"):
                found.append(Scalar(f"taper_{i}_{end}_{label}_stress",
                                    float(getattr(loads, f"{end}_{label}_stress")[i - 1])))
        if math.isfinite(float(goodman[i - 1])):
            found.append(Scalar(f"taper_{i}_goodman_loading", float(goodman[i - 1])))
    return found


def goodman_panel(string, loads, service_factor: float) -> Panel:
    """The modified Goodman diagram ([API11BR]): the (S_min, S_max) of each taper's top and
    bottom, the allowable line of each grade and the line S_max = S_min below which no
    point can lie."""
    curves = []
    for i in range(len(string.length)):
        for end, marker in (("top", "o"), ("bottom", "s")):
            low, high = float(getattr(loads, f"{end}_min_stress")[i]), float(getattr(loads, f"{end}_max_stress")[i])
            curves.append(Curve(f"taper {i + 1} {end}", (low,), (high,), quantity="stress", style=marker))
    strengths = sorted({float(t) for t in string.tensile_strength if math.isfinite(float(t))})
    for strength in strengths:
        span = np.array([0.0, strength / 2.0])
        allowable = goodman_allowable_stress(strength, span, service_factor)
        curves.append(Curve("allowable S_A, T = {}", tuple(span), tuple(allowable), quantity="stress", style="--",
                            label_values=(("stress", strength),)))
    if strengths:
        span = (0.0, strengths[-1] / 2.0)
        curves.append(Curve("S_max = S_min", span, span, quantity="stress", style=":"))
    return Panel("max stress", (), curves=tuple(curves), x_label="min stress (modified Goodman diagram)")
