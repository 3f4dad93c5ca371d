"""Translucent materials in the preview (issue #19 item 4, docs/preview.md "Subsurface"): a thin wall
lit from behind sends light to the camera and a thick body does not; no tier gives back more than
a white Lambertian under a white furnace; the preview is near Mitsuba's volumetric reference (a
rough dielectric boundary around a homogeneous medium, volpath) under a measured FLIP bound."""

from __future__ import annotations

import dataclasses
import tempfile

import numpy as np
import pytest

from cnlmc.api import compile_source
from cnlmc.material import Material

SIZE = 48
#: the tiers that integrate the environment; "analytic" lights the boundary's specular lobe with
#: pi f(v, n) x the mean radiance, above 1 at a smooth lobe's peak without any body (its own limit).
TIERS = ("splitsum", "fis16", "mc16")


def compiled(phrase: str) -> Material:
    return Material.from_ir(compile_source(phrase + "\n").ir["materials"][0])


def translucent(form: str, color=(0.85, 0.6, 0.4), radius=(0.004, 0.002, 0.001), thickness=None) -> Material:
    """A body as the IR states it (docs/subsurface.md): model.subsurface and params.subsurface."""
    model = {"base": "dielectric", "distribution": "ggx", "anisotropic": False, "coat": False, "diffuse": "lambert"}
    medium = {"color": list(color), "radius": list(radius), "anisotropy": 0.0, "thickness": thickness}
    params = {"base_color": list(color), "roughness": 0.3, "ior": 1.4, "subsurface": medium}
    return Material.from_ir({"name": f"body_{form}", "model": {**model, "subsurface": form}, "params": params})


def backlit_scene(renderer):
    """The sphere in the dark, the key light straight behind it (as seen from the camera)."""
    from cnlmc.backends.preview.environment import ENV_HEIGHT, ENV_WIDTH, Environment, KeyLight

    probe = renderer.scene("sphere", "studio")
    behind = np.subtract(probe.camera.target, probe.camera.eye)
    dark = Environment("dark", np.zeros((ENV_HEIGHT, ENV_WIDTH, 3), np.float32), KeyLight(tuple(behind), 3.0))
    scene = renderer.scene("sphere", dark)
    scene.background = "transparent"
    return scene


def centre_radiance(frame) -> float:
    """Mean linear radiance of the pixels within half the sphere's radius of its centre."""
    covered = frame.rgba[..., 3] > 0.99
    ys, xs = np.nonzero(covered)
    r = np.hypot(ys - ys.mean(), xs - xs.mean()) / np.sqrt(covered.sum() / np.pi)
    return float(frame.hdr[..., :3][covered][r < 0.5].mean())


@pytest.fixture(scope="module")
def small(gl_available):
    from cnlmc.backends.preview.render import Renderer

    with Renderer(SIZE) as made:
        yield made


@pytest.mark.parametrize("tier", ["splitsum", "fis16"])
def test_a_backlit_thin_wall_glows_and_a_thick_body_does_not(small, tier):
    scene = backlit_scene(small)
    leaf = compiled("leaf")
    assert leaf.model.subsurface == "thin"
    thin = centre_radiance(small.render(leaf, scene=scene, tier=tier, hdr=True))
    thick = centre_radiance(small.render(compiled("wax"), scene=scene, tier=tier, hdr=True))
    # measured 0.023 (48^2, splitsum): the leaf's sheet passes 0.19/0.50/0.11, twice on a closed shell
    # whose cavity spreads the key light over its walls
    assert thin > 0.01, f"a leaf lit from behind sends light through: {thin:.3f}"
    assert thick < 0.01 * thin, f"a 10 cm ball of wax (3-6 mm mean free path) lets almost none through: {thick:.4f}"


def test_a_thicker_wall_lets_less_through(small):
    scene = backlit_scene(small)
    leaf, card = (
        centre_radiance(small.render(translucent("thin", radius=(0.0005,) * 3, thickness=t), scene=scene, hdr=True))
        for t in (0.0003, 0.003)
    )
    assert card < 0.7 * leaf, (leaf, card)


