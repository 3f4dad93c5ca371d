"""What the exchange backends (MaterialX, USD, Mitsuba) share; no third-party imports here.

- `identifier`/`unique_identifiers`: any text -> a valid, unique identifier for a target.
- `exchange_options`: the options every exchange backend takes (maps, map_size, map_format, seed).
- conductor colours: OpenPBR's F82 tint and Standard Surface's edge colour from the IR's f0/f82/eta.
- `surface_inputs`: an IR material -> the inputs of `open_pbr_surface` or `standard_surface`.
- `bake_textures`: an IR material's `maps` -> baked image Artifacts and where each role goes.
"""

from __future__ import annotations

import math
import re
import tempfile
import unicodedata
from dataclasses import dataclass
from pathlib import Path

from .capabilities import COMPILER_OPTIONS
from .registry import Artifact

MU_82 = 1.0 / 7.0  # cos 82 degrees, rounded as OpenPBR does: the F82 angle
DIGITS = 6  # values are rounded so documents are stable (golden files)


# ---------------------------------------------------------------------------------- names


def identifier(text: str, fallback: str = "material") -> str:
    """Any text -> [A-Za-z_][A-Za-z0-9_]*: accents folded, everything else becomes '_'."""
    folded = unicodedata.normalize("NFKD", str(text)).encode("ascii", "ignore").decode("ascii")
    name = re.sub(r"[^A-Za-z0-9_]+", "_", folded).strip("_") or fallback
    return name if not name[0].isdigit() else f"_{name}"


def unique_identifiers(names, fallback: str = "material") -> list[str]:
    """Identifiers for a list of names, suffixed _2, _3 ... where two would collide."""
    seen: set[str] = set()
    out = []
    for name in names:
        base = identifier(name, fallback)
        candidate, n = base, 2
        while candidate in seen:
            candidate, n = f"{base}_{n}", n + 1
        seen.add(candidate)
        out.append(candidate)
    return out


# -------------------------------------------------------------------------------- options

MAP_MODES = ("bake", "none")
MAP_FORMATS = ("png8", "png16", "exr-half", "exr-float")
COMMON_OPTIONS = {"maps": "bake", "map_size": "256", "map_format": "png8", "seed": "0"}


def exchange_options(options: dict | None, target: str, extra: dict[str, tuple]) -> dict:
    """Validate options: `extra` is name -> (default, allowed values or None for any int)."""
    known = {**{k: (v, None) for k, v in COMMON_OPTIONS.items()}, **extra}
    options = {k: v for k, v in (options or {}).items() if k in known or k not in COMPILER_OPTIONS}
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise ValueError(f"{target}: unknown option(s) {', '.join(unknown)}; known: {', '.join(sorted(known))}")
    out = {}
    for name, (default, allowed) in known.items():
        value = str(options.get(name, default))
        if allowed is not None and value not in allowed:
            raise ValueError(f"{target}: option {name}={value!r}: use one of {', '.join(allowed)}")
        out[name] = value
    for name in ("map_size", "seed"):
        out[name] = _int_option(target, name, out[name])
    if out["maps"] not in MAP_MODES:
        raise ValueError(f"{target}: option maps={out['maps']!r}: use one of {', '.join(MAP_MODES)}")
    if out["map_format"] not in MAP_FORMATS:
        raise ValueError(f"{target}: option map_format={out['map_format']!r}: use one of {', '.join(MAP_FORMATS)}")
    return out


def _int_option(target: str, name: str, value: str) -> int:
    try:
        return int(value)
    except ValueError:
        raise ValueError(f"{target}: option {name}={value!r} must be a whole number") from None


def capabilities_for(capabilities: dict, opts: dict) -> dict:
    """With maps=none every map feature is dropped (and said so)."""
    if opts["maps"] != "none":
        return capabilities
    dropped = ("drop", "maps=none: procedural maps are not baked; the uniform parameters are used")
    return {f: (dropped if f.startswith("maps.") else p) for f, p in capabilities.items()}


# --------------------------------------------------------------------------- conductors


def clip01(values) -> list[float]:
    return [min(max(float(v), 0.0), 1.0) for v in values]


def rounded(values) -> list[float]:
    return [round(float(v), DIGITS) for v in values]


def schlick(f0: float, mu: float) -> float:
    return f0 + (1.0 - f0) * (1.0 - mu) ** 5


def conductor_f0(params: dict) -> list[float]:
    """The measured normal-incidence reflectance times the IR tint, clipped to [0, 1]."""
    return clip01(f * t for f, t in zip(params["f0"], params["base_color"]))


def f82_tint(params: dict) -> list[float]:
    """OpenPBR's specular_color for a metal: F(82 deg) / Schlick(F0, 82 deg), clipped to [0, 1].

    OpenPBR (and MaterialX's generalized_schlick_bsdf color82) subtracts a term so that the
    reflectance at mu = 1/7 equals specular_color * Schlick(F0, 1/7); the IR stores the
    measured F82, so the tint is f82 / schlick(f0, 1/7) (both scaled by the IR tint).
    """
    f0 = conductor_f0(params)
    f82 = [f * t for f, t in zip(params["f82"], params["base_color"])]
    return clip01(b / schlick(a, MU_82) for a, b in zip(f0, f82))


