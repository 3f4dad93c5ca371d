"""What the preview's subsurface shader (shaders/subsurface.glsl.j2) needs to know about a
translucent material and the scene: the body's albedo and mean free path in scene units, whether
it is a thick volume or a thin wall, and the object's bounding sphere (the path length light
takes through the body). docs/preview.md, "Subsurface".

The IR (docs/subsurface.md): `model.subsurface` is "volume" or "thin" (absent otherwise) and
`params.subsurface` holds `color` (multiple-scattering albedo), `radius` (mean free path per
channel, metres), `anisotropy` and `thickness` (metres, thin walls)."""

from __future__ import annotations

import dataclasses
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from cnlmc.material import Material

from .glass import bounding_sphere
from .mesh import Mesh
from .subsurface_profile import BesselK0, PreintegratedTable

DATA = Path(__file__).parent / "data" / "subsurface.toml"
FORMS = ("volume", "thin")


@dataclass(frozen=True)
class Settings:
    """The approximation's constants (data/subsurface.toml), immutable: one shared copy is safe."""

    default_thickness_m: float
    profile_cos_steps: int
    profile_rho_steps: int
    profile_u_max: float


@cache
def settings() -> Settings:
    """The constants, read once (a frozen value: no caller can change what another reads)."""
    with DATA.open("rb") as handle:
        table = tomllib.load(handle)
    return Settings(
        default_thickness_m=float(table["thin"]["default_thickness_m"]),
        profile_cos_steps=int(table["profile"]["cos_steps"]),
        profile_rho_steps=int(table["profile"]["rho_steps"]),
        profile_u_max=float(table["profile"]["u_max"]),
    )


@cache
def preintegrated_table() -> PreintegratedTable:
    """The key light's pre-integrated diffusion table (subsurface_profile.py), made once: an
    immutable value (its array is read-only)."""
    with DATA.open("rb") as handle:
        bessel = tomllib.load(handle)["bessel"]
    k0 = BesselK0(tuple(bessel["i0_small"]), tuple(bessel["k0_small"]), tuple(bessel["k0_large"]))
    constants = settings()
    return PreintegratedTable(constants.profile_cos_steps, constants.profile_rho_steps, constants.profile_u_max, k0)


@dataclass(frozen=True)
class TranslucentBody:
    """A translucent body: `form` "volume" or "thin"; `color` the multiple-scattering albedo,
    `radius` the mean free path (metres) per channel, `thickness` a thin wall's (metres)."""

    form: str
    color: tuple[float, float, float]
    radius: tuple[float, float, float]
    anisotropy: float = 0.0
    thickness: float | None = None
    ior: float = 1.4

    @property
    def thin(self) -> bool:
        return self.form == "thin"

    def wall(self) -> float:
        """A thin wall's thickness in metres (the data's default when the IR gives none)."""
        return float(self.thickness or settings().default_thickness_m)


def _field(record: Any, name: str, default: Any = None) -> Any:
    if isinstance(record, Mapping):
        return record.get(name, default)
    return getattr(record, name, default)


def _triple(value: Any) -> tuple[float, float, float]:
    values = [float(x) for x in np.broadcast_to(np.asarray(value, np.float64), (3,))]
    return values[0], values[1], values[2]


def subsurface_of(material: Any) -> TranslucentBody | None:
    """The material's subsurface body (a typed Material or its IR object), None when its model
    has none."""
    model, params = _field(material, "model"), _field(material, "params")
    form = _field(model, "subsurface")
    record = _field(params, "subsurface")
    if form not in FORMS or record is None:
        return None
    thickness = _field(record, "thickness")
    return TranslucentBody(
        form=str(form),
        color=_triple(_field(record, "color", 0.8)),
        radius=_triple(_field(record, "radius", 1e-3)),
        anisotropy=float(_field(record, "anisotropy", 0.0) or 0.0),
        thickness=None if thickness is None else float(thickness),
        ior=float(_field(params, "ior", 1.4) or 1.4),
    )


def has_subsurface(material: Any) -> bool:
    return subsurface_of(material) is not None


def boundary_material(material: Material) -> Material:
    """What the preview draws with cnlm_bsdf for a translucent material. A volume: its boundary
    alone, the base colour black (the body's light is the subsurface term; the IR's base_color is
    the colour the eye sees, for exports without subsurface). A volume with a base-colour map keeps
    the map and its params (the map's graph reads base_color as its input): the map colours the
    body, not the boundary, and the shader's plan draws the boundary black (glsl plan.body_map,
    snippets/subsurface_map.glsl: marble's veins). A thin sheet: its front as the Mitsuba export
    draws it, base_color x (1 - w), w the largest channel of the sheet's transmittance (the blend's
    weight; the subsurface term adds what comes through). Any other material is returned as it is."""
    body = subsurface_of(material)
    if body is None or (not body.thin and "base_color" in material.maps):
        return material
    if body.thin:
        _, through = sheet_optics(body)
        front = _triple(np.asarray(material.params.base_color, np.float64) * (1.0 - float(through.max())))
        return dataclasses.replace(material, params=dataclasses.replace(material.params, base_color=front))
    return dataclasses.replace(material, params=dataclasses.replace(material.params, base_color=(0.0, 0.0, 0.0)))


def metres_per_unit() -> float:
    """Metres one scene unit spans: the Mitsuba export's (backends/exchange/mitsuba_subsurface.py
    METRES_PER_UNIT, a unit sphere is a 10 cm ball), so the preview and its reference agree."""
    from ..exchange.mitsuba_subsurface import METRES_PER_UNIT

    return float(METRES_PER_UNIT)


