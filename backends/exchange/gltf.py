"""The 'gltf' target: glTF 2.0 (.glb, or .gltf beside its textures) for three.js, Babylon, Godot,
Unity, Unreal, Blender, Android Scene Viewer and WebXR (docs/gltf.md).

Each IR material becomes a metallic-roughness material with the KHR_materials_* extensions it needs
(gltf_material.py), shown on a preview mesh sized in metres (gltf_mesh.py); the materials of one
"or" phrase share one object whose KHR_materials_variants mappings switch between them. Baked maps
are PNG: base colour in sRGB, roughness and metalness packed into one linear
metallicRoughnessTexture (G and B), normals linear. Written with pygltflib (gltf_document.py).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from cnlmc.material import Document, Material
from cnlmc.output import main_file_name

from ..base import Artifact, Option, Options, Target, emit_each
from ..capabilities import ALL_FEATURES, EmitResult
from .gltf_document import GltfBuilder
from .gltf_mesh import FALLBACK_SIZE, MESH_NAMES, placements, preview_geometry
from .naming import MaterialIdents, phrase_text
from .options import Capabilities, capabilities_for, map_options
from .textures import bake_textures

FORMATS = ("glb", "gltf")
STEM = "materials"  # the main file's name (before its suffix) when -o names a folder
PACKED = "metallic_roughness"

OPTIONS = (
    *(o for o in map_options() if o.name != "map_format"),
    Option("map_format", str, "png8", choices=("png8", "png16"), doc="baked image encoding (glTF core reads PNG)"),
    Option("format", str, None, choices=FORMATS, doc="glb (one file) or gltf (text + textures); default: -o's suffix"),
    Option("mesh", str, "sphere", choices=(*MESH_NAMES, "none"), doc="the preview object each material is shown on"),
    Option(
        "size",
        float,
        None,
        range=(0.001, 100.0),
        doc="the preview object's size in metres (default: its own: sphere 10 cm, teapot 26 cm)",
    ),
)

BAKED = ("bake", "procedural graph baked to a PNG (sRGB colour, linear data) read through TEXCOORD_0")
CAPABILITIES: Capabilities = {
    "model.diffuse": ("exact", ""),
    "model.dielectric": (
        "approximate",
        "glTF's dielectric weights the diffuse base by 1 - F(V.H) (the spec's fresnel_mix), the IR by "
        "(1 - F(theta_o))(1 - F(theta_i)); same IOR (KHR_materials_ior)",
    ),
    "model.conductor": (
        "approximate",
        "glTF's metal is Schlick with baseColor = f0 (clipped to [0,1]) and a white edge: no F82 edge tint",
    ),
    "model.glass": ("exact", ""),
    "distribution.ggx": ("exact", ""),
    "distribution.ward": ("approximate", "glTF has no Ward lobe: anisotropic GGX with the same alpha_x, alpha_y"),
    "anisotropic": ("exact", ""),
    "diffuse.oren_nayar": ("approximate", "glTF's diffuse is Lambertian: Oren-Nayar sigma is left out"),
    "coat": (
        "approximate",
        "KHR_materials_clearcoat: a fixed coat IOR of 1.5 and a Fresnel-weighted layering, not the IR's "
        "Weidlich-Wilkie stack",
    ),
    "coat.color": ("drop", "KHR_materials_clearcoat has no coat colour"),
    "sheen": ("exact", "KHR_materials_sheen: the same Charlie lobe and albedo scaling"),
    "flakes": (
        "drop",
        "no ratified glTF extension draws flakes (KHR_materials_* has none): the paint exports as its pigment "
        "under the clearcoat",
    ),
    "subsurface.volume": (
        "approximate",
        "glTF has no scattering medium: KHR_materials_volume attenuation and KHR_materials_diffuse_transmission "
        "(NOT ratified; the validator reports it unsupported, an info) with the Kubelka-Munk share through the "
        "object's size (gltf_subsurface.py)",
    ),
    "subsurface.thin": (
        "approximate",
        "KHR_materials_diffuse_transmission (NOT ratified): the Kubelka-Munk sheet's transmitted share and colour",
    ),
    "maps.base_color": BAKED,
    "maps.roughness": ("bake", "baked into the G channel of the metallicRoughnessTexture (linear)"),
    "maps.metallic": ("bake", "baked into the B channel of the metallicRoughnessTexture (linear)"),
    "maps.normal": ("bake", "baked tangent-space normals (+Y up the image) in normalTexture, with mesh tangents"),
    "maps.mask": ("drop", "a mask has no shading input of its own (the colour and roughness maps it drives are kept)"),
}
assert set(CAPABILITIES) == set(ALL_FEATURES)


def output_format(options: Options) -> str:
    if options.format:
        return str(options.format)
    suffix = Path(options.output).suffix.lower().lstrip(".") if options.output else ""
    return suffix if suffix in FORMATS else "glb"


def packer(material: Material):
    """derive(): the baked roughness and metallic maps packed as glTF reads them (G = roughness,
    B = metalness; the channel without a map holds 1, so its factor gives the uniform value)."""

    def derive(arrays: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        out = {role: a for role, a in arrays.items() if role not in ("roughness", "metallic")}
        if "roughness" not in arrays and "metallic" not in arrays:
            return out
        size = next(iter(arrays.values())).shape[0]
        rough = arrays.get("roughness", np.ones((size, size), np.float32))
        if "roughness" in arrays and material.params.alpha_convention == "linear":
            rough = np.sqrt(rough)  # alpha = r there; glTF's alpha is roughness^2
        metal = arrays.get("metallic", np.ones((size, size), np.float32))
        out[PACKED] = np.stack([np.zeros_like(rough), rough, metal], -1).astype(np.float32)
        return out

    return derive


class GltfTarget(Target):
    name = "gltf"
    description = "glTF 2.0 (.glb/.gltf): metallic-roughness + KHR_materials_* extensions, variants for 'or'"
    capabilities = CAPABILITIES
    options = OPTIONS

    def emit(self, document: Document, options: Options) -> EmitResult:
        fmt = output_format(options)
        idents = MaterialIdents(document.materials)
        table = capabilities_for(CAPABILITIES, options.maps)
        baked: dict[int, dict[str, Artifact]] = {}
        main = main_file_name(options.output, f"{STEM}.{fmt}")

        def bake(material: Material) -> list[Artifact]:
            textures, images = bake_textures(
                material,
                idents[material],
                options,
                roles=("base_color", "normal", "roughness", "metallic"),
                derive=packer(material),
                main=main,
            )
            by_name = {image.name: image for image in images}
            baked[len(baked)] = {role: by_name[t.path] for role, t in textures.items()}
            return images

        result = emit_each(self, document, bake, lambda material: table)
        builder = GltfBuilder(embed_images=fmt == "glb")
        build_scene(builder, document.materials, [baked[i] for i in range(len(document.materials))], options)
        if fmt == "glb":
            return EmitResult([Artifact(main, builder.glb(), "binary")], result.notes)
        return EmitResult([Artifact(main, builder.gltf_json()), *result.artifacts], result.notes)


def groups_of(materials: Sequence[Material]) -> list[list[int]]:
    """Indices of the materials shown on one object: an "or" group's alternatives together."""
    groups: dict[str, list[int]] = {}
    for i, material in enumerate(materials):
        key = f"group:{material.variant.group}" if material.variant else f"material:{i}"
        groups.setdefault(key, []).append(i)
    return list(groups.values())


