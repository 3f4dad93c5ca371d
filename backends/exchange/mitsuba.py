"""The 'mitsuba' target: Mitsuba 3 scene XML from jinja2 templates (templates/mitsuba/*.j2).

`form=scene` (default): camera, constant (or `envmap=PATH`) light, one sphere per material,
`<default>` spp/resx/resy. `form=fragment`: just the BSDFs, to include or reference by id.
Plugins: diffuse, plastic/roughplastic, conductor/roughconductor (RGB eta/k),
dielectric/roughdielectric, principled (coat, anisotropic plastic), twosided, normalmap and
bitmap textures from baked maps. Every value is escaped by the template engine.
"""

from __future__ import annotations

import functools
import math
import re

import numpy as np

from ..capabilities import ALL_FEATURES, EmitResult, check_material
from ..registry import Artifact
from .conversions import alpha_pair, alpha_to_roughness, clip01, conductor_f0, rounded
from .naming import unique_identifiers, xml_text
from .options import capabilities_for, exchange_options
from .textures import bake_textures

NAME = "mitsuba"
DESCRIPTION = "Mitsuba 3 scene XML (full preview scene or BSDF fragment) with baked bitmap textures"
OPTIONS = {
    "form": ("scene", ("scene", "fragment")),
    "spp": ("64", None),
    "resolution": ("256", None),
    "max_depth": ("8", None),
    "envmap": ("", None),
    "bsdf": ("native", ("native", "cnlm")),
}
ALPHA_MIRROR = 1e-3
TEXTURED_ALPHA = ("roughconductor", "roughdielectric")  # roughplastic's alpha is a float

BAKED = ("bake", "procedural graph baked to a bitmap texture")
CAPABILITIES = {
    "model.diffuse": ("exact", ""),
    "model.dielectric": (
        "approximate",
        "roughplastic layers its diffuse base differently (rough-interface "
        "transmittance and internal re-reflection, not (1 - F)(1 - F)); bsdf=cnlm renders cnlmc's own",
    ),
    "model.conductor": ("exact", ""),
    "model.glass": ("exact", ""),
    "distribution.ggx": ("exact", ""),
    "distribution.ward": ("approximate", "Mitsuba 3 has no Ward BSDF: anisotropic GGX with the same alpha_u, alpha_v"),
    "anisotropic": (
        "approximate",
        "rough conductors and glass take alpha_u/alpha_v directly, but the streaks follow "
        "the UV tangent (no rotation); an anisotropic plastic becomes `principled` (Disney diffuse, Schlick)",
    ),
    "diffuse.oren_nayar": ("approximate", "Mitsuba 3 has no Oren-Nayar plugin: Lambertian `diffuse`"),
    "coat": (
        "approximate",
        "Mitsuba 3 has no coating BSDF: `principled` with clearcoat 1 (Disney's GTR1 coat at a "
        "fixed IOR 1.5, gloss from the coat roughness); a coated metal uses Schlick with base_color = f0",
    ),
    "coat.color": ("drop", "principled's clear coat is colourless"),
    "maps.base_color": BAKED,
    "maps.roughness": (
        "bake",
        "baked and converted to alpha = r^2 bitmaps; roughplastic takes one float "
        "alpha, so there the map's mean is used",
    ),
    "maps.normal": ("bake", "baked tangent-space normals through the `normalmap` plugin"),
    "maps.metallic": ("drop", "a metallic map would need a blend of two BSDFs; the uniform metalness is used"),
    "maps.mask": ("drop", "a mask has no shading input of its own (the colour and roughness maps it drives are kept)"),
}
assert set(CAPABILITIES) == set(ALL_FEATURES)
#: bsdf=cnlm: the plugin evaluates cnlmc's BSDF itself; like the GLSL backend it has no metallic map.
CNLM_CAPABILITIES = dict.fromkeys(ALL_FEATURES, ("exact", ""))
CNLM_CAPABILITIES["maps.metallic"] = ("drop", "no IR model reads a metallic map")
USED_MAPS = ("base_color", "roughness", "normal")
#: `bsdf=cnlm`: cnlmc's own BSDF through the `cnlm` plugin (backends/exchange/mitsuba_cnlm.py), which
#: reads these maps itself (normals still go through `normalmap`).
CNLM_MAPS = ("base_color", "roughness", "normal", "mask")


