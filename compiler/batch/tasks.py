"""One material on one target: the task, what running it gives, and its record on disk.

A task's files go into `OUT/<material folder>/<target>/`, all at once with the task's record
(`.cnlmc-build.json`: its key and each file's hash), through cnlmc.output: a folder holds the old
files and record or the new ones, never a mix; temps of a killed writer are removed by the next.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from cnlmc import __version__

from ..errors import UsageError
from ..output import Staging, safe_name
from .keys import BUILD_FORMAT, content_hash

RECORD_NAME = ".cnlmc-build.json"


@dataclass(frozen=True)
class Task:
    key: str
    folder: str  # relative to the output folder: `<material folder>/<target>`
    target: str
    options: dict[str, Any]
    document: dict[str, Any]


@dataclass
class Outcome:
    """What running a task gave: the files' hashes (and their bytes when they come back to be
    written by the caller), the target's notes, or the error that stopped it."""

    key: str
    folder: str
    target: str
    hashes: dict[str, str] = field(default_factory=dict)
    files: list[tuple[str, bytes]] | None = None
    notes: list[str] = field(default_factory=list)
    error: str | None = None
    version: str = __version__
    cpu_seconds: float = 0.0  # the worker's CPU time for the task (emit and, where it writes, the write)

    @property
    def ok(self) -> bool:
        return self.error is None


def task_folder(root: Path, folder: str) -> Path:
    """The task's folder under `root`: each part of `folder` a safe file name inside it."""
    return safe_name(folder, root)


def read_record(folder: Path) -> dict[str, Any] | None:
    try:
        record = json.loads((folder / RECORD_NAME).read_text("utf-8"))
    except (OSError, ValueError):
        return None
    return record if isinstance(record, dict) and isinstance(record.get("files"), dict) else None


def up_to_date(root: Path, task: Task) -> dict[str, str] | None:
    """The file hashes of the task's last build when its key is the same and every file is still
    there with that content; None when the task has to run."""
    folder = task_folder(root, task.folder)
    record = read_record(folder)
    if record is None or record.get("key") != task.key or record.get("format") != BUILD_FORMAT:
        return None
    hashes: dict[str, str] = record["files"]
    for name, expected in hashes.items():
        try:
            if content_hash((folder / name).read_bytes()) != expected:
                return None
        except OSError:
            return None
    return hashes


def record_text(task: Task, hashes: dict[str, str]) -> bytes:
    record = {"format": BUILD_FORMAT, "cnlmc": __version__, "key": task.key, "target": task.target, "files": hashes}
    return (json.dumps(record, indent=1, sort_keys=True) + "\n").encode("utf-8")


def write_task(root: Path, task: Task, files: list[tuple[str, bytes]]) -> None:
    """The task's files and record, all or nothing; a file the last build of this task wrote and
    this one lacks is removed (cnlmc.output's manifests, one per folder)."""
    folder = task_folder(root, task.folder)
    old = read_record(folder) or {"files": {}}
    hashes = {name: content_hash(data) for name, data in files}
    paths = [(safe_name(name, folder), data) for name, data in files]
    with Staging(root=folder) as staging:
        for path, data in paths:
            staging.add(path, _bytes_writer(data))
        for place in sorted({folder} | {p.parent for p, _ in paths} | _old_folders(folder, old["files"])):
            staging.own(place, [p.name for p, _ in paths if p.parent == place])
        staging.add(folder / RECORD_NAME, _bytes_writer(record_text(task, hashes)))  # last: renamed last
        staging.commit()


def _old_folders(folder: Path, names: object) -> set[Path]:
    if not isinstance(names, dict):
        return set()
    try:
        return {safe_name(name, folder).parent for name in names}
    except UsageError:
        return set()


def _bytes_writer(data: bytes) -> Callable[[Path], None]:
    def write(temp: Path) -> None:
        temp.write_bytes(data)

    return write
