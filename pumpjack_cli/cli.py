"""The `pumpjack` command: subcommands loaded on demand and the one error boundary.

Every user error (:class:`~pumpjack_cli.errors.PumpjackError`, a bad option) ends
as one line ``pumpjack: error: ...`` on stderr and exit code 2; ``--debug`` shows
the traceback instead. A subcommand's module (and with it numpy, scipy and the unit
models) is imported only when that subcommand runs; ``pumpjack --help``,
``--version`` and the listing of commands cost no more than typer itself.
"""

from __future__ import annotations

import functools
import gc
import importlib
import sys
import warnings

import typer
from typer.core import TyperGroup

from . import __version__
from .errors import PumpjackError, collected_warnings
from .text_input import forget_inputs

#: Subcommands: name -> (module under pumpjack_cli.commands, function, one-line summary).
#: The summary is the first line of the function's docstring (a test keeps them equal).
COMMANDS: dict[str, tuple[str, str, str]] = {
    "units": ("units", "units", "List the bundled units with their stroke; name one in any command, or give a file path."),
    "kinematics": ("kinematics", "kinematics",
                   "Exact kinematics of the polished rod, beam and pitman for uniform crank rotation."),
    "reactions": ("reactions", "reactions",
                  "Joint reactions and balancing torque of the rational mechanism from a dynamometer card."),
    "compare-redundancy": ("compare_redundancy", "compare_redundancy",
                           "Real mechanism (redundant constraints, elastic pitmans, errors) against the rational one."),
    "inertia-error": ("inertia_error", "inertia_error",
                      "Error of the approximate inertia-force laws against the exact motion."),
    "dynamics": ("dynamics", "dynamics", "Non-uniform crank rotation from the machine's equation of motion."),
    "torque": ("torque", "torque", "Gearbox torque, counterbalance and loading of a unit from a dynamometer card."),
    "downhole": ("downhole", "downhole", "Pump card from a surface dynamometer card through the rod string's wave equation."),
    "predict": ("predict", "predict", "Surface and pump cards predicted from unit, rods, pump and fluid level."),
    "report": ("report", "report",
               "One well on one page: unit, cards, torque and ratings, balance, rod loading, pump, provenance."),
    "batch": ("batch", "app", "A field's dynamometer cards through torque and downhole into an SQLite results store."),
}
CONTEXT = {"help_option_names": ["-h", "--help"]}


def command_function(name: str):
    """The function behind a subcommand, importing its module."""
    module, function, _ = COMMANDS[name]
    return getattr(importlib.import_module(f".commands.{module}", __package__), function)


class LazyCommands(TyperGroup):
    """A command group whose subcommands are built from their modules only when used."""

    def list_commands(self, ctx) -> list[str]:
        return list(COMMANDS)

    def get_command(self, ctx, name: str):
        if name not in COMMANDS:
            return None
        return _built_command(name)

    def format_commands(self, ctx, formatter) -> None:
        with formatter.section("Commands"):
            formatter.write_dl([(name, summary) for name, (_, _, summary) in COMMANDS.items()])


@functools.cache
def _built_command(name: str):
    """The click command of a subcommand, built from its function once per process (typer reads
    every option's annotation to build it; a library or test calling :func:`main` repeatedly
    reuses it: a command holds no state of a run)."""
    found = command_function(name)
    if isinstance(found, typer.Typer):
        group = typer.main.get_group(found)
        group.name = name
        return group
    single = typer.Typer(add_completion=False, pretty_exceptions_enable=False, rich_markup_mode=None,
                         context_settings=CONTEXT)
    single.command(name)(found)
    command = typer.main.get_command(single)
    command.name = name
    return command


def _version(value: bool) -> None:
    if value:
        sys.stdout.write(f"pumpjack {__version__}\n")
        raise typer.Exit()


app = typer.Typer(
    cls=LazyCommands,
    name="pumpjack",
    help="Engineering calculator for beam pumping units: exact kinematics and more.",
    epilog="Add --debug anywhere on the command line to see a traceback on errors.",
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
    context_settings=CONTEXT,
)


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", help="print the version and exit", callback=_version,
                                 is_eager=True),
) -> None:
    """Engineering calculator for beam pumping units (pumpjacks)."""


@functools.cache
def _built_group():
    """The click group of :data:`app`, built once per process (as :func:`_built_command`)."""
    return typer.main.get_command(app)


def _fail(message: str) -> int:
    sys.stderr.write(f"pumpjack: error: {message}\n")
    return 2


def _foreign_number(args: list[str]) -> str | None:
    """The message for a number written with digits other than 0-9 (Python reads ``٥`` or ``５``
    as 5; the quantity options and the card readers refuse them, and so do the plain numeric
    options), else None."""
    for i, arg in enumerate(args):
        option, _, value = arg.partition("=") if arg.startswith("--") else ("", "", arg)
        if value.isascii():
            continue
        try:
            float(value)
        except ValueError:
            continue
        name = option or (args[i - 1] if i and args[i - 1].startswith("-") else "argument")
        return f"{name}: '{ascii(value)[1:-1]}': write numbers with the digits 0-9"
    return None


def main(argv: list[str] | None = None, *, whole_process: bool = False) -> int:
    """Run the CLI; return the exit code (console-script entry point).

    Floating-point warnings are not printed: a result that is not finite is refused by
    the renderer with one line naming it. The run's own warnings
    (:func:`~pumpjack_cli.errors.warn`) follow on stderr when it succeeds; a failed run
    prints only its error line. ``whole_process`` (the console script, one command per
    process): the subcommand's module is imported first and what the imports made is
    frozen out of the garbage collector's walks (:func:`gc.freeze`): modules, classes and
    schemas live as long as the process, and walking them again in every full collection
    and at exit costs a tenth of a short command's time.
    """
    args = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in args
    args = [arg for arg in args if arg != "--debug"] or ["--help"]
    foreign = _foreign_number(args)
    if foreign:
        return _fail(foreign)
    command = _built_group()
    forget_inputs()
    with collected_warnings() as noted:
        try:
            if whole_process and args[0] in COMMANDS:
                _built_command(args[0])
                gc.freeze()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                code = command.main(args=args, prog_name="pumpjack", standalone_mode=False)
        except (PumpjackError, typer.TyperException) as exc:
            if debug:
                raise
            message = exc.format_message() if isinstance(exc, typer.TyperException) else str(exc)
            return _fail(" ".join(message.split()))
        except BrokenPipeError:
            # The reader of a pipe (`| head`) went away: stop quietly, as cat does.
            from .render import drop_stdout

            drop_stdout()
            return 1
        except MemoryError:
            if debug:
                raise
            return _fail("not enough memory for this computation: use fewer --steps or a smaller input")
        except KeyboardInterrupt:
            return 130
    for warning in noted:
        sys.stderr.write(f"pumpjack: warning: {warning}\n")
    return code if isinstance(code, int) else 0


if __name__ == "__main__":
    sys.exit(main(whole_process=True))
