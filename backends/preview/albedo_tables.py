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

The *shape* of a rough lobe changes with the view: towards grazing it leans towards the
normal, stretches in the plane of incidence, is clipped by the horizon and keeps a long tail
on the viewer's side. One environment kernel (prefiltered at α, centred where the lobe's
first moment points) misses that. So for every cos θv the lobe is also fitted with a mixture
of two prefilter kernels, each (direction in the plane of incidence, α, weight); the shader
looks the environment up twice (`_kernels`, split.glsl.j2).

One row when α is uniform; ROWS rows over sqrt(α) when a roughness map varies it.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from functools import lru_cache
from pathlib import Path

import numpy as np

import cnlmc.bsdf
from cnlmc.bsdf.alpha import anisotropy_stretch
from cnlmc.bsdf.evaluate import albedo, evaluate, material_alpha
from cnlmc.bsdf.geometry import dir_from_mu
from cnlmc.cache import cached
from cnlmc.material import RGB, Material

BSDF_SOURCES = Path(cnlmc.bsdf.__file__).parent
MU_SIZE = 32
ROWS = 8
SAMPLES = 512
#: sections of MU_SIZE columns in a table: albedo + lean, kernel 1, kernel 2 (`albedo_tables`)
SECTIONS = 3
#: lobes at least this rough (GGX α, per row) are fitted with two kernels; smoother ones keep
#: one kernel at the lean with the exact α (the split sum is accurate there: FLIP ≤ 0.02)
FIT_ALPHA = 0.15
#: the fit: points on the sphere (Fibonacci), the angular correlation of the environment's
#: radiance (the fit minimises the error expected over environments with that correlation),
#: the kernels it chooses from (direction in the plane of incidence x sqrt(α)).
FIT_POINTS = 1500
FIT_CORRELATION = np.radians(15.0)
FIT_PSI = np.radians(np.arange(-85.0, 85.0 + 1e-9, 2.5))
FIT_ROOT_ALPHA = np.arange(0.35, 1.0 + 1e-9, 0.05)  # α ≥ 0.12: resolved by FIT_POINTS
FIT_MIN_SCALE = 0.5  # a kernel is at least half as wide as the lobe's own α
FIT_MAX_WEIGHT = 0.6  # of the second kernel
FIT_STEP = (np.radians(10.0), 0.1)  # the parameter change between neighbouring cos θv that costs ...
FIT_SMOOTH = 0.05  # ... this fraction of the fit's error (keeps the tables smooth)
FIT_BLUR = 1.5  # then a Gaussian of this many texels over cos θv (no steps)


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


# ------------------------------------------------------------------ the two-kernel fit


def _sphere(n: int) -> np.ndarray:
    """n near-equal-area points on the unit sphere (Fibonacci lattice)."""
    i = np.arange(n) + 0.5
    z = 1.0 - 2.0 * i / n
    r = np.sqrt(np.maximum(1.0 - z * z, 0.0))
    phi = np.pi * (1.0 + np.sqrt(5.0)) * i
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], -1)


def _kernel(points: np.ndarray, psi: float, alpha: float) -> np.ndarray:
    """The environment kernel of prefilter.frag (GGX with n = v = r, each direction l weighted
    by r·l: density ∝ D(h) r·l) around r = psi from the normal towards the mirror side (−x),
    as masses on `points` (sum 1)."""
    r = np.array([-np.sin(psi), 0.0, np.cos(psi)])
    c = points @ r
    h = points + r
    h /= np.maximum(np.linalg.norm(h, axis=-1, keepdims=True), 1e-12)
    ch = h @ r
    a2 = alpha * alpha
    mass = np.where(c > 0, a2 / (np.pi * (ch * ch * (a2 - 1.0) + 1.0) ** 2) * c, 0.0)
    return mass / mass.sum()


@lru_cache(maxsize=1)
def _basis():
    """The fit's fixed parts: points, the radiance correlation C between them, the candidate
    kernels K (one per (psi, α)), C K and the Gram matrix K C Kᵀ. A pure function of this
    module's constants: computed once per process (lru_cache), never written to."""
    points = _sphere(FIT_POINTS)
    angle = np.arccos(np.clip(points @ points.T, -1.0, 1.0))
    corr = np.exp(-0.5 * (angle / FIT_CORRELATION) ** 2)
    params = np.array([(psi, ra * ra) for ra in FIT_ROOT_ALPHA for psi in FIT_PSI])
    kernels = np.array([_kernel(points, psi, a) for psi, a in params])
    ck = kernels @ corr
    return points, corr, params, kernels, ck, ck @ kernels.T


def _lobe_masses(material: Material, options: dict) -> np.ndarray:
    """(MU_SIZE, FIT_POINTS) the lobe f cos θi (mean over RGB) on the fit's points, per cos θv
    (the viewer at azimuth 0: the mirror side is −x), each row summing to 1 (0 for no lobe)."""
    points = _basis()[0]
    up = points[:, 2] > 0
    wi = points[up]
    wo = dir_from_mu(_mus())
    shape = (MU_SIZE, len(wi), 3)
    f = evaluate(material, np.broadcast_to(wo[:, None, :], shape), np.broadcast_to(wi, shape), **options)
    masses = np.zeros((MU_SIZE, len(points)))
    masses[:, up] = np.maximum(f.mean(-1), 0.0) * wi[:, 2]
    total = masses.sum(1, keepdims=True)
    return np.where(total > 1e-12, masses / np.maximum(total, 1e-12), 0.0)


