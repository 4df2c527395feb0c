"""The layers hold: who imports whom, what start-up imports, and the command table.

Layers (docs/architecture.md): core <- config <- analysis (run layer) <- render <- commands.
The core imports nothing of the layers above it and no I/O or validation library;
commands never import each other; ``--help``, ``--version`` and ``units`` import
neither numpy nor a unit model.
"""

from __future__ import annotations

import ast
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from pumpjack_cli.cli import COMMANDS, command_function

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "pumpjack_cli"


def _imports(path: Path) -> set[str]:
    """Absolute module names a file imports (relative imports resolved against its package)."""
    package = path.relative_to(ROOT).with_suffix("").parts[:-1]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = list(package[: len(package) - node.level + 1]) if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            found.add(module)
            found |= {f"{module}.{alias.name}" for alias in node.names}
    return found


def _modules(folder: str) -> list[Path]:
    return sorted((PACKAGE / folder).rglob("*.py"))


@pytest.mark.parametrize("path", _modules("commands"), ids=lambda p: p.name)
def test_commands_never_import_each_other(path):
    others = {f"pumpjack_cli.commands.{p.stem}" for p in _modules("commands") if p != path and p.stem != "__init__"}
    assert not _imports(path) & others


FORBIDDEN = {
    "core": ("pumpjack_cli.config", "pumpjack_cli.analysis", "pumpjack_cli.render", "pumpjack_cli.commands",
             "pumpjack_cli.cli", "pumpjack_cli.options", "pumpjack_cli.readers", "pydantic", "typer", "rich"),
    "config": ("pumpjack_cli.analysis", "pumpjack_cli.render", "pumpjack_cli.commands", "pumpjack_cli.cli",
               "pumpjack_cli.options", "typer", "rich"),
    "analysis": ("pumpjack_cli.render", "pumpjack_cli.commands", "pumpjack_cli.cli", "pumpjack_cli.options",
                 "typer", "rich"),
}


@pytest.mark.parametrize("layer,path", [(layer, p) for layer in FORBIDDEN for p in _modules(layer)],
                         ids=lambda x: x if isinstance(x, str) else x.name)
def test_layers_import_only_downwards(layer, path):
    bad = {name for name in _imports(path) if name.startswith(FORBIDDEN[layer])}
    assert not bad, f"{path.relative_to(ROOT)} imports {sorted(bad)}"


@pytest.mark.parametrize("path", sorted((ROOT / "tests").glob("test_*.py")), ids=lambda p: p.name)
def test_tests_do_not_import_command_modules(path):
    assert not {name for name in _imports(path) if name.startswith("pumpjack_cli.commands")}


@pytest.mark.parametrize("argv", [["--help"], ["--version"], ["-h"], ["units", "-f", "csv"]])
def test_startup_imports_no_numpy_and_no_unit_model(argv):
    probe = (
        "import sys, io, contextlib\n"
        "from pumpjack_cli.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    code = main({argv!r})\n"
        "heavy = sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'pumpjack_cli.config.beam_unit',\n"
        "                           'pumpjack_cli.config.slider_crank') if m in sys.modules)\n"
        "print(code, heavy)\n"
    )
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "0 []"


@pytest.mark.parametrize("name", list(COMMANDS))
def test_command_summary_is_the_docstring_first_line(name):
    found = command_function(name)
    text = found.info.help if hasattr(found, "info") else found.__doc__  # a command group (typer app) or a function
    assert COMMANDS[name][2] == text.splitlines()[0]


def test_every_package_is_listed_for_installation():
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(ROOT).parts) for p in PACKAGE.rglob("__init__.py")}
    found.add("pumpjack_cli.configs")
    assert listed == found
