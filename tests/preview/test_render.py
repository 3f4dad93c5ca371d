"""The preview renders every stdlib noun without NaN, deterministically; tiers and budgets."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.backends.preview import PreviewOptionError, compose, parse_options, preview_command
from cnlmc.backends.preview.tiers import QUALITY_ORDER, TIERS, TierError, parse_tier, select_tier

from .conftest import material_of, stdlib_nouns

NEAR_BLACK = 0.005  # albedo (luminance of base_color) below which a noun is black by its measured data


def _luminance(material) -> float:
    r, g, b = material.params.base_color
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


@pytest.mark.slow  # ~60 s: every stdlib noun rendered
def test_every_stdlib_noun_renders_without_nan(renderer, scene):
    nouns = stdlib_nouns()
    assert len(nouns) >= 40
    for noun in nouns:
        material = material_of(noun)
        frame = renderer.render(material, tier="splitsum", scene=scene, hdr=True)
        assert np.isfinite(frame.hdr).all(), noun
        covered = frame.rgba[..., 3] > 0
        assert 0.2 < covered.mean() < 0.8, noun  # the sphere is in the frame
        if _luminance(material) >= NEAR_BLACK:  # the ultra-black paints (MIT black, Musou) are meant to be black
            assert frame.rgba[..., :3][covered].mean() > 3, f"{noun} renders black"


@pytest.mark.parametrize(
    "phrase", ["gold", "walnut", "clear-coated red car paint", "lightly brushed, blue anodized aluminum"]
)
def test_two_renders_are_bit_identical(renderer, scene, phrase):
    material = material_of(phrase)
    for tier in ("splitsum", "mc16"):
        a = renderer.render(material, tier=tier, scene=scene, hdr=True)
        b = renderer.render(material, tier=tier, scene=scene, hdr=True)
        assert np.array_equal(a.rgba, b.rgba) and np.array_equal(a.hdr, b.hdr), (phrase, tier)
        assert np.isfinite(a.hdr).all()


def test_every_tier_renders_a_mirror_and_a_coat(renderer, scene):
    for phrase in ("mirror chrome", "clear-coated red car paint"):
        material = material_of(phrase)
        for name in TIERS:
            if name == "mc1024":
                continue
            frame = renderer.render(material, tier=name, scene=scene, hdr=True)
            assert np.isfinite(frame.hdr).all(), (phrase, name)


def test_tiers_parse_and_order():
    assert parse_tier("mc8").samples == 8 and not parse_tier("mc8").filtered
    assert parse_tier("fis32").filtered
    assert set(QUALITY_ORDER) == set(TIERS)
    with pytest.raises(TierError):
        parse_tier("mc0")
    with pytest.raises(TierError):
        parse_tier("ultra")


def test_budget_picks_the_best_tier_that_fits():
    cost = {
        "analytic": 1.0,
        "splitsum": 2.0,
        "mc16": 10.0,
        "fis16": 12.0,
        "mc64": 40.0,
        "fis64": 45.0,
        "mc256": 160.0,
        "mc1024": 640.0,
    }
    pick = lambda budget: select_tier(budget, lambda t: cost[t.name])[0].name
    assert pick(0.5) == "analytic"  # nothing fits: the cheapest
    assert pick(5) == "splitsum"
    assert pick(12) == "fis16"
    assert pick(50) == "fis64"
    assert pick(10_000) == "mc1024"


def test_budget_option_measures_real_frame_times(renderer, scene):
    from cnlmc.backends.preview import PreviewOptions, choose_tier

    material = material_of("gold")
    measure = lambda t: renderer.frame_time(scene, material, t, repeats=2)
    cheap = ("analytic", "splitsum", "mc16")
    tier, timings = select_tier(1e6, measure, cheap)
    assert tier.name == "mc16" and set(timings) == set(cheap) and all(v > 0 for v in timings.values())
    tier, timings = choose_tier(renderer, scene, material, PreviewOptions(size=64, budget_ms=1e-6))
    assert tier.name == QUALITY_ORDER[0] and len(timings) == 2  # stops after the first miss


def test_variant_sheet_and_command(tmp_path, gl_available):
    from cnlmc.api import compile_source

    ir = compile_source("blue or red plastic\n").ir
    report = preview_command(ir, tmp_path / "sheet.png", {"size": "48", "tier": "splitsum"})
    assert report.path.exists()
    image = compose(report.frames)
    assert image.shape[1] > 2 * 48 and image.shape[0] > 48  # two tiles side by side, labelled


def test_options_are_validated():
    with pytest.raises(PreviewOptionError):
        parse_options({"colour": "red"})
    with pytest.raises(PreviewOptionError):
        parse_options({"tier": "ultra"})
    assert parse_options({"size": "128", "fresnel": "schlick"}).glsl["fresnel"] == "schlick"


def test_fresnel_options_change_the_metal(renderer, scene):
    material = material_of("gold")
    exact = renderer.render(material, tier="splitsum", scene=scene, hdr=True).hdr
    schlick = renderer.render(material, tier="splitsum", scene=scene, hdr=True, glsl_options={"fresnel": "schlick"}).hdr
    assert not np.array_equal(exact, schlick)
    assert np.abs(exact - schlick).mean() < 0.1 * np.abs(exact).mean()


def test_teapot_and_shader_ball_render(renderer):
    from cnlmc.backends.preview.render import default_scene

    material = material_of("copper")
    for mesh in ("teapot", "shader_ball"):
        scene = default_scene(mesh, "studio", (64, 64))
        frame = renderer.render(material, tier="splitsum", scene=scene, hdr=True)
        assert np.isfinite(frame.hdr).all() and (frame.rgba[..., 3] == 255).all()  # opaque over the environment
        scene.background = "transparent"
        frame = renderer.render(material, tier="splitsum", scene=scene, hdr=True)
        assert 0.1 < (frame.rgba[..., 3] > 0).mean() < 0.9


def test_options_say_did_you_mean_and_ar_builds_on_them():
    from cnlmc.backends.ar import OPTIONS as AR_OPTIONS
    from cnlmc.backends.preview import OPTIONS

    with pytest.raises(PreviewOptionError, match="did you mean 'size'"):
        parse_options({"sise": "64"})
    with pytest.raises(PreviewOptionError, match="did you mean 'schlick'"):
        parse_options({"fresnel": "schlik"})
    preview = {o.name: o for o in OPTIONS}
    shared = [o for o in AR_OPTIONS if o.name in preview]
    assert {o.name for o in shared} == {"mesh", "tier", "env", "exposure", "msaa", "fresnel", "multiscatter"}
    assert all(o.type is preview[o.name].type and o.choices == preview[o.name].choices for o in shared)


def test_the_registry_finds_the_preview_target_and_both_commands():
    from cnlmc.backends.ar.command import ARCommand
    from cnlmc.backends.preview import TARGET
    from cnlmc.backends.preview.commands import PreviewCommand
    from cnlmc.backends.registry import get_command, get_target

    assert get_target("preview") is TARGET and PreviewCommand in TARGET.commands
    assert isinstance(get_command("preview"), PreviewCommand) and isinstance(get_command("ar"), ARCommand)


def test_programs_are_cached_by_content_not_identity(renderer):
    """Equal materials share a shader and its program; another material never gets theirs
    (an id()-keyed cache once returned another material's program)."""
    from dataclasses import replace

    from cnlmc.backends.preview.object_pass import object_program
    from cnlmc.backends.preview.tiers import parse_tier

    gold, copper = material_of("gold"), material_of("copper")
    tier = parse_tier("splitsum")
    programs = {}
    for _ in range(3):  # shaders made again each time (new objects), programs found by content
        for material in (gold, copper, replace(gold)):
            shader = replace(renderer.shader(material))
            programs.setdefault(material.key, set()).add(object_program(renderer.resources, shader, tier)[0])
    assert len(programs) == 2 and all(len(keys) == 1 for keys in programs.values())
    assert programs[gold.key] != programs[copper.key]
