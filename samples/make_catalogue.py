"""Make the sample unit catalogue ``samples/catalogue.csv`` (docs/catalogue.md) from units the repository cites.

Run from the repository root: ``python samples/make_catalogue.py`` rewrites the file;
``tests/readers/test_catalogue.py`` checks that the committed file is exactly what this
script makes.

Only published geometry goes in, that of the bundled units whose files cite it: the
letters, rotation and kind are read from the unit files; their crank holes (hole 1 the
longest stroke), published strokes, structural unbalance B and crank offset tau are those
the files cite (:data:`UNITS`). [Guo2007] Table 12.1 (p. 12/167) prints the three holes of
C-114D-133-54 and C-80D-133-48 and their Cs but no stroke per hole, so those rows have
none to check; [LufkinM912] prints the strokes of M-912D-365-168, and its third hole's
exact stroke is 0.83 in longer than the rounded 130 in (the file says so), which
``pumpjack units --catalogue`` flags. The crank offset of a conventional unit is 0 ([API11E]).
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
#: Bundled unit -> its source, crank holes R1, R2, R3 [in], the stroke published for each [in] (None: not
#: published), structural unbalance B [lbf] and crank offset tau [deg], as the unit file cites them.
UNITS = {
    "c-114d-133-54": ("[Guo2007] Table 12.1 p. 12/167", (24, 20, 16), None, 330, 0),
    "c-80d-133-48": ("[Guo2007] Table 12.1 p. 12/167", (24, 20, 16), None, 440, 0),
    "m-912d-365-168": ("[LufkinM912]", (63.56, 56.56, 49.56), (168, 149, 130), -5385, 19),
}
LETTERS = ("A", "C", "I", "P", "H", "G")
HEADER = ("designation", "crank_hole", "class", "rotation", *(f"{letter}_in" for letter in LETTERS), "R_in",
          "stroke_in", "B_lbf", "tau_deg", "source")


def _inches(value) -> str:
    """A length of a unit file in inches, as short as it is exact to 1e-9 in."""
    return f"{round(parse_quantity(value, 'length') / INCH, 9):g}"


def catalogue() -> str:
    """The text of samples/catalogue.csv."""
    out = io.StringIO()
    out.write("# Sample unit catalogue (docs/catalogue.md), made by samples/make_catalogue.py from the bundled units\n"
              "# whose files cite published geometry: C-114D-133-54 and C-80D-133-48 of [Guo2007] Table 12.1 (no\n"
              "# stroke per hole published) and M-912D-365-168 of [LufkinM912]. Hole 1 is the longest stroke.\n")
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(HEADER)
    for name, (source, holes, strokes, unbalance, offset) in UNITS.items():
        unit = read_table(ROOT / "configs" / f"{name}.toml")
        geometry = unit["geometry"]
        for hole, radius in enumerate(holes, start=1):
            writer.writerow((unit["designation"], hole, geometry.get("class", "conventional"), geometry["rotation"],
                             *(_inches(geometry[letter]) for letter in LETTERS), radius,
                             "" if strokes is None else strokes[hole - 1], unbalance, offset, source))
    return out.getvalue()


if __name__ == "__main__":
    TARGET.write_text(catalogue(), encoding="utf-8")
