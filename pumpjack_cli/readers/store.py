"""The results store of `pumpjack batch`: one SQLite file (stdlib ``sqlite3``, WAL journal).

Table ``results``: one row per card and analysis, keyed by (well, card_sha256,
analysis, options_sha256) so that a card already done with the same analysis and
options is skipped and never stored twice; ``options`` holds the JSON text whose SHA-256
is ``options_sha256`` (what made the result); ``status`` is ``ok`` or ``error`` with the
one-line message in ``error``; the analysis' summary values (SI, the suffixed names of
the single command's ``-f json`` summary) are columns of their own, added as new names
appear: ``REAL`` for a number, ``TEXT`` for text (a label). The rows of a card, and of the
several cards of a task, are written in one transaction, so a run killed at any moment
leaves every card either complete or absent.

A store is marked by its header (``application_id``) and carries its layout's version
(``user_version``, :data:`VERSION`). It is opened read-only, and checked (a regular file,
an SQLite database, a results table of known columns, a version this program knows,
``PRAGMA quick_check``) before anything is written to it: a file that is refused is left
as it was. Only a run with cards to store opens it for writing; a new store is built
beside its name and linked into place, so that it never exists half made.
"""

from __future__ import annotations

import errno
import functools
import os
import re
import sqlite3
from pathlib import Path

from ..errors import PumpjackError
from ..text_input import describe_os_error, file_kind, note_input

#: Columns every row has, in order (``options`` since version 1).
FIXED = ("well", "card", "card_sha256", "timestamp", "unit", "analysis", "options_sha256", "options", "status",
         "error", "warnings")
#: The header's application id of a results store: "PJCK".
APPLICATION_ID = 0x504A434B
#: Version of the store's layout (``PRAGMA user_version``): 1 has the ``options`` column and
#: the application id; 0 is a store of pumpjack-cli 0.3.0, read as it is and brought to
#: version 1 when a run writes to it.
VERSION = 1
_NAME = re.compile(r"^[a-z][a-z0-9_]*$")
_TABLE = (f"CREATE TABLE results (id INTEGER PRIMARY KEY, {', '.join(f'{name} TEXT NOT NULL' for name in FIXED)}, "
          f"UNIQUE (well, card_sha256, analysis, options_sha256))",
          "CREATE INDEX results_well ON results (well, timestamp, card)")
_HEADER = b"SQLite format 3\0"
#: What SQLite's primary result codes mean for a store, beyond its own words.
_CAUSES = {"SQLITE_FULL": "no space left on device", "SQLITE_BUSY": "locked by another process for over a minute",
           "SQLITE_LOCKED": "locked by another process for over a minute", "SQLITE_CORRUPT": "the file is damaged",
           "SQLITE_NOTADB": "not an SQLite database"}
#: Result codes of a file or directory that cannot be opened or written.
_ACCESS = ("SQLITE_READONLY", "SQLITE_CANTOPEN", "SQLITE_PERM", "SQLITE_AUTH")


@functools.lru_cache(maxsize=64)
def _insert(names: tuple[str, ...]) -> str:
    """The INSERT of a row of the fixed fields and the summary ``names`` (made once per set of names)."""
    columns = (*FIXED, *names)
    return f"INSERT OR IGNORE INTO results ({', '.join(columns)}) VALUES ({', '.join('?' * len(columns))})"


