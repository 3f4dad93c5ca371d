"""How many processes compile a document (cnlmc.parallel does the work): a module of its own so a
small compile decides it without importing multiprocessing."""

from __future__ import annotations

import os

PARALLEL_MIN_LINES = 5000  # below this, starting the processes costs more than they save
MAX_WORKERS = 8
WORKERS_VARIABLE = "CNLMC_WORKERS"


def worker_count(source: str, requested: int | None = None) -> int:
    """How many processes compile `source`: `requested`, else $CNLMC_WORKERS (a positive integer),
    else the CPUs this process may use; 1 below PARALLEL_MIN_LINES lines or where fork is missing."""
    wanted = requested if requested is not None else _workers_from_environment()
    if wanted <= 1 or max(source.count("\n"), source.count("\r")) + 1 < PARALLEL_MIN_LINES:
        return 1
    import multiprocessing  # only for a document large enough to share out

    if "fork" not in multiprocessing.get_all_start_methods():
        return 1
    return min(wanted, MAX_WORKERS)


def _workers_from_environment() -> int:
    value = os.environ.get(WORKERS_VARIABLE, "").strip()
    if value.isdigit() and int(value) > 0:
        return int(value)
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not on Linux
        return os.cpu_count() or 1
