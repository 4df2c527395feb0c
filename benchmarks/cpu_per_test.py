"""A pytest plugin for ``bench_tests.py --split``: the CPU time of each test.

For each test it takes the CPU time of the process running it (``time.process_time``) and
that of the children the test started and waited for (``resource.getrusage(RUSAGE_CHILDREN)``)
before and after the test, and on the session's end writes them as JSON to the folder named by the environment variable ``PUMPJACK_CPU_SPLIT`` (one
file per process: the run's, or each xdist worker's under ``-n``).
"""

from __future__ import annotations

import json
import os
import resource
import time
from pathlib import Path

import pytest

_ROWS: list[tuple[str, float, float]] = []


def _cpu() -> tuple[float, float]:
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time(), children.ru_utime + children.ru_stime


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    own, children = _cpu()
    yield
    own_after, children_after = _cpu()
    _ROWS.append((item.nodeid, own_after - own, children_after - children))


def pytest_sessionfinish(session):
    folder = os.environ.get("PUMPJACK_CPU_SPLIT")
    if folder:
        worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
        (Path(folder) / f"{worker}.json").write_text(json.dumps(_ROWS), encoding="utf-8")
