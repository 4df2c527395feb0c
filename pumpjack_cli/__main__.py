"""`python -m pumpjack_cli` and the `pumpjack` console script."""

import sys

from .cli import main


def run() -> None:
    sys.exit(main(whole_process=True))


if __name__ == "__main__":
    run()
