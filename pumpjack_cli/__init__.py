"""pumpjack-cli: engineering calculator for beam pumping units and sucker-rod wells.

Layers: :mod:`pumpjack_cli.core` (pure numerics, SI arrays) <- :mod:`pumpjack_cli.config`
(validated unit files) <- :mod:`pumpjack_cli.analysis` (the run layer) <-
:mod:`pumpjack_cli.render` (the one renderer) <- :mod:`pumpjack_cli.commands` (one thin
module per subcommand). See ``docs/architecture.md``.
"""

__version__ = "0.3.0"