def gulbrandsen_edge(params: dict) -> list[float]:
    """Standard Surface's specular_color for a metal: the edge tint g for which Gulbrandsen's
    artistic IOR mapping (MaterialX `artistic_ior`) gives back the measured eta at F0 = r."""
    edge = []
    for r, n in zip(conductor_f0(params), params["eta"]):
        r = min(r, 0.999)
        n_min = (1.0 - r) / (1.0 + r)
        n_max = (1.0 + math.sqrt(r)) / (1.0 - math.sqrt(r))
        edge.append(1.0 if n_max - n_min < 1e-6 else (n_max - n) / (n_max - n_min))
    return clip01(edge)


# ------------------------------------------------------------------------- roughness


def alpha_pair(params: dict) -> tuple[float, float]:
    """(alpha_x, alpha_y) as microfacet widths (alpha is authoritative in the IR)."""
    ax, ay = params["alpha"]  # widths in either convention: only r differs
    return float(ax), float(ay)


def alpha_to_roughness(alpha: float) -> float:
    """Perceptual roughness of the squared convention (alpha = r^2), used by every target here."""
    return math.sqrt(max(alpha, 0.0))


def openpbr_roughness(ax: float, ay: float) -> tuple[float, float]:
    """OpenPBR: alpha_t = r^2 sqrt(2 / (1 + (1-a)^2)), alpha_b = (1-a) alpha_t."""
    hi, lo = max(ax, ay), min(ax, ay)
    if hi <= 0.0:
        return 0.0, 0.0
    a = 1.0 - lo / hi
    return math.sqrt(hi / math.sqrt(2.0 / (1.0 + (1.0 - a) ** 2))), a


def standard_roughness(ax: float, ay: float) -> tuple[float, float]:
    """Standard Surface: alpha_x = r^2 / sqrt(1-a), alpha_y = r^2 sqrt(1-a), a <= 0.98."""
    hi, lo = max(ax, ay), min(ax, ay)
    if hi <= 0.0:
        return 0.0, 0.0
    a = min(1.0 - lo / hi, 0.98)
    return math.sqrt(math.sqrt(hi * lo) if lo > 0 else hi * math.sqrt(1 - a)), a


# ------------------------------------------------------------------- surface shader inputs

# IR concept -> input name, per MaterialX surface shader (per-target differences as a table).
SURFACE_NAMES = {
    "open_pbr_surface": {
        "base_weight": "base_weight",
        "base_color": "base_color",
        "metalness": "base_metalness",
        "diffuse_roughness": "base_diffuse_roughness",
        "specular_weight": "specular_weight",
        "specular_color": "specular_color",
        "roughness": "specular_roughness",
        "ior": "specular_ior",
        "anisotropy": "specular_roughness_anisotropy",
        "transmission": "transmission_weight",
        "transmission_color": "transmission_color",
        "coat": "coat_weight",
        "coat_color": "coat_color",
        "coat_roughness": "coat_roughness",
        "coat_ior": "coat_ior",
        "normal": "geometry_normal",
        "tangent": "geometry_tangent",
    },
    "standard_surface": {
        "base_weight": "base",
        "base_color": "base_color",
        "metalness": "metalness",
        "diffuse_roughness": "diffuse_roughness",
        "specular_weight": "specular",
        "specular_color": "specular_color",
        "roughness": "specular_roughness",
        "ior": "specular_IOR",
        "anisotropy": "specular_anisotropy",
        "rotation": "specular_rotation",
        "transmission": "transmission",
        "transmission_color": "transmission_color",
        "coat": "coat",
        "coat_color": "coat_color",
        "coat_roughness": "coat_roughness",
        "coat_ior": "coat_IOR",
        "normal": "normal",
        "tangent": "tangent",
    },
}
ROUGHNESS_FIT = {"open_pbr_surface": openpbr_roughness, "standard_surface": standard_roughness}
METAL_EDGE = {"open_pbr_surface": f82_tint, "standard_surface": gulbrandsen_edge}
SURFACES = tuple(SURFACE_NAMES)


def abstract_inputs(material: dict, surface: str) -> dict[str, tuple[str, object]]:
    """IR material -> concept -> (MaterialX type, value), before naming for a surface."""
    model, params = material["model"], material["params"]
    base = model["base"]
    out: dict[str, tuple[str, object]] = {"base_weight": ("float", 1.0)}
    if base == "conductor":
        out["base_color"] = ("color3", conductor_f0(params))
        out["metalness"] = ("float", 1.0)
        out["specular_color"] = ("color3", METAL_EDGE[surface](params))
    else:
        out["base_color"] = ("color3", clip01(params["base_color"]))
        out["metalness"] = ("float", 0.0)
    if base == "diffuse":
        out["specular_weight"] = ("float", 0.0)
    else:
        out.update(_specular_inputs(params, surface))
    if base == "glass":
        out["transmission"] = ("float", 1.0)
        out["transmission_color"] = ("color3", clip01(params["base_color"]))
    if model["diffuse"] == "oren_nayar":
        out["diffuse_roughness"] = ("float", min(max(float(params.get("diffuse_roughness", 0.0)), 0.0), 1.0))
    if model["coat"] and params.get("coat"):
        out.update(_coat_inputs(params["coat"]))
    return {k: (t, round(v, DIGITS) if isinstance(v, float) else rounded(v)) for k, (t, v) in out.items()}


