"""The one map-baking service: a material's procedural maps -> arrays, image files or Artifacts.

Every target that needs images asks here (the maps target, `cnlmc bake`, the exchange
formats, the preview); each failure is a `MapBakeError` naming the material.

    bake_arrays(material, size, seed, roles=None, on_progress=None) -> {role: ndarray}
    bake_files(material, out_dir, size, fmt, seed, stem=None, ...) -> [Path]       (written atomically)
    bake_artifacts(material, size, fmt, seed, stem=None, folder="", ...) -> [Artifact] (bytes)
    bake_images(material, size, fmt, seed, stem=None, folder="", ...) -> {role: Artifact}

`material` is a typed `cnlmc.material.Material` (or its IR dict); `roles` picks some of its
maps (default all); `derive(arrays) -> arrays` may add roles computed from the baked ones.
Formats: png8, png16, exr-half, exr-float (writer.FORMATS). Sizes: a power of two, 8 ... 8192.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from cnlmc.interrupts import SignalGuard
from cnlmc.material import Material, params_to_ir
from cnlmc.output import Staging
from cnlmc.scratch import scratch_folder

from ..base import Artifact
from .bake import OnProgress, bake
from .errors import MapError
from .writer import image_library, write_maps

Arrays = dict[str, np.ndarray]
Derive = Callable[[Arrays], Arrays]


class MapBakeError(MapError):
    """A material's maps cannot be baked: `material` names it, `reason` says why."""

    def __init__(self, material: str, reason: str):
        super().__init__(f"{material}: {reason}")
        self.material, self.reason = material, reason


def _parts(material: Material | Mapping[str, Any]) -> tuple[str, dict[str, Any], dict[str, Any]]:
    """Name, IR map references and IR parameters: what the graph engine reads."""
    if isinstance(material, Mapping):
        return material["name"], dict(material.get("maps") or {}), dict(material.get("params") or {})
    maps = {role: ref.to_ir() for role, ref in material.maps.items()}
    return material.name, maps, params_to_ir(material.params)


def has_maps(material: Material | Mapping[str, Any]) -> bool:
    return bool(_parts(material)[1])


def bake_arrays(
    material: Material | Mapping[str, Any],
    size: int,
    seed: int,
    roles: Collection[str] | None = None,
    on_progress: OnProgress | None = None,
) -> Arrays:
    """role -> float32 array (see maps.bake for shapes and value ranges)."""
    name, refs, params = _parts(material)
    chosen = {role: ref for role, ref in refs.items() if roles is None or role in roles}
    try:
        return bake(chosen, params, size, seed, on_progress=on_progress)
    except MapError as exc:
        raise MapBakeError(name, str(exc)) from None


def _derived(
    material: Material | Mapping[str, Any],
    size: int,
    seed: int,
    roles: Collection[str] | None,
    derive: Derive | None,
    on_progress: OnProgress | None = None,
) -> tuple[str, Arrays]:
    """The material's name and its baked arrays, passed through `derive` when one is given."""
    arrays = bake_arrays(material, size, seed, roles, on_progress)
    return _parts(material)[0], arrays if derive is None else derive(arrays)


def bake_files(
    material: Material | Mapping[str, Any],
    out_dir: str | Path,
    size: int,
    fmt: str,
    seed: int,
    stem: str | None = None,
    roles: Collection[str] | None = None,
    derive: Derive | None = None,
    on_progress: OnProgress | None = None,
    staging: Staging | None = None,
) -> list[Path]:
    """Bake and write out_dir/{stem}_{role}{.png|.exr} (stem: the material's name); all-or-nothing,
    or, with `staging`, written when the caller commits it (cnlmc.output.Staging)."""
    name, arrays = _derived(material, size, seed, roles, derive, on_progress)
    try:
        return write_maps(arrays, out_dir, fmt, stem=stem or name, staging=staging)
    except MapError as exc:
        raise MapBakeError(name, str(exc)) from None


def bake_images(
    material: Material | Mapping[str, Any],
    size: int,
    fmt: str,
    seed: int,
    stem: str | None = None,
    folder: str = "",
    roles: Collection[str] | None = None,
    derive: Derive | None = None,
) -> dict[str, Artifact]:
    """role -> image Artifact named `{folder}/{stem}_{role}.ext` (no folder: just the file name;
    a name too long for a file is shortened, writer.map_file_name). The images pass through a
    scratch folder that a signal (SIGTERM, SIGHUP, SIGINT) removes too."""
    prefix = f"{folder}/" if folder else ""
    name, arrays = _derived(material, size, seed, roles, derive)
    image_library()  # before the signal guard (writer.image_library)
    with SignalGuard(), scratch_folder("maps") as tmp:
        try:
            paths = write_maps(arrays, tmp, fmt, stem=stem or name)
        except MapError as exc:
            raise MapBakeError(name, str(exc)) from None
        return {role: Artifact(prefix + p.name, p.read_bytes(), "binary") for role, p in zip(arrays, paths)}


def bake_artifacts(
    material: Material | Mapping[str, Any],
    size: int,
    fmt: str,
    seed: int,
    stem: str | None = None,
    folder: str = "",
    roles: Collection[str] | None = None,
    derive: Derive | None = None,
) -> list[Artifact]:
    """Bake into image Artifacts named `{folder}/{stem}_{role}.ext` (no folder: just the file name)."""
    return list(bake_images(material, size, fmt, seed, stem, folder, roles, derive).values())
