"""Height to tangent-space normal (OpenGL convention: +X right, +Y up the image, +Z out)."""
from __future__ import annotations

import numpy as np

from .colour import as_array, is_rgb, luminance
from .grid import Grid

DEPTH_PER_STRENGTH = 0.01  # tile units of relief for a height range of 1 at strength 1


def central_difference(height: np.ndarray, axis: int) -> np.ndarray:
    """h[i + 1] - h[i - 1] along `axis`, wrapping around the tile."""
    h = height if axis == 1 else height.T
    out = np.empty_like(h)
    out[:, 1:-1] = h[:, 2:] - h[:, :-2]
    out[:, 0] = h[:, 1] - h[:, -1]
    out[:, -1] = h[:, 0] - h[:, -2]
    return out if axis == 1 else out.T


def slopes(height: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """dh/du and dh/dv in height units per tile (central differences, wrapping)."""
    half = np.float32(height.shape[0] / 2.0)
    return central_difference(height, 1) * half, central_difference(height, 0) * -half  # row 0 is the top


def height_to_normal(grid: Grid, input=0.5, strength=1.0):
    """Unit normals (H, W, 3) in [-1, 1] of the surface z = strength * 0.01 * height."""
    height = np.broadcast_to(as_array(input), (grid.size, grid.size) + np.shape(input)[2:])
    height = luminance(height) if is_rgb(height) else height
    d_du, d_dv = slopes(np.ascontiguousarray(height, np.float32))
    depth = np.float32(-strength * DEPTH_PER_STRENGTH)
    nx, ny = d_du * depth, d_dv * depth
    inverse_length = 1.0 / np.sqrt(nx * nx + ny * ny + np.float32(1.0))
    normal = np.empty((grid.size, grid.size, 3), np.float32)
    normal[..., 0], normal[..., 1], normal[..., 2] = nx * inverse_length, ny * inverse_length, inverse_length
    return normal


def is_normal_map(array: np.ndarray) -> bool:
    return array.ndim == 3 and array.shape[-1] == 3 and bool(np.all(array[..., 2] > 0))