class Store:
    """A results store opened read-only, or for writing (``write``: created if missing,
    a version-0 store brought to the current version)."""

    def __init__(self, path: Path, write: bool = False):
        self.path = Path(path)
        self.db: sqlite3.Connection | None = None
        exists = self._check_file(write)
        try:
            if exists:
                self.db = self._read_only()
                self._check()
            if write:
                self._check_writable()
                if not exists:
                    self._create()
                self.close()
                self.db = self._writable()
                self.types = self._types()
        except sqlite3.Error as exc:
            self.close()
            raise self._fault(exc, "cannot open") from None
        except BaseException:
            self.close()
            raise
        note_input(os.stat(self.path), "results store")

    # --- opening --------------------------------------------------------------------------

    def _refuse(self, message: str) -> PumpjackError:
        return PumpjackError(f"--store {self.path}: {message}")

    def _check_file(self, write: bool) -> bool:
        """Whether the store exists (a regular, non-empty SQLite file); a missing one is
        an error unless a run will create it."""
        try:
            info = os.stat(self.path)
        except FileNotFoundError:
            if os.path.islink(self.path):
                raise self._refuse("is a symbolic link to a missing file") from None
            if not write:
                raise self._refuse("no such results store") from None
            if not self.path.parent.is_dir():
                raise self._refuse(f"directory {self.path.parent} does not exist") from None
            return False
        except OSError as exc:
            raise self._refuse(describe_os_error(exc)) from None
        kind = file_kind(info.st_mode)
        if kind is not None:
            raise self._refuse(f"is {kind}, not a results store")
        if info.st_size == 0:
            raise self._refuse("is an empty file, not a results store; remove it or name another --store")
        try:
            with open(self.path, "rb") as handle:
                header = handle.read(100)
        except OSError as exc:
            raise self._refuse(f"cannot read: {describe_os_error(exc)}") from None
        if not header.startswith(_HEADER) or len(header) < 100:
            raise self._refuse("not an SQLite database, so not a results store")
        self._check_marks(int.from_bytes(header[68:72], "big"), int.from_bytes(header[60:64], "big"))
        return True

    def _read_only(self) -> sqlite3.Connection:
        """A read-only connection; in a directory this process cannot write, where SQLite
        cannot make the shared-memory file of the WAL journal, and no writer can have the
        store open, the file is read as immutable."""
        uri = self.path.absolute().as_uri()
        db = sqlite3.connect(f"{uri}?mode=ro", uri=True, timeout=60.0, isolation_level=None)
        try:
            db.execute("PRAGMA user_version")
            return db
        except sqlite3.OperationalError as exc:
            db.close()
            if (_code(exc) not in ("SQLITE_CANTOPEN", "SQLITE_READONLY") or self._writable_directory()
                    or os.path.exists(f"{self.path}-wal")):
                raise
        return sqlite3.connect(f"{uri}?immutable=1", uri=True, isolation_level=None)

    def _check(self) -> None:
        """Refuse what is not a results store of a version this program knows, or is damaged;
        note the columns' types."""
        assert self.db is not None
        application, version = (self.db.execute(f"PRAGMA {name}").fetchone()[0]
                                for name in ("application_id", "user_version"))
        self._check_marks(application, version)
        columns = list(self.db.execute("PRAGMA table_info(results)"))
        if not columns:
            raise self._refuse("an SQLite database without a results table, not a results store")
        self.types = self._types()
        for _, name, kind, notnull, _, key in columns:
            known = (name == "id" and key) or (name in FIXED and kind.upper() == "TEXT") or (
                _NAME.match(name) and kind.upper() in ("REAL", "TEXT") and not notnull and not key)
            if not known:
                raise self._refuse(f"column {name} ({kind or 'no type'}) is not one pumpjack-cli writes; "
                                   f"not a results store")
        missing = [name for name in FIXED if name not in self.types and (version or name != "options")]
        if missing or "id" not in self.types:
            raise self._refuse(f"the results table lacks the column {(missing or ['id'])[0]}; not a results store")
        problems = [row[0] for row in self.db.execute("PRAGMA quick_check")]
        if problems != ["ok"]:
            raise self._refuse(f"is damaged ({problems[0]}); restore it from a copy")

    def _types(self) -> dict[str, str]:
        """Column name -> its declared SQL type (TEXT for the fixed fields)."""
        return {row[1]: row[2].upper() for row in self.db.execute("PRAGMA table_info(results)")}

    def _check_marks(self, application: int, version: int) -> None:
        """Refuse another application's database and a store of a later version (from the
        file's header before SQLite opens it, and as SQLite reads them)."""
        if application not in (0, APPLICATION_ID):
            raise self._refuse(f"another application's SQLite database (application id {application:#x}), "
                               f"not a results store")
        if version > VERSION:
            raise self._refuse(f"a results store of version {version}, written by a later pumpjack-cli (this one "
                               f"knows versions up to {VERSION}); update pumpjack-cli to read or extend it")

    def _writable_directory(self) -> bool:
        return os.access(self.path.parent, os.W_OK | os.X_OK)

    def _access_problem(self) -> str | None:
        """Why the store or its directory cannot be written, if it cannot."""
        directory = self.path.parent
        try:
            read_only = bool(os.statvfs(directory).f_flag & os.ST_RDONLY)
        except OSError:
            read_only = False
        if read_only:
            return f"read-only file system (directory {directory})"
        if not self._writable_directory():
            return f"directory {directory} is not writable (SQLite writes its journal beside the store)"
        if self.path.exists() and not os.access(self.path, os.W_OK):
            return "the file is read-only (permission denied)"
        return None

    def _check_writable(self) -> None:
        problem = self._access_problem()
        if problem is not None:
            raise self._refuse(f"cannot write: {problem}")

    def _create(self) -> None:
        """A new store, built in a temporary file beside it and linked into place (a store
        another run created meanwhile is kept)."""
        temporary = self.path.parent / f".{self.path.name}.{os.getpid()}.{os.urandom(4).hex()}.new"
        try:
            os.close(os.open(temporary, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o666))
            db = sqlite3.connect(temporary, isolation_level=None)
            try:
                db.execute("BEGIN")
                for statement in _TABLE:
                    db.execute(statement)
                db.execute(f"PRAGMA application_id = {APPLICATION_ID}")
                db.execute(f"PRAGMA user_version = {VERSION}")
                db.execute("COMMIT")
                db.execute("PRAGMA journal_mode = WAL")
            finally:
                db.close()
            _link(temporary, self.path)
        except OSError as exc:
            raise self._refuse(f"cannot create: {describe_os_error(exc)}") from None
        finally:
            temporary.unlink(missing_ok=True)

    def _writable(self) -> sqlite3.Connection:
        """A connection that writes, the store brought to the current version under the write lock."""
        db = sqlite3.connect(self.path, timeout=60.0, isolation_level=None)
        try:
            db.execute("BEGIN IMMEDIATE")
            if db.execute("PRAGMA user_version").fetchone()[0] == 0:
                db.execute("ALTER TABLE results ADD COLUMN options TEXT NOT NULL DEFAULT ''")
                db.execute(f"PRAGMA application_id = {APPLICATION_ID}")
                db.execute(f"PRAGMA user_version = {VERSION}")
            db.execute("COMMIT")
            db.execute("PRAGMA journal_mode = WAL")
            db.execute("PRAGMA synchronous = NORMAL")
            return db
        except BaseException:
            db.close()
            raise

    def _fault(self, exc: sqlite3.Error, doing: str) -> PumpjackError:
        """One line for an SQLite error, naming its cause (a full disk, a read-only directory) where known."""
        code = _code(exc)
        cause = (self._access_problem() if code in _ACCESS else None) or _CAUSES.get(code) or str(exc)
        return self._refuse(f"{doing}: {cause}")

    # --- use ------------------------------------------------------------------------------

    def close(self) -> None:
        if self.db is not None:
            self.db.close()
            self.db = None

    def done(self) -> set[tuple[str, str, str, str]]:
        """(well, card_sha256, analysis, options_sha256) of every stored row."""
        return set(self.db.execute("SELECT well, card_sha256, analysis, options_sha256 FROM results"))

    def _ensure(self, summary: dict) -> None:
        """Add a column for each new summary name: TEXT for a text value, REAL for a number
        (called under the write lock: a column another run added meanwhile is seen first)."""
        if summary.keys() <= self.types.keys():
            return
        self.types = self._types()
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

    def add_cards(self, cards: list[list[dict]]) -> list[list[str]]:
        """Store the rows of several cards (each card a list of rows: fixed fields and summary
        values) in one transaction; for each card, the status of each of its rows stored (a row
        another run stored meanwhile is not stored again). A failure stores none of them: the
        transaction is rolled back (SQLite's journal does the same for a process killed within it)."""
        stored: list[list[str]] = []
        known = dict(self.types)  # the columns as they were, should the transaction's be rolled back
        try:
            self.db.execute("BEGIN IMMEDIATE")
            for rows in cards:
                statuses = []
                for row in rows:
                    summary = row["summary"]
                    self._ensure(summary)
                    cursor = self.db.execute(_insert(tuple(summary)),
                                             [row[name] for name in FIXED] + list(summary.values()))
                    statuses += [row["status"]] * cursor.rowcount
                stored.append(statuses)
            self.db.execute("COMMIT")
        except sqlite3.Error as exc:
            self._rollback(known)
            raise PumpjackError(f"{self._fault(exc, 'cannot write')}; every card stored before is kept") from None
        except BaseException:
            self._rollback(known)
            raise
        return stored

    def _rollback(self, types: dict[str, str]) -> None:
        """Undo the open transaction, the columns it added with it (``types``: those before it)."""
        if self.db.in_transaction:
            self.db.execute("ROLLBACK")
        self.types = types

    def rows(self, well: str | None = None, analysis: str | None = None) -> tuple[list[str], list[tuple]]:
        """Column names (the fixed fields, then the summary columns) and rows (ordered by well,
        timestamp, card, analysis), optionally of one well and one analysis; summary columns
        that are empty in every selected row are left out. A value of the wrong kind (not a
        number in a number's column) is refused."""
        where, values = [], []
        if well is not None:
            where.append("well = ?")
            values.append(well)
        if analysis is not None:
            where.append("analysis = ?")
            values.append(analysis)
        clause = f" WHERE {' AND '.join(where)}" if where else ""
        try:
            cursor = self.db.execute(f"SELECT * FROM results{clause} ORDER BY well, timestamp, card, analysis, id",
                                     values)
            names = [d[0] for d in cursor.description]
            rows = cursor.fetchall()
        except sqlite3.Error as exc:
            raise self._fault(exc, "cannot read") from None
        fixed = [names.index(name) for name in FIXED if name in names]
        summary = [i for i, name in enumerate(names) if name != "id" and name not in FIXED
                   and any(row[i] is not None for row in rows)]
        for i in fixed + summary:
            self._check_values(names[i], [row[i] for row in rows])
        keep = fixed + summary
        return [names[i] for i in keep], [tuple(row[i] for i in keep) for row in rows]

    def _check_values(self, name: str, values: list) -> None:
        kinds = (str,) if self.is_text(name) else (float, int)
        wrong = next((value for value in values if value is not None and not isinstance(value, kinds)), None)
        if wrong is not None:
            raise self._refuse(f"column {name} holds {type(wrong).__name__} where "
                               f"{'text' if self.is_text(name) else 'a number'} belongs; not a store pumpjack-cli "
                               f"wrote")


def _code(exc: sqlite3.Error) -> str:
    """SQLite's primary result code of an error (``SQLITE_READONLY`` for ``SQLITE_READONLY_DBMOVED``)."""
    name = getattr(exc, "sqlite_errorname", None) or ""
    return "_".join(name.split("_")[:2])


def _link(temporary: Path, path: Path) -> None:
    """Put the new store at ``path`` unless a store is there by now; on a file system
    without hard links, rename it there if none is there yet (two runs creating the same
    store at the very same moment could then both rename theirs)."""
    try:
        os.link(temporary, path)
    except FileExistsError:
        pass
    except OSError as exc:
        if exc.errno not in (errno.EPERM, errno.ENOTSUP, errno.EOPNOTSUPP):
            raise
        if not path.exists():
            os.rename(temporary, path)
