"""Mitsuba's native export draws a velvet's sheen with `principled`'s (Disney) sheen (docs/bsdf.md
"Sheen"): the scene loads and renders in Mitsuba, its rim is brighter against its centre than the
same fabric's without a sheen, and `bsdf=cnlm` (the Charlie sheen and the flakes, exactly) renders
a metallic paint brighter at its face than the paint without flakes."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from cnlmc.api import compile_source, emit

mi = pytest.importorskip("mitsuba")
SIZE = 32


def material_of(phrase: str):
    return compile_source(phrase + "\n").document.materials[0]


def without(material, *names: str):
    """The material with the named parameters back at their defaults (no sheen, no flakes)."""
    defaults = {n: None if n.endswith("_color") else getattr(type(material.params), n) for n in names}
    return dataclasses.replace(material, params=dataclasses.replace(material.params, **defaults))


def render(material, tmp_path, bsdf: str = "native") -> np.ndarray:
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.render import default_scene

    if bsdf == "native":
        mi.set_variant("scalar_rgb")
    scene = default_scene("sphere", "studio", (SIZE, SIZE))
    path = export_scene(material, scene, tmp_path, SIZE, SIZE, spp=16, bsdf=bsdf)
    image, _ = render_scene(path)
    assert np.isfinite(image).all()
    return image


def rim_over_centre(image: np.ndarray) -> float:
    """Mean luminance of the covered pixels beyond 0.8 of the disc's radius over those within 0.5."""
    covered = image[..., 3] > 0.99
    ys, xs = np.nonzero(covered)
    cy, cx, radius = ys.mean(), xs.mean(), (xs.max() - xs.min() + 1) / 2
    yy, xx = np.mgrid[: image.shape[0], : image.shape[1]]
    r = np.hypot(yy - cy, xx - cx) / radius
    luma = image[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
    return float(luma[covered & (r > 0.8)].mean() / luma[covered & (r < 0.5)].mean())


def test_velvet_exports_principled_with_its_sheen():
    text = emit(compile_source("navy blue velvet\n").ir, "mitsuba", {"form": "fragment"}).artifacts[0].content
    assert 'type="principled"' in text and 'name="sheen"' in text and 'name="specular" value="0"' in text


def test_native_velvet_rim_is_lifted_by_its_sheen(tmp_path):
    velvet = material_of("navy blue velvet")
    sheened = rim_over_centre(render(velvet, tmp_path / "sheen"))
    plain = rim_over_centre(render(without(velvet, "sheen_color"), tmp_path / "plain"))
    assert sheened > 1.1 * plain, (sheened, plain)


@pytest.fixture
def cnlm_plugin():
    dr = pytest.importorskip("drjit")
    from cnlmc.backends.exchange import mitsuba_cnlm

    previous = mi.variant()
    flags = {f: dr.flag(f) for f in (dr.JitFlag.SymbolicCalls, dr.JitFlag.SymbolicLoops)}
    try:
        mitsuba_cnlm.register()
    except mitsuba_cnlm.PluginError as exc:
        pytest.skip(str(exc))
    yield
    for flag, value in flags.items():
        dr.set_flag(flag, value)
    if previous:
        mi.set_variant(previous)


def test_cnlm_plugin_draws_the_flakes(tmp_path, cnlm_plugin):
    paint = material_of("metallic car paint")
    flaked = render(paint, tmp_path / "flakes", bsdf="cnlm")
    plain = render(without(paint, "flake_color", "flake_density"), tmp_path / "plain", bsdf="cnlm")
    luma = np.array([0.2126, 0.7152, 0.0722])
    assert (flaked[..., :3] @ luma).mean() > 1.2 * (plain[..., :3] @ luma).mean()