def _specular_inputs(params: dict, surface: str) -> dict:
    ax, ay = alpha_pair(params)
    roughness, anisotropy = ROUGHNESS_FIT[surface](ax, ay)
    out = {"specular_weight": ("float", 1.0), "roughness": ("float", roughness)}
    if "ior" in params:
        out["ior"] = ("float", float(params["ior"]))
    if anisotropy > 0.0:
        out["anisotropy"] = ("float", anisotropy)
        rotation = float(params.get("anisotropy_rotation") or 0.0)
        if rotation and "rotation" in SURFACE_NAMES[surface]:
            out["rotation"] = ("float", (rotation / (2 * math.pi)) % 1.0)
    return out


def _coat_inputs(coat: dict) -> dict:
    """The IR's coat colour is a normal-incidence round-trip tint scaled by thickness."""
    thickness = float(coat.get("thickness", 1.0))
    color = [max(float(c), 0.0) ** thickness for c in coat["color"]]
    return {
        "coat": ("float", 1.0),
        "coat_color": ("color3", clip01(color)),
        "coat_roughness": ("float", alpha_to_roughness(float(coat["alpha"][0]))),
        "coat_ior": ("float", float(coat["ior"])),
    }


def surface_inputs(material: dict, surface: str = "open_pbr_surface") -> dict[str, tuple[str, object]]:
    """IR material -> input name -> (MaterialX type, value) for `surface`."""
    names = SURFACE_NAMES[surface]
    return {names[k]: v for k, v in abstract_inputs(material, surface).items() if k in names}


def tangent_rotation(material: dict) -> float:
    """The streak direction in radians when the target has to rotate the tangent itself."""
    if not material["model"]["anisotropic"]:
        return 0.0
    return float(material["params"].get("anisotropy_rotation") or 0.0)


# -------------------------------------------------------------------------------- textures

COLOUR_ROLES = ("base_color",)


@dataclass(frozen=True)
class Texture:
    """One baked image: its role, its path relative to the output folder, how it is encoded."""

    role: str
    path: str
    encoding: str  # "srgb" (8/16-bit PNG colour), "linear" (EXR colour) or "raw" (data)

    @property
    def is_colour(self) -> bool:
        return self.encoding in ("srgb", "linear")


def texture_encoding(role: str, fmt: str) -> str:
    if role in COLOUR_ROLES:
        return "srgb" if fmt.startswith("png") else "linear"
    return "raw"


def bake_textures(
    material: dict, ident: str, opts: dict, folder: str = "textures", roles=None, derive=None
) -> tuple[dict[str, Texture], list[Artifact]]:
    """Bake the material's maps (the roles given, default all) into image Artifacts.

    `derive(arrays) -> arrays` may add roles computed from the baked ones (e.g. Mitsuba's
    alpha = roughness^2). Returns role -> Texture and the artifacts (bytes) to write.
    """
    refs = {r: ref for r, ref in (material.get("maps") or {}).items() if roles is None or r in roles}
    if opts["maps"] == "none" or not refs:
        return {}, []
    from cnlmc.backends.maps import MapError, bake, write_maps

    try:
        arrays = bake(refs, material["params"], opts["map_size"], opts["seed"])
        if derive:
            arrays = derive(arrays)
        with tempfile.TemporaryDirectory(prefix="cnlmc-tex-") as tmp:
            paths = write_maps(arrays, tmp, fmt=opts["map_format"], stem=ident)
            files = {p.stem[len(ident) + 1 :]: (p.name, p.read_bytes()) for p in paths}
    except MapError as exc:
        raise ValueError(f"{material['name']}: cannot bake maps: {exc}") from None
    textures, artifacts = {}, []
    for role, (name, data) in files.items():
        rel = f"{folder}/{name}"
        textures[role] = Texture(role, rel, texture_encoding(role, opts["map_format"]))
        artifacts.append(Artifact(rel, data, "binary"))
    return textures, artifacts


INVALID_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def xml_text(value) -> str:
    """Characters XML 1.0 cannot hold at all (even escaped) are removed; the rest is escaped
    by whichever writer the backend uses (MaterialX's, pxr's, jinja2's autoescape)."""
    return INVALID_XML.sub("", str(value))


def phrase_text(material: dict) -> str:
    return xml_text(material.get("phrase", ""))


def output_path_suffix(path: str | None, allowed: tuple[str, ...], default: str) -> str:
    suffix = Path(path).suffix.lower() if path else ""
    return suffix if suffix in allowed else default
