"""The bibliography: every citation key used in the project has an entry in docs/references.md,
and the seed papers are cited by their keys, never as "seed 00N".

A citation key is written in square brackets, e.g. ``[SK8Rotation2013]`` or ``[API11E]``.
The pattern below is chosen so that it cannot match the other bracketed texts of the
project:

* units in docstrings and descriptions (``[m]``, ``[N·m]``, ``[Pa]``, ``[GPa]``,
  ``[kg·m²]``, ``[1/s]``): a key is at least four characters of ASCII letters, digits and
  hyphens, starting with an upper-case letter;
* TOML tables (``[geometry]``, ``[masses.crank_arm]``) and option names: lower-case start
  or a dot;
* Markdown links ``[text](url)``: a key is never followed by ``(``;
* Python code (``list[Column]``, ``np.array([True])``): Python files are scanned only in
  their comments and string literals, and a key is never preceded by a word character;
* words in brackets inside strings (``[True]``, ``[Key]``): a key either contains a digit
  (author-year keys such as ``[Guo2007]``, standards such as ``[NIST811]``) or has at
  least two upper-case letters (``[NUNG]``, ``[PopovychSenchishak]``).

Entries are the lines ``**[Key]** ...`` of docs/references.md, each preceded by its
anchor ``<a id="key"></a>`` (the key in lower case) so that documents can link to it.
"""

from __future__ import annotations

import io
import re
import tokenize
from pathlib import Path

import pytest

from helpers import REPO_ROOT

REFERENCES = REPO_ROOT / "docs" / "references.md"

KEY = re.compile(r"(?<![\w\[\]])\[([A-Z][A-Za-z0-9-]{3,})\](?!\()")
ENTRY = re.compile(r"^\*\*\[([^\]]+)\]\*\*", re.MULTILINE)
ANCHOR = re.compile(r'^<a id="([^"]+)"></a>\s*\n\*\*\[([^\]]+)\]\*\*', re.MULTILINE)
#: "seed 004", "Seed 000", "seeds 000 and 003", "seed-004", "seed_001": the seed papers by number.
SEED_NUMBER = re.compile(r"\bseeds?[\s_-]*\d{3}\b", re.IGNORECASE)


def is_key(candidate: str) -> bool:
    """A bracketed word is a citation key if it has a digit or two upper-case letters."""
    return any(c.isdigit() for c in candidate) or sum(c.isupper() for c in candidate) >= 2


def keys_in(text: str) -> set[str]:
    return {match for match in KEY.findall(text) if is_key(match)}


def python_prose(path: Path) -> str:
    """The comments and string literals (docstrings included) of a Python file."""
    source = path.read_text(encoding="utf-8")
    tokens = tokenize.generate_tokens(io.StringIO(source).readline)
    prose_types = {tokenize.COMMENT, tokenize.STRING}
    prose_types |= {getattr(tokenize, name) for name in ("FSTRING_MIDDLE",) if hasattr(tokenize, name)}
    return "\n".join(token.string for token in tokens if token.type in prose_types)


def documents() -> list[Path]:
    """Every file whose text may cite a source: docs, configs, samples, package and tests."""
    files = [REPO_ROOT / "README.md", *sorted((REPO_ROOT / "docs").glob("*.md"))]
    files += sorted(p for p in (REPO_ROOT / "configs").iterdir() if p.suffix in (".toml", ".yaml", ".yml", ".json"))
    files += sorted(p for p in (REPO_ROOT / "samples").iterdir() if p.suffix in (".yaml", ".yml", ".py", ".csv"))
    files += sorted((REPO_ROOT / "pumpjack_cli").rglob("*.py")) + sorted((REPO_ROOT / "tests").rglob("*.py"))
    return [p for p in files if p != Path(__file__).resolve()]  # this file's examples are not citations


def prose(path: Path) -> str:
    return python_prose(path) if path.suffix == ".py" else path.read_text(encoding="utf-8")


def bibliography() -> set[str]:
    return set(ENTRY.findall(REFERENCES.read_text(encoding="utf-8")))


def rel(path: Path) -> str:
    return path.relative_to(REPO_ROOT).as_posix()


# --- the key pattern itself ------------------------------------------------------------


