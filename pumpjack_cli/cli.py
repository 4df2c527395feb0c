"""The `pumpjack` command: subcommands and the one error boundary.

Every user error (:class:`~pumpjack_cli.errors.PumpjackError`, a bad option) ends
as one line ``pumpjack: error: ...`` on stderr and exit code 2; ``--debug`` shows
the traceback instead.
"""

from __future__ import annotations

import sys

import typer

from .commands.dynamics import dynamics
from .commands.inertia_error import inertia_error
from .commands.compare_redundancy import compare_redundancy
from .commands.kinematics import kinematics
from .commands.reactions import reactions
from .commands.units import units
from .errors import PumpjackError

app = typer.Typer(
    name="pumpjack",
    help="Engineering calculator for beam pumping units: exact kinematics and more.",
    epilog="Add --debug anywhere on the command line to see a traceback on errors.",
    add_completion=False,
    pretty_exceptions_enable=False,
)
app.command("units")(units)
app.command("kinematics")(kinematics)
app.command("reactions")(reactions)
app.command("compare-redundancy")(compare_redundancy)
app.command("inertia-error")(inertia_error)
app.command("dynamics")(dynamics)


@app.callback()
def _root() -> None:
    """Engineering calculator for beam pumping units (pumpjacks)."""


def _fail(message: str) -> int:
    sys.stderr.write(f"pumpjack: error: {message}\n")
    return 2


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; return the exit code (console-script entry point)."""
    args = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in args
    args = [arg for arg in args if arg != "--debug"] or ["--help"]
    command = typer.main.get_command(app)
    try:
        code = command.main(args=args, prog_name="pumpjack", standalone_mode=False)
    except (PumpjackError, typer.TyperException) as exc:
        if debug:
            raise
        message = exc.format_message() if isinstance(exc, typer.TyperException) else str(exc)
        return _fail(" ".join(message.split()))
    except BrokenPipeError:
        # The reader of a pipe (`| head`) went away: stop quietly, as cat does.
        sys.stderr.close()
        return 1
    return code if isinstance(code, int) else 0


if __name__ == "__main__":
    sys.exit(main())
