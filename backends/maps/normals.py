"""Height to tangent-space normal (OpenGL convention: +X right, +Y up the image, +Z out)."""
from __future__ import annotations

import numpy as np

from .colour import as_array, is_rgb, luminance
from .grid import Grid

DEPTH_PER_STRENGTH = 0.01  # tile units of relief for a height range of 1 at strength 1


def slopes(height: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """dh/du and dh/dv in height units per tile (central differences, wrapping)."""
    size = height.shape[0]
    d_du = (np.roll(height, -1, axis=1) - np.roll(height, 1, axis=1)) * (size / 2.0)
    d_dv = (np.roll(height, 1, axis=0) - np.roll(height, -1, axis=0)) * (size / 2.0)  # row 0 is the top
    return d_du, d_dv


def height_to_normal(grid: Grid, input=0.5, strength=1.0):
    """Unit normals (H, W, 3) in [-1, 1] of the surface z = strength * 0.01 * height."""
    height = np.broadcast_to(as_array(input), (grid.size, grid.size) + np.shape(input)[2:])
    height = luminance(height) if is_rgb(height) else height
    d_du, d_dv = slopes(height.astype(np.float32))
    depth = np.float32(strength * DEPTH_PER_STRENGTH)
    normal = np.stack([-depth * d_du, -depth * d_dv, np.ones_like(d_du)], axis=-1)
    return (normal / np.linalg.norm(normal, axis=-1, keepdims=True)).astype(np.float32)


def is_normal_map(array: np.ndarray) -> bool:
    return array.ndim == 3 and array.shape[-1] == 3 and bool(np.all(array[..., 2] > 0))
