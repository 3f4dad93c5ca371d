"""The 'usd' target: a UsdShade Material per IR material (or per "or" group, with a VariantSet).

Each material holds two networks: a UsdPreviewSurface network (what every viewer shows) on
`outputs:surface`, and the MaterialX/OpenPBR network of the 'materialx' backend, written as
UsdShade prims with `ND_*` ids, on `outputs:mtlx:surface`. Textures go through UsdUVTexture +
UsdPrimvarReader_float2 ("st"). Format: `format=usda|usdc|usdz` (or the suffix of
`output=PATH`); binary formats come back as bytes. `mesh=sphere` adds bound preview spheres.
"""

from __future__ import annotations

import math
import tempfile
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

from pxr import Gf, Sdf, Usd, UsdGeom, UsdShade

from cnlmc.material import Document, Material

from ..base import Artifact, Option, Options, Target, emit_each
from ..capabilities import ALL_FEATURES, EmitResult
from . import materialx as mtlx_backend
from . import usdz
from .conversions import alpha_pair, alpha_to_roughness, clip01, conductor_f0, rounded
from .naming import MaterialIdents, display_name, identifier, phrase_text, unique_identifiers
from .options import Capabilities, capabilities_for, map_options
from .textures import Texture, Textures, bake_textures

FORMATS = ("usda", "usdc", "usdz")
NETWORK_SET = "network"  # preview: UsdPreviewSurface only; materialx: + the MaterialX network (needs usdMtlx)
NETWORKS = ("preview", "materialx")
OPTIONS = (
    *map_options(mtlx_backend.MAP_MODES),  # native: MaterialX nodes in the MaterialX network, baked for the preview
    Option("format", str, None, choices=FORMATS, doc="the file format (default: the suffix of -o, else usda)"),
    Option("mesh", str, "none", choices=("none", "sphere"), doc="sphere: a preview sphere bound to each material"),
    Option("surface", str, "open_pbr_surface", choices=mtlx_backend.SURFACES, doc="the MaterialX network's shader"),
    Option("root", str, "Root", doc="the name of the stage's default prim"),
    Option("network", str, "preview", choices=NETWORKS, doc="the `network` variant selected in the file"),
)
VARIANT_SET = "material"
PACKAGE_TEXTURES = "textures"  # a usdz's textures, inside the package
STEM = "materials"  # the stage's file name (before its suffix) when -o names a folder

KEPT = "(the MaterialX network beside it keeps it)"
BAKED = ("bake", "procedural graph baked to an image read by UsdUVTexture (st from UsdPrimvarReader_float2)")
CAPABILITIES: Capabilities = {
    "model.diffuse": ("exact", ""),
    "model.dielectric": ("exact", ""),
    "model.conductor": (
        "approximate",
        "UsdPreviewSurface metallic workflow: Schlick with diffuseColor = f0, no "
        "edge tint; the OpenPBR network carries the F82 tint",
    ),
    "model.glass": ("approximate", "UsdPreviewSurface: opacity 0 with ior, no refraction tint " + KEPT),
    "distribution.ggx": ("exact", ""),
    "distribution.ward": (
        "approximate",
        "no Ward lobe: GGX (anisotropic in the OpenPBR network, isotropic in the preview)",
    ),
    "anisotropic": ("drop", "UsdPreviewSurface has no anisotropy: isotropic roughness sqrt(sqrt(ax*ay)) " + KEPT),
    "diffuse.oren_nayar": (
        "approximate",
        "UsdPreviewSurface is Lambertian; the OpenPBR network has base_diffuse_roughness",
    ),
    "coat": ("approximate", "UsdPreviewSurface clearcoat (fixed IOR 1.5, clearcoatRoughness); OpenPBR coat beside it"),
    "coat.color": ("drop", "UsdPreviewSurface has no coat colour " + KEPT),
    "sheen": ("approximate", "UsdPreviewSurface has no sheen; the OpenPBR network beside it has fuzz " + KEPT),
    "flakes": ("drop", "neither UsdPreviewSurface nor OpenPBR has a flake slot: the pigment under the coat"),
    "subsurface.volume": (
        "approximate",
        "UsdPreviewSurface has no subsurface (diffuseColor = base_color); the OpenPBR network carries it " + KEPT,
    ),
    "subsurface.thin": ("approximate", "UsdPreviewSurface has no translucency; the OpenPBR network has it " + KEPT),
    "maps.base_color": BAKED,
    "maps.roughness": BAKED,
    "maps.metallic": BAKED,
    "maps.normal": ("bake", "baked tangent-space normals, UsdUVTexture scale 2 / bias -1 into normal"),
    "maps.mask": ("drop", "a mask has no shading input of its own (the colour and roughness maps it drives are kept)"),
}
assert set(CAPABILITIES) == set(ALL_FEATURES)

