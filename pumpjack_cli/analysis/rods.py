"""Result pieces of the rod string: per-taper stresses and Goodman loading, the Goodman diagram.

The rod string itself is built by the unit's config (:meth:`~pumpjack_cli.config.well.Well.rods`).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ..core.rods.analysis import goodman_allowable_stress, goodman_loading
from ..errors import warn
from ..results import Curve, Panel, Scalar


def taper_summary(string, loads, service_factor: float) -> list[Scalar]:
    """Per taper (top first): extreme stresses at its ends and its Goodman loading ([API11BR]) of
    one card's loads (:class:`TaperRows` of one card)."""
    return TaperRows(string, loads, service_factor).card(0)


class TaperRows:
    """Per taper (top first) of K cards' loads (shape (K, S), or (S,) for one card): the extreme
    stresses at its ends and its Goodman loading ([API11BR]), the loadings of all the cards one
    array computation; a card's rows (:meth:`card`) made of plain floats, one list a card."""

    def __init__(self, string, loads, service_factor: float) -> None:
        tapers = len(string.length)
        self._graded = not np.isnan(string.tensile_strength).any()
        columns = [loads.top_max_stress, loads.top_min_stress, loads.bottom_max_stress, loads.bottom_min_stress]
        if self._graded:
            columns.append(goodman_loading(string, loads, service_factor))
        self._values = np.stack(columns, axis=-1).reshape(-1, tapers * len(columns)).tolist()
        self._names = _taper_names(tapers, self._graded)

    def card(self, index: int) -> list[Scalar]:
        """The rows of card ``index``: each taper's stresses at its top and bottom (max, min) and its
        Goodman loading where it is finite; without a grade for every taper, no loading and a warning."""
        if not self._graded:
            warn("a rod section has no grade or tensile_strength: the Goodman loading is left out")
        return [Scalar(name, value) for (name, loading), value in zip(self._names, self._values[index])
                if not loading or math.isfinite(value)]


@functools.cache
def _taper_names(tapers: int, graded: bool) -> tuple[tuple[str, bool], ...]:
    """The summary names of each taper's stresses (top max, top min, bottom max, bottom min) and, if
    ``graded``, of its Goodman loading, each with whether it is the loading."""
    ends = [f"{end}_{label}_stress" for end in ("top", "bottom") for label in ("max", "min")]
    return tuple((f"taper_{i}_{name}", name == "goodman_loading") for i in range(1, tapers + 1)
                 for name in ends + ["goodman_loading"] * graded)


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
