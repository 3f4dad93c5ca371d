"""glTF 2.0 meshes in (`.gltf` with external or data-URI buffers, binary `.glb`) and `.glb` out.

Reading takes every triangle primitive of the default scene's nodes (each placed by its
node's world transform: `matrix`, or translation/rotation/scale), with POSITION, NORMAL and
TEXCOORD_0 when present (missing normals/UVs are derived by `make_mesh`), and indices of any
integer type. glTF puts the image's top row at v = 0 and the preview at v = 1, so v is
flipped. Anything the preview cannot draw is a MeshError naming the file and the reason.
"""

from __future__ import annotations

import base64
import json
import struct
from pathlib import Path

import numpy as np

from .mesh import Mesh, MeshError, make_mesh

GLB_MAGIC, JSON_CHUNK, BIN_CHUNK = 0x46546C67, 0x4E4F534A, 0x004E4942
COMPONENTS = {5120: "i1", 5121: "u1", 5122: "<i2", 5123: "<u2", 5125: "<u4", 5126: "<f4"}
WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
TRIANGLES = 4


# ----------------------------------------------------------------------------- reading


def load_gltf(path) -> Mesh:
    path = Path(path)
    try:
        doc, binary = _read_container(path)
        buffers = [_buffer(path, b, binary) for b in doc.get("buffers", [])]
        parts = [_primitive(doc, buffers, p, world) for p, world in _placed_primitives(doc)]
    except MeshError:
        raise
    except (KeyError, IndexError, TypeError, ValueError, struct.error, OSError) as exc:
        raise MeshError(f"{path}: not a readable glTF 2.0 file ({exc.__class__.__name__}: {exc})") from None
    if not parts:
        raise MeshError(f"{path}: no triangle meshes in the scene")
    return _merge(parts)


def _read_container(path: Path) -> tuple[dict, bytes | None]:
    data = path.read_bytes()
    if data[:4] != b"glTF":
        return json.loads(data.decode("utf-8")), None
    magic, version, _length = struct.unpack_from("<III", data, 0)
    if version != 2:
        raise MeshError(f"{path}: glTF version {version}; only 2 is read")
    doc, binary, offset = None, None, 12
    while offset + 8 <= len(data):
        size, kind = struct.unpack_from("<II", data, offset)
        chunk = data[offset + 8 : offset + 8 + size]
        if kind == JSON_CHUNK:
            doc = json.loads(chunk.decode("utf-8"))
        elif kind == BIN_CHUNK and binary is None:
            binary = chunk
        offset += 8 + size
    if doc is None:
        raise MeshError(f"{path}: a .glb without its JSON chunk")
    return doc, binary


def _buffer(path: Path, buffer: dict, binary: bytes | None) -> bytes:
    uri = buffer.get("uri")
    if uri is None:
        if binary is None:
            raise MeshError(f"{path}: a buffer without a URI and no binary chunk")
        return binary
    if uri.startswith("data:"):
        return base64.b64decode(uri.split(",", 1)[1])
    return (path.parent / uri).read_bytes()


def _accessor(doc: dict, buffers: list, index: int) -> np.ndarray:
    acc = doc["accessors"][index]
    if "sparse" in acc or "bufferView" not in acc:
        raise MeshError(f"accessor {index}: sparse or view-less accessors are not supported")
    view = doc["bufferViews"][acc["bufferView"]]
    dtype, width, count = np.dtype(COMPONENTS[acc["componentType"]]), WIDTHS[acc["type"]], acc["count"]
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    stride = view.get("byteStride") or dtype.itemsize * width
    raw = buffers[view["buffer"]]
    rows = np.ndarray((count, width), dtype, raw, start, (stride, dtype.itemsize))
    values = rows.astype(np.float64)
    if acc.get("normalized") and dtype.kind in "iu":
        values /= float(np.iinfo(dtype).max)
    return values


def _node_matrix(node: dict) -> np.ndarray:
    if "matrix" in node:
        return np.array(node["matrix"], np.float64).reshape(4, 4).T  # column-major
    x, y, z, w = node.get("rotation", (0.0, 0.0, 0.0, 1.0))
    rotation = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )
    m = np.eye(4)
    m[:3, :3] = rotation * np.asarray(node.get("scale", (1.0, 1.0, 1.0)))
    m[:3, 3] = node.get("translation", (0.0, 0.0, 0.0))
    return m


