"""Preview meshes: generated in numpy (sphere, shader ball, Newell teapot) or loaded (OBJ, PLY,
glTF: mesh_io.py). World space is y-up; `MESHES` maps a name to its generator. `fit()` scales a
mesh to a unit bounding sphere standing on y = 0. The mesh type itself is in mesh.py.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from .mesh import Mesh, MeshError, make_mesh, normalized, vertex_normals
from .mesh_io import load_mesh

__all__ = ["MESHES", "Mesh", "MeshError", "fit", "leaf", "make_mesh", "mesh_by_name", "shader_ball", "sphere", "teapot"]

DATA = Path(__file__).parent / "data"

#: Metres one UV unit of a generated mesh spans: the stdlib maps' texture unit (stdlib/graphs/*.toml,
#: `scale.metres_per_unit`), so a map shows at its real size. Our choice: pi x 5 cm, so the 10 cm
#: sphere's equator is exactly two units and every periodic map closes around it without a seam.
UV_UNIT_M = math.pi * 0.05

#: The stated real sizes of the generated meshes (what their UVs measure; `fit()` scales the
#: positions for the frame and keeps the UVs). Our choice: hand-held sample objects.
SPHERE_DIAMETER_M = 0.10  # a 10 cm ball (issue #15)
SHADER_BALL_UNIT_M = 0.06  # profile units -> metres: a 9.6 cm ball on a pedestal, 11.4 cm tall
TEAPOT_UNIT_M = 0.04  # one unit of Newell's data: 26 cm spout to handle, 12.6 cm tall (a ~1 l teapot)
LEAF_UNIT_M = 0.05  # a 10 cm leaf blade, 4.2 cm wide


def grid_indices(rows: int, cols: int, offset: int = 0) -> np.ndarray:
    """Two triangles per cell of a (rows+1) x (cols+1) vertex grid (row-major)."""
    i, j = np.meshgrid(np.arange(rows), np.arange(cols), indexing="ij")
    a = (i * (cols + 1) + j).ravel() + offset
    b, c, d = a + 1, a + cols + 1, a + cols + 2
    return np.concatenate([np.stack([a, c, b], 1), np.stack([b, c, d], 1)])


# ------------------------------------------------------------------------ generators


def lathe(profile: list[tuple[float, float]], segments: int = 96, unit_m: float = 0.05) -> Mesh:
    """A surface of revolution about +y of one smooth polyline (r, y), from bottom to top.

    Normals come from the profile's tangent, so each call is one smoothly shaded part. UVs are in
    UV_UNIT_M at the stated size (`unit_m` metres per profile unit): u is the arc length around the
    widest circle of the part, v the arc length up the profile; u starts (the seam) at the back (-z)."""
    prof = np.asarray(profile, np.float64)
    d = np.gradient(prof, axis=0)
    n2 = normalized(np.stack([d[:, 1], -d[:, 0]], 1))  # outward normal of the profile (r, y)
    on_axis = prof[:, 0] < 1e-9  # poles: the normal is the axis itself
    n2[on_axis] = np.stack([np.zeros(on_axis.sum()), np.sign(n2[on_axis, 1])], 1)
    phi = np.linspace(np.pi, 3 * np.pi, segments + 1)  # from the back (-z) round to the back
    s, c = np.sin(phi)[None, :], np.cos(phi)[None, :]
    r, y = prof[:, :1], prof[:, 1:]
    shape = (len(prof), segments + 1)
    pos = np.stack([r * s, np.broadcast_to(y, shape), r * c], -1)
    nor = np.stack([n2[:, :1] * s, np.broadcast_to(n2[:, 1:], shape), n2[:, :1] * c], -1)
    tan = np.stack([c, np.zeros_like(c), -s], -1) * np.ones((len(prof), 1, 1))
    arc = np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(prof, axis=0), axis=1))])
    metres = unit_m / UV_UNIT_M
    v = np.broadcast_to((arc * metres)[:, None], pos.shape[:2])
    u = np.broadcast_to(((phi - np.pi) * float(prof[:, 0].max()) * metres)[None, :], pos.shape[:2])
    idx = grid_indices(len(prof) - 1, segments)
    idx = idx[:, [0, 2, 1]]  # counter-clockwise from outside
    uvs = np.stack([u, v], -1).reshape(-1, 2)
    return make_mesh(pos.reshape(-1, 3), idx, nor.reshape(-1, 3), uvs, tan.reshape(-1, 3), UV_UNIT_M)


def merge(meshes: list[Mesh]) -> Mesh:
    offsets = np.cumsum([0] + [len(m.positions) for m in meshes[:-1]])
    cat = lambda attr: np.concatenate([getattr(m, attr) for m in meshes])
    return Mesh(
        cat("positions"),
        cat("normals"),
        cat("tangents"),
        cat("uvs"),
        np.concatenate([m.indices + o for m, o in zip(meshes, offsets)]).astype("u4"),
        meshes[0].metres_per_uv if len({m.metres_per_uv for m in meshes}) == 1 else None,
    )


def arc(cx: float, cy: float, radius: float, a0: float, a1: float, steps: int) -> list[tuple[float, float]]:
    t = np.linspace(a0, a1, steps)
    return [(max(cx + radius * math.cos(a), 0.0), cy + radius * math.sin(a)) for a in t]


def sphere(rings: int = 64, segments: int = 96) -> Mesh:
    """Unit sphere centred at the origin (poles on y); its UVs are those of the 10 cm ball
    (SPHERE_DIAMETER_M): u in [0, 2] round the equator, v in [0, 1] from pole to pole."""
    return lathe(arc(0.0, 0.0, 1.0, -math.pi / 2, math.pi / 2, rings + 1), segments, SPHERE_DIAMETER_M / 2)


#: the largest distance (pixels) between the tessellated silhouette and the true sphere's.
SILHOUETTE_ERROR_PX = 0.25


def sphere_segments(radius_px: float, error_px: float = SILHOUETTE_ERROR_PX) -> tuple[int, int]:
    """(rings, segments) of a sphere drawn `radius_px` pixels wide whose silhouette polygon stays
    within `error_px` of the circle: a chord over angle 2π/n sags r·(1 − cos(π/n)). Segments a
    multiple of 8 and rings even keep the poles, the equator and ±x, ±z on the mesh (the
    bounds, hence the framing, are the same at every level); at least 32 segments."""
    r = max(float(radius_px), 1.0)
    n = math.pi / math.acos(max(1.0 - error_px / r, -1.0)) if error_px < r else 1.0
    segments = max(32, 8 * math.ceil(n / 8))
    return 2 * round(segments / 3), segments


def sphere_for_pixels(radius_px: float) -> Mesh:
    """The fitted sphere with no more triangles than its size on screen needs: 4k triangles for
    a 256² preview, 7k at 512², 15k at 1024² (a renderer keeps the one it uses: Renderer.scene)."""
    return fit(sphere(*sphere_segments(radius_px)))


def shader_ball(segments: int = 96) -> Mesh:
    """A shader-ball-like form: a sphere with a recessed equatorial groove on a stepped pedestal."""
    ball_c, ball_r = 1.1, 0.8
    parts = [
        [(0.0, 0.0), (0.55, 0.0)],  # base underside
        [(0.55, 0.0), (0.55, 0.12)],  # base rim
        [(0.55, 0.12), (0.22, 0.12)],  # base top
        [(0.22, 0.12), (0.22, ball_c - ball_r * math.cos(0.28))],  # neck
        arc(0.0, ball_c, ball_r, -math.pi / 2 + 0.28, -0.12, 28),  # lower ball
        [
            (ball_r * math.cos(0.12), ball_c - ball_r * math.sin(0.12)),
            (0.68, ball_c - ball_r * math.sin(0.12)),
        ],  # groove floor (lower)
        [(0.68, ball_c - ball_r * math.sin(0.12)), (0.68, ball_c + ball_r * math.sin(0.12))],
        [
            (0.68, ball_c + ball_r * math.sin(0.12)),
            (ball_r * math.cos(0.12), ball_c + ball_r * math.sin(0.12)),
        ],  # groove ceiling
        arc(0.0, ball_c, ball_r, 0.12, math.pi / 2, 28),  # upper ball
    ]
    # One walk up the outside: every part has the outside on its right (outward normals).
    return merge([lathe(p, segments, SHADER_BALL_UNIT_M) for p in parts])


def _read_teapot() -> tuple[np.ndarray, np.ndarray]:
    text = (DATA / "teapot.txt").read_text("utf-8")
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.startswith("#")]
    n_patches = int(lines[0])
    patches = np.array([[int(i) - 1 for i in ln.split(",")] for ln in lines[1 : 1 + n_patches]])
    n_points = int(lines[1 + n_patches])
    points = np.array([[float(x) for x in ln.split(",")] for ln in lines[2 + n_patches : 2 + n_patches + n_points]])
    return patches, points


def teapot_patches() -> np.ndarray:
    """(32, 4, 4, 3) control points of the Newell teapot, z up, as published."""
    patches, points = _read_teapot()
    return points[patches].reshape(-1, 4, 4, 3)


def bernstein(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    s = 1.0 - t
    b = np.stack([s**3, 3 * s * s * t, 3 * s * t * t, t**3], -1)
    db = np.stack([-3 * s * s, 3 * s * s - 6 * s * t, 6 * s * t - 3 * t * t, 3 * t * t], -1)
    return b, db


def _weld(positions: np.ndarray, indices: np.ndarray, tol: float = 1e-5):
    keys = np.round(positions / tol).astype(np.int64)
    _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    return positions[first], inverse.ravel()[indices], first


def teapot(steps: int = 12) -> Mesh:
    """The Newell teapot tessellated (steps x steps quads per patch), y up, welded seams."""
    ctrl = teapot_patches()
    t = np.linspace(0.0, 1.0, steps + 1)
    b, _ = bernstein(t)
    pos = np.einsum("ui,vj,pijc->puvc", b, b, ctrl)  # (P, u, v, 3)
    P = len(ctrl)
    idx = np.concatenate([grid_indices(steps, steps, p * (steps + 1) ** 2) for p in range(P)])
    uvs = patch_uvs(pos, t).reshape(-1, 2)
    flat = pos.reshape(-1, 3)
    flat = flat[:, [0, 2, 1]] * [1.0, 1.0, -1.0]  # z-up -> y-up (right-handed)
    welded, widx, first = _weld(flat, idx)
    keep = (widx[:, 0] != widx[:, 1]) & (widx[:, 1] != widx[:, 2]) & (widx[:, 0] != widx[:, 2])
    widx = widx[keep]
    if signed_volume(welded, widx) < 0:  # make the winding outward
        widx = widx[:, [0, 2, 1]]
    normals = vertex_normals(welded, widx)
    return make_mesh(welded, widx, normals, uvs[first], metres_per_uv=UV_UNIT_M)


def patch_uvs(pos: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(P, n, n, 2) UVs of tessellated patches in UV_UNIT_M at TEAPOT_UNIT_M: each patch's (s, t)
    scaled by its mean arc length along s and along t, so a map keeps its real size on every patch."""
    along_s = np.linalg.norm(np.diff(pos, axis=1), axis=-1).sum(axis=1).mean(axis=1)  # (P,)
    along_t = np.linalg.norm(np.diff(pos, axis=2), axis=-1).sum(axis=2).mean(axis=1)
    metres = TEAPOT_UNIT_M / UV_UNIT_M
    s, tt = np.meshgrid(t, t, indexing="ij")
    return np.stack([s[None] * along_s[:, None, None], tt[None] * along_t[:, None, None]], -1) * metres


