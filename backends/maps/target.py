"""The 'maps' target: every material's procedural maps, baked to image files.

Options: size (default 1024, a power of two), format (png8 | png16 | exr-half | exr-float).
Uniform materials produce no files (nothing varies over their surface).
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from ..capabilities import ALL_FEATURES, COMPILER_OPTIONS, EmitResult
from ..registry import Artifact
from .bake import bake
from .errors import MapError
from .writer import write_maps

NAME = "maps"
DESCRIPTION = "baked procedural maps (PNG/EXR through OpenImageIO)"
CAPABILITIES = dict.fromkeys(
    ALL_FEATURES, ("exact", "maps are this target's whole output; BSDF features are not its concern")
)
OPTIONS = {"size": "1024", "format": "png8"}


def _options(options: dict) -> tuple[int, str]:
    unknown = sorted(set(options) - set(OPTIONS) - set(COMPILER_OPTIONS))
    if unknown:
        raise ValueError(f"maps: unknown option(s) {', '.join(unknown)}; known: {', '.join(OPTIONS)}")
    try:
        size = int(options.get("size", OPTIONS["size"]))
    except ValueError:
        raise ValueError(f"maps: size must be a whole number, got {options['size']!r}") from None
    return size, options.get("format", OPTIONS["format"])


def emit(ir: dict, options: dict) -> EmitResult:
    size, fmt = _options(options)
    seed = int(options.get("seed", 0))
    artifacts = []
    with tempfile.TemporaryDirectory(prefix="cnlmc-maps-") as tmp:
        for material in ir["materials"]:
            if material["maps"]:
                artifacts += _bake_material(material, size, fmt, seed, Path(tmp))
    return EmitResult(artifacts)


def _bake_material(material: dict, size: int, fmt: str, seed: int, folder: Path) -> list[Artifact]:
    try:
        arrays = bake(material["maps"], material["params"], size, seed)
        paths = write_maps(arrays, folder, fmt, stem=material["name"])
    except MapError as exc:
        raise ValueError(f"maps: {material['name']}: {exc}") from None
    return [Artifact(p.name, p.read_bytes(), "binary") for p in paths]
