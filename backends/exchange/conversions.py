"""IR parameters -> what exchange shaders take: conductor colours and roughness fits.

- conductor colours: OpenPBR's F82 tint and Standard Surface's edge colour from the IR's f0/f82/eta.
- roughness: the IR's microfacet widths (alpha) -> perceptual roughness and anisotropy per shader.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import replace
from typing import Any

from cnlmc.material import RGB, Material, Params

MU_82 = 1.0 / 7.0  # cos 82 degrees, rounded as OpenPBR does: the F82 angle
DIGITS = 6  # values are rounded so documents are stable (golden files)


def clip01(values: Iterable[float]) -> list[float]:
    return [min(max(float(v), 0.0), 1.0) for v in values]


def rounded(values: Iterable[float]) -> list[float]:
    return [round(float(v), DIGITS) for v in values]


# --------------------------------------------------------------------------- conductors


def schlick(f0: float, mu: float) -> float:
    return f0 + (1.0 - f0) * (1.0 - mu) ** 5


def measured(values: RGB | None, name: str) -> RGB:
    """A conductor's measured optics (f0, f82, eta, k): the IR gives them for every conductor."""
    if values is None:
        raise ValueError(f"a conductor without {name} in the IR")
    return values


def conductor_weight(params: Params) -> float:
    """The metal lobe's weight (OpenPBR base_weight, Standard Surface base): the IR tint's brightest
    channel. The IR tints the whole Fresnel curve (grazing included), a Schlick/F82 metal always
    rises to 1 at grazing: the weight keeps a dark tint's rim dark (issue #15: 'blue anodized
    aluminum' had a white rim), the colour is the tint over that weight."""
    return min(max(max(float(t) for t in params.base_color), 0.0), 1.0)


def _tinted(values: RGB, params: Params) -> list[float]:
    weight = conductor_weight(params)
    scale = 1.0 / weight if weight > 0.0 else 0.0
    return [f * (t * scale if weight > 0.0 else 1.0) for f, t in zip(values, params.base_color)]


def conductor_f0(params: Params) -> list[float]:
    """The measured normal-incidence reflectance times the IR tint, clipped to [0, 1]."""
    return clip01(f * t for f, t in zip(measured(params.f0, "f0"), params.base_color))


def weighted_f0(params: Params) -> list[float]:
    """The F0 a weighted metal lobe takes: the tinted F0 over `conductor_weight`, in [0, 1]."""
    return clip01(_tinted(measured(params.f0, "f0"), params))


def f82_floor(f0: float) -> float:
    """The least F82 for which the F82-tint curve stays >= 0 at every angle: F(mu) = S(mu) -
    (S(1/7) - F82) g(mu) with g(mu) = mu (1-mu)^6 / (mu82 (1-mu82)^6); F82 >= S(1/7) - S(mu)/g(mu)."""
    worst = 0.0
    for i in range(1, 200):
        mu = i / 200.0
        g = mu * (1.0 - mu) ** 6 / (MU_82 * (1.0 - MU_82) ** 6)
        worst = max(worst, schlick(f0, MU_82) - schlick(f0, mu) / g)
    return worst


def f82_tint(params: Params) -> list[float]:
    """OpenPBR's specular_color for a metal: F(82 deg) / Schlick(F0, 82 deg), clipped to [0, 1].

    OpenPBR (and MaterialX's generalized_schlick_bsdf color82) subtracts a term so that the
    reflectance at mu = 1/7 equals specular_color * Schlick(F0, 1/7); the IR stores the
    measured F82, so the tint is f82 / schlick(f0, 1/7) (both scaled by the IR tint). A tint
    below the one that keeps the curve >= 0 (a dark-tinted F0 near 0) is raised to it, else the
    curve goes negative at mid angles and MaterialX's renderer draws a bright rim (issue #15).
    """
    f0 = weighted_f0(params)
    f82 = _tinted(measured(params.f82, "f82"), params)
    return clip01(max(b, f82_floor(a)) / schlick(a, MU_82) for a, b in zip(f0, f82))


def gulbrandsen_edge(params: Params) -> list[float]:
    """Standard Surface's specular_color for a metal: the edge tint g for which Gulbrandsen's
    artistic IOR mapping (MaterialX `artistic_ior`) gives back the measured eta at F0 = r."""
    edge = []
    for r, n in zip(weighted_f0(params), measured(params.eta, "eta")):
        r = min(r, 0.999)
        n_min = (1.0 - r) / (1.0 + r)
        n_max = (1.0 + math.sqrt(r)) / (1.0 - math.sqrt(r))
        edge.append(1.0 if n_max - n_min < 1e-6 else (n_max - n) / (n_max - n_min))
    return clip01(edge)


# ------------------------------------------------------------------------- roughness


def alpha_pair(params: Params) -> tuple[float, float]:
    """(alpha_x, alpha_y) as microfacet widths (alpha is authoritative in the IR)."""
    ax, ay = params.alpha  # widths in either convention: only r differs
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


