"""One writer per output folder at a time, and the temps a killed writer left behind.

- **Temp names carry the writer's process id**: `.NAME.~cnlmc.PID.XXXXXXXX.ext` (a staged file)
  and `.NAME.~cnlmc.PID.bak` (an old file kept while a commit runs). `temp_prefix(name)` makes them.
- **The folder lock** (`FolderLock`): `fcntl.flock` on `.cnlmc.lock` in the folder, held from the
  first file staged there until the commit or the clean-up is done; the lock file is removed when
  it is released (nothing is left behind). A second writer waits up to `CNLMC_LOCK_WAIT` seconds
  (default 60) for the first to finish, then fails with a usage error naming the folder and the
  process that holds it. The kernel releases the lock of a killed process. On a file system
  without locks the folder is written unlocked.
- **Stale temps**: once it holds the lock, a writer removes the temps and backups in that folder
  whose process is no longer alive (a writer killed by SIGKILL, a power cut).
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import os
import re
import stat
import time
from pathlib import Path

from .errors import UsageError

LOCK_NAME = ".cnlmc.lock"
TEMP_MARK = "~cnlmc"
STALE = re.compile(r"^\..*\." + re.escape(TEMP_MARK) + r"\.(\d+)\.")
WAIT_VARIABLE = "CNLMC_LOCK_WAIT"
DEFAULT_WAIT_S = 60.0
POLL_S = 0.05
#: flock's errors on a file system that has no locks
UNLOCKABLE = {errno.ENOLCK, errno.EOPNOTSUPP, errno.ENOTSUP, errno.EINVAL}
#: the longest part of a destination's name a temp's name repeats (the temp stays under NAME_MAX)
TEMP_NAME_PART = 100


def temp_prefix(name: str) -> str:
    """The start of a temp's name for the file `name`: hidden, with this process's id."""
    return f".{name[:TEMP_NAME_PART]}.{TEMP_MARK}.{os.getpid()}."


def backup_name(name: str) -> str:
    return f"{temp_prefix(name)}bak"


def lock_wait() -> float:
    """How long a writer waits for another one's lock: CNLMC_LOCK_WAIT seconds, default 60."""
    raw = os.environ.get(WAIT_VARIABLE, "")
    try:
        value = float(raw) if raw.strip() else DEFAULT_WAIT_S
    except ValueError:
        raise UsageError(f"{WAIT_VARIABLE}={raw!r} must be a number of seconds") from None
    if not 0 <= value <= 86400:
        raise UsageError(f"{WAIT_VARIABLE}={raw!r} must be between 0 and 86400 seconds")
    return value


def process_alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return pid > 0
    return True


def remove_stale_temps(folder: Path) -> list[Path]:
    """Remove the temps and backups in `folder` whose writer is no longer alive; returns them."""
    removed = []
    with contextlib.suppress(OSError), os.scandir(folder) as entries:
        for entry in entries:
            found = STALE.match(entry.name)
            if found is None or process_alive(int(found.group(1))):
                continue
            with contextlib.suppress(OSError):
                if stat.S_ISREG(entry.stat(follow_symlinks=False).st_mode):
                    os.unlink(entry.path)
                    removed.append(Path(entry.path))
    return removed


class FolderLock:
    """The lock on one output folder (see the module docstring). `acquire` waits up to `wait` seconds."""

    def __init__(self, folder: Path, wait: float | None = None) -> None:
        self.folder = folder
        self.path = folder / LOCK_NAME
        self.wait = lock_wait() if wait is None else wait
        self.fd: int | None = None

    def acquire(self) -> None:
        deadline = time.monotonic() + self.wait
        while self.fd is None:
            fd = self._open()
            if self._try_lock(fd):
                self.fd = fd
                break
            os.close(fd)
            if time.monotonic() >= deadline:
                raise self._busy()
            time.sleep(POLL_S)
        with contextlib.suppress(OSError):  # a read-only lock file keeps no pid
            os.ftruncate(self.fd, 0)
            os.write(self.fd, f"{os.getpid()}\n".encode())
        remove_stale_temps(self.folder)

    def _open(self) -> int:
        """The lock file, for writing (to record the pid) or, when another user's killed writer
        left it behind and it is not ours to write, for reading: flock needs no write access."""
        flags = os.O_CREAT | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
        try:
            try:
                return os.open(self.path, flags | os.O_RDWR, 0o644)
            except PermissionError:
                return os.open(self.path, flags | os.O_RDONLY, 0o644)
        except OSError as exc:
            reason = exc.strerror or errno.errorcode.get(exc.errno or 0, str(exc))
            raise UsageError(f"cannot write into '{self.folder}': {reason}") from None

    def _try_lock(self, fd: int) -> bool:
        """Lock `fd`; False when another process holds it, or when the file was removed (released)
        after this process opened it (then the caller opens the new one)."""
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return False
        except OSError as exc:
            if exc.errno not in UNLOCKABLE:
                raise
            return True  # a file system without locks (some FUSE mounts): written unlocked, as before
        try:
            now = os.stat(self.path, follow_symlinks=False)
        except FileNotFoundError:
            return False
        held = os.fstat(fd)
        return (now.st_dev, now.st_ino) == (held.st_dev, held.st_ino)

    def _busy(self) -> UsageError:
        holder = ""
        with contextlib.suppress(OSError, ValueError):
            holder = f" (process {int(self.path.read_text().strip())})"
        return UsageError(
            f"cannot write into '{self.folder}': another cnlmc{holder} is writing there; waited "
            f"{self.wait:g} s for it (run again when it has finished, or set {WAIT_VARIABLE} to wait longer)"
        )

    def release(self) -> None:
        if self.fd is None:
            return
        with contextlib.suppress(OSError):
            os.unlink(self.path)  # before the unlock: a waiter that opened it retries on the new file
        os.close(self.fd)
        self.fd = None