def _fit(masses: np.ndarray, alpha: float) -> np.ndarray:
    """(MU_SIZE, 2, 3) (psi, α, weight) of two kernels per cos θv whose mixture is closest to
    the lobe in E_L[(∫ L (lobe − mixture))²] over radiance L with correlation C (a quadratic
    form; the weight has a closed form). Swept from grazing to normal view, each choice pays
    FIT_SMOOTH of its error per FIT_STEP of change from the previous one, so that neighbouring
    texels (interpolated by the shader) hold neighbouring solutions."""
    _, corr, params, kernels, ck, gram = _basis()
    allowed = params[:, 1] >= FIT_MIN_SCALE * alpha - 1e-9
    if not allowed.any():
        allowed = params[:, 1] >= params[:, 1].max() - 1e-9
    diag = np.diag(gram)
    coords = np.stack([params[:, 0] / FIT_STEP[0], np.sqrt(params[:, 1]) / FIT_STEP[1]], -1)
    out = np.zeros((MU_SIZE, 2, 3))
    prev = None
    for j in range(MU_SIZE):
        p = masses[j]
        if p.sum() <= 0:
            out[j] = ((0.0, alpha, 1.0), (0.0, alpha, 0.0))
            continue
        cp = corr @ p
        kp = kernels @ cp  # <k, p>
        single = np.where(allowed, diag - 2.0 * kp + p @ cp, np.inf)
        scale = max(float(single.min()), 1e-30) * FIT_SMOOTH

        def cost(index, which):
            return 0.0 if prev is None else scale * np.sum((coords[index] - coords[prev[which]]) ** 2, -1)

        firsts = np.argsort(single + cost(slice(None), 0))[:8]
        best = None
        for i in firsts:
            ab = gram[i] - diag[i] - kp + kp[i]  # <k_i − p, k − k_i>
            bb = diag - 2.0 * gram[i] + diag[i]  # |k − k_i|²
            w = np.clip(-ab / np.maximum(bb, 1e-30), 0.0, FIT_MAX_WEIGHT)
            err = single[i] + 2.0 * w * ab + w * w * bb
            total = np.where(allowed, err + cost(slice(None), 1), np.inf) + cost(i, 0)
            k = int(np.argmin(total))
            if best is None or total[k] < best[0]:
                best = (total[k], i, k, w[k])
        assert best is not None  # firsts is never empty
        _, i, k, w = best
        prev = (i, k)
        out[j] = ((params[i][0], params[i][1], 1.0 - w), (params[k][0], params[k][1], w))
    return out


def _kernels(
    material: Material, alpha: tuple[float, float], options: dict, lean: np.ndarray, fitted: bool
) -> np.ndarray:
    """(2 MU_SIZE, 4): two sections (kernel 1, kernel 2) of (lean, α / the lobe's α, weight,
    fitted) per cos θv; lean = the kernel's direction as a fraction of θv (as `_lean`), its α
    relative to the lobe's so that rows of a roughness map interpolate. Not fitted (fitted = 0):
    kernel 1 = the lobe's lean at its own α with weight 1, kernel 2 weight 0 (the shader then
    reads the environment prefiltered at exactly α)."""
    a = float(np.sqrt(alpha[0] * alpha[1]))
    section = np.zeros((2, MU_SIZE, 4))
    section[0, :, 0], section[0, :, 1], section[0, :, 2] = lean, 1.0, 1.0
    section[1, :, 1] = 1.0
    if fitted and a >= FIT_ALPHA:
        fit = _fit(_lobe_masses(material, options), a)
        theta_v = np.arccos(_mus())
        # the fit's candidates are a grid: blurred over cos θv, its steps in direction and α
        # become ramps (a step of the slope shows as a ring on a sphere)
        psi, root_alpha = _blur(fit[:, :, 0]), _blur(np.sqrt(fit[:, :, 1]))
        weight = _blur(fit[:, 1, 2])
        for k in range(2):
            section[k, :, 0] = psi[:, k] / theta_v
            section[k, :, 1] = root_alpha[:, k] ** 2 / a
            section[k, :, 2] = 1.0 - weight if k == 0 else weight
            section[k, :, 3] = 1.0
    return section.reshape(2 * MU_SIZE, 4)


def _blur(values: np.ndarray) -> np.ndarray:
    """A Gaussian of FIT_BLUR texels along the first axis (cos θv), edges extended."""
    radius = int(np.ceil(3 * FIT_BLUR))
    taps = np.exp(-0.5 * (np.arange(-radius, radius + 1) / FIT_BLUR) ** 2)
    taps /= taps.sum()
    padded = np.concatenate([np.repeat(values[:1], radius, 0), values, np.repeat(values[-1:], radius, 0)])
    return sum(t * padded[i : i + len(values)] for i, t in enumerate(taps))


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
    sources = [Path(__file__)] + sorted(BSDF_SOURCES.glob("*.py"))
    tables: Tables = cached(kind, sources, lambda: _integrate(material, fresnel, multiscatter, mapped))
    return tables


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
        black_rows.append(
            np.concatenate(
                [
                    np.concatenate([black, black_lean[:, None]], 1),
                    _kernels(black_material, alpha, options, black_lean, fit_black),
                ]
            )
        )
        # the tint lobe is fitted only for conductors, whose black part is zero (white = tint)
        tint_rows.append(
            np.concatenate(
                [
                    np.concatenate([white - black, tint_lean[:, None]], 1),
                    _kernels(white_material, alpha, options, tint_lean, fit_tint),
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
                  environment lookup (`_kernels`);
      [2 MU, 3 MU) kernel 2: likewise. Not fitted (fitted = 0, a smooth lobe): kernel 1 is the
                  lean with weight 1, and the lobe is looked up once, at exactly α.
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
