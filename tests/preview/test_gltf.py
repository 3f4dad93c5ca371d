"""glTF 2.0 meshes: .glb round trip, a hand-written .gltf (data URI, node transforms, 16-bit
indices, interleaved vertices), and clear errors for what the preview cannot draw."""

from __future__ import annotations

import base64
import json
import struct

import numpy as np
import pytest

from cnlmc.backends.preview import meshes as M
from cnlmc.backends.preview.gltf import load_gltf, write_glb
from cnlmc.backends.preview.mesh_io import load_mesh
from cnlmc.backends.preview.meshes import MeshError
from tests.helpers import run_cnlmc


def test_glb_round_trip(tmp_path):
    mesh = M.fit(M.shader_ball(24))
    write_glb(mesh, tmp_path / "ball.glb")
    back = load_mesh(tmp_path / "ball.glb")
    assert back.indices.shape == mesh.indices.shape
    assert np.allclose(back.positions[back.indices], mesh.positions[mesh.indices], atol=1e-6)
    assert np.allclose(back.normals[back.indices], mesh.normals[mesh.indices], atol=1e-5)
    assert np.allclose(back.uvs[back.indices], mesh.uvs[mesh.indices], atol=1e-6)


def quad_gltf(node: dict, interleaved: bool = True, mode: int = 4) -> dict:
    """A unit quad in z = 0: positions and UVs interleaved (stride 20), uint16 indices."""
    pos = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], "<f4")
    uv = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], "<f4")  # glTF: v = 0 at the image top
    vertices = np.hstack([pos, uv]).tobytes() if interleaved else pos.tobytes() + uv.tobytes()
    indices = np.array([0, 1, 2, 0, 2, 3], "<u2").tobytes()
    blob = vertices + indices
    stride = {"byteStride": 20} if interleaved else {}
    views = [
        {"buffer": 0, "byteOffset": 0, "byteLength": 80, **stride},
        {"buffer": 0, "byteOffset": 80, "byteLength": 12},
    ]
    uv_accessor = {
        "bufferView": 0,
        "byteOffset": 12 if interleaved else 48,
        "componentType": 5126,
        "count": 4,
        "type": "VEC2",
    }
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"children": [1], "translation": [0, 0, 5]}, node],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "mode": mode}]}],
        "buffers": [
            {"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}
        ],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
            uv_accessor,
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }


def test_gltf_with_data_uri_interleaved_vertices_and_node_transforms(tmp_path):
    path = tmp_path / "quad.gltf"
    path.write_text(json.dumps(quad_gltf({"mesh": 0, "scale": [2, 2, 2]})))
    mesh = load_gltf(path)
    assert mesh.indices.shape == (2, 3)
    assert np.allclose(mesh.positions.min(0), [0, 0, 5]) and np.allclose(mesh.positions.max(0), [2, 2, 5])
    assert np.allclose(mesh.normals, [0, 0, 1], atol=1e-6)  # derived, counter-clockwise
    corner = np.argmin(np.linalg.norm(mesh.positions - [0, 0, 5], axis=1))
    assert np.allclose(mesh.uvs[corner], [0, 0])  # v flipped to the preview's convention


def test_gltf_rotation_and_separate_buffers(tmp_path):
    half = np.sqrt(0.5)  # 90 degrees about +y
    doc = quad_gltf({"mesh": 0, "rotation": [0, half, 0, half]}, interleaved=False)
    blob = base64.b64decode(doc["buffers"][0]["uri"].split(",")[1])
    (tmp_path / "quad.bin").write_bytes(blob)
    doc["buffers"][0]["uri"] = "quad.bin"
    path = tmp_path / "quad.gltf"
    path.write_text(json.dumps(doc))
    mesh = load_gltf(path)
    assert np.allclose(mesh.normals, [1, 0, 0], atol=1e-6)  # +z turned to +x
    assert np.allclose(mesh.positions[:, 0], 0, atol=1e-6)  # x -> -z, then the parent's +5
    assert set(np.round(mesh.positions[:, 2], 5)) == {4.0, 5.0}


def test_gltf_errors_name_the_file_and_reason(tmp_path):
    lines = tmp_path / "lines.gltf"
    lines.write_text(json.dumps(quad_gltf({"mesh": 0}, mode=1)))
    with pytest.raises(MeshError, match="only triangles"):
        load_gltf(lines)
    broken = tmp_path / "broken.glb"
    broken.write_bytes(b"glTF" + struct.pack("<II", 2, 20) + b"\0" * 8)
    with pytest.raises(MeshError, match="broken.glb"):
        load_gltf(broken)
    garbage = tmp_path / "garbage.gltf"
    garbage.write_text("{not json")
    with pytest.raises(MeshError, match="garbage.gltf: not a readable glTF"):
        load_gltf(garbage)


def test_cli_previews_a_glb(tmp_path, renderer):
    write_glb(M.fit(M.teapot()), tmp_path / "teapot.glb")
    (tmp_path / "m.cnl").write_text("hammered copper\n")
    proc = run_cnlmc(
        *("preview", str(tmp_path / "m.cnl"), "--mesh", str(tmp_path / "teapot.glb")),
        *("--size", "64", "-o", str(tmp_path / "p.png")),
    )
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "p.png").stat().st_size > 1000
