"""Every `pumpjack` command shown in the README and docs/ runs as written.

The commands are taken from the documents' shell blocks (a `$ ` prompt and trailing
comments dropped, continued lines joined); one whose arguments are placeholders
(UNIT, FILE, NU, ...) or name files that are not in the repository (a field manifest, a
cluster address) is skipped. Output and plot files go to a temporary folder, so the
documents' own figures are left alone; a pipeline `pumpjack ... | pumpjack ...` feeds the
first command's standard output to the second.
"""

from __future__ import annotations

import io
import re
import shlex
import sys
from pathlib import Path

import pytest

from helpers import REPO_ROOT

DOCUMENTS = [REPO_ROOT / "README.md", *sorted((REPO_ROOT / "docs").glob("*.md"))]
#: Options whose value is a file the command writes.
OUTPUTS = ("--plot", "-o", "--output")
PLACEHOLDER = re.compile(r"^(?:[A-Z][A-Z_]*|\[.*|.*\|.*)$")


def _commands() -> list[tuple[str, str]]:
    found = []
    for path in DOCUMENTS:
        for language, block in re.findall(r"```([\w-]*)\n(.*?)```", path.read_text(encoding="utf-8"), re.S):
            if language not in ("", "sh", "bash", "console"):
                continue
            for line in block.replace("\\\n", " ").splitlines():
                text = line.strip().removeprefix("$ ")
                if text.startswith("pumpjack "):
                    found.append((path.name, text))
    return found


def _stages(text: str) -> list[list[str]] | None:
    """The pumpjack stages of a pipeline as argument lists, or None when it cannot run here."""
    stages = []
    for part in text.split(" #")[0].split("|"):
        words = shlex.split(part)
        if not words:
            return None
        if words[0] != "pumpjack":
            continue  # a shell filter (cut, head) after the command
        words = words[1:words.index(">")] if ">" in words else words[1:]
        for i, word in enumerate(words):
            previous = words[i - 1] if i else ""
            if previous in OUTPUTS:
                continue
            if PLACEHOLDER.match(word) or word.startswith("tcp://"):
                return None
            if re.search(r"\.(csv|toml|yaml|yml|json|sqlite)$", word) and not (REPO_ROOT / word).exists():
                return None
        stages.append(words)
    return stages or None


CASES = [(name, text, _stages(text)) for name, text in _commands()]
RUNNABLE = [(name, text, stages) for name, text, stages in CASES if stages]


def test_the_documents_show_commands_that_run_here():
    assert len(RUNNABLE) >= 12 and {name for name, _, _ in RUNNABLE} >= {"README.md", "torque.md", "downhole.md"}


#: A summary line of the terminal table: name, value, unit.
SUMMARY_LINE = re.compile(r"^([a-z][a-z0-9_]*)\s+(-?\d[\d.]*(?:e[+-]?\d+)?)\s+(\S+)(?:\s|$)")


def _shown_outputs() -> dict[tuple[str, str], dict[str, tuple[str, str]]]:
    """The summary lines (name -> value, unit) each single-command console example that prints
    a table shows, by (document, command)."""
    found = {}
    for path in DOCUMENTS:
        for language, block in re.findall(r"```([\w-]*)\n(.*?)```", path.read_text(encoding="utf-8"), re.S):
            if language != "console":
                continue
            for example in re.split(r"^(?=\$ )", block, flags=re.M):
                command, _, output = example.partition("\n")
                text = command.strip().removeprefix("$ ")
                stages = _stages(text) if command.startswith("$ pumpjack ") else None
                shown = {m[1]: (m[2], m[3]) for m in map(SUMMARY_LINE.match, output.splitlines()) if m}
                if stages and len(stages) == 1 and "|" not in command and shown:
                    found[(path.name, text)] = shown
    return found


SHOWN = _shown_outputs()


#: The standard output of each command line run, by its text and whether it ran as a terminal shows
#: it: a command that two documents show runs once.
_PRINTED: dict[tuple[str, bool], str] = {}


@pytest.mark.parametrize(("name", "text", "stages"), RUNNABLE, ids=[f"{n}: {t[:60]}" for n, t, _ in RUNNABLE])
def test_a_documented_command_runs(run_cli, tmp_path, monkeypatch, name, text, stages):
    """Each documented command runs; a console example that shows summary values (name,
    value, unit) runs once as a terminal shows it (``-f table``, a terminal's default) and
    prints those values."""
    monkeypatch.chdir(REPO_ROOT)
    shown = SHOWN.get((name, text))
    key = (text, bool(shown))
    if key not in _PRINTED:
        out = None
        for words in stages:
            argv = [str(tmp_path / Path(word).name) if i and words[i - 1] in OUTPUTS else word
                    for i, word in enumerate(words)]
            if out is not None:
                monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(out.encode("utf-8"))))
            code, out, err = run_cli(*argv, *(("-f", "table") if shown else ()))
            assert code == 0, f"{name}: {text}: {err}"
            assert "error" not in err, err
        _PRINTED[key] = out
    out = _PRINTED[key]
    if shown:
        printed = {m[1]: (m[2], m[3]) for m in map(SUMMARY_LINE.match, out.splitlines()) if m}
        assert {key: printed.get(key) for key in shown} == shown


def test_the_documents_show_numbers():
    assert len(SHOWN) >= 3 and sum(len(shown) for shown in SHOWN.values()) >= 40
    assert set(SHOWN) <= {(name, text) for name, text, _ in RUNNABLE}  # each example is run
