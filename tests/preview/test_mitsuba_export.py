"""The preview scene exported for Mitsuba loads, renders, and draws the same picture."""
from __future__ import annotations

import numpy as np
import pytest

from .conftest import material_of


@pytest.fixture(scope="module")
def mitsuba():
    mi = pytest.importorskip("mitsuba")
    mi.set_variant("scalar_rgb")
    return mi


def test_exported_scene_renders_like_the_preview(tmp_path, mitsuba, renderer):
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.render import default_scene
    size = 32
    material = material_of("blue plastic")
    scene = default_scene("sphere", "studio", (size, size))
    scene.background = "transparent"
    path = export_scene(material, scene, tmp_path, size, size, spp=16)
    for name in ("scene.xml", "materials.xml", "mesh.ply", "environment.exr"):
        assert (tmp_path / name).exists(), name
    image, seconds = render_scene(path)
    assert image.shape == (size, size, 4) and np.isfinite(image).all()
    from cnlmc.backends.preview.render import Renderer
    frame = Renderer(size).render(material, tier="fis16", scene=scene, hdr=True)
    ours, theirs = frame.hdr[..., 3] > 0.5, image[..., 3] > 0.5
    assert (ours == theirs).mean() > 0.97                       # same camera and mesh
    both = ours & theirs
    ratio = frame.hdr[..., :3][both].mean(0) / image[..., :3][both].mean(0)
    assert np.all(np.abs(ratio - 1) < 0.25), ratio              # same lighting, roughly


def test_exported_scene_with_maps_loads(tmp_path, mitsuba):
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.render import default_scene
    scene = default_scene("teapot", "studio", (16, 16))
    path = export_scene(material_of("walnut"), scene, tmp_path, 16, 16, spp=2)
    image, _ = render_scene(path)
    assert np.isfinite(image).all() and (image[..., 3] > 0).any()
