"""A material's textures for the object pass: its procedural maps baked (the map-baking service)
and uploaded, and for the split-sum tier its albedo tables and the environment prefiltered at
exactly its alphas."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from cnlmc.bsdf.evaluate import coat_alpha, material_alpha
from cnlmc.material import Material, Params

from ..glsl.options import GlslOptions
from ..glsl.plan import Sampler
from ..maps.service import MapBakeError, bake_arrays
from .environment_pass import EnvResources
from .resources import Resources
from .shader import PreviewPlan

MAP_SIZE = 512


def encode_map(role: str, array: np.ndarray) -> np.ndarray:
    """Baked map -> what the shader samples: normals as n * 0.5 + 0.5; image top row at v = 1."""
    a = np.asarray(array, np.float32)
    if role == "normal":
        a = a * 0.5 + 0.5
    return np.flipud(a)


def neutral_map(role: str, params: Params, size: int = 4) -> np.ndarray:
    """A uniform stand-in for a map that cannot be baked (the material's own value)."""
    values: dict[str, float | tuple[float, ...]] = {
        "base_color": params.base_color,
        "normal": (0.0, 0.0, 1.0),
        "roughness": params.roughness,
    }
    value = values.get(role, 0.0)
    return np.broadcast_to(np.asarray(value, np.float32), (size, size) + np.shape(value)).copy()


def bake_maps(material: Material, size: int, seed: int, notes: list[str] | None = None) -> dict[str, np.ndarray]:
    """Bake every map role (the map-baking service); a role whose graph fails gets a neutral
    map and a note."""
    try:
        return bake_arrays(material, size, seed)
    except MapBakeError:
        pass
    arrays = {}
    for role in material.maps:
        try:
            arrays.update(bake_arrays(material, size, seed, roles=[role]))
        except MapBakeError as exc:
            arrays[role] = neutral_map(role, material.params)
            if notes is not None:
                notes.append(f"preview: {material.name}: map {role} not baked ({exc.reason}); uniform value used")
    return arrays


def map_textures(
    resources: Resources, material: Material, samplers: Sequence[Sampler], size: int = MAP_SIZE, seed: int = 0
) -> dict[str, Any]:
    """sampler name -> texture, baked with the map-baking service (made once per material content)."""
    if not samplers:
        return {}

    def upload() -> dict[str, Any]:
        arrays = bake_maps(material, size, seed)
        return {role: resources.float_texture(encode_map(role, arr)) for role, arr in arrays.items()}

    baked = resources.once(("maps", material.key, size, seed), upload)
    return {s.name: baked[s.role] for s in samplers if s.role in baked}


def split_textures(
    resources: Resources, material: Material, plan: PreviewPlan, res: EnvResources, options: GlslOptions
) -> dict[str, Any]:
    """sampler name -> texture for the split-sum tier: the material's albedo tables, and the
    environment prefiltered at exactly the base's and the coat's alpha when they are uniform."""
    fresnel, multiscatter, mapped = options.fresnel, options.multiscatter, plan.roughness_map

    def upload() -> dict[str, Any]:
        black, tint = resources.tables.tables(material, fresnel, multiscatter, mapped)
        flat = lambda table: resources.float_texture(table, mipmaps=False, repeat=(False, False))
        return {"pv_black_albedo": flat(black), "pv_tint_albedo": flat(tint)}

    textures = dict(resources.once(("split tables", material.key, fresnel, multiscatter, mapped), upload))
    textures["pv_env_irradiance"] = res.irradiance
    coat = material.params.coat if plan.coat else None
    if plan.microfacet and not mapped:
        ax, ay = (float(a) for a in material_alpha(material))
        widen = float(coat.ior) if coat and plan.base == "conductor" else 1.0
        textures["pv_env_material"] = res.prefiltered_at(min(max(np.sqrt(ax * ay), 1e-3) * widen, 1.0))
    if coat:
        cx, cy = (float(a) for a in coat_alpha(coat, material.params.alpha_convention))
        textures["pv_env_coat"] = res.prefiltered_at(max(np.sqrt(cx * cy), 1e-3))
    return textures
