"""The 'materialx' target: a .mtlx document built with the MaterialX Python API.

One surface shader + surfacematerial per IR material: `open_pbr_surface` by default,
`standard_surface` with `--option surface=standard_surface`. Baked maps become `image`
nodes (colour in srgb_texture or lin_rec709, data without a colour transform). The source
phrase is the material's `doc` string. See docs/exchange.md.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping, Sequence
from typing import Any

import MaterialX as mx

from cnlmc.material import Document, MapRef, Material

from ..base import Artifact, Option, Options, Target, emit_each
from ..capabilities import ALL_FEATURES, EmitResult
from . import materialx_native as native
from .naming import MaterialIdents, display_name, phrase_text, unique_identifiers
from .options import Capabilities, capabilities_for, map_options
from .surface_inputs import SURFACE_NAMES, SURFACES, Inputs, surface_inputs, tangent_rotation
from .textures import Texture, Textures, bake_textures

# maps: bake (default), none, or native (MaterialX nodes where materialx_native has a recipe)
MAP_MODES = ("bake", "none", "native")
SURFACE_OPTION = Option(
    "surface", str, "open_pbr_surface", choices=SURFACES, doc="the MaterialX surface shader each material uses"
)

BAKED = ("bake", "procedural graph baked to an image read by an image node (no MaterialX nodes for cnlmc graphs)")
_SHARED = {
    "model.diffuse": ("exact", ""),
    "model.dielectric": ("exact", ""),
    "model.glass": ("exact", ""),
    "distribution.ggx": ("exact", ""),
    "distribution.ward": (
        "approximate",
        "no Ward lobe in MaterialX surfaces: anisotropic GGX with the same alpha_x, alpha_y",
    ),
    "anisotropic": ("exact", ""),
    "coat.color": (
        "approximate",
        "coat_color = color^thickness, the normal-incidence tint; the angular absorption is the shader's own",
    ),
    "flakes": (
        "drop",
        "OpenPBR and Standard Surface have no flake slot: the paint exports as its pigment under the coat; "
        "the flakes' brighter face, darker flop and sparkle are lost (docs/bsdf.md 'Flakes')",
    ),
    "subsurface.volume": (
        "approximate",
        "OpenPBR subsurface_* / Standard Surface subsurface: the albedo and the mean free path (scene unit: a metre) "
        "as the IR has them; the renderer inverts them its own way (subsurface_inputs.py)",
    ),
    "subsurface.thin": ("approximate", "the same inputs with geometry_thin_walled / thin_walled: the renderer's sheet"),
    "maps.base_color": BAKED,
    "maps.normal": BAKED,
    "maps.roughness": BAKED,
    "maps.metallic": BAKED,
    "maps.mask": ("drop", "a mask has no shading input of its own (the colour and roughness maps it drives are kept)"),
}
# Per-surface differences as a table.
CAPABILITIES_BY_SURFACE: dict[str, Capabilities] = {
    "open_pbr_surface": {
        **_SHARED,
        "model.conductor": (
            "approximate",
            "OpenPBR's F82-tint Schlick conductor fitted to the measured eta/k at 0 and 82 "
            "degrees: base_color = f0 (clipped to [0,1]), specular_color = f82 / Schlick(f0, 1/7)",
        ),
        "diffuse.oren_nayar": (
            "approximate",
            "OpenPBR's energy-preserving Oren-Nayar with base_diffuse_roughness = sigma (clipped to [0,1])",
        ),
        "coat": (
            "approximate",
            "OpenPBR coat (coat_ior, coat_roughness); OpenPBR also roughens and darkens the base "
            "under the coat, unlike the IR's Weidlich-Wilkie stack",
        ),
        "sheen": (
            "approximate",
            "OpenPBR fuzz (fuzz_weight = max(sheen_color), fuzz_color, fuzz_roughness = alpha): Zeltner's LTC "
            "sheen, not the Charlie lobe",
        ),
    },
    "standard_surface": {
        **_SHARED,
        "model.conductor": (
            "approximate",
            "Standard Surface's artistic conductor (Gulbrandsen): base_color = f0, "
            "specular_color = the edge tint that gives back the measured eta",
        ),
        "diffuse.oren_nayar": (
            "approximate",
            "Standard Surface's Oren-Nayar with diffuse_roughness = sigma (clipped to [0,1])",
        ),
        "coat": ("approximate", "Standard Surface coat (coat_IOR, coat_roughness); coat_affect_color/roughness stay 0"),
        "sheen": (
            "exact",
            "Standard Surface sheen (its lobe is the Charlie sheen): sheen, sheen_color, sheen_roughness",
        ),
    },
}
CAPABILITIES = CAPABILITIES_BY_SURFACE["open_pbr_surface"]
assert all(set(t) == set(ALL_FEATURES) for t in CAPABILITIES_BY_SURFACE.values())

# texture role -> (concept, image type); the concept is named per surface by SURFACE_NAMES
TEXTURE_INPUTS = {
    "base_color": ("base_color", "color3"),
    "roughness": ("roughness", "float"),
    "metallic": ("metalness", "float"),
    "normal": ("normal", "vector3"),
}
COLOUR_SPACES = {"srgb": "srgb_texture", "linear": "lin_rec709"}
MAIN_FILE = "materials.mtlx"  # the document's name when -o names a folder


def load_standard_library() -> Any:
    """MaterialX's standard node definitions (about 0.25 s: the target loads them once)."""
    lib = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), lib)
    return lib


