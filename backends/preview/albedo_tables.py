"""Per-material directional albedo tables for the split-sum tier (docs/preview.md).

The split-sum approximation (Karis 2013) multiplies the prefiltered environment by the
directional albedo of the lobe. A generic (F0 A + B) LUT stands in for that albedo with
Schlick's Fresnel; here it is integrated from the material's own BSDF instead (the numpy
reference, with the shader's Fresnel mode and multiscatter switch), so exact conductor
Fresnel, F82 tints, Oren–Nayar and the dielectric's (1 − F)(1 − F) diffuse weighting are
what the tier shows:

    black(μ) = ∫ f(wo, wi; ρ = 0) cos θi dωi                 (dielectric lobe, coat)
    tint(μ)  = ∫ f(wo, wi; ρ = 1) cos θi dωi − black(μ)      (diffuse, or the conductor lobe)
f is affine in the base colour ρ, so f(ρ) = black + ρ · tint exactly; except under a coat, where
the diffuse base's light trapped under the coat makes it ρ / (1 − ρ t) (cnlmc.bsdf.layered): there
f(ρ) = black + ρ (1 − t) / (1 − ρ t) · tint, exactly (t = ``cnlmc.bsdf.flakes.coat_trap``, the
shader's ``cnlm_coat_trap``; 0 for a metal).

The *shape* of a rough lobe changes with the view: towards grazing it leans towards the
normal, stretches in the plane of incidence, is clipped by the horizon and keeps a long tail
on the viewer's side. One environment kernel (prefiltered at α, centred where the lobe's
first moment points) misses that. So for every cos θv the lobe is also fitted with a mixture
of two prefilter kernels, each (direction in the plane of incidence, α, weight); the shader
looks the environment up twice (kernel_fit.py, split.glsl.j2).

One row when α is uniform; ROWS rows over sqrt(α) when a roughness map varies it.
"""

from __future__ import annotations

import dataclasses
import hashlib
import io
import json
from pathlib import Path

import numpy as np

import cnlmc.bsdf
from cnlmc.bsdf.alpha import anisotropy_stretch
from cnlmc.bsdf.evaluate import material_alpha
from cnlmc.bsdf.flakes import albedo_flaked as albedo  # a paint's flakes are in its tables (#15 item 5)
from cnlmc.cache import cached
from cnlmc.material import RGB, Material

from . import flake_tables, kernel_fit
from .flake_tables import coated_flakes, flake_sections
from .kernel_fit import FIT_ALPHA, kernels

BSDF_SOURCES = Path(cnlmc.bsdf.__file__).parent
MU_SIZE = 32
ROWS = 8
SAMPLES = 512
#: sections of MU_SIZE columns in a table: albedo + lean, kernel 1, kernel 2 (`albedo_tables`)
SECTIONS = 3


def _variant(material: Material, colour: RGB, alpha: tuple[float, float]) -> Material:
    """The material with another base colour and α (a table row of it)."""
    return dataclasses.replace(material, params=dataclasses.replace(material.params, base_color=colour, alpha=alpha))


def _row_alphas(material: Material, mapped: bool) -> list[tuple[float, float]]:
    """(αx, αy) per row: the material's own, or sqrt(α) at texel centres with its anisotropy."""
    if not mapped:
        ax, ay = material_alpha(material)
        return [(float(ax), float(ay))]
    aniso = float(material.params.anisotropy) if material.model.anisotropic else 0.0
    s = float(anisotropy_stretch(aniso))
    rows = ((np.arange(ROWS) + 0.5) / ROWS) ** 2
    return [(min(max(a / s, 1e-3), 1.0), min(max(a * s, 1e-3), 1.0)) for a in rows]


def _mus() -> np.ndarray:
    return (np.arange(MU_SIZE) + 0.5) / MU_SIZE


def _directional(material: Material, options: dict, moment: bool = False) -> np.ndarray:
    """(MU_SIZE, 3) directional albedo at the texel centres of cos θo (azimuth-averaged when
    anisotropic); with `moment`, (MU_SIZE, 2) mean-over-RGB first moments of the lobe instead:
    its component towards the viewer (in the tangent plane) and along the normal."""
    mus = _mus()
    phis = (0.0, np.pi / 4, np.pi / 2) if material.model.anisotropic else (0.0,)

    def one(phi):  # every mu at once (a batch of directions)
        if not moment:
            return albedo(material, mus, SAMPLES, phi, **options)
        toward = lambda wi: wi[..., 0] * np.cos(phi) + wi[..., 1] * np.sin(phi)
        along = lambda wi: wi[..., 2]
        return np.stack(
            [albedo(material, mus, SAMPLES, phi, weight, **options).mean(-1) for weight in (toward, along)], -1
        )

    return np.mean([one(phi) for phi in phis], 0)


def _lean(toward: np.ndarray, along: np.ndarray) -> np.ndarray:
    """Where a lobe's first moment points, as a fraction of the view angle θv measured from the
    normal towards the mirror direction: 1 = the mirror direction, 0 = the normal, < 0 leaning
    towards the viewer (back-scattering). Smooth in μ, unlike the angle itself near μ = 1."""
    theta_v = np.arccos(_mus())
    return -np.arctan2(toward, np.maximum(along, 1e-12)) / theta_v


def _leans(black_material: Material, white_material: Material, options: dict) -> tuple[np.ndarray, np.ndarray]:
    """(MU_SIZE,) lean of the black lobe and of the tint lobe (tint = white − black)."""
    white = _directional(white_material, options, moment=True)
    black = _directional(black_material, options, moment=True)
    tint = white - black
    return _lean(black[:, 0], black[:, 1]), _lean(tint[:, 0], tint[:, 1])


