"""The Cook–Torrance model of Löw et al. 2012's MERL fits, as the BSDF benchmark bbm defines it.

J. Löw, J. Kronander, A. Ynnerman, J. Unger, "BRDF models for accurate and efficient rendering of
glossy surfaces", ACM TOG 31(1), 2012; fits collected in ../shared/data/merl_fits/
low_cooktorrance_E2.fit, each line `Aggregate(Lambertian(albedo = kd), LowCookTorrance(albedo = ks,
roughness = m, eta = η))`. Model definitions read from bbm (bsdfbenchmark/bbm):
include/bsdfmodel/low.h (LowCookTorrance = cooktorrance), cooktorrance.h, microfacet.h,
include/ndf/beckmann.h (un-normalised: no 1/π), include/maskingshadowing/vgroove.h,
include/bbm/fresnel_cook.h, include/bsdfmodel/lambertian.h. Local frame: normal +z.

    f(wo, wi) = kd / π  +  ks · D(h) G(wi, wo, h) F(c) / (π cos θi cos θo)
    D(h)      = exp(−tan² θh / m²) / (m² cos⁴ θh)              (Beckmann, without its 1/π)
    G         = min(1, 2 cos θh cos θi / (wi·h), 2 cos θh cos θo / (wo·h))   (V-groove)
    F(c)      = ½ a² (1 + b²),  g = √(η² + c² − 1),  a = (g − c)/(g + c),
                b = (c (g + c) − 1)/(c (g − c) + 1),  c = ½ (wi·h + wo·h)  (Cook's Fresnel)

The π in the specular denominator is bbm's "Cook" normalisation (microfacet_n::Cook). kd and ks
are RGB in MERL's camera space, m the Beckmann slope RMS, η a scalar index of refraction.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np


def beckmann_unnormalised(cos_h: np.ndarray, m: float) -> np.ndarray:
    """D(h) = exp(−tan² θh / m²) / (m² cos⁴ θh) for cos θh > 0, else 0."""
    c2 = np.clip(cos_h, 0.0, 1.0) ** 2
    up = c2 > 0.0
    safe = np.where(up, c2, 1.0)
    tan2 = (1.0 - safe) / safe
    return np.where(up, np.exp(-tan2 / (m * m)) / (m * m * safe * safe), 0.0)


def vgroove(cos_h: np.ndarray, cos_i: np.ndarray, cos_o: np.ndarray, ih: np.ndarray, oh: np.ndarray) -> np.ndarray:
    """Torrance–Sparrow V-groove masking-shadowing; 0 where wi·h or wo·h is not positive."""
    ok = (ih > 0.0) & (oh > 0.0)
    gi = 2.0 * cos_h * cos_i / np.where(ok, ih, 1.0)
    go = 2.0 * cos_h * cos_o / np.where(ok, oh, 1.0)
    return np.where(ok, np.minimum(1.0, np.minimum(gi, go)), 0.0)


def fresnel_cook(c: np.ndarray, eta: float) -> np.ndarray:
    """Cook and Torrance's unpolarised dielectric Fresnel reflectance at cos = c (c ≥ 0)."""
    c = np.clip(c, 0.0, 1.0)
    g = np.sqrt(np.maximum(eta * eta + c * c - 1.0, 0.0))
    a = (g - c) / np.maximum(g + c, 1e-12)
    b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
    return np.maximum(0.5 * a * a * (1.0 + b * b), 0.0)


@dataclass(frozen=True)
class LowCookTorrance:
    """One material's fit: Lambertian kd plus the specular lobe (ks, m, η)."""

    diffuse: tuple[float, float, float]
    specular: tuple[float, float, float]
    roughness: float
    eta: float

    @classmethod
    def from_fit(cls, record: Mapping[str, Any]) -> LowCookTorrance:
        """From a parsed .fit line (keys diffuse, albedo, roughness, eta; see parse_low_fits)."""
        kd, ks = record["diffuse"], record["albedo"]
        return cls((kd[0], kd[1], kd[2]), (ks[0], ks[1], ks[2]), float(record["roughness"]), float(record["eta"]))

    def evaluate(self, wo: Any, wi: Any) -> np.ndarray:
        """f(wo, wi), RGB (..., 3), not multiplied by cos θi; 0 when either is below the horizon."""
        wo, wi = np.asarray(wo, np.float64), np.asarray(wi, np.float64)
        cos_o, cos_i = wo[..., 2], wi[..., 2]
        above = (cos_o > 0.0) & (cos_i > 0.0)
        h = wo + wi
        h = h / np.maximum(np.linalg.norm(h, axis=-1, keepdims=True), 1e-12)
        ih, oh = np.sum(wi * h, axis=-1), np.sum(wo * h, axis=-1)
        d = beckmann_unnormalised(h[..., 2], self.roughness)
        g = vgroove(h[..., 2], cos_i, cos_o, ih, oh)
        f = fresnel_cook(0.5 * (ih + oh), self.eta)
        denom = np.where(above, cos_i * cos_o, 1.0)
        spec = np.where(above, d * g * f / (np.pi * denom), 0.0)
        diffuse = np.where(above, 1.0 / np.pi, 0.0)
        return diffuse[..., None] * np.asarray(self.diffuse) + spec[..., None] * np.asarray(self.specular)


_LINE = re.compile(
    r"^([\w.-]+) = Aggregate\(Lambertian\(albedo = \[([^\]]*)\]\), LowCookTorrance\("
    r"albedo = \[([^\]]*)\], roughness = ([-\d.eE+]+), eta = ([-\d.eE+]+)\)\)\s*$"
)


def parse_low_fits(path: Path) -> dict[str, LowCookTorrance]:
    """low_cooktorrance_E2.fit -> MERL name -> its fitted model (comment lines skipped)."""
    out: dict[str, LowCookTorrance] = {}
    for line in path.read_text("utf-8").splitlines():
        m = _LINE.match(line.strip())
        if m:
            name, kd, ks, rough, eta = m.groups()
            rec = {"diffuse": [float(v) for v in kd.split(",")], "albedo": [float(v) for v in ks.split(",")]}
            out[name] = LowCookTorrance.from_fit(rec | {"roughness": rough, "eta": eta})
    return out


__all__ = ["parse_low_fits", "LowCookTorrance", "beckmann_unnormalised", "fresnel_cook", "vgroove"]