def _value(mx_type: str, value: Any) -> Any:
    if mx_type == "color3":
        return mx.Color3(*value)
    if mx_type == "vector3":
        return mx.Vector3(*value)
    return value


def _set(node: Any, name: str, mx_type: str, value: Any) -> None:
    node.setInputValue(name, _value(mx_type, value), mx_type)


def add_image(doc: Any, ident: str, texture: Texture, mx_type: str) -> Any:
    image = doc.addNode("image", f"{ident}_{texture.role}_image", mx_type)
    file_input = image.setInputValue("file", texture.path, "filename")
    if texture.is_colour and mx_type == "color3":
        file_input.setColorSpace(COLOUR_SPACES[texture.encoding])
    return image


def texture_source(doc: Any, material: Material, ident: str, texture: Texture, surface: str, inputs: Inputs) -> Any:
    """The node whose output feeds the surface input for one baked role."""
    concept, mx_type = TEXTURE_INPUTS[texture.role]
    image = add_image(doc, ident, texture, mx_type)
    return map_source(doc, material, ident, texture.role, image, surface, inputs)


def map_source(doc: Any, material: Material, ident: str, role: str, image: Any, surface: str, inputs: Inputs) -> Any:
    """A map's node (baked image or native recipe) -> the node that feeds the surface input."""
    if role == "normal":
        normal = doc.addNode("normalmap", f"{ident}_normalmap", "vector3")
        normal.setConnectedNode("in", image)
        return normal
    if role == "base_color" and material.model.base == "conductor":  # the map is the tint on f0
        tint = doc.addNode("multiply", f"{ident}_base_color_f0", "color3")
        tint.setConnectedNode("in1", image)
        _set(tint, "in2", "color3", inputs[SURFACE_NAMES[surface]["base_color"]][1])
        return tint
    if role == "roughness" and material.params.alpha_convention == "linear":
        root = doc.addNode("sqrt", f"{ident}_roughness_sqrt", "float")  # alpha = r -> r' = sqrt(r)
        root.setConnectedNode("in", image)
        return root
    return image


def texture_targets(material: Material, role: str, surface: str) -> list[str]:
    names = SURFACE_NAMES[surface]
    if role == "base_color" and material.model.base == "glass":
        return [names["transmission_color"]]
    return [names[TEXTURE_INPUTS[role][0]]]


