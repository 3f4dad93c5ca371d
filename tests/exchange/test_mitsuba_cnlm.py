"""`--target mitsuba --option bsdf=cnlm` and the `cnlm` Mitsuba plugin: Mitsuba itself
evaluates, samples and renders cnlmc's BSDF, and the values equal the numpy reference."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from cnlmc.api import compile_source
from cnlmc.backends.exchange import mitsuba
from cnlmc.bsdf.evaluate import albedo, evaluate
from tests.helpers import require


def material(phrase: str) -> dict:
    return compile_source(phrase + "\n").ir["materials"][0]


def fragment(phrase: str) -> ET.Element:
    ir = compile_source(phrase + "\n").ir
    result = mitsuba.emit(ir, {"form": "fragment", "bsdf": "cnlm"})
    files = {a.name: a.content for a in result.artifacts}
    return ET.fromstring(files["materials.xml"].encode())


def plugins(root: ET.Element) -> list[str]:
    return [b.get("type") for b in root.iter("bsdf")]


def test_cnlm_option_emits_the_plugin_with_the_ir_material():
    root = fragment("terracotta")
    assert plugins(root) == ["twosided", "cnlm"]
    text = next(s.get("value") for s in root.iter("string") if s.get("name") == "material")
    assert json.loads(text)["params"] == material("terracotta")["params"]


def test_glass_keeps_its_exact_native_plugin():
    assert "cnlm" not in plugins(fragment("rough glass")) and "roughdielectric" in plugins(fragment("rough glass"))


@pytest.mark.oiio
def test_maps_become_textures_of_the_plugin_and_normals_a_normalmap():
    require("OpenImageIO", "maps")  # the maps are baked
    root = fragment("oak")
    names = {t.get("name") for t in root.iter("texture")}
    assert {"base_color", "roughness"} <= names
    assert plugins(fragment("lightly brushed steel"))[0] == "normalmap"


def test_dollar_signs_cannot_become_mitsuba_parameters():
    ir = compile_source("cost$1: red plastic\n").ir
    files = {a.name: a.content for a in mitsuba.emit(ir, {"form": "fragment", "bsdf": "cnlm"}).artifacts}
    assert "$" not in next(s.get("value") for s in ET.fromstring(files["materials.xml"].encode()).iter("string"))


def test_unknown_bsdf_option_is_refused():
    with pytest.raises(ValueError, match="bsdf"):
        mitsuba.emit(compile_source("gold\n").ir, {"bsdf": "exact"})


# ----------------------------------------------------------------- inside Mitsuba


@pytest.fixture(scope="module")
def mi():
    mitsuba_module = pytest.importorskip("mitsuba")
    import drjit as dr

    from cnlmc.backends.exchange import mitsuba_cnlm

    previous = mitsuba_module.variant()
    flags = {f: dr.flag(f) for f in (dr.JitFlag.SymbolicCalls, dr.JitFlag.SymbolicLoops)}
    try:
        mitsuba_cnlm.register()
    except mitsuba_cnlm.PluginError as exc:
        pytest.skip(str(exc))
    yield mitsuba_module
    for flag, value in flags.items():
        dr.set_flag(flag, value)
    if previous:
        mitsuba_module.set_variant(previous)


def directions(n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    w = rng.normal(size=(n, 3))
    w[:, 2] = np.abs(w[:, 2]) + 0.05
    return w / np.linalg.norm(w, axis=1)[:, None]


def interaction(mi, wo: np.ndarray):
    import drjit as dr

    si = dr.zeros(mi.SurfaceInteraction3f, len(wo))
    si.wi = mi.Vector3f(*(np.ascontiguousarray(wo[:, k], np.float32) for k in range(3)))
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    return si


PHRASES = ("terracotta", "gold", "clear-coated red car paint", "lightly brushed steel", "suede", "glossy blue plastic")


@pytest.mark.mitsuba
@pytest.mark.parametrize("phrase", PHRASES)
def test_plugin_eval_is_the_numpy_reference_times_cosine(mi, phrase):
    m = material(phrase)
    bsdf = mi.load_dict({"type": "cnlm", "material": json.dumps(m)})
    wo, wi = directions(64, 1), directions(64, 2)
    got = np.array(bsdf.eval(mi.BSDFContext(), interaction(mi, wo), mi.Vector3f(*wi.T.astype(np.float32)))).T
    want = evaluate(m, wo, wi) * wi[:, 2:3]
    np.testing.assert_allclose(got, want, rtol=2e-4, atol=1e-6)


@pytest.mark.mitsuba
@pytest.mark.parametrize("phrase", PHRASES)
def test_plugin_sampling_integrates_to_the_directional_albedo(mi, phrase):
    """Mean of sample weights (f cos / pdf) = ∫ f cos dωi, against the deterministic QMC albedo."""
    m = material(phrase)
    bsdf = mi.load_dict({"type": "cnlm", "material": json.dumps(m)})
    n, mu = 200_000, 0.6
    wo = np.tile([np.sqrt(1 - mu * mu), 0.0, mu], (n, 1))
    rng = np.random.default_rng(3)
    u = rng.random((n, 3)).astype(np.float32)
    bs, weight = bsdf.sample(mi.BSDFContext(), interaction(mi, wo), mi.Float(u[:, 0]), mi.Point2f(u[:, 1], u[:, 2]))
    weight = np.array(weight).T
    assert np.all(np.isfinite(weight))
    np.testing.assert_allclose(weight.mean(0), albedo(m, mu), rtol=0.03, atol=2e-3)
    pdf = np.array(bsdf.pdf(mi.BSDFContext(), interaction(mi, wo), bs.wo))
    np.testing.assert_allclose(pdf, np.array(bs.pdf), rtol=1e-3, atol=1e-4)


@pytest.mark.mitsuba
def test_a_lambert_material_renders_as_mitsubas_own_diffuse(mi, tmp_path):
    """Same scene, `cnlm` plugin vs native `diffuse`: Lambert is exact in both."""
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.render import default_scene

    m = material("paper")
    m["model"]["diffuse"] = "lambert"  # stdlib paper is Oren-Nayar
    scene = default_scene("sphere", "studio", (48, 48))
    images = {}
    for kind in ("cnlm", "native"):
        path = export_scene(m, scene, tmp_path / kind, 48, 48, spp=64, bsdf=kind)
        images[kind], _ = render_scene(path, spp=64, seed=5, variant="vectorized")
    assert np.all(np.isfinite(images["cnlm"]))
    inside = images["native"][..., 3] > 0.99
    ratio = images["cnlm"][inside, :3].mean(0) / images["native"][inside, :3].mean(0)
    np.testing.assert_allclose(ratio, 1.0, atol=0.02)


def test_native_plugins_warn_where_they_approximate_and_cnlm_does_not():
    ir = compile_source("terracotta\n").ir
    native = [n.text() for n in mitsuba.emit(ir, {"form": "fragment"}).notes]
    cnlm = [n.text() for n in mitsuba.emit(ir, {"form": "fragment", "bsdf": "cnlm"}).notes]
    assert any("oren_nayar" in t for t in native) and any("model.dielectric" in t for t in native)
    assert cnlm == []


@pytest.mark.mitsuba
def test_without_llvm_19_the_plugin_refuses_clearly_instead_of_aborting():
    require("mitsuba", "mitsuba")
    """Mitsuba's llvm variants abort the process with LLVM 15/16: no LLVM 19, no attempt."""
    code = (
        "import os; os.environ.pop('DRJIT_LIBLLVM_PATH', None)\n"
        "from cnlmc.backends.exchange import mitsuba_cnlm\n"
        "mitsuba_cnlm.LLVM_LIBRARY = '/nonexistent/libLLVM.so.19.1'\n"
        "try:\n    mitsuba_cnlm.register()\nexcept mitsuba_cnlm.PluginError as exc:\n    print('refused:', exc)\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "DRJIT_LIBLLVM_PATH"}
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, env=env)
    assert proc.returncode == 0 and "refused:" in proc.stdout and "libllvm19" in proc.stdout
