"""The 'materialx' target: a .mtlx document built with the MaterialX Python API.

One surface shader + surfacematerial per IR material: `open_pbr_surface` by default,
`standard_surface` with `--option surface=standard_surface`. Baked maps become `image`
nodes (colour in srgb_texture or lin_rec709, data without a colour transform). The source
phrase is the material's `doc` string. See docs/exchange.md.
"""

from __future__ import annotations

import functools
import math

import MaterialX as mx

from ..capabilities import ALL_FEATURES, EmitResult, check_material
from ..registry import Artifact
from . import materialx_native as native
from .naming import phrase_text, unique_identifiers
from .options import capabilities_for, exchange_options
from .surface_inputs import SURFACE_NAMES, SURFACES, surface_inputs, tangent_rotation
from .textures import bake_textures

NAME = "materialx"
DESCRIPTION = "MaterialX document (.mtlx): OpenPBR Surface (or standard_surface) with baked image maps"
OPTIONS = {"surface": ("open_pbr_surface", SURFACES)}
# maps: bake (default), none, or native (MaterialX nodes where materialx_native has a recipe)
MAP_MODES = ("bake", "none", "native")

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
    "maps.base_color": BAKED,
    "maps.normal": BAKED,
    "maps.roughness": BAKED,
    "maps.metallic": BAKED,
    "maps.mask": ("drop", "a mask has no shading input of its own (the colour and roughness maps it drives are kept)"),
}
# Per-surface differences as a table.
CAPABILITIES_BY_SURFACE = {
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


@functools.lru_cache(maxsize=1)
def standard_library():
    lib = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), lib)
    return lib


def _value(mx_type: str, value):
    if mx_type == "color3":
        return mx.Color3(*value)
    if mx_type == "vector3":
        return mx.Vector3(*value)
    return value


def _set(node, name: str, mx_type: str, value) -> None:
    node.setInputValue(name, _value(mx_type, value), mx_type)


def add_image(doc, ident: str, texture, mx_type: str):
    image = doc.addNode("image", f"{ident}_{texture.role}_image", mx_type)
    file_input = image.setInputValue("file", texture.path, "filename")
    if texture.is_colour and mx_type == "color3":
        file_input.setColorSpace(COLOUR_SPACES[texture.encoding])
    return image


def texture_source(doc, material: dict, ident: str, texture, surface: str, inputs: dict):
    """The node whose output feeds the surface input for one baked role."""
    concept, mx_type = TEXTURE_INPUTS[texture.role]
    image = add_image(doc, ident, texture, mx_type)
    return map_source(doc, material, ident, texture.role, image, surface, inputs)


def map_source(doc, material: dict, ident: str, role: str, image, surface: str, inputs: dict):
    """A map's node (baked image or native recipe) -> the node that feeds the surface input."""
    base = material["model"]["base"]
    if role == "normal":
        normal = doc.addNode("normalmap", f"{ident}_normalmap", "vector3")
        normal.setConnectedNode("in", image)
        return normal
    if role == "base_color" and base == "conductor":  # the map is the tint on f0
        tint = doc.addNode("multiply", f"{ident}_base_color_f0", "color3")
        tint.setConnectedNode("in1", image)
        _set(tint, "in2", "color3", inputs[SURFACE_NAMES[surface]["base_color"]][1])
        return tint
    if role == "roughness" and material["params"].get("alpha_convention") == "linear":
        root = doc.addNode("sqrt", f"{ident}_roughness_sqrt", "float")  # alpha = r -> r' = sqrt(r)
        root.setConnectedNode("in", image)
        return root
    return image


def texture_targets(material: dict, role: str, surface: str) -> list[str]:
    names = SURFACE_NAMES[surface]
    if role == "base_color" and material["model"]["base"] == "glass":
        return [names["transmission_color"]]
    return [names[TEXTURE_INPUTS[role][0]]]


def add_tangent_rotation(doc, ident: str, shader, angle: float, surface: str) -> None:
    """OpenPBR has no rotation input: tangent = cos(angle) T + sin(angle) B, normalised."""
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
    shader.setConnectedNode(SURFACE_NAMES[surface]["tangent"], unit)


def native_maps(material: dict) -> dict:
    """role -> map ref for the maps maps=native expresses with MaterialX nodes. A rust-like
    mask becomes metalness = 1 - mask, only on a conductor without a metallic map of its own."""
    found = native.native_roles(material, tuple(TEXTURE_INPUTS) + ("mask",))
    if "mask" in found and (
        material["model"]["base"] != "conductor"
        or "metallic" in (material.get("maps") or {})
        or native.recipe_for({**found["mask"], "output": "metallic"}) is None
    ):
        del found["mask"]
    return found


