"""Simplex-style noise that tiles: radial kernels on a triangulated integer lattice.

Classic simplex noise skews the plane so that triangles become equilateral; a skewed
lattice cannot repeat over the unit square.  Here each square lattice cell is split
along its diagonal into two triangles and each of the three corners contributes
(0.5 - d^2)^4 * (g . d), the simplex kernel, with gradients on the wrapped lattice.
The kernel reaches zero at distance sqrt(0.5), so only the three corners of the
containing triangle can contribute and the field is continuous and periodic.
"""
from __future__ import annotations

import numpy as np

from .grid import Grid
from .lattice import periods

KERNEL_RADIUS_SQ = 0.5
NORMALISATION = 1.0 / 0.0095  # the sum of the three kernels rarely exceeds 0.0095 for unit gradients


def corner_contribution(gx, gy, cx, cy, x, y):
    dx, dy = x - cx, y - cy
    falloff = np.maximum(KERNEL_RADIUS_SQ - dx * dx - dy * dy, 0.0)
    falloff *= falloff
    return falloff * falloff * (gx * dx + gy * dy)


def simplex_signed(grid: Grid, scale: int, stretch: int = 1, salt="simplex") -> np.ndarray:
    """Simplex-style noise, roughly [-1, 1]."""
    py, px = periods(scale, stretch)
    angle = grid.rng(salt, py, px).uniform(0.0, 2.0 * np.pi, (py, px))
    gx, gy = np.cos(angle).astype(np.float32), np.sin(angle).astype(np.float32)
    y = (grid.axis * py).astype(np.float32)[:, None]
    x = (grid.axis * px).astype(np.float32)[None, :]
    iy, ix = np.floor(y).astype(np.int64), np.floor(x).astype(np.int64)
    upper = (x - ix) > (y - iy)  # triangle (0,0)-(1,0)-(1,1) in cell coordinates
    mid_x, mid_y = ix + upper, iy + ~upper
    total = np.zeros((grid.size, grid.size), np.float32)
    for cx, cy in ((ix, iy), (mid_x, mid_y), (ix + 1, iy + 1)):
        cell = (cy % py, cx % px)
        total += corner_contribution(gx[cell], gy[cell], cx, cy, x, y)
    return total * np.float32(NORMALISATION)


def simplex_noise(grid: Grid, scale: int, stretch: int = 1, salt="simplex") -> np.ndarray:
    """Simplex-style noise rescaled to roughly [0, 1]."""
    noise = simplex_signed(grid, scale, stretch, salt)
    noise *= np.float32(0.5)
    noise += np.float32(0.5)
    return np.clip(noise, 0.0, 1.0, out=noise)
