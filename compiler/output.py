"""Atomic output: a file appears whole or not at all; an existing file survives a failure."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


def write_atomic(path: Path, content: str | bytes) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    data = content.encode("utf-8") if isinstance(content, str) else content
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the file the usual mode
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_artifacts(artifacts, out: str) -> list[Path]:
    """One artifact and a file path: write it there; otherwise into the folder `out`."""
    target = Path(out)
    if len(artifacts) == 1 and not out.endswith(("/", os.sep)) and not target.is_dir():
        write_atomic(target, artifacts[0].content)
        return [target]
    paths = [target / a.name for a in artifacts]
    for path, artifact in zip(paths, artifacts):
        write_atomic(path, artifact.content)
    return paths
