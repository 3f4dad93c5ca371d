"""The 'usdz' target: one self-contained .usdz for iPhone/iPad AR Quick Look (docs/gltf.md).

Only what AR Quick Look reads: a UsdPreviewSurface network per material (UsdPreviewSurface,
UsdUVTexture, UsdPrimvarReader_float2: the usd target's preview network, without its MaterialX
one), PNG textures inside the package, a preview mesh sized in metres (metersPerUnit 1, y up)
bound to each material, a usdc root layer first, every file stored and 64-byte aligned, fixed
zip timestamps, so two runs give the same bytes. An "or" phrase is one object whose material
has a VariantSet `material` (the first alternative shown). `arkit_rules.check_package` runs the
ARKit rules of OpenUSD's compliance checker on the result (the tests run it on every package).
"""

from __future__ import annotations

import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
from pxr import Gf, Sdf, Usd, UsdGeom, UsdShade, Vt

from cnlmc.material import Document, Material
from cnlmc.output import main_file_name

from ..base import Artifact, Option, Options, Target, emit_each
from ..capabilities import ALL_FEATURES, EmitResult
from ..maps.library import metres_per_unit
from . import usd
from .gltf_mesh import MESH_NAMES, PreviewGeometry, placements, preview_geometry
from .naming import MaterialIdents, identifier, phrase_text, unique_identifiers
from .options import Capabilities, capabilities_for, map_options
from .textures import Textures, bake_textures
from .usdz import package as usdz_bytes  # the deterministic usdz writer the usd target uses too

STEM = "materials"
VARIANT_SET = "material"
ROLES = ("base_color", "normal", "roughness", "metallic")
OPTIONS = (
    *(o for o in map_options() if o.name != "map_format"),
    Option("map_format", str, "png8", choices=("png8",), doc="baked image encoding (AR Quick Look reads 8-bit PNG)"),
    Option("mesh", str, "sphere", choices=MESH_NAMES, doc="the preview object each material is shown on"),
    Option(
        "size",
        float,
        None,
        range=(0.001, 100.0),
        doc="the preview object's size in metres (default: its own: sphere 10 cm, teapot 26 cm)",
    ),
    Option("root", str, "Root", doc="the name of the stage's default prim"),
)
PREVIEW_ONLY = "(AR Quick Look reads UsdPreviewSurface only)"
CAPABILITIES: Capabilities = {
    **usd.CAPABILITIES,
    "model.glass": ("approximate", "UsdPreviewSurface: opacity 0 with ior, no refraction tint " + PREVIEW_ONLY),
    "anisotropic": ("drop", "UsdPreviewSurface has no anisotropy: isotropic roughness sqrt(sqrt(ax*ay))"),
    "distribution.ward": ("approximate", "no Ward lobe: isotropic GGX " + PREVIEW_ONLY),
    "diffuse.oren_nayar": ("approximate", "UsdPreviewSurface is Lambertian " + PREVIEW_ONLY),
    "coat": ("approximate", "UsdPreviewSurface clearcoat (fixed IOR 1.5, clearcoatRoughness)"),
    "coat.color": ("drop", "UsdPreviewSurface has no coat colour"),
    "sheen": ("drop", "UsdPreviewSurface has no sheen: the fabric's body colour only " + PREVIEW_ONLY),
    "subsurface.volume": ("drop", "UsdPreviewSurface has no subsurface: base_color as its surface " + PREVIEW_ONLY),
    "subsurface.thin": ("drop", "UsdPreviewSurface has no translucency: base_color as its surface " + PREVIEW_ONLY),
    "model.conductor": (
        "approximate",
        "UsdPreviewSurface metallic workflow: Schlick with diffuseColor = f0, no edge tint",
    ),
}
assert set(CAPABILITIES) == set(ALL_FEATURES)


# ---------------------------------------------------------------------------- geometry


def author_mesh(stage: Any, path: Any, geometry: PreviewGeometry, where: Sequence[float]) -> Any:
    """The preview geometry as a UsdGeom.Mesh (triangles, vertex normals, st with v up the image)."""
    mesh = UsdGeom.Mesh.Define(stage, path)
    points = (geometry.positions + np.asarray(where, np.float32)).astype(np.float32)
    mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(points))
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(geometry.indices), 3, np.int32)))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(geometry.indices.reshape(-1).astype(np.int32)))
    mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(geometry.normals))
    mesh.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateExtentAttr(Vt.Vec3fArray.FromNumpy(np.stack([points.min(0), points.max(0)])))
    st = np.stack([geometry.uvs[:, 0], 1.0 - geometry.uvs[:, 1]], 1).astype(np.float32)  # glTF's v -> USD's
    primvar = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar("st", Sdf.ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.vertex)
    primvar.Set(Vt.Vec2fArray.FromNumpy(st))
    return mesh


# ---------------------------------------------------------------------------- materials


