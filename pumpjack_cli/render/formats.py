"""The output format names, contents and plot file suffixes, declared once, and the choice of a format.

``options.Format`` (the ``--format`` choices) is built from :data:`FORMATS`, ``options.What``
(the ``--what`` choices) from :data:`CONTENTS`.
"""

from __future__ import annotations

import sys
from pathlib import Path

#: The output formats, in the order ``--help`` lists them.
FORMATS = ("table", "csv", "json")
TABLE, CSV, JSON = FORMATS
#: What a text output holds: the columns (a table and JSON add the summary), or the summary alone.
CONTENTS = ("columns", "summary")
COLUMNS, SUMMARY = CONTENTS
#: The format an ``--output`` file's suffix implies (any other suffix: csv).
SUFFIX_FORMATS = {".json": JSON, ".csv": CSV, ".txt": TABLE}
#: The file suffixes of a ``--plot`` file, each its matplotlib file format.
PLOT_SUFFIXES = (".png", ".svg", ".pdf")


def choose_format(fmt: str | None, output: Path | None) -> str:
    """Explicit format; else from the output file's suffix; else table on a terminal, csv in a pipe."""
    if fmt is not None:
        return fmt
    if output is not None:
        return SUFFIX_FORMATS.get(output.suffix.lower(), CSV)
    return TABLE if sys.stdout is not None and sys.stdout.isatty() else CSV
