"""The parameter table: every IR parameter declared once, as a field of `Params` or `Coat`.

Each field carries its metadata (`param(...)`): kind, range, default, unit and colour space,
the base models that use it, when it appears, and a one-line doc. Everything else is derived
from it: the range pass (`ranges()`), the model -> parameters map (`params_by_model()`), the
parameters a noun may set (`noun_params()`), the JSON schema and the docs table
(cnlmc.params_doc), the stdlib schema's parameter fields (cnlmc.lexicon_schema).

To add a parameter: declare one field here, then teach the backends that express it.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any, TypeVar

from .conventions import ALPHA_MIRROR, CONVENTIONS

RGB = tuple[float, float, float]
T = TypeVar("T")

BASES = ("diffuse", "dielectric", "conductor", "glass")
DISTRIBUTIONS = (None, "ggx", "ward")
DIFFUSE_LOBES = (None, "lambert", "oren_nayar")
SPECULAR = ("dielectric", "conductor", "glass")

#: when a parameter is in a material's IR: "base" (its base model is in `models`), or a condition on the model
WHEN = {
    "base": "the base model is one of `models`",
    "specular": "the base is not diffuse",
    "anisotropic": "model.anisotropic",
    "oren_nayar": 'model.diffuse is "oren_nayar"',
    "always": "always (null when the model has no coat)",
    "sheen": "the noun has a sheen (velvet, cloth: docs/bsdf.md 'Sheen')",
    "flakes": "a word asks for flakes (metallic, pearlescent, glittery paint or plastic: docs/bsdf.md 'Flakes')",
    "subsurface": "model.subsurface is not null (docs/subsurface.md)",
}
SUBSURFACE_MODELS = (None, "volume", "thin")


@dataclass(frozen=True)
class ParamSpec:
    """One row of the table (a field's metadata, with the field's name and default)."""

    name: str
    kind: str  # "number" | "rgb" | "alpha" | "enum" | "coat" | "subsurface" | "str"
    default: Any
    range: tuple[float, float] | None
    unit: str
    models: tuple[str, ...]
    when: str
    doc: str
    choices: tuple[str, ...] = ()
    optional: bool = False  # None is a value (the metal optics)
    required: bool = False  # always in the JSON (the schema's "required")
    noun: bool = False  # a lexicon noun may set it (stdlib/schema.toml [nouns])
    convention: str = ""  # the alpha convention note, where it matters


def param(
    *,
    default: T,
    kind: str,
    doc: str,
    range: tuple[float, float] | None = None,
    unit: str = "",
    models: tuple[str, ...] = BASES,
    when: str = "base",
    choices: tuple[str, ...] = (),
    optional: bool = False,
    required: bool = False,
    noun: bool = False,
    convention: str = "",
) -> T:
    """A table field: its default, and its metadata for everything derived from the table."""
    meta = {
        "kind": kind,
        "range": range,
        "unit": unit,
        "models": models,
        "when": when,
        "doc": doc,
        "choices": choices,
        "optional": optional,
        "required": required,
        "noun": noun,
        "convention": convention,
    }
    return field(default=default, metadata={"param": meta})


ALPHA_NOTE = "alpha = r^2 (squared) or r (linear); s = sqrt(1 - 0.9 a), alpha_x = alpha / s, alpha_y = alpha * s"


@dataclass(frozen=True)
class Coat:
    """A dielectric coat layer over the base (Weidlich-Wilkie stacking)."""

    name: str = param(default="", kind="str", doc="the coat's lexicon name", required=True)
    ior: float = param(
        default=1.5, kind="number", range=(1.0, 3.0), doc="index of refraction of the coat", required=True
    )
    roughness: float = param(
        default=0.0, kind="number", range=(0.0, 1.0), unit="perceptual r", doc="the coat's roughness", required=True
    )
    alpha: tuple[float, float] = param(
        default=(0.0, 0.0),
        kind="alpha",
        range=(0.0, 1.0),
        doc="isotropic [a, a] from the coat's roughness, in the same convention as the base",
        required=True,
        convention=ALPHA_NOTE,
    )
    color: RGB = param(
        default=(1.0, 1.0, 1.0),
        kind="rgb",
        range=(0.0, 1.0),
        unit="linear Rec.709",
        doc="the linear RGB round-trip transmittance tint at normal incidence; along refracted directions "
        "color^(thickness * (1/cos to + 1/cos ti) / 2)",
        required=True,
    )
    thickness: float = param(
        default=1.0, kind="number", range=(0.0, 10.0), unit="unitless", doc="a unitless absorption scale", required=True
    )


@dataclass(frozen=True)
class Subsurface:
    """Light that enters the body and leaves elsewhere (docs/subsurface.md): a homogeneous medium."""

    color: RGB = param(
        default=(0.8, 0.8, 0.8),
        kind="rgb",
        range=(0.0, 1.0),
        unit="linear Rec.709",
        doc="the multiple-scattering albedo (what a thick slab of the medium reflects), per channel",
        required=True,
    )
    radius: RGB = param(
        default=(0.001, 0.001, 0.001),
        kind="rgb",
        range=(0.0, 1.0),
        unit="metres",
        doc="the mean free path per channel (how far light travels in the body)",
        required=True,
    )
    anisotropy: float = param(
        default=0.0,
        kind="number",
        range=(-0.99, 0.99),
        doc="the Henyey-Greenstein phase function's g (0 = isotropic)",
        required=True,
    )
    thickness: float | None = param(
        default=None,
        kind="number",
        range=(0.0, 1.0),
        unit="metres",
        doc='the sheet\'s thickness for model.subsurface "thin"; null for "volume" (the mesh is the body)',
        optional=True,
        required=True,
    )


@dataclass(frozen=True)
class Params:
    """A material's parameters. Fields in IR order; `present` names the keys the IR JSON has."""

    base_color: RGB = param(
        default=(1.0, 1.0, 1.0),
        kind="rgb",
        range=(0.0, 1.0),
        unit="linear Rec.709",
        doc="diffuse albedo for diffuse/dielectric; for glass the transmittance through transmission_depth of the "
        "material (Beer-Lambert); a multiplicative tint on the Fresnel term for conductors (1,1,1 = the measured metal)",
        required=True,
        noun=True,
    )
    roughness: float = param(
        default=0.5,
        kind="number",
        range=(0.0, 1.0),
        unit="perceptual r",
        models=SPECULAR,
        doc="perceptual roughness r; kept for targets that take it (alpha is authoritative)",
        noun=True,
    )
    eta: RGB | None = param(
        default=None,
        kind="rgb",
        models=("conductor",),
        doc="conductor optical constant eta (the fitted RGB triplet of the dataset)",
        optional=True,
        noun=True,
    )
    k: RGB | None = param(
        default=None,
        kind="rgb",
        models=("conductor",),
        doc="conductor optical constant k (extinction), RGB",
        optional=True,
        noun=True,
    )
    f0: RGB | None = param(
        default=None,
        kind="rgb",
        models=("conductor",),
        doc="measured reflectance at 0 degrees (Schlick); may exceed 1 in one channel (gold's red)",
        optional=True,
        noun=True,
    )
    f82: RGB | None = param(
        default=None,
        kind="rgb",
        models=("conductor",),
        doc="measured reflectance at 82 degrees (the F82 approximation)",
        optional=True,
        noun=True,
    )
    ior: float = param(
        default=1.5,
        kind="number",
        range=(1.0, 5.0),
        models=("dielectric", "glass"),
        doc="scalar index of refraction (the outside medium is air, 1.0)",
        noun=True,
    )
    transmission_depth: float = param(
        default=0.05,
        kind="number",
        range=(1e-5, 100.0),
        unit="metres",
        models=("glass",),
        doc="the depth through which base_color is the glass's transmittance: a path of length d inside keeps "
        "base_color^(d / transmission_depth) (Beer-Lambert; docs/bsdf.md 'Absorption')",
        noun=True,
    )
    diffuse_roughness: float = param(
        default=0.0,
        kind="number",
        range=(0.0, 1.6),
        unit="radians",
        when="oren_nayar",
        doc="Oren-Nayar sigma (0 = Lambert)",
        noun=True,
    )
    alpha: tuple[float, float] = param(
        default=(0.25, 0.25),
        kind="alpha",
        range=(0.0, 1.0),
        models=SPECULAR,
        when="specular",
        doc="[alpha_x, alpha_y], the microfacet widths from roughness and anisotropy by alpha_convention "
        f"(cnlmc.conventions.alpha_of); below ALPHA_MIRROR = {ALPHA_MIRROR:g} a perfect mirror",
        convention=ALPHA_NOTE,
    )
    alpha_convention: str = param(
        default="squared",
        kind="enum",
        choices=CONVENTIONS,
        models=SPECULAR,
        when="specular",
        doc="squared (alpha = r^2, the stdlib) or linear (alpha = r, the paper's m)",
        convention=ALPHA_NOTE,
    )
    anisotropy: float = param(
        default=0.0,
        kind="number",
        range=(0.0, 1.0),
        models=SPECULAR,
        when="anisotropic",
        doc="a; alpha_x = alpha / s, alpha_y = alpha * s with s = sqrt(1 - 0.9 a)",
        convention=ALPHA_NOTE,
    )
    anisotropy_rotation: float = param(
        default=0.0,
        kind="number",
        unit="radians",
        models=SPECULAR,
        when="anisotropic",
        doc="the tangent direction of the streaks",
    )
    coat: Coat | None = param(
        default=None,
        kind="coat",
        when="always",
        doc="null, or the coat layer (the coat table below)",
        optional=True,
        required=True,
    )
    sheen_color: RGB | None = param(
        default=None,
        kind="rgb",
        range=(0.0, 1.0),
        unit="linear Rec.709",
        when="sheen",
        doc="the Charlie sheen's colour over the base (a fibre layer: velvet, cloth); null = no sheen",
        optional=True,
        noun=True,
    )
    sheen_roughness: float = param(
        default=0.3,
        kind="number",
        range=(0.0, 1.0),
        unit="perceptual r",
        when="sheen",
        doc="the sheen's roughness r; the Charlie lobe's alpha = r^2",
        noun=True,
    )
    flake_color: RGB | None = param(
        default=None,
        kind="rgb",
        range=(0.0, 1.0),
        unit="linear Rec.709",
        when="flakes",
        doc="the flakes' normal-incidence reflectance F0 (Schlick), under the coat; null = no flakes",
        optional=True,
    )
    flake_density: float = param(
        default=0.0,
        kind="number",
        range=(0.0, 1.0),
        unit="area fraction",
        when="flakes",
        doc="the share of the surface the flakes cover; the pigment below shows through 1 - density",
    )
    flake_roughness: float = param(
        default=0.5,
        kind="number",
        range=(0.0, 1.0),
        unit="perceptual r",
        when="flakes",
        doc="the spread of the flakes' orientations; their GGX normal distribution's alpha = r^2",
    )
    flake_size: float = param(
        default=0.0001,
        kind="number",
        range=(0.00001, 0.001),
        unit="metres",
        when="flakes",
        doc="a flake's real size (0.02-0.2 mm paint, up to 1 mm glitter): how many flakes a pixel sees",
    )
    subsurface: Subsurface | None = param(
        default=None,
        kind="subsurface",
        when="subsurface",
        doc="the medium under the dielectric boundary (the subsurface table below); the boundary's IOR is `ior`",
        optional=True,
    )
    present: frozenset[str] = field(default=frozenset(), compare=True)