# MaterialX type -> Sdf value type, and how a MaterialX value becomes a USD value
Converter = Callable[[Any], Any]
MX_TYPES: dict[str, tuple[Any, Converter | None]] = {
    "float": (Sdf.ValueTypeNames.Float, float),
    "integer": (Sdf.ValueTypeNames.Int, int),
    "boolean": (Sdf.ValueTypeNames.Bool, bool),
    "color3": (Sdf.ValueTypeNames.Color3f, lambda v: Gf.Vec3f(*v)),
    "vector3": (Sdf.ValueTypeNames.Float3, lambda v: Gf.Vec3f(*v)),
    "vector2": (Sdf.ValueTypeNames.Float2, lambda v: Gf.Vec2f(*v)),
    "string": (Sdf.ValueTypeNames.String, str),
    "filename": (Sdf.ValueTypeNames.Asset, lambda v: Sdf.AssetPath(str(v))),
    "surfaceshader": (Sdf.ValueTypeNames.Token, None),
}
# texture role -> (UsdPreviewSurface input, type, UsdUVTexture output)
PREVIEW_TEXTURES = {
    "base_color": ("diffuseColor", Sdf.ValueTypeNames.Color3f, "rgb"),
    "roughness": ("roughness", Sdf.ValueTypeNames.Float, "r"),
    "metallic": ("metallic", Sdf.ValueTypeNames.Float, "r"),
    "normal": ("normal", Sdf.ValueTypeNames.Normal3f, "rgb"),
}
SOURCE_COLOUR_SPACE = {"srgb": "sRGB", "linear": "raw", "raw": "raw"}


# -------------------------------------------------------------------------- preview surface


def preview_inputs(material: Material) -> dict[str, tuple[Any, Any]]:
    """IR material -> UsdPreviewSurface input -> (Sdf type, value)."""
    model, params = material.model, material.params
    base = model.base
    F, C, I = Sdf.ValueTypeNames.Float, Sdf.ValueTypeNames.Color3f, Sdf.ValueTypeNames.Int
    colour = conductor_f0(params) if base == "conductor" else clip01(params.base_color)
    out: dict[str, tuple[Any, Any]] = {
        "diffuseColor": (C, colour),
        "metallic": (F, 1.0 if base == "conductor" else 0.0),
    }
    if base == "diffuse":  # no specular lobe: the specular workflow with black specular
        out.update(useSpecularWorkflow=(I, 1), specularColor=(C, [0.0, 0.0, 0.0]), roughness=(F, 1.0))
    else:
        ax, ay = alpha_pair(params)
        out["roughness"] = (F, alpha_to_roughness(math.sqrt(ax * ay)))
        if "ior" in params.present:
            out["ior"] = (F, float(params.ior))
    if base == "glass":
        out["opacity"] = (F, 0.0)
    if model.coat and params.coat is not None:
        out["clearcoat"] = (F, 1.0)
        out["clearcoatRoughness"] = (F, alpha_to_roughness(float(params.coat.alpha[0])))
    return {
        k: (t, rounded(v) if isinstance(v, list) else (round(v, 6) if isinstance(v, float) else v))
        for k, (t, v) in out.items()
    }


def _usd_value(sdf_type: Any, value: Any) -> Any:
    if sdf_type in (Sdf.ValueTypeNames.Color3f, Sdf.ValueTypeNames.Float3, Sdf.ValueTypeNames.Normal3f):
        return Gf.Vec3f(*value)
    return value


