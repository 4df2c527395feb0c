"""The figures and the unit files of docs/units.md.

The SVG figures in ``docs/figures/`` are what ``docs/figures/make_unit_figures.py`` makes: the
script is run into a temporary folder and each file is compared byte for byte. The script fixes
the SVG hash salt, drops the date and starts from matplotlib's defaults, so a run is reproducible
with the same matplotlib; after an upgrade of matplotlib, run the script and commit its figures.

The page also shows unit files of its own (the TOML blocks that start with ``# NAME.toml``),
which are not in the repository, so ``test_docs_commands.py`` skips the commands that name them.
Here they are written to a temporary folder and the page's commands run on them: each summary
value the page shows is what the command prints.
"""

from __future__ import annotations

import importlib.util
import re
import shlex

import matplotlib
import pytest

from helpers import REPO_ROOT

PAGE = REPO_ROOT / "docs" / "units.md"
FIGURES = REPO_ROOT / "docs" / "figures"
SCRIPT = FIGURES / "make_unit_figures.py"
#: A summary line of the terminal table: name, value, unit.
SUMMARY_LINE = re.compile(r"^([a-z][a-z0-9_]*)\s+(-?\d[\d.]*(?:e[+-]?\d+)?)\s+(\S+)(?:\s|$)")


def _script():
    spec = importlib.util.spec_from_file_location("make_unit_figures", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def script():
    return _script()


def _page_examples(files: set[str]) -> list[tuple[str, list[str], dict[str, tuple[str, str]]]]:
    """(command, its arguments, the summary lines shown) of each console example on the page that
    names one of the page's own files."""
    found = []
    for block in re.findall(r"```console\n(.*?)```", PAGE.read_text(encoding="utf-8"), re.S):
        for example in re.split(r"^(?=\$ )", block, flags=re.M):
            command, _, output = example.partition("\n")
            words = shlex.split(command.removeprefix("$ "))
            if words[:1] == ["pumpjack"] and files & set(words):
                shown = {m[1]: (m[2], m[3]) for m in map(SUMMARY_LINE.match, output.splitlines()) if m}
                found.append((command, words[1:], shown))
    return found


EXAMPLES = _page_examples(set(_script().page_files(PAGE.read_text(encoding="utf-8"))))


def test_the_committed_figures_are_what_the_script_makes(script, tmp_path):
    def committed() -> dict[str, bytes]:  # the folder's files (Python may keep its bytecode cache beside them)
        return {path.name: path.read_bytes() for path in FIGURES.iterdir() if path.is_file()}

    before = committed()
    made = script.make(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in made)
    assert sorted(p.name for p in made) == sorted(p.name for p in FIGURES.glob("*.svg"))
    stale = [p.name for p in made if p.read_bytes() != (FIGURES / p.name).read_bytes()]
    assert not stale, (f"{stale} differ from what docs/figures/make_unit_figures.py makes with matplotlib "
                       f"{matplotlib.__version__}: run the script and commit the figures")
    assert committed() == before   # nothing written there


def test_each_kind_has_a_small_figure_on_the_page(script):
    page = PAGE.read_text(encoding="utf-8")
    for kind, _ in script.UNITS:
        figure = FIGURES / f"unit-{kind}.svg"
        assert f"](figures/{figure.name})" in page, f"docs/units.md does not show {figure.name}"
        assert figure.stat().st_size < 60_000, f"{figure.name} is {figure.stat().st_size} bytes"
        assert "<dc:date>" not in figure.read_text(encoding="utf-8")


def test_the_page_files_are_read_as_the_kinds_they_show(script):
    files = script.page_files(PAGE.read_text(encoding="utf-8"))
    assert {"rm-640d-365-168.toml", "beam-balanced-example.toml", "mark-ii-letters-as-class-i.toml"} <= set(files)
    kinds = {name: script.load(name).geometry.unit_class for name in files}
    assert kinds["rm-640d-365-168.toml"] == "reverse-mark"
    assert kinds["beam-balanced-example.toml"] == "beam-balanced"
    assert kinds["mark-ii-letters-as-class-i.toml"] == "conventional"


def test_the_page_shows_runs_on_its_files():
    assert len(EXAMPLES) >= 4 and all(shown for *_, shown in EXAMPLES)


@pytest.mark.parametrize(("command", "words", "shown"), EXAMPLES, ids=[command[2:70] for command, _, _ in EXAMPLES])
def test_a_command_on_a_page_file_prints_what_the_page_shows(script, run_cli, tmp_path, monkeypatch,
                                                              command, words, shown):
    files = script.page_files(PAGE.read_text(encoding="utf-8"))
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    monkeypatch.chdir(REPO_ROOT)      # the page's sample cards are named from the repository's root
    argv = [str(tmp_path / word) if word in files else word for word in words]
    code, out, err = run_cli(*argv, "-f", "table")
    assert code == 0, err
    assert "warning" not in err, err
    printed = {m[1]: (m[2], m[3]) for m in map(SUMMARY_LINE.match, out.splitlines()) if m}
    assert {key: printed.get(key) for key in shown} == shown
