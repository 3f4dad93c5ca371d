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

from .grid import Grid, row_blocks
from .lattice import periods

KERNEL_RADIUS_SQ = 0.5
NORMALISATION = 1.0 / 0.0095  # the sum of the three kernels rarely exceeds 0.0095 for unit gradients


def corner_contribution(gx, gy, rows, cols, dx, dy) -> np.ndarray:
    """(0.5 - d^2)^4 (g . d) for one corner over a block of rows; d = (dx[col], dy[row]).
    The fourth corner of a square cell lies at d^2 >= 0.5 from the containing triangle, so
    summing all four corners equals the three-corner simplex sum."""
    falloff = np.float32(KERNEL_RADIUS_SQ) - dx * dx - (dy * dy)[:, None]
    np.maximum(falloff, np.float32(0.0), out=falloff)
    falloff *= falloff
    falloff *= falloff
    if np.all(rows == rows[0]):  # one lattice row: gradients vary along the row only
        dot = np.multiply(gy[rows[0]][cols][None, :], dy[:, None])
        dot += gx[rows[0]][cols] * dx
    else:
        dot = np.multiply(gy[rows][:, cols], dy[:, None])
        dot += gx[rows][:, cols] * dx
    falloff *= dot
    return falloff


def simplex_signed(grid: Grid, scale: int, stretch: int = 1, salt="simplex") -> np.ndarray:
    """Simplex-style noise, roughly [-1, 1]."""
    py, px = periods(scale, stretch)
    angle = grid.rng(salt, py, px).uniform(0.0, 2.0 * np.pi, (py, px))
    gx, gy = np.cos(angle).astype(np.float32), np.sin(angle).astype(np.float32)
    y = (grid.axis * py).astype(np.float32)
    x = (grid.axis * px).astype(np.float32)
    iy, ix = np.floor(y).astype(np.int64), np.floor(x).astype(np.int64)
    fy, fx = y - iy.astype(np.float32), x - ix.astype(np.float32)
    corners_x = [((ix + ox) % px, fx - np.float32(ox)) for ox in (0, 1)]
    total = np.zeros((grid.size, grid.size), np.float32)
    for r0, r1 in row_blocks(iy, grid.size):
        block = total[r0:r1]
        for oy in (0, 1):
            rows, dy = (iy[r0:r1] + oy) % py, fy[r0:r1] - np.float32(oy)
            for cols, dx in corners_x:
                block += corner_contribution(gx, gy, rows, cols, dx, dy)
    total *= np.float32(NORMALISATION)
    return total


def simplex_noise(grid: Grid, scale: int, stretch: int = 1, salt="simplex") -> np.ndarray:
    """Simplex-style noise rescaled to roughly [0, 1]."""
    noise = simplex_signed(grid, scale, stretch, salt)
    noise *= np.float32(0.5)
    noise += np.float32(0.5)
    return np.clip(noise, 0.0, 1.0, out=noise)
