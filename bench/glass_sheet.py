"""The glass sheet of docs/preview.md: clear glass, frosted glass, blue glass and water on the
preview sphere (`splitsum`), in the studio and sky environments; with --before COMMIT, a first
row rendered by that commit's preview (its backends/preview extracted with `git archive` into a
temporary folder and loaded beside the current package), to show what changed.

    .venv/bin/python bench/glass_sheet.py [--size 176] [--before 386c22a] [-o docs/preview_glass.png]
"""

from __future__ import annotations

import argparse
import importlib
import importlib.util
import io
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
PHRASES = ("clear glass", "frosted glass", "blue glass", "water")


def renderer_of_commit(commit: str, folder: Path) -> Any:
    """The Renderer class of `commit`'s preview, loaded as cnlmc.backends.preview_<commit>."""
    import cnlmc.backends

    archive = subprocess.run(
        ["git", "archive", commit, "backends/preview"], cwd=ROOT, check=True, capture_output=True
    ).stdout
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        tar.extractall(folder, filter="data")
    package = folder / "backends" / "preview"
    name = f"{cnlmc.backends.__name__}.preview_{commit}"
    spec = importlib.util.spec_from_file_location(
        name, package / "__init__.py", submodule_search_locations=[str(package)]
    )
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return importlib.import_module(f"{name}.render").Renderer


def row(renderer_class: Any, size: int, env: str, caption: str) -> list:
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.sheet import label

    tiles = []
    with renderer_class(size) as renderer:
        for phrase in PHRASES:
            material = compile_source(phrase + "\n").document.materials[0]
            frame = renderer.render(material, tier="splitsum", env=env)
            tiles.append(label(frame.rgba, f"{caption}: {phrase}"))
    return tiles


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=176)
    parser.add_argument("--before", default="", help="a commit whose preview makes the first row")
    parser.add_argument("-o", "--out", default=str(ROOT / "docs" / "preview_glass.png"))
    args = parser.parse_args()
    from cnlmc.backends.preview.render import Renderer
    from cnlmc.backends.preview.sheet import png_bytes, sheet

    rows = []
    with tempfile.TemporaryDirectory() as folder:
        if args.before:
            rows.append(row(renderer_of_commit(args.before, Path(folder)), args.size, "studio", "before"))
        rows.append(row(Renderer, args.size, "studio", "after" if args.before else "studio"))
        rows.append(row(Renderer, args.size, "sky", "after, sky" if args.before else "sky"))
    Path(args.out).write_bytes(png_bytes(sheet(rows)))
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
