"""The preview's path through a thick body comes from the mesh (shaders/subsurface.glsl.j2,
pv_sss_path): the chord through the sphere of the surface's own curvature, at most the bounding
sphere's. A thin part of an object (a teapot's spout; here a small ball beside a big one, both inside
one bounding sphere) lets the light behind it through; the thick part does not."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.api import compile_source
from cnlmc.material import Material

SIZE = 96


def two_balls():
    """A 5 cm-radius ball and a 3 mm-radius ball side by side (0.05 m a unit): one bounding sphere."""
    from cnlmc.backends.preview.meshes import merge, sphere

    def ball(centre, radius):
        mesh = sphere(32, 48)
        mesh.positions = (mesh.positions * radius + np.asarray(centre)).astype("f4")
        return mesh

    return merge([ball((-0.5, 0.0, 0.0), 0.5), ball((0.6, 0.0, 0.0), 0.06)])


@pytest.fixture(scope="module")
def renderer(gl_available):
    from cnlmc.backends.preview.render import Renderer

    with Renderer(SIZE) as made:
        yield made


def test_a_thin_part_glows_backlit_and_the_thick_part_does_not(renderer):
    from cnlmc.backends.preview.environment import ENV_HEIGHT, ENV_WIDTH, Environment, KeyLight
    from cnlmc.backends.preview.scene import default_scene

    mesh = two_balls()
    probe = default_scene(mesh, "studio", (SIZE, SIZE))
    behind = np.subtract(probe.camera.target, probe.camera.eye)
    dark = Environment("dark", np.zeros((ENV_HEIGHT, ENV_WIDTH, 3), np.float32), KeyLight(tuple(behind), 3.0))
    scene = default_scene(mesh, dark, (SIZE, SIZE))
    scene.background = "transparent"
    wax = Material.from_ir(compile_source("wax\n").ir["materials"][0])
    frame = renderer.render(wax, scene=scene, tier="splitsum", hdr=True)
    covered = frame.rgba[..., 3] > 0.99
    columns = np.nonzero(covered.any(0))[0]
    split = columns.min() + 0.85 * (columns.max() - columns.min())  # the small ball is the last 6 % across
    ys, xs = np.mgrid[0:SIZE, 0:SIZE]
    radiance = frame.hdr[..., :3].max(-1)
    small = radiance[covered & (xs > split)]
    big = covered & (xs < split)
    cy, cx = ys[big].mean(), xs[big].mean()
    centre = big & (np.hypot(ys - cy, xs - cx) < 0.5 * np.sqrt(big.sum() / np.pi))
    # light through 6 mm of wax (mean free path 3-6 mm) against through 50 mm: measured 0.24 / 0.0000
    assert np.percentile(small, 75) > 0.05, np.percentile(small, 75)
    assert np.percentile(small, 75) > 50 * max(float(radiance[centre].mean()), 1e-6), radiance[centre].mean()
