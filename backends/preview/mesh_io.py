"""User meshes: OBJ (v/vt/vn, polygons fanned), PLY (ascii, binary little/big endian) and glTF 2.0
(.gltf/.glb, gltf.py) in;
PLY (binary, what Mitsuba reads) and OBJ out. Missing normals/UVs/tangents are derived."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from .gltf import load_gltf
from .mesh import Mesh, MeshError, make_mesh

PLY_TYPES = {
    "char": "i1",
    "int8": "i1",
    "uchar": "u1",
    "uint8": "u1",
    "short": "i2",
    "int16": "i2",
    "ushort": "u2",
    "uint16": "u2",
    "int": "i4",
    "int32": "i4",
    "uint": "u4",
    "uint32": "u4",
    "float": "f4",
    "float32": "f4",
    "double": "f8",
    "float64": "f8",
}
UV_NAMES = (("u", "v"), ("s", "t"), ("texture_u", "texture_v"))


# ------------------------------------------------------------------------------- OBJ


def _obj_index(token: str, count: int) -> int:
    i = int(token)
    return i - 1 if i > 0 else count + i


def load_obj(path) -> Mesh:
    v, vt, vn, corners = [], [], [], []
    for number, line in enumerate(Path(path).read_text("utf-8", errors="replace").splitlines(), 1):
        parts = line.split()
        if not parts:
            continue
        try:
            if parts[0] == "v":
                v.append([float(x) for x in parts[1:4]])
            elif parts[0] == "vt":
                vt.append([float(x) for x in parts[1:3]])
            elif parts[0] == "vn":
                vn.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                refs = [(p.split("/") + ["", ""])[:3] for p in parts[1:]]
                face = [
                    tuple(_obj_index(r[k], n) if r[k] else -1 for k, n in ((0, len(v)), (1, len(vt)), (2, len(vn))))
                    for r in refs
                ]
                corners += [(face[0], face[k], face[k + 1]) for k in range(1, len(face) - 1)]
        except (ValueError, IndexError) as exc:
            raise MeshError(f"{path}:{number}: cannot read {line.strip()!r} ({exc})") from None
    if not v or not corners:
        raise MeshError(f"{path}: no vertices or faces")
    return _unify(np.array(v), np.array(vt) if vt else None, np.array(vn) if vn else None, corners, path)


def _unify(v, vt, vn, corners, path) -> Mesh:
    """OBJ corners (v, vt, vn) -> one vertex per distinct triple."""
    triples = np.array(corners, np.int64).reshape(-1, 3)
    if triples[:, 0].max() >= len(v) or triples[:, 0].min() < 0:
        raise MeshError(f"{path}: a face refers to a vertex that does not exist")
    keys, inverse = np.unique(triples, axis=0, return_inverse=True)
    pos = v[keys[:, 0]]
    uvs = vt[np.clip(keys[:, 1], 0, None)] if vt is not None and (keys[:, 1] >= 0).all() else None
    normals = vn[np.clip(keys[:, 2], 0, None)] if vn is not None and (keys[:, 2] >= 0).all() else None
    return make_mesh(pos, inverse.reshape(-1, 3), normals, uvs)


def write_obj(mesh: Mesh, path) -> None:
    lines = [f"v {x:.7g} {y:.7g} {z:.7g}" for x, y, z in mesh.positions]
    lines += [f"vt {u:.7g} {v:.7g}" for u, v in mesh.uvs]
    lines += [f"vn {x:.7g} {y:.7g} {z:.7g}" for x, y, z in mesh.normals]
    lines += ["f " + " ".join(f"{i + 1}/{i + 1}/{i + 1}" for i in tri) for tri in mesh.indices]
    Path(path).write_text("\n".join(lines) + "\n")


# ------------------------------------------------------------------------------- PLY


def _ply_header(f, path):
    if f.readline().strip() != b"ply":
        raise MeshError(f"{path}: not a PLY file")
    fmt: str | None = None
    elements: list[dict[str, Any]] = []
    while True:
        line = f.readline()
        if not line:
            raise MeshError(f"{path}: PLY header has no end_header")
        parts = line.decode("ascii", "replace").split()
        if not parts or parts[0] in ("comment", "obj_info"):
            continue
        if parts[0] == "end_header":
            return fmt, elements
        if parts[0] == "format":
            fmt = parts[1]
        elif parts[0] == "element":
            elements.append({"name": parts[1], "count": int(parts[2]), "props": []})
        elif parts[0] == "property":
            elements[-1]["props"].append(parts[1:])


def _read_binary_element(f, element, endian):
    props = element["props"]
    if all(p[0] != "list" for p in props):
        dtype = np.dtype([(p[1], endian + PLY_TYPES[p[0]]) for p in props])
        return np.frombuffer(f.read(dtype.itemsize * element["count"]), dtype, element["count"]), None
    if len(props) != 1:
        raise MeshError("PLY: only faces with a single list property are supported")
    _, count_t, index_t, _ = props[0]
    ct, it = np.dtype(endian + PLY_TYPES[count_t]), np.dtype(endian + PLY_TYPES[index_t])
    faces = []
    for _ in range(element["count"]):
        n = int(np.frombuffer(f.read(ct.itemsize), ct)[0])
        faces.append(np.frombuffer(f.read(it.itemsize * n), it).astype(np.int64))
    return None, faces


def _read_ascii_element(f, element):
    rows = [f.readline().split() for _ in range(element["count"])]
    if any(p[0] == "list" for p in element["props"]):
        return None, [np.array(r[1 : 1 + int(r[0])], np.int64) for r in rows]
    names = [p[1] for p in element["props"]]
    data = np.array(rows, np.float64).reshape(-1, len(names))
    return {n: data[:, k] for k, n in enumerate(names)}, None


def load_ply(path) -> Mesh:
    with open(path, "rb") as f:
        fmt, elements = _ply_header(f, path)
        vertices, faces = None, None
        for element in elements:
            if fmt == "ascii":
                table, lists = _read_ascii_element(f, element)
            elif fmt in ("binary_little_endian", "binary_big_endian"):
                table, lists = _read_binary_element(f, element, "<" if fmt == "binary_little_endian" else ">")
            else:
                raise MeshError(f"{path}: unknown PLY format {fmt!r}")
            if element["name"] == "vertex":
                vertices = table
            elif element["name"] == "face":
                faces = lists
    if vertices is None or not faces:
        raise MeshError(f"{path}: PLY has no vertex or face element")
    col = lambda n: np.asarray(vertices[n], np.float64)
    names = vertices.dtype.names if hasattr(vertices, "dtype") else tuple(vertices)
    pos = np.stack([col("x"), col("y"), col("z")], 1)
    normals = np.stack([col("nx"), col("ny"), col("nz")], 1) if "nx" in names else None
    uvs = next((np.stack([col(a), col(b)], 1) for a, b in UV_NAMES if a in names), None)
    tris = [(face[0], face[k], face[k + 1]) for face in faces for k in range(1, len(face) - 1)]
    return make_mesh(pos, np.array(tris, np.int64), normals, uvs)


def write_ply(mesh: Mesh, path, flip_v: bool = False) -> None:
    """Binary little-endian PLY with normals and UVs (u, v), triangles as uchar/int lists.

    `flip_v` writes v' = 1 - v: Mitsuba 3 samples a bitmap's top row at v = 0 and does not flip
    PLY texture coordinates (its OBJ loader does), while our UVs put the top row at v = 1."""
    n, m = len(mesh.positions), len(mesh.indices)
    header = (
        "ply\nformat binary_little_endian 1.0\ncomment cnlmc preview mesh\n"
        f"element vertex {n}\n"
        + "".join(f"property float {p}\n" for p in ("x", "y", "z", "nx", "ny", "nz", "u", "v"))
        + f"element face {m}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    uvs = np.column_stack([mesh.uvs[:, 0], 1.0 - mesh.uvs[:, 1]]) if flip_v else mesh.uvs
    verts = np.hstack([mesh.positions, mesh.normals, uvs]).astype("<f4")
    faces = np.zeros(m, np.dtype([("n", "u1"), ("i", "<i4", (3,))]))
    faces["n"], faces["i"] = 3, mesh.indices.astype("<i4")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(verts.tobytes())
        f.write(faces.tobytes())


LOADERS = {".obj": load_obj, ".ply": load_ply, ".gltf": load_gltf, ".glb": load_gltf}


def load_mesh(path) -> Mesh:
    path = Path(path)
    if not path.exists():
        raise MeshError(f"mesh file {path} does not exist")
    loader = LOADERS.get(path.suffix.lower())
    if loader is None:
        raise MeshError(f"{path}: unsupported mesh format {path.suffix!r} (known: {', '.join(LOADERS)})")
    return loader(path)
