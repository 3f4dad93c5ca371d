"""The preview scene exported for Mitsuba loads, renders, and draws the same picture."""

from __future__ import annotations

import dataclasses

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

    frame = Renderer(size, resources=renderer.resources).render(material, tier="fis16", scene=scene, hdr=True)
    ours, theirs = frame.hdr[..., 3] > 0.5, image[..., 3] > 0.5
    assert (ours == theirs).mean() > 0.97  # same camera and mesh
    both = ours & theirs
    ratio = frame.hdr[..., :3][both].mean(0) / image[..., :3][both].mean(0)
    assert np.all(np.abs(ratio - 1) < 0.25), ratio  # same lighting, roughly


def test_exported_scene_with_maps_loads(tmp_path, mitsuba):
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.render import default_scene

    scene = default_scene("teapot", "studio", (16, 16))
    path = export_scene(material_of("walnut"), scene, tmp_path, 16, 16, spp=2)
    image, _ = render_scene(path)
    assert np.isfinite(image).all() and (image[..., 3] > 0).any()


def _halves_pattern(size: int) -> np.ndarray:
    """Image top half red, bottom half blue (maps convention: top row at v = 1)."""
    img = np.zeros((size, size, 3), np.float32)
    img[: size // 2, :, 0] = 1.0
    img[size // 2 :, :, 2] = 1.0
    return img


def test_texture_orientation_matches_mitsuba(tmp_path, mitsuba, renderer, monkeypatch):
    """Regression (issue #6): the Mitsuba reference sampled base_color maps upside down (its
    PLY loader keeps v, its bitmaps put the top row at v = 0): the top of the sphere must be red
    in both renderers."""
    from cnlmc.backends.maps import service
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.render import Renderer, default_scene

    real_bake = service.bake

    def bake(refs, params, size, seed=0, **options):  # the one baking service both renderers use
        out = real_bake(refs, params, size, seed, **options)
        out["base_color"] = _halves_pattern(out["base_color"].shape[0])
        return out

    monkeypatch.setattr(service, "bake", bake)
    granite = material_of("granite")
    seeded = dataclasses.replace(granite.maps["base_color"], seed=60606)  # its own entry in the baked-map cache
    material = dataclasses.replace(granite, maps={**granite.maps, "base_color": seeded})
    size = 32
    scene = default_scene("sphere", "studio", (size, size))
    scene.background = "transparent"
    image, _ = render_scene(export_scene(material, scene, tmp_path, size, size, spp=4))
    frame = Renderer(size, resources=renderer.resources).render(material, tier="splitsum", scene=scene, hdr=True)
    for name, img in (("mitsuba", image), ("preview", frame.hdr)):
        inside = img[..., 3] > 0.5
        red = img[..., 0] > img[..., 2]
        top, bottom = inside.copy(), inside.copy()
        top[size // 2 :], bottom[: size // 2] = False, False
        assert red[top].mean() > 0.8 and red[bottom].mean() < 0.5, name


@pytest.mark.parametrize(
    "spp, sampler",
    [
        (1, "independent"),
        (2, "independent"),
        (4, "ldsampler"),
        (16, "ldsampler"),
        (32, "independent"),
        (64, "ldsampler"),
        (128, "independent"),
        (256, "ldsampler"),
    ],
)
def test_the_exported_sampler_renders_exactly_the_asked_samples(tmp_path, spp, sampler):
    """ldsampler takes only 4^k spp (it rounds 1 up to 4, 32 to 64): any other count gets the
    independent sampler, so a 1-spp render is one sample (the chart's Mitsuba curve)."""
    mi = pytest.importorskip("mitsuba")
    from cnlmc.backends.preview.mitsuba_scene import export_scene, sampler_for
    from cnlmc.backends.preview.render import default_scene

    assert sampler_for(spp) == sampler
    path = export_scene(material_of("gold"), default_scene("sphere", "studio", (8, 8)), tmp_path, 8, 8, spp=spp)
    assert f'<sampler type="{sampler}">' in path.read_text()
    if mi.variant() is None:
        mi.set_variant("scalar_rgb")
    assert mi.load_file(str(path)).sensors()[0].sampler().sample_count() == spp
