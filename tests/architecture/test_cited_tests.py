"""The tests that documents and comments cite exist, and test files have unique names.

docs/validation.md and the other documents point to tests by path (``tests/core/test_well.py``),
by file name in a table (``test_rods_downhole.py``) and by test (``test_predict_gibbs.py::test_…``,
``…::test_…`` for the file of the row above, a trailing ``*`` for a family); the package's
comments, the unit files and the tests' own docstrings do too. A test moved or renamed
without its citations would leave the reader at a dead end: every path must exist, every
file name must be the name of exactly one test file, and every cited test must be defined.
"""

from __future__ import annotations

import ast
import fnmatch
import re
from collections import Counter
from pathlib import Path

from helpers import REPO_ROOT, syntax_tree

TESTS = REPO_ROOT / "tests"
#: ``tests/...`` (a folder or a file; a sentence's full stop is not part of it).
PATH = re.compile(r"(?<![\w/])tests/[\w/.-]*[\w/]")
#: A test file's name, with the test it names if any: ``test_x.py`` or ``test_x.py::test_y*``.
FILE = re.compile(r"(?<![\w/])(test_\w+\.py)(?:::(test_\w+\*?))?")
#: A test of the file cited last: ``…::test_y`` or ``::test_y``.
SAME_FILE = re.compile(r"(?:…|`)::(test_\w+\*?)")


def _citing_files() -> list[Path]:
    files = [REPO_ROOT / "README.md", REPO_ROOT / "pyproject.toml", REPO_ROOT / "Makefile",
             *sorted((REPO_ROOT / "docs").glob("*.md")), *sorted((REPO_ROOT / "configs").glob("*.toml")),
             *sorted((REPO_ROOT / "samples").glob("*.py")), *sorted((REPO_ROOT / "pumpjack_cli").rglob("*.py")),
             *sorted(TESTS.rglob("*.py"))]
    return [p for p in files if p != Path(__file__).resolve()]  # this file's examples are not citations


def _test_files() -> list[Path]:
    return sorted(TESTS.rglob("test_*.py"))


def _defined(path: Path) -> set[str]:
    return {node.name for node in syntax_tree(path).body
            if isinstance(node, ast.FunctionDef)}


def _citations(text: str) -> tuple[list[str], list[tuple[str, str | None]]]:
    """The ``tests/`` paths and the (file name, test) pairs a text cites; ``…::test_y`` is a test
    of the file cited last in the same paragraph (table)."""
    tests: list[tuple[str, str | None]] = []
    current = None
    for line in text.splitlines():
        if not line.strip():
            current = None
        for match in re.finditer(f"{FILE.pattern}|{SAME_FILE.pattern}", line):
            if match.group(1):
                current = match.group(1)
                tests.append((current, match.group(2)))
            else:
                assert current is not None, f"{line!r} cites a test without its file"
                tests.append((current, match.group(3)))
    return PATH.findall(text), tests


def test_test_file_names_are_unique():
    """One name, one file: a table that cites ``test_x.py`` without its folder is unambiguous."""
    counts = Counter(p.name for p in _test_files())
    assert not [name for name, count in counts.items() if count > 1]


def test_the_citations_are_found_at_all():
    """Guards the check below against patterns that silently match nothing."""
    text = (REPO_ROOT / "docs" / "validation.md").read_text(encoding="utf-8")
    paths, tests = _citations(text)
    assert len(paths) >= 40 and "tests/validation/test_guo2007.py" in paths
    assert _citations("| `test_a.py::test_b` | x |\n| `…::test_c*` | y |\nsee test_d.py.")[1] == [
        ("test_a.py", "test_b"), ("test_a.py", "test_c*"), ("test_d.py", None)]


def test_every_cited_test_exists():
    """Every citing file's cited paths, test files and tests, each offending file named with what it cites."""
    by_name = {p.name: p for p in _test_files()}
    defined = {name: _defined(path) for name, path in by_name.items()}
    found = []
    for path in _citing_files():
        paths, tests = _citations(path.read_text(encoding="utf-8"))
        where = path.relative_to(REPO_ROOT)
        missing = [p for p in paths if not (REPO_ROOT / p).exists()]
        if missing:
            found.append(f"{where} cites {missing}, which do not exist")
        unknown = sorted({name for name, _ in tests if name not in by_name})
        if unknown:
            found.append(f"{where} cites {unknown}, which are no test files")
        undefined = sorted(f"{name}::{test}" for name, test in tests
                           if test and name in by_name and not fnmatch.filter(defined[name], test))
        if undefined:
            found.append(f"{where} cites {undefined}, which are not defined")
    assert not found, "; ".join(found)
