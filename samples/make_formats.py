"""Make one sample file per card layout of docs/cards.md from the bundled SK8-3,5-4000 sample card.

Run from the repository root: ``python samples/make_formats.py`` rewrites the files of
:data:`FILES` in ``samples/``; ``tests/readers/cards/test_card_layouts.py`` checks that the
committed files are exactly what this script makes. Every file holds the numbers of
``samples/sk8-3.5-4000-card.csv`` (``samples/make_cards.py``: synthetic, for trying the
program), read here with numpy, rewritten in another layout:

* ``sk8-3.5-4000-preamble.csv``: delimited text after a metadata preamble (well, date,
  SPM, stroke, units), in field units with a bare header;
* ``sk8-3.5-4000-card.bin``: the fixed binary block of XSPOC-type storage, 200 float32
  loads [lbf] then 200 positions [in], little-endian, the 180 points padded with (0, 0);
* ``sk8-3.5-4000-card.hex``: the same block as one line of hex digits;
* ``sk8-3.5-4000-card.json``: ``{"S": [...], "F": [...], "SPM": ...}``, S in m, F in kN;
* ``sk8-3.5-4000-recording.csv``: a continuous recording of 20 whole strokes of the card,
  between half a stroke before and after, its loads with Gaussian noise of 0.2 % of the
  load range (seeded), after a preamble with the well, the date and the SPM.
"""

from __future__ import annotations

import json
import struct
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"
SOURCE = SAMPLES / "sk8-3.5-4000-card.csv"
INCH, POUND_FORCE = 0.0254, 4.4482216152605  # [NIST811], as pumpjack_cli.quantities
POINTS = 200
STROKES = 20
NOISE = 0.002
SEED = 21


def sample() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The sample card's time [s], position [m] and load [N], read with numpy."""
    time, position, load_kn = np.loadtxt(SOURCE, delimiter=",", comments="#", skiprows=4, unpack=True)
    return time, position, load_kn * 1e3


def period(time: np.ndarray) -> float:
    """The sample's cycle time [s]: its samples are equally spaced over one cycle."""
    return float(time[-1] * time.size / (time.size - 1))


def preamble() -> str:
    time, position, load = sample()
    lines = ["Well Name,SK8-DEMO", "Date,2026-11-20 08:05", f"SPM: {60 / period(time):.2f}",
             f"Stroke,{np.ptp(position) / INCH:.1f} in", "Units,field", "time,position,load"]
    lines += [f"{t:.4f},{p / INCH:.4f},{w / POUND_FORCE:.2f}" for t, p, w in zip(time, position, load)]
    return "\n".join(lines) + "\n"


def block() -> bytes:
    """200 float32 loads [lbf], then 200 positions [in]; the points beyond the card's are (0, 0)."""
    _, position, load = sample()
    loads, positions = np.zeros(POINTS), np.zeros(POINTS)
    loads[:load.size], positions[:position.size] = load / POUND_FORCE, position / INCH
    return struct.pack(f"<{2 * POINTS}f", *loads, *positions)


def hex_text() -> str:
    return (f"# The SK8-3,5-4000 sample card as a {POINTS}-point block (float32 loads [lbf], then positions [in]): "
            f"--card-units field\n{block().hex().upper()}\n")


def service_json() -> str:
    time, position, load = sample()
    return json.dumps({"well": "SK8-DEMO", "S": [round(float(p), 5) for p in position],
                       "F": [round(float(w) / 1e3, 4) for w in load], "SPM": round(60 / period(time), 2)}) + "\n"


def recording() -> str:
    """20 whole strokes from half a stroke in (sample index 90) to half a stroke after."""
    time, position, load = sample()
    n = time.size
    index = np.arange(n // 2, (STROKES + 1) * n + n // 2)
    noise = np.random.default_rng(SEED).normal(0.0, NOISE * np.ptp(load), index.size)
    lines = ["Well Name,SK8-DEMO", "Date,2026-11-20 08:05", f"SPM,{60 / period(time):.2f}",
             "time_s,position_m,load_kN"]
    lines += [f"{t:.4f},{p:.5f},{w / 1e3:.4f}" for t, p, w in
              zip(index * period(time) / n, position[index % n], load[index % n] + noise)]
    return "\n".join(lines) + "\n"


#: File name in samples/ -> its content (text or bytes).
FILES = {
    "sk8-3.5-4000-preamble.csv": preamble,
    "sk8-3.5-4000-card.bin": block,
    "sk8-3.5-4000-card.hex": hex_text,
    "sk8-3.5-4000-card.json": service_json,
    "sk8-3.5-4000-recording.csv": recording,
}


def main() -> None:
    for name, make in FILES.items():
        content = make()
        path = SAMPLES / name
        (path.write_bytes(content) if isinstance(content, bytes) else path.write_text(content, encoding="utf-8"))


if __name__ == "__main__":
    main()
