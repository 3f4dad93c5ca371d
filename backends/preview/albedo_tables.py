"""Per-material directional albedo tables for the split-sum tier (docs/preview.md).

The split-sum approximation (Karis 2013) multiplies the prefiltered environment by the
directional albedo of the lobe. A generic (F0 A + B) LUT stands in for that albedo with
Schlick's Fresnel; here it is integrated from the material's own BSDF instead (the numpy
reference, with the shader's Fresnel mode and multiscatter switch), so exact conductor
Fresnel, F82 tints, Oren–Nayar and the dielectric's (1 − F)(1 − F) diffuse weighting are
what the tier shows:

    black(μ) = ∫ f(wo, wi; ρ = 0) cos θi dωi                 (dielectric lobe, coat)
    tint(μ)  = ∫ f(wo, wi; ρ = 1) cos θi dωi − black(μ)      (diffuse, or the conductor lobe)
f is affine in the base colour ρ, so f(ρ) = black + ρ · tint exactly.

One row when α is uniform; ROWS rows over sqrt(α) when a roughness map varies it.
"""
from __future__ import annotations

import hashlib
import json
from functools import lru_cache
from pathlib import Path

import numpy as np

import cnlmc.bsdf

BSDF_SOURCES = Path(cnlmc.bsdf.__file__).parent
MU_SIZE = 32
ROWS = 8
SAMPLES = 512


def _variant(material: dict, colour, alpha=None) -> dict:
    params = {**material["params"], "base_color": list(colour)}
    if alpha is not None:
        params["alpha"] = list(alpha)
    return {**material, "params": params}


def _row_alphas(material: dict, mapped: bool) -> list:
    """(αx, αy) per row: the material's own, or sqrt(α) at texel centres with its anisotropy."""
    from cnlmc.bsdf.alpha import anisotropy_stretch
    from cnlmc.bsdf.evaluate import material_alpha
    if not mapped:
        return [tuple(float(a) for a in material_alpha(material))]
    params = material["params"]
    aniso = float(params.get("anisotropy") or 0.0) if material["model"].get("anisotropic") else 0.0
    s = float(anisotropy_stretch(aniso))
    rows = (((np.arange(ROWS) + 0.5) / ROWS) ** 2)
    return [(min(max(a / s, 1e-3), 1.0), min(max(a * s, 1e-3), 1.0)) for a in rows]


def _directional(material: dict, options: dict, moment: bool = False) -> np.ndarray:
    """(MU_SIZE, 3) directional albedo at the texel centres of cos θo (azimuth-averaged when
    anisotropic); with `moment`, (MU_SIZE, 2) mean-over-RGB first moments of the lobe instead:
    its component towards the viewer (in the tangent plane) and along the normal."""
    from cnlmc.bsdf.evaluate import albedo
    mus = (np.arange(MU_SIZE) + 0.5) / MU_SIZE
    phis = (0.0, np.pi / 4, np.pi / 2) if material["model"].get("anisotropic") else (0.0,)

    def one(phi):                                  # every mu at once (a batch of directions)
        if not moment:
            return albedo(material, mus, SAMPLES, phi, **options)
        toward = lambda wi: wi[..., 0] * np.cos(phi) + wi[..., 1] * np.sin(phi)  # noqa: E731
        along = lambda wi: wi[..., 2]  # noqa: E731
        return np.stack([albedo(material, mus, SAMPLES, phi, weight, **options).mean(-1)
                         for weight in (toward, along)], -1)
    return np.mean([one(phi) for phi in phis], 0)


def _lean(toward: np.ndarray, along: np.ndarray) -> np.ndarray:
    """Where a lobe's first moment points, as a fraction of the view angle θv measured from the
    normal towards the mirror direction: 1 = the mirror direction, 0 = the normal, < 0 leaning
    towards the viewer (back-scattering). Smooth in μ, unlike the angle itself near μ = 1."""
    theta_v = np.arccos((np.arange(MU_SIZE) + 0.5) / MU_SIZE)
    return -np.arctan2(toward, np.maximum(along, 1e-12)) / theta_v


def _leans(material: dict, alpha, options: dict) -> tuple[np.ndarray, np.ndarray]:
    """(MU_SIZE,) lean of the black lobe and of the tint lobe (tint = white − black)."""
    white = _directional(_variant(material, (1, 1, 1), alpha), options, moment=True)
    black = _directional(_variant(material, (0, 0, 0), alpha), options, moment=True)
    tint = white - black
    return _lean(black[:, 0], black[:, 1]), _lean(tint[:, 0], tint[:, 1])


@lru_cache(maxsize=64)
def _tables(material_json: str, fresnel: str, multiscatter: bool, mapped: bool) -> tuple:
    """Memoized here and on disk (cnlmc.cache, keyed by the inputs and by the source files of
    the BSDF code): a mapped material's 8 rows take a few seconds to integrate."""
    from cnlmc.cache import cached
    inputs = json.dumps([material_json, fresnel, multiscatter, mapped, MU_SIZE, ROWS, SAMPLES])
    kind = "albedo-tables-" + hashlib.sha256(inputs.encode()).hexdigest()[:20]
    sources = [Path(__file__)] + sorted(BSDF_SOURCES.glob("*.py"))
    return cached(kind, sources, lambda: _integrate(material_json, fresnel, multiscatter, mapped))


def _integrate(material_json: str, fresnel: str, multiscatter: bool, mapped: bool) -> tuple:
    material = json.loads(material_json)
    options = {"fresnel": fresnel, "multiscatter": multiscatter}
    black_rows, tint_rows = [], []
    for alpha in _row_alphas(material, mapped):
        black = _directional(_variant(material, (0, 0, 0), alpha), options)
        white = _directional(_variant(material, (1, 1, 1), alpha), options)
        black_lean, tint_lean = _leans(material, alpha, options)
        black_rows.append(np.concatenate([black, black_lean[:, None]], 1))
        tint_rows.append(np.concatenate([white - black, tint_lean[:, None]], 1))
    return np.array(black_rows, np.float32), np.array(tint_rows, np.float32)


def albedo_tables(material: dict, fresnel: str = "exact", multiscatter: bool = False,
                  mapped_roughness: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """(black, tint) tables, each (rows, MU_SIZE, 4) float32: row = sqrt(α) texel of the base
    lobe, column = cos θo texel; RGB = directional albedo, A = the lobe's lean (`_lean`): the
    direction the split-sum tier looks the environment up in. Cached (memory and disk)."""
    key = json.dumps({"model": material["model"], "params": material["params"]}, sort_keys=True, default=float)
    return _tables(key, fresnel, bool(multiscatter), bool(mapped_roughness))
