"""Where tasks run: in this process, in a pool of worker processes, or on a Dask cluster.

Each runner takes the tasks and yields one Outcome per task as it finishes (in any order). At most
WINDOW_PER_WORKER tasks per worker are handed out ahead, so memory does not grow with the catalogue.
"""

from __future__ import annotations

import itertools
import multiprocessing
import os
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path
from typing import Any

from ..errors import UsageError
from .tasks import Outcome, Task
from .work import run_task

WINDOW_PER_WORKER = 4  # tasks handed to a worker ahead of the one it runs (our choice: keeps each busy)


def available_cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not on Linux
        return os.cpu_count() or 1


def run_serial(tasks: Iterable[Task], root: Path) -> Iterator[Outcome]:
    for task in tasks:
        yield run_task(task, str(root))


def run_pool(tasks: Iterable[Task], root: Path, jobs: int) -> Iterator[Outcome]:
    """`jobs` worker processes, started fresh (forkserver where there is one: no GL context, lock
    or thread of this process is inherited); they write their files themselves."""
    method = "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() else "spawn"
    with ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context(method)) as pool:
        submit = lambda task: pool.submit(run_task, task, str(root))
        try:
            yield from _windowed(tasks, submit, jobs * WINDOW_PER_WORKER, _pool_outcome)
        except BaseException:
            pool.shutdown(wait=False, cancel_futures=True)
            raise


def _pool_outcome(task: Task, future: Future[Outcome]) -> Outcome:
    try:
        return future.result()
    except BrokenProcessPool:
        return Outcome(
            task.key,
            task.folder,
            task.target,
            error="error: a worker process died (killed?); run the build again to finish it",
        )


def _windowed(
    tasks: Iterable[Task],
    submit: Callable[[Task], Any],
    window: int,
    outcome_of: Callable[[Task, Any], Outcome],
) -> Iterator[Outcome]:
    pending: dict[Any, Task] = {}
    queue = iter(tasks)
    for task in queue:
        pending[submit(task)] = task
        if len(pending) >= window:
            break
    while pending:
        done, _ = wait(list(pending), return_when=FIRST_COMPLETED)
        for future in done:
            yield outcome_of(pending.pop(future), future)
            following = next(queue, None)
            if following is not None:
                pending[submit(following)] = following


def run_dask(tasks: Iterable[Task], root: Path, scheduler: str, results: str) -> Iterator[Outcome]:
    """The tasks on the Dask cluster at `scheduler` (tcp://HOST:PORT). results='return': the files'
    bytes come back and are written here; 'shared': each worker writes them into `root`, which
    must be the same folder on every worker (a shared file system)."""
    try:
        from distributed import Client, as_completed
    except ImportError as exc:
        raise UsageError(f"--scheduler needs Dask: {exc}; install it with: pip install 'cnlmc[build]'") from None
    try:
        # how long to wait for the scheduler: Dask's own setting, distributed.comm.timeouts.connect
        # (30 s; DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT=5s in the environment changes it)
        client = Client(scheduler, set_as_default=False)  # type: ignore[no-untyped-call]
    except (OSError, TimeoutError, ValueError) as exc:
        raise UsageError(f"cannot reach the Dask scheduler at '{scheduler}': {exc}") from None
    where = str(root.resolve()) if results == "shared" else None
    with client:
        yield from _dask_outcomes(client, as_completed, tasks, where)


def _dask_outcomes(client: Any, as_completed: Any, tasks: Iterable[Task], where: str | None) -> Iterator[Outcome]:
    window = max(1, len(client.scheduler_info().get("workers", {}))) * WINDOW_PER_WORKER
    queue = iter(tasks)
    pending: dict[str, Task] = {}
    numbers = itertools.count()

    def submit(task: Task) -> Any:  # a Dask key the dashboard shows: target, build key, a serial number
        key = f"cnlmc-build-{task.target}-{task.key[:16]}-{next(numbers)}"
        future = client.submit(run_task, task, where, key=key, pure=False)
        pending[future.key] = task
        return future

    running = as_completed([submit(t) for _, t in zip(range(window), queue)], loop=client.loop)
    for future in running:
        task = pending.pop(future.key)
        try:
            outcome: Outcome = future.result()
        except Exception as exc:  # the worker died (KilledWorker), or the task could not run there
            outcome = Outcome(
                task.key, task.folder, task.target, error=f"error: on the Dask cluster: {type(exc).__name__}: {exc}"
            )
        future.release()
        yield outcome
        following = next(queue, None)
        if following is not None:
            running.add(submit(following))
