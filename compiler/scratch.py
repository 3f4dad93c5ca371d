"""Scratch folders in the system's temp folder (`$TMPDIR`), and the ones a killed process left.

A scratch folder is named `cnlmc-KIND-PID-XXXXXXXX`: it carries its process's id, so the next
process that makes one removes those of its own user whose process is no longer alive (a run
killed by SIGKILL cannot remove its own). The folder itself is removed when its `with` block ends,
and by the signal guard's clean-up (cnlmc.interrupts) on SIGTERM, SIGHUP and SIGINT.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path

from .folder_lock import process_alive


def _pattern(kind: str) -> re.Pattern[str]:
    return re.compile(rf"^cnlmc-{re.escape(kind)}-(\d+)-")


def remove_dead_scratch(kind: str, parent: str | Path | None = None) -> list[Path]:
    """Remove this user's scratch folders of `kind` whose process is no longer alive; returns them."""
    pattern, removed = _pattern(kind), []
    root = Path(parent or tempfile.gettempdir())
    with contextlib.suppress(OSError), os.scandir(root) as entries:
        for entry in entries:
            found = pattern.match(entry.name)
            if found is None or process_alive(int(found.group(1))):
                continue
            with contextlib.suppress(OSError):
                info = entry.stat(follow_symlinks=False)
                if stat.S_ISDIR(info.st_mode) and info.st_uid == os.getuid():
                    shutil.rmtree(entry.path)
                    removed.append(Path(entry.path))
    return removed


@contextlib.contextmanager
def scratch_folder(kind: str) -> Iterator[str]:
    """A new private scratch folder of `kind`, removed at the end; dead ones are removed first."""
    remove_dead_scratch(kind)
    with tempfile.TemporaryDirectory(prefix=f"cnlmc-{kind}-{os.getpid()}-") as folder:
        yield folder
