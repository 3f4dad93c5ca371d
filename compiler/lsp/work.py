"""Where the server's compiler work runs: one thread, in time slices.

All work that touches the compiler (analysis, hover, colours, tokens, ...) runs on one worker
thread, so the lexicon's caches are only ever used from one thread, and the event loop stays
free to read messages. Long work is a generator of small steps; `Worker.drive` runs steps for
at most SLICE_SECONDS, then hands the thread back: a request that arrived meanwhile (a hover)
runs between two slices, and a request the client cancelled ($/cancelRequest) or that a newer
edit made stale stops at the end of the current slice.
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable, Generator, Iterable
from concurrent.futures import ThreadPoolExecutor
from typing import Any, TypeVar

T = TypeVar("T")
Item = TypeVar("Item")
Steps = Generator[None, None, T]

SLICE_SECONDS = 0.02


class Worker:
    """The single compiler thread; its lifetime is the server's."""

    def __init__(self) -> None:
        self._pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="cnlmc-analysis")

    async def call(self, function: Callable[..., T], *args: Any) -> T:
        """`function(*args)` on the worker thread (one short piece of work)."""
        return await asyncio.get_running_loop().run_in_executor(self._pool, function, *args)

    async def drive(self, steps: Steps[T]) -> T:
        """Run a generator of steps to its end, one time slice at a time; cancelling the awaiting
        task stops it after the current slice."""
        while True:
            done, value = await self.call(_run_slice, steps)
            if done:
                return value  # type: ignore[return-value]

    async def collect(self, batches: Iterable[list[Item]]) -> list[Item]:
        """Everything a lazy sequence of batches yields (one batch per line, say), in slices."""
        return await self.drive(_gather(batches))

    def close(self) -> None:
        self._pool.shutdown(wait=False, cancel_futures=True)


def _run_slice(steps: Steps[T]) -> tuple[bool, T | None]:
    deadline = time.perf_counter() + SLICE_SECONDS
    try:
        while time.perf_counter() < deadline:
            next(steps)
    except StopIteration as finished:
        return True, finished.value
    return False, None


def _gather(batches: Iterable[list[Item]]) -> Steps[list[Item]]:
    out: list[Item] = []
    for batch in batches:
        out += batch
        yield
    return out
