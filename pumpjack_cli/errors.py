"""Exceptions that reach the user as one line on stderr with exit code 2.

Everything the user can get wrong (a config file, a unit name, an impossible
geometry, a bad option value) raises a subclass of :class:`PumpjackError`; the CLI
boundary in :mod:`pumpjack_cli.cli` prints ``pumpjack: error: <message>`` and exits
with code 2. Programming errors are left to raise normally.
"""

import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager


class PumpjackError(Exception):
    """A problem with the user's input, reported without a traceback."""


class ConfigError(PumpjackError, ValueError):
    """A unit file that cannot be read or does not validate."""


class GeometryError(PumpjackError, ValueError):
    """A linkage that cannot assemble or cannot turn through a full revolution."""


class DynamicsError(PumpjackError, ValueError):
    """A machine whose motion cannot be computed: inertia, motor, well data or a failed solve."""


class DesignationError(PumpjackError, ValueError):
    """A pumping-unit designation that is neither an API Spec 11E nor a GOST 5866-76 one."""


class TorqueError(PumpjackError, ValueError):
    """Gearbox-torque, counterbalance or loading input that cannot give a result."""


class BalanceError(TorqueError):
    """A balance criterion that no value of the balancing variable meets on a card; ``note`` says why."""

    def __init__(self, message: str, note: str) -> None:
        super().__init__(message)
        self.note = note


class DownholeError(PumpjackError, ValueError):
    """A rod string or a dynamometer card the downhole (pump-card) calculation cannot use."""


class CardError(PumpjackError, ValueError):
    """A dynamometer card that cannot be read, contradicts itself or does not fit the unit."""


class PredictionError(PumpjackError, ValueError):
    """A well whose cards cannot be predicted: rod string, pump or fluid data, or a solve that does not converge."""


#: Collectors of warnings of this thread, innermost last (see :func:`collected_warnings`);
#: per thread, so that the cards a Dask worker analyses in parallel keep their own.
_LOCAL = threading.local()


def _collectors() -> list[list[str]]:
    if not hasattr(_LOCAL, "stack"):
        _LOCAL.stack = []
    return _LOCAL.stack


def warn(message: str) -> None:
    """A warning for the user, one line (runs of whitespace collapsed): noted by the
    innermost :func:`collected_warnings` of this thread, else written to stderr at once."""
    text = " ".join(message.split())
    stack = _collectors()
    if stack:
        stack[-1].append(text)
    else:
        sys.stderr.write(f"pumpjack: warning: {text}\n")


@contextmanager
def collected_warnings() -> Iterator[list[str]]:
    """Collect the warnings of a run instead of printing them: the CLI prints them once the
    run has succeeded and drops them when it fails (a failure is one line on stderr); a
    batch run files them with each card's outcome."""
    noted: list[str] = []
    stack = _collectors()
    stack.append(noted)
    try:
        yield noted
    finally:
        stack.pop()
