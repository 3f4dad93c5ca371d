"""Mitsuba 3 `principled`'s diffuse and sheen energy, for a fabric's sheen (issue #15 item 6).

principled is Disney's BRDF (Burley 2012, "Physically-Based Shading at Disney", and Mitsuba 3's
plugin documentation): its lobes are added, not layered. Per unit colour,

    diffuse  f_d = 1/pi [(1 - Fi/2)(1 - Fo/2) + Rr (Fo + Fi + Fo Fi (Rr - 1))],  Rr = 2 r cos^2 theta_d
    sheen    f_s = sheen * c_tint * F_d,                  F_x = (1 - cos theta_x)^5 (Schlick's weight)

with theta_d the angle between the light and the half vector, r principled's roughness and c_tint
the base colour over its luminance (sheen_tint 1). A white base at r = 1 returns 1.04 at normal view
and 1.38 at mu = 0.1: more than it receives, where the IR's sheen takes the fibres' share from the
base (docs/bsdf.md "Sheen"). `sheen_base` picks the base colour and sheen weight whose hemispherical
energy (what a sphere under a white sky averages to) is the IR's, per channel.
"""

from __future__ import annotations

import functools

import numpy as np

from cnlmc.material import Material

from .conversions import hemispherical_albedo, with_base_color, without_extras

#: Mitsuba's luminance weights (mi.luminance: linear sRGB / Rec. 709), for principled's c_tint
LUMINANCE = np.array([0.212671, 0.715160, 0.072169])
QUADRATURE_MUS, QUADRATURE_PHIS = 48, 96  # Gauss-Legendre in mu (both directions), uniform in phi


def schlick_weight(cos: np.ndarray) -> np.ndarray:
    return np.clip(1.0 - cos, 0.0, 1.0) ** 5


