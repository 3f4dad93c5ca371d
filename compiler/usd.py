"""USD for pipelines: author a cnlmc material into an existing stage.

    from pxr import Usd
    from cnlmc.usd import author_material
    stage = Usd.Stage.CreateInMemory()
    mat = author_material(stage, "/Looks/Hull", "lightly brushed, blue anodized aluminum",
                          bind_to=["/World/Hull"])

pxr is imported only when these functions run.
"""

from __future__ import annotations

from pathlib import Path


def _compile(phrase: str, lexicon, seed: int) -> list[dict]:
    from .api import compile_source
    from .diagnostics import render

    result = compile_source(phrase, "<phrase>", lexicon, seed)
    if not result.ok or not result.materials:
        errors = [render(d, phrase, "<phrase>") for d in result.diagnostics if d.is_error]
        raise ValueError("\n".join(errors) or f"the phrase names no material: {phrase!r}")
    return result.materials


def author_material(
    stage,
    path: str,
    phrase: str,
    bind_to=(),
    lexicon=None,
    *,
    seed: int = 0,
    texture_dir: str | Path | None = None,
    map_size: int = 512,
    surface: str = "open_pbr_surface",
):
    """Author `phrase` as a UsdShade.Material at `path` (an "or" phrase: one prim with a VariantSet)
    and bind it to the prims at `bind_to`. Returns the UsdShade.Material.

    Baked maps are written into `texture_dir` (asset paths are relative to the stage's root
    layer when it is on disk, else absolute); without `texture_dir` maps are left out.
    Raises ValueError with the rendered diagnostics for a phrase that does not compile.
    """
    from pxr import Sdf, UsdGeom

    from cnlmc.backends.exchange import usd as backend
    from cnlmc.backends.exchange.naming import unique_identifiers
    from cnlmc.backends.exchange.textures import bake_textures
    from cnlmc.material import Material

    materials = [Material.from_ir(m) for m in _compile(phrase, lexicon, seed)]
    sdf_path = Sdf.Path(path)
    if not sdf_path.IsAbsolutePath() or not sdf_path.IsPrimPath():
        raise ValueError(f"'{path}' is not an absolute prim path")
    targets = [stage.GetPrimAtPath(p) for p in bind_to]
    missing = [str(p) for p, prim in zip(bind_to, targets) if not prim.IsValid()]
    if missing:
        raise ValueError(f"cannot bind: no prim at {', '.join(missing)}")
    opts = backend.TARGET.parse_options({"maps": "bake" if texture_dir else "none", "map_size": map_size, "seed": seed})
    textures = []
    for material, ident in zip(materials, unique_identifiers(m.name for m in materials)):
        tex, images = bake_textures(material, ident, opts)
        if images:
            tex = _write_textures(stage, Path(texture_dir), tex, images)
        textures.append(tex)
    parent = sdf_path.GetParentPath()
    if parent != Sdf.Path.absoluteRootPath and not stage.GetPrimAtPath(parent).IsValid():
        UsdGeom.Scope.Define(stage, parent)
    material_prim = backend.author_group(stage, sdf_path, materials, textures, surface)
    for prim in targets:
        backend.bind(prim, material_prim)
    return material_prim


def _write_textures(stage, folder: Path, textures: dict, images) -> dict:
    """Write baked images and point the texture paths at them."""
    from dataclasses import replace

    from cnlmc.output import write_atomic

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
