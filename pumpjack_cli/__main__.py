"""`python -m pumpjack_cli` and the `pumpjack` console script."""

import os
import sys

from .cli import main


def run() -> None:
    # One BLAS thread (unless the environment says otherwise), set before numpy is imported: a
    # command's matrices are small, and `batch` runs a process on every core; OpenBLAS's own
    # threads only spin beside them (docs/performance.md: `predict` 1.18 s of CPU with them, 0.71 s without).
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    sys.exit(main(whole_process=True))


if __name__ == "__main__":
    run()