def signed_volume(positions: np.ndarray, indices: np.ndarray) -> float:
    p = positions[indices].astype(np.float64)
    return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0)


def fit(mesh: Mesh, stand: bool = True) -> Mesh:
    """Scale to a unit bounding sphere (about the box centre); `stand` puts the base on y = 0."""
    lo, hi = mesh.bounds
    centre = (lo + hi) / 2
    radius = float(np.linalg.norm(mesh.positions - centre, axis=1).max()) or 1.0
    pos = (mesh.positions - centre) / radius
    if stand:
        pos[:, 1] -= pos[:, 1].min()
    return Mesh(pos.astype("f4"), mesh.normals, mesh.tangents, mesh.uvs, mesh.indices, mesh.metres_per_uv)


def leaf(rows: int = 48, cols: int = 24) -> Mesh:
    """An open, gently curved leaf blade facing +z (the camera): 2 units long on y, its half-width
    0.42 (1 - s^2)^0.75 tapering to both tips, bent back into a trough along its midrib
    (z = 0.35 x^2 + 0.12 y^2). A thin sheet on it is lit from one side and seen from the other,
    as a leaf is (a closed mesh holds a cavity: docs/subsurface.md). UVs in UV_UNIT_M at
    LEAF_UNIT_M metres a unit (a 10 cm leaf)."""
    s = np.linspace(-1.0, 1.0, rows + 1)[:, None]
    t = np.linspace(-1.0, 1.0, cols + 1)[None, :]
    x = t * 0.42 * (1.0 - s**2) ** 0.75
    y = s * np.ones_like(t)
    pos = np.stack([x, y, 0.35 * x**2 + 0.12 * y**2], -1).reshape(-1, 3)
    nor = np.stack([-0.7 * x, -0.24 * y, np.ones_like(x)], -1).reshape(-1, 3)  # (-dz/dx, -dz/dy, 1)
    uvs = np.stack([x, y], -1).reshape(-1, 2) * (LEAF_UNIT_M / UV_UNIT_M)
    idx = grid_indices(rows, cols)[:, [0, 2, 1]]  # counter-clockwise seen from +z
    return make_mesh(pos, idx, nor, uvs, metres_per_uv=UV_UNIT_M)


#: name -> generator (no arguments). `load_mesh` also accepts a path to an OBJ/PLY file.
MESHES: dict[str, Callable[[], Mesh]] = {"sphere": sphere, "shader_ball": shader_ball, "teapot": teapot, "leaf": leaf}
#: the generated meshes that are open sheets, not solids (no inside: a thin material has no cavity)
OPEN_MESHES = ("leaf",)
MESH_FORMATS = ".obj/.ply/.gltf/.glb"


def mesh_choices() -> str:
    """The built-in meshes as help and error messages list them (from MESHES, never by hand)."""
    return ", ".join(MESHES)


def mesh_by_name(name_or_path: str) -> Mesh:
    if name_or_path in MESHES:
        return MESHES[name_or_path]()
    if not Path(name_or_path).exists():
        raise MeshError(f"mesh file {name_or_path} does not exist (or use one of: {mesh_choices()})")
    return load_mesh(name_or_path)