# ----------------------------------------------------------------------------- properties


def prop(kind: str, name: str, value) -> dict:
    if kind == "float":
        value = f"{float(value):.6g}"
    elif kind == "rgb":
        value = [f"{float(v):.6g}" for v in value]
    return {"kind": kind, "name": name, "value": value}


def bitmap(name: str, texture) -> dict:
    props = [prop("string", "filename", texture.path), prop("boolean", "raw", texture.encoding != "srgb")]
    return prop("texture", name, {"type": "bitmap", "props": props})


def colour(name: str, value, texture=None) -> dict:
    return bitmap(name, texture) if texture else prop("rgb", name, rounded(clip01(value)))


def node(plugin: str, props, children=()) -> dict:
    return {"type": plugin, "id": None, "props": list(props), "children": list(children)}


# -------------------------------------------------------------------------- plugin choice


def plugin_for(material: dict) -> str:
    """The Mitsuba plugin for an IR material (the decision table, in order)."""
    model, params = material["model"], material["params"]
    base = model["base"]
    if base == "diffuse":
        return "diffuse"
    if model["coat"] or (base == "dielectric" and model["anisotropic"]):
        return "principled"
    mirror = max(alpha_pair(params)) < ALPHA_MIRROR
    return {
        "dielectric": ("roughplastic", "plastic"),
        "conductor": ("roughconductor", "conductor"),
        "glass": ("roughdielectric", "dielectric"),
    }[base][mirror]


class AlphaMaps:
    """Baked roughness (perceptual, IR convention) -> the alpha maps the chosen plugin reads.

    roughplastic takes only a uniform alpha: it gets the mean of the map (`mean_alpha`).
    """

    def __init__(self, material: dict):
        self.params = material["params"]
        self.plugin = plugin_for(material)
        self.anisotropy = float(self.params.get("anisotropy") or 0.0) if material["model"]["anisotropic"] else 0.0
        self.mean_alpha = None

    def __call__(self, arrays: dict) -> dict:
        if "roughness" not in arrays:
            return arrays
        r = np.asarray(arrays.pop("roughness"), np.float32)
        alpha = r if self.params.get("alpha_convention") == "linear" else r * r
        if self.plugin == "principled":
            arrays["principled_roughness"] = np.sqrt(alpha)
        elif self.plugin not in TEXTURED_ALPHA:
            self.mean_alpha = float(alpha.mean())  # plastic: one float; mirrors: none
        elif self.anisotropy:
            s = math.sqrt(1.0 - 0.9 * self.anisotropy)
            arrays["alpha_u"], arrays["alpha_v"] = np.clip(alpha / s, 0, 1), alpha * s
        else:
            arrays["alpha"] = alpha
        return arrays


def roughness_props(material: dict, tex: dict) -> list[dict]:
    ax, ay = alpha_pair(material["params"])
    if "mean_alpha" in tex:
        ax = ay = tex["mean_alpha"]
    props = [prop("string", "distribution", "ggx")]
    if material["model"]["anisotropic"] and abs(ax - ay) > 1e-9:
        for name, value in (("alpha_u", ax), ("alpha_v", ay)):
            props.append(bitmap(name, tex[name]) if name in tex else prop("float", name, value))
    else:
        props.append(bitmap("alpha", tex["alpha"]) if "alpha" in tex else prop("float", "alpha", ax))
    return props


def diffuse_bsdf(material, tex):
    return node("diffuse", [colour("reflectance", material["params"]["base_color"], tex.get("base_color"))])


def plastic_bsdf(material, tex, rough: bool):
    params = material["params"]
    props = [
        prop("float", "int_ior", params["ior"]),
        prop("float", "ext_ior", 1.0),
        colour("diffuse_reflectance", params["base_color"], tex.get("base_color")),
    ]
    return node("roughplastic" if rough else "plastic", (roughness_props(material, tex) if rough else []) + props)


