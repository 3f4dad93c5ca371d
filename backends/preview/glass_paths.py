"""The light a rough glass ball keeps inside after its first exit: a table, measured by tracing
paths through a rough dielectric sphere (docs/preview.md, "Transparent materials").

The preview's glass shader follows the view ray along the macro normals: in, across, out. With
rough interfaces part of the light that reaches the far side meets a facet it reflects from
(Fresnel, and total internal reflection beyond the critical angle, which tilted facets reach
long before the macro angle does near the silhouette), crosses the ball again and leaves after
more interfaces, in directions that have little to do with the lens image. This module traces
that light (Monte Carlo, numpy) for a unit sphere of index `ior` and GGX width `alpha` at every
interface, entered at cosine `mu` between the view and the entry's normal, and tabulates per
(ior, alpha, mu):

* `more` -- the share of the light that entered (and was not blocked at the entry) that leaves
  after the first exit: at the second interface inside or later;
* `angle` -- the direction of that light's mean exit direction, as an angle from the view ray
  (straight through) towards the entry's normal projected across the view (towards the rim the
  entry point lies on), in radians;
* `spread` -- the GGX alpha of the preview's prefiltered environment whose kernel has that
  light's mean cosine about its mean direction (1: as wide as the widest prefiltered level);
* `length` -- its mean path inside, in radii (for Beer-Lambert).

Each interface samples a visible GGX normal (Heitz 2018) and reflects or refracts on it with
the exact dielectric Fresnel; a direction that its neighbour facets block (the Smith G1 as a
chance) scatters again and leaves in a cosine lobe on the side it was going to: nothing is lost
(Heitz, Hanika, d'Eon & Dachsbacher 2016 -- their rough dielectric conserves energy; the chart's
reference gives the blocked light back in such a lobe, backends/preview/reference_glass.py).

    .venv/bin/python -m cnlmc.backends.preview.glass_paths   # rewrites data/glass_paths.npz
"""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np

TABLE = Path(__file__).parent / "data" / "glass_paths.npz"
#: the table's grid: indices of refraction, GGX alphas, entry cosines (cell centres)
IORS = (1.2, 1.31, 1.4, 1.52, 1.65, 1.8, 2.0, 2.2, 2.42)
ALPHAS = (0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.65, 0.8, 1.0)
COSINES = 16
#: what the table holds per cell (see the module and `lobe`)
KEYS = ("more", "angle", "spread", "length", "mean_cos", "first_angle", "first_spread", "first_mean_cos")
#: paths per (ior, alpha, cosine) and the most interfaces a path meets before it is dropped
PATHS = 4096
MAX_INTERFACES = 64


