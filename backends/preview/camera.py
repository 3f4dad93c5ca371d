"""Camera matrices (OpenGL conventions: right-handed, looking down -z, clip z in [-1, 1])."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


def look_at(eye, target, up=(0.0, 1.0, 0.0)) -> np.ndarray:
    eye, target, up = (np.asarray(x, np.float64) for x in (eye, target, up))
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = s, u, -f
    view[:3, 3] = -view[:3, :3] @ eye
    return view


def perspective(fov_y_deg: float, aspect: float, near: float, far: float) -> np.ndarray:
    f = 1.0 / math.tan(math.radians(fov_y_deg) / 2)
    p = np.zeros((4, 4))
    p[0, 0], p[1, 1] = f / aspect, f
    p[2, 2], p[2, 3] = (far + near) / (near - far), 2 * far * near / (near - far)
    p[3, 2] = -1.0
    return p


@dataclass
class Camera:
    eye: tuple
    target: tuple
    fov_y: float = 30.0
    aspect: float = 1.0
    near: float = 0.05
    far: float = 100.0
    up: tuple = (0.0, 1.0, 0.0)
    view_override: np.ndarray | None = None
    projection_override: np.ndarray | None = None

    @property
    def view(self) -> np.ndarray:
        return self.view_override if self.view_override is not None else look_at(self.eye, self.target, self.up)

    @property
    def projection(self) -> np.ndarray:
        if self.projection_override is not None:
            return self.projection_override
        return perspective(self.fov_y, self.aspect, self.near, self.far)

    @property
    def view_projection(self) -> np.ndarray:
        return self.projection @ self.view

    @property
    def position(self) -> np.ndarray:
        return np.linalg.inv(self.view)[:3, 3]


def framing_camera(
    lo,
    hi,
    fov_y: float = 30.0,
    aspect: float = 1.0,
    elevation_deg: float = 18.0,
    azimuth_deg: float = 0.0,
    margin: float = 1.08,
) -> Camera:
    """A camera that sees the whole bounding sphere of the box [lo, hi] from the front (+z)."""
    lo, hi = np.asarray(lo, np.float64), np.asarray(hi, np.float64)
    centre = (lo + hi) / 2
    radius = float(np.linalg.norm(hi - lo)) / 2
    half = math.radians(fov_y) / 2
    if aspect < 1:
        half = math.atan(math.tan(half) * aspect)
    distance = radius * margin / math.sin(half)
    el, az = math.radians(elevation_deg), math.radians(azimuth_deg)
    direction = np.array([math.cos(el) * math.sin(az), math.sin(el), math.cos(el) * math.cos(az)])
    return Camera(tuple(centre + direction * distance), tuple(centre), fov_y, aspect)
