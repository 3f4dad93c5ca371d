"""USD for pipelines: author a cnlmc material into an existing stage.

    from pxr import Usd
    from cnlmc.backends.exchange.usd_stage import author_material
    stage = Usd.Stage.CreateInMemory()
    mat = author_material(stage, "/Looks/Hull", "lightly brushed, blue anodized aluminum",
                          bind_to=["/World/Hull"])

Like the usd target it builds on, this module needs pxr (pip install 'cnlmc[usd]').
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any

from pxr import Sdf, UsdGeom, UsdShade

from cnlmc.api import compile_source
from cnlmc.diagnostics import render
from cnlmc.lexicon import Lexicon
from cnlmc.material import Material
from cnlmc.output import write_atomic

from ..base import Artifact
from . import usd as backend
from .naming import unique_identifiers
from .textures import Texture, bake_textures


def compile_phrase_materials(phrase: str, lexicon: Lexicon | None, seed: int) -> list[Material]:
    """The phrase's materials, typed; ValueError with the rendered diagnostics when it does not compile."""
    result = compile_source(phrase, "<phrase>", lexicon, seed)
    if not result.ok or not result.materials:
        errors = [render(d, phrase, "<phrase>") for d in result.diagnostics if d.is_error]
        raise ValueError("\n".join(errors) or f"the phrase names no material: {phrase!r}")
    return [Material.from_ir(m) for m in result.materials]


def author_material(
    stage: Any,
    path: str,
    phrase: str,
    bind_to: Iterable[str] = (),
    lexicon: Lexicon | None = None,
    *,
    seed: int = 0,
    texture_dir: str | Path | None = None,
    map_size: int = 512,
    surface: str = "open_pbr_surface",
) -> UsdShade.Material:
    """Author `phrase` as a UsdShade.Material at `path` (an "or" phrase: one prim with a VariantSet)
    and bind it to the prims at `bind_to`. Returns the UsdShade.Material.

    Baked maps are written into `texture_dir` (asset paths are relative to the stage's root
    layer when it is on disk, else absolute); without `texture_dir` maps are left out.
    Raises ValueError with the rendered diagnostics for a phrase that does not compile.
    """
    materials = compile_phrase_materials(phrase, lexicon, seed)
    sdf_path = Sdf.Path(path)
    if not sdf_path.IsAbsolutePath() or not sdf_path.IsPrimPath():
        raise ValueError(f"'{path}' is not an absolute prim path")
    bind_paths = list(bind_to)
    targets = [stage.GetPrimAtPath(p) for p in bind_paths]
    missing = [str(p) for p, prim in zip(bind_paths, targets) if not prim.IsValid()]
    if missing:
        raise ValueError(f"cannot bind: no prim at {', '.join(missing)}")
    opts = backend.TARGET.parse_options({"maps": "bake" if texture_dir else "none", "map_size": map_size, "seed": seed})
    textures = []
    for material, ident in zip(materials, unique_identifiers(m.name for m in materials)):
        tex, images = bake_textures(material, ident, opts)
        if images and texture_dir is not None:
            tex = write_textures(stage, Path(texture_dir), tex, images)
        textures.append(tex)
    parent = sdf_path.GetParentPath()
    if parent != Sdf.Path.absoluteRootPath and not stage.GetPrimAtPath(parent).IsValid():
        UsdGeom.Scope.Define(stage, parent)
    material_prim = backend.author_group(stage, sdf_path, materials, textures, surface)
    for prim in targets:
        backend.bind(prim, material_prim)
    return material_prim


def write_textures(
    stage: Any, folder: Path, textures: dict[str, Texture], images: Sequence[Artifact]
) -> dict[str, Texture]:
    """Write baked images and point the texture paths at them."""
    folder.mkdir(parents=True, exist_ok=True)
    layer_path = stage.GetRootLayer().realPath
    out = {}
    for role, texture in textures.items():
        image = next(i for i in images if i.name == texture.path)
        target = folder / Path(texture.path).name
        write_atomic(target, image.content)
        ref = str(target.resolve())
        if layer_path:
            try:
                ref = "./" + str(target.resolve().relative_to(Path(layer_path).resolve().parent))
            except ValueError:
                pass
        out[role] = replace(texture, path=ref)
    return out