def frame(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit tangents completing the unit normals n (rows) to orthonormal frames."""
    helper = np.where(np.abs(n[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    t = np.cross(helper, n)
    t /= np.linalg.norm(t, axis=1, keepdims=True)
    return t, np.cross(n, t)


def g1(cos: np.ndarray, alpha: float) -> np.ndarray:
    """Smith G1 of GGX for directions at cosine `cos` to the macro normal (0 below it)."""
    c2 = np.clip(cos * cos, 1e-12, 1.0)
    out = 2.0 / (1.0 + np.sqrt(1.0 + alpha * alpha * (1.0 - c2) / c2))
    return np.where(cos > 0.0, out, 0.0)


def sample_facet(n: np.ndarray, w: np.ndarray, alpha: float, u: np.ndarray) -> np.ndarray:
    """A GGX visible normal around the macro normals n for directions w (both unit rows,
    w . n > 0), from uniform numbers u (rows of two) -- Heitz 2018's sampling."""
    t, b = frame(n)
    local = np.stack([np.sum(w * t, 1), np.sum(w * b, 1), np.maximum(np.sum(w * n, 1), 1e-6)], 1)
    vh = local * [alpha, alpha, 1.0]
    vh /= np.linalg.norm(vh, axis=1, keepdims=True)
    lensq = vh[:, 0] ** 2 + vh[:, 1] ** 2
    inv = 1.0 / np.sqrt(np.maximum(lensq, 1e-30))
    t1 = np.where(lensq[:, None] > 0, np.stack([-vh[:, 1] * inv, vh[:, 0] * inv, 0 * inv], 1), [[1.0, 0.0, 0.0]])
    t2 = np.cross(vh, t1)
    r, phi = np.sqrt(u[:, 0]), 2.0 * np.pi * u[:, 1]
    p1, p2 = r * np.cos(phi), r * np.sin(phi)
    s = 0.5 * (1.0 + vh[:, 2])
    p2 = (1.0 - s) * np.sqrt(np.maximum(1.0 - p1 * p1, 0.0)) + s * p2
    nh = p1[:, None] * t1 + p2[:, None] * t2 + np.sqrt(np.maximum(1.0 - p1 * p1 - p2 * p2, 0.0))[:, None] * vh
    ne = np.stack([alpha * nh[:, 0], alpha * nh[:, 1], np.maximum(nh[:, 2], 1e-6)], 1)
    ne /= np.linalg.norm(ne, axis=1, keepdims=True)
    return ne[:, :1] * t + ne[:, 1:2] * b + ne[:, 2:] * n


def fresnel(cos_i: np.ndarray, eta: np.ndarray) -> np.ndarray:
    """Unpolarised dielectric Fresnel from the side of index 1 towards index eta (1 under TIR)."""
    c = np.clip(cos_i, 0.0, 1.0)
    sin_t2 = (1.0 - c * c) / (eta * eta)
    ct = np.sqrt(np.clip(1.0 - sin_t2, 0.0, 1.0))
    rs = (c - eta * ct) / np.maximum(c + eta * ct, 1e-12)
    rp = (eta * c - ct) / np.maximum(eta * c + ct, 1e-12)
    return np.where(sin_t2 >= 1.0, 1.0, 0.5 * (rs * rs + rp * rp))


def refract(w: np.ndarray, m: np.ndarray, eta: np.ndarray) -> np.ndarray:
    """The direction refracted through facet m of light arriving from w (pointing away from the
    surface on m's side; eta: the index across over the index on w's side); TIR never asked."""
    c = np.sum(w * m, 1, keepdims=True)
    e = np.asarray(eta, np.float64).reshape(-1, 1)
    ct = np.sqrt(np.clip(1.0 - (1.0 - c * c) / (e * e), 0.0, 1.0))
    return -w / e + (c / e - ct) * m


def interface(n: np.ndarray, w: np.ndarray, alpha: float, eta: float, rng) -> tuple[np.ndarray, np.ndarray]:
    """Light arriving from w (unit rows, w . n > 0) at a rough interface of macro normal n and
    relative index eta (index beyond / index on w's side): (out direction, crossed?), reflected or
    refracted by Fresnel on a sampled visible facet. A direction the neighbour facets block
    (Smith G1 as a chance) scatters again and leaves in a cosine lobe on the side it was going
    to, as the chart's reference gives the blocked light back (Kulla & Conty's lobe)."""
    count = len(w)
    m = sample_facet(n, w, alpha, rng.random((count, 2)))
    e = np.full(count, eta)
    f = fresnel(np.sum(w * m, 1), e)
    reflect = rng.random(count) < f
    wr = 2.0 * np.sum(w * m, 1, keepdims=True) * m - w
    wo = np.where(reflect[:, None], wr, refract(w, m, np.where(reflect, 1.0, e)))
    towards = n * np.where(reflect, 1.0, -1.0)[:, None]  # the normal of the side it goes to
    kept = rng.random(count) < g1(np.sum(wo * towards, 1), alpha)
    blocked = np.flatnonzero(~kept)
    wo[blocked] = cosine_lobe(towards[blocked], rng.random((len(blocked), 2)))
    return wo, ~reflect


def cosine_lobe(n: np.ndarray, u: np.ndarray) -> np.ndarray:
    """Cosine-distributed directions about the unit normals n (rows)."""
    t, b = frame(n)
    r, phi = np.sqrt(u[:, 0]), 2.0 * np.pi * u[:, 1]
    z = np.sqrt(np.maximum(1.0 - u[:, 0], 0.0))
    return (r * np.cos(phi))[:, None] * t + (r * np.sin(phi))[:, None] * b + z[:, None] * n


def trace(ior: float, alpha: float, mu: float, paths: int, rng) -> dict[str, float]:
    """The table's values at one (ior, alpha, mu) from `paths` traced paths (see the module)."""
    theta = np.arccos(mu)
    n0 = np.tile([np.sin(theta), 0.0, np.cos(theta)], (paths, 1))
    view = np.tile([0.0, 0.0, 1.0], (paths, 1))
    # entry: the refracted light that is not blocked (the preview draws the rest separately)
    m = sample_facet(n0, view, alpha, rng.random((paths, 2)))
    d = refract(view, m, np.full(paths, ior))
    weight = (1.0 - fresnel(np.sum(view * m, 1), np.full(paths, ior))) * g1(-np.sum(d * n0, 1), alpha)
    p = n0.copy()
    length = np.zeros(paths)
    alive = weight > 0
    exits: list[tuple[np.ndarray, np.ndarray, np.ndarray, int]] = []  # (index, direction, length, k)
    for k in range(1, MAX_INTERFACES + 1):
        idx = np.flatnonzero(alive)
        if not len(idx):
            break
        b = np.sum(p[idx] * d[idx], 1)
        s = -b + np.sqrt(np.maximum(b * b - (np.sum(p[idx] ** 2, 1) - 1.0), 0.0))
        p[idx] += s[:, None] * d[idx]
        p[idx] /= np.linalg.norm(p[idx], axis=1, keepdims=True)
        length[idx] += s
        wo, crossed = interface(-p[idx], -d[idx], alpha, 1.0 / ior, rng)
        left = idx[crossed]
        exits.append((left, wo[crossed], length[left].copy(), k))
        alive[left] = False
        d[idx[~crossed]] = wo[~crossed]
    first = lobe([e for e in exits if e[3] == 1], weight)
    later = lobe([e for e in exits if e[3] > 1], weight)
    return {
        "more": later["share"],
        "angle": float(np.mod(later["angle"], 2.0 * np.pi)),  # mostly near pi: no wrap between cells
        "spread": later["spread"],
        "length": later["length"],
        "mean_cos": later["mean_cos"],
        "first_angle": first["angle"],
        "first_spread": first["spread"],
        "first_mean_cos": first["mean_cos"],
    }


def lobe(exits: list, weight: np.ndarray) -> dict[str, float]:
    """Share, mean direction (its angle in the frame: straight through -z, across towards the
    entry's side +x), mean cosine about it, the prefilter alpha whose kernel has the same median
    angle, and mean path of the light that left at these exits."""
    if not exits:
        return {"share": 0.0, "angle": np.pi, "spread": 1.0, "mean_cos": 0.0, "length": 2.0}
    index = np.concatenate([e[0] for e in exits])
    dirs = np.concatenate([e[1] for e in exits])
    lengths = np.concatenate([e[2] for e in exits])
    w = weight[index]
    if w.sum() <= 0:
        return {"share": 0.0, "angle": np.pi, "spread": 1.0, "mean_cos": 0.0, "length": 2.0}
    c1, c2 = float(np.sum(w * -dirs[:, 2]) / w.sum()), float(np.sum(w * dirs[:, 0]) / w.sum())
    angle = float(np.arctan2(c2, c1))
    cos = dirs @ np.array([np.sin(angle), 0.0, -np.cos(angle)])
    order = np.argsort(-cos)
    median = float(cos[order][min(np.searchsorted(np.cumsum(w[order]) / w.sum(), 0.5), len(w) - 1)])
    return {
        "share": float(w.sum() / weight.sum()),
        "angle": angle,
        "spread": spread_alpha(median),
        "mean_cos": float(np.sum(w * cos) / w.sum()),
        "length": float(np.sum(w * lengths) / w.sum()),
    }


@functools.lru_cache(maxsize=1)
def _kernel_medians() -> tuple[np.ndarray, np.ndarray]:
    """(alphas, the cosine of the median angle about its axis of the prefiltered kernel at each
    alpha): GGX's D(h) / 4 around the lookup direction, h halfway (Karis's n = v = r), as the
    shader's pv_key_seen evaluates it."""
    alphas = np.linspace(0.01, 1.0, 100)
    cos = np.linspace(-1.0, 1.0, 20001)
    ch = np.sqrt(np.clip((1.0 + cos) / 2.0, 0.0, 1.0))
    medians = []
    for a in alphas:
        kernel = a * a / (np.pi * (ch * ch * (a * a - 1.0) + 1.0) ** 2)
        outside = np.cumsum(kernel[::-1])[::-1]  # the kernel's weight beyond each cosine
        medians.append(float(cos[np.searchsorted(-outside / outside[0], -0.5)]))
    return alphas, np.array(medians)


def spread_alpha(median_cos: float) -> float:
    """The prefiltered kernel's alpha with this median cosine about its axis (1 when wider): the
    median, not the mean, because GGX's long tail would make the mean match a narrower core."""
    alphas, medians = _kernel_medians()
    return float(np.interp(-median_cos, -medians, alphas))


def build(paths: int = PATHS, seed: int = 20261202) -> dict[str, np.ndarray]:
    """The whole table: arrays over (ior, alpha, cosine)."""
    rng = np.random.default_rng(seed)
    mus = (np.arange(COSINES) + 0.5) / COSINES
    shape = (len(IORS), len(ALPHAS), COSINES)
    out = {key: np.zeros(shape) for key in KEYS}
    for i, ior in enumerate(IORS):
        for j, alpha in enumerate(ALPHAS):
            for k, mu in enumerate(mus):
                for key, value in trace(ior, alpha, mu, paths, rng).items():
                    out[key][i, j, k] = value
    return {"iors": np.array(IORS), "alphas": np.array(ALPHAS), "cosines": mus, **out}


@functools.lru_cache(maxsize=1)
def table() -> dict[str, np.ndarray]:
    with np.load(TABLE) as data:
        return {key: data[key] for key in data.files}


def rows_for(ior: float, alpha: float) -> np.ndarray:
    """(COSINES, len(KEYS)): the table's values over the entry cosines for this ior and alpha,
    interpolated linearly in the table (clamped to its grid)."""
    t = table()
    values = np.stack([t[key] for key in KEYS], -1)
    i0, i1, wi = _bracket(t["iors"], ior)
    j0, j1, wj = _bracket(t["alphas"], alpha)
    at_ior = values[i0] * (1 - wi) + values[i1] * wi
    return at_ior[j0] * (1 - wj) + at_ior[j1] * wj


def _bracket(grid: np.ndarray, x: float) -> tuple[int, int, float]:
    x = float(np.clip(x, grid[0], grid[-1]))
    j = int(np.clip(np.searchsorted(grid, x) - 1, 0, len(grid) - 2))
    return j, j + 1, float((x - grid[j]) / (grid[j + 1] - grid[j]))


def main() -> int:
    data = build()
    TABLE.parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(TABLE, **data)  # type: ignore[arg-type]
    print(f"wrote {TABLE}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
