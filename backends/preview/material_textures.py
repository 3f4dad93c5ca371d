"""A material's textures for the object pass: its procedural maps baked (the map-baking service)
and uploaded, and for the split-sum tier its albedo tables and the environment prefiltered at
exactly its alphas."""

from __future__ import annotations

import json

import numpy as np

from cnlmc.bsdf.evaluate import coat_alpha, material_alpha

from ..maps.service import MapBakeError, bake_arrays
from .environment_pass import EnvResources
from .resources import Resources

MAP_SIZE = 512


def encode_map(role: str, array: np.ndarray) -> np.ndarray:
    """Baked map -> what the shader samples: normals as n * 0.5 + 0.5; image top row at v = 1."""
    a = np.asarray(array, np.float32)
    if role == "normal":
        a = a * 0.5 + 0.5
    return np.flipud(a)


def neutral_map(role: str, params: dict, size: int = 4) -> np.ndarray:
    """A uniform stand-in for a map that cannot be baked (the material's own value)."""
    value = {
        "base_color": params.get("base_color", [0.8, 0.8, 0.8]),
        "normal": [0.0, 0.0, 1.0],
        "roughness": params.get("roughness", 0.5),
        "mask": 0.0,
        "metallic": 0.0,
    }.get(role, 0.0)
    return np.broadcast_to(np.asarray(value, np.float32), (size, size) + np.shape(value)).copy()


def bake_maps(material: dict, size: int, seed: int, notes: list | None = None) -> dict:
    """Bake every map role (the map-baking service); a role whose graph fails gets a neutral
    map and a note."""
    try:
        return bake_arrays(material, size, seed)
    except MapBakeError:
        pass
    arrays = {}
    for role in material.get("maps", {}):
        try:
            arrays.update(bake_arrays(material, size, seed, roles=[role]))
        except MapBakeError as exc:
            arrays[role] = neutral_map(role, material["params"])
            if notes is not None:
                notes.append(f"preview: {material['name']}: map {role} not baked ({exc.reason}); uniform value used")
    return arrays


def map_textures(resources: Resources, material: dict, samplers: list, size: int = MAP_SIZE, seed: int = 0) -> dict:
    """sampler name -> texture, baked with cnlmc.backends.maps (made once per maps and parameters)."""
    if not samplers:
        return {}
    key = (
        "maps",
        json.dumps(material.get("maps", {}), sort_keys=True),
        json.dumps(material["params"], sort_keys=True, default=str),
        size,
        seed,
    )

    def upload() -> dict:
        arrays = bake_maps(material, size, seed)
        return {role: resources.float_texture(encode_map(role, arr)) for role, arr in arrays.items()}

    baked = resources.once(key, upload)
    return {s["name"]: baked[s["role"]] for s in samplers if s["role"] in baked}


def split_textures(
    resources: Resources, material: dict, plan: dict, res: EnvResources, glsl_options: dict | None
) -> dict:
    """sampler name -> texture for the split-sum tier: the material's albedo tables, and the
    environment prefiltered at exactly the base's and the coat's alpha when they are uniform."""
    opts = glsl_options or {}
    fresnel, multiscatter = str(opts.get("fresnel", "exact")), str(opts.get("multiscatter", "off")) == "on"
    key = (
        "split tables",
        json.dumps([material["model"], material["params"]], sort_keys=True, default=str),
        fresnel,
        multiscatter,
        plan["roughness_map"],
    )

    def upload() -> dict:
        black, tint = resources.tables.tables(material, fresnel, multiscatter, plan["roughness_map"])
        flat = lambda table: resources.float_texture(table, mipmaps=False, repeat=(False, False))
        return {"pv_black_albedo": flat(black), "pv_tint_albedo": flat(tint)}

    textures = dict(resources.once(key, upload))
    textures["pv_env_irradiance"] = res.irradiance
    params = material["params"]
    coat = params.get("coat") if plan["coat"] else None
    if plan["microfacet"] and not plan["roughness_map"]:
        ax, ay = (float(a) for a in material_alpha(material))
        widen = float(coat.get("ior", 1.5)) if coat and plan["base"] == "conductor" else 1.0
        textures["pv_env_material"] = res.prefiltered_at(min(max(np.sqrt(ax * ay), 1e-3) * widen, 1.0))
    if coat:
        cx, cy = (float(a) for a in coat_alpha(coat, params.get("alpha_convention", "squared")))
        textures["pv_env_coat"] = res.prefiltered_at(max(np.sqrt(cx * cy), 1e-3))
    return textures
