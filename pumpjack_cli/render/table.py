"""The terminal table: title, summary lines and the brief columns as plain text.

Laid out here, without a layout engine: numbers and headers are never cut; columns
that do not fit the width are folded into further blocks.
"""

from __future__ import annotations

import re
import shutil
import textwrap
from typing import TextIO

from ..quantities import output_unit
from ..results import TEXT, Result
from .display import CSV_BLOCK, display_values, unit_label
from .formats import CSV, JSON

#: Width of a table written to a file [characters].
FILE_TABLE_WIDTH = 160


def _wrap(text: str, width: int) -> list[str]:
    """Lines of at most ``width`` characters that never break inside a number written with
    digit groups ("13 300 lbf" stays on one line)."""
    guarded = re.sub(r"(?<=\d) (?=\d)", "\u00a0", text)
    return [line.replace("\u00a0", " ") for line in textwrap.wrap(guarded, width)]


def _format(value: float) -> str:
    return f"{value:.6g}"


def _summary_lines(result: Result, system: str, width: int) -> list[str]:
    """Summary as aligned lines: name, value, unit, and the meaning wrapped to the width."""
    rows = []
    for s in result.summary:
        if isinstance(s.value, str):
            rows.append((s.name, s.value, "", s.description))
            continue
        unit = output_unit(s.quantity, system)
        rows.append((s.name, _format(unit.convert(float(s.value))), unit.label, s.description))
    if not rows:
        return []
    name_w = max(len(r[0]) for r in rows)
    value_w = max(len(r[1]) for r in rows)
    unit_w = max(len(r[2]) for r in rows)
    lead = name_w + value_w + unit_w + 6
    room = width - lead
    lines = []
    for name, value, label, meaning in rows:
        head = f"{name:<{name_w}}  {value:>{value_w}}  {label:<{unit_w}}  "
        if lead > width:
            lines += [name, f"    {value}  {label}".rstrip()]
            lines += ["    " + more for more in _wrap(meaning, max(width - 4, 20))]
        elif room >= 24:
            wrapped = _wrap(meaning, room) or [""]
            lines.append((head + wrapped[0]).rstrip())
            lines += [" " * lead + more for more in wrapped[1:]]
        else:
            lines.append(head.rstrip())
            lines += ["    " + more for more in _wrap(meaning, max(width - 4, 20))]
    return lines


def _wrap_text_columns(columns: list[tuple[str, str, list[str], bool]], width: int):
    """Text cells wrapped (lines joined by newlines) so that the text columns fit beside the
    first column; numbers are never wrapped."""
    first = max(len(columns[0][0]), len(columns[0][1]), *(len(v) for v in columns[0][2]))
    room = max(width - first - 2, 20)
    return [(name, label, ["\n".join(_wrap(v, room)) or "" for v in values] if text else values, text)
            if i and text else (name, label, values, text) for i, (name, label, values, text) in enumerate(columns)]


def _cell_width(text: str) -> int:
    return max((len(part) for part in text.split("\n")), default=0)


def _table_blocks(columns: list[tuple[str, str, list[str], bool]], width: int) -> list[list[int]]:
    """Column indices per block: the first column starts every block, the others fill the width."""
    widths = [max(len(name), len(label), *(_cell_width(v) for v in values)) for name, label, values, _ in columns]
    blocks, current, used = [], [0], widths[0]
    for i in range(1, len(columns)):
        if len(current) > 1 and used + 2 + widths[i] > width:
            blocks.append(current)
            current, used = [0], widths[0]
        current.append(i)
        used += 2 + widths[i]
    blocks.append(current)
    return blocks


def _row_lines(columns: list[tuple[str, str, list[str], bool]], block: list[int]) -> list[str]:
    """Header (name, unit), a rule and the rows of one block; text left-aligned, numbers right-aligned."""
    widths = {i: max(len(columns[i][0]), len(columns[i][1]), *(_cell_width(v) for v in columns[i][2])) for i in block}

    def line(cells) -> str:
        return "  ".join(cell.ljust(widths[i]) if columns[i][3] else cell.rjust(widths[i]) for i, cell in cells).rstrip()

    def row(r: int) -> list[str]:
        parts = {i: columns[i][2][r].split("\n") for i in block}
        height = max(len(p) for p in parts.values())
        return [line((i, parts[i][k] if k < len(parts[i]) else "") for i in block) for k in range(height)]

    lines = [line((i, columns[i][0]) for i in block), line((i, columns[i][1]) for i in block),
             "  ".join("-" * widths[i] for i in block)]
    for r in range(len(columns[block[0]][2])):
        lines += row(r)
    return lines


def write_table(result: Result, system: str, stream: TextIO, width: int | None = None) -> None:
    """Title, summary and the brief columns as plain text that never cuts a number or a name
    (``width`` [characters]: default the terminal's)."""
    width = width if width is not None else shutil.get_terminal_size(fallback=(80, 24)).columns
    width = max(width, 40)
    lines = _wrap(result.title, width)
    summary = _summary_lines(result, system, width)
    if summary:
        lines += [""] + summary
    brief = [c for c in result.columns if c.brief]
    columns = []
    for c in brief:
        label = unit_label(c.quantity, system)
        values = display_values(c, c.values, system)
        columns.append((c.name, f"[{label}]" if label else "",
                        [v if isinstance(v, str) else "" if v is None else _format(v) for v in values],
                        c.quantity == TEXT))
    if columns:
        columns = _wrap_text_columns(columns, width)
        for block in _table_blocks(columns, width):
            lines += [""] + _row_lines(columns, block)
    hidden = len(result.columns) - len(brief)
    if hidden:
        lines += ["", f"{hidden} more columns with --format {CSV} or {JSON}"]
    for start in range(0, len(lines), CSV_BLOCK):
        stream.write("\n".join(lines[start:start + CSV_BLOCK]) + "\n")