def sheet_optics(body: TranslucentBody) -> tuple[np.ndarray, np.ndarray]:
    """(diffuse reflectance R, diffuse transmittance T) of a thin wall: the Kubelka-Munk slab of
    the IR's medium at its thickness (cnlmc.bsdf.subsurface.slab; the Mitsuba export's sheet
    transmits its T)."""
    from cnlmc.bsdf.subsurface import medium_of, slab

    medium = medium_of(body.color, body.radius, body.anisotropy, body.ior)
    reflectance, transmittance = slab(medium, body.wall())
    return np.clip(reflectance, 0.0, 1.0), np.clip(transmittance, 0.0, 1.0)


def schlick_f0(ior: float) -> float:
    return ((ior - 1.0) / (ior + 1.0)) ** 2


def entry_transmittance(ior: float) -> float:
    """The share of diffuse light that crosses the boundary into the body: 1 - the cosine-weighted
    mean of Schlick's Fresnel, f0 + (1 - f0) / 21 (int (1 - mu)^5 2 mu dmu = 1/21). Jensen et al.
    2001's BSSRDF has a Fresnel transmittance where light enters as where it leaves; light that
    reaches a point by diffusion entered at many angles, so the mean is taken."""
    f0 = schlick_f0(ior)
    return 1.0 - (f0 + (1.0 - f0) / 21.0)


def profile_scale(body: TranslucentBody) -> np.ndarray:
    """Christensen-Burley's d = l_d / s(A) per channel (metres): the unit of the pre-integrated table."""
    from cnlmc.bsdf.subsurface import profile_shape

    return np.asarray(body.radius, np.float64) / profile_shape(np.clip(body.color, 0.0, 1.0))


def wall_reflectance(boundary: Any, body: TranslucentBody) -> np.ndarray:
    """A thin wall's diffuse reflectance seen from inside a closed shell (the cavity's light comes
    back from it; the sheet is two-sided): the interface's mean reflectance for diffuse light,
    1 - t_in (entry_transmittance), plus what enters it and comes back from the front colour as
    cnlm_bsdf draws it, t_in x the boundary's base_color (boundary_material: base_color x (1 - max T)),
    at most 1 - T (the wall reflects no more than it does not let through: R + T <= 1)."""
    _, through = sheet_optics(body)
    t_in = entry_transmittance(body.ior)
    front = np.asarray(_field(_field(boundary, "params"), "base_color", 0.0), np.float64)
    reflect = (1.0 - t_in) + t_in * np.clip(front, 0.0, 1.0)
    return np.clip(np.minimum(reflect, 1.0 - through), 0.0, 1.0)


def body_uniforms(material: Any) -> dict[str, Any]:
    """The body term's material uniforms (the GLSL library's cnlm_sss_*, snippets/subsurface.glsl;
    lengths in metres) of `material` as cnlm_bsdf draws it (its boundary_material: what the preview
    and the GLSL target make their plan from); none when the material has no subsurface body. The GLSL target's plan
    declares them with these values (glsl/plan.py), so the preview and the target read the same."""
    body = subsurface_of(material)
    if body is None:
        return {}
    # a volume's colour is the dipole's total diffuse reflectance (docs/subsurface.md): the body albedo
    # a thin sheet's front is cnlm_bsdf's (boundary_material): the term adds what comes through
    reflect, through = (
        (np.zeros(3), sheet_optics(body)[1]) if body.thin else (np.clip(body.color, 0.0, 1.0), np.zeros(3))
    )
    return {
        # thin: what the wall reflects back into a closed shell's cavity (wall_reflectance)
        "cnlm_sss_wall_reflect": wall_reflectance(material, body) if body.thin else np.zeros(3),
        "cnlm_sss_albedo": reflect,
        "cnlm_sss_mfp": np.asarray(body.radius, np.float64),
        "cnlm_sss_profile_scale": profile_scale(body),
        "cnlm_sss_thin": int(body.thin),
        # thin: the sheet's diffuse transmittance (the shader squares it on a closed mesh: two walls)
        "cnlm_sss_wall_through": through,
        "cnlm_sss_f0": schlick_f0(body.ior),
        "cnlm_sss_entry": entry_transmittance(body.ior),
        "cnlm_sss_lut_u_max": preintegrated_table().u_max,
    }


def object_defaults() -> dict[str, object]:
    """The body term's object uniforms as the preview's unit sphere has them (the GLSL target's
    initial values): the bounding sphere, a closed mesh, metres_per_unit metres a unit."""
    return {
        "cnlm_sss_centre": np.zeros(3),
        "cnlm_sss_radius": 1.0,
        "cnlm_sss_closed": 1,
        "cnlm_sss_unit": metres_per_unit(),
    }


def lut_image() -> np.ndarray:
    """The pre-integrated table as the texture cnlm_sss_lut: (cos steps, rho steps) float32, row 0
    (texelFetch's y = 0) at cos(theta) = -1, column 0 at u = 0."""
    return preintegrated_table().values


def subsurface_uniforms(material: Any, mesh: Mesh, model: np.ndarray) -> dict[str, object]:
    """The body term's object uniforms for the object drawn with `model` (world = model @ object);
    none when the material has no subsurface body: the bounding sphere in world units, whether
    the mesh is closed, and the metres one world unit spans (the scene's metres_per_unit over the
    model matrix's scale). The material's own uniforms are the library's (body_uniforms)."""
    if subsurface_of(material) is None:
        return {}
    centre, radius = bounding_sphere(mesh)
    model = np.asarray(model, np.float64)
    scale = abs(float(np.linalg.det(model[:3, :3]))) ** (1.0 / 3.0) or 1.0
    return {
        "cnlm_sss_centre": model[:3, :3] @ centre + model[:3, 3],
        "cnlm_sss_radius": radius * scale,
        "cnlm_sss_closed": int(mesh.closed),
        "cnlm_sss_unit": metres_per_unit() / scale,
    }
