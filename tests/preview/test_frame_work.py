"""A frame does no more work than it needs, and the shortcuts change no pixel: the sphere is
tessellated for its size on screen; without a background only the rectangle around what is
drawn is cleared, tone mapped and read back; a warm material is drawn once per render()."""

from __future__ import annotations

import math

import numpy as np
import pytest

from cnlmc.backends.preview import render as render_module
from cnlmc.backends.preview.meshes import SILHOUETTE_ERROR_PX, sphere_for_pixels, sphere_segments
from cnlmc.backends.preview.targets import strips_around

from .conftest import material_of


@pytest.mark.parametrize("radius_px", [1, 20, 64, 128, 256, 511, 2048])
def test_sphere_level_keeps_the_silhouette_within_a_quarter_pixel(radius_px):
    rings, segments = sphere_segments(radius_px)
    assert segments % 8 == 0 and rings % 2 == 0 and segments >= 32
    assert radius_px * (1 - math.cos(math.pi / segments)) <= SILHOUETTE_ERROR_PX + 1e-12
    # no coarser than needed: the next level down would break the bound (above the minimum)
    if segments > 32:
        assert radius_px * (1 - math.cos(math.pi / (segments - 8))) > SILHOUETTE_ERROR_PX


def test_sphere_levels_share_the_bounds_hence_the_framing():
    levels = [sphere_for_pixels(r) for r in (32, 128, 256, 700)]
    assert len({len(m.indices) for m in levels}) == 4
    for mesh in levels:
        np.testing.assert_allclose(mesh.bounds[0], levels[0].bounds[0], atol=1e-6)
        np.testing.assert_allclose(mesh.bounds[1], levels[0].bounds[1], atol=1e-6)
    assert sphere_for_pixels(128).key == sphere_for_pixels(128).key  # one content: uploaded once


def test_a_renderer_keeps_the_scene_mesh_and_environment_it_made(renderer):
    first, second = renderer.scene("sphere", "studio"), renderer.scene("sphere", "studio")
    assert first is not second  # a scene of its own to change (background, exposure)
    assert first.mesh is second.mesh and first.env is second.env  # made once, by name and size


def test_default_scene_sphere_grows_finer_with_the_frame():
    small = render_module.default_scene("sphere", "studio", (256, 256)).mesh
    large = render_module.default_scene("sphere", "studio", (1024, 1024)).mesh
    assert len(small.indices) < 12288 < len(large.indices)


def off_centre_scene(size: int):
    scene = render_module.default_scene("sphere", "studio", (size, size))
    scene.background = "transparent"
    model = np.diag([0.45, 0.45, 0.45, 1.0])
    model[:3, 3] = (0.35, 0.1, 0.0)
    return scene, model


def full_frame(monkeypatch):
    monkeypatch.setattr(render_module.Renderer, "drawn_rect", lambda self, *a, **k: None)


@pytest.mark.parametrize("phrase", ["gold", "white varnished oak"])
def test_tone_map_over_the_drawn_rectangle_changes_no_pixel(renderer, phrase, monkeypatch):
    scene, model = off_centre_scene(renderer.width)
    material = material_of(phrase)
    rect = renderer.drawn_rect(scene, model)
    assert rect is not None and rect[2] * rect[3] < 0.5 * renderer.width * renderer.height
    renderer.render(material, tier="splitsum", scene=renderer_scene_filled(renderer))  # leaves pixels behind
    clipped = renderer.render(material, tier="splitsum", scene=scene, model=model, hdr=True)
    full_frame(monkeypatch)
    whole = renderer.render(material, tier="splitsum", scene=scene, model=model, hdr=True)
    assert clipped.rgba[..., 3].max() == 255  # the object is there
    np.testing.assert_array_equal(clipped.rgba, whole.rgba)
    np.testing.assert_array_equal(clipped.hdr, whole.hdr)


def renderer_scene_filled(renderer):
    scene = render_module.default_scene("sphere", "studio", (renderer.width, renderer.height))
    scene.background = "transparent"
    return scene


def test_drawn_rectangle_holds_every_covered_pixel(renderer):
    scene, model = off_centre_scene(renderer.width)
    rgba = renderer.render(material_of("blue plastic"), tier="analytic", scene=scene, model=model).rgba
    x, y, w, h = renderer.drawn_rect(scene, model)
    rows, cols = np.nonzero(rgba[..., 3])
    gl_rows = renderer.height - 1 - rows  # rgba is top row first
    assert cols.min() >= x and cols.max() < x + w and gl_rows.min() >= y and gl_rows.max() < y + h


def test_no_rectangle_when_the_object_reaches_behind_the_camera(renderer):
    scene, _ = off_centre_scene(renderer.width)
    lo, hi = scene.mesh.bounds
    model = np.eye(4)
    model[:3, 3] = scene.camera.position - (lo + hi) / 2  # the camera inside the object's box
    assert renderer.drawn_rect(scene, model) is None


def test_an_overlay_without_world_points_gets_the_whole_frame(renderer):
    scene, model = off_centre_scene(renderer.width)
    assert renderer.drawn_rect(scene, model, overlay=lambda r, s: None) is None


def test_a_warm_material_is_drawn_once_per_render(renderer, scene, monkeypatch):
    material = material_of("copper")
    renderer.render(material, tier="analytic", scene=scene)
    calls = []
    original = render_module.Renderer.draw
    monkeypatch.setattr(
        render_module.Renderer, "draw", lambda self, *a, **k: calls.append(1) or original(self, *a, **k)
    )
    frame = renderer.render(material, tier="analytic", scene=scene)
    assert len(calls) == 1 and frame.ms > 0


def test_the_background_outside_the_drawn_rectangle_changes_no_pixel(renderer, monkeypatch):
    """With the environment background the frame outside the object's rectangle is tone mapped
    by the background-only variant: the same image as one whole-frame pass."""
    scene, model = off_centre_scene(renderer.width)
    scene.background = "env"
    rect = renderer.drawn_rect(scene, model)
    assert len(strips_around(rect, renderer.width, renderer.height)) == 4
    split = renderer.render(material_of("gold"), tier="splitsum", scene=scene, model=model).rgba
    full_frame(monkeypatch)
    whole = renderer.render(material_of("gold"), tier="splitsum", scene=scene, model=model).rgba
    assert split[..., 3].min() == 255  # the background covers every pixel
    np.testing.assert_array_equal(split, whole)


def test_strips_around_tile_the_frame_outside_the_rectangle():
    rect = (3, 5, 7, 4)
    covered = np.zeros((20, 16), int)
    for x, y, w, h in strips_around(rect, 16, 20) + [rect]:
        covered[y : y + h, x : x + w] += 1
    assert np.all(covered == 1)
    assert strips_around((0, 0, 16, 20), 16, 20) == []
