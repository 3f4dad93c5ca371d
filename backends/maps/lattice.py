"""Periodic lattice noises evaluated separably on the pixel grid.

Value and gradient (Perlin) noise interpolate lattice values with the quintic fade
w(f) = 6f^5 - 15f^4 + 10f^3.  Both are sums of products of a function of x and a
function of y, so over a regular grid they are matrix products:
    value  = Wy @ V @ Wx.T
    perlin = Wy @ Gx @ Dx.T + Dy @ Gy @ Wx.T
where W holds fade weights and D fade weights times the offset to the lattice point.
Lattice indices wrap modulo the integer period, so every noise tiles over the unit square.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .grid import Grid, derive_seed


def fade(f: np.ndarray) -> np.ndarray:
    return f * f * f * (f * (f * 6.0 - 15.0) + 10.0)


@lru_cache(maxsize=64)
def axis_weights(size: int, period: int) -> tuple[np.ndarray, np.ndarray]:
    """Fade-weight matrix W and offset-weighted matrix D, both (size, period)."""
    positions = np.arange(size, dtype=np.float64) / size
    t = positions * period
    cell = np.floor(t).astype(np.int64)
    f = t - cell
    w1 = fade(f)
    rows = np.arange(len(positions))
    weights = np.zeros((len(positions), period))
    offsets = np.zeros((len(positions), period))
    np.add.at(weights, (rows, cell % period), 1.0 - w1)
    np.add.at(weights, (rows, (cell + 1) % period), w1)
    np.add.at(offsets, (rows, cell % period), f * (1.0 - w1))
    np.add.at(offsets, (rows, (cell + 1) % period), (f - 1.0) * w1)
    weights.flags.writeable = False
    offsets.flags.writeable = False
    return weights, offsets


def periods(scale: int, stretch: int = 1) -> tuple[int, int]:
    """Lattice periods (rows, cols); stretch > 1 elongates features along the columns (u)."""
    rows = max(1, int(round(scale)))
    return rows, max(1, int(round(rows / max(1, stretch))))


def low_rank(wy: np.ndarray, table: np.ndarray, wx: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(left, right) with left @ right = wy @ table @ wx.T, associated so the shared
    dimension is min(rows, cols) of the lattice table (the rank of the octave)."""
    if table.shape[1] < table.shape[0]:
        return wy @ table, wx.T
    return wy, table @ wx.T


@lru_cache(maxsize=256)
def value_factors_cached(size: int, seed: int, py: int, px: int, salt) -> tuple[np.ndarray, np.ndarray]:
    lattice = np.random.default_rng(derive_seed(seed, salt, py, px)).random((py, px)) * 2.0 - 1.0
    wy, _ = axis_weights(size, py)
    wx, _ = axis_weights(size, px)
    return frozen(*low_rank(wy, lattice, wx))


@lru_cache(maxsize=256)
def perlin_factors_cached(size: int, seed: int, py: int, px: int, salt) -> tuple[np.ndarray, np.ndarray]:
    angle = np.random.default_rng(derive_seed(seed, salt, py, px)).uniform(0.0, 2.0 * np.pi, (py, px))
    wy, dy = axis_weights(size, py)
    wx, dx = axis_weights(size, px)
    along_u = low_rank(wy, np.cos(angle) * np.sqrt(2.0), dx)
    along_v = low_rank(dy, np.sin(angle) * np.sqrt(2.0), wx)
    return frozen(np.hstack([along_u[0], along_v[0]]), np.vstack([along_u[1], along_v[1]]))


def frozen(left: np.ndarray, right: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """float32 read-only copies (they live in a cache shared by every bake)."""
    pair = np.ascontiguousarray(left, np.float32), np.ascontiguousarray(right, np.float32)
    for array in pair:
        array.flags.writeable = False
    return pair


def value_factors(grid: Grid, scale: int, stretch: int, salt) -> tuple[np.ndarray, np.ndarray]:
    """(left, right) float32 with left @ right = signed value noise in [-1, 1]."""
    return value_factors_cached(grid.size, grid.seed, *periods(scale, stretch), salt)


def perlin_factors(grid: Grid, scale: int, stretch: int, salt) -> tuple[np.ndarray, np.ndarray]:
    """(left, right) float32 with left @ right = signed gradient noise, roughly [-1, 1]."""
    return perlin_factors_cached(grid.size, grid.seed, *periods(scale, stretch), salt)


FACTORS = {"value": value_factors, "perlin": perlin_factors}


def noise_sum(grid: Grid, basis: str, layers, stretch: int, offset: float = 0.0) -> np.ndarray:
    """offset + sum of weight * signed octave over `layers` of (scale, weight, salt), as
    one float32 matrix product: factors side by side, the offset as a rank-one term."""
    pairs = [FACTORS[basis](grid, scale, stretch, salt) for scale, _, salt in layers]
    lefts = [left * np.float32(weight) for (left, _), (_, weight, _) in zip(pairs, layers)]
    rights = [right for _, right in pairs]
    if offset:
        lefts.append(np.ones((grid.size, 1), np.float32))
        rights.append(np.full((1, grid.size), offset, np.float32))
    return np.hstack(lefts) @ np.vstack(rights)


def signed_noise(grid: Grid, basis: str, scale: int, stretch: int = 1, salt=None) -> np.ndarray:
    return noise_sum(grid, basis, [(scale, 1.0, basis if salt is None else salt)], stretch)


def value_noise(grid: Grid, scale: int, stretch: int = 1, salt="value") -> np.ndarray:
    """Value noise in [0, 1]."""
    return noise_sum(grid, "value", [(scale, 0.5, salt)], stretch, offset=0.5)


def perlin_noise(grid: Grid, scale: int, stretch: int = 1, salt="perlin") -> np.ndarray:
    """Gradient noise, rescaled to roughly [0, 1] (0.5 on lattice points)."""
    return clip01(noise_sum(grid, "perlin", [(scale, 0.5, salt)], stretch, offset=0.5))


def clip01(array: np.ndarray) -> np.ndarray:
    """Clamp a float32 array to [0, 1] in place."""
    return np.clip(array, 0.0, 1.0, out=array)


def fractal_sum(
    grid: Grid, basis: str, scales: list[int], weights: list[float], stretch: int, salt, offset: float = 0.0
) -> np.ndarray:
    """offset + weighted sum of signed octaves (salts (salt, k)) as one matrix product."""
    layers = [(s, w, (salt, k)) for k, (s, w) in enumerate(zip(scales, weights))]
    return noise_sum(grid, basis, layers, stretch, offset)
