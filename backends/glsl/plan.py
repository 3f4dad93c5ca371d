"""What one material needs in GLSL: the model choices, snippets, uniforms and samplers.

Everything model-specific is a table here; the templates only arrange what the plan lists.
Values are taken with the reference library's own helpers (`cnlmc.bsdf`), so the shader
and the ground truth share one reading of the IR (α clamping, coat α, F_avg).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from cnlmc.bsdf import coat_alpha, conductor_fresnel, f0_conductor, fresnel_average, material_alpha
from cnlmc.bsdf.flakes import coat_trap, flake_alpha, has_flakes
from cnlmc.bsdf.sheen import has_sheen, sheen_alpha, sheen_row
from cnlmc.material import Coat, Material, Params

from .options import GlslOptions

MICROFACET_BASES = ("dielectric", "conductor", "glass")
#: The Fresnel mode a base actually uses: dielectrics have no F82 data (Schlick of the IOR).
EFFECTIVE_FRESNEL: dict[str, dict[str, str | None]] = {
    "conductor": {"exact": "exact", "schlick": "schlick", "f82": "f82"},
    "dielectric": {"exact": "exact", "schlick": "schlick", "f82": "schlick"},
    "glass": {"exact": "exact", "schlick": "schlick", "f82": "schlick"},
    "diffuse": {"exact": None, "schlick": None, "f82": None},
}
#: Snippets of each Fresnel flavour (the binding `cnlm_base_fresnel` is in the template).
FRESNEL_SNIPPETS: dict[tuple[str, str | None], tuple[str, ...]] = {
    ("conductor", "exact"): ("fresnel_conductor",),
    ("conductor", "schlick"): ("fresnel_schlick",),
    ("conductor", "f82"): ("fresnel_schlick", "fresnel_f82"),
    ("dielectric", "exact"): ("fresnel_dielectric",),
    ("dielectric", "schlick"): ("fresnel_schlick",),
    ("glass", "exact"): ("fresnel_dielectric",),
    ("glass", "schlick"): ("fresnel_schlick",),
}
DISTRIBUTION_SNIPPETS: dict[tuple[str | None, bool], tuple[str, ...]] = {
    ("ggx", False): ("ggx_isotropic",),
    ("ggx", True): ("ggx_aniso_terms", "ggx_anisotropic"),
    ("ward", True): ("ward",),
    ("ward", False): ("ward",),
}
DIFFUSE_SNIPPETS = {"lambert": ("diffuse_lambert",), "oren_nayar": ("diffuse_oren_nayar",), None: ()}
ALPHA_SNIPPETS = {"squared": ("alpha_squared",), "linear": ("alpha_linear",)}
#: Sampler role -> (GLSL name, colour space / encoding, what the shader reads).
SAMPLER_ROLES = {
    "base_color": (
        "cnlm_map_base_color",
        "srgb",
        "RGB albedo/tint; upload as an sRGB texture (GL_SRGB8[_ALPHA8]) so texture() returns linear",
    ),
    "normal": (
        "cnlm_map_normal",
        "linear",
        "tangent-space normal, OpenGL convention (+Y up the image), stored as n * 0.5 + 0.5",
    ),
    "roughness": ("cnlm_map_roughness", "linear", "perceptual roughness in the red channel"),
    "mask": (
        "cnlm_map_mask",
        "linear",
        "coverage in the red channel: blends the surface towards a Lambert lobe of the base colour",
    ),
}
#: Roles the shader reads (others go through the capability table).
SHADER_ROLES = tuple(SAMPLER_ROLES)
#: The body term's table (not a map: written by the target as a 16-bit PNG, docs/glsl.md "Subsurface").
LUT_SAMPLER = (
    "cnlm_sss_lut",
    "subsurface_lut",
    "linear",
    "the pre-integrated diffusion table D(cos theta, u) in red: rows cos(theta) -1..1 (image row 0 first, "
    "no flip), columns u = rho / (1 + rho) 0..cnlm_sss_lut_u_max; read with texelFetch (upload as float: "
    "R16F/R32F, value = 16-bit sample / 65535)",
)
#: the body term's uniforms: name -> type (values from backends/preview/subsurface.py)
BODY_UNIFORMS = {
    "cnlm_sss_albedo": "vec3",
    "cnlm_sss_mfp": "vec3",
    "cnlm_sss_profile_scale": "vec3",
    "cnlm_sss_thin": "int",
    "cnlm_sss_wall_through": "vec3",
    "cnlm_sss_wall_reflect": "vec3",
    "cnlm_sss_f0": "float",
    "cnlm_sss_entry": "float",
    "cnlm_sss_lut_u_max": "float",
    "cnlm_sss_centre": "vec3",
    "cnlm_sss_radius": "float",
    "cnlm_sss_closed": "int",
    "cnlm_sss_unit": "float",
}
#: the uber form's values for a material without a body (no body: a zero albedo, no wall)
BODY_NEUTRAL: dict[str, Any] = {
    "cnlm_sss_mfp": 1e-3,
    "cnlm_sss_profile_scale": 1e-3,
    "cnlm_sss_radius": 1.0,
    "cnlm_sss_closed": 1,
    "cnlm_sss_unit": 0.05,
    "cnlm_sss_lut_u_max": 0.95,
}


@dataclass(frozen=True)
class Uniform:
    name: str
    type: str
    value: object  # float or list of floats


@dataclass(frozen=True)
class Sampler:
    name: str
    role: str
    colour_space: str
    doc: str


@dataclass
class Plan:
    """The model choices of one material, as the templates read them."""

    base: str
    distribution: str | None
    anisotropic: bool
    diffuse: str | None
    fresnel: str | None
    coat: bool
    coat_color: bool
    multiscatter: bool
    maps: tuple
    alpha_convention: str
    snippets: list = field(default_factory=list)
    uniforms: list = field(default_factory=list)
    samplers: list = field(default_factory=list)
    sheen: bool = False  # the Charlie sheen over the base (snippets/sheen.glsl)
    flakes: bool = False  # the flake lobe mixed into the base under the coat (snippets/flakes.glsl)
    subsurface: bool = False  # the body term cnlm_subsurface and its table (snippets/subsurface.glsl)
    body: dict = field(default_factory=dict)  # the body term's uniform values (body_values), made once
    # a volume's base-colour map colours its body (cnlm_sss_mapped_albedo), not its black boundary
    body_map: bool = False
    # the body's table as a const array in the library (maps=none: no image), not the sampler cnlm_sss_lut
    lut_const: bool = False

    @property
    def microfacet(self) -> bool:
        return self.base in MICROFACET_BASES

    @property
    def transmission(self) -> bool:
        """Glass: the library also has cnlm_btdf (Walter 2007 transmission lobe)."""
        return self.base == "glass"

    @property
    def needs_tangent(self) -> bool:
        return self.anisotropic or "normal" in self.maps

    @property
    def alpha_type(self) -> str:
        return "vec2" if self.anisotropic else "float"


def _rgb(value: Any) -> list[float]:
    return [float(x) for x in np.broadcast_to(np.asarray(value, float), (3,))]


def diffuse_kind(material: Material) -> str | None:
    """Lambert or Oren-Nayar, by the same rule as the reference (σ > 0 for Oren-Nayar)."""
    kind = material.model.diffuse
    if kind == "oren_nayar" and not material.params.diffuse_roughness > 0:
        return "lambert"
    return kind if material.model.base in ("diffuse", "dielectric") else None


def material_coat(material: Material) -> Coat | None:
    """The coat the shader draws: the model says it has one and the parameters hold it."""
    return material.params.coat if material.model.coat else None


def make_plan(material: Material, options: GlslOptions) -> Plan:
    model, coat = material.model, material_coat(material)
    base = model.base
    plan = Plan(
        base=base,
        distribution=(model.distribution or "ggx") if base in MICROFACET_BASES else None,
        anisotropic=model.anisotropic and base in MICROFACET_BASES,
        diffuse=diffuse_kind(material),
        fresnel=EFFECTIVE_FRESNEL[base][options.fresnel],
        coat=coat is not None,
        coat_color=coat is not None and any(abs(c - 1.0) > 1e-6 for c in coat.color),
        multiscatter=options.multiscatter and base == "conductor",
        maps=tuple(role for role in SHADER_ROLES if role in material.maps),
        alpha_convention=material.params.alpha_convention,
        sheen=has_sheen(material),
        flakes=has_flakes(material),
        subsurface=has_body(material),
        lut_const=has_body(material) and options.maps == "none",
    )
    plan.body_map = plan.subsurface and material.model.subsurface == "volume" and "base_color" in plan.maps
    plan.body = body_values(material) if plan.subsurface else {}
    plan.snippets = snippet_names(plan)
    plan.uniforms = uniforms_for(plan, material)
    plan.samplers = [Sampler(SAMPLER_ROLES[r][0], r, SAMPLER_ROLES[r][1], SAMPLER_ROLES[r][2]) for r in plan.maps]
    plan.samplers += table_samplers(plan)
    return plan


def has_body(material: Material) -> bool:
    """A translucent body (model.subsurface "volume" or "thin"): the library has cnlm_subsurface."""
    return material.model.subsurface in ("volume", "thin") and material.params.subsurface is not None


def table_samplers(plan: Plan) -> list[Sampler]:
    """The samplers of the library's own tables (not maps): the body term's pre-integrated table."""
    return [Sampler(*LUT_SAMPLER)] if plan.subsurface and not plan.lut_const else []


def body_values(material: Material) -> dict[str, Any]:
    """The body term's uniform values: the material's (lengths in metres) and the object's as the
    preview's unit sphere has them (backends/preview/subsurface.py, the preview's own source)."""
    from ..preview.subsurface import body_uniforms, object_defaults

    values = {**object_defaults(), **body_uniforms(material)}
    return {name: _rgb(v) if np.size(v) == 3 else v for name, v in values.items()}  # plain Python values


def _body(name: str) -> UniformValue:
    def value(material: Material, plan: Plan) -> Any:
        found = plan.body[name] if plan.body else BODY_NEUTRAL.get(name, 0.0)
        kind = BODY_UNIFORMS[name]
        return _rgb(found) if kind == "vec3" else (int(found) if kind == "int" else float(found))

    return value


def snippet_names(plan: Plan) -> list[str]:
    """Snippet files in dependency order, each once."""
    names = ["common", "any_tangent"]
    if plan.maps:
        names.append("map_bound")
    if plan.needs_tangent:
        names.append("frame")
    if plan.anisotropic:
        names.append("rotate_tangent")
    if "roughness" in plan.maps and plan.microfacet:
        names += ALPHA_SNIPPETS[plan.alpha_convention]
    if plan.microfacet:
        names += FRESNEL_SNIPPETS[(plan.base, plan.fresnel)]
        names += DISTRIBUTION_SNIPPETS[(plan.distribution, plan.anisotropic)]
    if plan.transmission:
        names += ["ggx_aniso_terms", "ggx_transmission"]
    names += DIFFUSE_SNIPPETS[plan.diffuse]
    if "mask" in plan.maps:
        names += DIFFUSE_SNIPPETS["lambert"]
    if plan.coat:
        names += ["fresnel_dielectric", "coat", "ggx_isotropic"]
        if plan.coat_color:
            names.append("coat_absorption")
    if "normal" in plan.maps:
        names.append("normal_map")
    if plan.flakes:
        names += ["ggx_isotropic", "fresnel_schlick", "flakes"]
    if plan.sheen:
        names.append("sheen")
    if plan.subsurface:
        names.append("subsurface")
    if plan.body_map:
        names.append("subsurface_map")
    return list(dict.fromkeys(names))


def _alpha_value(plan: Plan, material: Material) -> float | list[float]:
    ax, ay = (float(a) for a in material_alpha(material))
    return [ax, ay] if plan.anisotropic else ax


def _f0(params: Params) -> list[float]:
    if params.f0 is not None:
        return _rgb(params.f0)
    return _rgb(f0_conductor(_rgb(params.eta), _rgb(params.k)))


def _multiscatter_favg(material: Material, fresnel: str) -> list[float]:
    coat = material_coat(material)
    outside = coat.ior if coat is not None else 1.0
    return _rgb(fresnel_average(conductor_fresnel(material.params, fresnel, outside)))


def _coat(material: Material) -> Coat:
    """The coat of a plan that has one."""
    assert material.params.coat is not None, f"{material.name}: a coat plan without a coat"
    return material.params.coat


UniformValue = Callable[[Material, Plan], Any]
#: uniform name -> (type, when it is needed, its value). Read by `uniforms_for`.
UNIFORM_TABLE: dict[str, tuple[str | None, Callable[[Plan], bool], UniformValue]] = {
    "cnlm_base_color": (
        "vec3",
        lambda p: "base_color" not in p.maps or p.body_map,  # a volume's map colours its body, not cnlm_bsdf
        lambda m, p: [0.0, 0.0, 0.0] if p.body_map else _rgb(m.params.base_color),  # a volume's boundary: black
    ),
    "cnlm_alpha": (
        None,
        lambda p: p.microfacet and "roughness" not in p.maps,  # float or vec2
        lambda m, p: _alpha_value(p, m),
    ),
    "cnlm_anisotropy": (
        "float",
        lambda p: p.anisotropic and "roughness" in p.maps,
        lambda m, p: float(m.params.anisotropy),
    ),
    "cnlm_anisotropy_rotation": (
        "float",
        lambda p: p.anisotropic,
        lambda m, p: float(m.params.anisotropy_rotation),
    ),
    "cnlm_eta": (
        "vec3",
        lambda p: p.base == "conductor" and p.fresnel == "exact",
        lambda m, p: _rgb(m.params.eta),
    ),
    "cnlm_k": ("vec3", lambda p: p.base == "conductor" and p.fresnel == "exact", lambda m, p: _rgb(m.params.k)),
    "cnlm_f0": (
        "vec3",
        lambda p: p.base == "conductor" and p.fresnel in ("schlick", "f82"),
        lambda m, p: _f0(m.params),
    ),
    "cnlm_f82": ("vec3", lambda p: p.base == "conductor" and p.fresnel == "f82", lambda m, p: _rgb(m.params.f82)),
    "cnlm_ior": ("float", lambda p: p.base in ("dielectric", "glass"), lambda m, p: float(m.params.ior)),
    "cnlm_transmission_depth": (
        "float",
        lambda p: p.base == "glass",
        lambda m, p: float(m.params.transmission_depth),
    ),
    "cnlm_diffuse_roughness": (
        "float",
        lambda p: p.diffuse == "oren_nayar",
        lambda m, p: float(m.params.diffuse_roughness),
    ),
    "cnlm_coat_ior": ("float", lambda p: p.coat, lambda m, p: float(_coat(m).ior)),
    "cnlm_coat_alpha": (
        "float",
        lambda p: p.coat,
        lambda m, p: float(coat_alpha(_coat(m), m.params.alpha_convention)[0]),
    ),
    # per unit base colour, what the coat sends back to the diffuse base in one round trip
    # (cnlmc.bsdf.flakes.coat_trap): the diffuse part is diff / (eta^2 (1 - base colour * trap))
    "cnlm_coat_trap": (
        "vec3",
        lambda p: p.coat and p.base != "conductor",
        lambda m, p: _rgb(coat_trap(m, p.fresnel or "exact")),
    ),
    "cnlm_coat_color": ("vec3", lambda p: p.coat_color, lambda m, p: _rgb(_coat(m).color)),
    "cnlm_coat_thickness": (
        "float",
        lambda p: p.coat_color,
        lambda m, p: float(_coat(m).thickness),
    ),
    "cnlm_ms_favg": ("vec3", lambda p: p.multiscatter, lambda m, p: _multiscatter_favg(m, p.fresnel or "exact")),
    # layers (zero without them: the uber form draws them always, a zero layer is no layer)
    "cnlm_flake_color": ("vec3", lambda p: p.flakes, lambda m, p: _rgb(m.params.flake_color or 0.0)),
    "cnlm_flake_density": ("float", lambda p: p.flakes, lambda m, p: _flake_density(m)),
    "cnlm_flake_alpha": ("float", lambda p: p.flakes, lambda m, p: float(flake_alpha(m.params.flake_roughness))),
    "cnlm_sheen_color": ("vec3", lambda p: p.sheen, lambda m, p: _rgb(m.params.sheen_color or 0.0)),
    "cnlm_sheen_alpha": ("float", lambda p: p.sheen, lambda m, p: _sheen_alpha(m)),
    # the white sheen's albedo row at that alpha (cnlmc.bsdf.sheen.sheen_row): re-emit to change alpha
    "cnlm_sheen_albedo": ("float[32]", lambda p: p.sheen, lambda m, p: [float(e) for e in sheen_row(_sheen_alpha(m))]),
    # the body term (snippets/subsurface.glsl): the material's, then the object's (set them for your mesh)
    **{name: (gl_type, lambda p: p.subsurface, _body(name)) for name, gl_type in BODY_UNIFORMS.items()},
}


def _flake_density(material: Material) -> float:
    return float(material.params.flake_density) if has_flakes(material) else 0.0


def _sheen_alpha(material: Material) -> float:
    return float(sheen_alpha(material.params.sheen_roughness))


def uniforms_for(plan: Plan, material: Material) -> list[Uniform]:
    """The uniforms the plan's code reads, with the material's values (to a float's 9 digits)."""
    return [
        Uniform(name, gl_type or plan.alpha_type, _to_float32_digits(value(material, plan)))
        for name, (gl_type, needed, value) in UNIFORM_TABLE.items()
        if needed(plan)
    ]


def _to_float32_digits(value: Any) -> Any:
    """A uniform's value to 9 significant digits, what a 32-bit GLSL float holds exactly: the
    computed ones (a sheen albedo row, the body's inverted medium) otherwise differ in their last
    of 17 digits from one CPU's vector code to another's, and the emitted files with them."""
    if isinstance(value, float):
        return float(format(value, ".9g"))
    if isinstance(value, (list, tuple)):
        return type(value)(_to_float32_digits(v) for v in value)
    return value


# ---- the all-features ("uber") form: option specialize=off ----

#: Placeholders for the uniforms of an uber shader that the material's model leaves without a
#: value: the metal optics (the table has no default for them; these make a dielectric-like
#: conductor the selectors never read) and a clear, smooth coat. Every other parameter holds
#: the table's default when the IR lacks it (cnlmc.params).
UBER_OPTICS: dict[str, Any] = {
    "eta": (1.5, 1.5, 1.5),
    "k": (0.0, 0.0, 0.0),
    "f0": (0.04, 0.04, 0.04),
    "f82": (0.04, 0.04, 0.04),
}
UBER_COAT_DEFAULT = Coat(name="", ior=1.5, roughness=0.0, alpha=(0.0, 0.0), color=(1.0, 1.0, 1.0), thickness=0.0)
#: selector uniform -> plan attribute -> integer code read by templates/uber.glsl.j2.
UBER_SELECTORS: dict[str, tuple[str, dict[Any, int]]] = {
    "cnlm_sel_base": ("base", {"diffuse": 0, "dielectric": 1, "conductor": 2, "glass": 3}),
    "cnlm_sel_distribution": ("distribution", {None: 0, "ggx": 0, "ward": 1}),
    "cnlm_sel_diffuse": ("diffuse", {None: 0, "lambert": 0, "oren_nayar": 1}),
    "cnlm_sel_fresnel": ("fresnel", {None: 0, "exact": 0, "schlick": 1, "f82": 2}),
    "cnlm_sel_alpha_convention": ("alpha_convention", {"squared": 0, "linear": 1}),
    "cnlm_use_anisotropy": ("anisotropic", {False: 0, True: 1}),
    "cnlm_use_coat": ("coat", {False: 0, True: 1}),
    "cnlm_use_multiscatter": ("multiscatter", {False: 0, True: 1}),
}
UBER_SNIPPETS = (
    "common",
    "any_tangent",
    "frame",
    "rotate_tangent",
    "fresnel_dielectric",
    "fresnel_conductor",
    "fresnel_schlick",
    "fresnel_f82",
    "ggx_isotropic",
    "ggx_aniso_terms",
    "ggx_anisotropic",
    "ward",
    "diffuse_lambert",
    "diffuse_oren_nayar",
    "coat",
    "coat_absorption",
    "map_bound",
    "normal_map",
    "flakes",
    "sheen",
    "subsurface",
    "subsurface_map",
)


def complete_material(material: Material) -> Material:
    """The material with every parameter an uber shader reads: a placeholder for the metal
    optics and the coat where the IR has none (the table's defaults cover the rest)."""
    params = material.params
    neutral = {name: value for name, value in UBER_OPTICS.items() if getattr(params, name) is None}
    coat = params.coat if params.coat is not None else UBER_COAT_DEFAULT
    return dataclasses.replace(material, params=dataclasses.replace(params, **neutral, coat=coat))


def make_uber_plan(material: Material, options: GlslOptions) -> Plan:
    """Every branch compiled in: the material's choices become integer uniforms."""
    plan = make_plan(material, options)
    every = Plan(
        base="conductor",
        distribution="ggx",
        anisotropic=True,
        diffuse="oren_nayar",
        fresnel=options.fresnel,
        coat=True,
        coat_color=True,
        multiscatter=True,
        maps=SHADER_ROLES,
        alpha_convention=plan.alpha_convention,
        snippets=list(UBER_SNIPPETS),
        sheen=True,
        flakes=True,
        subsurface=True,
        body=plan.body,
        body_map=plan.body_map,
        lut_const=plan.lut_const,
    )
    selectors = [
        Uniform(name, "int", codes[getattr(plan, attribute)]) for name, (attribute, codes) in UBER_SELECTORS.items()
    ]
    # a volume's base-colour map colours its body (cnlm_sss_use_map), not its boundary (cnlm_use_map_base_color 0)
    drawn = [role for role in plan.maps if not (plan.body_map and role == "base_color")]
    map_flags = [Uniform(f"cnlm_use_map_{role}", "int", int(role in drawn)) for role in SHADER_ROLES]
    map_flags.append(Uniform("cnlm_sss_use_map", "int", int(plan.body_map)))
    full = complete_material(material)
    params = [
        Uniform(name, gl_type or "vec2", value(full, every)) for name, (gl_type, _, value) in UNIFORM_TABLE.items()
    ]
    every.uniforms = selectors + map_flags + params
    every.samplers = [Sampler(SAMPLER_ROLES[r][0], r, SAMPLER_ROLES[r][1], SAMPLER_ROLES[r][2]) for r in SHADER_ROLES]
    every.samplers += table_samplers(every)
    return every
