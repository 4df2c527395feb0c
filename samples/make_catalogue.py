"""Make the sample unit catalogue ``samples/catalogue.csv`` (docs/catalogue.md) from units the repository cites.

Run from the repository root: ``python samples/make_catalogue.py`` rewrites the file;
``tests/readers/test_catalogue.py`` checks that the committed file is exactly what this
script makes.

Only published geometry goes in: the two bundled API units whose letters come from
[Guo2007] Table 12.1 (p. 12/167), ``configs/c-114d-133-54.toml`` and
``configs/c-80d-133-48.toml``. Their letters and rotation are read from those files; the
same table prints the three crank holes R1 > R2 > R3 = 24, 20, 16 in of both and their
structural unbalance Cs = 330 and 440 lb (the files cite them), one row per hole, hole 1
the longest stroke. The crank offset of a conventional unit is 0 ([API11E]). The table
prints no stroke per hole, so the ``stroke_in`` column is left empty: the catalogue
publishes none to check.
"""

from __future__ import annotations

import csv
import io
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from pumpjack_cli.quantities import INCH, parse_quantity  # noqa: E402
from pumpjack_cli.readers.unit_files import read_table  # noqa: E402

TARGET = ROOT / "samples" / "catalogue.csv"
SOURCE = "[Guo2007] Table 12.1 p. 12/167"
#: Bundled unit -> crank holes R1, R2, R3 [in] and structural unbalance Cs [lbf], [Guo2007] Table 12.1.
UNITS = {"c-114d-133-54": ((24, 20, 16), 330), "c-80d-133-48": ((24, 20, 16), 440)}
LETTERS = ("A", "C", "I", "P", "H", "G")
HEADER = ("designation", "crank_hole", "class", "rotation", *(f"{letter}_in" for letter in LETTERS), "R_in",
          "stroke_in", "B_lbf", "tau_deg", "source")


def _inches(value) -> str:
    """A length of a unit file in inches, as short as it is exact to 1e-9 in."""
    return f"{round(parse_quantity(value, 'length') / INCH, 9):g}"


def catalogue() -> str:
    """The text of samples/catalogue.csv."""
    out = io.StringIO()
    out.write("# Sample unit catalogue (docs/catalogue.md), made by samples/make_catalogue.py from units with\n"
              f"# published geometry: {SOURCE}, the letters of configs/c-114d-133-54.toml and\n"
              "# configs/c-80d-133-48.toml, crank holes 24/20/16 in (hole 1 = longest stroke) and Cs.\n"
              "# The source prints no stroke per hole: stroke_in is empty.\n")
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(HEADER)
    for name, (holes, unbalance) in UNITS.items():
        unit = read_table(ROOT / "configs" / f"{name}.toml")
        geometry = unit["geometry"]
        for hole, radius in enumerate(holes, start=1):
            writer.writerow((unit["designation"], hole, "conventional", geometry["rotation"],
                             *(_inches(geometry[letter]) for letter in LETTERS), radius, "", unbalance, 0, SOURCE))
    return out.getvalue()


if __name__ == "__main__":
    TARGET.write_text(catalogue(), encoding="utf-8")
