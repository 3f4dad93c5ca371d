"""USD for pipelines: author a cnlmc material into an existing stage.

    from pxr import Usd
    from cnlmc.backends.exchange.usd_stage import author_material
    stage = Usd.Stage.CreateInMemory()
    mat = author_material(stage, "/Looks/Hull", "lightly brushed, blue anodized aluminum",
                          bind_to=["/World/Hull"])

Like the usd target it builds on, this module needs pxr (pip install 'cnlmc[usd]').

Authoring again at the same path replaces what was authored there (the prim is cleared first, so
nothing of the old network or its variants is kept), and its textures: each material prim owns a
folder in `texture_dir` (`<layer file name>_<prim path>`, e.g. `tex/shot.usda_Looks_Hull/`) with
a manifest, and the textures the new phrase no longer has are removed (cnlmc.output).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import replace
from pathlib import Path
from typing import Any

from pxr import Sdf, UsdGeom, UsdShade

from cnlmc.api import compile_source
from cnlmc.diagnostics import render
from cnlmc.filenames import fit_name
from cnlmc.lexicon import Lexicon
from cnlmc.material import Material
from cnlmc.output import write_files

from ..base import Artifact
from . import usd as backend
from .naming import unique_identifiers
from .textures import Textures, bake_textures


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
    network: str = "preview",
) -> UsdShade.Material:
    """Author `phrase` as a UsdShade.Material at `path` (an "or" phrase: one prim with a VariantSet)
    and bind it to the prims at `bind_to`. Returns the UsdShade.Material. A prim authored there
    before (in the stage's edit target) is replaced, not merged with.

    Baked maps are written into `texture_dir` (a relative one is relative to the folder of the
    stage's root layer, or to the current folder for a stage in memory), in the prim's own folder
    there; asset paths are relative (`./tex/...`) to the root layer's folder when the layer is on
    disk, else as `texture_dir` gives them. Without `texture_dir` maps are left out.
    `network`: the selected variant of the Material's `network` VariantSet ("preview": only
    UsdPreviewSurface, valid on every USD build; "materialx": also the MaterialX network, for a
    USD build with usdMtlx). Both variants are always authored.
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
    textures = bake_and_write(stage, sdf_path, materials, texture_dir, map_size, seed)
    parent = sdf_path.GetParentPath()
    if parent != Sdf.Path.absoluteRootPath and not stage.GetPrimAtPath(parent).IsValid():
        UsdGeom.Scope.Define(stage, parent)
    if stage.GetPrimAtPath(sdf_path).IsValid():
        stage.RemovePrim(sdf_path)  # re-authoring replaces: no old input, variant or shader survives
    material_prim = backend.author_group(stage, sdf_path, materials, textures, surface, network=network)
    for prim in targets:
        backend.bind(prim, material_prim)
    return material_prim


def layer_folder(stage: Any) -> Path | None:
    """The folder of the stage's root layer, when it is a file on disk."""
    real = stage.GetRootLayer().realPath
    return Path(real).resolve().parent if real else None


def texture_folder(stage: Any, sdf_path: Any, texture_dir: str | Path) -> Path:
    """The folder the material prim at `sdf_path` owns in `texture_dir` (resolved against the
    root layer's folder): `<layer file name>_<prim path>`."""
    base = layer_folder(stage)
    folder = Path(texture_dir)
    if base is not None and not folder.is_absolute():
        folder = base / folder
    real = stage.GetRootLayer().realPath
    owner = (Path(real).name if real else "") + str(sdf_path).replace("/", "_")
    return folder / fit_name(owner.lstrip("_") or "material")


def asset_path(stage: Any, target: Path) -> str:
    """`./...` relative to the root layer's folder when on disk (and inside it), else as given."""
    base = layer_folder(stage)
    if base is None:
        return str(target)
    try:
        return "./" + Path(os.path.relpath(target.resolve(), base)).as_posix()
    except ValueError:
        return str(target.resolve())


def bake_and_write(
    stage: Any, sdf_path: Any, materials: list[Material], texture_dir: str | Path | None, map_size: int, seed: int
) -> list[Textures]:
    """Each material's baked textures, written into the prim's folder (all-or-nothing, with its
    manifest: the textures an earlier authoring left there and this one lacks are removed)."""
    opts = backend.TARGET.parse_options({"maps": "bake" if texture_dir else "none", "map_size": map_size, "seed": seed})
    textures: list[Textures] = []
    images: list[Artifact] = []
    for material, ident in zip(materials, unique_identifiers(m.name for m in materials)):
        tex, baked = bake_textures(material, ident, opts, main="stage")
        textures.append(tex)
        images += baked
    if texture_dir is None:
        return textures
    folder = texture_folder(stage, sdf_path, texture_dir)
    files = {image.name: folder / Path(image.name).name for image in images}
    write_files([(files[i.name], i.content) for i in images], owned=folder, root=folder)
    return [{role: replace(t, path=asset_path(stage, files[t.path])) for role, t in tex.items()} for tex in textures]
