"""Atomic output: a file appears whole or not at all; an existing file survives a failure."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import Protocol


class Artifact(Protocol):
    """What is written: a file name relative to the output, and its content (a backend's Artifact)."""

    @property
    def name(self) -> str: ...

    @property
    def content(self) -> str | bytes: ...


def write_atomic(path: Path, content: str | bytes) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    data = content.encode("utf-8") if isinstance(content, str) else content
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.chmod(tmp, usual_mode())  # mkstemp makes 0600; give the file the usual mode
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def usual_mode() -> int:
    """The mode a plain open() would give a new file under the current umask."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def looks_like_file(out: str) -> bool:
    target = Path(out)
    return not out.endswith(("/", os.sep)) and not target.is_dir() and bool(target.suffix)


def write_artifacts(artifacts: Sequence[Artifact], out: str) -> list[Path]:
    """`out` a file path: the first (main) artifact goes there, the others beside it.
    `out` a folder (existing, ending in '/', or without a suffix): every artifact goes into it."""
    target = Path(out)
    if looks_like_file(out) or (len(artifacts) == 1 and not target.is_dir() and not out.endswith(("/", os.sep))):
        paths = [target] + [target.parent / a.name for a in artifacts[1:]]
    else:
        paths = [target / a.name for a in artifacts]
    for path, artifact in zip(paths, artifacts):
        write_atomic(path, artifact.content)
    return paths
