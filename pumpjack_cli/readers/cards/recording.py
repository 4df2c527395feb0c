"""Continuous recordings: a card with time stamps over several strokes, split into its strokes.

A dynamometer or controller that records continuously writes time, position and load
over many cycles. Such a card, in any format with time stamps, is split here into its
strokes, each from one bottom of the stroke (the lowest position of a cycle) to the next,
using the positions alone (no unit is known yet):

* a top is the highest position before the position has fallen by :data:`HYSTERESIS`
  of its range, a bottom the lowest before it has risen as much (reversals with
  hysteresis, no smoothing); a top at the first sample is the recording's start, not a
  top;
* a card with fewer than two tops is one card, read as it is;
* the bottoms are the lowest position between two successive tops and, before the first
  top and after the last, the lowest position there when it lies within
  :data:`EDGE_TOLERANCE` of the range of the bottoms between tops (a recording that
  starts or ends at a bottom); the samples before the first bottom and after the last
  are a part of a stroke, dropped;
* every whole stroke is a card of its own (``RawCard.strokes``, named "<file> stroke k"),
  with the recording's metadata and ``start``, the time of its first sample [s]; the
  recording's raw card is its last stroke (:func:`.raw.several`). A recording with
  fewer than one whole stroke, or a stroke of fewer than :data:`~.raw.MIN_POINTS`
  samples, is refused in one line.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ...errors import CardError
from .raw import MIN_POINTS, RawCard, several

#: A reversal counts once the position has come back by this fraction of its range: far above
#: a dynamometer's noise (below 1 % of the stroke), far below a stroke (the whole range).
HYSTERESIS = 0.2
#: A lowest position before the first top or after the last is a bottom when it lies within
#: this fraction of the range of the median bottom between tops: near a bottom the position
#: changes slowly (1 % of the stroke is about 11 deg of crank rotation on either side).
EDGE_TOLERANCE = 0.01


def tops(position: np.ndarray, hysteresis: float) -> list[int]:
    """Indices of the tops of ``position``: each the highest sample since the last bottom,
    confirmed when the position has fallen ``hysteresis`` [its unit] below it (and a bottom,
    the lowest since the last top, when it has risen as much). A top at the first sample is
    not one.

    >>> tops(np.array([0.0, 1.0, 0.2, 0.0, 0.9, 1.0, 0.1, 0.4]), 0.5)
    [1, 5]
    """
    values = position.tolist()
    found = []
    high = low = 0
    rising: bool | None = None
    for i in range(1, len(values)):
        value = values[i]
        if value > values[high]:
            high = i
        if value < values[low]:
            low = i
        if rising is not False and values[high] - value >= hysteresis:
            if high > 0:
                found.append(high)
            rising, low = False, i
        elif rising is not True and value - values[low] >= hysteresis:
            rising, high = True, i
    return found


def turns_twice(position: np.ndarray, hysteresis: float) -> bool:
    """Whether ``position`` falls by ``hysteresis`` (> 0), then rises by as much, then falls by as
    much again, each turn after the last: :func:`tops` confirms a top on such a fall and the next
    only after such a rise, so a card without these turns has fewer than two tops and is known
    to be one card without the walk sample by sample. Each turn is taken where it is first
    complete, against the running extreme since the last.

    >>> turns_twice(np.array([0.0, 1.0, 0.2, 0.0, 0.9, 1.0, 0.1, 0.4]), 0.5)
    True
    >>> turns_twice(np.array([0.0, 1.0, 0.2, 0.0, 0.3]), 0.5)
    False
    """
    at = 0
    for falls in (True, False, True):
        rest = position[at:]
        done = (np.maximum.accumulate(rest) - rest if falls else rest - np.minimum.accumulate(rest)) >= hysteresis
        turn = int(done.argmax())
        if not done[turn]:
            return False
        at += turn
    return True


def split(raw: RawCard) -> RawCard:
    """A card with time stamps as it is when its positions pass fewer than two tops, else the
    strokes of the recording (the module's rules)."""
    position = raw.position
    span = float(position.max() - position.min())
    if span > 0 and not turns_twice(position, HYSTERESIS * span):
        return raw
    found = tops(position, HYSTERESIS * span)
    if len(found) < 2:
        return raw
    inner = [a + int(np.argmin(position[a:b])) for a, b in zip(found, found[1:])]
    level = float(np.median(position[inner])) + EDGE_TOLERANCE * span
    lead = int(np.argmin(position[:found[0]]))
    tail = found[-1] + 1 + int(np.argmin(position[found[-1] + 1:]))
    bottoms = [edge for edge in (lead,) if position[edge] <= level] + inner + \
        [edge for edge in (tail,) if position[edge] <= level]
    if len(bottoms) < 2:
        raise CardError(f"{raw.source}: the positions pass {len(found)} tops (a recording of several strokes) but "
                        f"hold no whole stroke from a bottom to the next; record at least one whole stroke")
    strokes = []
    for a, b in zip(bottoms, bottoms[1:]):
        if b - a < MIN_POINTS:
            raise CardError(f"{raw.source}: line {raw.lines[a]}: the stroke from line {raw.lines[a]} to line "
                            f"{raw.lines[b - 1]} has {b - a} samples; a stroke needs at least {MIN_POINTS} "
                            f"(positions that turn every few samples are not a recording)")
        strokes.append(replace(raw, load=raw.load[a:b], lines=raw.lines[a:b], time=raw.time[a:b],
                               position=position[a:b], metadata={**raw.metadata, "start": float(raw.time[a])}))
    return several(strokes)