def add_tangent_rotation(doc: Any, ident: str, angle: float) -> Any:
    """OpenPBR has no rotation input: tangent = cos(angle) T + sin(angle) B, normalised (the node)."""
    tangent = doc.addNode("tangent", f"{ident}_tangent", "vector3")
    bitangent = doc.addNode("bitangent", f"{ident}_bitangent", "vector3")
    along = doc.addNode("multiply", f"{ident}_tangent_cos", "vector3")
    along.setConnectedNode("in1", tangent)
    _set(along, "in2", "vector3", [round(math.cos(angle), 6)] * 3)
    across = doc.addNode("multiply", f"{ident}_tangent_sin", "vector3")
    across.setConnectedNode("in1", bitangent)
    _set(across, "in2", "vector3", [round(math.sin(angle), 6)] * 3)
    total = doc.addNode("add", f"{ident}_tangent_sum", "vector3")
    total.setConnectedNode("in1", along)
    total.setConnectedNode("in2", across)
    unit = doc.addNode("normalize", f"{ident}_tangent_rotated", "vector3")
    unit.setConnectedNode("in", total)
    return unit


Natives = dict[str, MapRef]


def native_maps(material: Material) -> Natives:
    """role -> map ref for the maps maps=native expresses with MaterialX nodes. A rust-like
    mask becomes metalness = 1 - mask, only on a conductor without a metallic map of its own."""
    found = native.native_roles(material, (*TEXTURE_INPUTS, "mask"))
    if "mask" in found and (
        material.model.base != "conductor"
        or "metallic" in material.maps
        or native.recipe_for(found["mask"].graph, "metallic") is None
    ):
        del found["mask"]
    return found


class MapGraph:
    """The node graph `NG_<ident>` that holds one material's map nodes (images, native recipes,
    their conductor tint / sqrt / normalmap, the rotated tangent). Created on first use, so a
    material without maps has none; the shader reads each map through a graph output."""

    def __init__(self, doc: Any, ident: str, shader: Any):
        self.doc, self.ident, self.shader = doc, ident, shader
        self.graph: Any = None

    def nodes(self) -> Any:
        """Where map nodes are added (the graph)."""
        if self.graph is None:
            self.graph = self.doc.addNodeGraph(f"NG_{self.ident}")
        return self.graph

    def connect(self, target: str, source: Any) -> None:
        """shader.target <- the graph output that carries `source` (one output per source node)."""
        name = f"{source.getName()}_out"
        output = self.graph.getOutput(name) or self.graph.addOutput(name, source.getType())
        output.setConnectedNode(source)
        shader_input = self.shader.getInput(target) or self.shader.addInput(target, source.getType())
        shader_input.setConnectedOutput(output)


def add_material(
    doc: Any, material: Material, ident: str, surface: str, textures: Textures, natives: Natives | None = None
) -> None:
    shader = doc.addNode(surface, f"SR_{ident}", "surfaceshader")
    inputs = surface_inputs(material, surface)
    for name, (mx_type, value) in inputs.items():
        _set(shader, name, mx_type, value)
    graph = MapGraph(doc, ident, shader)
    for role, texture in textures.items():
        if role not in TEXTURE_INPUTS:
            continue
        source = texture_source(graph.nodes(), material, ident, texture, surface, inputs)
        for target in texture_targets(material, role, surface):
            graph.connect(target, source)
    for role, ref in (natives or {}).items():
        node = native.build(graph.nodes(), material, ident, ref)
        role = "metallic" if role == "mask" else role
        source = map_source(graph.nodes(), material, ident, role, node, surface, inputs)
        for target in texture_targets(material, role, surface):
            graph.connect(target, source)
    angle = tangent_rotation(material)
    if angle and "rotation" not in SURFACE_NAMES[surface]:
        graph.connect(SURFACE_NAMES[surface]["tangent"], add_tangent_rotation(graph.nodes(), ident, angle))
    node = doc.addMaterialNode(f"M_{ident}", shader)
    node.setDocString(phrase_text(material))
    if display_name(material):  # the name as written, where the identifier could not keep it
        node.setAttribute("uiname", display_name(material))


def new_document() -> Any:
    doc = mx.createDocument()
    doc.setColorSpace("lin_rec709")
    return doc


def build_document(
    materials: Sequence[Material],
    surface: str = "open_pbr_surface",
    textures: Mapping[str, Textures] | None = None,
    idents: Sequence[str] | None = None,
    natives: Mapping[str, Natives] | None = None,
) -> Any:
    """Typed materials -> a MaterialX Document (not yet validated). `natives`: ident -> role ->
    map ref for the maps expressed with MaterialX nodes (maps=native)."""
    idents = idents or unique_identifiers(m.name for m in materials)
    textures, natives = textures or {}, natives or {}
    doc = new_document()
    for material, ident in zip(materials, idents):
        add_material(doc, material, ident, surface, textures.get(ident, {}), natives.get(ident, {}))
    return doc


