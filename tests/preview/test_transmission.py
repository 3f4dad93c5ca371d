"""Glass in the preview (#15): the environment refracted through the object, as a lens inverts
it; absorption tints it (Beer-Lambert, the base colour per bounding radius); rough interfaces
blur it; a thin-walled sheet does not deflect it; no tier makes a NaN. Real renders of
compiled phrases in a known environment (left half red, right half green, a blue disc behind
the object as the camera sees it)."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.backends.preview import PreviewOptionError, parse_options
from cnlmc.backends.preview.environment import Environment, KeyLight, pixel_directions

from .conftest import material_of

SIZE = 96
RED, GREEN, BLUE = (2.0, 0.05, 0.05), (0.05, 2.0, 0.05), (0.05, 0.05, 2.0)


def halves_environment(behind: bool) -> Environment:
    """x < 0 red, x > 0 green; with `behind`, the directions within 8 degrees of the camera's
    line of sight through the object (18 degrees below the horizon, towards -z) blue."""
    d = pixel_directions(128, 256)
    image = np.where((d[..., 0] < 0.0)[..., None], RED, GREEN).astype(np.float32)
    if behind:
        sight = np.array([0.0, -np.sin(np.radians(18.0)), -np.cos(np.radians(18.0))])
        image[d @ sight > np.cos(np.radians(8.0))] = BLUE
    return Environment("halves-behind" if behind else "halves", image)


def uniform_environment() -> Environment:
    return Environment("white", np.ones((64, 128, 3), np.float32))


@pytest.fixture(scope="module")
def glass_renderer(gl_available):
    from cnlmc.backends.preview.render import Renderer

    with Renderer(SIZE) as made:
        yield made


def render(renderer, phrase: str, env: Environment, tier: str = "splitsum", glass: str = "auto"):
    scene = renderer.scene("sphere", env)
    scene.background, scene.glass = "transparent", glass
    return renderer.render(material_of(phrase), tier=tier, scene=scene, hdr=True)


def sphere_centre(frame) -> tuple[int, int, float]:
    """(row, column) of the silhouette's centroid and its radius in pixels."""
    covered = frame.rgba[..., 3] > 128
    rows, cols = np.nonzero(covered)
    return int(round(rows.mean())), int(round(cols.mean())), float(np.sqrt(covered.sum() / np.pi))


def at(frame, dx: float, dy: float = 0.0) -> np.ndarray:
    """Linear radiance at a point given in sphere radii from the silhouette's centre (x right)."""
    row, col, radius = sphere_centre(frame)
    return frame.hdr[row + int(round(dy * radius)), col + int(round(dx * radius)), :3]


def test_clear_glass_inverts_the_environment_behind_it(glass_renderer):
    frame = render(glass_renderer, "clear glass", halves_environment(behind=True))
    centre, left, right = at(frame, 0.0), at(frame, -0.55, -0.2), at(frame, 0.55, -0.2)
    assert centre[2] > 2.0 * max(centre[0], centre[1]), f"the centre shows what is behind (blue): {centre}"
    # a ball lens inverts: the left of the sphere shows the environment's right half (green)
    assert left[1] > 3.0 * left[0], f"left of centre: {left}"
    assert right[0] > 3.0 * right[1], f"right of centre: {right}"


def test_thin_walled_glass_does_not_invert(glass_renderer):
    frame = render(glass_renderer, "clear glass", halves_environment(behind=False), glass="thin")
    left, right = at(frame, -0.55), at(frame, 0.55)
    assert left[0] > 3.0 * left[1] and right[1] > 3.0 * right[0], (left, right)


def test_blue_glass_tints_by_beer_lambert(glass_renderer):
    env = uniform_environment()
    clear = at(render(glass_renderer, "clear glass", env), 0.0)
    blue = at(render(glass_renderer, "blue glass", env), 0.0)
    colour = np.asarray(material_of("blue glass").params.base_color)
    ratio = blue / clear
    # through the centre: two radii of glass, colour^2 (0.54 in blue, 1e-6 in red); the ~4 %
    # reflected at the front is untinted
    assert ratio[2] == pytest.approx(colour[2] ** 2 + 0.04, abs=0.06), ratio
    assert ratio[0] < 0.1 and ratio[1] < 0.12, ratio


def edge_sharpness(frame) -> float:
    """The steepest red-green step along the rows through the sphere's middle (per pixel)."""
    row, col, radius = sphere_centre(frame)
    band = frame.hdr[row - 3 : row + 4, col - int(0.6 * radius) : col + int(0.6 * radius), :3]
    hue = band[..., 0] - band[..., 1]
    return float(np.abs(np.diff(hue, axis=1)).max())


@pytest.mark.parametrize("tier", ["splitsum", "fis16"])
def test_frosted_glass_blurs_what_clear_glass_shows(glass_renderer, tier):
    env = halves_environment(behind=False)
    clear = edge_sharpness(render(glass_renderer, "clear glass", env, tier))
    frosted = edge_sharpness(render(glass_renderer, "frosted glass", env, tier))
    assert frosted < 0.5 * clear, (clear, frosted)