@functools.lru_cache(maxsize=64)
def lobe_albedos(roughness: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(mu, the Gauss-Legendre weights of 2 int . mu dmu, the diffuse lobe's directional albedo A(mu)
    per unit colour, the sheen lobe's per unit sheen): principled's lobes under a white sky."""
    x, w = np.polynomial.legendre.leggauss(QUADRATURE_MUS)
    mu, weight = 0.5 * (x + 1.0), 0.5 * w
    phi = (np.arange(QUADRATURE_PHIS) + 0.5) * (2.0 * np.pi / QUADRATURE_PHIS)
    mo, mi, ph = np.meshgrid(mu, mu, phi, indexing="ij")
    cos_oi = mo * mi + np.sqrt((1 - mo**2) * (1 - mi**2)) * np.cos(ph)
    cos_d = np.sqrt(np.clip((1.0 + cos_oi) / 2.0, 0.0, 1.0))  # light . half vector
    fo, fi = schlick_weight(mo), schlick_weight(mi)
    rr = 2.0 * roughness * cos_d**2
    diffuse = ((1 - fi / 2) * (1 - fo / 2) + rr * (fo + fi + fo * fi * (rr - 1))) / np.pi
    sheen = schlick_weight(cos_d)
    measure = (weight * mi[0, :, 0])[None, :, None] * (2.0 * np.pi / QUADRATURE_PHIS)  # mu_i dmu_i dphi
    return mu, 2.0 * weight * mu, np.sum(diffuse * measure, axis=(1, 2)), np.sum(sheen * measure, axis=(1, 2))


def lobe_energies(roughness: float) -> tuple[float, float]:
    """(diffuse, sheen) hemispherical energy 2 int A(mu) mu dmu per unit colour and unit sheen."""
    _mu, weight, diffuse, sheen = lobe_albedos(float(roughness))
    return float(weight @ diffuse), float(weight @ sheen)


def chromaticity(colour: np.ndarray) -> np.ndarray:
    """principled's c_tint: the colour over its luminance (white where it is black)."""
    lum = float(LUMINANCE @ colour)
    return colour / lum if lum > 1e-6 else np.ones(3)


def split(left: np.ndarray, weight: float, roughness: float) -> tuple[np.ndarray, np.ndarray, float]:
    """(base colour, c_tint, the largest directional albedo over mu and the channels) of the principled
    whose diffuse and sheen (of `weight`) lobes return `left`, per channel: c_tint follows the base,
    so base = c L with c = left / lum(left) and L D + weight S = lum(left) (D, S the lobes' energies):
    then base D + weight c S = c lum(left) = left exactly."""
    _mu, _w, diffuse, sheen = lobe_albedos(roughness)
    d_energy, s_energy = lobe_energies(roughness)
    tint = chromaticity(left)
    base = np.clip(tint * max(float(LUMINANCE @ left) - weight * s_energy, 0.0) / d_energy, 0.0, 1.0)
    peak = float(np.max(base[None, :] * diffuse[:, None] + weight * tint[None, :] * sheen[:, None]))
    return base, tint, peak


#: principled's roughness for a fabric (no specular lobe: it shapes only Disney's retro-reflection), the
#: first of these whose diffuse lobe keeps every view at or under 1 (a white felt's base at 1 gives 1.11)
FABRIC_ROUGHNESSES = (1.0, 0.75, 0.5, 0.25, 0.0)


def fabric_roughness(material: Material) -> float:
    """principled's roughness for a fabric (a diffuse base with a sheen): see FABRIC_ROUGHNESSES."""
    for roughness in FABRIC_ROUGHNESSES:
        if split(energy_left(material), 0.0, roughness)[2] <= 1.0:
            return roughness
    return FABRIC_ROUGHNESSES[-1]


def energy_left(material: Material) -> np.ndarray:
    """What the IR returns beyond its specular lobes, per channel (hemispherical): the diffuse and sheen
    lobes' share (principled's specular lobe taken as the IR's: both GGX of the same alpha and IOR)."""
    total = np.asarray(hemispherical_albedo(material, full=True))
    specular = np.asarray(hemispherical_albedo(with_base_color(without_extras(material), 0.0)))
    return np.maximum(total - specular, 0.0)


#: principled's largest sheen weight: Burley's parameter is 0-1. Past 1 the energy can still be kept
#: under 1 (`split`), but the grazing response is several times Disney's and a consumer that clamps
#: the parameter to its range changes the material's energy.
SHEEN_MAX = 1.0


def sheen_weight(material: Material, roughness: float) -> float:
    """principled's sheen weight before the peak check: the one whose lobe has the IR's sheen lobe's
    energy (luminance; c_tint has luminance 1), at most the energy left to the two lobes and at most
    SHEEN_MAX. A Disney sheen of weight 1 returns ~1 % of the light where the IR's fibres return up to
    ~11 %, so a fabric's sheen is mostly capped: the base colour carries the rest (`split`), which
    keeps the hemispherical energy and moves the capped share from the rim to the whole sphere."""
    _d_energy, s_energy = lobe_energies(float(roughness))
    left = energy_left(material)
    fibres = np.asarray(hemispherical_albedo(with_base_color(material, 0.0), full=True))  # the sheen lobe
    return min(float(LUMINANCE @ fibres) / s_energy, float(LUMINANCE @ left) / s_energy, SHEEN_MAX)


def sheen_base(material: Material, roughness: float) -> tuple[list[float], float]:
    """(principled's base_color, sheen) for the IR's sheened material, given principled's roughness:
    the sheen weight of `sheen_weight`, lowered until no view returns more than 1 (Disney's sheen
    rises towards grazing far faster than the Charlie lobe); the base colour takes the rest of the
    energy left to the two lobes (`energy_left`, `split`)."""
    roughness = float(roughness)
    left = energy_left(material)
    weight = sheen_weight(material, roughness)
    if split(left, weight, roughness)[2] > 1.0:
        low, high = 0.0, weight
        for _ in range(30):  # the largest weight whose peak is <= 1 (the peak rises with the weight)
            middle = (low + high) / 2
            low, high = (middle, high) if split(left, middle, roughness)[2] <= 1.0 else (low, middle)
        weight = low
    return [float(v) for v in split(left, weight, roughness)[0]], float(weight)