def conductor_bsdf(material, tex, rough: bool):
    params = material["params"]
    props = [
        prop("rgb", "eta", rounded(params["eta"])),
        prop("rgb", "k", rounded(params["k"])),
        colour("specular_reflectance", params["base_color"], tex.get("base_color")),
    ]
    return node("roughconductor" if rough else "conductor", (roughness_props(material, tex) if rough else []) + props)


def glass_bsdf(material, tex, rough: bool):
    params = material["params"]
    props = [
        prop("float", "int_ior", params["ior"]),
        prop("float", "ext_ior", 1.0),
        colour("specular_transmittance", params["base_color"], tex.get("base_color")),
    ]
    return node("roughdielectric" if rough else "dielectric", (roughness_props(material, tex) if rough else []) + props)


def principled_bsdf(material, tex):
    """Coats and anisotropic plastics: Mitsuba's principled (Disney) BSDF."""
    model, params = material["model"], material["params"]
    base = model["base"]
    ax, ay = alpha_pair(params)
    alpha = math.sqrt(ax * ay)
    base_color = conductor_f0(params) if base == "conductor" else params["base_color"]
    props = [
        colour("base_color", base_color, tex.get("base_color") if base != "conductor" else None),
        prop("float", "metallic", 1.0 if base == "conductor" else 0.0),
    ]
    roughness = alpha_to_roughness(alpha)  # principled: alpha = roughness^2
    props.append(
        bitmap("roughness", tex["principled_roughness"])
        if "principled_roughness" in tex
        else prop("float", "roughness", roughness)
    )
    if model["anisotropic"]:
        props.append(prop("float", "anisotropic", min(max(float(params.get("anisotropy") or 0.0), 0.0), 1.0)))
    if "ior" in params:
        props.append(prop("float", "eta", params["ior"]))
    if base == "glass":
        props.append(prop("float", "spec_trans", 1.0))
    if model["coat"] and params.get("coat"):
        coat_alpha = float(params["coat"]["alpha"][0])
        gloss = min(max((0.1 - coat_alpha) / 0.099, 0.0), 1.0)  # Disney: alpha_c = lerp(0.1, 0.001, gloss)
        props += [prop("float", "clearcoat", 1.0), prop("float", "clearcoat_gloss", gloss)]
    return node("principled", props)


BUILDERS = {
    "diffuse": diffuse_bsdf,
    "principled": principled_bsdf,
    "roughplastic": functools.partial(plastic_bsdf, rough=True),
    "plastic": functools.partial(plastic_bsdf, rough=False),
    "roughconductor": functools.partial(conductor_bsdf, rough=True),
    "conductor": functools.partial(conductor_bsdf, rough=False),
    "roughdielectric": functools.partial(glass_bsdf, rough=True),
    "dielectric": functools.partial(glass_bsdf, rough=False),
}
TRANSMISSIVE = {"roughdielectric", "dielectric"}


def cnlm_bsdf(material: dict, tex: dict) -> dict:
    """The `cnlm` plugin: the IR material (name, model, params) as JSON plus the raw maps it
    reads. '$' is written as a JSON escape: Mitsuba's loader substitutes $parameters in strings."""
    import json

    shading = {key: material[key] for key in ("name", "model", "params")}
    text = json.dumps(shading, sort_keys=True, default=float).replace("$", "\\u0024")
    props = [prop("string", "material", text)]
    props += [bitmap(role, tex[role]) for role in ("base_color", "roughness", "mask") if role in tex]
    return node("cnlm", props)


def uses_cnlm(material: dict, opts: dict) -> bool:
    """bsdf=cnlm applies to every reflective model; glass keeps roughdielectric (its exact match)."""
    return opts.get("bsdf") == "cnlm" and material["model"]["base"] != "glass"


def bsdf_for(material: dict, ident: str, tex: dict, cnlm: bool = False) -> dict:
    """The BSDF tree: plugin, then twosided (opaque ones), then normalmap; the root gets the id."""
    plugin = "cnlm" if cnlm else plugin_for(material)
    tree = cnlm_bsdf(material, tex) if cnlm else BUILDERS[plugin](material, tex)
    if plugin not in TRANSMISSIVE and material["model"]["base"] != "glass":
        tree = node("twosided", [], [tree])
    if "normal" in tex:
        tree = node("normalmap", [bitmap("normalmap", tex["normal"])], [tree])
    tree["id"] = ident
    return tree


