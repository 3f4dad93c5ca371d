"""Preview geometry for glTF and USDZ: the preview's sphere, shader ball and Newell teapot
(cnlmc.backends.preview.meshes, numpy only: no GL is loaded), sized in metres, as the flat
arrays a glTF primitive takes.

glTF conventions (glTF 2.0 spec, "Meshes" and "Materials"): y up, metres; TEXCOORD_0 has v = 0 at
the image's top row (the preview has v = 1 there, so v is flipped); TANGENT is a vec4 whose w
(+1 or -1) gives the bitangent as cross(normal, tangent.xyz) * w. The baked normal maps have +Y up
the image (cnlmc.backends.maps.roles), so w is chosen per vertex to make that bitangent point up
the image, the direction in which the preview's v grows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

MESH_NAMES = ("sphere", "shader_ball", "teapot")
#: our choice, for a mesh that states no size of its own: 10 cm, the preview sphere's size
FALLBACK_SIZE = 0.1


@dataclass(frozen=True)
class PreviewGeometry:
    """Triangles in metres, standing on y = 0: float32 attributes, uint32 indices."""

    name: str
    positions: np.ndarray  # (N, 3)
    normals: np.ndarray  # (N, 3), unit
    tangents: np.ndarray  # (N, 4), xyz unit and orthogonal to the normal, w = +-1
    uvs: np.ndarray  # (N, 2), glTF's v (0 = the image's top row)
    indices: np.ndarray  # (M, 3)
    #: metres one UV unit spans on this object as written (None: the mesh states no UV unit)
    metres_per_uv: float | None = None

    @property
    def size(self) -> float:
        """The largest extent, in metres."""
        return float((self.positions.max(0) - self.positions.min(0)).max())


def preview_geometry(name: str, size: float | None = None) -> PreviewGeometry:
    """The preview mesh `name` fitted into a bounding sphere `size` metres across, on y = 0; without
    `size`, at the size the mesh states (its UVs then span the maps' texture unit: the 10 cm sphere,
    the 11.4 cm shader ball, the 26 cm teapot of cnlmc.backends.preview.meshes)."""
    from ..preview.meshes import MESHES, fit  # numpy generators; the preview's GL modules load lazily

    mesh = fit(MESHES[name]())
    unit_ball = np.asarray(mesh.positions, np.float64)
    stated = getattr(mesh, "metres_per_uv", None)  # generated meshes give UVs in a real unit
    if size is None:
        along_v = metres_along_v(unit_ball, np.asarray(mesh.uvs, np.float64), np.asarray(mesh.indices).reshape(-1, 3))
        size = 2.0 * stated / along_v if stated else FALLBACK_SIZE
    positions = unit_ball * (size / 2.0)
    normals = unit(np.asarray(mesh.normals, np.float64))
    tangent = unit(np.asarray(mesh.tangents, np.float64))
    uvs = np.asarray(mesh.uvs, np.float64)
    indices = np.asarray(mesh.indices, np.int64).reshape(-1, 3)
    sign = bitangent_signs(positions, uvs, indices, normals, tangent)
    return PreviewGeometry(
        name,
        positions.astype(np.float32),
        normals.astype(np.float32),
        np.hstack([tangent, sign[:, None]]).astype(np.float32),
        np.stack([uvs[:, 0], 1.0 - uvs[:, 1]], 1).astype(np.float32),
        indices.astype(np.uint32),
        None if stated is None else metres_along_v(positions, uvs, indices),
    )


def metres_along_v(positions: np.ndarray, uvs: np.ndarray, indices: np.ndarray) -> float:
    """Metres one UV unit spans on the mesh as scaled: the median |dP/dv| over its triangles (our
    choice: v is the arc length along the profile of the generated meshes, so |dP/dv| is the same
    everywhere on them, and u is measured in the same unit: their UVs are isotropic)."""
    p, uv = positions[indices], uvs[indices]
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    d1, d2 = uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    keep = np.abs(det) > 1e-12
    dp_dv = (e2[keep] * d1[keep, 0:1] - e1[keep] * d2[keep, 0:1]) / det[keep, None]
    return float(np.median(np.linalg.norm(dp_dv, axis=1)))


def unit(v: np.ndarray) -> np.ndarray:
    length = np.linalg.norm(v, axis=1, keepdims=True)
    return v / np.where(length > 0.0, length, 1.0)


def bitangent_signs(
    positions: np.ndarray, uvs: np.ndarray, indices: np.ndarray, normals: np.ndarray, tangents: np.ndarray
) -> np.ndarray:
    """+1 or -1 per vertex: the sign that turns cross(N, T) into dP/dv (v as the preview has it)."""
    p, uv = positions[indices], uvs[indices]
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    d1, d2 = uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    inverse = np.where(np.abs(det) > 1e-20, 1.0 / np.where(det == 0.0, 1.0, det), 0.0)
    dp_dv = (e2 * d1[:, 0:1] - e1 * d2[:, 0:1]) * inverse[:, None]
    along_v = np.zeros_like(positions)
    for corner in range(3):
        np.add.at(along_v, indices[:, corner], dp_dv)
    facing = np.einsum("ij,ij->i", np.cross(normals, tangents), along_v)
    return np.where(facing < 0.0, -1.0, 1.0)


def placements(count: int, size: float) -> list[tuple[float, float, float]]:
    """Where each of `count` objects stands: a square-ish grid on the floor (rows along x, then
    back along -z), a quarter of `size` apart, centred on the origin."""
    step = size * 1.25
    columns = max(1, math.ceil(math.sqrt(count)))
    rows = math.ceil(count / columns)
    x0, z0 = -step * (min(count, columns) - 1) / 2.0, step * (rows - 1) / 2.0
    return [(x0 + (i % columns) * step, 0.0, z0 - (i // columns) * step) for i in range(count)]
