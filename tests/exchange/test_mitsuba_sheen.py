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


def principled_albedo(props: dict, mu: float, n: int = 24) -> np.ndarray:
    """Mitsuba's own principled under a white sky at view cosine mu: sum of bsdf.eval (cosine
    included) over a midpoint grid of n x 4n light directions, cosine-weighted (no formula of ours)."""
    mi.set_variant("scalar_rgb")
    bsdf = mi.load_dict({"type": "principled", **props})
    si = mi.SurfaceInteraction3f()
    si.n, si.sh_frame = mi.Vector3f(0, 0, 1), mi.Frame3f(mi.Vector3f(0, 0, 1))
    si.wi = mi.Vector3f(float(np.sqrt(1 - mu * mu)), 0.0, mu)
    ctx, total = mi.BSDFContext(), np.zeros(3)
    for i in range(n):  # cos theta_i = sqrt(u): cosine-weighted cells, each of measure pi / (n 4n)
        ci = float(np.sqrt((i + 0.5) / n))
        for j in range(4 * n):
            phi = 2 * np.pi * (j + 0.5) / (4 * n)
            s = float(np.sqrt(1 - ci * ci))
            wo = mi.Vector3f(s * float(np.cos(phi)), s * float(np.sin(phi)), ci)
            total += np.array(bsdf.eval(ctx, si, wo)) / ci
    return total * np.pi / (4 * n * n)


@pytest.mark.parametrize("mu", [1.0, 0.5, 0.15])
def test_principled_lobe_albedos_are_mitsubas(mu):
    """The exporter's Disney diffuse and sheen albedos (mitsuba_principled, from the published
    formulas) are what Mitsuba's principled returns: the diffuse lobe's > 1 is real (1.04 at normal
    view), so a sheen fabric's base must be dimmed to keep the IR's energy."""
    from cnlmc.backends.exchange.mitsuba_principled import lobe_albedos

    grid, _weights, diffuse, sheen = lobe_albedos(1.0)
    white = {"base_color": {"type": "rgb", "value": [1.0, 1.0, 1.0]}, "roughness": 1.0, "specular": 0.0}
    fibres = {**white, "base_color": {"type": "rgb", "value": [0.0, 0.0, 0.0]}, "sheen": 1.0}
    ours_diffuse, ours_sheen = np.interp(mu, grid, diffuse), np.interp(mu, grid, sheen)
    assert principled_albedo(white, mu)[1] == pytest.approx(ours_diffuse, rel=0.02)
    assert principled_albedo(fibres, mu)[1] == pytest.approx(ours_sheen, rel=0.05, abs=2e-4)


def test_sheen_export_keeps_the_irs_energy_and_stays_under_one():
    """A fabric's principled base colour and sheen give the IR's hemispherical albedo (velvet's was
    1.3x over the IR's Oren-Nayar one with the IR's base colour) and no view returns more than 1."""
    from cnlmc.backends.exchange.conversions import hemispherical_albedo
    from cnlmc.backends.exchange.mitsuba_principled import fabric_roughness, lobe_albedos, lobe_energies, sheen_base

    for phrase in ("velvet", "navy blue velvet", "white felt", "denim"):
        material = material_of(phrase)
        roughness = fabric_roughness(material)
        base, weight = sheen_base(material, roughness)
        diffuse, sheen = lobe_energies(roughness)
        tint = np.asarray(base) / max(float(np.dot(base, [0.212671, 0.715160, 0.072169])), 1e-9)
        exported = np.asarray(base) * diffuse + weight * tint * sheen
        assert exported == pytest.approx(hemispherical_albedo(material, full=True), abs=0.01), phrase
        _mu, _w, d_mu, s_mu = lobe_albedos(roughness)
        assert np.max(np.outer(d_mu, base) + weight * np.outer(s_mu, tint)) <= 1.0 + 1e-6, phrase
        assert weight > 0.5, phrase  # the sheen is drawn, not dropped
        assert weight <= 1.0, phrase  # Burley's range


def sheened_nouns() -> list[str]:
    from cnlmc.api import lexicon_for
    from cnlmc.bsdf.sheen import has_sheen

    nouns = sorted(lexicon_for().all_of("nouns"))
    return [n for n in nouns if (m := compile_source(n + "\n").document.materials) and has_sheen(m[0])]


def principled_props(phrase: str) -> dict:
    """The exported principled's float and rgb parameters, as Mitsuba's load_dict takes them."""
    import xml.etree.ElementTree as ET

    text = emit(compile_source(phrase + "\n").ir, "mitsuba", {"form": "fragment"}).artifacts[0].content
    (node,) = [b for b in ET.fromstring(text).iter("bsdf") if b.get("type") == "principled"]
    props: dict = {}
    for child in node:
        if child.tag == "float":
            props[child.get("name")] = float(child.get("value"))
        elif child.tag == "rgb":
            props[child.get("name")] = {"type": "rgb", "value": [float(v) for v in child.get("value").split(",")]}
    return props


def test_every_fabric_exports_a_sheen_weight_in_burleys_range():
    """Every stdlib fibre noun's principled sheen is in 0-1 (it was 2.2-5.7: Disney's grazing term
    up to 5.7x its own at full weight) and still drawn; the IR's fibre energy beyond it is in the base,
    so the export's hemispherical energy stays the IR's (the lobes' energies from the published formulas)."""
    from cnlmc.backends.exchange.conversions import hemispherical_albedo
    from cnlmc.backends.exchange.mitsuba_principled import LUMINANCE, lobe_energies

    nouns = sheened_nouns()
    assert {"velvet", "microfiber", "felt", "silk"} <= set(nouns)
    for phrase in nouns:
        props = principled_props(phrase)
        assert 0.5 < props["sheen"] <= 1.0, (phrase, props["sheen"])
        base = np.asarray(props["base_color"]["value"])
        diffuse, sheen = lobe_energies(props["roughness"])
        tint = base / max(float(LUMINANCE @ base), 1e-9) if base.any() else np.ones(3)
        exported = base * diffuse + props["sheen"] * tint * sheen
        material = compile_source(phrase + "\n").document.materials[0]
        if material.model.base == "diffuse":  # a dielectric's specular lobe is principled's own
            assert exported == pytest.approx(hemispherical_albedo(material, full=True), abs=0.01), phrase


def test_capped_sheen_keeps_mitsubas_grazing_view_under_one():
    """The fabric whose sheen weight was highest (microfiber, 5.7): Mitsuba's own principled with the
    exported parameters returns at most what it receives at a grazing view and at normal view."""
    props = principled_props("microfiber")
    for mu in (0.15, 1.0):
        assert np.all(principled_albedo(props, mu) <= 1.0 + 1e-3), mu
