"""One module per `pumpjack` subcommand."""