def real_size(stage: Any, material_prim: Any, material: Material, uv_metres: float | None) -> None:
    """A UsdTransform2d between the st reader and each texture, scaling st so the map shows at its
    graph's real size on a mesh whose UV unit spans `uv_metres` (none where the scale is 1)."""
    for role, ref in material.maps.items():
        texture = UsdShade.Shader(stage.GetPrimAtPath(material_prim.GetPath().AppendChild(f"Texture_{role}")))
        unit = metres_per_unit(ref.graph)
        if not texture or uv_metres is None or not unit or abs(uv_metres / unit - 1.0) < 1e-6:
            continue
        st = texture.GetInput("st")
        (source,) = st.GetConnectedSources()[0]
        transform = UsdShade.Shader.Define(stage, material_prim.GetPath().AppendChild(f"Transform_{role}"))
        transform.CreateIdAttr("UsdTransform2d")
        transform.CreateInput("in", Sdf.ValueTypeNames.Float2).ConnectToSource(
            source.source.GetOutput(source.sourceName)
        )
        scale = round(uv_metres / unit, 6)
        transform.CreateInput("scale", Sdf.ValueTypeNames.Float2).Set(Gf.Vec2f(scale, scale))
        st.ConnectToSource(transform.CreateOutput("result", Sdf.ValueTypeNames.Float2))


def author_material(
    stage: Any, material_prim: Any, material: Material, textures: Textures, uv_metres: float | None
) -> None:
    usd.author_preview(stage, material_prim, material, textures)
    real_size(stage, material_prim, material, uv_metres)


def author_group(
    stage: Any, path: Any, materials: Sequence[Material], textures: Sequence[Textures], uv_metres: float | None
) -> Any:
    """One Material prim: a single material's preview network, or a VariantSet of them."""
    material_prim = UsdShade.Material.Define(stage, path)
    material_prim.GetPrim().SetDocumentation(phrase_text(materials[0]))
    if len(materials) == 1 and materials[0].variant is None:
        author_material(stage, material_prim, materials[0], textures[0], uv_metres)
        return material_prim
    variants = material_prim.GetPrim().GetVariantSets().AddVariantSet(VARIANT_SET)
    names = unique_identifiers(m.variant.name if m.variant else m.name for m in materials)
    for name, material, tex in zip(names, materials, textures):
        variants.AddVariant(name)
        variants.SetVariantSelection(name)
        with variants.GetVariantEditContext():
            author_material(stage, material_prim, material, tex, uv_metres)
    variants.SetVariantSelection(names[0])
    return material_prim


def groups_of(materials: Sequence[Material]) -> list[list[int]]:
    groups: dict[str, list[int]] = {}
    for i, material in enumerate(materials):
        key = f"group:{material.variant.group}" if material.variant else f"material:{i}"
        groups.setdefault(key, []).append(i)
    return list(groups.values())


def group_name(materials: Sequence[Material], group: Sequence[int]) -> str:
    """A prim name that says what the object holds: 'red_or_green_glass' for an "or" phrase."""
    first = materials[group[0]]
    return identifier(first.phrase if first.variant else first.name)


def build_stage(materials: Sequence[Material], textures: Sequence[Textures], options: Options) -> Any:
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    root = UsdGeom.Xform.Define(stage, Sdf.Path.absoluteRootPath.AppendChild(identifier(options.root, "Root")))
    stage.SetDefaultPrim(root.GetPrim())
    looks, objects = root.GetPath().AppendChild("Looks"), root.GetPath().AppendChild("Preview")
    UsdGeom.Scope.Define(stage, looks)
    UsdGeom.Scope.Define(stage, objects)
    geometry = preview_geometry(options.mesh, options.size)
    groups = groups_of(materials)
    names = unique_identifiers(group_name(materials, g) for g in groups)
    for name, group, where in zip(names, groups, placements(len(groups), geometry.size)):
        members = [materials[i] for i in group]
        prim = author_group(
            stage, looks.AppendChild(name), members, [textures[i] for i in group], geometry.metres_per_uv
        )
        mesh = author_mesh(stage, objects.AppendChild(name), geometry, where)
        UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(prim)
    return stage


# --------------------------------------------------------------------------------- emit


def package(stage: Any, images: Mapping[str, bytes]) -> bytes:
    """The stage as a usdc layer, first, then the images: one usdz's bytes."""
    with tempfile.TemporaryDirectory(prefix="cnlmc-usdz-") as tmp:
        layer = Path(tmp) / f"{STEM}.usdc"
        stage.GetRootLayer().Export(str(layer))
        return usdz_bytes([(layer.name, layer.read_bytes()), *sorted(images.items())])


class UsdzTarget(Target):
    name = "usdz"
    description = "USDZ for AR Quick Look: UsdPreviewSurface only, PNG inside, sized in metres, same bytes every run"
    capabilities = CAPABILITIES
    options = OPTIONS

    def emit(self, document: Document, options: Options) -> EmitResult:
        idents = MaterialIdents(document.materials)
        table = capabilities_for(CAPABILITIES, options.maps)
        main = main_file_name(options.output, f"{STEM}.usdz")
        textures: list[Textures] = []
        images: dict[str, bytes] = {}

        def bake(material: Material) -> list[Artifact]:
            baked, artifacts = bake_textures(material, idents[material], options, roles=ROLES, main=main)
            inside = {t.role: replace(t, path=f"textures/{Path(t.path).name}") for t in baked.values()}
            textures.append(inside)
            by_name = {a.name: a for a in artifacts}
            for texture, original in zip(inside.values(), baked.values()):
                content = by_name[original.path].content
                images[texture.path] = content if isinstance(content, bytes) else content.encode()
            return []

        result = emit_each(self, document, bake, lambda material: table)
        stage = build_stage(document.materials, textures, options)
        return EmitResult([Artifact(main, package(stage, images), "binary")], result.notes)


TARGET = UsdzTarget()


def emit(ir: Document | Mapping[str, Any], options: Mapping[str, object] | None = None) -> EmitResult:
    """The target on an IR (typed or JSON form) with raw `--option` pairs."""
    return TARGET.emit_ir(ir, options)
