"""Roles: what a graph output becomes for the role a material gives it.

color             -> (H, W, 3) linear RGB in [0, 1] (scalar outputs become grey)
normal            -> (H, W, 3) unit tangent-space normals, OpenGL convention (+Y up the image)
roughness, metallic, mask, height -> (H, W) linear values in [0, 1]
"""

from __future__ import annotations

import numpy as np

from .colour import is_rgb, luminance
from .errors import MapError

COLOR_ROLES = ("color", "base_color")


def to_color(array: np.ndarray, size: int) -> np.ndarray:
    rgb = array if is_rgb(array) else np.asarray(array, np.float32)[..., None]
    return np.ascontiguousarray(np.clip(np.broadcast_to(rgb, (size, size, 3)), 0.0, 1.0), np.float32)


def to_normal(array: np.ndarray, size: int, where: str) -> np.ndarray:
    if np.ndim(array) != 3 or np.shape(array)[-1] != 3:
        raise MapError(f"{where}: a normal output must come from a height_to_normal node")
    return np.ascontiguousarray(array, np.float32)  # height_to_normal already normalises


def to_parameter(array: np.ndarray, size: int) -> np.ndarray:
    scalar = luminance(array) if is_rgb(array) else np.asarray(array, np.float32)
    return np.ascontiguousarray(np.clip(np.broadcast_to(scalar, (size, size)), 0.0, 1.0), np.float32)


def finish(role: str, array: np.ndarray, size: int, where: str) -> np.ndarray:
    if role in COLOR_ROLES:
        return to_color(array, size)
    if role == "normal":
        return to_normal(array, size, where)
    return to_parameter(array, size)