def _specs(cls: type) -> tuple[ParamSpec, ...]:
    return tuple(
        ParamSpec(name=f.name, default=f.default, **f.metadata["param"])
        for f in dataclasses.fields(cls)
        if "param" in f.metadata
    )


PARAMS: tuple[ParamSpec, ...] = _specs(Params)
COAT_PARAMS: tuple[ParamSpec, ...] = _specs(Coat)
SUBSURFACE_PARAMS: tuple[ParamSpec, ...] = _specs(Subsurface)
PARAM_NAMES: frozenset[str] = frozenset(s.name for s in PARAMS)


def params_by_model() -> dict[str, tuple[str, ...]]:
    """base model -> the parameters it always has in the IR, in IR order."""
    return {base: tuple(s.name for s in PARAMS if s.when == "base" and base in s.models) for base in BASES}


def ranges(specs: tuple[ParamSpec, ...] = PARAMS) -> dict[str, tuple[float, float]]:
    """param -> (low, high) for the range pass: the settable numbers and colours with a range."""
    return {s.name: s.range for s in specs if s.range is not None and s.kind in ("number", "rgb")}


def noun_params() -> tuple[str, ...]:
    """The parameters a lexicon noun may set."""
    return tuple(s.name for s in PARAMS if s.noun)


def spec(name: str, specs: tuple[ParamSpec, ...] = PARAMS) -> ParamSpec:
    for s in specs:
        if s.name == name:
            return s
    raise KeyError(name)
