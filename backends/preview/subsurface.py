"""What the preview's subsurface shader (shaders/subsurface.glsl.j2) needs to know about a
translucent material and the scene: the body's albedo and mean free path in scene units, whether
it is a thick volume or a thin wall, and the object's bounding sphere (the path length light
takes through the body). docs/preview.md, "Subsurface".

The IR (docs/subsurface.md): `model.subsurface` is "volume" or "thin" (absent otherwise) and
`params.subsurface` holds `color` (multiple-scattering albedo), `radius` (mean free path per
channel, metres), `anisotropy` and `thickness` (metres, thin walls)."""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from .glass import bounding_sphere
from .mesh import Mesh

DATA = Path(__file__).parent / "data" / "subsurface.toml"
FORMS = ("volume", "thin")


@cache
def settings() -> Mapping[str, Any]:
    """The approximation's constants (data/subsurface.toml; read once, never changed)."""
    with DATA.open("rb") as handle:
        return tomllib.load(handle)


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
        return float(self.thickness or settings()["thin"]["default_thickness_m"])


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


def single_scattering_albedo(color: Any) -> np.ndarray:
    """The single-scattering albedo whose multiple-scattering albedo is `color`: the
    Christensen-Burley inversion (Christensen & Burley 2015, "Approximate Reflectance Profiles
    for Efficient Subsurface Scattering", their fit of van de Hulst's albedo):
    alpha = 1 - (4.09712 + 4.20863 c - sqrt(9.59217 + 41.6808 c + 17.7126 c^2))^2."""
    c = np.clip(np.asarray(color, np.float64), 0.0, 1.0)
    return np.asarray(1.0 - (4.09712 + 4.20863 * c - np.sqrt(9.59217 + 41.6808 * c + 17.7126 * c * c)) ** 2)


def diffuse_reflectance(alpha: Any, ior: float) -> np.ndarray:
    """What a semi-infinite medium of single-scattering albedo `alpha` under a boundary of `ior`
    reflects in all (Jensen et al. 2001, the dipole's total diffuse reflectance R_d, with
    Egan-Hilgeman's diffuse Fresnel reflectance F_dr for the boundary). The body's albedo in the
    preview: what Mitsuba's medium behind its dielectric boundary gives back (docs/preview.md)."""
    a = np.clip(np.asarray(alpha, np.float64), 0.0, 1.0)
    f_dr = -1.440 / ior**2 + 0.710 / ior + 0.668 + 0.0636 * ior
    boundary = (1.0 + f_dr) / (1.0 - f_dr)
    s = np.sqrt(3.0 * (1.0 - a))
    return np.asarray(a / 2.0 * (1.0 + np.exp(-4.0 / 3.0 * boundary * s)) * np.exp(-s))


def body_albedo(body: TranslucentBody) -> np.ndarray:
    """The share of light entering the body that leaves it again, per channel (<= 1)."""
    return np.clip(diffuse_reflectance(single_scattering_albedo(body.color), body.ior), 0.0, 1.0)


def wall_optics(body: TranslucentBody) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(diffuse reflectance, diffuse transmittance, unscattered transmittance) of a thin wall,
    per channel: Kubelka-Munk for a slab of the wall's thickness (K = 2 sigma_a, S = sigma_s (1 - g);
    Kubelka & Munk 1931, our mapping from the medium) for what scatters, Beer-Lambert
    exp(-sigma_t t) for what crosses without scattering (seen through the wall, undeflected)."""
    sigma_t = 1.0 / np.maximum(np.asarray(body.radius, np.float64), 1e-9)
    albedo = single_scattering_albedo(body.color)
    k = 2.0 * sigma_t * (1.0 - albedo)
    scatter = np.maximum(sigma_t * albedo * (1.0 - body.anisotropy), 1e-12)
    a = 1.0 + k / scatter
    b = np.sqrt(np.maximum(a * a - 1.0, 0.0))
    x = np.minimum(b * scatter * body.wall(), 50.0)
    sinh_over_b = np.where(b > 1e-9, np.sinh(x) / np.maximum(b, 1e-12), scatter * body.wall())
    denominator = a * sinh_over_b + np.cosh(x)
    ballistic = np.exp(-sigma_t * body.wall())
    reflect = sinh_over_b / denominator
    through = np.clip(1.0 / denominator - ballistic, 0.0, 1.0)
    return np.asarray(reflect), np.asarray(through), np.asarray(ballistic)


def schlick_f0(ior: float) -> float:
    return ((ior - 1.0) / (ior + 1.0)) ** 2


def subsurface_uniforms(material: Any, mesh: Mesh, model: np.ndarray) -> dict[str, object]:
    """The subsurface uniforms for the object drawn with `model` (world = model @ object); none
    when the material has no subsurface body. Lengths are in scene units: metres divided by
    the scene's metres_per_unit (data/subsurface.toml), scaled with the model matrix."""
    body = subsurface_of(material)
    if body is None:
        return {}
    centre, radius = bounding_sphere(mesh)
    model = np.asarray(model, np.float64)
    scale = abs(float(np.linalg.det(model[:3, :3]))) ** (1.0 / 3.0) or 1.0
    per_unit = float(settings()["scene"]["metres_per_unit"])
    wrap = settings()["wrap"]
    reflect, through, ballistic = wall_optics(body) if body.thin else (body_albedo(body), np.zeros(3), np.zeros(3))
    return {
        "pv_sss_albedo": reflect,
        "pv_sss_wall_through": through,
        "pv_sss_wall_ballistic": ballistic ** (2 if mesh.closed else 1),  # a closed shell: in and out
        "pv_sss_mfp": np.maximum(np.asarray(body.radius) / per_unit * scale, 1e-6),
        "pv_sss_thin": int(body.thin),
        "pv_sss_centre": model[:3, :3] @ centre + model[:3, 3],
        "pv_sss_radius": radius * scale,
        "pv_sss_f0": schlick_f0(body.ior),
        "pv_sss_wrap_gain": float(wrap["gain"]),
        "pv_sss_wrap_max": float(wrap["max"]),
    }