@pytest.mark.parametrize("tier", TIERS)
@pytest.mark.parametrize("form", ["volume", "thin"])
def test_no_body_is_brighter_than_a_white_lambertian_in_a_white_furnace(small, form, tier):
    """Under a uniform white sky (radiance 1) a white Lambertian returns exactly 1 everywhere; a
    white body (albedo 1, no absorption) behind its boundary returns at most that: what the
    boundary reflects plus what the body sends out through it."""
    from cnlmc.backends.preview.environment import ENV_HEIGHT, ENV_WIDTH, Environment, KeyLight

    white = Environment("white", np.ones((ENV_HEIGHT, ENV_WIDTH, 3), np.float32), KeyLight(irradiance=0.0))
    scene = small.scene("sphere", white)
    scene.background = "transparent"
    body = translucent(form, color=(1.0, 1.0, 1.0), radius=(0.002, 0.002, 0.002), thickness=0.0002)
    frame = small.render(body, scene=scene, tier=tier, hdr=True)
    inside = frame.rgba[..., 3] > 0.99
    radiance = frame.hdr[..., :3][inside]
    assert radiance.mean() <= 1.0 + 0.01, radiance.mean()
    assert np.percentile(radiance, 99) <= 1.0 + 0.03, np.percentile(radiance, 99)
    # and not black: measured 1.005 (volume), 0.86 (thin: the sheet's front base_color x (1 - max T)
    # and T through both walls of the closed shell; what its cavity sends back is not followed)
    assert radiance.mean() > 0.6, f"and it is not black: {radiance.mean():.3f}"


#: FLIP of the default tier against the Mitsuba export's reference (48^2, the studio), measured with
#: 64 spp: wax 0.094 (128 spp: 0.076: at 64 spp the wax reference's own noise is most of it; session
#: 10: 0.091), leaf 0.143 in session 9, 0.057 in session 10 (its front had been drawn with an eighth
#: of its colour, and its cavity now gets back what the walls reflect; the reference's noise 0.016).
FLIP_BOUND = {"volume": 0.13, "thin": 0.09}
REFERENCE_SPP = 64


@pytest.mark.slow
@pytest.mark.parametrize("form", ["volume", "thin"])
def test_the_preview_is_near_mitsubas_volumetric_reference(small, form):
    """wax (a volume: the rough dielectric boundary around its medium) and leaf (a thin sheet)."""
    pytest.importorskip("mitsuba")
    pytest.importorskip("flip_evaluator")
    from cnlmc.backends.preview.subsurface_reference import render_subsurface

    from ..helpers import load_module

    chart = load_module(
        "preview_chart_bench", __import__("pathlib").Path(__file__).parents[2] / "bench" / "preview_chart.py"
    )
    body = compiled("wax" if form == "volume" else "leaf")
    scene = small.scene("sphere", "studio")
    scene.background = "transparent"
    with tempfile.TemporaryDirectory() as folder:
        reference, _ = render_subsurface(body, scene, folder, SIZE, REFERENCE_SPP)
    preview = small.render(body, scene=scene, tier="splitsum", hdr=True).hdr
    flip, _ = chart.errors(chart.tonemap(reference), chart.tonemap(preview))
    assert flip <= FLIP_BOUND[form], flip


def vein_contrast(renderer, scene, material: Material, tier: str) -> float:
    """The base-colour map's contrast over the lit object at the scene's lighting: the 5-95 percentile
    spread of the luminance with the map over the luminance of the same material without it
    (lighting and shading divide out; pixels lit at least half the median)."""
    luminance = np.array([0.2126, 0.7152, 0.0722])
    mapped = renderer.render(material, scene=scene, tier=tier, hdr=True)
    plain = renderer.render(dataclasses.replace(material, maps={}), scene=scene, tier=tier, hdr=True)
    with_map, without = mapped.hdr[..., :3] @ luminance, plain.hdr[..., :3] @ luminance
    covered = mapped.rgba[..., 3] > 250
    lit = covered & (without > 0.5 * np.median(without[covered]))
    assert lit.sum() > 0.1 * covered.sum()
    low, high = np.percentile(with_map[lit] / without[lit], [5, 95])
    return float(high - low)


@pytest.mark.parametrize("phrase", ["marble", "black marble with white veins", "green marble"])
@pytest.mark.parametrize("tier", ["analytic", "splitsum"])
def test_veins_show_through_the_body(renderer, scene, phrase, tier):
    """Issue #19 review 1: a translucent marble keeps its veins (the base-colour map colours the body,
    softened by the diffusion): its map's contrast is at least half the opaque marble's at the same
    lighting (measured 0.92-1.05x at 128^2), and far from none."""
    material = compiled(phrase)
    assert material.model.subsurface == "volume" and "base_color" in material.maps
    ir = material.to_ir()
    ir["model"].pop("subsurface")
    ir["params"].pop("subsurface")
    opaque = Material.from_ir(ir)
    ours, theirs = vein_contrast(renderer, scene, material, tier), vein_contrast(renderer, scene, opaque, tier)
    assert theirs > 0.1, theirs  # the map has veins to show
    assert ours >= 0.5 * theirs, (ours, theirs)
