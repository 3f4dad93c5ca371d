"""The preview's reference lights the body with the key light (backends/preview/subsurface_reference.py).

Mitsuba cannot connect a directional (delta) light through a smooth (delta) dielectric boundary, so
the reference's key light is a small far disk of the same irradiance. On an opaque material the disk
and the directional light give the same image; a smooth body (milk) and a rough one (wax) are now
brighter with the key light on than off."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import require

mi = require("mitsuba", "mitsuba")
pytestmark = pytest.mark.mitsuba

from cnlmc.api import compile_source  # noqa: E402
from cnlmc.material import Material  # noqa: E402

SIZE, SPP = 32, 64


def compiled(phrase: str) -> Material:
    return Material.from_ir(compile_source(phrase + "\n").ir["materials"][0])


def studio(key_irradiance: float | None = None):
    from cnlmc.backends.preview.environment import Environment, KeyLight
    from cnlmc.backends.preview.scene import default_scene

    scene = default_scene("sphere", "studio", (SIZE, SIZE))
    if key_irradiance is not None:
        env = scene.env
        scene = default_scene(
            scene.mesh, Environment("studio key", env.image, KeyLight(env.key.direction, key_irradiance))
        )
    scene.background = "transparent"
    return scene


def test_the_key_disk_has_the_directional_lights_irradiance():
    from cnlmc.backends.preview.subsurface_reference import KEY_DISTANCE, KEY_HALF_ANGLE_DEG, key_disk

    scene = studio()
    xml = key_disk(scene)
    radiance = float(xml.split('name="radiance" value="')[1].split('"')[0])
    radius = float(xml.split('<scale value="')[1].split('"')[0])
    sin_theta = radius / np.hypot(radius, KEY_DISTANCE)
    assert np.isclose(np.degrees(np.arcsin(sin_theta)), KEY_HALF_ANGLE_DEG, atol=1e-6)
    assert np.isclose(np.pi * radiance * sin_theta**2, scene.env.key.irradiance, rtol=1e-6)


def test_an_opaque_material_looks_the_same_under_the_disk_and_the_directional_light(tmp_path):
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.subsurface_reference import with_key_disk

    scene, plastic = studio(), compiled("glossy white plastic")
    path = export_scene(plastic, scene, tmp_path, SIZE, SIZE, spp=SPP)
    directional, _ = render_scene(path, spp=SPP, variant="vectorized")
    path.write_text(with_key_disk(path.read_text(), scene))
    disk, _ = render_scene(path, spp=SPP, variant="vectorized")
    assert 'type="directional"' not in path.read_text()
    lit, key = directional[..., :3].sum((0, 1)), disk[..., :3].sum((0, 1))
    assert np.allclose(lit, key, rtol=0.01), (lit, key)
    # per pixel: the glossy highlight is the 4-degree disk's, spread over a few pixels
    assert np.abs(directional - disk).mean() < 0.01 * directional.max(), np.abs(directional - disk).mean()


@pytest.mark.parametrize("phrase", ["milk", "wax"])
def test_a_body_is_brighter_with_the_key_light_on(tmp_path, phrase):
    """Milk's boundary is smooth (the directional light never reached its body), wax's rough.
    Measured at 32x32, 64 spp (two seeds): milk on/off 1.22-1.42 per channel, wax 1.2-1.5;
    before the disk, milk's ratio was 1.0 exactly."""
    from cnlmc.backends.preview.subsurface_reference import render_subsurface

    body = compiled(phrase)
    on, _ = render_subsurface(body, studio(), tmp_path / "on", SIZE, SPP)
    off, _ = render_subsurface(body, studio(0.0), tmp_path / "off", SIZE, SPP)
    lit, unlit = on[..., :3].sum((0, 1)), off[..., :3].sum((0, 1))
    assert (lit > 1.1 * unlit).all(), (lit, unlit)