def author_preview(stage: Any, material_prim: Any, material: Material, textures: Textures) -> None:
    path = material_prim.GetPath()
    surface = UsdShade.Shader.Define(stage, path.AppendChild("PreviewSurface"))
    surface.CreateIdAttr("UsdPreviewSurface")
    for name, (sdf_type, value) in preview_inputs(material).items():
        surface.CreateInput(name, sdf_type).Set(_usd_value(sdf_type, value))
    surface_out = surface.CreateOutput("surface", Sdf.ValueTypeNames.Token)
    material_prim.CreateSurfaceOutput().ConnectToSource(surface_out)
    usable = {r: t for r, t in textures.items() if r in PREVIEW_TEXTURES}
    if not usable:
        return
    reader = UsdShade.Shader.Define(stage, path.AppendChild("PrimvarReader_st"))
    reader.CreateIdAttr("UsdPrimvarReader_float2")
    reader.CreateInput("varname", Sdf.ValueTypeNames.String).Set("st")
    st = reader.CreateOutput("result", Sdf.ValueTypeNames.Float2)
    for role, texture in usable.items():
        author_uv_texture(stage, path, surface, st, material, role, texture)


def author_uv_texture(
    stage: Any, path: Any, surface: Any, st: Any, material: Material, role: str, texture: Texture
) -> None:
    target, sdf_type, channel = PREVIEW_TEXTURES[role]
    shader = UsdShade.Shader.Define(stage, path.AppendChild(f"Texture_{role}"))
    shader.CreateIdAttr("UsdUVTexture")
    shader.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(Sdf.AssetPath(texture.path))
    shader.CreateInput("st", Sdf.ValueTypeNames.Float2).ConnectToSource(st)
    shader.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set(SOURCE_COLOUR_SPACE[texture.encoding])
    for wrap in ("wrapS", "wrapT"):
        shader.CreateInput(wrap, Sdf.ValueTypeNames.Token).Set("repeat")
    if role == "normal":
        shader.CreateInput("scale", Sdf.ValueTypeNames.Float4).Set(Gf.Vec4f(2, 2, 2, 1))
        shader.CreateInput("bias", Sdf.ValueTypeNames.Float4).Set(Gf.Vec4f(-1, -1, -1, 0))
    elif role == "base_color" and material.model.base == "conductor":  # the map tints f0
        shader.CreateInput("scale", Sdf.ValueTypeNames.Float4).Set(Gf.Vec4f(*conductor_f0(material.params), 1.0))
    out_type = Sdf.ValueTypeNames.Float3 if channel == "rgb" else Sdf.ValueTypeNames.Float
    output = shader.CreateOutput(channel, out_type)
    surface.CreateInput(target, sdf_type).ConnectToSource(output)


# ---------------------------------------------------------------------- MaterialX network


def author_materialx(
    stage: Any, material_prim: Any, material: Material, textures: Textures, surface: str, natives: Any = None
) -> None:
    """The 'materialx' backend's document for this material, as UsdShade prims with ND_* ids: the
    surface shader directly in the Material (validation wants connectable ancestors), each MaterialX
    node graph as a UsdShade NodeGraph beside it with its outputs."""
    ident, natives = identifier(material.name), natives or {}
    baked = {role: texture for role, texture in textures.items() if role not in natives}  # the rest: native nodes
    doc = mtlx_backend.build_document([material], surface, {ident: baked}, [ident], {ident: natives})
    mtlx_backend.validate(doc, mtlx_backend.TARGET.library)
    scope = material_prim.GetPath()
    shaders: Shaders = {}
    for graph in mtlx_backend.node_graphs(doc):
        graph_path = UsdShade.NodeGraph.Define(stage, scope.AppendChild(graph.getName())).GetPath()
        for node in graph.getNodes():
            define_mx_shader(stage, graph_path, graph.getName(), node, shaders)
    top = [n for n in doc.getNodes() if n.getCategory() != "surfacematerial"]
    for node in top:
        define_mx_shader(stage, scope, "", node, shaders)
    for (graph_name, _), (node, shader) in shaders.items():
        _author_mx_inputs(stage, scope, graph_name, node, shader, shaders)
    (sr_name,) = [n.getName() for n in top if n.getType() == "surfaceshader"]
    out = shaders[("", sr_name)][1].CreateOutput("out", Sdf.ValueTypeNames.Token)
    material_prim.CreateSurfaceOutput("mtlx").ConnectToSource(out)


Shaders = dict[tuple[str, str], tuple[Any, Any]]  # (graph name or "", node name) -> (mx node, usd shader)


def define_mx_shader(stage: Any, parent: Any, graph_name: str, node: Any, shaders: Shaders) -> None:
    shader = UsdShade.Shader.Define(stage, parent.AppendChild(node.getName()))
    shader.CreateIdAttr(node.getNodeDef().getName())
    shaders[(graph_name, node.getName())] = (node, shader)


