"""Periodic Worley (cellular / Voronoi) noise: one jittered feature point per cell.

Distances are taken to the feature points of the 3x3 neighbouring cells, with cell
indices wrapped modulo the integer period, so the pattern tiles over the unit square.
Distances are in cell units: F1 in [0, ~1.1], F2 - F1 (the cell-edge distance) in [0, ~1].
"""

from __future__ import annotations

import numpy as np

from .grid import Grid, row_blocks
from .lattice import periods

FEATURES = ("f1", "f2", "edge", "cell")


def feature_points(grid: Grid, py: int, px: int, jitter: float, salt):
    rng = grid.rng(salt, py, px)
    offsets = 0.5 + jitter * (rng.random((2, py, px)) - 0.5)
    cell_values = rng.random((py, px))
    return offsets.astype(np.float32), cell_values.astype(np.float32)


class Nearest:
    """Running F1, F2 (squared) and nearest-cell value over one block of pixel rows."""

    def __init__(self, rows: int, size: int, need_f2: bool, need_cell: bool):
        shape = (rows, size)
        self.f1 = np.full(shape, np.inf, np.float32)
        self.f2 = np.full(shape, np.inf, np.float32) if need_f2 else None
        self.value = np.zeros(shape, np.float32) if need_cell else None
        self.scratch = np.empty(shape, np.float32) if need_f2 else None

    def update(self, dist: np.ndarray, values) -> None:
        if self.value is not None:
            np.copyto(self.value, values(), where=dist < self.f1)
        if self.f2 is not None and self.scratch is not None:  # min(f2, max(f1, d)) == min(f2, d if d >= f1 else f1)
            np.maximum(self.f1, dist, out=self.scratch)
            np.minimum(self.f2, self.scratch, out=self.f2)
        np.minimum(self.f1, dist, out=self.f1)


def squared_distances(offsets, lattice_rows, cols, to_cell_y, to_cell_x) -> np.ndarray:
    """|feature - pixel|^2 for the block: feature cells at lattice_rows x cols."""
    if np.all(lattice_rows == lattice_rows[0]):  # one lattice row: separable, no 2-D gather
        dy = to_cell_y[:, None] + offsets[0][lattice_rows[0]][cols][None, :]
        dx = offsets[1][lattice_rows[0]][cols] + to_cell_x
        dy *= dy
        dy += dx * dx
        return dy
    dy = offsets[0][lattice_rows][:, cols] + to_cell_y[:, None]
    dx = offsets[1][lattice_rows][:, cols] + to_cell_x[None, :]
    dy *= dy
    dx *= dx
    dy += dx
    return dy


def nearest_two(grid: Grid, py: int, px: int, jitter: float, salt, need_f2: bool = True, need_cell: bool = True):
    """(F1, F2, random value of the nearest cell), each (size, size) float32 (F2 and the
    value are None unless asked for).  Works through cache-sized blocks of rows."""
    offsets, cell_values = feature_points(grid, py, px, jitter, salt)
    y, x = grid.axis * py, grid.axis * px
    iy, ix = np.floor(y).astype(np.int64), np.floor(x).astype(np.int64)
    to_cell_y, to_cell_x = (iy - y).astype(np.float32), (ix - x).astype(np.float32)
    neighbours_x = [((ix + ox) % px, to_cell_x + np.float32(ox)) for ox in (-1, 0, 1)]
    shape = (grid.size, grid.size)
    f1 = np.empty(shape, np.float32)
    f2 = np.empty(shape, np.float32) if need_f2 else None
    value = np.empty(shape, np.float32) if need_cell else None
    for r0, r1 in row_blocks(iy, grid.size):
        best = Nearest(r1 - r0, grid.size, need_f2, need_cell)
        for oy in (-1, 0, 1):
            rows = (iy[r0:r1] + oy) % py
            ty = to_cell_y[r0:r1] + np.float32(oy)
            for cols, tx in neighbours_x:
                dist = squared_distances(offsets, rows, cols, ty, tx)
                best.update(dist, lambda: cell_values[rows][:, cols])
        f1[r0:r1] = best.f1
        if f2 is not None:
            f2[r0:r1] = best.f2
        if value is not None:
            value[r0:r1] = best.value
    np.sqrt(f1, out=f1)
    if f2 is not None:
        np.sqrt(f2, out=f2)
    return f1, f2, value


def worley_noise(
    grid: Grid, scale: int, feature: str = "f1", jitter: float = 1.0, stretch: int = 1, salt="worley"
) -> np.ndarray:
    py, px = periods(scale, stretch)
    f1, f2, value = nearest_two(grid, py, px, jitter, salt, feature in ("f2", "edge"), feature == "cell")
    if feature == "f1":
        return np.clip(f1, 0.0, 1.0, out=f1)
    if feature == "f2":
        f2 *= np.float32(0.75)
        return np.clip(f2, 0.0, 1.0, out=f2)
    if feature == "edge":
        f2 -= f1
        return np.clip(f2, 0.0, 1.0, out=f2)
    return value
