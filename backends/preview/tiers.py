"""Quality tiers of the preview renderer (docs/preview.md), and picking one by frame budget.

A tier is how the environment light is integrated; the key light is always evaluated exactly
with cnlm_bsdf. Every tier combines with the GLSL backend's options (fresnel=exact|f82|schlick,
multiscatter=on|off), which change the BSDF the tier integrates.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

#: What each kind of tier does for a glass's transmission (shaders/transmission.glsl.j2,
#: docs/preview.md "Transparent materials"); the key light is transmitted only through rough exits
#: in the prefiltered tiers (through smooth glass a directional light is a delta: no caustics,
#: no shadows; a sampled exit never meets it).
TRANSMISSION = {
    "ambient": "as splitsum: the refracted path, one prefiltered lookup (the constant ambient is "
    "the reflection's only)",
    "splitsum": "the view refracted in and out along the macro normals (solid: the bounding sphere "
    "as the exit, two exits with internal and total internal reflection; thin: undeflected), "
    "exact Fresnel at each interface, Beer-Lambert tint; a rough solid: two lobes from a table traced "
    "through a rough ball (glass_paths.py), what leaves at the first exit and what stays inside and "
    "leaves later (total internal reflection on tilted facets), each looked up around its mean "
    "direction at its spread, the key light through each as a von Mises-Fisher lobe; a rough sheet: "
    "one lookup at the transmitted lobe's width (fitted to mc256); the light the entry's facets block "
    "(1 - G1) leaving diffusely",
    "sampled": "per sample a GGX visible-normal facet at the entry and at every exit (rough "
    "transmission sampled, not prefiltered), the same paths, Fresnel and tint, the blocked light "
    "leaving diffusely; no key light through the glass; fis: the environment's mip level from the "
    "lobe's solid angle per sample",
}


@dataclass(frozen=True)
class Tier:
    name: str
    ibl: str  # "ambient" | "splitsum" | "sampled"
    samples: int = 0
    filtered: bool = False
    doc: str = ""

    @property
    def transmission(self) -> str:
        """What this tier does for a glass's transmission."""
        return TRANSMISSION[self.ibl]


TIERS = {
    "analytic": Tier(
        "analytic", "ambient", doc="key light + constant ambient (mean environment radiance x pi f(v, n))"
    ),
    "splitsum": Tier(
        "splitsum",
        "splitsum",
        doc="key light + environment prefiltered at the lobe's alpha x the "
        "material's own directional albedo (split sum, Karis 2013, specialized per material) + "
        "cosine-prefiltered irradiance x the diffuse directional albedo",
    ),
    "fis16": Tier(
        "fis16",
        "sampled",
        16,
        True,
        "key light + 16 BSDF samples per pixel, MIS, environment mip "
        "level from the pdf (filtered importance sampling, Krivanek & Colbert 2008)",
    ),
    "fis64": Tier("fis64", "sampled", 64, True, "as fis16 with 64 samples"),
    "mc16": Tier(
        "mc16",
        "sampled",
        16,
        False,
        "key light + 16-sample Monte Carlo IBL per pixel (MIS of cosine and "
        "GGX visible normals), per-pixel rotated Hammersley, unfiltered: unbiased, noisy",
    ),
    "mc64": Tier("mc64", "sampled", 64, False, "as mc16 with 64 samples"),
    "mc256": Tier("mc256", "sampled", 256, False, "as mc16 with 256 samples"),
    "mc1024": Tier("mc1024", "sampled", 1024, False, "as mc16 with 1024 samples (reference-like)"),
}
#: Worst to best image quality (by the error against Mitsuba, bench/preview_chart.py).
QUALITY_ORDER = ("analytic", "splitsum", "mc16", "fis16", "mc64", "fis64", "mc256", "mc1024")
DEFAULT_TIER = "splitsum"  # lowest mean FLIP per ms in bench/preview_chart.py (docs/preview.md)
_GENERIC = re.compile(r"^(mc|fis)(\d+)$")


class TierError(ValueError):
    """An unknown tier name."""


def parse_tier(name: str) -> Tier:
    """A tier from the table, or any `mc<N>` / `fis<N>` (N = 1 ... 65536)."""
    name = str(name).strip().lower()
    if name in TIERS:
        return TIERS[name]
    match = _GENERIC.match(name)
    if match and 1 <= int(match.group(2)) <= 65536:
        kind, n = match.group(1), int(match.group(2))
        return Tier(name, "sampled", n, kind == "fis", f"{TIERS[kind + '16'].doc.split(',')[0]} with {n} samples")
    raise TierError(f"unknown preview tier {name!r}: use one of {', '.join(TIERS)} or mc<N> / fis<N>")


def select_tier(
    budget_ms: float, measure: Callable[[Tier], float], candidates=QUALITY_ORDER
) -> tuple[Tier, dict[str, float]]:
    """The best-quality tier whose measured frame time (ms) fits the budget.

    Tiers are measured in quality order (which is also, roughly, cost order) and measuring
    stops at the first tier after the cheapest that does not fit. When nothing fits, the
    cheapest tier is returned. Returns (tier, {name: ms measured})."""
    timings: dict[str, float] = {}
    best = parse_tier(candidates[0])
    for name in candidates:
        tier = parse_tier(name)
        ms = measure(tier)
        timings[name] = ms
        if ms <= budget_ms:
            best = tier
        elif name != candidates[0]:
            break
    return best, timings