# ------------------------------------------------------------------------- energy

ALBEDO_MUS = 8  # Gauss-Legendre points in mu for the hemispherical average
ALBEDO_SAMPLES = 256  # QMC samples per direction (cnlmc.bsdf.albedo): ~1e-3 for a diffuse lobe


def hemispherical_albedo(material: Material, full: bool = False) -> list[float]:
    """2 integral A(mu) mu dmu, RGB: what a sphere under a white sky averages to; `full`: of the
    complete BRDF (flakes and sheen included, `cnlmc.bsdf.flakes.albedo_full`)."""
    import numpy as np

    from cnlmc.bsdf import albedo
    from cnlmc.bsdf.flakes import albedo_full

    x, w = np.polynomial.legendre.leggauss(ALBEDO_MUS)
    mu = 0.5 * (x + 1.0)
    integrate = albedo_full if full else albedo
    return [float(v) for v in (w * mu) @ integrate(material, mu, n_samples=ALBEDO_SAMPLES)]


def without_coat(material: Material) -> Material:
    return replace(material, model=replace(material.model, coat=False), params=replace(material.params, coat=None))


def coat_lobe_albedo(material: Material) -> list[float]:
    """The hemispherical albedo of the coat's own lobe: a black dielectric of its IOR and alpha."""
    coat = material.params.coat
    if coat is None:
        raise ValueError("a coat lobe of a material without a coat")
    model = {"base": "dielectric", "distribution": "ggx", "anisotropic": False, "coat": False, "diffuse": "lambert"}
    params = {"base_color": [0.0, 0.0, 0.0], "ior": float(coat.ior), "alpha": list(coat.alpha), "roughness": 0.0}
    return hemispherical_albedo(Material.from_ir({"name": "coat_lobe", "model": model, "params": params}))


def base_under_coat(material: Material) -> list[float]:
    """What the base keeps under the IR's coat, RGB in [0, 1]: (coated albedo - the coat lobe's) over
    the bare base's, all from the reference: for a target that adds a coat lobe over a base it can
    only weight (Mitsuba's principled), so the energy is the IR's (#15 item 6)."""
    total, lobe, bare = (
        hemispherical_albedo(material),
        coat_lobe_albedo(material),
        hemispherical_albedo(without_coat(material)),
    )
    return [min(max((t - c) / b, 0.0), 1.0) if b > 1e-6 else 0.0 for t, c, b in zip(total, lobe, bare)]


DISNEY_COAT_IOR, DISNEY_COAT_ALPHA = 1.5, 0.01  # the GTR1 clear coat: Schlick F0 0.04, a quarter weight per unit
FULL_CLEARCOAT = 4.0  # principled's clearcoat at which its coat lobe has full weight (its grazing F reaches 1)


def principled_clearcoat(material: Material) -> float:
    """principled's clearcoat giving the IR coat lobe's energy: full weight (4) times the coat lobe's
    hemispherical albedo over a smooth IOR 1.5 coat's, never above full weight (a grazing F above 1)."""
    coat = material.params.coat
    if coat is None:
        raise ValueError("a clearcoat for a material without a coat")
    smooth = replace(coat, ior=DISNEY_COAT_IOR, alpha=(DISNEY_COAT_ALPHA, DISNEY_COAT_ALPHA))
    reference = coat_lobe_albedo(replace(material, params=replace(material.params, coat=smooth)))
    ratio = sum(coat_lobe_albedo(material)) / sum(reference)
    return min(FULL_CLEARCOAT * ratio, FULL_CLEARCOAT)


# ------------------------------------------------------------------- a diffuse base's energy
#
# The IR puts a dielectric's diffuse base under its interface as (1 - F(theta_o)) (1 - F(theta_i)) rho
# (docs/bsdf.md: internal reflection neglected), so a white base keeps 1 - F_avg of the light it
# scatters; under a coat it sums the light trapped under it, rho / (eta^2 (1 - rho K))
# (cnlmc.bsdf.layered). The targets layer it otherwise (each documented below); the base colour a
# target is given is the one that gives the IR's diffuse energy, per channel: the same hemispherical
# energy, hence the same white furnace (#15). Linear targets get the IR's colour scaled by the
# ratio of the two energies; Mitsuba's coat (`roughplastic`, nonlinear) the solved `roughplastic_colour`.

MITSUBA_TABLE_MUS = 16  # Gauss-Legendre points in mu for roughplastic's transmittance average
MITSUBA_INTERNAL_MUS = 64  # roughplastic's own table size (MI_ROUGH_TRANSMITTANCE_RES)


def with_base_color(material: Material, value: float) -> Material:
    return replace(material, params=replace(material.params, base_color=(value, value, value)))


