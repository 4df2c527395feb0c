"""The layers hold: who imports whom, what start-up imports, and the command table.

Layers (docs/architecture.md): core <- config <- analysis (run layer) <- render <- commands.
The core imports nothing of the layers above it and no I/O or validation library; the
file readers (readers/) import only errors, quantities, text_input and names of this package;
commands never import each other; ``--help``, ``--version`` and ``units`` import
neither numpy nor a unit model.
"""

from __future__ import annotations

import ast
import functools
import os
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from pumpjack_cli.cli import COMMANDS, command_function

from helpers import REPO_ROOT, syntax_tree

PACKAGE = REPO_ROOT / "pumpjack_cli"


@functools.cache
def _imports(path: Path) -> frozenset[str]:
    """Absolute module names a file imports (relative imports resolved against its package)."""
    package = path.relative_to(REPO_ROOT).with_suffix("").parts[:-1]
    found: set[str] = set()
    for node in ast.walk(syntax_tree(path)):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = list(package[: len(package) - node.level + 1]) if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            found.add(module)
            found |= {f"{module}.{alias.name}" for alias in node.names}
    return frozenset(found)


def _modules(folder: str) -> list[Path]:
    return sorted((PACKAGE / folder).rglob("*.py"))


def _offences(paths, offending) -> list[str]:
    """``file: what`` for each of ``paths`` for which ``offending(path)`` finds something."""
    return [f"{path.relative_to(REPO_ROOT)}: {found}" for path in paths if (found := offending(path))]


def test_commands_never_import_each_other():
    commands = _modules("commands")
    names = {path: f"pumpjack_cli.commands.{path.stem}" for path in commands if path.stem != "__init__"}
    bad = _offences(commands, lambda path: sorted(_imports(path) & (set(names.values()) - {names.get(path)})))
    assert not bad, "; ".join(bad)


FORBIDDEN = {
    "core": ("pumpjack_cli.config", "pumpjack_cli.analysis", "pumpjack_cli.render", "pumpjack_cli.commands",
             "pumpjack_cli.cli", "pumpjack_cli.options", "pumpjack_cli.readers", "pydantic", "typer", "rich"),
    "config": ("pumpjack_cli.analysis", "pumpjack_cli.render", "pumpjack_cli.commands", "pumpjack_cli.cli",
               "pumpjack_cli.options", "typer", "rich"),
    "analysis": ("pumpjack_cli.render", "pumpjack_cli.commands", "pumpjack_cli.cli", "pumpjack_cli.options",
                 "typer", "rich"),
}


def test_layers_import_only_downwards():
    bad = [offence for layer, forbidden in FORBIDDEN.items() for offence in _offences(
        _modules(layer), lambda path: sorted(name for name in _imports(path) if name.startswith(forbidden)))]
    assert not bad, f"imports of a layer above: {'; '.join(bad)}"


#: What the readers (pumpjack_cli/readers/) may import of this package: nothing but these and each other
#: (names: the numpy-free catalogue of output names, so that a card reader knows the tool's own outputs).
READERS_IMPORT = ("pumpjack_cli.errors", "pumpjack_cli.quantities", "pumpjack_cli.text_input", "pumpjack_cli.names",
                  "pumpjack_cli.readers")


def test_readers_import_only_errors_quantities_and_text_input():
    bad = _offences(_modules("readers"), lambda path: sorted(
        name for name in _imports(path) if name.startswith(("pumpjack_cli", "pydantic", "typer", "rich"))
        and not name.startswith(READERS_IMPORT)))
    assert not bad, "; ".join(bad)


def test_tests_do_not_import_command_modules():
    bad = _offences(sorted((REPO_ROOT / "tests").rglob("test_*.py")), lambda path: sorted(
        name for name in _imports(path) if name.startswith("pumpjack_cli.commands")))
    assert not bad, "; ".join(bad)


def test_startup_imports_no_numpy_and_no_unit_model():
    """Each command line run in turn in one fresh interpreter, the heavy modules looked for after
    each: modules only accumulate, so none found after the last means none imported by any."""
    argvs = [["--help"], ["--version"], ["-h"], ["units", "-f", "csv"],
             ["units", "--catalogue", str(REPO_ROOT / "samples" / "catalogue.csv"), "-f", "csv"]]
    probe = (
        "import sys, io, contextlib\n"
        "from pumpjack_cli.cli import main\n"
        f"for argv in {argvs!r}:\n"
        "    with contextlib.redirect_stdout(io.StringIO()):\n"
        "        code = main(argv)\n"
        "    heavy = sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'pydantic', 'pumpjack_cli.config.beam_unit',\n"
        "                               'pumpjack_cli.config.slider_crank') if m in sys.modules)\n"
        "    print(argv, code, heavy)\n"
    )
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert out.splitlines() == [f"{argv} 0 []" for argv in argvs]


