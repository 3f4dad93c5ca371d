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

from .grid import Grid


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


def value_factors(grid: Grid, scale: int, stretch: int, salt) -> tuple[np.ndarray, np.ndarray]:
    """(left, right) float32 with left @ right = signed value noise in [-1, 1]."""
    py, px = periods(scale, stretch)
    lattice = grid.rng(salt, py, px).random((py, px)) * 2.0 - 1.0
    wy, _ = axis_weights(grid.size, py)
    wx, _ = axis_weights(grid.size, px)
    return wy.astype(np.float32), (lattice @ wx.T).astype(np.float32)


def perlin_factors(grid: Grid, scale: int, stretch: int, salt) -> tuple[np.ndarray, np.ndarray]:
    """(left, right) float32 with left @ right = signed gradient noise, roughly [-1, 1]."""
    py, px = periods(scale, stretch)
    angle = grid.rng(salt, py, px).uniform(0.0, 2.0 * np.pi, (py, px))
    wy, dy = axis_weights(grid.size, py)
    wx, dx = axis_weights(grid.size, px)
    left = np.hstack([wy, dy])
    right = np.vstack([np.cos(angle) @ dx.T, np.sin(angle) @ wx.T]) * np.sqrt(2.0)
    return left.astype(np.float32), right.astype(np.float32)


def value_signed(grid: Grid, scale: int, stretch: int, salt) -> np.ndarray:
    left, right = value_factors(grid, scale, stretch, salt)
    return left @ right


def perlin_signed(grid: Grid, scale: int, stretch: int, salt) -> np.ndarray:
    left, right = perlin_factors(grid, scale, stretch, salt)
    return left @ right


FACTORS = {"value": value_factors, "perlin": perlin_factors}
SIGNED = {"value": value_signed, "perlin": perlin_signed}


def signed_noise(grid: Grid, basis: str, scale: int, stretch: int = 1, salt=None) -> np.ndarray:
    return SIGNED[basis](grid, scale, stretch, basis if salt is None else salt)


def value_noise(grid: Grid, scale: int, stretch: int = 1, salt="value") -> np.ndarray:
    """Value noise in [0, 1]."""
    return 0.5 + 0.5 * signed_noise(grid, "value", scale, stretch, salt)


def perlin_noise(grid: Grid, scale: int, stretch: int = 1, salt="perlin") -> np.ndarray:
    """Gradient noise, rescaled to roughly [0, 1] (0.5 on lattice points)."""
    return np.clip(0.5 + 0.5 * signed_noise(grid, "perlin", scale, stretch, salt), 0.0, 1.0)


def fractal_sum(grid: Grid, basis: str, scales: list[int], weights: list[float], stretch: int, salt) -> np.ndarray:
    """Weighted sum of signed octaves as one matrix product (factors stacked side by side)."""
    pairs = [FACTORS[basis](grid, s, stretch, (salt, k)) for k, s in enumerate(scales)]
    left = np.hstack([l * np.float32(w) for (l, _), w in zip(pairs, weights)])
    return left @ np.vstack([r for _, r in pairs])
