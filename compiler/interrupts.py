"""Signals during a write: SIGTERM, SIGHUP and SIGINT become an exception, so the writer's clean-up
runs (temps removed, renamed files put back) before the process exits with 128 + the signal's number.

    with SignalGuard():          # the output writer's staging and commit, a bake's scratch folder
        ...                      # a signal here raises Interrupted; `with` blocks clean up on the way out

The outermost guard prints one line (`cnlmc: interrupted by SIGTERM: ...`) once everything inside
it has cleaned up; `Interrupted` is a SystemExit, so the interpreter exits with its code and no
traceback. A guard only takes over a signal whose handler is the default one (a program that set
its own handler keeps it) and only in the main thread (where Python delivers signals). A second
signal while cleaning up is ignored. SIGKILL cannot be caught: the temps it leaves behind carry the
writer's process id and the next writer removes them (cnlmc.folder_lock).
"""

from __future__ import annotations

import signal
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from types import FrameType, TracebackType
from typing import Any

SIGNALS = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP", "SIGINT") if hasattr(signal, name))
DEFAULT_HANDLERS = (signal.SIG_DFL, signal.default_int_handler)


class Interrupted(SystemExit):
    """A signal arrived during a write: exit 128 + its number once the clean-up has run."""

    def __init__(self, signum: int) -> None:
        super().__init__(128 + signum)
        self.signum = signum

    @property
    def signal_name(self) -> str:
        try:
            return signal.Signals(self.signum).name
        except ValueError:
            return f"signal {self.signum}"


class _RaiseInterrupted:
    """The handler a guard installs: the first signal raises, later ones (during clean-up) are ignored."""

    def __init__(self) -> None:
        self.fired = False

    def __call__(self, signum: int, frame: FrameType | None) -> None:
        if self.fired:
            return
        self.fired = True
        raise Interrupted(signum)


class SignalGuard:
    """See the module docstring. Nested guards share the outer one's handler."""

    def __init__(self) -> None:
        self.previous: dict[int, Any] = {}
        self.outermost = False

    def __enter__(self) -> SignalGuard:
        if threading.current_thread() is not threading.main_thread():
            return self
        handler = _RaiseInterrupted()
        for signum in SIGNALS:
            current = signal.getsignal(signum)
            if isinstance(current, _RaiseInterrupted):
                continue  # an outer guard already has it
            if current in DEFAULT_HANDLERS:
                self.previous[signum] = current
                signal.signal(signum, handler)
        self.outermost = bool(self.previous)
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None) -> None:
        for signum, previous in self.previous.items():
            signal.signal(signum, previous)
        self.previous = {}
        if self.outermost and isinstance(exc, Interrupted):
            print(
                f"cnlmc: interrupted by {exc.signal_name}: nothing was written "
                "(temporary files removed, replaced files put back)",
                file=sys.stderr,
            )


@contextmanager
def signals_deferred() -> Iterator[None]:
    """SIGTERM, SIGHUP and SIGINT held back while a C library writes one file (an image encoder
    interrupted between its calls leaves a half-open file that complains on stderr when it is
    finalised: 'libpng error: No IDATs written'); a signal that arrives meanwhile is delivered, and
    a guard's clean-up runs, as soon as the block ends. Main thread only (elsewhere a no-op)."""
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, SIGNALS)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)
