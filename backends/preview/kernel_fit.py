"""The split-sum tables' two-kernel fit (docs/preview.md): a rough lobe, seen from each cos θv,
as a mixture of two environment kernels (prefilter.frag's GGX), each (direction in the plane of
incidence, α, weight), chosen to minimise the expected error over environments whose radiance
has FIT_CORRELATION; the shader then looks the environment up twice (split.glsl.j2)."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from cnlmc.bsdf.evaluate import evaluate
from cnlmc.bsdf.geometry import dir_from_mu
from cnlmc.material import Material

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


def _lobe_masses(material: Material, options: dict, mus: np.ndarray) -> np.ndarray:
    """(len(mus), FIT_POINTS) the lobe f cos θi (mean over RGB) on the fit's points, per cos θv
    in `mus` (the viewer at azimuth 0: the mirror side is −x), each row summing to 1 (0 for no lobe)."""
    points = _basis()[0]
    up = points[:, 2] > 0
    wi = points[up]
    wo = dir_from_mu(mus)
    shape = (len(mus), len(wi), 3)
    f = evaluate(material, np.broadcast_to(wo[:, None, :], shape), np.broadcast_to(wi, shape), **options)
    masses = np.zeros((len(mus), len(points)))
    masses[:, up] = np.maximum(f.mean(-1), 0.0) * wi[:, 2]
    total = masses.sum(1, keepdims=True)
    return np.where(total > 1e-12, masses / np.maximum(total, 1e-12), 0.0)


def _fit(masses: np.ndarray, alpha: float) -> np.ndarray:
    """(len(masses), 2, 3) (psi, α, weight) of two kernels per cos θv whose mixture is closest to
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
    out = np.zeros((len(masses), 2, 3))
    prev = None
    for j in range(len(masses)):
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


def kernels(
    material: Material, alpha: tuple[float, float], options: dict, lean: np.ndarray, fitted: bool, mus: np.ndarray
) -> np.ndarray:
    """(2 len(mus), 4): two sections (kernel 1, kernel 2) of (lean, α / the lobe's α, weight,
    fitted) per cos θv in `mus`; lean = the kernel's direction as a fraction of θv (as the
    tables' leans, albedo_tables._lean), its α
    relative to the lobe's so that rows of a roughness map interpolate. Not fitted (fitted = 0):
    kernel 1 = the lobe's lean at its own α with weight 1, kernel 2 weight 0 (the shader then
    reads the environment prefiltered at exactly α)."""
    a = float(np.sqrt(alpha[0] * alpha[1]))
    section = np.zeros((2, len(mus), 4))
    section[0, :, 0], section[0, :, 1], section[0, :, 2] = lean, 1.0, 1.0
    section[1, :, 1] = 1.0
    if fitted and a >= FIT_ALPHA:
        fit = _fit(_lobe_masses(material, options, mus), a)
        theta_v = np.arccos(mus)
        # the fit's candidates are a grid: blurred over cos θv, its steps in direction and α
        # become ramps (a step of the slope shows as a ring on a sphere)
        psi, root_alpha = _blur(fit[:, :, 0]), _blur(np.sqrt(fit[:, :, 1]))
        weight = _blur(fit[:, 1, 2])
        for k in range(2):
            section[k, :, 0] = psi[:, k] / theta_v
            section[k, :, 1] = root_alpha[:, k] ** 2 / a
            section[k, :, 2] = 1.0 - weight if k == 0 else weight
            section[k, :, 3] = 1.0
    return section.reshape(2 * len(mus), 4)


def _blur(values: np.ndarray) -> np.ndarray:
    """A Gaussian of FIT_BLUR texels along the first axis (cos θv), edges extended."""
    radius = int(np.ceil(3 * FIT_BLUR))
    taps = np.exp(-0.5 * (np.arange(-radius, radius + 1) / FIT_BLUR) ** 2)
    taps /= taps.sum()
    padded = np.concatenate([np.repeat(values[:1], radius, 0), values, np.repeat(values[-1:], radius, 0)])
    return sum(t * padded[i : i + len(values)] for i, t in enumerate(taps))