def diffuse_energy(material: Material) -> tuple[list[float], float]:
    """(the IR's hemispherical energy of its diffuse base per unit base colour, RGB; the specular
    lobes' hemispherical albedo): A(white base) - A(black base), and A(black base)."""
    white, black = (
        hemispherical_albedo(with_base_color(material, 1.0)),
        hemispherical_albedo(with_base_color(material, 0.0)),
    )
    return [w - b for w, b in zip(white, black)], float(sum(black) / 3.0)


def layered_diffuse_scale(material: Material) -> list[float]:
    """OpenPBR / Standard Surface (and MaterialX's `layer` of a `dielectric_bsdf` over a diffuse
    base) scale the base by the top lobe's directional albedo, 1 - E(mu_o): its hemispherical diffuse
    energy is 1 - E_avg (OpenPBR specification, "Dielectric base": energy-conserving albedo scaling).
    The IR's over that, per channel (for base_weight or a base colour)."""
    energy, specular = diffuse_energy(material)
    return [e / max(1.0 - specular, 1e-6) for e in energy]


def roughplastic_diffuse_energy(ior: float, alpha: float) -> float:
    """Mitsuba 3 `roughplastic`'s hemispherical diffuse energy for diffuse_reflectance 1. Its model
    (src/bsdfs/roughplastic.cpp, nonlinear = false): rho / (1 - R_int) / eta^2 * t(mu_i) t(mu_o) cos / pi,
    t the rough interface's transmittance from outside (`eval_transmittance`: visible normals, (1 - F)
    G1, separable Smith) and R_int twice the mean of its internal reflectance times mu over 64 mu in
    [0, 1] (`eval_reflectance` at 1/eta). So (2 int t mu dmu)^2 / (eta^2 (1 - R_int)); the same at
    rho = 1 with nonlinear = true (rho / (1 - rho R_int) in place of rho / (1 - R_int))."""
    through, internal = roughplastic_terms(ior, alpha)
    return through * through / (ior * ior * max(1.0 - internal, 1e-6))


def roughplastic_colour(energy: Any, ior: float, alpha: float) -> Any:
    """The diffuse_reflectance of a `roughplastic` with nonlinear = true whose hemispherical diffuse
    energy is `energy` (per channel, or an array of texels): T^2 rho / (eta^2 (1 - rho R_int)) = E
    solved for rho = E eta^2 / (T^2 + E eta^2 R_int) (`roughplastic_terms`; not clipped). This is the
    IR's own form of a diffuse base under a coat (cnlmc.bsdf.layered: rho / (eta^2 (1 - rho K))), so
    a colour map keeps its texels' energies, not only its mean's."""
    import numpy as np

    through, internal = roughplastic_terms(ior, max(alpha, 1e-3))
    e = np.maximum(np.asarray(energy, np.float64), 0.0) * ior * ior
    return e / (through * through + e * internal)


def roughplastic_terms(ior: float, alpha: float) -> tuple[float, float]:
    """(2 int t mu dmu, R_int) of Mitsuba 3's `roughplastic` (`roughplastic_diffuse_energy`)."""
    import numpy as np

    from cnlmc.bsdf.transmission import interface_albedo

    x, w = np.polynomial.legendre.leggauss(MITSUBA_TABLE_MUS)
    mu = 0.5 * (x + 1.0)
    _, transmitted = interface_albedo(mu, ior, alpha, n=1024, g2="separable")
    grid = np.maximum(np.linspace(0.0, 1.0, MITSUBA_INTERNAL_MUS), 1e-6)
    inside, _ = interface_albedo(grid, 1.0 / ior, alpha, n=1024, g2="separable")
    through = float(np.sum(w * mu * transmitted))
    internal = 2.0 * float(np.mean(inside * grid))
    return through, internal


def without_extras(material: Material) -> Material:
    """The material without flakes and sheen (what a target without those lobes draws)."""
    return replace(material, params=replace(material.params, flake_color=None, sheen_color=None))


def diffuse_colour(material: Material, target_energy: float) -> list[float]:
    """The constant base colour for a target whose diffuse base, of hemispherical energy
    `target_energy` per unit colour, sits under the IR's interface: (the IR's complete hemispherical
    albedo - its specular lobes') / target_energy, per channel. Without flakes and sheen this is the
    base colour times the energy ratio; with them, their energy goes to the base (the target has no
    such lobe: the look changes, the energy stays)."""
    total = hemispherical_albedo(material, full=True)
    specular = hemispherical_albedo(with_base_color(without_extras(material), 0.0))
    return [max(t - s, 0.0) / max(target_energy, 1e-6) for t, s in zip(total, specular)]


def roughplastic_diffuse_scale(material: Material, ior: float, alpha: float) -> list[float]:
    """What roughplastic's diffuse_reflectance is multiplied by so that its diffuse energy is the IR's
    (of `material`, whose interface has `ior` and `alpha`: the material's own, or its coat's)."""
    energy, _ = diffuse_energy(material)
    target = roughplastic_diffuse_energy(ior, max(alpha, 1e-3))
    return [e / target for e in energy]