@pytest.mark.parametrize("tier", ["analytic", "splitsum", "fis16", "mc16"])
@pytest.mark.parametrize("glass", ["solid", "thin"])
def test_no_glass_pixel_is_nan_in_any_tier(glass_renderer, tier, glass):
    env = uniform_environment()  # what a glass passes is not black in white light
    for phrase in ("clear glass", "frosted glass", "blue glass", "water"):
        frame = render(glass_renderer, phrase, env, tier, glass)
        assert np.isfinite(frame.hdr).all(), (phrase, tier, glass)
        covered = frame.rgba[..., 3] > 128
        assert frame.hdr[covered, :3].max(axis=-1).mean() > 0.1, f"{phrase} ({tier}, {glass}) is black"


def light_behind_environment() -> Environment:
    """Black but for a bright disc (radiance 40, 25 degrees) on the camera's line of sight through the
    object, and no key light: every direction on the camera's side is dark, where a rough ball's later
    lobe looks (back towards the viewer)."""
    d = pixel_directions(128, 256)
    sight = np.array([0.0, -np.sin(np.radians(18.0)), -np.cos(np.radians(18.0))])
    image = np.where((d @ sight > np.cos(np.radians(25.0)))[..., None], (40.0, 40.0, 40.0), 0.0).astype(np.float32)
    return Environment("light-behind", image, KeyLight(irradiance=0.0))


@pytest.mark.parametrize("tier", ["splitsum", "analytic"])
def test_rough_glass_over_a_dark_direction_is_never_negative(glass_renderer, tier):
    """The later lobe's order-1 environment estimate L_mean (1 - 1.5 m) + 1.5 m E(d) is negative past
    mean cosine m = 2/3 where E(d) < L_mean (1 - 2 / (3 m)) (here E ~ 0 on the camera's side; slightly
    rough glass has m 0.7-0.9 near the centre), before the blend to the GGX lookup takes over at 0.8:
    floored at 0 in the shader. The frame is finite, shows the light through the ball, and has no
    negative pixel (preview.frag floors its output too: a negative lobe would take light from the
    others, at most 0.25 % of L_mean over the glass_paths table)."""
    env = light_behind_environment()
    for phrase in ("slightly rough glass", "lightly frosted glass", "frosted glass"):
        frame = render(glass_renderer, phrase, env, tier)
        assert np.isfinite(frame.hdr).all(), (phrase, tier)
        covered = frame.rgba[..., 3] > 128
        assert frame.hdr[covered, :3].max() > 1.0, (phrase, tier)  # the light is seen through it
        assert frame.hdr[..., :3].min() >= 0.0, (phrase, tier, float(frame.hdr[..., :3].min()))


def test_glass_option_is_declared_and_checked():
    assert parse_options({"glass": "thin"}).glass == "thin"
    assert parse_options({}).glass == "auto"
    with pytest.raises(PreviewOptionError):
        parse_options({"glass": "hollow"})


def test_every_tier_says_what_it_does_for_glass():
    from cnlmc.backends.preview.tiers import QUALITY_ORDER, parse_tier

    for name in (*QUALITY_ORDER, "fis3"):
        text = parse_tier(name).transmission
        assert "tint" in text or text.startswith("as splitsum"), (name, text)


def test_auto_glass_is_a_solid_for_a_closed_mesh_and_a_sheet_for_an_open_one():
    from cnlmc.backends.preview.glass import glass_form
    from cnlmc.backends.preview.scene import scene_mesh

    assert glass_form(scene_mesh("sphere", (64, 64))) == "solid"
    assert glass_form(scene_mesh("teapot", (64, 64))) == "thin"  # Newell's teapot has open rims
    assert glass_form(scene_mesh("teapot", (64, 64)), "solid") == "solid"


@pytest.mark.parametrize("phrase", ["clear glass", "blue glass", "lager"])
def test_smooth_glass_agrees_with_mitsubas_path_traced_dielectric(tmp_path, glass_renderer, phrase):
    """The exported scene path-traces glass (the `direct` integrator would stop at its surface;
    a tinted glass has its absorbing medium inside, through the volumetric path tracer); the
    preview's refraction, Fresnel and Beer-Lambert tint give Mitsuba's picture: the mean over
    the sphere within 4 % per channel."""
    mi = pytest.importorskip("mitsuba")
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene

    if mi.variant() is None:
        mi.set_variant("scalar_rgb")
    size = 48
    scene = glass_renderer.scene("sphere", halves_environment(behind=True))
    scene.background = "transparent"
    path = export_scene(material_of(phrase), scene, tmp_path, size, size, spp=16)
    text = path.read_text()
    tinted = min(material_of(phrase).params.base_color) < 1.0
    assert ('type="volpathmis"' if tinted else 'type="path"') in text
    assert ('<ref name="interior"' in text) == tinted
    theirs, _ = render_scene(path)
    from cnlmc.backends.preview.render import Renderer

    frame = Renderer(size, resources=glass_renderer.resources).render(
        material_of(phrase), tier="splitsum", scene=scene, hdr=True
    )
    both = (frame.hdr[..., 3] > 0.99) & (theirs[..., 3] > 0.99)
    ours_mean, theirs_mean = frame.hdr[..., :3][both].mean(0), theirs[..., :3][both].mean(0)
    assert np.allclose(ours_mean, theirs_mean, rtol=0.04, atol=0.005), (ours_mean, theirs_mean)
