"""`cnlmc bake`: every material's procedural maps to image files, with a progress bar."""

from __future__ import annotations

import sys

from .errors import UsageError


class ProgressBar:
    """A one-line bar on stderr, drawn only when stderr is a terminal and there is more than one map."""

    def __init__(self, stream=sys.stderr, width: int = 30):
        self.stream, self.width = stream, width
        self.enabled = stream.isatty()

    def __call__(self, done: int, total: int, name: str) -> None:
        if not self.enabled or total <= 1:
            return
        filled = int(self.width * done / total)
        self.stream.write(f"\r[{'#' * filled}{'.' * (self.width - filled)}] {done}/{total} {name[:40]:<40}")
        if done == total:
            self.stream.write("\n")
        self.stream.flush()


def bake_materials(ir: dict, out_dir: str, size: int, fmt: str, seed: int) -> list:
    try:
        from cnlmc.backends.maps import MapError, bake, write_maps
    except ImportError as exc:
        raise UsageError(f"baking cannot load: {exc}; install it with: pip install 'cnlmc[maps]'") from None
    paths, progress = [], ProgressBar()
    try:
        for material in ir["materials"]:
            if not material["maps"]:
                print(f"{material['name']}: uniform, no maps to bake", file=sys.stderr)
                continue
            arrays = bake(material["maps"], material["params"], size, seed, on_progress=progress)
            paths += write_maps(arrays, out_dir, fmt, stem=material["name"])
    except MapError as exc:
        raise UsageError(str(exc)) from None
    return paths
