"""What the preview draws of each IR feature, and how its tiers approximate it (docs/preview.md).

This is the preview's own table: `cnlmc preview` checks a material against it (shader.py), never
against the GLSL export's, whose notes are about a file the preview does not write. The tiers
(tiers.py) differ only in how the environment light is integrated; where that changes what a
feature looks like, the reason says so per tier (analytic | splitsum | fis/mc)."""

from __future__ import annotations

NAME = "preview"
_BAKED = "procedural map baked with cnlmc.backends.maps and bound as a texture"
CAPABILITIES: dict[str, tuple[str, str]] = {
    "model.diffuse": ("exact", ""),
    "model.dielectric": ("exact", ""),
    "model.conductor": ("exact", ""),
    "model.glass": (
        "approximate",
        "the environment refracted through the object (a solid's second interface is its bounding "
        "sphere: exact for the sphere mesh; glass=thin: a sheet), Beer-Lambert absorption along "
        "the path inside (the colour through transmission_depth), rough transmission prefiltered or sampled by tier (the light the facets block leaves "
        "diffusely, not lost); the key light only through rough exits in splitsum/analytic (no "
        "caustics, no shadows); docs/preview.md 'Transparent materials'",
    ),
    "distribution.ggx": ("exact", ""),
    "distribution.ward": ("exact", ""),
    "anisotropic": ("exact", "exact in the key light and the mc/fis tiers; split-sum uses sqrt(ax ay)"),
    "diffuse.oren_nayar": ("exact", "exact in the key light and the mc/fis tiers; split-sum uses Lambert"),
    "coat": ("exact", ""),
    "coat.color": ("exact", ""),
    "sheen": (
        "approximate",
        "every tier: the Charlie lobe exact for the key light; the environment's sheen from 32 fixed "
        "cosine directions in the environment blurred to mip 5; the base scaled by 1 - s E(mu_o) "
        "(the reference scales by the larger of both directions' E)",
    ),
    "flakes": (
        "approximate",
        "the flakes' mean lobe is in cnlm_bsdf: exact for the key light; fis/mc: the environment "
        "sampled through it; splitsum: the flakes' energy is in the material's albedo tables; under a "
        "coat their share is looked up at their own width (seen through the coat), uncoated at the "
        "base lobe's (sharper than the flakes' spread); "
        "analytic: constant ambient. Sparkle, in every tier and for the key light only: per pixel, how "
        "many of the flakes its footprint holds at their real size face the half vector (a Poisson "
        "count with the mean lobe as its mean, capped at 64x)",
    ),
    "subsurface.volume": ("approximate", "the preview's subsurface body shader (docs/preview.md 'Subsurface')"),
    "subsurface.thin": ("approximate", "the preview's thin-wall shader (docs/preview.md 'Subsurface')"),
    "maps.base_color": ("bake", _BAKED),
    "maps.normal": ("bake", _BAKED),
    "maps.roughness": ("bake", _BAKED),
    "maps.mask": ("bake", _BAKED),
    "maps.metallic": ("drop", "no IR model reads a metallic map"),
}
