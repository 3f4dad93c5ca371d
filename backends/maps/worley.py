"""Periodic Worley (cellular / Voronoi) noise: one jittered feature point per cell.

Distances are taken to the feature points of the 3x3 neighbouring cells, with cell
indices wrapped modulo the integer period, so the pattern tiles over the unit square.
Distances are in cell units: F1 in [0, ~1.1], F2 - F1 (the cell-edge distance) in [0, ~1].
"""
from __future__ import annotations

import numpy as np

from .grid import Grid
from .lattice import periods

FEATURES = ("f1", "f2", "edge", "cell")


def feature_points(grid: Grid, py: int, px: int, jitter: float, salt):
    rng = grid.rng(salt, py, px)
    offsets = 0.5 + jitter * (rng.random((2, py, px)) - 0.5)
    cell_values = rng.random((py, px))
    return offsets.astype(np.float32), cell_values.astype(np.float32)


def nearest_two(grid: Grid, py: int, px: int, jitter: float, salt):
    """(F1, F2, random value of the nearest cell), each (size, size) float32."""
    offsets, cell_values = feature_points(grid, py, px, jitter, salt)
    y, x = grid.axis * py, grid.axis * px
    iy, ix = np.floor(y).astype(np.int64), np.floor(x).astype(np.int64)
    to_cell_y = (iy - y).astype(np.float32)[:, None]
    to_cell_x = (ix - x).astype(np.float32)[None, :]
    shape = (grid.size, grid.size)
    f1, f2 = np.full(shape, np.inf, np.float32), np.full(shape, np.inf, np.float32)
    value = np.zeros(shape, np.float32)
    for oy in (-1, 0, 1):
        rows = (iy + oy) % py
        for ox in (-1, 0, 1):
            cols = (ix + ox) % px
            dy = offsets[0][rows][:, cols] + (to_cell_y + oy)
            dx = offsets[1][rows][:, cols] + (to_cell_x + ox)
            dist = dy * dy + dx * dx
            closer = dist < f1
            np.minimum(f2, np.where(closer, f1, dist), out=f2)
            np.copyto(value, cell_values[rows][:, cols], where=closer)
            np.copyto(f1, dist, where=closer)
    return np.sqrt(f1), np.sqrt(f2), value


def worley_noise(grid: Grid, scale: int, feature: str = "f1", jitter: float = 1.0,
                 stretch: int = 1, salt="worley") -> np.ndarray:
    py, px = periods(scale, stretch)
    f1, f2, value = nearest_two(grid, py, px, jitter, salt)
    if feature == "f1":
        return np.clip(f1, 0.0, 1.0)
    if feature == "f2":
        return np.clip(f2 * 0.75, 0.0, 1.0)
    if feature == "edge":
        return np.clip(f2 - f1, 0.0, 1.0)
    return value