@pytest.mark.parametrize("name", list(COMMANDS))
def test_command_summary_is_the_docstring_first_line(name):
    found = command_function(name)
    text = found.info.help if hasattr(found, "info") else found.__doc__  # a command group (typer app) or a function
    assert COMMANDS[name][2] == text.splitlines()[0]


def test_every_package_is_listed_for_installation():
    listed = set(tomllib.loads((REPO_ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(REPO_ROOT).parts) for p in PACKAGE.rglob("__init__.py")}
    found.add("pumpjack_cli.configs")
    assert listed == found


# --- the mechanism seam -------------------------------------------------------------

#: Modules that are mechanisms (or build them from a unit file), or models specific to the
#: conventional unit's six-link mechanism (spatial kinetostatics and the real mechanism), or
#: another kind of machine (the slider-crank of drill pumps): they may read a linkage's dimensions.
MECHANISM_MODULES = {
    "core/beam/geometry.py", "core/beam/linkage.py",
    "core/beam/spatial.py", "core/beam/kinetostatics.py", "core/beam/reactions.py", "core/beam/redundancy.py",
    "config/conventional.py", "config/geometry_names.py",
}
#: The class I four-bar's own dimensions and helpers; everything else asks the Mechanism protocol.
CLASS_I_ATTRIBUTES = {"front_arm", "rear_arm", "crank_radius", "pitman", "horizontal_offset", "vertical_offset",
                      "crank_shaft", "frame_length", "pin_rates"}
ARMS = {"front_arm", "horsehead_arm"}


def _seam_modules() -> list[Path]:
    return [p for p in sorted(PACKAGE.rglob("*.py")) if str(p.relative_to(PACKAGE)) not in MECHANISM_MODULES
            and "slider_crank" not in p.parts and p.stem != "slider_crank"]


def _names(node: ast.AST) -> set[str]:
    return {n.attr for n in ast.walk(node) if isinstance(n, ast.Attribute)} | {
        n.id for n in ast.walk(node) if isinstance(n, ast.Name)}


def _class_i_reads(tree: ast.AST) -> list[str]:
    """The class-I dimensions a module reads, with their lines (a section's own field is not one)."""
    return sorted({f"{node.attr} (line {node.lineno})" for node in ast.walk(tree)
                   if isinstance(node, ast.Attribute) and node.attr in CLASS_I_ATTRIBUTES
                   and not (isinstance(node.value, ast.Name) and node.value.id == "self")})


def _torque_factors(tree: ast.AST) -> list[int]:
    """The lines where a module multiplies a beam rate by an arm: a torque factor computed."""
    return [node.lineno for node in ast.walk(tree) if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult)
            and ({"beam_rate", "beam_rate2"} & _names(node.left) and ARMS & _names(node.right)
                 or {"beam_rate", "beam_rate2"} & _names(node.right) and ARMS & _names(node.left))]


def test_only_mechanisms_read_linkage_dimensions_or_compute_a_torque_factor():
    modules = _seam_modules()
    read = _offences(modules, lambda path: _class_i_reads(syntax_tree(path)))
    assert not read, f"class-I dimensions read outside the mechanisms (use the Mechanism protocol): {'; '.join(read)}"
    products = _offences(modules, lambda path: _torque_factors(syntax_tree(path)))
    assert not products, f"a torque factor computed outside the mechanisms (ask the mechanism): {'; '.join(products)}"


def test_the_seam_test_sees_a_torque_factor():
    """The checks above fail on the patterns they forbid (a test that can fail)."""
    tree = ast.parse("tf = unit.front_arm * m.beam_rate\nother = m.beam_rate * q.horsehead_arm\nr = unit.crank_radius\n")
    assert _torque_factors(tree) == [1, 2]
    assert _class_i_reads(tree) == ["crank_radius (line 3)", "front_arm (line 1)"]


def test_the_core_type_checks(tmp_path):
    """mypy over the numerical core: 0 errors (settings in pyproject.toml's [tool.mypy]); no
    cache written (``--cache-dir /dev/null``, mypy's way to turn it off: a test's cache is cold)."""
    pytest.importorskip("mypy")
    done = subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", os.devnull,
                           "--config-file", str(REPO_ROOT / "pyproject.toml"), str(PACKAGE / "core")],
                          capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
