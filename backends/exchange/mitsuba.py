"""The 'mitsuba' target: Mitsuba 3 scene XML from jinja2 templates (templates/mitsuba/*.j2).

`form=scene` (default): camera, constant (or `envmap=PATH`) light, one sphere per material,
`<default>` spp/resx/resy. `form=fragment`: just the BSDFs, to include or reference by id.
Plugins: diffuse, plastic/roughplastic, conductor/roughconductor (RGB eta/k),
dielectric/roughdielectric, principled (coat, anisotropic plastic), twosided, normalmap and
bitmap textures from baked maps. Every value is escaped by the template engine.
"""

from __future__ import annotations

import functools
import json
import math
import re
from collections.abc import Callable, Iterable, Mapping
from importlib.metadata import PackageNotFoundError
from importlib.metadata import version as dist_version
from typing import Any

import jinja2
import markupsafe
import numpy as np

from cnlmc.bsdf.flakes import coat_trap
from cnlmc.bsdf.sheen import has_sheen
from cnlmc.conventions import ALPHA_MIRROR, alpha_isotropic, alpha_of
from cnlmc.diagnostics import visible
from cnlmc.material import Document, Material

from ..base import Artifact, Option, Options, Target, emit_each
from ..capabilities import ALL_FEATURES, EmitResult
from .conversions import (
    alpha_pair,
    alpha_to_roughness,
    base_under_coat,
    clip01,
    conductor_f0,
    diffuse_colour,
    diffuse_energy,
    hemispherical_albedo,
    measured,
    principled_clearcoat,
    roughplastic_colour,
    roughplastic_diffuse_energy,
    roughplastic_diffuse_scale,
    rounded,
    with_base_color,
    without_extras,
)
from .mitsuba_principled import fabric_roughness, sheen_base
from .mitsuba_subsurface import VOLUME_MAX_DEPTH, medium_entry, roulette_depth, subsurface_bsdf
from .naming import MaterialIdents, described, xml_text
from .options import Capabilities, capabilities_for, map_options
from .textures import Texture, bake_textures

OPTIONS = (
    *map_options(),
    Option("form", str, "scene", choices=("scene", "fragment"), doc="scene: a preview scene; fragment: BSDFs only"),
    Option("spp", int, 64, doc="samples per pixel of the scene", range=(1, 1 << 20)),
    Option("resolution", int, 256, doc="the scene's image width and height", range=(1, 16384)),
    Option("max_depth", int, 8, doc="the path tracer's maximum depth", range=(1, 1024)),
    Option("envmap", str, "", doc="an environment map lighting the scene (default: constant light)"),
    Option("bsdf", str, "native", choices=("native", "cnlm"), doc="native plugins, or cnlmc's own BSDF (cnlm)"),
    Option("unit_metres", float, 0.05, doc="metres per scene unit, for a medium's mean free path", range=(1e-6, 1e6)),
)
TEXTURED_ALPHA = ("roughconductor", "roughdielectric")  # roughplastic's alpha is a float