@pytest.mark.parametrize("text", [
    "force [N], torque [N·m], modulus [Pa], [GPa], inertia [kg·m²], speed [1/s], angle [deg], [rad], [W], [J]",
    "[geometry] and [masses.crank_arm] tables, the unit's [deviations] and [well]",
    "see [docs/cards.md](docs/cards.md) and [Gibbs](https://example.org)",
    "an entry reads **[Key]** ...; doctest output [True] or [False]",
])
def test_key_pattern_ignores_units_tables_links_and_words(text):
    assert keys_in(text) == set()


def test_key_pattern_finds_every_kind_of_key():
    text = ("([SK8Rotation2013] eq. 25), [API11E] letters, [NUNG] eqs. 5.12-5.18, "
            "[PopovychSenchishak]'s crank, [NIST811], [Guo2007], [Some-Key2]")
    assert keys_in(text) == {"SK8Rotation2013", "API11E", "NUNG", "PopovychSenchishak", "NIST811", "Guo2007",
                             "Some-Key2"}


def test_python_prose_skips_code(tmp_path):
    path = tmp_path / "module.py"
    path.write_text('"""Doc [API11E]."""\nx = list[Column]  # note [NUNG]\ny = f"[{x}] [Guo2007]"\n', encoding="utf-8")
    assert keys_in(python_prose(path)) == {"API11E", "NUNG", "Guo2007"}


# --- the bibliography ------------------------------------------------------------------


def test_every_entry_has_its_anchor_and_a_unique_key():
    text = REFERENCES.read_text(encoding="utf-8")
    entries = ENTRY.findall(text)
    assert len(entries) == len(set(entries)), "a key has two entries"
    anchored = ANCHOR.findall(text)
    assert [key for _, key in anchored] == entries, "every **[Key]** entry must follow its <a id> line"
    for anchor, key in anchored:
        assert anchor == key.lower(), f"anchor {anchor!r} of [{key}] must be the key in lower case"
        assert is_key(key), f"[{key}] would not be recognised as a key in the text"


def test_the_seed_papers_have_entries():
    assert {"Spatial7SK12", "InertiaUNB600A", "PopovychSenchishak", "SK8Rotation2013"} <= bibliography()


def test_every_cited_key_has_an_entry():
    """Every document's keys (the README, docs, configs, samples, the package and the tests), each
    offending file named with its keys. A Python file's prose is tokens of its text, and no key can
    start or end at a token's edge (strings begin and end with quotes, comments with # and the
    line's end), so its keys are among those of the whole text: the tokens are read only when the
    text has a missing key."""
    entries, found = bibliography(), []
    for path in documents():
        missing = keys_in(path.read_text(encoding="utf-8")) - entries
        if missing and path.suffix == ".py":
            missing = keys_in(python_prose(path)) - entries
        if missing:
            found.append(f"{rel(path)} cites {sorted(missing)}")
    assert not found, f"without an entry in docs/references.md: {'; '.join(found)}"


def test_the_citations_are_found_at_all():
    # Guards the test above against a pattern that silently matches nothing.
    expected, cited = {"SK8Rotation2013", "Spatial7SK12", "InertiaUNB600A", "PopovychSenchishak", "API11E"}, set()
    for path in documents():
        cited |= keys_in(prose(path))
        if expected <= cited:
            break
    assert expected <= cited


# --- no seed numbers -------------------------------------------------------------------


def seed_documents() -> list[Path]:
    files = [REPO_ROOT / "README.md", *sorted((REPO_ROOT / "docs").glob("*.md"))]
    files += sorted((REPO_ROOT / "pumpjack_cli").rglob("*.py"))
    files += sorted(p for p in (REPO_ROOT / "configs").iterdir() if p.is_file() and p.suffix != ".pyc")
    files += sorted(p for p in (REPO_ROOT / "samples").iterdir() if p.is_file() and p.suffix != ".bin")  # no text
    return [p for p in files if p != REFERENCES]


def test_seed_pattern():
    for text in ("seed 004 eq. 25", "(Seed 000)", "seeds 000 and 003", "SEED 001", "seed-004", "seed_003"):
        assert SEED_NUMBER.search(text), text
    for text in ("the seed papers", "SEED_OMEGA1", "random seed", "[SK8Rotation2013]"):
        assert not SEED_NUMBER.search(text), text


def test_no_seed_numbers():
    found = [f"{rel(path)} ({numbers[0]!r})" for path in seed_documents()
             if (numbers := SEED_NUMBER.findall(path.read_text(encoding="utf-8")))]
    assert not found, f"a seed paper named by number, cite its key instead: {'; '.join(found)}"