def _placed_primitives(doc: dict):
    """(primitive, world matrix) for every mesh node of the default scene (or, without
    scenes, every mesh at the origin)."""
    nodes = doc.get("nodes", [])
    scenes = doc.get("scenes")
    if not scenes:
        for mesh in doc.get("meshes", []):
            for prim in mesh["primitives"]:
                yield prim, np.eye(4)
        return
    stack = [(i, np.eye(4)) for i in scenes[doc.get("scene", 0)].get("nodes", [])]
    seen = 0
    while stack:
        index, parent = stack.pop()
        seen += 1
        if seen > 100_000:
            raise MeshError("the node hierarchy does not end (a cycle?)")
        node = nodes[index]
        world = parent @ _node_matrix(node)
        if "mesh" in node:
            for prim in doc["meshes"][node["mesh"]]["primitives"]:
                yield prim, world
        stack += [(child, world) for child in node.get("children", [])]


def _primitive(doc: dict, buffers: list, prim: dict, world: np.ndarray) -> dict:
    if prim.get("mode", TRIANGLES) != TRIANGLES:
        raise MeshError(f"a primitive of mode {prim['mode']} (only triangles, mode 4, are drawn)")
    attrs = prim["attributes"]
    positions = _accessor(doc, buffers, attrs["POSITION"])[:, :3]
    indices = (
        _accessor(doc, buffers, prim["indices"])[:, 0].astype(np.int64)
        if "indices" in prim
        else np.arange(len(positions))
    )
    if len(indices) % 3 or (len(indices) and (indices.min() < 0 or indices.max() >= len(positions))):
        raise MeshError("triangle indices out of range or not a multiple of three")
    if np.linalg.det(world[:3, :3]) < 0:  # a mirroring transform flips the winding
        indices = indices.reshape(-1, 3)[:, ::-1].ravel()
    part = {"positions": positions @ world[:3, :3].T + world[:3, 3], "indices": indices.reshape(-1, 3)}
    if "NORMAL" in attrs:
        part["normals"] = _accessor(doc, buffers, attrs["NORMAL"])[:, :3] @ np.linalg.inv(world[:3, :3])
    if "TEXCOORD_0" in attrs:
        uv = _accessor(doc, buffers, attrs["TEXCOORD_0"])[:, :2]
        part["uvs"] = np.column_stack([uv[:, 0], 1.0 - uv[:, 1]])
    return part


def _merge(parts: list[dict]) -> Mesh:
    offsets = np.cumsum([0] + [len(p["positions"]) for p in parts[:-1]])
    positions = np.concatenate([p["positions"] for p in parts])
    indices = np.concatenate([p["indices"] + o for p, o in zip(parts, offsets)])
    normals = np.concatenate([p["normals"] for p in parts]) if all("normals" in p for p in parts) else None
    uvs = np.concatenate([p["uvs"] for p in parts]) if all("uvs" in p for p in parts) else None
    return make_mesh(positions, indices, normals, uvs)


# ----------------------------------------------------------------------------- writing


def write_glb(mesh: Mesh, path) -> None:
    """One mesh, one primitive: float positions/normals/UVs (v flipped back) and uint32 indices."""
    uvs = np.column_stack([mesh.uvs[:, 0], 1.0 - mesh.uvs[:, 1]])
    arrays = [np.asarray(a, "<f4") for a in (mesh.positions, mesh.normals, uvs)] + [np.asarray(mesh.indices, "<u4")]
    blob, views, offset = b"", [], 0
    for array in arrays:
        data = array.tobytes()
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(data)})
        blob += data + b"\0" * (-len(data) % 4)
        offset = len(blob)
    lo, hi = mesh.positions.min(0), mesh.positions.max(0)
    accessors = [
        {
            "bufferView": 0,
            "componentType": 5126,
            "count": len(mesh.positions),
            "type": "VEC3",
            "min": [float(x) for x in lo],
            "max": [float(x) for x in hi],
        },
        {"bufferView": 1, "componentType": 5126, "count": len(mesh.normals), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
        {"bufferView": 3, "componentType": 5125, "count": mesh.indices.size, "type": "SCALAR"},
    ]
    doc = {
        "asset": {"version": "2.0", "generator": "cnlmc"},
        "buffers": [{"byteLength": len(blob)}],
        "bufferViews": views,
        "accessors": accessors,
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
    }
    text = json.dumps(doc).encode("utf-8")
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), JSON_CHUNK) + text + struct.pack("<II", len(blob), BIN_CHUNK) + blob
    Path(path).write_bytes(struct.pack("<III", GLB_MAGIC, 2, 12 + len(body)) + body)