def _mx_output(shaders: Shaders, graph_name: str, node_name: str) -> Any:
    node, shader = shaders[(graph_name, node_name)]
    return shader.CreateOutput("out", MX_TYPES[node.getType()][0])


def _connect_graph_output(stage: Any, scope: Any, mx_input: Any, shaders: Shaders) -> Any:
    """A top-level shader input fed by a MaterialX node graph output -> the UsdShade NodeGraph output."""
    graph_name, output_name = mx_input.getNodeGraphString(), mx_input.getOutputString()
    graph = UsdShade.NodeGraph(stage.GetPrimAtPath(scope.AppendChild(graph_name)))
    mx_output = mx_input.getConnectedOutput()
    output = graph.CreateOutput(output_name, MX_TYPES[mx_output.getType()][0])
    output.ConnectToSource(_mx_output(shaders, graph_name, mx_output.getNodeName()))
    return output


def _author_mx_inputs(stage: Any, scope: Any, graph_name: str, node: Any, shader: Any, shaders: Shaders) -> None:
    for mx_input in node.getInputs():
        sdf_type, convert = MX_TYPES[mx_input.getType()]
        usd_input = shader.CreateInput(mx_input.getName(), sdf_type)
        if mx_input.getNodeGraphString():
            usd_input.ConnectToSource(_connect_graph_output(stage, scope, mx_input, shaders))
            continue
        if mx_input.getNodeName():
            usd_input.ConnectToSource(_mx_output(shaders, graph_name, mx_input.getNodeName()))
            continue
        value = mx_input.getValue()
        assert convert is not None, f"a {mx_input.getType()} input holds no value"
        usd_input.Set(convert(list(value) if hasattr(value, "__len__") and not isinstance(value, str) else value))
        if mx_input.getColorSpace():
            usd_input.GetAttr().SetColorSpace(mx_input.getColorSpace())


# ------------------------------------------------------------------------------ materials


def author_network(
    stage: Any, material_prim: Any, material: Material, textures: Textures, surface: str, natives: Any = None
) -> None:
    """The preview network, and the MaterialX network inside the `network` VariantSet's `materialx`
    variant: a USD without usdMtlx (pip usd-core) knows no `ND_*` shader, so the stage validates
    everywhere with `preview` selected (the default) and a full USD build selects `materialx`."""
    author_preview(stage, material_prim, material, textures)
    networks = material_prim.GetPrim().GetVariantSets().AddVariantSet(NETWORK_SET)
    for name in NETWORKS:
        networks.AddVariant(name)
    networks.SetVariantSelection("materialx")
    with networks.GetVariantEditContext():
        author_materialx(stage, material_prim, material, textures, surface, natives)
    networks.ClearVariantSelection()  # the Material's own selection (author_group) decides


def record_phrase(material_prim: Any, material: Material) -> None:
    prim = material_prim.GetPrim()
    phrase = phrase_text(material)
    prim.SetCustomDataByKey("cnlmc:phrase", phrase)
    prim.SetDocumentation(phrase)
    if display_name(material):  # the name as written, where the prim name could not keep it
        prim.SetDisplayName(display_name(material))


def groups_of(materials: Sequence[Material]) -> list[tuple[str, list[int]]]:
    """(prim name source, indices): materials sharing variant.group become one prim."""
    groups: dict[str, list[int]] = {}
    order = []
    for i, material in enumerate(materials):
        variant = material.variant
        key = f"group:{variant.group}" if variant else f"material:{i}"
        if key not in groups:
            groups[key] = []
            order.append((variant.group if variant else material.name, key))
        groups[key].append(i)
    return [(group_prim_name(name, [materials[i] for i in groups[key]]), groups[key]) for name, key in order]


def group_prim_name(group: str, materials: Sequence[Material]) -> str:
    """A variant group's prim is named for the whole phrase ('red or green glass' ->
    red_or_green_glass) when the compiler named the group after its first alternative (red_glass
    would hold green too); a name the user gave (`hull: red or green glass`) is kept."""
    first = materials[0].variant
    if first is None or len(materials) < 2:
        return group
    words = set(group.split("_"))
    own = set(identifier(first.name).split("_"))
    others = {w for m in materials[1:] if m.variant for w in identifier(m.variant.name).split("_")}
    named_after_first = own <= words and not (others - own) & words
    return identifier(phrase_text(materials[0])) if named_after_first else group


