"""The preview chart's physically complete reference (#15 item 7): rough glass in Mitsuba keeps the
light its facets block (backends/preview/reference_glass.py: roughdielectric plus a Kulla-Conty
compensation), so a white furnace stays white where the single-scattering plugin loses a tenth;
the preview's frosted glass and metallic paint agree with that reference (real renders: Mitsuba's
llvm variant with the cnlm plugins, the preview on llvmpipe)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import load_module

from .conftest import material_of

FROSTED = {"type": "roughdielectric", "distribution": "ggx", "alpha": 0.25, "int_ior": 1.52, "ext_ior": 1.0}


@pytest.fixture(scope="module")
def mi():
    mitsuba = pytest.importorskip("mitsuba")
    from cnlmc.backends.exchange import mitsuba_cnlm
    from cnlmc.backends.preview import reference_glass

    try:
        mitsuba_cnlm.register()
    except mitsuba_cnlm.PluginError as exc:
        pytest.skip(str(exc))
    reference_glass.register()
    return mitsuba


@pytest.fixture(scope="module")
def chart():
    return load_module("preview_chart_bench", Path(__file__).parents[2] / "bench" / "preview_chart.py")


def furnace_mean(mi, bsdf: dict) -> np.ndarray:
    """Mean RGB over a sphere in a uniform white environment (path tracing, depth 16)."""
    camera = mi.ScalarTransform4f().look_at(origin=[0, 0, 5], target=[0, 0, 0], up=[0, 1, 0])
    scene = mi.load_dict(
        {
            "type": "scene",
            "integrator": {"type": "path", "max_depth": 16},
            "sensor": {
                "type": "perspective",
                "fov": 30,
                "to_world": camera,
                "film": {"type": "hdrfilm", "width": 24, "height": 24, "pixel_format": "rgba"},
                "sampler": {"type": "independent", "sample_count": 16},
            },
            "emitter": {"type": "constant", "radiance": 1.0},
            "shape": {"type": "sphere", "bsdf": bsdf},
        }
    )
    image = np.array(mi.render(scene))
    return image[image[..., 3] > 0.999][:, :3].mean(axis=0)


def test_the_reference_keeps_the_light_rough_glass_facets_block(mi):
    from cnlmc.backends.preview.reference_glass import PLUGIN

    native = furnace_mean(mi, FROSTED)
    kept = furnace_mean(mi, {**FROSTED, "type": PLUGIN})
    tinted = furnace_mean(
        mi, {**FROSTED, "type": PLUGIN, "specular_transmittance": {"type": "rgb", "value": [0.5, 1, 1]}}
    )
    assert native.mean() < 0.93  # measured 0.895: single scattering loses light
    assert 0.97 < kept.mean() < 1.04  # measured 1.017
    assert tinted[0] < 0.8 * tinted[1] and tinted[1] < 1.04  # the tint still absorbs


def test_the_chart_scene_wraps_rough_glass_only(tmp_path):
    from cnlmc.backends.preview.mitsuba_scene import export_scene
    from cnlmc.backends.preview.reference_glass import PLUGIN
    from cnlmc.backends.preview.render import default_scene

    scene = default_scene("sphere", "studio", (16, 16))
    for phrase, wrapped in (("frosted glass", True), ("clear glass", False)):
        export_scene(material_of(phrase), scene, tmp_path / phrase, 16, 16, spp=4, bsdf="cnlm")
        text = (tmp_path / phrase / "materials.xml").read_text()
        assert (f'type="{PLUGIN}"' in text) is wrapped, text
        native = tmp_path / (phrase + "-native")
        export_scene(material_of(phrase), scene, native, 16, 16, spp=4)
        assert PLUGIN not in (native / "materials.xml").read_text()  # what a user exports is unchanged


def reference_and_preview(chart, work: Path, phrase: str, size: int, spp: int):
    from cnlmc.backends.preview.render import Renderer, default_scene

    scene = default_scene("sphere", "studio", (size, size))
    scene.background = "transparent"
    material = material_of(phrase).to_ir()
    reference, _ = chart.mitsuba_reference(material, scene, size, spp, work)
    with Renderer(size) as renderer:
        preview = renderer.render(material, tier="splitsum", scene=scene, hdr=True).hdr
    return reference, preview


def test_metallic_paint_split_sum_sees_its_flakes_at_their_width(mi, chart, gl_available, tmp_path):
    """Looked up at the coat's width, the flakes mirrored the studio's window sharply: FLIP 0.075
    against the reference at 128^2; at their own width 0.030."""
    reference, preview = reference_and_preview(chart, tmp_path, "metallic car paint", 64, 32)
    flip, _ = chart.errors(chart.tonemap(reference), chart.tonemap(preview))
    assert flip <= 0.05, flip


def test_frosted_glass_is_as_bright_as_the_complete_reference(mi, chart, gl_available, tmp_path):
    """The preview keeps what the facets block and what a rough ball keeps inside (and shows the
    key light through rough exits): its mean within 8 % of the compensated reference. Measured:
    +0.2 % here (48^2, 32 spp), -1.0 % at 64^2, -3.7 % in red at 128^2 (256 spp); +5 % with the
    old two-exit model, +14 % with the traced lobes each seen through one GGX lookup (the broad
    later lobe is now seen through its mean vector). The single-scattering reference was 17 %
    darker than the preview."""
    reference, preview = reference_and_preview(chart, tmp_path, "frosted glass", 48, 32)
    ours, theirs = preview[..., :3].mean(), reference[..., :3].mean()
    assert abs(ours / theirs - 1.0) < 0.08, (ours, theirs)
