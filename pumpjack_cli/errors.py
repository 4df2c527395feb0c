"""Exceptions that reach the user as one line on stderr with exit code 2.

Everything the user can get wrong (a config file, a unit name, an impossible
geometry, a bad option value) raises a subclass of :class:`PumpjackError`; the CLI
boundary in :mod:`pumpjack_cli.cli` prints ``pumpjack: error: <message>`` and exits
with code 2. Programming errors are left to raise normally.
"""


class PumpjackError(Exception):
    """A problem with the user's input, reported without a traceback."""


class ConfigError(PumpjackError, ValueError):
    """A unit file that cannot be read or does not validate."""


class GeometryError(PumpjackError, ValueError):
    """A linkage that cannot assemble or cannot turn through a full revolution."""


class DynamicsError(PumpjackError, ValueError):
    """A machine whose motion cannot be computed: inertia, motor, well data or a failed solve."""


class PredictionError(PumpjackError, ValueError):
    """A well whose cards cannot be predicted: rod string, pump or fluid data, or a solve that does not converge."""