# ------------------------------------------------------------------------------- templates


def comment(value) -> str:
    """Safe inside <!-- -->: no '--', no trailing '-', one line."""
    text = xml_text(value).replace("\r", " ").replace("\n", " ")
    text = re.sub("-(?=-)", "- ", text)
    return text + " " if text.endswith("-") else text


def _finalize(value):
    import markupsafe

    return xml_text(value) if isinstance(value, str) and not isinstance(value, markupsafe.Markup) else value


@functools.lru_cache(maxsize=1)
def environment():
    import jinja2

    env = jinja2.Environment(
        loader=jinja2.PackageLoader("cnlmc.backends.exchange", "templates/mitsuba"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        finalize=_finalize,
    )
    env.filters["comment"] = comment
    return env


def layout(count: int) -> tuple[list[list[float]], dict]:
    """Sphere centres on a grid and a camera that frames them."""
    cols = math.ceil(math.sqrt(count))
    rows = math.ceil(count / cols)
    spacing = 2.5
    centres = [
        [(i % cols - (cols - 1) / 2) * spacing, ((rows - 1) / 2 - i // cols) * spacing, 0.0] for i in range(count)
    ]
    extent = max(cols, rows) * spacing
    fov = 40.0
    distance = extent / (2 * math.tan(math.radians(fov / 2))) + 1.5
    return centres, {"fov": fov, "origin": [0, 0, round(distance, 4)], "target": [0, 0, 0]}


@functools.lru_cache(maxsize=1)
def version() -> str:
    try:
        from importlib.metadata import version as dist_version

        return dist_version("cnlmc")
    except Exception:  # pragma: no cover - not installed
        return "dev"


def render_xml(entries: list[dict], opts: dict) -> str:
    env = environment()
    if opts["form"] == "fragment":
        return env.get_template("fragment.xml.j2").render(materials=entries, version=version())
    centres, camera = layout(len(entries))
    for entry, centre in zip(entries, centres):
        entry["center"] = centre
    return env.get_template("scene.xml.j2").render(
        materials=entries,
        camera=camera,
        spp=opts["spp"],
        resolution=opts["resolution"],
        max_depth=opts["max_depth"],
        envmap=opts["envmap"],
        version=version(),
    )


def parse_options(options: dict) -> dict:
    opts = exchange_options(options, NAME, OPTIONS)
    for name in ("spp", "resolution", "max_depth"):
        try:
            opts[name] = int(opts[name])
        except ValueError:
            raise ValueError(f"mitsuba: option {name}={opts[name]!r} must be a whole number") from None
        if opts[name] < 1:
            raise ValueError(f"mitsuba: option {name} must be at least 1")
    return opts


def emit(ir: dict, options: dict) -> EmitResult:
    opts = parse_options(options)
    caps = capabilities_for(CAPABILITIES, opts)
    materials = ir["materials"]
    notes, entries, images = [], [], []
    for material, ident in zip(materials, unique_identifiers(m["name"] for m in materials)):
        cnlm = uses_cnlm(material, opts)
        check_material(notes, NAME, capabilities_for(CNLM_CAPABILITIES, opts) if cnlm else caps, material)
        alpha_maps = None if cnlm else AlphaMaps(material)
        tex, baked = bake_textures(material, ident, opts, roles=CNLM_MAPS if cnlm else USED_MAPS, derive=alpha_maps)
        if alpha_maps and alpha_maps.mean_alpha is not None and plugin_for(material) == "roughplastic":
            tex["mean_alpha"] = alpha_maps.mean_alpha
        images += baked
        entries.append(
            {"ident": ident, "phrase": material.get("phrase", ""), "bsdf": bsdf_for(material, ident, tex, cnlm)}
        )
    name = "materials.xml" if opts["form"] == "fragment" else "scene.xml"
    return EmitResult([Artifact(name, render_xml(entries, opts))] + images, notes)