def author_materials(
    stage: Any,
    looks: Any,
    materials: Sequence[Material],
    textures: Sequence[Textures],
    surface: str = "open_pbr_surface",
    natives: Sequence[Any] | None = None,
    network: str = "preview",
) -> list[Any]:
    """Author every IR material (variant groups as one prim) under `looks`."""
    groups = groups_of(materials)
    natives = natives or [{}] * len(materials)
    prims = []
    for prim_name, (_, indices) in zip(unique_identifiers(n for n, _ in groups), groups):
        prims.append(
            author_group(
                stage,
                looks.AppendChild(prim_name),
                [materials[i] for i in indices],
                [textures[i] for i in indices],
                surface,
                [natives[i] for i in indices],
                network,
            )
        )
    return prims


def author_group(
    stage: Any,
    path: Any,
    materials: Sequence[Material],
    textures: Sequence[Textures],
    surface: str,
    natives: Sequence[Any] | None = None,
    network: str = "preview",
) -> Any:
    material_prim = UsdShade.Material.Define(stage, path)
    record_phrase(material_prim, materials[0])
    natives = natives or [{}] * len(materials)
    if len(materials) == 1 and materials[0].variant is None:
        author_network(stage, material_prim, materials[0], textures[0], surface, natives[0])
    else:
        author_variants(stage, material_prim, materials, textures, surface, natives)
    material_prim.GetPrim().GetVariantSets().GetVariantSet(NETWORK_SET).SetVariantSelection(network)
    return UsdShade.Material(stage.GetPrimAtPath(path))  # the selection recomposed the prim: a fresh handle


def author_variants(
    stage: Any,
    material_prim: Any,
    materials: Sequence[Material],
    textures: Sequence[Textures],
    surface: str,
    natives: Sequence[Any],
) -> None:
    vset = material_prim.GetPrim().GetVariantSets().AddVariantSet(VARIANT_SET)
    names = unique_identifiers(m.variant.name if m.variant else m.name for m in materials)
    for name, material, tex, native in zip(names, materials, textures, natives):
        vset.AddVariant(name)
        vset.SetVariantSelection(name)
        with vset.GetVariantEditContext():
            author_network(stage, material_prim, material, tex, surface, native)
            material_prim.GetPrim().SetCustomDataByKey("cnlmc:material", identifier(material.name))
    vset.SetVariantSelection(names[0])


# ---------------------------------------------------------------------------- preview mesh


def uv_sphere(
    stage: Any, path: Any, centre: Sequence[float], radius: float = 1.0, rings: int = 16, segments: int = 32
) -> Any:
    """A UV sphere mesh with faceVarying-free vertex st, so baked textures map onto it."""
    points, st, counts, indices = [], [], [], []
    for i in range(rings + 1):
        v = i / rings
        theta = v * math.pi
        for j in range(segments + 1):
            u = j / segments
            phi = u * 2 * math.pi
            points.append(
                Gf.Vec3f(
                    centre[0] + radius * math.sin(theta) * math.cos(phi),
                    centre[1] + radius * math.cos(theta),
                    centre[2] - radius * math.sin(theta) * math.sin(phi),
                )
            )
            st.append(Gf.Vec2f(u, 1.0 - v))
    row = segments + 1
    for i in range(rings):
        for j in range(segments):
            a, b = i * row + j, (i + 1) * row + j
            counts.append(4)
            indices += [a, b, b + 1, a + 1]
    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(points)
    mesh.CreateFaceVertexCountsAttr(counts)
    mesh.CreateFaceVertexIndicesAttr(indices)
    mesh.CreateSubdivisionSchemeAttr("none")
    mesh.CreateExtentAttr(
        [
            Gf.Vec3f(centre[0] - radius, centre[1] - radius, centre[2] - radius),
            Gf.Vec3f(centre[0] + radius, centre[1] + radius, centre[2] + radius),
        ]
    )
    UsdGeom.PrimvarsAPI(mesh).CreatePrimvar("st", Sdf.ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.vertex).Set(st)
    return mesh


def bind(prim: Any, material: Any) -> None:
    UsdShade.MaterialBindingAPI.Apply(prim)
    UsdShade.MaterialBindingAPI(prim).Bind(material)


