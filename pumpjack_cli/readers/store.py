"""The results store of `pumpjack batch`: one SQLite file (stdlib ``sqlite3``, WAL journal).

Table ``results``: one row per card and analysis, keyed by (well, card_sha256,
analysis, options_sha256) so that a card already done with the same analysis and
options is skipped and never stored twice; ``status`` is ``ok`` or ``error`` with the
one-line message in ``error``; the analysis' summary values (SI, the suffixed names of
the single command's ``-f json`` summary) are columns of their own, added as new names
appear: ``REAL`` for a number, ``TEXT`` for text (a label). A card's rows are written in
one transaction, so a run killed at any moment leaves every card either complete or absent.
"""

from __future__ import annotations

import os
import re
import sqlite3
from pathlib import Path

from ..errors import PumpjackError
from ..text_input import note_input

#: Columns every row has, in order.
FIXED = ("well", "card", "card_sha256", "timestamp", "unit", "analysis", "options_sha256", "status", "error",
         "warnings")
_NAME = re.compile(r"^[a-z][a-z0-9_]*$")
SCHEMA = f"""
CREATE TABLE IF NOT EXISTS results (
    id INTEGER PRIMARY KEY,
    {', '.join(f'{name} TEXT NOT NULL' for name in FIXED)},
    UNIQUE (well, card_sha256, analysis, options_sha256)
);
CREATE INDEX IF NOT EXISTS results_well ON results (well, timestamp, card);
"""


class Store:
    """An open results store (created if missing)."""

    def __init__(self, path: Path, create: bool = True):
        self.path = Path(path)
        if not create and not self.path.is_file():
            raise PumpjackError(f"--store {path}: no such results store")
        if not self.path.parent.is_dir():
            raise PumpjackError(f"--store {path}: directory {self.path.parent} does not exist")
        try:
            self.db = sqlite3.connect(self.path, timeout=60.0, isolation_level=None)
            self.db.execute("PRAGMA journal_mode=WAL")
            self.db.execute("PRAGMA synchronous=NORMAL")
            if create:
                self.db.executescript(SCHEMA)
            #: Column name -> its declared SQL type (TEXT for the fixed fields).
            self.types = {row[1]: row[2].upper() for row in self.db.execute("PRAGMA table_info(results)")}
        except sqlite3.DatabaseError as exc:
            raise PumpjackError(f"--store {path}: not a results store ({exc})") from None
        if "options_sha256" not in self.types:
            raise PumpjackError(f"--store {path}: not a results store (no results table)")
        note_input(os.stat(self.path), "results store")

    def close(self) -> None:
        self.db.close()

    def done(self) -> set[tuple[str, str, str, str]]:
        """(well, card_sha256, analysis, options_sha256) of every stored row."""
        return set(self.db.execute("SELECT well, card_sha256, analysis, options_sha256 FROM results"))

    def _ensure(self, summary: dict) -> None:
        """Add a column for each new summary name: TEXT for a text value, REAL for a number."""
        for name, value in summary.items():
            if name not in self.types:
                if not _NAME.match(name):
                    raise PumpjackError(f"cannot store a result named {name!r}")
                kind = "TEXT" if isinstance(value, str) else "REAL"
                self.db.execute(f"ALTER TABLE results ADD COLUMN {name} {kind}")
                self.types[name] = kind

    def is_text(self, name: str) -> bool:
        """Whether the column ``name`` holds text (a fixed field or a text summary value)."""
        return self.types[name] == "TEXT"

    def add_card(self, rows: list[dict]) -> None:
        """Store the rows of one card (fixed fields and summary values) in one transaction."""
        try:
            self.db.execute("BEGIN IMMEDIATE")
            for row in rows:
                summary = row["summary"]
                self._ensure(summary)
                names = list(FIXED) + list(summary)
                self.db.execute(f"INSERT OR IGNORE INTO results ({', '.join(names)}) VALUES "
                                f"({', '.join('?' * len(names))})",
                                [row[name] for name in FIXED] + list(summary.values()))
            self.db.execute("COMMIT")
        except sqlite3.Error as exc:
            if self.db.in_transaction:
                self.db.execute("ROLLBACK")
            raise PumpjackError(f"--store {self.path}: cannot write: {exc}") from None

    def rows(self, well: str | None = None, analysis: str | None = None) -> tuple[list[str], list[tuple]]:
        """Column names and rows (ordered by well, timestamp, card, analysis), optionally of one
        well and one analysis; summary columns that are empty in every selected row are left out."""
        where, values = [], []
        if well is not None:
            where.append("well = ?")
            values.append(well)
        if analysis is not None:
            where.append("analysis = ?")
            values.append(analysis)
        clause = f" WHERE {' AND '.join(where)}" if where else ""
        cursor = self.db.execute(f"SELECT * FROM results{clause} ORDER BY well, timestamp, card, analysis", values)
        names = [d[0] for d in cursor.description]
        rows = cursor.fetchall()
        keep = [i for i, name in enumerate(names) if name != "id" and (
            name in FIXED or any(row[i] is not None for row in rows))]
        return [names[i] for i in keep], [tuple(row[i] for i in keep) for row in rows]