BAKED = ("bake", "procedural graph baked to a bitmap texture")
CAPABILITIES: Capabilities = {
    "model.diffuse": ("exact", ""),
    "model.dielectric": (
        "approximate",
        "roughplastic layers its diffuse base differently (rough-interface "
        "transmittance and internal re-reflection, not (1 - F)(1 - F)): its diffuse_reflectance is set to "
        "give the IR's hemispherical energy (clipped to 1); bsdf=cnlm renders cnlmc's own",
    ),
    "model.conductor": ("exact", ""),
    "model.glass": (
        "exact",
        "a dielectric around a homogeneous absorbing medium: Beer-Lambert through transmission_depth",
    ),
    "distribution.ggx": ("exact", ""),
    "distribution.ward": ("approximate", "Mitsuba 3 has no Ward BSDF: anisotropic GGX with the same alpha_u, alpha_v"),
    "anisotropic": (
        "approximate",
        "rough conductors and glass take alpha_u/alpha_v directly, but the streaks follow "
        "the UV tangent (no rotation); an anisotropic plastic becomes `principled` (Disney diffuse, Schlick)",
    ),
    "diffuse.oren_nayar": (
        "approximate",
        "Mitsuba 3 has no Oren-Nayar plugin: Lambertian `diffuse` with the lobe's hemispherical albedo (its energy)",
    ),
    "coat": (
        "approximate",
        "Mitsuba 3 has no coating BSDF: a coat over a plastic or paint is `roughplastic` (the coat's IOR and "
        "alpha over the diffuse base, with internal reflection, nonlinear as the IR's); over a metal or an anisotropic plastic "
        "`principled` (Disney's GTR1 coat, Schlick F0 0.04) with the clearcoat weight of the coat lobe's "
        "energy and the base dimmed by what the coat lets through (both from the reference: the IR's energy)",
    ),
    "coat.color": (
        "approximate",
        "roughplastic: color^thickness tints the base under it; principled's coat is colourless",
    ),
    "sheen": (
        "approximate",
        "principled's sheen is Disney's (a (1 - cos)^5 grazing term, no roughness), weight at most 1 "
        "(Burley's range), sheen_tint 1: at full weight it returns ~1 % of the light where the IR's fibres "
        "return up to ~11 %, so the rest of the fibres' energy is in the base colour: the hemispherical "
        "energy is the IR's, the rim is dimmer and the face brighter than the IR's; bsdf=cnlm draws the Charlie sheen",
    ),
    "flakes": (
        "drop",
        "no native Mitsuba BSDF has flakes: the paint's pigment under its coat; bsdf=cnlm draws them",
    ),
    "subsurface.volume": (
        "exact",
        "a dielectric boundary around a homogeneous medium, volpathmis (mitsuba_subsurface.py)",
    ),
    "subsurface.thin": (
        "approximate",
        "blendbsdf: a two-sided diffuse front of base_color and a diffuse transmitter of the Kubelka-Munk T: "
        "diffuse through, no forward peak",
    ),
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
CNLM_CAPABILITIES: dict[str, tuple[str, str]] = dict.fromkeys(ALL_FEATURES, ("exact", ""))
CNLM_CAPABILITIES["maps.metallic"] = ("drop", "no IR model reads a metallic map")
CNLM_CAPABILITIES["subsurface.thin"] = CAPABILITIES["subsurface.thin"]  # a medium is always native
USED_MAPS = ("base_color", "roughness", "normal")
#: `bsdf=cnlm`: cnlmc's own BSDF through the `cnlm` plugin (mitsuba_cnlm.py), which
#: reads these maps itself (normals still go through `normalmap`).
CNLM_MAPS = ("base_color", "roughness", "normal", "mask")


# ----------------------------------------------------------------------------- properties

Prop = dict[str, Any]
#: role -> Texture for the bitmaps a BSDF reads; roughplastic's 'mean_alpha' -> float beside them
BsdfTextures = dict[str, Any]


def prop(kind: str, name: str, value: Any) -> Prop:
    if kind == "float":
        value = f"{float(value):.6g}"
    elif kind == "rgb":
        value = [f"{float(v):.6g}" for v in value]
    return {"kind": kind, "name": name, "value": value}


def bitmap(name: str, texture: Texture) -> Prop:
    props = [prop("string", "filename", texture.path), prop("boolean", "raw", texture.encoding != "srgb")]
    return prop("texture", name, {"type": "bitmap", "props": props})


def colour(name: str, value: Iterable[float], texture: Texture | None = None) -> Prop:
    return bitmap(name, texture) if texture else prop("rgb", name, rounded(clip01(value)))


def node(plugin: str, props: Iterable[Prop], children: Iterable[Prop] = ()) -> Prop:
    return {"type": plugin, "id": None, "props": list(props), "children": list(children)}


# -------------------------------------------------------------------------- plugin choice


def plugin_for(material: Material) -> str:
    """The Mitsuba plugin for an IR material (the decision table, in order)."""
    model = material.model
    base = model.base
    if has_sheen(material) and base in ("diffuse", "dielectric"):
        return "principled"  # the one native plugin with a sheen (Disney's: docs/bsdf.md "Sheen")
    if base == "diffuse":
        return "diffuse"
    if model.coat and base == "dielectric" and not model.anisotropic:
        return "coated"
    if model.coat or (base == "dielectric" and model.anisotropic):
        return "principled"
    mirror = max(alpha_pair(material.params)) < ALPHA_MIRROR
    return {
        "dielectric": ("roughplastic", "plastic"),
        "conductor": ("roughconductor", "conductor"),
        "glass": ("roughdielectric", "dielectric"),
    }[base][mirror]


def anisotropy_of(material: Material) -> float:
    return float(material.params.anisotropy) if material.model.anisotropic else 0.0


def roughplastic_interface(material: Material) -> tuple[float, float] | None:
    """(ior, alpha) of the interface a roughplastic puts over the diffuse base: the plastic's own, or
    the coat's over a paint (`coated`); None for the other plugins."""
    plugin, params = plugin_for(material), material.params
    if plugin in ("roughplastic", "plastic"):
        ax, ay = alpha_pair(params)
        return float(params.ior), max(math.sqrt(ax * ay), ALPHA_MIRROR)
    if plugin == "coated" and params.coat is not None:
        return float(params.coat.ior), max(float(params.coat.alpha[0]), ALPHA_MIRROR)
    return None


def diffuse_scale(material: Material) -> list[float] | None:
    """What a baked colour map is multiplied by so that its diffuse energy is the IR's: roughplastic
    (conversions.roughplastic_diffuse_scale), an Oren-Nayar lobe drawn as Lambert (the lobe's
    hemispherical albedo per unit colour, as the constant colour gets); None for the other plugins."""
    interface = roughplastic_interface(material)
    if interface is not None:
        return roughplastic_diffuse_scale(material, *interface)
    if plugin_for(material) == "diffuse" and material.model.diffuse == "oren_nayar":
        return hemispherical_albedo(with_base_color(material, 1.0))
    return None


def diffuse_reflectance(material: Material, tex: BsdfTextures) -> Prop:
    """roughplastic's diffuse_reflectance: the baked map (scaled by `AlphaMaps`), else the constant
    colour that gives the IR's hemispherical albedo, flakes and sheen folded in
    (conversions.diffuse_colour over roughplastic_diffuse_energy; clipped to 1: Mitsuba's RGB
    reflectance must be in [0, 1], so a light base under a very rough interface stays below)."""
    interface = roughplastic_interface(material)
    assert interface is not None, "a roughplastic has an interface"
    if "base_color" in tex:
        return bitmap("diffuse_reflectance", tex["base_color"])
    if plugin_for(material) == "coated":  # nonlinear: the colour solved for the IR's energy per channel
        energy = diffuse_colour(material, 1.0)  # the IR's diffuse energy (flakes and sheen folded in)
        return colour("diffuse_reflectance", [float(c) for c in roughplastic_colour(energy, *interface)])
    return colour("diffuse_reflectance", diffuse_colour(material, roughplastic_diffuse_energy(*interface)))


def coat_colour_map(material: Material) -> Callable[[np.ndarray], np.ndarray]:
    """Texels of the IR's base colour -> a coated paint's `roughplastic` (nonlinear) diffuse_reflectance:
    each texel's diffuse energy under the IR's coat, E(c) = E(1) c (1 - t) / (1 - c t) (t the coat's
    round trip per unit colour, cnlmc.bsdf.flakes.coat_trap), solved for roughplastic's colour
    (conversions.roughplastic_colour), clipped to [0, 1]."""
    interface = roughplastic_interface(material)
    assert interface is not None, "a coated paint has an interface"
    white, _ = diffuse_energy(material)
    trap = np.clip(coat_trap(material), 0.0, 1.0 - 1e-9)

    def convert(texels: np.ndarray) -> np.ndarray:
        c = np.clip(np.asarray(texels, np.float64), 0.0, 1.0)
        energy = np.asarray(white) * c * (1.0 - trap) / (1.0 - c * trap)
        return np.clip(roughplastic_colour(energy, *interface), 0.0, 1.0).astype(np.float32)

    return convert


class AlphaMaps:
    """Baked maps -> what the chosen plugin reads: roughness (perceptual, IR convention) as alpha
    maps, a roughplastic's colour map scaled to the IR's diffuse energy (`diffuse_scale`).

    roughplastic takes only a uniform alpha: it gets the mean of the map (`mean_alpha`).
    """

    def __init__(self, material: Material):
        self.convention = material.params.alpha_convention
        self.plugin = plugin_for(material)
        self.anisotropy = anisotropy_of(material)
        self.mean_alpha: float | None = None
        self.colour_scale = diffuse_scale(material)
        self.coat_colour = coat_colour_map(material) if self.plugin == "coated" else None

    def __call__(self, arrays: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        if "base_color" in arrays and self.coat_colour is not None:
            arrays["base_color"] = self.coat_colour(arrays["base_color"])
        elif "base_color" in arrays and self.colour_scale is not None:
            scale = np.asarray(self.colour_scale, np.float32)
            arrays["base_color"] = np.clip(np.asarray(arrays["base_color"], np.float32) * scale, 0.0, 1.0)
        if "roughness" not in arrays:
            return arrays
        r = np.asarray(arrays.pop("roughness"), np.float32)
        alpha = alpha_isotropic(r, self.convention)
        if self.plugin == "principled":
            arrays["principled_roughness"] = np.sqrt(alpha)
        elif self.plugin not in TEXTURED_ALPHA:
            self.mean_alpha = float(alpha.mean())  # plastic: one float; mirrors: none
        elif self.anisotropy:
            arrays["alpha_u"], arrays["alpha_v"] = alpha_of(r, self.anisotropy, self.convention)
        else:
            arrays["alpha"] = alpha
        return arrays


def roughness_props(material: Material, tex: BsdfTextures) -> list[Prop]:
    ax, ay = alpha_pair(material.params)
    if "mean_alpha" in tex:
        ax = ay = tex["mean_alpha"]
    props = [prop("string", "distribution", "ggx")]
    if material.model.anisotropic and abs(ax - ay) > 1e-9:
        for name, value in (("alpha_u", ax), ("alpha_v", ay)):
            props.append(bitmap(name, tex[name]) if name in tex else prop("float", name, value))
    else:
        props.append(bitmap("alpha", tex["alpha"]) if "alpha" in tex else prop("float", "alpha", ax))
    return props


def diffuse_bsdf(material: Material, tex: BsdfTextures) -> Prop:
    """Lambert; an Oren-Nayar lobe (no Mitsuba plugin) keeps its energy: the reflectance is the
    lobe's hemispherical albedo from the reference (conversions.hemispherical_albedo, #15 item 6)."""
    colour_of: Iterable[float] = material.params.base_color
    if material.model.diffuse == "oren_nayar" and "base_color" not in tex:
        colour_of = hemispherical_albedo(material)
    return node("diffuse", [colour("reflectance", colour_of, tex.get("base_color"))])


def plastic_bsdf(material: Material, tex: BsdfTextures, rough: bool) -> Prop:
    """A plastic: the IR's interface over a diffuse base; the base colour scaled to the IR's diffuse
    energy (roughplastic re-reflects inside, the IR keeps (1 - F)(1 - F): docs/bsdf.md "White furnace")."""
    params = material.params
    props = [prop("float", "int_ior", params.ior), prop("float", "ext_ior", 1.0), diffuse_reflectance(material, tex)]
    plastic = node("roughplastic" if rough else "plastic", (roughness_props(material, tex) if rough else []) + props)
    return with_lambert_share(material, tex, plastic)


#: A coated paint's roughplastic (nonlinear) reaches the IR's white limit 1 - F_dr_ext but for its own
#: tables (R_int from 64 points: 0.588 where the IR's is 0.596 at IOR 1.5): a full-colour channel can
#: need a colour a few per cent above 1. Up to this the colour is clipped (that channel a few per cent
#: dark), not blended with a Lambert that would take the coat's reflection away.
COAT_SHORTFALL = 1.05


def lambert_share(material: Material) -> tuple[float, list[float]] | None:
    """(blend weight w, Lambert colour) when roughplastic cannot return the IR's energy: its diffuse
    energy per unit colour falls with the interface's roughness (the rough transmittance in and out,
    `roughplastic_diffuse_energy`: 0.43 of the IR's at matte white plastic's alpha), so the colour that
    would match exceeds 1, which Mitsuba refuses. Then a `blendbsdf` gives w of a Lambert of the
    colour that makes up the rest, per channel: (1 - w) roughplastic (colour clipped to 1, its
    specular lobe taken as the IR's) + w Lambert = the IR's hemispherical albedo, w the least that
    keeps the Lambert colour <= 1. A convex blend of two BSDFs each <= 1: <= 1 at every view.
    None when roughplastic reaches the IR's energy (every other material)."""
    interface = roughplastic_interface(material)
    if interface is None:
        return None
    per_unit = roughplastic_diffuse_energy(*interface)
    needed = diffuse_colour(material, per_unit)
    if max(needed) <= (COAT_SHORTFALL if plugin_for(material) == "coated" else 1.0):
        return None
    total = hemispherical_albedo(material, full=True)
    specular = hemispherical_albedo(with_base_color(without_extras(material), 0.0))
    plastic = [min(s + per_unit * min(n, 1.0), 1.0) for s, n in zip(specular, needed)]
    weight = max(min(max((t - p) / max(1.0 - p, 1e-6) for t, p in zip(total, plastic)), 1.0), 0.0)
    if weight <= 1e-4:
        return None
    colour = [min(max((t - (1.0 - weight) * p) / weight, 0.0), 1.0) for t, p in zip(total, plastic)]
    return weight, colour


def with_lambert_share(material: Material, tex: BsdfTextures, plastic: Prop) -> Prop:
    """The roughplastic as is, or blended with a Lambert that carries the energy it cannot
    (`lambert_share`; a colour map stays as baked, clipped)."""
    share = None if "base_color" in tex else lambert_share(material)
    if share is None:
        return plastic
    weight, colour_of = share
    return node(
        "blendbsdf", [prop("float", "weight", weight)], [plastic, node("diffuse", [colour("reflectance", colour_of)])]
    )


def conductor_bsdf(material: Material, tex: BsdfTextures, rough: bool) -> Prop:
    params = material.params
    props = [
        prop("rgb", "eta", rounded(measured(params.eta, "eta"))),
        prop("rgb", "k", rounded(measured(params.k, "k"))),
        colour("specular_reflectance", params.base_color, tex.get("base_color")),
    ]
    return node("roughconductor" if rough else "conductor", (roughness_props(material, tex) if rough else []) + props)


def glass_bsdf(material: Material, tex: BsdfTextures, rough: bool) -> Prop:
    params = material.params
    props = [
        prop("float", "int_ior", params.ior),
        prop("float", "ext_ior", 1.0),
    ]  # colourless: the glass's colour is its interior medium's absorption (mitsuba_subsurface.medium_entry)
    return node("roughdielectric" if rough else "dielectric", (roughness_props(material, tex) if rough else []) + props)


def principled_bsdf(material: Material, tex: BsdfTextures) -> Prop:
    """Coats and anisotropic plastics: Mitsuba's principled (Disney) BSDF."""
    model, params = material.model, material.params
    base = model.base
    ax, ay = alpha_pair(params)
    alpha = math.sqrt(ax * ay)
    base_color = conductor_f0(params) if base == "conductor" else params.base_color
    if model.coat and params.coat is not None and "base_color" not in tex:  # the base dimmed by the coat (#15)
        base_color = [c * t for c, t in zip(base_color, base_under_coat(material))]
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
    if model.anisotropic:
        props.append(prop("float", "anisotropic", min(max(float(params.anisotropy), 0.0), 1.0)))
    if "ior" in params.present:
        props.append(prop("float", "eta", params.ior))
    if base == "glass":
        props.append(prop("float", "spec_trans", 1.0))
    if base == "diffuse":  # a fabric: principled's diffuse without its specular lobe
        props = [p for p in props if p["name"] != "roughness"] + [
            prop("float", "roughness", 1.0),
            prop("float", "specular", 0.0),
        ]
    props = principled_sheen(material, props)
    if model.coat and params.coat is not None:
        coat_alpha = float(params.coat.alpha[0])
        gloss = min(max((0.1 - coat_alpha) / 0.099, 0.0), 1.0)  # Disney: alpha_c = lerp(0.1, 0.001, gloss)
        clearcoat = principled_clearcoat(material)  # the coat lobe's energy (#15)
        props += [prop("float", "clearcoat", clearcoat), prop("float", "clearcoat_gloss", gloss)]
    return node("principled", props)


def principled_sheen(material: Material, props: list[Prop]) -> list[Prop]:
    """principled's Disney sheen for the IR's Charlie sheen. Disney's lobes are added: its diffuse
    alone returns more than a white base gets (1.07 at roughness 1) and its sheen adds to it, where the
    IR's sheen takes the fibres' share from the base. So the base colour and sheen weight are the ones
    whose energy is the IR's (`mitsuba_principled.sheen_base`), sheen_tint 1 (the IR dyes the sheen
    with the base colour, cnlmc.sheen_colour). What it cannot match: the lobe's shape (Disney's is a
    (1 - cos theta_d)^5 grazing term without roughness, ~1 % of the energy at its full weight of 1:
    the fibres' energy beyond that is in the base colour)."""
    if not has_sheen(material):
        return props
    floats = {p["name"]: float(p["value"]) for p in props if p["kind"] == "float"}
    roughness = floats.get("roughness", alpha_to_roughness(math.sqrt(math.prod(alpha_pair(material.params)))))
    if material.model.base == "diffuse":  # a fabric: the roughness only shapes Disney's retro-reflection
        roughness = fabric_roughness(material)
        props = [prop("float", "roughness", roughness) if p["name"] == "roughness" else p for p in props]
    if any(p["name"] == "base_color" and p["kind"] == "texture" for p in props):  # a colour map: as baked
        weight = min(max(float(c) for c in material.params.sheen_color or (0.0,)), 1.0)  # not re-derived
    else:
        base, weight = sheen_base(material, roughness)
        props = [colour("base_color", base) if p["name"] == "base_color" else p for p in props]
    return props + [prop("float", "sheen", weight), prop("float", "sheen_tint", 1.0)]


def coated_bsdf(material: Material, tex: BsdfTextures) -> Prop:
    """A clear coat over a plastic or paint: Mitsuba's `roughplastic` is exactly that stack (a
    dielectric interface of the coat's IOR and alpha over a diffuse base, with internal reflection,
    `nonlinear`: rho / (1 - rho R_int), the IR's own sum of the light trapped under the coat);
    the base's own specular lobe vanishes under a coat of its index (the IR's relative IOR ~ 1). The
    base colour gives the IR's energy under the coat, per channel (`diffuse_reflectance`: the coat's
    colour and absorption, and a paint's flakes, are in it; a colour map per texel: `coat_colour_map`)."""
    coat = material.params.coat
    assert coat is not None, "plugin_for chose 'coated' for a coated material"
    props = [
        prop("string", "distribution", "ggx"),
        prop("float", "alpha", max(float(coat.alpha[0]), ALPHA_MIRROR)),
        prop("float", "int_ior", float(coat.ior)),
        prop("float", "ext_ior", 1.0),
        prop("boolean", "nonlinear", True),  # rho / (1 - rho R_int): the IR's light trapped under the coat
        diffuse_reflectance(material, tex),
    ]
    return with_lambert_share(material, tex, node("roughplastic", props))


BUILDERS: Mapping[str, Callable[[Material, BsdfTextures], Prop]] = {
    "coated": coated_bsdf,
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


def cnlm_bsdf(material: Material, tex: BsdfTextures) -> Prop:
    """The `cnlm` plugin: the IR material (name, model, params) as JSON plus the raw maps it
    reads. '$' is written as a JSON escape: Mitsuba's loader substitutes $parameters in strings."""
    ir = material.to_ir()
    shading = {key: ir[key] for key in ("name", "model", "params")}
    text = json.dumps(shading, sort_keys=True, default=float).replace("$", "\\u0024")
    props = [prop("string", "material", text)]
    props += [bitmap(role, tex[role]) for role in ("base_color", "roughness", "mask") if role in tex]
    return node("cnlm", props)


#: a volume's base-colour map (marble's veins): Mitsuba's homogeneous medium has one albedo per channel
MEDIUM_MAP_DROPPED = (
    "drop",
    "Mitsuba's homogeneous medium cannot be textured: the body takes the IR's uniform colour (a volume's "
    "subsurface colour, a glass's base colour) and the base-colour map is not drawn (the preview and the GLSL "
    "target colour the body by it)",
)


def untextured_medium(material: Material) -> bool:
    """A volume or a glass with a base-colour map, exported natively: the map would colour its
    body, which a homogeneous medium cannot be."""
    return (material.model.subsurface == "volume" or material.model.base == "glass") and "base_color" in material.maps


def uses_cnlm(material: Material, options: Options) -> bool:
    """bsdf=cnlm applies to every reflective model; glass keeps roughdielectric (its exact match)."""
    return bool(options.bsdf == "cnlm" and material.model.base != "glass")


def bsdf_for(material: Material, ident: str, tex: BsdfTextures, cnlm: bool = False) -> Prop:
    """The BSDF tree: plugin, then twosided (opaque ones), then normalmap; the root gets the id."""
    if material.model.subsurface is not None:  # the medium's boundary, or a thin sheet (mitsuba_subsurface)
        tree = subsurface_bsdf(material)
    else:
        plugin = "cnlm" if cnlm else plugin_for(material)
        tree = cnlm_bsdf(material, tex) if cnlm else BUILDERS[plugin](material, tex)
        if plugin not in TRANSMISSIVE and material.model.base != "glass":
            tree = node("twosided", [], [tree])
    if "normal" in tex:
        tree = node("normalmap", [bitmap("normalmap", tex["normal"])], [tree])
    tree["id"] = ident
    return tree


# ------------------------------------------------------------------------------- templates


def comment(value: object) -> str:
    """Safe inside <!-- -->: no '--', no trailing '-', one line; control characters (DEL, C1, bidi
    overrides) shown escaped as on the terminal, so a file printed there cannot drive it."""
    text = visible(xml_text(value).replace("\r", " ").replace("\n", " "), one_line=True)
    text = re.sub("-(?=-)", "- ", text)
    return text + " " if text.endswith("-") else text


def _finalize(value: Any) -> Any:
    return xml_text(value) if isinstance(value, str) and not isinstance(value, markupsafe.Markup) else value


def template_environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.PackageLoader("cnlmc.backends.exchange", "templates/mitsuba"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        finalize=_finalize,
    )
    env.filters["comment"] = comment
    return env


def layout(count: int) -> tuple[list[list[float]], dict[str, Any]]:
    """Sphere centres on a grid and a camera that frames them (an empty scene: no sphere, the camera of one)."""
    cols = max(1, math.ceil(math.sqrt(count)))
    rows = max(1, math.ceil(count / cols))
    spacing = 2.5
    centres = [
        [(i % cols - (cols - 1) / 2) * spacing, ((rows - 1) / 2 - i // cols) * spacing, 0.0] for i in range(count)
    ]
    extent = max(cols, rows) * spacing
    fov = 40.0
    distance = extent / (2 * math.tan(math.radians(fov / 2))) + 1.5
    return centres, {"fov": fov, "origin": [0, 0, round(distance, 4)], "target": [0, 0, 0]}


# The backdrop: BACKDROP_DEPTH behind the spheres' plane, a little wider than the view there, with
# about CHECKS_PER_SPHERE checks across a sphere's diameter (our choice: glass shows a bent checker).
BACKDROP_DEPTH, BACKDROP_MARGIN, CHECKS_PER_SPHERE = 3.0, 1.2, 3.0


def backdrop(camera: dict[str, Any]) -> dict[str, float]:
    depth = camera["origin"][2] + BACKDROP_DEPTH
    half = depth * math.tan(math.radians(camera["fov"] / 2)) * BACKDROP_MARGIN
    return {
        "z": -BACKDROP_DEPTH,
        "half_size": round(half, 4),
        "checks": round(half * CHECKS_PER_SPHERE / 2.0, 4),  # the rectangle's uv spans 2 * half
    }


def installed_version() -> str:
    try:
        return dist_version("cnlmc")
    except PackageNotFoundError:  # pragma: no cover - not installed
        return "dev"


def render_xml(entries: list[dict[str, Any]], options: Options, env: jinja2.Environment, version: str) -> str:
    if options.form == "fragment":
        return env.get_template("fragment.xml.j2").render(materials=entries, version=version)
    volume = any(entry["medium"] for entry in entries)  # a medium: volpath, deep enough to scatter in it
    centres, camera = layout(len(entries))
    for entry, centre in zip(entries, centres):
        entry["center"] = centre
    return env.get_template("scene.xml.j2").render(
        materials=entries,
        camera=camera,
        spp=options.spp,
        resolution=options.resolution,
        max_depth=VOLUME_MAX_DEPTH if volume else options.max_depth,
        rr_depth=roulette_depth([entry["medium"] for entry in entries if entry["medium"]]),
        volume=volume,
        envmap=options.envmap,
        backdrop=backdrop(camera),
        cnlm=options.bsdf == "cnlm",
        version=version,
    )


# ------------------------------------------------------------------------------------ emit


def main_file(options: Options) -> str:
    """The XML file's name when -o names a folder (its textures go to textures/<that name>/)."""
    return "materials.xml" if options.form == "fragment" else "scene.xml"


class MitsubaScene:
    """One scene (or fragment) being built: the shared emit loop adds the materials' BSDFs."""

    def __init__(self, document: Document, options: Options):
        self.options = options
        self.idents = MaterialIdents(document.materials)
        self.native = capabilities_for(CAPABILITIES, options.maps)
        self.cnlm = capabilities_for(CNLM_CAPABILITIES, options.maps)
        self.entries: list[dict[str, Any]] = []

    def capabilities_of(self, material: Material) -> Capabilities:
        if uses_cnlm(material, self.options):
            return self.cnlm
        if untextured_medium(material) and self.options.maps != "none":
            return {**self.native, "maps.base_color": MEDIUM_MAP_DROPPED}
        return self.native

    def add(self, material: Material) -> list[Artifact]:
        """The material's BSDF entry; returns its baked bitmaps."""
        ident, cnlm = self.idents[material], uses_cnlm(material, self.options)
        alpha_maps = None if cnlm else AlphaMaps(material)
        roles: tuple[str, ...] = CNLM_MAPS if cnlm else USED_MAPS
        if not cnlm and untextured_medium(material):  # the medium takes one colour: its map is not baked
            roles = tuple(role for role in roles if role != "base_color")
        main = main_file(self.options)
        textures, images = bake_textures(material, ident, self.options, roles=roles, derive=alpha_maps, main=main)
        tex: BsdfTextures = dict(textures)
        if alpha_maps and alpha_maps.mean_alpha is not None and plugin_for(material) == "roughplastic":
            tex["mean_alpha"] = alpha_maps.mean_alpha
        entry: dict[str, Any] = {
            "ident": ident,
            "phrase": described(material),
            "bsdf": bsdf_for(material, ident, tex, cnlm),
            "medium": medium_entry(material, ident, self.options.unit_metres),
        }
        self.entries.append(entry)
        return images


class MitsubaTarget(Target):
    name = "mitsuba"
    description = "Mitsuba 3 scene XML (full preview scene or BSDF fragment) with baked bitmap textures"
    capabilities = CAPABILITIES
    options = OPTIONS

    @functools.cached_property
    def templates(self) -> jinja2.Environment:
        """The template environment (it keeps the compiled templates), made on first use."""
        return template_environment()

    @functools.cached_property
    def version(self) -> str:
        """The cnlmc version the files are stamped with."""
        return installed_version()

    def emit(self, document: Document, options: Options) -> EmitResult:
        scene = MitsubaScene(document, options)
        baked = emit_each(self, document, scene.add, scene.capabilities_of)
        xml = render_xml(scene.entries, options, self.templates, self.version)
        return EmitResult([Artifact(main_file(options), xml), *baked.artifacts], baked.notes)


TARGET = MitsubaTarget()


def emit(ir: Document | Mapping[str, Any], options: Mapping[str, object] | None = None) -> EmitResult:
    """The target on an IR (typed or JSON form) with raw `--option` pairs."""
    return TARGET.emit_ir(ir, options)
