"""What one output owns: the manifest of the files it wrote into its own folder.

A result with textures writes them into a folder that belongs to its main file
(`textures/<main file name>/`, see `owned_folder`), with `.cnlmc-manifest.json` listing the files
it wrote there. The next write of the same output removes the files the old manifest lists and
the new result no longer has (its stale textures), and nothing else: a file it did not write
(not in its manifest) is never removed. When the new result has no textures, the old ones, the
manifest and the then-empty folders go.
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Iterable
from pathlib import Path, PurePosixPath

from .filenames import fit_name

MANIFEST_NAME = ".cnlmc-manifest.json"
OWNED_ROOT = "textures"
MAX_MANIFEST_BYTES = 1 << 20
FORMAT = 1


def owned_folder(main_name: str) -> str:
    """The folder (relative to the main file's folder) whose files belong to the main file `main_name`."""
    return f"{OWNED_ROOT}/{fit_name(main_name)}"


def manifest_text(names: Iterable[str]) -> str:
    return json.dumps({"cnlmc_manifest": FORMAT, "files": sorted(names)}, indent=1) + "\n"


def _plain(name: object) -> bool:
    """A file name of the folder itself: no separator, not hidden, not '.' or '..'."""
    return isinstance(name, str) and bool(name) and PurePosixPath(name).name == name and not name.startswith(".")


def read_manifest(folder: Path) -> set[str]:
    """The file names a manifest in `folder` lists (none when there is none, or it is not one)."""
    path = folder / MANIFEST_NAME
    try:
        with path.open("rb") as handle:
            data = json.loads(handle.read(MAX_MANIFEST_BYTES + 1)[:MAX_MANIFEST_BYTES])
    except (OSError, ValueError):
        return set()
    files = data.get("files") if isinstance(data, dict) and data.get("cnlmc_manifest") == FORMAT else None
    return {name for name in files if _plain(name)} if isinstance(files, list) else set()


def remove_stale(folder: Path, old: set[str], new: set[str]) -> list[Path]:
    """Remove the regular files `old` lists and `new` does not (and the manifest, when there are
    no `new` files). Returns what was removed. Run it while holding the folder's lock."""
    removed = []
    for name in sorted(old - new):
        path = folder / name
        with contextlib.suppress(OSError):
            if path.is_file() and not path.is_symlink():
                path.unlink()
                removed.append(path)
    if not new:
        with contextlib.suppress(OSError):
            (folder / MANIFEST_NAME).unlink()
    return removed


def prune(folder: Path) -> None:
    """Remove `folder` when empty (after the lock is released), then its parent when that is an
    empty `textures` folder."""
    for empty in (folder, folder.parent) if folder.parent.name == OWNED_ROOT else (folder,):
        with contextlib.suppress(OSError):
            empty.rmdir()
