"""A material's shader for the preview: the GLSL backend's library form of the material, its
samplers, and what the preview's templates need to know about it (PreviewPlan), all read
from the GLSL backend's own plan (glsl.plan.make_plan, glsl.emit.library_source)."""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from cnlmc.bsdf.flakes import has_flakes
from cnlmc.bsdf.sampling import lobe_shares
from cnlmc.bsdf.sheen import has_sheen
from cnlmc.material import Material

from ..capabilities import check_material
from ..glsl.emit import library_source
from ..glsl.options import GlslOptions, parse_glsl_options
from ..glsl.plan import MICROFACET_BASES, SHADER_ROLES, Plan, Sampler, make_plan
from ..glsl.render import ShaderWriter
from .albedo_tables import split_fitted
from .capability_table import CAPABILITIES
from .capability_table import NAME as PREVIEW
from .resources import source_key
from .subsurface import has_subsurface

#: the GLSL backend's options that change a material's shader
GLSL_OPTION_KEYS = ("fresnel", "multiscatter", "specialize")

#: a material as the preview takes it: typed, or its IR object (typed once, on the way in)
MaterialLike = Material | Mapping[str, Any]


def as_material(material: MaterialLike) -> Material:
    return material if isinstance(material, Material) else Material.from_ir(dict(material))


@dataclass(frozen=True)
class PreviewPlan:
    """What the preview's templates (adapter.glsl.j2, split.glsl.j2) need to know."""

    base: str
    microfacet: bool
    anisotropic: bool
    coat: bool
    coat_color: bool
    normal_map: bool
    roughness_map: bool
    strategy: tuple[str, ...]  # the sampled tiers' lobe shares, as GLSL literals
    summary: str
    split_fitted: bool  # the split-sum tables hold a fitted kernel pair: two lookups (split.glsl.j2)
    sheen: bool = False  # a Charlie sheen over the base (sheen.glsl.j2)
    flakes: bool = False  # the flakes' sparkle for the key light (flakes.glsl.j2; their mean is in cnlm_bsdf)
    subsurface: bool = False  # a translucent body under a black-based boundary (subsurface.glsl.j2)


@dataclass(frozen=True)
class MaterialShader:
    name: str
    library: str
    plan: PreviewPlan
    samplers: tuple[Sampler, ...]
    notes: list[str]

    @cached_property
    def key(self) -> str:
        """A digest of what the object program is made from: programs are cached by it."""
        return source_key(self.name, self.library, json.dumps(dataclasses.asdict(self.plan), sort_keys=True))


def preview_plan(material: Material, library: Plan, specialized: Plan) -> PreviewPlan:
    """The preview's plan from the GLSL backend's: `library` is the plan the library was written
    from (the all-features one with specialize=off: every coat uniform and sampler present),
    `specialized` the material's own choices."""
    base = material.model.base
    coat = library.coat
    flags = {"anisotropic": specialized.anisotropic, "coat": coat, "normal_map": "normal" in library.maps}
    roughness_map = "roughness" in library.maps
    return PreviewPlan(
        base=base,
        microfacet=base in MICROFACET_BASES,
        anisotropic=specialized.anisotropic,
        coat=coat,
        coat_color=library.coat_color,
        normal_map=flags["normal_map"],
        roughness_map=roughness_map,
        strategy=tuple(repr(float(x)) for x in lobe_shares(base, coat)),
        summary=base + "".join(f", {k}" for k, on in flags.items() if on),
        split_fitted=split_fitted(material, roughness_map),
        sheen=has_sheen(material),
        flakes=has_flakes(material),
        subsurface=has_subsurface(material),
    )


def shader_options(glsl_options: Mapping[str, Any] | None) -> GlslOptions:
    """The GLSL backend's options that change a material's shader (the library form)."""
    pairs = {k: str(v) for k, v in (glsl_options or {}).items() if k in GLSL_OPTION_KEYS}
    return parse_glsl_options({**pairs, "form": "library"})


def shader_key(material: Material, options: GlslOptions) -> tuple[str, str, GlslOptions]:
    """What a material's shader is cached by: its content, its name (the library names it) and
    the GLSL options (a frozen record)."""
    return material.key, material.name, options


def without_sheen(material: Material) -> Material:
    """The material the preview takes the GLSL library of: its sheen left out, because the preview
    draws the sheen itself (sheen.glsl.j2: the key light exactly, the environment by tier)."""
    if material.params.sheen_color is None:
        return material
    return dataclasses.replace(material, params=dataclasses.replace(material.params, sheen_color=None))


def material_shader(material: Material, options: GlslOptions, writer: ShaderWriter) -> MaterialShader:
    """The library form of one material and its plans, made anew (Renderer.shader keeps them)."""
    library, plan = library_source(without_sheen(material), options, writer)
    specialized = plan if options.specialize else make_plan(material, options)
    notes: list = []
    check_material(notes, PREVIEW, CAPABILITIES, material)  # the preview's own table, not the GLSL export's
    plans = preview_plan(material, plan, specialized)
    maps = tuple(s for s in plan.samplers if s.role in SHADER_ROLES)  # the library's tables are bound by name
    return MaterialShader(material.name, library, plans, maps, [n.text() for n in notes])
