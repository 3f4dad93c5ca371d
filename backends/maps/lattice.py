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


def value_noise(grid: Grid, scale: int, stretch: int = 1, salt="value") -> np.ndarray:
    """Value noise in [0, 1]."""
    py, px = periods(scale, stretch)
    lattice = grid.rng(salt, py, px).random((py, px))
    wy, _ = axis_weights(grid.size, py)
    wx, _ = axis_weights(grid.size, px)
    return (wy @ lattice @ wx.T).astype(np.float32)


def perlin_noise(grid: Grid, scale: int, stretch: int = 1, salt="perlin") -> np.ndarray:
    """Gradient noise, rescaled to roughly [0, 1] (0.5 on lattice points)."""
    py, px = periods(scale, stretch)
    angle = grid.rng(salt, py, px).uniform(0.0, 2.0 * np.pi, (py, px))
    wy, dy = axis_weights(grid.size, py)
    wx, dx = axis_weights(grid.size, px)
    signed = wy @ np.cos(angle) @ dx.T + dy @ np.sin(angle) @ wx.T
    return (0.5 + 0.5 * np.sqrt(2.0) * signed).astype(np.float32)
