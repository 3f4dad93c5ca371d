"""The preview's mesh type: indexed triangles with per-vertex position, unit normal, unit tangent
(the +U direction, Gram-Schmidt against the normal) and UV, and how missing normals, tangents
and UVs are derived. Generators are in meshes.py, file formats in mesh_io.py and gltf.py."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import cached_property

import numpy as np


@dataclass
class Mesh:
    positions: np.ndarray  # (N, 3) float32
    normals: np.ndarray  # (N, 3) float32, unit
    tangents: np.ndarray  # (N, 3) float32, unit, orthogonal to the normal
    uvs: np.ndarray  # (N, 2) float32
    indices: np.ndarray  # (M, 3) uint32, counter-clockwise seen from outside
    #: metres one UV unit spans on the object at its stated size (generated meshes: meshes.UV_UNIT_M,
    #: the stdlib maps' texture unit, so a map shows at its real size); None: a file's UVs, unit unknown
    metres_per_uv: float | None = None

    def interleaved(self) -> np.ndarray:
        """position, normal, tangent, uv per vertex (11 floats): the preview's vertex layout."""
        return np.hstack([self.positions, self.normals, self.tangents, self.uvs]).astype("f4")

    @property
    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        return self.positions.min(0), self.positions.max(0)

    @cached_property
    def key(self) -> str:
        """A digest of the vertex data and the triangles: what GPU buffers made from the mesh are
        cached by (a mesh is not changed once made; an edit makes a new Mesh)."""
        digest = hashlib.blake2b(digest_size=16)
        for array in (self.positions, self.normals, self.tangents, self.uvs, self.indices):
            digest.update(str((array.dtype.str, array.shape)).encode())
            digest.update(np.ascontiguousarray(array).tobytes())
        return digest.hexdigest()

    @cached_property
    def closed(self) -> bool:
        """Every edge (vertices welded by position) is used once in each direction: a closed,
        consistently wound surface, whose back faces cannot be seen from outside."""
        _, weld = np.unique(np.round(np.asarray(self.positions, np.float64), 6), axis=0, return_inverse=True)
        tri = weld.reshape(-1)[np.asarray(self.indices, np.int64)]  # UV seams welded by position
        tri = tri[(tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 2] != tri[:, 0])]
        edges = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
        n = int(edges.max()) + 1
        forward = np.unique(edges[:, 0] * n + edges[:, 1])
        backward = np.unique(edges[:, 1] * n + edges[:, 0])
        return len(forward) == len(edges) and bool(np.array_equal(forward, backward))


class MeshError(ValueError):
    """A mesh file that cannot be read (the message names the file and the problem)."""


# ------------------------------------------------------------------ normals and tangents


def normalized(v: np.ndarray) -> np.ndarray:
    """Each row scaled to unit length (zero rows stay zero)."""
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n > 1e-20, n, 1.0)


def face_normals(positions: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """Area-weighted (unnormalised) face normals."""
    p = positions[indices]
    return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])


def vertex_normals(positions: np.ndarray, indices: np.ndarray) -> np.ndarray:
    acc = np.zeros_like(positions, dtype=np.float64)
    fn = face_normals(positions.astype(np.float64), indices)
    for k in range(3):
        np.add.at(acc, indices[:, k], fn)
    return normalized(acc)


def any_perpendicular(n: np.ndarray) -> np.ndarray:
    helper = np.where(np.abs(n[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    return normalized(np.cross(helper, n))


def orthonormal_tangents(tangents: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """Gram-Schmidt; a tangent parallel to its normal is replaced by any perpendicular."""
    t = tangents - normals * np.sum(tangents * normals, axis=1, keepdims=True)
    bad = np.linalg.norm(t, axis=1) < 1e-8
    t = normalized(t)
    if bad.any():
        t[bad] = any_perpendicular(normals[bad])
    return t


def uv_tangents(positions, uvs, indices, normals) -> np.ndarray:
    """Per-vertex +U tangents from the UV parameterisation (accumulated per triangle)."""
    p, uv = positions[indices].astype(np.float64), uvs[indices].astype(np.float64)
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    d1, d2 = uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    r = np.where(np.abs(det) > 1e-20, 1.0 / np.where(det == 0, 1, det), 0.0)
    t = (e1 * d2[:, 1:2] - e2 * d1[:, 1:2]) * r[:, None]
    acc = np.zeros_like(positions, dtype=np.float64)
    for k in range(3):
        np.add.at(acc, indices[:, k], t)
    return orthonormal_tangents(acc, normals.astype(np.float64))


def make_mesh(positions, indices, normals=None, uvs=None, tangents=None, metres_per_uv: float | None = None) -> Mesh:
    positions = np.asarray(positions, np.float64)
    indices = np.asarray(indices, np.int64).reshape(-1, 3)
    normals = vertex_normals(positions, indices) if normals is None else normalized(np.asarray(normals, np.float64))
    if uvs is None:
        uvs = spherical_uvs(positions)
    uvs = np.asarray(uvs, np.float64)
    tangents = (
        uv_tangents(positions, uvs, indices, normals)
        if tangents is None
        else orthonormal_tangents(np.asarray(tangents, np.float64), normals)
    )
    return Mesh(
        positions.astype("f4"),
        normals.astype("f4"),
        tangents.astype("f4"),
        uvs.astype("f4"),
        indices.astype("u4"),
        metres_per_uv,
    )


def spherical_uvs(positions: np.ndarray) -> np.ndarray:
    c = positions - positions.mean(0)
    d = normalized(c)
    return np.stack([0.5 + np.arctan2(d[:, 0], d[:, 2]) / (2 * np.pi), np.arccos(np.clip(d[:, 1], -1, 1)) / np.pi], 1)
