"""Render targets without MSAA (the default): drawn straight into the half-float texture, the
tone-map pass filters edges and composites the environment background."""

from __future__ import annotations

import numpy as np

from .conftest import SMALL, material_of


def test_default_has_no_msaa_and_filters_edges(renderer, scene):
    from cnlmc.backends.preview.render import DEFAULT_MSAA, Renderer

    assert DEFAULT_MSAA == 0
    material = material_of("blue plastic")
    soft = Renderer(SMALL, resources=renderer.resources).render(material, tier="analytic", scene=scene)
    hard = Renderer(SMALL, edge_aa=False, resources=renderer.resources).render(material, tier="analytic", scene=scene)
    partial = lambda f: ((f.rgba[..., 3] > 0) & (f.rgba[..., 3] < 255)).sum()
    assert partial(hard) == 0 and partial(soft) > 20  # coverage is blended at the silhouette
    inside = hard.rgba[..., 3] == 255
    changed = np.any(soft.rgba[..., :3] != hard.rgba[..., :3], axis=2) & inside
    assert changed.sum() < 0.3 * inside.sum()  # smooth shading is left alone


def test_background_is_composited_behind_the_object(gl_available):
    from cnlmc.backends.preview.render import Renderer, default_scene

    material = material_of("blue plastic")
    env_scene = default_scene("sphere", "studio", (SMALL, SMALL))
    with Renderer(SMALL) as own:  # a renderer with resources of its own
        frame = own.render(material, tier="analytic", scene=env_scene, hdr=True)
    assert (frame.rgba[..., 3] == 255).all()
    corner = frame.rgba[0, 0, :3].astype(int)
    assert corner.sum() > 30  # the environment, not black
    centre = frame.rgba[SMALL // 2, SMALL // 2, :3].astype(int)
    assert centre[2] > centre[0] + 20  # the blue object is in front


def test_back_faces_are_culled_only_on_closed_meshes(renderer, scene):
    from dataclasses import replace

    from cnlmc.backends.preview.meshes import fit, mesh_by_name
    from cnlmc.backends.preview.render import Renderer

    assert scene.mesh.closed  # the sphere (UV seam welded by position)
    assert not fit(mesh_by_name("teapot")).closed  # Newell's teapot has no bottom
    material = material_of("gold")
    plain = Renderer(SMALL, resources=renderer.resources)  # the default: no MSAA
    culled = plain.render(material, tier="splitsum", scene=scene)
    open_mesh = replace(scene.mesh)
    open_mesh.closed = False  # the same mesh, said to be open: back faces drawn
    both = plain.render(material, tier="splitsum", scene=replace(scene, mesh=open_mesh))
    assert np.array_equal(culled.rgba, both.rgba)  # culling changes the cost, not the image


def test_the_tone_map_pass_encodes_exactly_to_eight_bits(renderer, scene):
    """The 8-bit output is the exact tone map (exposure, ACES fit, sRGB with pow) of the HDR
    frame, rounded: within half a level plus the shader's sRGB curve's error (a fitted sum of
    square roots, 3e-5 = 0.008 of a level)."""
    from cnlmc.backends.preview.render import Renderer

    frame = Renderer(SMALL, edge_aa=False, resources=renderer.resources).render(
        material_of("white varnished oak"), tier="splitsum", scene=scene, hdr=True
    )
    x = np.maximum(frame.hdr[..., :3], 0) * scene.exposure
    x = np.clip(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
    exact = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055) * 255
    covered = frame.hdr[..., 3] > 0.5
    diff = np.abs(frame.rgba[..., :3].astype(float) - exact)[covered]
    assert covered.sum() > 500 and diff.max() < 0.52, diff.max()  # rounding: 0.5; the curve: 0.008