def add_material(doc, material: dict, ident: str, surface: str, textures: dict, natives=None) -> None:
    shader = doc.addNode(surface, f"SR_{ident}", "surfaceshader")
    inputs = surface_inputs(material, surface)
    for name, (mx_type, value) in inputs.items():
        _set(shader, name, mx_type, value)
    for role, texture in textures.items():
        if role not in TEXTURE_INPUTS:
            continue
        source = texture_source(doc, material, ident, texture, surface, inputs)
        for target in texture_targets(material, role, surface):
            shader.setConnectedNode(target, source)
    for role, ref in (natives or {}).items():
        node = native.build(doc, material, ident, role, ref)
        role = "metallic" if role == "mask" else role
        source = map_source(doc, material, ident, role, node, surface, inputs)
        for target in texture_targets(material, role, surface):
            shader.setConnectedNode(target, source)
    angle = tangent_rotation(material)
    if angle and "rotation" not in SURFACE_NAMES[surface]:
        add_tangent_rotation(doc, ident, shader, angle, surface)
    node = doc.addMaterialNode(f"M_{ident}", shader)
    node.setDocString(phrase_text(material))


def build_document(materials: list[dict], surface: str = "open_pbr_surface", textures=None, idents=None, natives=None):
    """IR materials -> a MaterialX Document (not yet validated). `natives`: ident -> role -> map
    ref for the maps expressed with MaterialX nodes (maps=native)."""
    idents = idents or unique_identifiers(m["name"] for m in materials)
    textures, natives = textures or {}, natives or {}
    doc = mx.createDocument()
    doc.setColorSpace("lin_rec709")
    for material, ident in zip(materials, idents):
        add_material(doc, material, ident, surface, textures.get(ident, {}), natives.get(ident, {}))
    return doc


def validate(doc) -> None:
    doc.setDataLibrary(standard_library())
    ok, message = doc.validate()
    if not ok:
        raise RuntimeError(f"materialx: the generated document does not validate: {message}")


def escape_attribute(text: str) -> str:
    """Escape for a double-quoted XML attribute, whitespace kept as character references."""
    table = {"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "\n": "&#10;", "\r": "&#13;", "\t": "&#9;"}
    return "".join(table.get(c, c) for c in text)


def to_xml(doc) -> str:
    """Serialise with MaterialX's writer. Its writer leaves '<' raw inside attributes (not
    well-formed XML), so free text (doc strings) is written through placeholders and escaped here."""
    options = mx.XmlWriteOptions()
    options.writeXIncludeEnable = False
    texts = {}
    for i, element in enumerate(e for e in doc.traverseTree() if e.hasAttribute("doc")):
        key = f"cnlmc_doc_placeholder_{i}"
        texts[key] = (element, element.getDocString())
        element.setDocString(key)
    try:
        xml = mx.writeToXmlString(doc, options)
    finally:
        for element, text in texts.values():
            element.setDocString(text)
    for key, (_, text) in texts.items():
        xml = xml.replace(f'doc="{key}"', f'doc="{escape_attribute(text)}"', 1)
    return xml


def map_mode(options: dict | None, target: str) -> tuple[dict, str]:
    """Take maps=native out (the shared option check knows bake and none); check the value."""
    options = dict(options or {})
    mode = str(options.get("maps", "bake"))
    if mode not in MAP_MODES:
        raise ValueError(f"{target}: option maps={mode!r}: use one of {', '.join(MAP_MODES)}")
    if mode == "native":
        options["maps"] = "bake"
    return options, mode


def prepare(ir: dict, options: dict, target: str = NAME, extra=None):
    """Options, identifiers, capability notes and baked textures for a list of materials.
    With maps=native, `natives` (ident -> role -> map ref) are the maps with a recipe; the
    rest are baked through the same capability path."""
    options, mode = map_mode(options, target)
    opts = exchange_options(options, target, {**OPTIONS, **(extra or {})})
    opts["maps"] = mode
    caps = capabilities_for(CAPABILITIES_BY_SURFACE[opts["surface"]], opts)
    materials = ir["materials"]
    idents = unique_identifiers(m["name"] for m in materials)
    notes, textures, natives, artifacts = [], {}, {}, []
    for material, ident in zip(materials, idents):
        natives[ident] = native_maps(material) if mode == "native" else {}
        material_caps = {**caps, **{f"maps.{role}": native.NATIVE for role in natives[ident]}}
        check_material(notes, target, material_caps, material)
        roles = tuple(r for r in TEXTURE_INPUTS if r not in natives[ident])
        textures[ident], baked = bake_textures(
            material, ident, {**opts, "maps": "none" if mode == "none" else "bake"}, roles=roles
        )
        artifacts += baked
    return opts, idents, notes, textures, natives, artifacts


def emit(ir: dict, options: dict) -> EmitResult:
    opts, idents, notes, textures, natives, images = prepare(ir, options)
    doc = build_document(ir["materials"], opts["surface"], textures, idents, natives)
    validate(doc)
    return EmitResult([Artifact("materials.mtlx", to_xml(doc))] + images, notes)