def split_fitted(material: Material, mapped_roughness: bool = False) -> bool:
    """Whether the material's tables hold a fitted kernel pair (for the shader: two environment
    lookups for its specular lobe, or one). Mapped roughness: its rougher rows are fitted."""
    if not any(_fitted_lobes(material)):
        return False
    return bool(mapped_roughness) or float(np.sqrt(np.prod(material_alpha(material)))) >= FIT_ALPHA


def _fitted_lobes(material: Material) -> tuple[bool, bool]:
    """(black, tint): which lobe is one isotropic microfacet reflection (fitted): the
    dielectric's specular lobe (black) or the conductor's (tint); none under a coat."""
    model = material.model
    simple = model.base in ("dielectric", "conductor", "glass") and not model.coat and not model.anisotropic
    return simple and model.base != "conductor", simple and model.base == "conductor"


Tables = tuple[np.ndarray, np.ndarray]


def _tables(material: Material, fresnel: str, multiscatter: bool, mapped: bool) -> Tables:
    """Stored on disk (cnlmc.cache, keyed by the inputs and by the source files of the BSDF code
    and of this module): a mapped material's 8 rows take a few seconds."""
    inputs = json.dumps([_table_key(material), fresnel, multiscatter, mapped, MU_SIZE, ROWS, SAMPLES, SECTIONS])
    kind = "albedo-tables-" + hashlib.sha256(inputs.encode()).hexdigest()[:20]
    sources = [Path(__file__), Path(kernel_fit.__file__), Path(flake_tables.__file__)] + sorted(
        BSDF_SOURCES.glob("*.py")
    )
    tables: Tables = cached(
        kind, sources, lambda: _integrate(material, fresnel, multiscatter, mapped), _dump_tables, _load_tables
    )
    return tables


def _dump_tables(tables: Tables) -> bytes:
    """The two tables as .npy arrays, one after the other (plain numbers; never pickled)."""
    buffer = io.BytesIO()
    for table in tables:
        np.save(buffer, table, allow_pickle=False)
    return buffer.getvalue()


def _load_tables(payload: bytes) -> Tables:
    buffer = io.BytesIO(payload)
    try:
        return np.load(buffer, allow_pickle=False), np.load(buffer, allow_pickle=False)
    except (EOFError, OSError) as exc:
        raise ValueError(f"not two .npy arrays: {exc}") from None


def _integrate(material: Material, fresnel: str, multiscatter: bool, mapped: bool) -> Tables:
    options = {"fresnel": fresnel, "multiscatter": multiscatter}
    fit_black, fit_tint = _fitted_lobes(material)
    black_rows, tint_rows = [], []
    for alpha in _row_alphas(material, mapped):
        black_material = _variant(material, (0.0, 0.0, 0.0), alpha)
        white_material = _variant(material, (1.0, 1.0, 1.0), alpha)
        black = _directional(black_material, options)
        white = _directional(white_material, options)
        black_lean, tint_lean = _leans(black_material, white_material, options)
        black_kernels = (
            flake_sections(black_material, _mus(), SAMPLES, _lean)
            if coated_flakes(material)  # a coat's lobes are never fitted: its kernel sections hold the flakes
            else kernels(black_material, alpha, options, black_lean, fit_black, _mus())
        )
        black_rows.append(np.concatenate([np.concatenate([black, black_lean[:, None]], 1), black_kernels]))
        # the tint lobe is fitted only for conductors, whose black part is zero (white = tint)
        tint_rows.append(
            np.concatenate(
                [
                    np.concatenate([white - black, tint_lean[:, None]], 1),
                    kernels(white_material, alpha, options, tint_lean, fit_tint, _mus()),
                ]
            )
        )
    return np.array(black_rows, np.float32), np.array(tint_rows, np.float32)


def _table_key(material: Material) -> str:
    """What the tables depend on: the material's model and parameters (not its name or maps)."""
    ir = material.to_ir()
    return json.dumps({"model": ir["model"], "params": ir["params"]}, sort_keys=True)


def albedo_tables(
    material: Material, fresnel: str = "exact", multiscatter: bool = False, mapped_roughness: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """(black, tint) tables, each (rows, SECTIONS * MU_SIZE, 4) float32: row = sqrt(α) texel of
    the base lobe; three sections of MU_SIZE columns over cos θo:
      [0, MU)     RGB = directional albedo, A = the lobe's lean (`_lean`);
      [MU, 2 MU)  kernel 1: (lean, α / the lobe's α, weight, fitted) of the first
                  environment lookup (`kernel_fit.kernels`);
      [2 MU, 3 MU) kernel 2: likewise. Not fitted (fitted = 0, a smooth lobe): kernel 1 is the
                  lean with weight 1, and the lobe is looked up once, at exactly α.
    A coated paint with flakes (flake_tables.coated_flakes): the black table's kernel sections
    hold the flakes' share of its albedo with their lean, and the flake lobe's α (flake_sections).
    Stored on disk; `TableCache` keeps them in memory too."""
    return _tables(material, fresnel, bool(multiscatter), bool(mapped_roughness))


class TableCache:
    """The albedo tables a renderer has used, kept in memory for its lifetime (keyed by the
    material's model and parameters and the options, not by its name)."""

    def __init__(self) -> None:
        self._tables: dict[tuple[str, str, bool, bool], Tables] = {}

    def tables(
        self, material: Material, fresnel: str = "exact", multiscatter: bool = False, mapped_roughness: bool = False
    ) -> Tables:
        """albedo_tables(material, fresnel, multiscatter, mapped_roughness), made once."""
        key = (_table_key(material), fresnel, bool(multiscatter), bool(mapped_roughness))
        if key not in self._tables:
            self._tables[key] = _tables(material, fresnel, bool(multiscatter), bool(mapped_roughness))
        return self._tables[key]