def node_graphs(doc: Any) -> list[Any]:
    """The document's own node graphs (not those of a data library it is set to)."""
    return [child for child in doc.getChildren() if child.getCategory() == "nodegraph"]


def validate(doc: Any, library: Any) -> None:
    doc.setDataLibrary(library)
    ok, message = doc.validate()
    if not ok:
        raise RuntimeError(f"materialx: the generated document does not validate: {message}")


def escape_attribute(text: str) -> str:
    """Escape for a double-quoted XML attribute, whitespace kept as character references."""
    table = {"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "\n": "&#10;", "\r": "&#13;", "\t": "&#9;"}
    return "".join(table.get(c, c) for c in text)


FREE_TEXT = ("doc", "uiname")  # attributes that hold free text (a phrase, a name as written)


def to_xml(doc: Any) -> str:
    """Serialise with MaterialX's writer. Its writer leaves '<' raw inside attributes (not
    well-formed XML), so free text (doc strings, ui names) is written through placeholders and
    escaped here."""
    options = mx.XmlWriteOptions()
    options.writeXIncludeEnable = False
    texts: dict[str, tuple[Any, str, str]] = {}
    for element in doc.traverseTree():
        for attribute in FREE_TEXT:
            if element.hasAttribute(attribute):
                key = f"cnlmc_text_placeholder_{len(texts)}"
                texts[key] = (element, attribute, element.getAttribute(attribute))
                element.setAttribute(attribute, key)
    try:
        xml = mx.writeToXmlString(doc, options)
    finally:
        for element, attribute, text in texts.values():
            element.setAttribute(attribute, text)
    for key, (_, attribute, text) in texts.items():
        xml = xml.replace(f'{attribute}="{key}"', f'{attribute}="{escape_attribute(text)}"', 1)
    return xml


class MaterialxBuild:
    """One .mtlx being built: the shared emit loop adds the materials one at a time."""

    def __init__(self, document: Document, options: Options):
        self.options = options
        self.idents = MaterialIdents(document.materials)
        self.table = capabilities_for(CAPABILITIES_BY_SURFACE[options.surface], options.maps)
        self.doc = new_document()

    def natives(self, material: Material) -> Natives:
        return native_maps(material) if self.options.maps == "native" else {}

    def capabilities_of(self, material: Material) -> Capabilities:
        """The surface's table; with maps=native, the maps with a recipe are approximations."""
        return {**self.table, **{f"maps.{role}": native.NATIVE for role in self.natives(material)}}

    def add(self, material: Material) -> list[Artifact]:
        """The material's shader and material nodes; returns its baked images."""
        ident, natives = self.idents[material], self.natives(material)
        roles = tuple(r for r in TEXTURE_INPUTS if r not in natives)
        textures, images = bake_textures(material, ident, self.options, roles=roles, main=MAIN_FILE)
        add_material(self.doc, material, ident, self.options.surface, textures, natives)
        return images


class MaterialxTarget(Target):
    name = "materialx"
    description = "MaterialX document (.mtlx): OpenPBR Surface (or standard_surface) with baked image maps"
    capabilities = CAPABILITIES
    options = (*map_options(MAP_MODES), SURFACE_OPTION)

    @functools.cached_property
    def library(self) -> Any:
        """The standard library every document is validated against (loaded on first use)."""
        return load_standard_library()

    def emit(self, document: Document, options: Options) -> EmitResult:
        build = MaterialxBuild(document, options)
        images = emit_each(self, document, build.add, build.capabilities_of)
        validate(build.doc, self.library)
        return EmitResult([Artifact(MAIN_FILE, to_xml(build.doc)), *images.artifacts], images.notes)


TARGET = MaterialxTarget()


def emit(ir: Document | Mapping[str, Any], options: Mapping[str, object] | None = None) -> EmitResult:
    """The target on an IR (typed or JSON form) with raw `--option` pairs."""
    return TARGET.emit_ir(ir, options)
