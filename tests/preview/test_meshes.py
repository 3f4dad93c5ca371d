"""Mesh generators and OBJ/PLY round trips."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.backends.preview import meshes as M
from cnlmc.backends.preview.mesh import face_normals
from cnlmc.backends.preview.mesh_io import MeshError, load_mesh, load_obj, load_ply, write_obj, write_ply


def open_edges(mesh: M.Mesh, tol: float = 1e-5) -> int:
    """Edges used by exactly one triangle after welding coincident vertices."""
    _, inverse = np.unique(np.round(mesh.positions / tol).astype(np.int64), axis=0, return_inverse=True)
    tri = inverse.ravel()[mesh.indices.astype(np.int64)]
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    edges = edges[edges[:, 0] != edges[:, 1]]
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return int((counts == 1).sum())


@pytest.mark.parametrize("name", sorted(M.MESHES))
def test_generated_meshes_are_sound(name):
    mesh = M.MESHES[name]()
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1, atol=1e-5)
    assert np.allclose(np.linalg.norm(mesh.tangents, axis=1), 1, atol=1e-5)
    assert np.abs(np.sum(mesh.normals * mesh.tangents, axis=1)).max() < 1e-4
    fn = face_normals(mesh.positions.astype(float), mesh.indices.astype(int))
    vn = mesh.normals[mesh.indices].mean(1)
    assert (np.einsum("ij,ij->i", fn, vn) >= 0).mean() > 0.99  # normals agree with winding
    if name in M.OPEN_MESHES:
        return
    assert M.signed_volume(mesh.positions, mesh.indices) > 0  # outward winding
    edges = len(mesh.indices) * 3 / 2
    assert open_edges(mesh) < 0.02 * edges  # watertight-ish


def test_the_leaf_is_an_open_sheet_facing_the_camera():
    """A thin material on it is seen on the side away from the light (docs/subsurface.md)."""
    mesh = M.leaf()
    assert not mesh.closed and open_edges(mesh) > 0
    assert (mesh.normals[:, 2] > 0.5).all()  # towards +z, where the preview's camera is
    lo, hi = mesh.bounds
    assert np.allclose(hi[:2] - lo[:2], [0.84, 2.0], atol=0.02)  # 10 cm x 4.2 cm at LEAF_UNIT_M


def test_sphere_is_watertight_and_round():
    mesh = M.sphere(32, 48)
    assert open_edges(mesh) == 0
    assert np.allclose(np.linalg.norm(mesh.positions, axis=1), 1, atol=1e-5)
    assert np.allclose(mesh.normals, mesh.positions, atol=1e-3)


def test_teapot_patch_table():
    patches = M.teapot_patches()
    assert patches.shape == (32, 4, 4, 3)
    fitted = M.fit(M.teapot())
    lo, hi = fitted.bounds
    assert abs(lo[1]) < 1e-6 and np.isclose(
        np.linalg.norm(fitted.positions - (lo + hi) / 2, axis=1).max(), 1, atol=1e-4
    )
    assert hi[0] - lo[0] > hi[1] - lo[1]  # spout to handle is wider than the pot is tall


@pytest.mark.parametrize("writer,loader,suffix", [(write_ply, load_ply, ".ply"), (write_obj, load_obj, ".obj")])
def test_round_trip(tmp_path, writer, loader, suffix):
    mesh = M.fit(M.shader_ball(24))
    path = tmp_path / f"mesh{suffix}"
    writer(mesh, path)
    back = loader(path)
    assert back.indices.shape == mesh.indices.shape
    assert np.allclose(back.positions[back.indices], mesh.positions[mesh.indices], atol=1e-5)
    assert np.allclose(back.normals[back.indices], mesh.normals[mesh.indices], atol=1e-4)
    assert np.allclose(back.uvs[back.indices], mesh.uvs[mesh.indices], atol=1e-5)


def test_ascii_ply_and_obj_polygons(tmp_path):
    ply = tmp_path / "quad.ply"
    ply.write_text(
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"
    )
    mesh = load_ply(ply)
    assert mesh.indices.shape == (2, 3) and np.allclose(mesh.normals, [0, 0, 1])
    obj = tmp_path / "quad.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")
    assert load_obj(obj).indices.shape == (2, 3)
    obj.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\n")  # negative indices
    assert load_obj(obj).indices.shape == (1, 3)


def test_bad_mesh_files_name_the_problem(tmp_path):
    with pytest.raises(MeshError, match="does not exist"):
        load_mesh(tmp_path / "missing.obj")
    bad = tmp_path / "bad.stl"
    bad.write_text("solid")
    with pytest.raises(MeshError, match="unsupported"):
        load_mesh(bad)
    broken = tmp_path / "broken.obj"
    broken.write_text("v 0 0 x\nf 1 2 3\n")
    with pytest.raises(MeshError, match="broken.obj:1"):
        load_obj(broken)


def test_help_and_the_unknown_mesh_error_list_every_mesh_of_the_table(tmp_path):
    """`cnlmc preview --help` and the unknown-mesh error name every built-in mesh (the table's,
    leaf included), read from MESHES rather than written by hand."""
    import subprocess
    import sys

    help_text = subprocess.run(
        [sys.executable, "-m", "cnlmc", "preview", "--help"], capture_output=True, text=True, check=True
    ).stdout
    with pytest.raises(MeshError) as error:
        M.mesh_by_name(str(tmp_path / "no_such_mesh"))
    for name in M.MESHES:
        assert name in " ".join(help_text.split()), name
        assert name in str(error.value), name