def build_scene(
    builder: GltfBuilder, materials: Sequence[Material], images: Sequence[Mapping[str, Artifact]], options: Options
) -> None:
    shape = None if options.mesh == "none" else preview_geometry(options.mesh, options.size)
    uv_metres = None if shape is None else shape.metres_per_uv
    thickness = round(shape.size, 6) if shape is not None else (options.size or FALLBACK_SIZE)  # glass: its depth
    indices = [builder.add_material(m, im, thickness, uv_metres) for m, im in zip(materials, images)]
    if shape is None:
        return
    geometry = builder.add_geometry(shape)
    groups = groups_of(materials)
    for group, where in zip(groups, placements(len(groups), shape.size)):
        first = materials[group[0]]
        if first.variant is None:
            builder.add_object(first.name, geometry, [(indices[group[0]], None)], where)
            continue
        pairs = [(indices[i], builder.add_variant(materials[i].variant.name)) for i in group]  # type: ignore[union-attr]
        builder.add_object(phrase_text(first), geometry, pairs, where)  # "red or green glass"


TARGET = GltfTarget()


def emit(ir: Document | Mapping[str, Any], options: Mapping[str, object] | None = None) -> EmitResult:
    """The target on an IR (typed or JSON form) with raw `--option` pairs."""
    return TARGET.emit_ir(ir, options)