# Preview spheres at a real-world size (the stage is 1 m per unit): 10 cm across, 5 cm apart.
# Our choice: the size of a sample ball on a desk in AR.
SPHERE_RADIUS, SPHERE_GAP = 0.05, 0.05


def author_preview_meshes(stage: Any, root: Any, materials: Sequence[Any]) -> None:
    UsdGeom.Scope.Define(stage, root.AppendChild("Preview"))
    step = 2 * SPHERE_RADIUS + SPHERE_GAP
    first = -step * (len(materials) - 1) / 2  # centred on the origin
    for i, material in enumerate(materials):
        mesh = uv_sphere(
            stage,
            root.AppendChild("Preview").AppendChild(f"Sphere_{material.GetPrim().GetName()}"),
            (round(first + i * step, 6), SPHERE_RADIUS, 0.0),  # resting on the ground plane y = 0
            SPHERE_RADIUS,
        )
        bind(mesh.GetPrim(), material)


# ------------------------------------------------------------------------------------ emit


def output_format(options: Options) -> str:
    if options.format:
        return str(options.format)
    suffix = Path(options.output).suffix.lower().lstrip(".") if options.output else ""
    return suffix if suffix in FORMATS else "usda"


def new_stage(root_name: str) -> tuple[Any, Any]:
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    root = UsdGeom.Xform.Define(stage, Sdf.Path.absoluteRootPath.AppendChild(identifier(root_name, "Root")))
    stage.SetDefaultPrim(root.GetPrim())
    return stage, root.GetPath()


def build_stage(materials: Sequence[Material], options: Options, textures: Sequence[Textures]) -> Any:
    stage, root = new_stage(options.root)
    looks = root.AppendChild("Looks")
    UsdGeom.Scope.Define(stage, looks)
    natives = [mtlx_backend.native_maps(m) if options.maps == "native" else {} for m in materials]
    prims = author_materials(stage, looks, materials, textures, options.surface, natives, options.network)
    if options.mesh == "sphere":
        author_preview_meshes(stage, root, prims)
    return stage


def export(stage: Any, fmt: str, images: list[Artifact], stem: str = STEM) -> list[Artifact]:
    if fmt == "usda":
        return [Artifact(f"{stem}.usda", stage.GetRootLayer().ExportToString())] + images
    with tempfile.TemporaryDirectory(prefix="cnlmc-usd-") as tmp:
        layer_path = Path(tmp) / f"{stem}.usdc"
        stage.GetRootLayer().Export(str(layer_path))
        layer = layer_path.read_bytes()
    if fmt == "usdc":
        return [Artifact(layer_path.name, layer, "binary")] + images
    files = [(layer_path.name, layer)] + [(image.name, _bytes(image)) for image in images]
    return [Artifact(f"{stem}.usdz", usdz.package(files), "binary")]  # the textures travel inside


def _bytes(artifact: Artifact) -> bytes:
    return artifact.content if isinstance(artifact.content, bytes) else artifact.content.encode()


class UsdTarget(Target):
    name = "usd"
    description = "USD stage (.usda/.usdc/.usdz): UsdPreviewSurface + MaterialX OpenPBR networks, variants for 'or'"
    capabilities = CAPABILITIES
    options = OPTIONS

    def emit(self, document: Document, options: Options) -> EmitResult:
        idents = MaterialIdents(document.materials)
        table = capabilities_for(CAPABILITIES, options.maps)
        textures: dict[str, Textures] = {}

        def bake(material: Material) -> list[Artifact]:
            ident = idents[material]
            fmt = output_format(options)
            textures[ident], images = bake_textures(
                material,
                ident,
                options,
                roles=tuple(PREVIEW_TEXTURES),
                main=f"{STEM}.{fmt}",
                folder=PACKAGE_TEXTURES if fmt == "usdz" else None,
            )
            return images

        baked = emit_each(self, document, bake, lambda material: table)
        in_order = [textures[idents[m]] for m in document.materials]
        stage = build_stage(document.materials, options, in_order)
        return EmitResult(export(stage, output_format(options), baked.artifacts), baked.notes)


TARGET = UsdTarget()


def emit(ir: Document | Mapping[str, Any], options: Mapping[str, object] | None = None) -> EmitResult:
    """The target on an IR (typed or JSON form) with raw `--option` pairs."""
    return TARGET.emit_ir(ir, options)
