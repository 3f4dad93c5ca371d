"""Height to tangent-space normal (OpenGL convention: +X right, +Y up the image, +Z out)."""

from __future__ import annotations

import numpy as np

from .colour import as_array, is_rgb, luminance
from .grid import Grid

DEPTH_PER_STRENGTH = 0.01  # tile units of relief for a height range of 1 at strength 1


def central_difference(height: np.ndarray, axis: int, scale: np.float32) -> np.ndarray:
    """(h[i + 1] - h[i - 1]) * scale along `axis`, wrapping around the tile."""
    out = np.empty_like(height)
    if axis == 1:
        np.subtract(height[:, 2:], height[:, :-2], out=out[:, 1:-1])
        np.subtract(height[:, 1], height[:, -1], out=out[:, 0])
        np.subtract(height[:, 0], height[:, -2], out=out[:, -1])
    else:
        np.subtract(height[2:], height[:-2], out=out[1:-1])
        np.subtract(height[1], height[-1], out=out[0])
        np.subtract(height[0], height[-2], out=out[-1])
    out *= scale
    return out


def slopes(height: np.ndarray, factor: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """dh/du and dh/dv in height units per tile, times `factor` (central differences,
    wrapping).  The half-size step is a power of two, so folding it into `factor`
    rounds exactly like scaling twice."""
    half = np.float32(height.shape[0] / 2.0)
    step = np.float32(factor)
    return central_difference(height, 1, half * step), central_difference(height, 0, -half * step)  # row 0: the top


def height_to_normal(grid: Grid, input=0.5, strength=1.0):
    """Unit normals (H, W, 3) in [-1, 1] of the surface z = strength * 0.01 * height."""
    height = np.broadcast_to(as_array(input), (grid.size, grid.size) + np.shape(input)[2:])
    height = luminance(height) if is_rgb(height) else height
    nx, ny = slopes(np.ascontiguousarray(height, np.float32), -strength * DEPTH_PER_STRENGTH)
    inverse_length = nx * nx
    inverse_length += np.multiply(ny, ny)
    inverse_length += np.float32(1.0)
    np.sqrt(inverse_length, out=inverse_length)
    np.divide(np.float32(1.0), inverse_length, out=inverse_length)
    normal = np.empty((grid.size, grid.size, 3), np.float32)
    np.multiply(nx, inverse_length, out=normal[..., 0])
    np.multiply(ny, inverse_length, out=normal[..., 1])
    normal[..., 2] = inverse_length
    return normal


def is_normal_map(array: np.ndarray) -> bool:
    return array.ndim == 3 and array.shape[-1] == 3 and bool(np.all(array[..., 2] > 0))
